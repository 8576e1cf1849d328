// The output stage shared by every core: per axis a stepdir_axis (hostmot2
// step/dir timing, see rtl/stepdir_axis.sv) and a signed position counter,
// and once for all axes the settings as the axes take them
// (rtl/stepdir_timing.sv).
//
// The engine says, per axis, whether the running command moves the axis at
// all (want_valid_i) and in which direction (want_dir_i: 1 = negative); the
// stage answers whether a pulse may start on the next clock (ready_o). The
// engine fires only ready axes (fire_i; it stalls otherwise), so no step is
// ever lost and no timing is ever violated. With READY_Q = 1 the engine also
// says a clock ahead which axes it will want to step (want_step_next_i) and
// the stage answers with block_o, a register per axis: the engine stalls
// when any is set. A fired axis raises step_o on the
// next clock and its position counter counts the step on the same clock:
// pos_o always equals the pulses that reached the wire.
//
// Per-axis vectors are flat with `+:` slices (Yosys 0.23 cannot parse
// multi-dimensional packed arrays; Icarus 11 cannot index them with a loop
// variable).
module step_stage #(
  parameter int AXES    = 2,    // axes (>= 1)
  parameter int POS_W   = 32,   // position counter width (>= 2; wraps)
  parameter int TIM_W   = 16,   // width of the timing settings and counters (>= 2)
  parameter bit READY_Q = 1'b0  // 1: ready_o registers, decided from want_dir_next_i (rtl/stepdir_axis.sv)
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  // hostmot2 timing in clocks (0 acts as 1); a phase takes the value of the clock it starts on
  input  logic [TIM_W-1:0]      step_len_i,
  input  logic [TIM_W-1:0]      step_space_i,
  input  logic [TIM_W-1:0]      dir_setup_i,
  input  logic [TIM_W-1:0]      dir_hold_i,
  input  logic [AXES-1:0]       want_valid_i,  // the running command moves the axis
  input  logic [AXES-1:0]       want_dir_i,    // ...in this direction (1: negative)
  input  logic [AXES-1:0]       want_dir_next_i,  // want_dir_i of the next clock (READY_Q = 1)
  input  logic [AXES-1:0]       want_step_next_i,  // the engine wants a pulse on the next clock (READY_Q = 1)
  input  logic [AXES-1:0]       fire_i,        // start a pulse next clock (ready axes only)
  output logic [AXES-1:0]       ready_o,       // a pulse in direction want_dir_i may start next clock
  output logic [AXES-1:0]       block_o,       // a pulse wanted now and not ready_o: stall (READY_Q = 1; else 0)
  output logic [AXES-1:0]       step_o,
  output logic [AXES-1:0]       dir_o,         // 1: negative motion
  output logic [AXES*POS_W-1:0] pos_o          // axis i in bits [i*POS_W +: POS_W]
);
  // Parameter checks at elaboration: Verilator and Yosys stop with the
  // message (Icarus 11 has no elaboration system tasks: it skips them).
`ifndef __ICARUS__
  if (AXES < 1) begin : g_bad_axes
    $error("step_stage: parameter AXES must be >= 1");
  end
  if (POS_W < 2) begin : g_bad_pos_w
    $error("step_stage: parameter POS_W must be >= 2");
  end
  if (TIM_W < 2) begin : g_bad_tim_w
    $error("step_stage: parameter TIM_W must be >= 2");
  end
`endif

  logic [TIM_W-1:0] len, space, setup, hold;
  logic len_one, space_one, setup_one, hold_one, space_two, setup_two, hold_two, fresh;

  stepdir_timing #(
    .TIM_W(TIM_W)
  ) u_timing (
    .clk_i,
    .rst_ni,
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .len_o      (len),
    .space_o    (space),
    .setup_o    (setup),
    .hold_o     (hold),
    .len_one_o  (len_one),
    .space_one_o(space_one),
    .setup_one_o(setup_one),
    .hold_one_o (hold_one),
    .space_two_o(space_two),
    .setup_two_o(setup_two),
    .hold_two_o (hold_two),
    .fresh_o    (fresh)
  );

  for (genvar i = 0; i < AXES; i++) begin : g_axis
    logic [POS_W-1:0] pos_q, pos_d;

    // One adder: +1, or + all ones (-1) for the negative direction.
    assign pos_d = fire_i[i] ? pos_q + {{(POS_W - 1) {want_dir_i[i]}}, 1'b1} : pos_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) pos_q <= '0;
      else pos_q <= pos_d;
    end
    assign pos_o[i*POS_W +: POS_W] = pos_q;

    stepdir_axis #(
      .TIM_W  (TIM_W),
      .READY_Q(READY_Q)
    ) u_stepdir (
      .clk_i,
      .rst_ni,
      .len_i           (len),
      .space_i         (space),
      .setup_i         (setup),
      .hold_i          (hold),
      .len_one_i       (len_one),
      .space_one_i     (space_one),
      .setup_one_i     (setup_one),
      .hold_one_i      (hold_one),
      .space_two_i     (space_two),
      .setup_two_i     (setup_two),
      .hold_two_i      (hold_two),
      .fresh_i         (fresh),
      .want_valid_i    (want_valid_i[i]),
      .want_dir_i      (want_dir_i[i]),
      .want_dir_next_i (want_dir_next_i[i]),
      .want_step_next_i(want_step_next_i[i]),
      .fire_i          (fire_i[i]),
      .ready_o         (ready_o[i]),
      .block_o         (block_o[i]),
      .step_o          (step_o[i]),
      .dir_o           (dir_o[i])
    );
  end
endmodule

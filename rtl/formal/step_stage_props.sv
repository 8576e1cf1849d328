// Formal properties of step_stage, the output stage every core shares
// (scripts/formal.sh; the per-axis timing is proved in stepdir_axis_props.sv).
//
// Free want/fire inputs on every axis; the monitors read only the stage's
// outputs:
//   a_pos    each axis's pos_o changes by exactly +1 (dir_o low) or -1 (dir_o
//            high) on the clock its step_o rises, and never otherwise: the
//            position is the integral of the step/dir wires, so after any
//            stop it equals the pulses that reached the wire;
//   a_fire   a fire_i on an axis starts its pulse on the next clock and on no
//            other axis.
// Assumptions: reset in the first cycle only; the engine fires only ready
// axes. The settings are free on every clock.
module step_stage_props #(
  parameter int AXES  = 2,
  parameter int POS_W = 4,
  parameter int TIM_W = 3
) (
  input logic             clk_i,
  input logic             rst_ni,
  input logic [TIM_W-1:0] step_len_i,
  input logic [TIM_W-1:0] step_space_i,
  input logic [TIM_W-1:0] dir_setup_i,
  input logic [TIM_W-1:0] dir_hold_i,
  input logic [AXES-1:0]  want_valid_i,
  input logic [AXES-1:0]  want_dir_i,
  input logic [AXES-1:0]  fire_i
);
  logic [AXES-1:0]       ready, step, dir;
  logic [AXES-1:0]       unused_block;
  logic [AXES*POS_W-1:0] pos;

  step_stage #(
    .AXES (AXES),
    .POS_W(POS_W),
    .TIM_W(TIM_W)
  ) dut (
    .clk_i,
    .rst_ni,
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .want_valid_i,
    .want_dir_i,
    .want_dir_next_i (want_dir_i),  // READY_Q = 0: unused
    .want_step_next_i('0),  // READY_Q = 0: unused
    .fire_i,
    .ready_o         (ready),
    .block_o         (unused_block),  // READY_Q = 0: always 0
    .step_o          (step),
    .dir_o           (dir),
    .pos_o           (pos)
  );

  logic [AXES-1:0]       p_step, p_fire;
  logic [AXES*POS_W-1:0] p_pos;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      p_step <= '0;
      p_fire <= '0;
      p_pos  <= '0;
    end else begin
      p_step <= step;
      p_fire <= fire_i;
      p_pos  <= pos;
    end
  end

  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;

  logic [AXES-1:0] rise;
  assign rise = step & ~p_step;

  always_comb begin
    assume(rst_ni == !f_init);
    assume((fire_i & ~ready) == '0);
    if (!f_init) a_fire: assert(rise == p_fire);
  end

  // a_pos per axis. Unlabelled: Yosys 0.23 names a labelled assertion without
  // its generate scope, so every axis's copy would clash with the first.
  for (genvar i = 0; i < AXES; i++) begin : g_axis
    always_comb begin
      if (!f_init)
        assert(pos[i*POS_W +: POS_W] == p_pos[i*POS_W +: POS_W] +
               (!rise[i] ? POS_W'(0) : dir[i] ? {POS_W{1'b1}} : POS_W'(1)));
    end
  end
endmodule

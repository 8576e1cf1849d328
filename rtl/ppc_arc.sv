// ppc_arc: 2-axis point-by-point comparison (PPC) circular-arc interpolator,
// CW and CCW, crossing quadrants, ending exactly on the commanded end point
// even when it is off the circle through the start ("rule M", models/ppc.h,
// models::PpcArcStream: the arc, its bound and its derivation).
//
// command stream -> buffer (rtl/ppc_arc_prep.sv: s, e, E) -> PPC arc engine
//                (rtl/ppc_arc_engine.sv: set-up, arc, closing line) -> step_stage
//
// Command, taken on a clock where cmd_valid_i && cmd_ready_o (one-entry
// buffer, cmd_ready_o a register, back-to-back commands gapless), all signed
// COORD_W-bit lattice offsets from the start, which is wherever the axes are;
// a command buffered while the engine is idle makes its first operation two
// clocks later (rtl/ppc_arc_engine.sv, "Taking a command"):
//   cmd_center_i  centre - start (G-code I, J): I at [0 +: COORD_W], J above
//   cmd_end_i     end - start, x at [0 +: COORD_W], y above
//   cmd_ccw_i     1: counter-clockwise, 0: clockwise
// rtl/ppc_arc_engine.sv states rule M, the operations (one per feed tick: a
// step of x or y, or the switch to the closing line, which steps neither) and
// the internal widths.
//
// Feed, step/dir timing, abort and status: exactly as rtl/ppc_line.sv (and
// rtl/dda_line.sv): feed_accum gates the operations, the engine stalls while
// the axis it steps is not ready (a motion sign that flips at a quadrant
// entry turns dir_o after dir_hold_i, and the next step on that axis waits
// dir_setup_i), abort_i ends the running command and drops the buffered one
// with no operation on its edge (busy_o falls at most max(step_len_i, 1) - 1
// clocks later; no done_o for it), done_o pulses with each completed
// command's last operation, busy_o = running || buffered || a pulse high,
// pos_o the signed positions (wrap at POS_W bits).
//
// Per-axis vectors are flat with `+:` slices (Yosys 0.23, Icarus 11).
module ppc_arc #(
  parameter int AXES    = 2,   // axes: must be 2 (a planar method)
  parameter int COORD_W = 24,  // width of the command's signed coordinates (3..60)
  parameter int POS_W   = 32,  // position counter width (2..64; wraps)
  parameter int TIM_W   = 16,  // width of the step/dir timing settings and counters (>= 2)
  parameter int FEED_W  = 16   // feed phase width (>= 1); feed_i = 2^FEED_W is full feed
) (
  input  logic                    clk_i,         // clock
  input  logic                    rst_ni,        // asynchronous, active low
  // Command stream
  input  logic                    cmd_valid_i,   // a command is offered on cmd_*_i
  output logic                    cmd_ready_o,   // the buffer is free: an offered command is taken
  input  logic [AXES*COORD_W-1:0] cmd_center_i,  // centre - start: I at [0 +: COORD_W], J above
  input  logic [AXES*COORD_W-1:0] cmd_end_i,     // end - start: x at [0 +: COORD_W], y above
  input  logic                    cmd_ccw_i,     // 1: counter-clockwise, 0: clockwise
  // Run-time settings
  input  logic [FEED_W:0]         feed_i,        // operations per clock = feed_i / 2^FEED_W
  input  logic [TIM_W-1:0]        step_len_i,    // step pulse length, clocks (0 acts as 1)
  input  logic [TIM_W-1:0]        step_space_i,  // min low time between pulses, clocks
  input  logic [TIM_W-1:0]        dir_setup_i,   // dir stable before a step rises, clocks
  input  logic [TIM_W-1:0]        dir_hold_i,    // dir stable after a step falls, clocks
  input  logic                    abort_i,       // end the move, drop the buffer (one clock)
  // Step/dir and status
  output logic [AXES-1:0]         step_o,        // step pulses, axis i in bit i
  output logic [AXES-1:0]         dir_o,         // 1: negative motion
  output logic [AXES*POS_W-1:0]   pos_o,         // signed positions, axis i at [i*POS_W +: POS_W]
  output logic                    busy_o,        // a command buffered or running, or a pulse high
  output logic                    done_o         // one clock per completed command
);
  localparam int PREP_W = 6 * COORD_W + 4;  // rtl/ppc_arc_prep.sv

  // ---------------------------------------------------------------------------
  // Parameter checks at elaboration: Verilator and Yosys stop with the
  // message (Icarus 11 has no elaboration system tasks: it skips them). The
  // upper bounds are the range the HLS face (hls/ppc_arc.h), and so the
  // lockstep verification, covers.
`ifndef __ICARUS__
  if (AXES != 2) begin : g_bad_axes
    $error("ppc_arc: parameter AXES must be 2");
  end
  if (COORD_W < 3 || COORD_W > 60) begin : g_bad_coord_w
    $error("ppc_arc: parameter COORD_W must be 3..60");
  end
  if (POS_W < 2 || POS_W > 64) begin : g_bad_pos_w
    $error("ppc_arc: parameter POS_W must be 2..64");
  end
  if (TIM_W < 2) begin : g_bad_tim_w
    $error("ppc_arc: parameter TIM_W must be >= 2");
  end
  if (FEED_W < 1) begin : g_bad_feed_w
    $error("ppc_arc: parameter FEED_W must be >= 1");
  end
`endif

  // ---------------------------------------------------------------------------
  // Command buffer (one entry): s, e, E (rtl/ppc_arc_prep.sv) and the
  // direction. It stays valid until the engine starts the command (its first
  // operation moves into the engine's operation register: eng_start), though
  // the engine copies it a clock or more before (rtl/ppc_arc_engine.sv,
  // "Taking a command").
  logic              buf_valid_q, buf_valid_d;
  logic [PREP_W-1:0] buf_prep_q, buf_prep_d, cmd_prep;
  logic              buf_ccw_q, buf_ccw_d;
  logic              cmd_take;  // a command is taken this clock
  logic              eng_start;  // the engine starts the buffered command this clock

  assign cmd_ready_o = !buf_valid_q;
  assign cmd_take    = cmd_valid_i && !buf_valid_q;

  ppc_arc_prep #(
    .COORD_W(COORD_W)
  ) u_prep (
    .center_i(cmd_center_i),
    .end_i   (cmd_end_i),
    .prep_o  (cmd_prep)
  );

  // ---------------------------------------------------------------------------
  // Engine: its operation register is this clock's operation (registers:
  // act, carry, want_valid, want_dir, eng_last), and it says the next clock's
  // (act_next, carry_next, want_dir_next), so that the step/dir stage decides
  // the stall a clock ahead (READY_Q = 1: block, a register per axis).
  logic            act, act_next;  // a command is running (this clock, the next)
  logic            done_q, done_d;
  logic            eng_last, unused_pending;
  logic [AXES-1:0] carry, carry_next;  // this operation steps the axis (this clock, the next)
  logic [AXES-1:0] want_valid;  // the running command may step the axis
  logic [AXES-1:0] want_dir, want_dir_next;
  logic [AXES-1:0] unused_ready;  // the stall reads block instead
  logic [AXES-1:0] block;  // the axis must step and is not ready: stall (a register)
  logic            tick, stall, advance, last;

  assign stall   = |block;
  assign advance = tick && !stall && !abort_i;
  assign last    = advance && eng_last;

  feed_accum #(
    .FEED_W(FEED_W)
  ) u_feed (
    .clk_i,
    .rst_ni,
    .feed_i,
    .run_i     (act),
    .hold_i    (stall),
    .run_next_i(act_next),
    .tick_o    (tick)
  );

  ppc_arc_engine #(
    .COORD_W(COORD_W)
  ) u_arc (
    .clk_i,
    .rst_ni,
    .ld_valid_i     (buf_valid_q),
    .ld_prep_i      (buf_prep_q),
    .ld_ccw_i       (buf_ccw_q),
    .pending_o      (unused_pending),
    .start_o        (eng_start),
    .fill_i         (1'b1),
    .advance_i      (advance),
    .abort_i,
    .run_o          (act),
    .step_o         (carry),
    .want_valid_o   (want_valid),
    .want_dir_o     (want_dir),
    .last_o         (eng_last),
    .run_next_o     (act_next),
    .step_next_o    (carry_next),
    .want_dir_next_o(want_dir_next)
  );

  always_comb begin
    buf_valid_d = !abort_i && (cmd_take || (buf_valid_q && !eng_start));
    buf_prep_d  = cmd_take ? cmd_prep : buf_prep_q;
    buf_ccw_d   = cmd_take ? cmd_ccw_i : buf_ccw_q;
    done_d      = last;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      buf_valid_q <= 1'b0;
      buf_prep_q  <= '0;
      buf_ccw_q   <= 1'b0;
      done_q      <= 1'b0;
    end else begin
      buf_valid_q <= buf_valid_d;
      buf_prep_q  <= buf_prep_d;
      buf_ccw_q   <= buf_ccw_d;
      done_q      <= done_d;
    end
  end

  // ---------------------------------------------------------------------------
  // Output stage: step/dir timing and position counters.
  step_stage #(
    .AXES   (AXES),
    .POS_W  (POS_W),
    .TIM_W  (TIM_W),
    .READY_Q(1'b1)
  ) u_out (
    .clk_i,
    .rst_ni,
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .want_valid_i    (want_valid),
    .want_dir_i      (want_dir),
    .want_dir_next_i (want_dir_next),
    .want_step_next_i(carry_next),
    .fire_i          ({AXES{advance}} & carry),
    .ready_o         (unused_ready),
    .block_o         (block),
    .step_o,
    .dir_o,
    .pos_o
  );

  assign busy_o = act || buf_valid_q || (|step_o);
  assign done_o = done_q;
endmodule

// ppc_line: 2-axis point-by-point comparison (PPC) line interpolator
// (papers 003_b291717b57510359.txt, 004_dc68f1177cad466f.txt).
//
// command stream -> buffer (|dx|, |dy|, signs) -> PPC engine (feed_accum gated) -> step_stage
//
// Command: cmd_delta_i holds the signed (two's complement) ACC_W-bit deltas,
// dx in bits [0 +: ACC_W], dy in [ACC_W +: ACC_W]; it is taken on a clock
// where cmd_valid_i && cmd_ready_o. A one-entry buffer holds the next command
// as magnitudes and signs while the engine runs, so back-to-back commands run
// without a gap; cmd_ready_o is a register.
//
// Engine (rtl/ppc_line_step.sv, the guarded rule of models::PpcLineRule):
// one operation (deviation test, one axis step, deviation update) per feed
// tick; F >= 0 steps x while x has steps left, else y; exactly |dx| + |dy|
// operations, the reference model's move sequence (models::PpcLineStream).
// A zero-length command takes one operation that steps nothing, then done_o.
// Normal path error < max(|dx|, |dy|) / L < 1 step (models::ppc_line_error_bound).
// |delta| <= 2^(ACC_W-1), so the magnitudes take ACC_W bits and F ACC_W + 1.
//
// Feed (rtl/feed_accum.sv): each clock a FEED_W-bit phase accumulator adds
// feed_i; its carry lets the engine do one operation. feed_i >= 2^FEED_W is
// full feed (every clock), feed_i = 0 holds the move. The engine stalls, and
// the feed phase holds, whenever the axis that would step is not ready
// (step/dir timing, rtl/step_stage.sv): steps are delayed, never dropped.
//
// Abort: abort_i high at a clock edge ends the running command and drops the
// buffered one (a command transferred on that same edge too); no operation
// runs on that edge, so no new step starts from it on. A pulse already high
// keeps its full length: busy_o falls at most max(step_len_i, 1) - 1 clocks
// after the abort edge, and pos_o then equals the pulses on the wire, a point
// the command's path visits. No done_o for an aborted command. The core takes
// commands again from the next clock on.
//
// Status: busy_o while a command is buffered or running or a pulse is high;
// done_o pulses for one clock, with the last operation's step, per completed
// command; pos_o holds the signed position of each axis, axis i in bits
// [i*POS_W +: POS_W] (wraps at POS_W bits; the testbench refuses commands that
// would wrap it). dir_o = 1: negative motion.
module ppc_line #(
  parameter int AXES   = 2,   // axes: must be 2 (PPC is a planar method)
  parameter int ACC_W  = 32,  // width of each signed delta of cmd_delta_i (3..62)
  parameter int POS_W  = 32,  // position counter width (2..64; wraps)
  parameter int TIM_W  = 16,  // width of the step/dir timing settings and counters (>= 2)
  parameter int FEED_W = 16   // feed phase width (>= 1); feed_i = 2^FEED_W is full feed
) (
  input  logic                  clk_i,         // clock
  input  logic                  rst_ni,        // asynchronous, active low
  // Command stream
  input  logic                  cmd_valid_i,   // a command is offered on cmd_*_i
  output logic                  cmd_ready_o,   // the buffer is free: an offered command is taken
  input  logic [AXES*ACC_W-1:0] cmd_delta_i,   // dx at [0 +: ACC_W], dy at [ACC_W +: ACC_W]
  // Run-time settings
  input  logic [FEED_W:0]       feed_i,        // operations per clock = feed_i / 2^FEED_W
  input  logic [TIM_W-1:0]      step_len_i,    // step pulse length, clocks (0 acts as 1)
  input  logic [TIM_W-1:0]      step_space_i,  // min low time between pulses, clocks
  input  logic [TIM_W-1:0]      dir_setup_i,   // dir stable before a step rises, clocks
  input  logic [TIM_W-1:0]      dir_hold_i,    // dir stable after a step falls, clocks
  input  logic                  abort_i,       // end the move, drop the buffer (one clock)
  // Step/dir and status
  output logic [AXES-1:0]       step_o,        // step pulses, axis i in bit i
  output logic [AXES-1:0]       dir_o,         // 1: negative motion
  output logic [AXES*POS_W-1:0] pos_o,         // signed positions, axis i at [i*POS_W +: POS_W]
  output logic                  busy_o,        // a command buffered or running, or a pulse high
  output logic                  done_o         // one clock per completed command
);
  // ---------------------------------------------------------------------------
  // Parameter checks at elaboration: Verilator and Yosys stop with the
  // message (Icarus 11 has no elaboration system tasks: it skips them).
  // ACC_W >= 3: the line engine's flags read bits 2 and up
  // (rtl/ppc_line_step.sv); the upper bounds are the range the HLS face
  // (hls/ppc_line.h), and so the lockstep verification, covers.
`ifndef __ICARUS__
  if (AXES != 2) begin : g_bad_axes
    $error("ppc_line: parameter AXES must be 2");
  end
  if (ACC_W < 3 || ACC_W > 62) begin : g_bad_acc_w
    $error("ppc_line: parameter ACC_W must be 3..62");
  end
  if (POS_W < 2 || POS_W > 64) begin : g_bad_pos_w
    $error("ppc_line: parameter POS_W must be 2..64");
  end
  if (TIM_W < 2) begin : g_bad_tim_w
    $error("ppc_line: parameter TIM_W must be >= 2");
  end
  if (FEED_W < 1) begin : g_bad_feed_w
    $error("ppc_line: parameter FEED_W must be >= 1");
  end
`endif

  // ---------------------------------------------------------------------------
  // Command buffer (one entry): magnitudes and signs of the taken command.
  logic             buf_valid_q, buf_valid_d;
  logic [ACC_W-1:0] buf_ax_q, buf_ax_d, buf_ay_q, buf_ay_d;  // |dx|, |dy|
  logic [AXES-1:0]  buf_neg_q, buf_neg_d;  // sign of dx (bit 0), dy (bit 1)
  logic             cmd_take;  // a command is taken this clock
  logic             buf_take;  // the engine loads the buffer this clock
  logic [ACC_W-1:0] cmd_dx, cmd_dy;

  assign cmd_ready_o = !buf_valid_q;
  assign cmd_take    = cmd_valid_i && !buf_valid_q;
  assign cmd_dx      = cmd_delta_i[0 +: ACC_W];
  assign cmd_dy      = cmd_delta_i[ACC_W +: ACC_W];

  // ---------------------------------------------------------------------------
  // Engine: the PPC line, the feed and the directions.
  logic            act_q, act_d;  // a command is running
  logic [AXES-1:0] neg_q, neg_d;  // directions of the running command
  logic            done_q, done_d;
  logic            x_left, y_left, step_x, step_y, line_last;
  logic [AXES-1:0] carry;  // this operation steps the axis
  logic [AXES-1:0] ready;  // the axis may start a pulse on the next clock
  logic [AXES-1:0] unused_block;  // the stage's block_o (READY_Q = 1 only)
  logic            tick, stall, advance, last;

  assign carry    = {act_q && step_y, act_q && step_x};
  assign stall    = |(carry & ~ready);
  assign advance  = tick && !stall && !abort_i;
  assign last     = advance && line_last;
  assign buf_take = buf_valid_q && (!act_q || last) && !abort_i;

  feed_accum #(
    .FEED_W(FEED_W)
  ) u_feed (
    .clk_i,
    .rst_ni,
    .feed_i,
    .run_i     (act_q),
    .hold_i    (stall),
    .run_next_i(act_d),
    .tick_o    (tick)
  );

  ppc_line_step #(
    .MAG_W(ACC_W)
  ) u_line (
    .clk_i,
    .rst_ni,
    .load_i   (buf_take),
    .load_ax_i(buf_ax_q),
    .load_ay_i(buf_ay_q),
    .load_nz_i ({|buf_ay_q, |buf_ax_q}),
    .load_le1_i({buf_ay_q[ACC_W-1:1] == '0, buf_ax_q[ACC_W-1:1] == '0}),
    .advance_i(advance),
    .x_left_o (x_left),
    .y_left_o (y_left),
    .step_x_o (step_x),
    .step_y_o (step_y),
    .last_o   (line_last)
  );

  always_comb begin
    act_d = act_q;
    if (last) act_d = 1'b0;
    if (buf_take) act_d = 1'b1;
    if (abort_i) act_d = 1'b0;
    buf_valid_d = !abort_i && (cmd_take || (buf_valid_q && !buf_take));
    buf_ax_d    = buf_ax_q;
    buf_ay_d    = buf_ay_q;
    buf_neg_d   = buf_neg_q;
    if (cmd_take) begin
      // |-2^(ACC_W-1)| = 2^(ACC_W-1) still fits ACC_W unsigned bits.
      buf_ax_d  = cmd_dx[ACC_W-1] ? ACC_W'(-cmd_dx) : cmd_dx;
      buf_ay_d  = cmd_dy[ACC_W-1] ? ACC_W'(-cmd_dy) : cmd_dy;
      buf_neg_d = {cmd_dy[ACC_W-1], cmd_dx[ACC_W-1]};
    end
    neg_d  = buf_take ? buf_neg_q : neg_q;
    done_d = last;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      buf_valid_q <= 1'b0;
      buf_ax_q    <= '0;
      buf_ay_q    <= '0;
      buf_neg_q   <= '0;
      act_q       <= 1'b0;
      neg_q       <= '0;
      done_q      <= 1'b0;
    end else begin
      buf_valid_q <= buf_valid_d;
      buf_ax_q    <= buf_ax_d;
      buf_ay_q    <= buf_ay_d;
      buf_neg_q   <= buf_neg_d;
      neg_q       <= neg_d;
      act_q       <= act_d;
      done_q      <= done_d;
    end
  end

  // ---------------------------------------------------------------------------
  // Output stage: step/dir timing and position counters.
  step_stage #(
    .AXES (AXES),
    .POS_W(POS_W),
    .TIM_W(TIM_W)
  ) u_out (
    .clk_i,
    .rst_ni,
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .want_valid_i    ({act_q && y_left, act_q && x_left}),
    .want_dir_i      (neg_q),
    .want_dir_next_i (neg_q),  // unused: READY_Q = 0 (measured: READY_Q = 1 costs this core speed)
    .want_step_next_i('0),  // unused: READY_Q = 0
    .fire_i          ({AXES{advance}} & carry),
    .ready_o         (ready),
    .block_o         (unused_block),  // READY_Q = 0: always 0
    .step_o,
    .dir_o,
    .pos_o
  );

  assign busy_o = act_q || buf_valid_q || (|step_o);
  assign done_o = done_q;
endmodule

// dda_line: N-axis digital differential analyzer line interpolator.
//
// command stream -> buffer (|delta|, exponent) -> DDA engine (feed_accum gated) -> step_stage
//
// Command: cmd_delta_i holds one signed (two's complement) ACC_W-bit delta in
// steps per axis, axis i in bits [i*ACC_W +: ACC_W]; it is taken on a clock
// where cmd_valid_i && cmd_ready_o. A one-entry buffer holds the next command
// while the engine runs, so back-to-back commands run without a gap;
// cmd_ready_o is a register.
//
// Normalisation: with M = max |delta_i| and n its bit length, the engine adds
// |delta_i| << (ACC_W - n) to an ACC_W-bit accumulator per axis for 2^n
// iterations; the carry out is a step. Axis i thus steps
// floor(k |delta_i| / 2^n + p) times after k iterations (p = 0, or 1/2 with
// half_preload_i, sampled with the command when it is taken): exactly
// |delta_i| steps, ending on the end point. models/dda_line_model.h states the
// same mathematics and the error bounds. The work is split over the two
// stages a command passes anyway, to keep each clock's path short: taking a
// command registers the magnitudes and n (negate, OR, priority encode); the
// engine shifts them as it loads the command.
//
// Feed (rtl/feed_accum.sv): each clock a FEED_W-bit phase accumulator adds
// feed_i; its carry lets the engine do one iteration. feed_i >= 2^FEED_W is
// full feed (every clock), feed_i = 0 holds the move. The engine stalls, and
// the feed phase holds, whenever an axis that would step is not ready
// (step/dir timing, rtl/step_stage.sv): steps are delayed, never dropped.
//
// Abort: abort_i high at a clock edge ends the running command and drops the
// buffered one (a command transferred on that same edge too); no iteration
// runs on that edge, so no new step starts from it on. A pulse already high
// keeps its full length: busy_o falls at most max(step_len_i, 1) - 1 clocks
// after the abort edge, and pos_o then equals the pulses on the wire, a point
// the command's path visits. No done_o for an aborted command. The core takes
// commands again from the next clock on.
//
// Status: busy_o while a command is buffered or running or a pulse is high;
// done_o pulses for one clock, with the last iteration's steps, per completed
// command; pos_o holds the signed position of each axis, axis i in bits
// [i*POS_W +: POS_W] (wraps at POS_W bits; the testbench refuses commands that
// would wrap it).
//
// Per-axis vectors are flat with `+:` slices, not packed 2-D arrays: Yosys
// 0.23 (Debian 12) cannot parse multi-dimensional packed arrays, and
// Icarus 11 cannot bit-select into them with a loop index.
module dda_line #(
  parameter int AXES   = 2,
  parameter int ACC_W  = 32,
  parameter int POS_W  = 32,
  parameter int TIM_W  = 16,
  parameter int FEED_W = 16
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  // Command stream
  input  logic                   cmd_valid_i,
  output logic                   cmd_ready_o,
  input  logic [AXES*ACC_W-1:0]  cmd_delta_i,
  // Run-time settings
  input  logic [FEED_W:0]        feed_i,
  input  logic                   half_preload_i,
  input  logic [TIM_W-1:0]       step_len_i,
  input  logic [TIM_W-1:0]       step_space_i,
  input  logic [TIM_W-1:0]       dir_setup_i,
  input  logic [TIM_W-1:0]       dir_hold_i,
  input  logic                   abort_i,  // end the move, drop the buffer (one clock)
  // Step/dir and status
  output logic [AXES-1:0]        step_o,
  output logic [AXES-1:0]        dir_o,
  output logic [AXES*POS_W-1:0]  pos_o,
  output logic                   busy_o,
  output logic                   done_o
);
  localparam int ExpW = $clog2(ACC_W + 1);  // holds n in [0, ACC_W]
  localparam int LeftW = ACC_W + 1;  // holds 2^n

  // ---------------------------------------------------------------------------
  // Command buffer (one entry): taken commands wait here as magnitudes, signs
  // and the exponent n.
  logic                  buf_valid_q, buf_valid_d;
  logic [ExpW-1:0]       buf_exp_q;
  logic                  buf_half_q;
  logic                  cmd_take;  // a command is taken this clock
  logic                  buf_take;  // the engine loads the buffer this clock
  logic [AXES*ACC_W-1:0] cmd_mag;  // |delta_i| of the offered command
  logic [ACC_W-1:0]      cmd_any;  // OR of the magnitudes: same bit length as their max
  logic [ExpW-1:0]       cmd_exp;

  assign cmd_ready_o = !buf_valid_q;
  assign cmd_take    = cmd_valid_i && !buf_valid_q;

  always_comb begin
    cmd_any = '0;
    for (int i = 0; i < AXES; i++) cmd_any = cmd_any | cmd_mag[i*ACC_W +: ACC_W];
    cmd_exp = '0;
    for (int b = 0; b < ACC_W; b++) begin
      if (cmd_any[b]) cmd_exp = ExpW'(b + 1);
    end
  end

  // ---------------------------------------------------------------------------
  // Engine: iteration count, feed and the per-axis slices below.
  logic                  act_q, act_d;  // a command is running
  logic [LeftW-1:0]      left_q, left_d;  // iterations still to do
  logic                  done_q;
  logic [AXES-1:0]       carry;  // this iteration steps the axis
  logic [AXES-1:0]       moves;  // the running command moves the axis at all
  logic [AXES-1:0]       neg;  // ...in the negative direction
  logic [AXES-1:0]       ready;  // the axis may start a pulse on the next clock
  logic                  tick, stall, advance, last;

  assign stall    = |(carry & ~ready);
  assign advance  = tick && !stall && !abort_i;
  assign last     = advance && (left_q == LeftW'(1));
  assign buf_take = buf_valid_q && (!act_q || last) && !abort_i;

  feed_accum #(
    .FEED_W(FEED_W)
  ) u_feed (
    .clk_i,
    .rst_ni,
    .feed_i,
    .run_i (act_q),
    .hold_i(stall),
    .tick_o(tick)
  );

  always_comb begin
    act_d  = act_q;
    left_d = left_q;
    if (advance) begin
      left_d = left_q - LeftW'(1);
      if (last) act_d = 1'b0;
    end
    if (buf_take) begin
      act_d  = 1'b1;
      left_d = LeftW'(1) << buf_exp_q;
    end
    if (abort_i) act_d = 1'b0;
    buf_valid_d = !abort_i && (cmd_take || (buf_valid_q && !buf_take));
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      buf_valid_q <= 1'b0;
      buf_exp_q   <= '0;
      buf_half_q  <= 1'b0;
      act_q       <= 1'b0;
      left_q      <= '0;
      done_q      <= 1'b0;
    end else begin
      buf_valid_q <= buf_valid_d;
      if (cmd_take) begin
        buf_exp_q  <= cmd_exp;
        buf_half_q <= half_preload_i;
      end
      act_q  <= act_d;
      left_q <= left_d;
      done_q <= last;
    end
  end

  // ---------------------------------------------------------------------------
  // Per-axis slices: magnitude of the offered delta, its buffer entry and the
  // accumulator.
  for (genvar i = 0; i < AXES; i++) begin : g_axis
    logic [ACC_W-1:0] delta;
    logic             cmd_neg;
    logic [ACC_W-1:0] buf_mag_q;
    logic             buf_neg_q;
    logic [ACC_W-1:0] acc_q, acc_d;
    logic [ACC_W-1:0] inc_q;
    logic             neg_q;
    logic [ACC_W:0]   sum;

    assign delta   = cmd_delta_i[i*ACC_W +: ACC_W];
    assign cmd_neg = delta[ACC_W-1];
    assign cmd_mag[i*ACC_W +: ACC_W] = cmd_neg ? ACC_W'(-delta) : delta;

    assign sum      = {1'b0, acc_q} + {1'b0, inc_q};
    assign carry[i] = sum[ACC_W];
    assign moves[i] = act_q && (inc_q != '0);
    assign neg[i]   = neg_q;
    // A new command restarts the accumulator at 0 or one half.
    assign acc_d = buf_take ? (buf_half_q ? {1'b1, {(ACC_W - 1) {1'b0}}} : '0) :
                   advance  ? sum[ACC_W-1:0] : acc_q;

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        buf_mag_q <= '0;
        buf_neg_q <= 1'b0;
        acc_q     <= '0;
        inc_q     <= '0;
        neg_q     <= 1'b0;
      end else begin
        if (cmd_take) begin
          buf_mag_q <= cmd_mag[i*ACC_W +: ACC_W];
          buf_neg_q <= cmd_neg;
        end
        if (buf_take) begin
          // |delta| << (ACC_W - n); n = 0 only for an all-zero command.
          inc_q <= buf_mag_q << (ExpW'(ACC_W) - buf_exp_q);
          neg_q <= buf_neg_q;
        end
        acc_q <= acc_d;
      end
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
    .want_valid_i(moves),
    .want_dir_i  (neg),
    .fire_i      ({AXES{advance}} & carry),
    .ready_o     (ready),
    .step_o,
    .dir_o,
    .pos_o
  );

  assign busy_o = act_q || buf_valid_q || (|step_o);
  assign done_o = done_q;
endmodule

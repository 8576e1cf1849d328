// dda_line: N-axis digital differential analyzer line interpolator.
//
// command stream -> normalise -> DDA engine (feed-rate gated) -> stepdir_axis per axis
//
// Command: cmd_delta_i holds one signed (two's complement) ACC_W-bit delta in
// steps per axis; it is taken on a clock where cmd_valid_i && cmd_ready_o.
// A one-entry buffer holds the next command while the engine runs, so
// back-to-back commands run without a gap; cmd_ready_o is a register.
//
// Normalisation (on acceptance): with M = max |delta_i| and n its bit length,
// the increments are |delta_i| << (ACC_W - n) and the engine runs 2^n
// iterations. Each iteration adds the increment to an ACC_W-bit accumulator;
// the carry out is a step. Axis i thus steps floor(k |delta_i| / 2^n + p)
// times after k iterations (p = 0, or 1/2 with half_preload_i, sampled with
// the command when it is taken): exactly |delta_i| steps, ending on the end point.
// models/dda_line_model.h states the same mathematics and the error bounds.
//
// Feed: each clock a FEED_W-bit phase accumulator adds feed_i; its carry lets
// the engine do one iteration. feed_i >= 2^FEED_W is full feed (every clock).
// The engine stalls, and the feed phase holds, whenever an axis that would
// step is not ready (step/dir timing): steps are delayed, never dropped.
//
// Status: busy_o while a command is buffered or running or a pulse is high;
// done_o pulses for one clock, with the last iteration's steps, per command;
// pos_o is the signed position of each axis (wraps at POS_W bits; the
// testbench refuses commands that would wrap it).
module dda_line #(
  parameter int AXES   = 2,
  parameter int ACC_W  = 32,
  parameter int POS_W  = 32,
  parameter int TIM_W  = 16,
  parameter int FEED_W = 16
) (
  input  logic                        clk_i,
  input  logic                        rst_ni,
  // Command stream
  input  logic                        cmd_valid_i,
  output logic                        cmd_ready_o,
  input  logic [AXES-1:0][ACC_W-1:0]  cmd_delta_i,
  // Run-time settings
  input  logic [FEED_W:0]             feed_i,
  input  logic                        half_preload_i,
  input  logic [TIM_W-1:0]            step_len_i,
  input  logic [TIM_W-1:0]            step_space_i,
  input  logic [TIM_W-1:0]            dir_setup_i,
  input  logic [TIM_W-1:0]            dir_hold_i,
  // Step/dir and status
  output logic [AXES-1:0]             step_o,
  output logic [AXES-1:0]             dir_o,
  output logic [AXES-1:0][POS_W-1:0]  pos_o,
  output logic                        busy_o,
  output logic                        done_o
);
  localparam int ExpW = $clog2(ACC_W + 1);  // holds n in [0, ACC_W]
  localparam int LeftW = ACC_W + 1;  // holds 2^n

  // ---------------------------------------------------------------------------
  // Normalise the offered command (combinational, registered into the buffer).
  logic [AXES-1:0][ACC_W-1:0] cmd_mag;
  logic [AXES-1:0]            cmd_neg;
  logic [ACC_W-1:0]           cmd_any;  // OR of magnitudes: same bit length as the max
  logic [ExpW-1:0]            cmd_exp;
  logic [AXES-1:0][ACC_W-1:0] cmd_inc;

  for (genvar i = 0; i < AXES; i++) begin : g_norm
    assign cmd_neg[i] = cmd_delta_i[i][ACC_W-1];
    assign cmd_mag[i] = cmd_neg[i] ? ACC_W'(-cmd_delta_i[i]) : cmd_delta_i[i];
    assign cmd_inc[i] = cmd_mag[i] << (ExpW'(ACC_W) - cmd_exp);
  end

  always_comb begin
    cmd_any = '0;
    for (int i = 0; i < AXES; i++) cmd_any = cmd_any | cmd_mag[i];
    cmd_exp = '0;
    for (int b = 0; b < ACC_W; b++) begin
      if (cmd_any[b]) cmd_exp = ExpW'(b + 1);
    end
  end

  // ---------------------------------------------------------------------------
  // One-entry command buffer.
  logic                       buf_valid_q, buf_valid_d;
  logic [AXES-1:0][ACC_W-1:0] buf_inc_q;
  logic [AXES-1:0]            buf_neg_q;
  logic [ExpW-1:0]            buf_exp_q;
  logic                       buf_half_q;
  logic                       cmd_take;  // accepted this clock
  logic                       buf_take;  // moved into the engine this clock

  assign cmd_ready_o = !buf_valid_q;
  assign cmd_take    = cmd_valid_i && !buf_valid_q;

  // ---------------------------------------------------------------------------
  // Engine.
  logic                       act_q, act_d;  // a command is running
  logic [AXES-1:0][ACC_W-1:0] acc_q, acc_d;
  logic [AXES-1:0][ACC_W-1:0] inc_q;
  logic [AXES-1:0]            neg_q;
  logic [LeftW-1:0]           left_q, left_d;  // iterations still to do
  logic [FEED_W-1:0]          feed_q, feed_d;
  logic [AXES-1:0][POS_W-1:0] pos_q, pos_d;
  logic                       done_q;

  logic [AXES-1:0][ACC_W:0]   sum;
  logic [AXES-1:0]            carry;  // this iteration steps the axis
  logic [AXES-1:0]            moves;  // the running command moves the axis at all
  logic [AXES-1:0]            ready;
  logic [FEED_W:0]            feed_sum;
  logic [FEED_W-1:0]          feed_phase;  // feed_sum without its carry
  logic                       feed_full, tick, stall, advance, last;

  // Per-axis slices: accumulator adder, step decision, position counter.
  for (genvar i = 0; i < AXES; i++) begin : g_axis_engine
    assign sum[i]   = {1'b0, acc_q[i]} + {1'b0, inc_q[i]};
    assign carry[i] = sum[i][ACC_W];
    assign moves[i] = act_q && (inc_q[i] != '0);
    // A new command restarts the accumulator at 0 or one half.
    assign acc_d[i] = buf_take ? (buf_half_q ? {1'b1, {(ACC_W - 1) {1'b0}}} : '0) :
                      advance  ? sum[i][ACC_W-1:0] : acc_q[i];
    assign pos_d[i] = !(advance && carry[i]) ? pos_q[i] :
                      neg_q[i] ? pos_q[i] - POS_W'(1) : pos_q[i] + POS_W'(1);
  end

  assign feed_full = feed_i[FEED_W];
  assign feed_sum  = {1'b0, feed_q} + {1'b0, feed_i[FEED_W-1:0]};
  assign feed_phase = feed_sum[FEED_W-1:0];
  assign tick      = act_q && (feed_full || feed_sum[FEED_W]);
  assign stall     = |(carry & ~ready);
  assign advance   = tick && !stall;
  assign last      = advance && (left_q == LeftW'(1));
  assign buf_take  = buf_valid_q && (!act_q || last);

  always_comb begin
    act_d  = act_q;
    left_d = left_q;
    // The feed phase runs while a command runs, and holds on a stalled tick so
    // that the iteration is retried on the next clock.
    feed_d = feed_q;
    if (act_q && !feed_full && !(tick && stall)) feed_d = feed_phase;

    if (advance) begin
      left_d = left_q - LeftW'(1);
      if (last) act_d = 1'b0;
    end
    if (buf_take) begin
      act_d  = 1'b1;
      left_d = LeftW'(1) << buf_exp_q;
    end
    buf_valid_d = cmd_take || (buf_valid_q && !buf_take);
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      buf_valid_q <= 1'b0;
      buf_inc_q   <= '0;
      buf_neg_q   <= '0;
      buf_exp_q   <= '0;
      buf_half_q  <= 1'b0;
      act_q       <= 1'b0;
      acc_q       <= '0;
      inc_q       <= '0;
      neg_q       <= '0;
      left_q      <= '0;
      feed_q      <= '0;
      pos_q       <= '0;
      done_q      <= 1'b0;
    end else begin
      buf_valid_q <= buf_valid_d;
      if (cmd_take) begin
        buf_inc_q <= cmd_inc;
        buf_neg_q <= cmd_neg;
        buf_exp_q <= cmd_exp;
        buf_half_q <= half_preload_i;
      end
      if (buf_take) begin
        inc_q <= buf_inc_q;
        neg_q <= buf_neg_q;
      end
      act_q  <= act_d;
      acc_q  <= acc_d;
      left_q <= left_d;
      feed_q <= feed_d;
      pos_q  <= pos_d;
      done_q <= last;
    end
  end

  // ---------------------------------------------------------------------------
  // Output stage.
  for (genvar i = 0; i < AXES; i++) begin : g_axis
    stepdir_axis #(
      .TIM_W(TIM_W)
    ) u_stepdir (
      .clk_i,
      .rst_ni,
      .step_len_i,
      .step_space_i,
      .dir_setup_i,
      .dir_hold_i,
      .want_valid_i(moves[i]),
      .want_dir_i  (neg_q[i]),
      .fire_i      (advance && carry[i]),
      .ready_o     (ready[i]),
      .step_o      (step_o[i]),
      .dir_o       (dir_o[i])
    );
  end

  assign pos_o  = pos_q;
  assign busy_o = act_q || buf_valid_q || (|step_o);
  assign done_o = done_q;
endmodule

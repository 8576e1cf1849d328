// dda_line: N-axis digital differential analyzer line interpolator.
//
// command stream -> buffer A (|delta|) -> buffer B (normalised) -> DDA engine (feed_accum gated) -> step_stage
//
// Command: cmd_delta_i holds one signed (two's complement) ACC_W-bit delta in
// steps per axis, axis i in bits [i*ACC_W +: ACC_W]; it is taken on a clock
// where cmd_valid_i && cmd_ready_o. Two buffer entries hold the next commands
// while the engine runs, so back-to-back commands run without a gap;
// cmd_ready_o is a register (buffer A empty).
//
// Mathematics: with M = max |delta_i| and n its bit length, the engine runs
// 2^n iterations; axis i has an n-bit accumulator that adds |delta_i| each
// iteration, and its carry out of bit n-1 is a step. Axis i thus steps
// floor(k |delta_i| / 2^n + p) times after k iterations (p = 0, or 1/2 with
// half_preload_i, sampled with the command when it is taken): exactly
// |delta_i| steps, ending on the end point. models/dda_line_model.h states the
// same mathematics and the error bounds.
//
// Datapath: the accumulator is ACC_W bits wide with its bits n and up held at
// one (hm, the command's high mask), so the carry out of bit n-1 runs through
// them to the adder's carry out: no shifter, and the carry is always the top
// bit. Each axis keeps s_q = accumulator + |delta_i| one iteration ahead, so
// this iteration's carry is a register; s_q holds the mask itself (ORed in
// after each add), so an iteration adds s_q + |delta_i| (rtl/dda_axis.sv). Taking a command registers the magnitudes and their OR (buffer
// A); the next clock derives from the OR the command's masks and the first
// accumulator value (buffer B: 2^n - 1, hm, hm + 2^(n-1) with half preload);
// the engine loads buffer B, its first add being that first value plus the
// magnitudes. A command thus reaches an idle engine two clocks after it is
// taken, and its first iteration runs on the third.
//
// Feed (rtl/feed_accum.sv): each clock a FEED_W-bit phase accumulator adds
// feed_i; its carry lets the engine do one iteration. feed_i >= 2^FEED_W is
// full feed (every clock), feed_i = 0 holds the move. The engine stalls, and
// the feed phase holds, whenever an axis that would step is not ready
// (step/dir timing, rtl/step_stage.sv): steps are delayed, never dropped.
// Whether the engine advances depends on registers only (the carries, the
// stage's readiness, the iteration count) and the feed's tick.
//
// Abort: abort_i high at a clock edge ends the running command and drops the
// buffered ones (a command transferred on that same edge too); no iteration
// runs on that edge, so no new step starts from it on. A pulse already high
// keeps its full length: busy_o falls at most L - 1 clocks after the abort
// edge (L: that pulse's step_len), and pos_o then equals the pulses on the
// wire, a point the command's path visits. No done_o for an aborted command.
// The core takes commands again from the next clock on.
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
  parameter int AXES   = 2,   // axes (1..32)
  parameter int ACC_W  = 32,  // signed delta width, accumulator width (2..62)
  parameter int POS_W  = 32,  // position counter width (2..64; wraps)
  parameter int TIM_W  = 16,  // width of the step/dir timing settings (>= 2)
  parameter int FEED_W = 16   // feed phase width (>= 1); feed_i is FEED_W + 1 bits
) (
  input  logic                   clk_i,           // clock
  input  logic                   rst_ni,          // asynchronous, active low
  // Command stream
  input  logic                   cmd_valid_i,     // a command is offered on cmd_*_i
  output logic                   cmd_ready_o,     // the buffer is free: an offered command is taken
  input  logic [AXES*ACC_W-1:0]  cmd_delta_i,     // signed steps, axis i at [i*ACC_W +: ACC_W]
  // Run-time settings
  input  logic [FEED_W:0]        feed_i,          // iterations per clock = feed_i / 2^FEED_W
  input  logic                   half_preload_i,  // sampled with each command
  input  logic [TIM_W-1:0]       step_len_i,      // step pulse length, clocks (0 acts as 1)
  input  logic [TIM_W-1:0]       step_space_i,    // min low time between pulses, clocks
  input  logic [TIM_W-1:0]       dir_setup_i,     // dir stable before a step rises, clocks
  input  logic [TIM_W-1:0]       dir_hold_i,      // dir stable after a step falls, clocks
  input  logic                   abort_i,         // end the move, drop the buffer (one clock)
  // Step/dir and status
  output logic [AXES-1:0]        step_o,          // step pulses, axis i in bit i
  output logic [AXES-1:0]        dir_o,           // 1: negative motion
  output logic [AXES*POS_W-1:0]  pos_o,           // axis i at [i*POS_W +: POS_W]
  output logic                   busy_o,          // a command buffered or running, or a pulse high
  output logic                   done_o           // one clock per completed command
);
  // ---------------------------------------------------------------------------
  // Parameter checks at elaboration: Verilator and Yosys stop with the
  // message (Icarus 11 has no elaboration system tasks: it skips them). The
  // upper bounds are the range the HLS face (hls/dda_line.h), and so the
  // lockstep verification, covers.
`ifndef __ICARUS__
  if (AXES < 1 || AXES > 32) begin : g_bad_axes
    $error("dda_line: parameter AXES must be 1..32");
  end
  if (ACC_W < 2 || ACC_W > 62) begin : g_bad_acc_w
    $error("dda_line: parameter ACC_W must be 2..62");
  end
  if (POS_W < 2 || POS_W > 64) begin : g_bad_pos_w
    $error("dda_line: parameter POS_W must be 2..64");
  end
  if (TIM_W < 2) begin : g_bad_tim_w
    $error("dda_line: parameter TIM_W must be >= 2");
  end
  if (FEED_W < 1) begin : g_bad_feed_w
    $error("dda_line: parameter FEED_W must be >= 1");
  end
`endif

  // ---------------------------------------------------------------------------
  // Buffer A: the taken command as magnitudes, signs and the OR of the
  // magnitudes (same bit length as their maximum).
  logic                  a_valid_q, a_valid_d;
  logic [ACC_W-1:0]      a_any_q, a_any_d;
  logic                  a_half_q, a_half_d;
  logic                  cmd_take;  // a command is taken this clock
  logic                  a_to_b;  // buffer A moves to buffer B this clock
  logic [AXES*ACC_W-1:0] cmd_mag;  // |delta_i| of the offered command
  logic [ACC_W-1:0]      cmd_any;

  assign cmd_ready_o = !a_valid_q;
  assign cmd_take    = cmd_valid_i && !a_valid_q;

  always_comb begin
    cmd_any = '0;
    for (int i = 0; i < AXES; i++) cmd_any = cmd_any | cmd_mag[i*ACC_W +: ACC_W];
  end

  // ---------------------------------------------------------------------------
  // Buffer B: the command normalised. low = 2^n - 1 (bits below n: the
  // iterations to run after the first), hm = ~low, a0 = the first
  // accumulator value (hm, plus 2^(n-1) with half preload).
  logic                  b_valid_q, b_valid_d;
  logic [ACC_W-1:0]      b_low_q, b_low_d, b_hm_q, b_hm_d, b_a0_q, b_a0_d;
  logic                  b_low_zero_q, b_low_zero_d;  // b_low_q == 0
  logic                  b_low_one_q, b_low_one_d;  // b_low_q == 1
  logic                  load;  // the engine loads buffer B this clock
  logic                  pre_load_q, pre_load_d;  // ...if it advances (or is idle): a register
  logic [ACC_W-1:0]      a_low, a_hm, a_top;

  dda_norm #(
    .W(ACC_W)
  ) u_norm (
    .any_i(a_any_q),
    .low_o(a_low),
    .hm_o (a_hm),
    .top_o(a_top)
  );

  // ---------------------------------------------------------------------------
  // Engine: iteration count, feed and the per-axis slices below.
  logic                  act_q, act_d;  // a command is running
  logic [ACC_W-1:0]      left_q, left_d;  // iterations still to do after this one
  logic                  left_zero_q, left_zero_d;  // left_q == 0: this iteration is the last
  logic                  left_one_q, left_one_d;  // left_q == 1
  logic [ACC_W-1:0]      hm_q, hm_d;
  logic                  done_q, done_d;
  logic [AXES-1:0]       carry;  // this iteration steps the axis
  logic [AXES-1:0]       carry_next;  // carry on the next clock (the stage decides block a clock ahead)
  logic [AXES-1:0]       moves;  // the running command moves the axis at all
  logic [AXES-1:0]       neg;  // ...in the negative direction
  logic [AXES-1:0]       neg_next;  // neg on the next clock (the stage decides ready a clock ahead)
  logic [AXES-1:0]       unused_ready;  // the stall reads block instead
  logic [AXES-1:0]       block;  // the axis must step and is not ready: stall (a register)
  logic                  tick, stall, advance, last;

  // The adders' operands select on pre_load_q, not load, and every next state
  // below is a choice by advance between two values computed from registers:
  // the clock's late signal enters each register at its last gate.
  // pre_load_q == b_valid_q && (!act_q || left_zero_q), kept as a register.
  // The stall is an OR of registers, one per axis: the stage's block_o,
  // decided a clock ahead from the next clock's carry (carry_next).
  // The counts' compares are registers too (left_one_q, b_low_zero_q,
  // b_low_one_q), so these next states are small cones of registers: a
  // compare inside one would let the mapper (ABC) put the late advance
  // under more LUT levels.
  // Buffer A moves on only into an empty buffer B, so neither depends on the
  // clock's advance; a command still reaches B a clock before the engine can
  // load it again (2^n >= 1 iterations, and cmd_ready_o lets in one command
  // per two clocks at most).
  assign stall   = |block;
  assign advance = tick && !stall && !abort_i;
  assign last    = advance && left_zero_q;
  assign load    = pre_load_q && (!act_q || advance) && !abort_i;
  assign a_to_b  = a_valid_q && !b_valid_q && !abort_i;

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

  // Each next state below is advance ? (its value if the engine advances) :
  // (its value if not), both from registers: the clock's late signal enters
  // at the last gate. Without an advance only an idle engine loads.
  logic idle_load;
  logic act_adv, act_idle, lz_adv, lz_idle, bv_adv, bv_idle;
  assign idle_load = pre_load_q && !act_q && !abort_i;
  assign act_adv   = pre_load_q || !left_zero_q;
  assign act_idle  = (act_q && !abort_i) || idle_load;
  assign lz_adv    = pre_load_q ? b_low_zero_q : left_one_q;
  assign lz_idle   = idle_load ? b_low_zero_q : left_zero_q;
  assign bv_adv    = a_to_b || (b_valid_q && !pre_load_q);
  assign bv_idle   = !abort_i && (a_to_b || (b_valid_q && !idle_load));

  assign act_d       = advance ? act_adv : act_idle;
  assign left_zero_d = advance ? lz_adv : lz_idle;
  assign left_one_d  = advance ? (pre_load_q ? b_low_one_q : (left_q == ACC_W'(2))) :
                                 (idle_load ? b_low_one_q : left_one_q);
  assign left_d      = advance ? (pre_load_q ? b_low_q : left_q - ACC_W'(1)) :
                                 (idle_load ? b_low_q : left_q);
  assign b_valid_d   = advance ? bv_adv : bv_idle;
  assign pre_load_d  = advance ? bv_adv && (!act_adv || lz_adv) : bv_idle && (!act_idle || lz_idle);
  assign a_valid_d   = !abort_i && (cmd_take || (a_valid_q && !a_to_b));
  assign a_any_d     = cmd_take ? cmd_any : a_any_q;
  assign a_half_d    = cmd_take ? half_preload_i : a_half_q;
  assign b_low_d     = a_to_b ? a_low : b_low_q;
  assign b_hm_d      = a_to_b ? a_hm : b_hm_q;
  assign b_a0_d      = a_to_b ? a_hm | (a_half_q ? a_top : '0) : b_a0_q;
  // low = 2^n - 1 is 0 (1) just when the magnitudes' OR is 0 (1).
  assign b_low_zero_d = a_to_b ? (a_any_q == '0) : b_low_zero_q;
  assign b_low_one_d  = a_to_b ? (a_any_q == ACC_W'(1)) : b_low_one_q;
  assign hm_d        = load ? b_hm_q : hm_q;
  assign done_d      = last;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      a_valid_q    <= 1'b0;
      a_any_q      <= '0;
      a_half_q     <= 1'b0;
      b_valid_q    <= 1'b0;
      pre_load_q   <= 1'b0;
      b_low_q      <= '0;
      b_hm_q       <= '0;
      b_a0_q       <= '0;
      b_low_zero_q <= 1'b0;
      b_low_one_q  <= 1'b0;
      act_q        <= 1'b0;
      left_q       <= '0;
      left_zero_q  <= 1'b0;
      left_one_q   <= 1'b0;
      hm_q         <= '0;
      done_q       <= 1'b0;
    end else begin
      a_valid_q    <= a_valid_d;
      a_any_q      <= a_any_d;
      a_half_q     <= a_half_d;
      b_valid_q    <= b_valid_d;
      pre_load_q   <= pre_load_d;
      b_low_q      <= b_low_d;
      b_hm_q       <= b_hm_d;
      b_a0_q       <= b_a0_d;
      b_low_zero_q <= b_low_zero_d;
      b_low_one_q  <= b_low_one_d;
      act_q        <= act_d;
      left_q       <= left_d;
      left_zero_q  <= left_zero_d;
      left_one_q   <= left_one_d;
      hm_q         <= hm_d;
      done_q       <= done_d;
    end
  end

  // ---------------------------------------------------------------------------
  // Per-axis slices: the offered magnitude, buffers A and B, the engine's
  // increment and lookahead sum (carry = s_q[ACC_W]).
  for (genvar i = 0; i < AXES; i++) begin : g_axis
    logic [ACC_W-1:0] delta;
    logic             cmd_neg;
    logic [ACC_W-1:0] a_mag_q, a_mag_d, b_mag_q, b_mag_d;
    logic             a_neg_q, a_neg_d, b_neg_q, b_neg_d, neg_q, neg_d;
    logic             a_moves_q, a_moves_d, b_moves_q, b_moves_d, moves_q, moves_d;

    assign delta = cmd_delta_i[i*ACC_W +: ACC_W];
    magnitude #(
      .W(ACC_W)
    ) u_mag (
      .x_i  (delta),
      .mag_o(cmd_mag[i*ACC_W +: ACC_W]),
      .neg_o(cmd_neg)
    );

    // The accumulator (s_q is written only on a load or an advance, and then
    // pre_load_q == load).
    dda_axis #(
      .W         (ACC_W),
      .MODULUS_2N(1'b1)
    ) u_acc (
      .clk_i,
      .rst_ni,
      .pre_i       (pre_load_q),
      .ld_i        (load),
      .en_i        (load || advance),
      .a0_i        (b_a0_q),
      .b_mag_i     (b_mag_q),
      .b_dc_i      ('0),
      .hm_i        (hm_q),
      .carry_o     (carry[i]),
      .carry_next_o(carry_next[i])
    );

    // A load brings the next command's; the last iteration or an abort ends it.
    assign moves_d  = advance ? (pre_load_q ? b_moves_q : moves_q && !left_zero_q) :
                                (idle_load ? b_moves_q : moves_q && !abort_i);
    assign moves[i] = moves_q;
    assign neg[i]   = neg_q;
    assign neg_next[i] = neg_d;
    assign a_mag_d   = cmd_take ? cmd_mag[i*ACC_W +: ACC_W] : a_mag_q;
    assign a_neg_d   = cmd_take ? cmd_neg : a_neg_q;
    assign a_moves_d = cmd_take ? (delta != '0) : a_moves_q;
    assign b_mag_d   = a_to_b ? a_mag_q : b_mag_q;
    assign b_neg_d   = a_to_b ? a_neg_q : b_neg_q;
    assign b_moves_d = a_to_b ? a_moves_q : b_moves_q;
    assign neg_d     = load ? b_neg_q : neg_q;

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        a_mag_q   <= '0;
        a_neg_q   <= 1'b0;
        a_moves_q <= 1'b0;
        b_mag_q   <= '0;
        b_neg_q   <= 1'b0;
        b_moves_q <= 1'b0;
        neg_q     <= 1'b0;
        moves_q   <= 1'b0;
      end else begin
        a_mag_q   <= a_mag_d;
        a_neg_q   <= a_neg_d;
        a_moves_q <= a_moves_d;
        b_mag_q   <= b_mag_d;
        b_neg_q   <= b_neg_d;
        b_moves_q <= b_moves_d;
        neg_q     <= neg_d;
        moves_q   <= moves_d;
      end
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
    .want_valid_i    (moves),
    .want_dir_i      (neg),
    .want_dir_next_i (neg_next),
    .want_step_next_i(carry_next),
    .fire_i          ({AXES{advance}} & carry),
    .ready_o         (unused_ready),
    .block_o         (block),
    .step_o,
    .dir_o,
    .pos_o
  );

  assign busy_o = act_q || a_valid_q || b_valid_q || (|step_o);
  assign done_o = done_q;

`ifdef FORMAL
  // ---------------------------------------------------------------------------
  // Formal (scripts/formal.sh, rtl/formal/dda_line_props.sv): the port
  // contract every core shares (rtl/formal/core_contract.sv) with the
  // commands buffers A and B and the engine hold, and the invariants of the
  // registers it rests on (each a register kept equal to what it stands for).
  logic [1:0] f_held;  // also read by log_stepper's proof (scripts/formal.sh links it)
  assign f_held = 2'(a_valid_q) + 2'(b_valid_q) + 2'(act_q);

  core_contract #(
    .AXES  (AXES),
    .TIM_W (TIM_W),
    .CAP   (3),
    .HELD_W(2)
  ) u_contract (
    .clk_i,
    .rst_ni,
    .cmd_valid_i,
    .cmd_ready_o,
    .abort_i,
    .step_len_i,
    .step_o,
    .busy_o,
    .done_o,
    .held_i(f_held)
  );

  // Progress: while a command runs with full feed (feed_i >= 2^FEED_W on the
  // clock before) and no abort, the engine advances on every clock but one on
  // which an axis its iteration steps is not ready: it waits for the step/dir
  // timing only, and rtl/formal/stepdir_axis_props.sv proves that ready_o waits
  // for exactly that (never longer; dir_o turns as soon as the hold allows).
  logic f_full_q, f_full_d;
  assign f_full_d = feed_i[FEED_W];
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) f_full_q <= 1'b0;
    else f_full_q <= f_full_d;
  end

  always_comb begin
    if (rst_ni) begin
      a_progress: assert(!(act_q && f_full_q && !abort_i) || advance || (carry & ~unused_ready) != '0);
      a_pre_load: assert(pre_load_q == (b_valid_q && (!act_q || left_zero_q)));
      a_tick: assert(!tick || act_q);
      a_left: assert(!act_q || (left_zero_q == (left_q == '0) && left_one_q == (left_q == ACC_W'(1))));
      a_b_low: assert(!b_valid_q || (b_low_zero_q == (b_low_q == '0) &&
                                     b_low_one_q == (b_low_q == ACC_W'(1))));
    end
  end
`endif
endmodule

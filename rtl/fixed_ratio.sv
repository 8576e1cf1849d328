// fixed_ratio: N-axis fixed-ratio (velocity-synthesis) line generator
// (paper 004_dc68f1177cad466f.txt): one computation per line sets a rate per
// axis in the ratio of the axis deltas; per axis a fixed-rate pulse generator
// then sends exactly |delta_i| pulses.
//
// command stream -> buffer (|delta|, M, rate dividers) -> engine (feed_accum gated) -> step_stage
//
// Command: cmd_delta_i holds one signed (two's complement) ACC_W-bit delta in
// steps per axis, axis i in bits [i*ACC_W +: ACC_W]; it is taken on a clock
// where cmd_valid_i && cmd_ready_o (cmd_ready_o is a register: the buffer is
// free). Taking a command registers |delta_i| and the signs.
//
// Per-line computation, in the buffer: with M = max_i |delta_i| (a true
// maximum) the rate word of axis i is
//     R_i = ceil(|delta_i| 2^FRAC_W / M)
// (a fixed-point fraction with FRAC_W fraction bits; the major axis gets
// exactly 1.0 = 2^FRAC_W). One divider per axis, all in parallel, FRAC_W + 2
// clocks:
//   1. M: every pair of magnitudes compared at once (one carry chain deep),
//      into registers. Computing M at the take instead (negate, then a chain
//      of AXES compares) made that the critical path (29 MHz on iCE40 HX8K
//      with 4 axes); the compares and the remainder step in one clock made
//      it 61-73 MHz.
//   2. the integer bit, |delta_i| >= M, i.e. the axis is a maximum (from the
//      registered compares; a maximal axis's R is 2^FRAC_W); M, the OR of
//      the maximal magnitudes (all equal).
//   3. FRAC_W fraction bits, one a clock, by non-restoring division: the
//      register holds rem - M, the bit is its sign (a register), and the
//      step adds -M or +M as that sign says, so no choice follows the carry
//      chain (a restoring step, rem -= M when rem >= M, put 3-4 LUTs after
//      it: 89 MHz on HX8K with 4 axes). The last bit is the sign of the
//      final remainder.
// The dividend is |delta_i| 2^FRAC_W + M - 1, so the quotient is the
// rounded-up one itself (no increment after the division, no remainder
// test); its low FRAC_W bits are M - 1, shifted in from a register loaded
// with M - 1 in the first fraction clock (they are needed from the third
// on when FRAC_W >= ACC_W + 1). Rounding up, not to nearest: with
// any rounding error e_i = R_i / 2^FRAC_W - |delta_i| / M >= 0 a step due
// exactly on a tick stays on it, so the generator is tick for tick the
// paper's exact-frequency generator whenever 2 M^2 <= 2^FRAC_W
// (models/fixed_ratio_model.h; to nearest it is not, e.g. on (6,5)).
// Zero-length commands (M = 0) skip the division.
//
// Latency and gaps: a command is loaded into the engine at the earliest
// FRAC_W + 3 clocks after the clock that took it (on the clock after the
// FRAC_W + 2 divider clocks: the load reads the quotient from registers
// only); a zero-length one 1 clock after. The division runs while the
// previous command runs; the buffer frees on the clock that loads the
// engine and takes the next command one clock later, so a command is loaded
// at the earliest FRAC_W + 4 clocks after the previous one. Back-to-back
// commands therefore run without a gap when each runs at least FRAC_W + 4
// clocks from its load to its last tick; after a shorter one (C clocks) the
// engine idles FRAC_W + 4 - C clocks before the next one's load. At feed 1/2
// with 1-clock pulses and spaces (nothing stalls) a command runs
// C = 2 max(M, 1) clocks: no gap from M >= (FRAC_W + 4) / 2 on (20 steps at
// FRAC_W = 35), short lines back to back one per FRAC_W + 4 clocks (tested
// in tests/tb/fixed_ratio_test.cpp).
//
// Engine: per axis a FRAC_W-bit phase accumulator, started at one half (the
// paper's mid-period step edge, its Eqs. 9/10), adds R_i on each feed tick;
// its carry is a step. It is kept one tick ahead: the tick's carry as a
// register, and the next tick's phase + R_i (FRAC_W + 1 bits), whose carry
// is the next tick's step: the step/dir stage, which decides the stall a
// clock ahead, reads a register either way, and the adder (from registers)
// only feeds the next tick's register. After k ticks axis i has stepped
//     floor(k R_i / 2^FRAC_W + 1/2)
// times. A per-axis down counter, loaded with |delta_i|, stops the axis after
// exactly |delta_i| pulses, and the command completes when every counter is
// 0. The major axis (rate 1.0) steps on every tick; with rates rounded up no
// other axis can lag (each is due its |delta_i| pulses by tick M, whatever
// FRAC_W), and none runs ahead of its count when M 2^-FRAC_W <= 1/2, i.e. for
// every M the widths accept when FRAC_W >= ACC_W: the counters never clip a
// step, and every command completes in exactly M ticks (proof in
// models/fixed_ratio_model.h). A zero-length command takes one tick with no
// step, then done_o.
//
// Path error (normal distance of every visited point from the ideal line, in
// steps): the lag of minor axis i from the exact line lies in
// (-1/2, 1/2 + M e_i] with M e_i < M 2^-FRAC_W <= 2^(ACC_W-1-FRAC_W); the
// major axis has none. 2 axes: error <= (M / L) (1/2 + M e) <=
// (|dx| + |dy|) / (2 L) + M^2 2^-FRAC_W / L. N axes:
// error <= sqrt(N - 1) (1/2 + 2^(ACC_W-1-FRAC_W)); FRAC_W = ACC_W + 3 makes
// the rounding term <= 1/16 and the bound < 1 for N <= 4 (0.974 for 4 axes).
// models::fixed_ratio_hw_bound() gives the per-command bound the testbench
// checks on every move.
//
// Feed (rtl/feed_accum.sv): each clock a FEED_W-bit phase accumulator adds
// feed_i; its carry lets the engine do one tick. feed_i >= 2^FEED_W is full
// feed (every clock), feed_i = 0 holds the move. The engine stalls, and the
// feed phase holds, whenever an axis that must step is not ready (step/dir
// timing, rtl/step_stage.sv): steps are delayed, never dropped.
//
// Abort: abort_i high at a clock edge ends the running command and drops the
// buffered one (a command transferred on that same edge too, and a division
// in progress); no tick runs on that edge, so no new step starts from it on.
// A pulse already high keeps its full length: busy_o falls at most
// max(step_len_i, 1) - 1 clocks after the abort edge, and pos_o then equals
// the pulses on the wire, a point the command's path visits. No done_o for an
// aborted command. The core takes commands again from the next clock on.
//
// Status: busy_o while a command is buffered (or being divided) or running
// or a pulse is high; done_o pulses for one clock, with the last tick's
// steps, per completed command; pos_o holds the signed position of each axis,
// axis i in bits [i*POS_W +: POS_W] (wraps at POS_W bits; the testbench
// refuses commands that would wrap it). dir_o = 1: negative motion.
//
// Per-axis vectors are flat with `+:` slices, not packed 2-D arrays: Yosys
// 0.23 (Debian 12) cannot parse multi-dimensional packed arrays, and
// Icarus 11 cannot bit-select into them with a loop index. Constant part
// selects are continuous assignments (Icarus 11 does not support them inside
// always_* processes).
module fixed_ratio #(
  parameter int AXES   = 2,   // axes (1..32)
  parameter int ACC_W  = 32,  // width of each signed delta of cmd_delta_i (2..63)
  parameter int FRAC_W = 35,  // rate-word fraction bits: ACC_W + 1..62 (exact counts; the divider)
  parameter int POS_W  = 32,  // position counter width (2..64; wraps)
  parameter int TIM_W  = 16,  // width of the step/dir timing settings and counters (>= 2)
  parameter int FEED_W = 16   // feed phase width (>= 1); feed_i = 2^FEED_W is full feed
) (
  input  logic                  clk_i,         // clock
  input  logic                  rst_ni,        // asynchronous, active low
  // Command stream
  input  logic                  cmd_valid_i,   // a command is offered on cmd_delta_i
  output logic                  cmd_ready_o,   // the buffer is free: an offered command is taken
  input  logic [AXES*ACC_W-1:0] cmd_delta_i,   // signed delta of axis i at [i*ACC_W +: ACC_W]
  // Run-time settings
  input  logic [FEED_W:0]       feed_i,        // ticks per clock = feed_i / 2^FEED_W
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
  // Parameter checks at elaboration: Verilator and Yosys stop with the
  // message (Icarus 11 has no elaboration system tasks: it skips them).
  // FRAC_W >= ACC_W + 1: no minor axis lags past tick M
  // (models/fixed_ratio_model.h), and the divider's dividend bits come in
  // time (below). The upper bounds are the range the HLS face
  // (hls/fixed_ratio.h), and so the lockstep verification, covers.
`ifndef __ICARUS__
  if (AXES < 1 || AXES > 32) begin : g_bad_axes
    $error("fixed_ratio: parameter AXES must be 1..32");
  end
  if (ACC_W < 2 || ACC_W > 63) begin : g_bad_acc_w
    $error("fixed_ratio: parameter ACC_W must be 2..63");
  end
  if (FRAC_W < ACC_W + 1 || FRAC_W > 62) begin : g_bad_frac_w
    $error("fixed_ratio: parameter FRAC_W must be ACC_W + 1..62");
  end
  if (POS_W < 2 || POS_W > 64) begin : g_bad_pos_w
    $error("fixed_ratio: parameter POS_W must be 2..64");
  end
  if (TIM_W < 2) begin : g_bad_tim_w
    $error("fixed_ratio: parameter TIM_W must be >= 2");
  end
  if (FEED_W < 1) begin : g_bad_feed_w
    $error("fixed_ratio: parameter FEED_W must be >= 1");
  end
`endif

  localparam int DivN = FRAC_W + 2;  // divider clocks: compares, integer bit, FRAC_W fraction bits
  localparam int DivW = $clog2(DivN + 1);  // holds the divider clocks left, 0..DivN
  localparam logic [DivW-1:0] DivClocks = DivW'(DivN);

  // ---------------------------------------------------------------------------
  // Command buffer (one entry): magnitudes and signs of the taken command,
  // M, and the dividers that turn them into rate words while the engine runs.
  logic                  buf_valid_q, buf_valid_d;
  // ~M, M = max |delta_i| the divisor (from divider clock 3 on): inverted, so
  // that the carry chain of rem - M = rem + ~M + 1 takes a register (M itself
  // would need an inverter LUT in front of the chain).
  logic [ACC_W-1:0]      max_n_q, max_n_d;
  logic [DivW-1:0]       div_left_q, div_left_d;  // divider clocks still to run
  logic                  div_done_q, div_done_d;  // div_left_q == 0: the rate words are in quot_q
  logic                  cmd_take;  // a command is taken this clock
  logic                  buf_take;  // the engine loads the buffer this clock
  logic                  div_run;  // the dividers run one of their clocks
  logic [2:0]            ph_q, ph_d;  // bit k: divider clock k + 1 (compares, integer bit, first fraction bit)
  logic                  buf_ready;  // the buffered command's rate words are ready
  logic [AXES*ACC_W-1:0] buf_mag;  // |delta_i| of the buffered command at [i*ACC_W +: ACC_W]
  logic [AXES*AXES-1:0]  cmp_ge, cmp_eq;  // bit i*AXES + j, i < j: |delta_i| >= (=) |delta_j|
  logic [AXES*AXES-1:0]  ge_q, ge_d, eq_q, eq_d;  // ...registered in divider clock 1
  logic [AXES*AXES-1:0]  ge;  // bit i*AXES + j: |delta_i| >= |delta_j|, from ge_q and eq_q
  logic [AXES-1:0]       is_max;  // |delta_i| = M: the axis's integer quotient bit
  logic [ACC_W-1:0]      max;  // M, the OR of the maximal magnitudes (all equal)
  logic [FRAC_W-1:0]     low_q, low_d;  // the dividend's low bits (M - 1) still to shift in, next in the MSB
  logic                  cmd_zero;  // the offered command is zero-length

  assign cmd_ready_o = !buf_valid_q;
  assign cmd_take    = cmd_valid_i && !buf_valid_q;
  assign div_run     = buf_valid_q && (div_left_q != '0);
  assign buf_ready   = buf_valid_q && div_done_q;
  assign cmd_zero    = (cmd_delta_i == '0);

  // M, a true maximum: every pair compared at once in the first divider
  // clock (one carry chain deep, not a chain of compares) into registers; in
  // the second, is_max = the magnitude is >= all others (the integer
  // quotient bit, |delta_i| >= M) and M is the OR of the maximal
  // magnitudes.
  for (genvar i = 0; i < AXES; i++) begin : g_max
    for (genvar j = 0; j < AXES; j++) begin : g_pair
      if (i < j) begin : g_cmp  // one compare per pair
        assign cmp_ge[i*AXES+j] = buf_mag[i*ACC_W +: ACC_W] >= buf_mag[j*ACC_W +: ACC_W];
        assign cmp_eq[i*AXES+j] = buf_mag[i*ACC_W +: ACC_W] == buf_mag[j*ACC_W +: ACC_W];
        assign ge[i*AXES+j]     = ge_q[i*AXES+j];
      end else begin : g_mirror  // j <= i: from the pair's compare
        assign cmp_ge[i*AXES+j] = 1'b0;
        assign cmp_eq[i*AXES+j] = 1'b0;
        assign ge[i*AXES+j]     = (i == j) || !ge_q[j*AXES+i] || eq_q[j*AXES+i];
      end
    end
    assign is_max[i] = &ge[i*AXES +: AXES];
  end
  always_comb begin
    max = '0;
    for (int i = 0; i < AXES; i++) max = max | (is_max[i] ? buf_mag[i*ACC_W +: ACC_W] : '0);
  end

  // The dividend's low FRAC_W bits, M - 1 (< 2^(ACC_W-1)), MSB first, one
  // clock after the restoring division would take each (the non-restoring
  // step of clock k + 1 adds the bit of rem's step in clock k): cleared in the
  // first divider clock, so that the first and second fraction clocks shift
  // in zeros (bits FRAC_W - 1 and FRAC_W - 2 of M - 1, both 0 as FRAC_W >=
  // ACC_W + 1); loaded in the first fraction clock, aligned so that its MSB
  // is the bit the second one shifts in; shifted left every clock.
  assign low_d = ph_q[2] ? FRAC_W'({~(max_n_q + ACC_W'(1)), 1'b0}) :  // ~(~M + 1) = M - 1
                 ph_q[0] ? '0 : {low_q[FRAC_W-2:0], 1'b0};
  // A division's clocks 1-3; an abort clears them (its division ends).
  assign ph_d  = abort_i ? '0 : {ph_q[1:0], cmd_take && !cmd_zero};
  assign ge_d  = ph_q[0] ? cmp_ge : ge_q;
  assign eq_d  = ph_q[0] ? cmp_eq : eq_q;
  assign max_n_d = ph_q[1] ? ~max : max_n_q;

  // ---------------------------------------------------------------------------
  // Engine: completion, feed and the per-axis slices below.
  logic            act_q, act_d;  // a command is running
  logic            done_q, done_d;
  logic [AXES-1:0] left;  // the axis still has pulses to send
  logic [AXES-1:0] carry;  // its phase carries on this tick
  logic [AXES-1:0] must;  // it steps on this tick
  logic [AXES-1:0] must_next;  // must on the next clock (the stage decides block a clock ahead)
  logic [AXES-1:0] major;  // the axis is a major axis of the running command (|delta_i| = M)
  logic [AXES-1:0] two;  // its pulse counter is at 2
  logic [AXES-1:0] buf_le1;  // the buffered command's |delta_i| <= 1
  logic            last_q, last_d;  // the running command's next tick is its last
  logic [AXES-1:0] neg;  // direction of the running command (1: negative)
  logic [AXES-1:0] neg_next;  // neg on the next clock (the stage decides ready a clock ahead)
  logic [AXES-1:0] unused_ready;  // the stall reads block instead
  logic [AXES-1:0] block;  // the axis must step and is not ready: stall (a register)
  logic            tick, stall, advance, last;
  logic            take_adv, take_idle;  // the engine loads the buffer if it advances, if not

  // Every next state below that the advance decides is written
  // advance ? (its value if the engine advances) : (its value if not), both
  // from registers (last_q, the counters' compares, buf_ready are registers
  // or small cones of them): the clock's late signal enters each register at
  // its last gate, as in rtl/dda_line.sv. A tick comes only with act_q
  // (rtl/feed_accum.sv) and never with an abort. The stall is an OR of
  // registers, one per axis: the stage's block_o, decided a clock ahead from
  // the next clock's must (must_next).
  // Completion: every command completes in exactly max(M, 1) ticks, and a
  // major axis (rate 1.0) steps on every one of them, so its pulse counter
  // counts the ticks left; no other axis has a pulse left after tick M
  // (models/fixed_ratio_model.h). So "every axis has sent its last pulse
  // with this tick" is last_q: set at the load when M <= 1, else when a
  // tick leaves a major axis's counter at 1. (The HLS core tests every
  // axis's counter instead; the lockstep compares the two.)
  assign must      = carry & left;
  assign stall     = |block;
  assign advance   = tick && !stall && !abort_i;
  assign last      = advance && last_q;
  assign take_adv  = buf_ready && last_q;
  assign take_idle = buf_ready && !act_q && !abort_i;
  assign buf_take  = advance ? take_adv : take_idle;

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

  always_comb begin
    act_d = advance ? (!last_q || take_adv) : ((act_q && !abort_i) || take_idle);
    last_d = advance ? (take_adv ? (&buf_le1) : |(major & two)) : (take_idle ? (&buf_le1) : last_q);
    buf_valid_d = advance ? (cmd_take || (buf_valid_q && !take_adv)) :
                            (!abort_i && (cmd_take || (buf_valid_q && !take_idle)));
    // The clock after the last divider clock may load the engine.
    div_left_d  = div_left_q;
    if (div_run) div_left_d = div_left_q - DivW'(1);
    if (cmd_take) div_left_d = cmd_zero ? '0 : DivClocks;
    // div_left_d == 0, as a choice of registers and the take: no compare
    // after the take's choice (ECP5: in_q -> div_done_q was 3-5 LUT + 1-3 mux).
    div_done_d = cmd_take ? cmd_zero : div_run ? (div_left_q == DivW'(1)) : div_done_q;
    done_d     = last;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      buf_valid_q <= 1'b0;
      max_n_q     <= '0;
      div_left_q  <= '0;
      div_done_q  <= 1'b1;
      ph_q        <= '0;
      ge_q        <= '0;
      eq_q        <= '0;
      low_q       <= '0;
      act_q       <= 1'b0;
      last_q      <= 1'b0;
      done_q      <= 1'b0;
    end else begin
      buf_valid_q <= buf_valid_d;
      div_left_q  <= div_left_d;
      div_done_q  <= div_done_d;
      ph_q        <= ph_d;
      low_q       <= low_d;
      ge_q        <= ge_d;
      eq_q        <= eq_d;
      max_n_q     <= max_n_d;
      act_q       <= act_d;
      last_q      <= last_d;
      done_q      <= done_d;
    end
  end

`ifdef FORMAL
  // Per axis: the flag registers equal the compares they stand for (below).
  logic [AXES-1:0] f_cnt_ok;
`endif

  // ---------------------------------------------------------------------------
  // Per-axis slices: the magnitude of the offered delta, its buffer entry and
  // divider, and the engine's phase accumulator and pulse counter.
  for (genvar i = 0; i < AXES; i++) begin : g_axis
    logic [ACC_W-1:0] delta;
    logic             cmd_neg;
    logic [ACC_W-1:0] cmd_mag;  // |delta_i| of the offered command
    // Buffer and divider
    logic [ACC_W-1:0] buf_mag_q, buf_mag_d;  // |delta_i|
    logic             buf_neg_q, buf_neg_d;
    logic             buf_nz_q, buf_nz_d;  // |delta_i| != 0
    logic             buf_one_q, buf_one_d;  // |delta_i| == 1
    // Non-restoring division: s = rem - M (two's complement, -M <= s < M),
    // so that the quotient bit is s's sign, a register, and a step adds +M or
    // -M as that register says (no choice after the carry chain).
    logic [ACC_W-1:0] s_q, s_d;  // rem - M; |delta_i| after divider clock 2
    logic             s_neg;  // s < 0: the quotient bit of this remainder is 0
    logic             zap_q, zap_d;  // divider clock 3 of a maximal axis: its remainder is 0
    logic [ACC_W-1:0] op_a, op_b;  // the step's operands: 2 s + the dividend bit, and -M or +M
    logic             op_c;  // its carry in (-M = ~M + 1)
    /* verilator lint_off UNUSEDSIGNAL */
    logic [ACC_W:0]   step;  // {op_a + op_b + op_c, the carry in's bit}
    /* verilator lint_on UNUSEDSIGNAL */
    logic [FRAC_W-2:0] quot_q, quot_d;  // fraction bits but the last, the latest in bit 0
    logic [FRAC_W:0]  rate_load;  // R of the buffered command, once its division is done
    // Engine: the rate word R <= 2^FRAC_W, and the phase accumulator kept one
    // tick ahead: this tick's carry as a register, and the next tick's
    // phase + R, so that the carry the stage reads a clock ahead is a
    // register too (no add between a register and the stall).
    logic [FRAC_W:0]  rate_q, rate_d;  // R = ceil(|delta_i| 2^FRAC_W / M)
    logic             car_q, car_d;  // this tick's carry (its step)
    logic [FRAC_W:0]  nxt_q, nxt_d;  // the next tick's phase + R < 2^(FRAC_W+1)
    logic [FRAC_W:0]  nxt_add;  // the tick after the next one's phase + R
    logic             nxt_sel;  // the add goes into nxt_q: the engine advances, no load
    logic             car_load;  // at a load: the first tick's carry, of one half + R
    logic [FRAC_W:0]  nxt_load;  // ...and the second tick's phase + R
    logic [ACC_W-1:0] cnt_q, cnt_d;  // pulses still to send
    // cnt_q != 0 and cnt_q == 1 as registers, decided a clock ahead: the
    // stall and completion logic reads no compare of the counter.
    logic             left_q, left_d;
    logic             one_q, one_d;
    logic             major_q, major_d;  // |delta_i| = M for the running command
    logic             neg_q, neg_d;

    assign delta   = cmd_delta_i[i*ACC_W +: ACC_W];
    assign cmd_neg = delta[ACC_W-1];
    // |-2^(ACC_W-1)| = 2^(ACC_W-1) still fits ACC_W unsigned bits.
    assign cmd_mag = cmd_neg ? ACC_W'(-delta) : delta;
    assign buf_mag[i*ACC_W +: ACC_W] = buf_mag_q;

    // One division step a clock (divider clocks 3 .. FRAC_W + 2), with
    // rem the restoring division's partial remainder (0 <= rem < 2 M) and b
    // the dividend's next bit: its quotient bit is rem >= M, i.e. s >= 0, and
    // the next s is 2 (rem - M [bit]) + b - M = 2 s + b - M (bit 1) or
    // 2 s + b + M (bit 0): an add of registers, its operands chosen in front
    // of the carry chain by registers only. Divider clock 2 loads s with
    // |delta_i| (op_a = |delta_i|, op_b = 0), rem after the integer step
    // (rem = |delta_i| - M bit; M is not yet in max_n_q); clock 3's step
    // (s >= 0: -M; for |delta_i| = M = 2^(ACC_W-1), +M, the same modulo
    // 2^ACC_W) then gives s = 2 rem - M, with rem = 0 for a maximal axis
    // (zap_q: op_a = 0, the integer bit 1). The bit of the s each clock
    // starts with goes into quot_q (clocks 4 .. FRAC_W + 2: the fraction bits
    // but the last), the last is the sign of the final s; the integer bit is
    // is_max. (In clock 1 the step's result is not used.)
    assign s_neg = s_q[ACC_W-1];
    assign zap_d = ph_q[1] && is_max[i];
    assign op_a  = ph_q[1] ? buf_mag_q : zap_q ? '0 : {s_q[ACC_W-2:0], low_q[FRAC_W-1]};
    assign op_b  = ph_q[1] ? '0 : (max_n_q ^ {ACC_W{s_neg}});  // s < 0: +M = ~max_n_q
    assign op_c  = !ph_q[1] && !s_neg;
    assign step  = {op_a, 1'b1} + {op_b, op_c};
    assign s_d   = div_run ? step[ACC_W:1] : s_q;
    assign quot_d = div_run ? {quot_q[FRAC_W-3:0], !s_neg} : quot_q;
    assign rate_load = {is_max[i], quot_q, !s_neg};

    // Engine: a tick adds R to the phase; the carry out is a step.
    assign carry[i] = car_q;
    assign left[i]  = left_q;
    assign two[i]   = cnt_q == ACC_W'(2);
    assign major[i] = major_q;
    assign buf_le1[i] = !buf_nz_q || buf_one_q;
    assign neg[i]   = neg_q;
    assign neg_next[i] = neg_d;
    // A tick: this tick's carry becomes the next one's (a register), and the
    // next tick's phase + R the one after it (the add, from registers only).
    assign nxt_add = {1'b0, nxt_q[FRAC_W-1:0]} + rate_q;
    // A load (R = rate_load <= 2^FRAC_W, the division done: registers only;
    // the phase starts at one half): the first tick's phase + R is one half + R,
    // its carry R[F] | R[F-1] (F = FRAC_W); the second's, one half + 2 R -
    // 2^F carry, differs from 2 R only in the top two bits (written out, no
    // adder): with t = R[F:F-2] (0..4) they are 1 + t - 2 (t >= 2).
    assign car_load = rate_load[FRAC_W] || rate_load[FRAC_W-1];
    assign nxt_load = {rate_load[FRAC_W] || rate_load[FRAC_W-2], !rate_load[FRAC_W-2],
                       rate_load[FRAC_W-3:0], 1'b0};
    // advance is late: it only selects, in the last LUT before each register.
    assign nxt_sel = advance && !take_adv;
    assign car_d   = nxt_sel ? nxt_q[FRAC_W] : (buf_take ? car_load : car_q);
    assign nxt_d   = nxt_sel ? nxt_add : (buf_take ? nxt_load : nxt_q);
    assign cnt_d  = advance ? (take_adv ? buf_mag_q : must[i] ? cnt_q - ACC_W'(1) : cnt_q) :
                              (take_idle ? buf_mag_q : cnt_q);
    assign left_d = advance ? (take_adv ? buf_nz_q : must[i] ? !one_q : left_q) :
                              (take_idle ? buf_nz_q : left_q);
    assign must_next[i] = car_d && left_d;
    assign one_d  = advance ? (take_adv ? buf_one_q : must[i] ? two[i] : one_q) :
                              (take_idle ? buf_one_q : one_q);
    // The buffer takes the offered command; the engine, on a load, the
    // buffered one (major_q: its compares, still in ge_q and eq_q).
    assign buf_mag_d = cmd_take ? cmd_mag : buf_mag_q;
    assign buf_neg_d = cmd_take ? cmd_neg : buf_neg_q;
    assign buf_nz_d  = cmd_take ? delta != '0 : buf_nz_q;
    assign buf_one_d = cmd_take ? (delta == ACC_W'(1)) || (delta == '1) : buf_one_q;  // +1 or -1
    assign rate_d    = buf_take ? rate_load : rate_q;
    assign neg_d     = buf_take ? buf_neg_q : neg_q;
    assign major_d   = buf_take ? is_max[i] : major_q;
`ifdef FORMAL
    assign f_cnt_ok[i] = left_q == (cnt_q != '0) && one_q == (cnt_q == ACC_W'(1)) &&
                         buf_nz_q == (buf_mag_q != '0) && buf_one_q == (buf_mag_q == ACC_W'(1));
`endif

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        buf_mag_q <= '0;
        buf_neg_q <= 1'b0;
        buf_nz_q  <= 1'b0;
        buf_one_q <= 1'b0;
        left_q    <= 1'b0;
        one_q     <= 1'b0;
        s_q       <= '0;
        zap_q     <= 1'b0;
        quot_q    <= '0;
        rate_q    <= '0;
        car_q     <= 1'b0;
        nxt_q     <= '0;
        cnt_q     <= '0;
        neg_q     <= 1'b0;
        major_q   <= 1'b0;
      end else begin
        buf_mag_q <= buf_mag_d;
        buf_neg_q <= buf_neg_d;
        buf_nz_q  <= buf_nz_d;
        buf_one_q <= buf_one_d;
        left_q    <= left_d;
        one_q     <= one_d;
        s_q       <= s_d;
        zap_q     <= zap_d;
        quot_q    <= quot_d;
        rate_q    <= rate_d;
        car_q     <= car_d;
        nxt_q     <= nxt_d;
        cnt_q     <= cnt_d;
        neg_q     <= neg_d;
        major_q   <= major_d;
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
    .want_valid_i    ({AXES{act_q}} & left),
    .want_dir_i      (neg),
    .want_dir_next_i (neg_next),
    .want_step_next_i(must_next),
    .fire_i          ({AXES{advance}} & must),
    .ready_o         (unused_ready),
    .block_o         (block),
    .step_o,
    .dir_o,
    .pos_o
  );

  assign busy_o = act_q || buf_valid_q || (|step_o);
  assign done_o = done_q;

`ifdef FORMAL
  // Formal (scripts/formal.sh): rtl/formal/fixed_ratio_props.sv attaches the
  // port contract and the engine's progress; here, the flag registers equal
  // the compares they stand for.
  always_comb begin
    if (rst_ni) a_cnt_flags: assert(f_cnt_ok == '1 && div_done_q == (div_left_q == '0));
  end
`endif
endmodule

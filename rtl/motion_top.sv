// motion_top: lines and arcs in one core, one command stream tagged line or
// arc: lines on the DDA engine over all axes (rtl/dda_axis.sv,
// rtl/dda_norm.sv), arcs on the PPC arc engine (rtl/ppc_arc_engine.sv, rule
// M) in the selected plane with the other axes slaved to the arc's
// operations (helices), one shared step/dir stage, a continuous position,
// moves chained without a gap, a feed word per move.
// models/motion_top_model.h states the mathematics, move for move.
//
// command stream -> buffer A (magnitudes, arc prep) -> buffer B (normalised)
//                -> DDA engine (every axis) + PPC arc engine (plane axes) -> step_stage
//
// Command, taken on a clock where cmd_valid_i && cmd_ready_o:
//   cmd_arc_i     0: a line, 1: an arc
//   cmd_delta_i   signed ACC_W-bit steps per axis, axis i at [i*ACC_W +: ACC_W]:
//                 a line's deltas; an arc's slaved (helical) axes' deltas,
//                 0 on the two plane axes
//   cmd_plane_i   the arc's plane: 0 XY (the arc's x = axis 0, y = axis 1),
//                 1 ZX (x = axis 2, y = axis 0), 2 YZ (x = axis 1, y = axis 2)
//   cmd_center_i  the arc's centre - start in the plane (I, J), signed COORD_W bits, x first
//   cmd_end_i     the arc's end - start in the plane, signed COORD_W bits, x first
//   cmd_ccw_i     the arc's direction: 1 counter-clockwise, 0 clockwise
//   cmd_ops_i     the arc's operations N (models::motion_arc_ops), the slaved
//                 axes' modulus; at least every slaved |delta|
//   cmd_feed_i    the move's feed word: operations per clock = cmd_feed_i / 2^FEED_W
//                 (>= 2^FEED_W: one a clock); 0: the move follows feed_i's word
//                 (a feed profile drives the pin: rtl/feed_profile.sv)
// Two buffer entries hold the next commands while one runs, so moves chain
// without a gap; cmd_ready_o is a register (buffer A empty).
//
// Lines: with M = max |delta_i| and n its bit length, 2^n iterations of a DDA
// (plain preload: an accumulator per axis from 0, modulus 2^n). Arcs: the
// PPC arc of rule M in the plane, one engine operation per tick (a step of x
// or y, or the switch to the closing line, which steps neither), and for
// each slaved axis a Bresenham over the N operations: err starts at
// floor(N/2), each operation adds |delta|, and err >= N steps the axis (in the
// sign of delta) and subtracts N, on the same operation as the plane step.
// Both are the DDA axis of rtl/dda_axis.sv with a general modulus: the
// accumulator is offset by 2^ACC_W - K (K = 2^n for a line, N for an arc) so
// its carry is always the top bit, and a carry adds |delta| + 2^ACC_W - K
// (dc, formed in buffer B: |delta| | hm for a line, |delta| - N for an arc).
// The arc's plane axes carry a zero delta: their DDA axes never step.
//
// Feed: the running move's feed word drives the feed accumulator
// (rtl/feed_accum.sv: sampled a clock ahead, the phase not cleared between
// moves; the word of the move that runs on the next clock is the one
// sampled). feed_i, the shared pin, gates it: 0 holds the move (feed hold),
// any other value runs every move at its own feed word, and a move whose
// feed word is 0 at the pin's word; the pin, like every feed word, applies
// from the clock after it is sampled.
//
// Step/dir timing, abort and status as every core (rtl/dda_line.sv): the
// engine stalls while an axis that must step is not ready; abort_i ends the
// running command and drops the buffered ones; busy_o, done_o (one clock
// with each completed command's last operation), pos_o.
//
// Timing: the engine's advance depends on registers (the carries, the arc
// engine's state, the stage's readiness, the iteration count) and the feed's
// tick; every next state is a late choice by advance. Buffer A's work
// (magnitudes, the arc's prep) starts at the pins, buffer B's (masks, dc) at
// buffer A.
//
// Per-axis vectors are flat with `+:` slices (Yosys 0.23, Icarus 11).
module motion_top #(
  parameter int AXES    = 3,   // axes: 3 (X Y Z) to 6; the arc planes use axes 0-2
  parameter int ACC_W   = 32,  // signed line and slaved delta width; the DDA accumulators (4..62)
  parameter int COORD_W = 24,  // signed arc coordinate width (3..60)
  parameter int OPS_W   = 28,  // arc operation count width (1..ACC_W - 1)
  parameter int POS_W   = 32,  // position counter width (2..64; wraps)
  parameter int TIM_W   = 16,  // width of the step/dir timing settings (>= 2)
  parameter int FEED_W  = 16   // feed phase width (>= 1); feed words are FEED_W + 1 bits
) (
  input  logic                    clk_i,         // clock
  input  logic                    rst_ni,        // asynchronous, active low
  // Command stream
  input  logic                    cmd_valid_i,   // a command is offered on cmd_*_i
  output logic                    cmd_ready_o,   // buffer A is free: an offered command is taken
  input  logic                    cmd_arc_i,     // 0 line, 1 arc
  input  logic [AXES*ACC_W-1:0]   cmd_delta_i,   // signed steps per axis (an arc's: slaved axes only)
  input  logic [1:0]              cmd_plane_i,   // arc plane: 0 XY, 1 ZX, 2 YZ
  input  logic [2*COORD_W-1:0]    cmd_center_i,  // arc centre - start (plane x, y)
  input  logic [2*COORD_W-1:0]    cmd_end_i,     // arc end - start (plane x, y)
  input  logic                    cmd_ccw_i,     // arc direction, 1: counter-clockwise
  input  logic [OPS_W-1:0]        cmd_ops_i,     // arc operations N (>= 1)
  input  logic [FEED_W:0]         cmd_feed_i,    // the move's operations per clock, / 2^FEED_W
  // Run-time settings
  input  logic [FEED_W:0]         feed_i,        // 0: feed hold; else the moves run at their feed words (feed word 0: at this one)
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
  localparam int PREP_W = 6 * COORD_W + 4;  // the arc's s, e, E (rtl/ppc_arc_prep.sv)

  // ---------------------------------------------------------------------------
  // Parameter checks at elaboration: Verilator and Yosys stop with the
  // message (Icarus 11 has no elaboration system tasks: it skips them).
  // OPS_W < ACC_W: a slaved axis's accumulator holds the modulus N; the
  // other bounds are the range the HLS face (hls/motion_top.h,
  // hls/ppc_arc_engine.h), and so the lockstep verification, covers.
`ifndef __ICARUS__
  if (AXES < 3 || AXES > 6) begin : g_bad_axes
    $error("motion_top: parameter AXES must be 3..6");
  end
  if (ACC_W < 4 || ACC_W > 62) begin : g_bad_acc_w
    $error("motion_top: parameter ACC_W must be 4..62");
  end
  if (COORD_W < 3 || COORD_W > 60) begin : g_bad_coord_w
    $error("motion_top: parameter COORD_W must be 3..60");
  end
  if (OPS_W < 1 || OPS_W >= ACC_W) begin : g_bad_ops_w
    $error("motion_top: parameter OPS_W must be 1..ACC_W - 1");
  end
  if (POS_W < 2 || POS_W > 64) begin : g_bad_pos_w
    $error("motion_top: parameter POS_W must be 2..64");
  end
  if (TIM_W < 2) begin : g_bad_tim_w
    $error("motion_top: parameter TIM_W must be >= 2");
  end
  if (FEED_W < 1) begin : g_bad_feed_w
    $error("motion_top: parameter FEED_W must be >= 1");
  end
`endif

  // ---------------------------------------------------------------------------
  // Buffer A: the taken command, magnitudes and the arc's prep.
  logic                  a_valid_q, a_valid_d;
  logic                  a_arc_q, a_arc_d, a_ccw_q, a_ccw_d;
  logic [1:0]            a_plane_q, a_plane_d;
  logic [ACC_W-1:0]      a_any_q, a_any_d;  // OR of the magnitudes
  logic [ACC_W-1:0]      a_negn_q, a_negn_d;  // 2^ACC_W - N
  logic [FEED_W:0]       a_feed_q, a_feed_d;
  logic [PREP_W-1:0]     a_prep_q, a_prep_d;
  logic                  cmd_take;
  logic                  a_to_b;
  logic [AXES*ACC_W-1:0] cmd_mag;
  logic [ACC_W-1:0]      cmd_any;
  logic [PREP_W-1:0]     cmd_prep;

  assign cmd_ready_o = !a_valid_q;
  assign cmd_take    = cmd_valid_i && !a_valid_q;

  always_comb begin
    cmd_any = '0;
    for (int i = 0; i < AXES; i++) cmd_any = cmd_any | cmd_mag[i*ACC_W +: ACC_W];
  end

  ppc_arc_prep #(
    .COORD_W(COORD_W)
  ) u_prep (
    .center_i(cmd_center_i),
    .end_i   (cmd_end_i),
    .prep_o  (cmd_prep)
  );

  // ---------------------------------------------------------------------------
  // Buffer B: the command normalised: a line's iterations after the first
  // (2^n - 1), the accumulators' first value a0 (hm = 2^ACC_W - 2^n for a
  // line; 2^ACC_W - ceil(N/2) for an arc, i.e. err = floor(N/2)), and per axis
  // dc (in the slices below).
  logic                  b_valid_q, b_valid_d;
  logic                  b_arc_q, b_arc_d, b_ccw_q, b_ccw_d;
  logic [1:0]            b_plane_q, b_plane_d;
  logic [ACC_W-1:0]      b_low_q, b_low_d, b_a0_q, b_a0_d;
  logic                  b_low_zero_q, b_low_zero_d;
  logic [FEED_W:0]       b_feed_q, b_feed_d;
  logic [PREP_W-1:0]     b_prep_q, b_prep_d;
  logic [ACC_W-1:0]      a_low, a_hm, a_top;
  logic                  load;  // the engine loads buffer B this clock

  dda_norm #(
    .W(ACC_W)
  ) u_norm (
    .any_i(a_any_q),
    .low_o(a_low),
    .hm_o (a_hm),
    .top_o(a_top)
  );

  // ---------------------------------------------------------------------------
  // Engine.
  logic            act_q, act_d;  // a command is running
  logic            arc_q, arc_d;  // ...an arc
  logic [AXES-1:0] on_x_q, on_x_d, on_y_q, on_y_d;  // the axis is the running arc's x / y
  logic [ACC_W-1:0] left_q, left_d;  // a line's iterations after this one
  logic            left_zero_q, left_zero_d;
  logic            pre_load;  // the next add is a load's: buffer B waits and the engine is idle or ends
  logic [FEED_W:0] feed_q, feed_d;  // the running move's feed word
  logic            hold_q, hold_d;  // feed_i was 0
  logic [FEED_W:0] pin_q, pin_d;    // feed_i, for the moves that follow it
  logic            b_pin_q, b_pin_d, cur_pin_q, cur_pin_d;  // buffer B's / the running move's feed word is 0
  logic            done_q, done_d;
  logic [AXES-1:0] dda_carry, carry, want_valid, want_dir, ready;
  logic [AXES-1:0] unused_block;  // the stage's block_o (READY_Q = 1 only)
  logic [AXES-1:0] unused_carry_next;  // the DDA axes' carry_next_o (for READY_Q = 1 only)
  logic            unused;  // the half bit (no half preload here)
  assign unused = ^a_top;
  logic [1:0]      eng_step, eng_want_valid, eng_want_dir;
  logic [1:0]      unused_eng_step_next, unused_eng_want_dir_next;
  logic            eng_last, eng_pending, unused_eng_start, unused_eng_run, unused_eng_run_next;
  logic            cur_last;  // this clock's operation ends the running command
  logic            tick, stall, advance, last, idle_load;

  // The arc engine's last_o is a register; an arc in buffer B loads only
  // once the engine has copied it (eng_pending: rtl/ppc_arc_engine.sv,
  // "Taking a command"), a line at once.
  assign cur_last  = arc_q ? eng_last : left_zero_q;
  assign pre_load  = b_valid_q && (!act_q || cur_last) && (!b_arc_q || eng_pending);
  assign stall     = |(carry & ~ready);
  assign advance   = tick && !stall && !abort_i;
  assign last      = advance && cur_last;
  assign load      = pre_load && (!act_q || advance) && !abort_i;
  assign idle_load = pre_load && !act_q && !abort_i;
  assign a_to_b    = a_valid_q && !b_valid_q && !abort_i;

  // The arc engine runs one operation ahead: its outputs are registers, so
  // the stall (carry & ~ready) waits on no arc arithmetic. The stage stays
  // READY_Q = 0: a registered stall would need each DDA axis's next carry
  // (carry_next_o: a load-or-iterate mux and a 33-bit add behind pre_load),
  // which measured slower (54 MHz against 73 MHz on HX8K, seed 1).
  ppc_arc_engine #(
    .COORD_W(COORD_W)
  ) u_arc (
    .clk_i,
    .rst_ni,
    .ld_valid_i     (b_valid_q && b_arc_q),
    .ld_prep_i      (b_prep_q),
    .ld_ccw_i       (b_ccw_q),
    .pending_o      (eng_pending),
    .start_o        (unused_eng_start),  // = load && b_arc_q
    .fill_i         (load && b_arc_q),
    .advance_i      (advance && arc_q),
    .abort_i,
    .run_o          (unused_eng_run),  // = act_q && arc_q
    .step_o         (eng_step),
    .want_valid_o   (eng_want_valid),
    .want_dir_o     (eng_want_dir),
    .last_o         (eng_last),
    .run_next_o     (unused_eng_run_next),
    .step_next_o    (unused_eng_step_next),  // for READY_Q = 1 only
    .want_dir_next_o(unused_eng_want_dir_next)
  );

  // The feed word of the move on the next clock (pre_load: the next
  // command's, as it loads if the engine advances), gated by feed_i; a move
  // whose word is 0 takes the pin's.
  logic [FEED_W:0] accum_feed;
  assign accum_feed = hold_q ? '0 : (pre_load ? (b_pin_q ? pin_q : b_feed_q)
                                              : (cur_pin_q ? pin_q : feed_q));
  feed_accum #(
    .FEED_W(FEED_W)
  ) u_feed (
    .clk_i,
    .rst_ni,
    .feed_i    (accum_feed),
    .run_i     (act_q),
    .hold_i    (stall),
    .run_next_i(act_d),
    .tick_o    (tick)
  );

  // Next states as advance ? (advancing) : (not), from registers.
  logic act_adv, act_idle, lz_adv, lz_idle, bv_adv, bv_idle;
  assign act_adv     = pre_load || !cur_last;
  assign act_idle    = (act_q && !abort_i) || idle_load;
  assign lz_adv      = pre_load ? b_low_zero_q : (left_q == ACC_W'(1));
  assign lz_idle     = idle_load ? b_low_zero_q : left_zero_q;
  assign bv_adv      = a_to_b || (b_valid_q && !pre_load);
  assign bv_idle     = !abort_i && (a_to_b || (b_valid_q && !idle_load));
  assign act_d       = advance ? act_adv : act_idle;
  assign left_zero_d = advance ? lz_adv : lz_idle;
  assign left_d      = advance ? (pre_load ? b_low_q : left_q - ACC_W'(1)) :
                                 (idle_load ? b_low_q : left_q);
  assign b_valid_d   = advance ? bv_adv : bv_idle;
  assign a_valid_d   = !abort_i && (cmd_take || (a_valid_q && !a_to_b));

  // Buffer A takes the offered command, buffer B buffer A's (normalised), the
  // engine buffer B's on a load.
  always_comb begin
    a_arc_d      = a_arc_q;
    a_ccw_d      = a_ccw_q;
    a_plane_d    = a_plane_q;
    a_any_d      = a_any_q;
    a_negn_d     = a_negn_q;
    a_feed_d     = a_feed_q;
    a_prep_d     = a_prep_q;
    if (cmd_take) begin
      a_arc_d   = cmd_arc_i;
      a_ccw_d   = cmd_ccw_i;
      a_plane_d = cmd_plane_i;
      a_any_d   = cmd_any;
      a_negn_d  = ACC_W'(0) - ACC_W'(cmd_ops_i);
      a_feed_d  = cmd_feed_i;
      a_prep_d  = cmd_prep;
    end
    b_arc_d      = b_arc_q;
    b_ccw_d      = b_ccw_q;
    b_plane_d    = b_plane_q;
    b_low_d      = b_low_q;
    b_low_zero_d = b_low_zero_q;
    b_a0_d       = b_a0_q;
    b_feed_d     = b_feed_q;
    b_prep_d     = b_prep_q;
    if (a_to_b) begin
      b_arc_d      = a_arc_q;
      b_ccw_d      = a_ccw_q;
      b_plane_d    = a_plane_q;
      b_low_d      = a_arc_q ? '0 : a_low;
      b_low_zero_d = a_arc_q || (a_any_q == '0);
      // An arc: -N >>> 1 = -ceil(N/2).
      b_a0_d       = a_arc_q ? {a_negn_q[ACC_W-1], a_negn_q[ACC_W-1:1]} : a_hm;
      b_feed_d     = a_feed_q;
      b_prep_d     = a_prep_q;
    end
    b_pin_d = a_to_b ? (a_feed_q == '0) : b_pin_q;
    arc_d     = arc_q;
    feed_d    = feed_q;
    cur_pin_d = cur_pin_q;
    on_x_d = on_x_q;
    on_y_d = on_y_q;
    if (load) begin
      arc_d     = b_arc_q;
      feed_d    = b_feed_q;
      cur_pin_d = b_pin_q;
      for (int i = 0; i < AXES; i++) begin
        on_x_d[i] = b_arc_q && (i == (b_plane_q == 2'd0 ? 0 : b_plane_q == 2'd1 ? 2 : 1));
        on_y_d[i] = b_arc_q && (i == (b_plane_q == 2'd0 ? 1 : b_plane_q == 2'd1 ? 0 : 2));
      end
    end
    hold_d = feed_i == '0;
    pin_d  = feed_i;
    done_d = last;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      a_valid_q    <= 1'b0;
      a_arc_q      <= 1'b0;
      a_ccw_q      <= 1'b0;
      a_plane_q    <= '0;
      a_any_q      <= '0;
      a_negn_q     <= '0;
      a_feed_q     <= '0;
      a_prep_q     <= '0;
      b_valid_q    <= 1'b0;
      b_arc_q      <= 1'b0;
      b_ccw_q      <= 1'b0;
      b_plane_q    <= '0;
      b_low_q      <= '0;
      b_a0_q       <= '0;
      b_low_zero_q <= 1'b0;
      b_feed_q     <= '0;
      b_prep_q     <= '0;
      act_q        <= 1'b0;
      arc_q        <= 1'b0;
      on_x_q       <= '0;
      on_y_q       <= '0;
      left_q       <= '0;
      left_zero_q  <= 1'b0;
      feed_q       <= '0;
      hold_q       <= 1'b1;
      pin_q        <= '0;
      b_pin_q      <= 1'b0;
      cur_pin_q    <= 1'b0;
      done_q       <= 1'b0;
    end else begin
      a_valid_q    <= a_valid_d;
      a_arc_q      <= a_arc_d;
      a_ccw_q      <= a_ccw_d;
      a_plane_q    <= a_plane_d;
      a_any_q      <= a_any_d;
      a_negn_q     <= a_negn_d;
      a_feed_q     <= a_feed_d;
      a_prep_q     <= a_prep_d;
      b_valid_q    <= b_valid_d;
      b_arc_q      <= b_arc_d;
      b_ccw_q      <= b_ccw_d;
      b_plane_q    <= b_plane_d;
      b_low_q      <= b_low_d;
      b_a0_q       <= b_a0_d;
      b_low_zero_q <= b_low_zero_d;
      b_feed_q     <= b_feed_d;
      b_prep_q     <= b_prep_d;
      act_q        <= act_d;
      arc_q        <= arc_d;
      on_x_q       <= on_x_d;
      on_y_q       <= on_y_d;
      left_q       <= left_d;
      left_zero_q  <= left_zero_d;
      feed_q       <= feed_d;
      hold_q       <= hold_d;
      pin_q        <= pin_d;
      b_pin_q      <= b_pin_d;
      cur_pin_q    <= cur_pin_d;
      done_q       <= done_d;
    end
  end

  // ---------------------------------------------------------------------------
  // Per-axis slices: magnitude, buffers, the DDA axis, and the step request
  // (the arc engine's on the running arc's plane axes).
  for (genvar i = 0; i < AXES; i++) begin : g_axis
    logic [ACC_W-1:0] delta, a_mag_q, a_mag_d, b_mag_q, b_mag_d;
    logic [ACC_W:0]   b_dc_q, b_dc_d;  // up to 2^ACC_W: a slaved axis that steps every operation
    logic             cmd_neg, a_neg_q, a_neg_d, b_neg_q, b_neg_d, neg_q, neg_d;
    logic             a_moves_q, a_moves_d, b_moves_q, b_moves_d, moves_q, moves_d;

    assign delta = cmd_delta_i[i*ACC_W +: ACC_W];
    magnitude #(
      .W(ACC_W)
    ) u_mag (
      .x_i  (delta),
      .mag_o(cmd_mag[i*ACC_W +: ACC_W]),
      .neg_o(cmd_neg)
    );

    dda_axis #(
      .W         (ACC_W),
      .MODULUS_2N(1'b0)
    ) u_acc (
      .clk_i,
      .rst_ni,
      .pre_i       (pre_load),
      .ld_i        (load),
      .en_i        (load || advance),
      .a0_i        (b_a0_q),
      .b_mag_i     (b_mag_q),
      .b_dc_i      (b_dc_q),
      .hm_i        ('0),
      .carry_o     (dda_carry[i]),
      .carry_next_o(unused_carry_next[i])  // the stage's READY_Q = 0: no block to predict
    );

    // The engine's operation register is empty (no step, no want) when no
    // arc runs: its outputs need no gate.
    assign carry[i]         = dda_carry[i] || (on_x_q[i] && eng_step[0]) || (on_y_q[i] && eng_step[1]);
    assign want_valid[i]    = on_x_q[i] ? eng_want_valid[0] : on_y_q[i] ? eng_want_valid[1] : moves_q;
    assign want_dir[i]      = on_x_q[i] ? eng_want_dir[0] : on_y_q[i] ? eng_want_dir[1] : neg_q;
    assign moves_d       = advance ? (pre_load ? b_moves_q : moves_q && !cur_last) :
                                     (idle_load ? b_moves_q : moves_q && !abort_i);
    assign a_mag_d       = cmd_take ? cmd_mag[i*ACC_W +: ACC_W] : a_mag_q;
    assign a_neg_d       = cmd_take ? cmd_neg : a_neg_q;
    assign a_moves_d     = cmd_take ? delta != '0 : a_moves_q;
    assign b_mag_d       = a_to_b ? a_mag_q : b_mag_q;
    // dc = |delta| + 2^ACC_W - K: | hm for a line, - N for an arc
    // (|delta| <= N: 2^ACC_W at most).
    assign b_dc_d        = !a_to_b ? b_dc_q :
                           a_arc_q ? {1'b0, a_mag_q} + {1'b0, a_negn_q} : {1'b0, a_mag_q | a_hm};
    assign b_neg_d       = a_to_b ? a_neg_q : b_neg_q;
    assign b_moves_d     = a_to_b ? a_moves_q : b_moves_q;
    assign neg_d         = load ? b_neg_q : neg_q;

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        a_mag_q   <= '0;
        a_neg_q   <= 1'b0;
        a_moves_q <= 1'b0;
        b_mag_q   <= '0;
        b_dc_q    <= '0;
        b_neg_q   <= 1'b0;
        b_moves_q <= 1'b0;
        neg_q     <= 1'b0;
        moves_q   <= 1'b0;
      end else begin
        a_mag_q   <= a_mag_d;
        a_neg_q   <= a_neg_d;
        a_moves_q <= a_moves_d;
        b_mag_q   <= b_mag_d;
        b_dc_q    <= b_dc_d;
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
    .READY_Q(1'b0)
  ) u_out (
    .clk_i,
    .rst_ni,
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .want_valid_i    (want_valid),
    .want_dir_i      (want_dir),
    .want_dir_next_i (want_dir),  // unused: READY_Q = 0
    .want_step_next_i('0),  // unused: READY_Q = 0
    .fire_i          ({AXES{advance}} & carry),
    .ready_o         (ready),
    .block_o         (unused_block),  // READY_Q = 0: always 0
    .step_o,
    .dir_o,
    .pos_o
  );

  assign busy_o = act_q || a_valid_q || b_valid_q || (|step_o);
  assign done_o = done_q;

`ifdef FORMAL
  // ---------------------------------------------------------------------------
  // Formal (scripts/formal.sh, rtl/formal/motion_top_props.sv): the port
  // contract every core shares (rtl/formal/core_contract.sv) with the
  // commands buffers A and B and the engine hold, and the invariants of the
  // registers it rests on.
  logic [1:0] f_held;
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

  // Progress: while a command runs with full feed (the feed word the feed
  // accumulator samples >= 2^FEED_W on the clock before) and no abort, the
  // engine advances on every clock but one on which an axis its operation steps
  // is not ready: it waits for the step/dir timing only, and
  // rtl/formal/stepdir_axis_props.sv proves that ready_o waits for exactly that
  // (never longer; dir_o turns as soon as the hold allows).
  logic f_full_q, f_full_d;
  assign f_full_d = accum_feed[FEED_W];
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) f_full_q <= 1'b0;
    else f_full_q <= f_full_d;
  end

  always_comb begin
    if (rst_ni) begin
      a_progress: assert(!(act_q && f_full_q && !abort_i) || advance || (carry & ~ready) != '0);
      a_tick: assert(!tick || act_q);
    end
  end
`endif
endmodule

// motion_soc: motion_top (rtl/motion_top.sv) behind the register map of
// rtl/regs/motion_soc.rdl. This module is everything between the register
// block and the core; rtl/motion_soc_axil.sv and rtl/motion_soc_wb.sv put it
// behind PeakRDL-regblock's AXI4-Lite or Wishbone register block (generated
// into rtl/regs/gen/, one description). The register page is
// docs/soc_regs.md, the bring-up docs/soc.md.
//
//   CMD_* staging registers --CMD_PUSH--> command FIFO (prim_ram_1r1w)
//     --> head (waits for its apply-at TIME) --> motion_top --> step outputs
//
// Command FIFO: a write of CMD_PUSH pushes the staged command (CMD_DELTA ...
// CMD_FLAGS as written before) at the edge that ends the write's clock. A push to a full FIFO is not
// taken and sets EVENTS.overflow; a push while stopped (EVENTS.wdog or
// EVENTS.estop set) or in an abort's clock is not taken and sets
// EVENTS.refused: never a silent drop; so is a timed push (CMD_FLAGS.timed)
// in a PROFILE = 1 build (its moves are not timed). FIFO_DEPTH commands fit, the head
// included; FIFO_LEVEL counts them; EVENTS.low_water is set on every clock
// the level is at most FIFO_LOW.
//
// Time: TIME counts clocks from reset (64 bits, wraps after 2^64). A command
// pushed with CMD_PUSH.timed waits at the head until TIME >= CMD_AT and is
// offered to the core from that clock; if the core takes it at a TIME past
// CMD_AT (the core was still busy, or it reached the head late), EVENTS.late.
//
// Watchdog: with WDOG_PERIOD = P != 0, a write of WDOG_KICK or WDOG_PERIOD at
// clock k arms it; without another write, it bites at clock k + P + 1: abort_i
// of the core high for that clock, the FIFO dropped, EVENTS.wdog set, and
// pushes refused until software clears EVENTS.wdog (the watchdog restarts
// with a full period then). estop_i (synchronized, two flip-flops) does the
// same while high, with EVENTS.estop. CTRL.abort_motion aborts once.
//
// The feed profile (PROFILE = 1; PROFILE = 0 builds are today's logic): the
// jerk-limited feed profile (rtl/feed_profile.sv, docs/profile.md) drives
// motion_top's feed_i as rtl/motion_profile.sv wires it (FEED is then
// unused). Each FIFO entry carries the command and its profile move
// (CMD_MV_OPS, CMD_MV_TARGET, CMD_MV_END, CMD_MV_MAX), and the FIFO has two
// consumers that take from it independently: the profile's move port and
// motion_top's command port. The FIFO head, the choice: a second read
// pointer. The moves live in a second RAM written at the same address as the
// commands (one write pointer) and read through their own read pointer, RAM
// read register (the move head) and count, so the profile takes its moves as
// far ahead of motion_top as its own pending/next slots allow, and a
// junction with an end level above 0 is joined at speed. An entry's place
// is free once both have read it: the level is the larger of the two
// consumers' levels (count + head).
// The exact-stop rule (tb/lockstep/profile_feed.h's, in hardware): once the
// profile has taken a move whose end level is 0, the next move is not offered
// and motion_top's next command (the first one whose move is not taken yet:
// commands level <= moves level) is not offered while the profile is busy
// (busy_o: moves queued, moving or settling).
// Watchdog with the profile, a controlled stop: the bite sets EVENTS.wdog
// (pushes refused) and STATUS.wdog_stopping, whose hold brings the profile to
// rest along the path within its jerk and acceleration limits; on the first
// clock with the profile's speed and feed word 0 and no step output high, the
// FIFO is dropped and motion_top aborted (an abort clock as above), and the
// profile is cleared (its reset for the next clock: a flip-flop's output,
// so glitch-free) of the moves it still held. estop_i, CTRL.abort_motion and
// a stopping probe latch stay immediate aborts (the profile cleared too).
// PROF_CTRL.hold is the feed hold: the same controlled stop, and release
// resumes the planned profile.
//
// Snapshot: SNAP_CTRL.arm arms it; on the first clock TIME >= SNAP_AT (at
// once if passed) TIME, every axis's position and speed go into SNAP_TIME,
// SNAP_POS, SNAP_SPEED together, EVENTS.snap. Probe latch: probe_i
// synchronized, then filtered (the level must hold PROBE_CFG.filter clocks
// past the first differing one), and on the chosen edge of the filtered
// level an armed latch takes TIME and every position into LATCH_TIME,
// LATCH_POS (EVENTS.latch; with PROBE_CFG.stop also an abort). Each set of
// shadow registers changes only at its event: read in any order, it is one
// snapshot.
//
// Step outputs per axis (STEP_TYPE, taken while the axis's step is low),
// motion_top's step/dir through rtl/step_encode.sv: 0 step/dir (out_a =
// step, out_b = dir), 1 up/down (out_a = step of a positive step, out_b = of
// a negative), 2 quadrature (each step moves the (out_a, out_b) phase one
// state: 00 10 11 01 forward, A leading; the reverse backward).
// The core's step stage keeps the step/dir timing (STEP_LEN ...): a
// quadrature state lasts at least STEP_LEN + STEP_SPACE clocks.
module motion_soc #(
  parameter int AXES       = 3,   // as motion_top (3..6)
  parameter int ACC_W      = 32,  // as motion_top
  parameter int COORD_W    = 24,  // as motion_top
  parameter int OPS_W      = 28,  // as motion_top
  parameter int POS_W      = 32,  // as motion_top (2..64)
  parameter int TIM_W      = 16,  // as motion_top (2..32)
  parameter int FEED_W     = 16,  // as motion_top (1..31)
  parameter int FIFO_DEPTH = 16,  // commands the FIFO holds, the head included (2..65535)
  parameter int BUS        = 0,   // ID_BUILD.bus: 0 AXI4-Lite, 1 Wishbone
  parameter int unsigned CLK_HZ = 50_000_000,  // ID_CLOCK: the clock's frequency, Hz
  parameter int PROFILE    = 0,   // 1: the feed profile drives motion_top's feed_i (0..1)
  // the feed profile's (rtl/feed_profile.sv states their ranges; unused with PROFILE = 0)
  parameter int SPD_W      = 48,  // speed fraction bits (FEED_W < SPD_W <= 62)
  parameter int TICK_W     = 10,  // a tick is 2^TICK_W clocks
  parameter int LEN_W      = 10,  // the moving sum is at most 2^LEN_W ticks (1..16)
  parameter int PROF_LVL_W = 16,  // speed level bits (2..24)
  parameter int MV_OPS_W   = 28   // operations of a move (2..40)
) (
  input  logic                                          clk_i,
  input  logic                                          rst_ni,      // asynchronous, active low
  // The register block's fields (its `intr` summary of EVENTS is not used:
  // irq_o below applies IRQ_EN).
  /* verilator lint_off UNUSEDSIGNAL */
  input  motion_soc_regs_pkg::motion_soc_regs__out_t    hwif_out_i,
  /* verilator lint_on UNUSEDSIGNAL */
  output motion_soc_regs_pkg::motion_soc_regs__in_t     hwif_in_o,   // to the register block
  input  logic                                          probe_i,     // probe / index input (asynchronous)
  input  logic                                          estop_i,     // 1: stop (asynchronous)
  output logic [AXES-1:0]                               out_a_o,     // per axis: step, up or phase A
  output logic [AXES-1:0]                               out_b_o,     // per axis: dir, down or phase B
  output logic                                          irq_o        // OR of EVENTS & IRQ_EN
);
`ifndef __ICARUS__
  if (AXES < 3 || AXES > 6) begin : g_bad_axes
    $error("motion_soc: parameter AXES must be 3..6");
  end
  if (TIM_W < 2 || TIM_W > 32) begin : g_bad_tim_w
    $error("motion_soc: parameter TIM_W must be 2..32");
  end
  if (FEED_W < 1 || FEED_W > 31) begin : g_bad_feed_w
    $error("motion_soc: parameter FEED_W must be 1..31");
  end
  if (FIFO_DEPTH < 2 || FIFO_DEPTH > 65535) begin : g_bad_fifo_depth
    $error("motion_soc: parameter FIFO_DEPTH must be 2..65535");
  end
  if (BUS < 0 || BUS > 1) begin : g_bad_bus
    $error("motion_soc: parameter BUS must be 0 (AXI4-Lite) or 1 (Wishbone)");
  end
  if (PROFILE < 0 || PROFILE > 1) begin : g_bad_profile
    $error("motion_soc: parameter PROFILE must be 0 (none) or 1 (the feed profile)");
  end
  if (PROFILE == 1 && (SPD_W <= FEED_W || SPD_W > 62)) begin : g_bad_spd_w
    $error("motion_soc: parameter SPD_W must be FEED_W + 1..62");
  end
  if (PROFILE == 1 && (LEN_W < 1 || LEN_W > 16 || PROF_LVL_W < 2 || PROF_LVL_W > 24 ||
                       MV_OPS_W < 2 || MV_OPS_W > 40)) begin : g_bad_prof_w
    $error("motion_soc: parameters LEN_W (1..16), PROF_LVL_W (2..24), MV_OPS_W (2..40)");
  end
`endif

  localparam int PTR_W = $clog2(FIFO_DEPTH);
  localparam int LVL_W = $clog2(FIFO_DEPTH + 1);
  // A FIFO entry: {at, timed, feed, ops, ccw, end, center, plane, delta, arc};
  // with PROFILE = 1 without {at, timed} (ENTRY_W = E_TIMED): a timed push
  // is refused there, so every entry's timed bit would be 0 (the head reads
  // it as 0 from the bits above the RAM's word, and the apply-at compare
  // folds away). 65 bits less: 16 SB_RAM40_4K instead of 20 at
  // motion_top_n3's widths.
  localparam int E_ARC    = 0;
  localparam int E_DELTA  = E_ARC + 1;
  localparam int E_PLANE  = E_DELTA + AXES * ACC_W;
  localparam int E_CENTER = E_PLANE + 2;
  localparam int E_END    = E_CENTER + 2 * COORD_W;
  localparam int E_CCW    = E_END + 2 * COORD_W;
  localparam int E_OPS    = E_CCW + 1;
  localparam int E_FEED   = E_OPS + OPS_W;
  localparam int E_TIMED  = E_FEED + FEED_W + 1;
  localparam int E_AT     = E_TIMED + 1;
  localparam int FULL_W   = E_AT + 64;   // every field
  localparam int ENTRY_W  = (PROFILE == 0) ? FULL_W : E_TIMED;
  // A move entry (the profile's FIFO): {max, end, target, ops}.
  localparam int M_OPS    = 0;
  localparam int M_TARGET = M_OPS + MV_OPS_W;
  localparam int M_END    = M_TARGET + PROF_LVL_W;
  localparam int M_MAX    = M_END + PROF_LVL_W;
  localparam int MV_W     = M_MAX + PROF_LVL_W;

  // ---------------------------------------------------------------------------
  // Register values as the core's widths: signed values sign-extended from
  // 32 bits (or cut to the width), unsigned ones zero-extended, settings
  // saturated.
  function automatic logic [63:0] sext32(input logic [31:0] v);
    sext32 = {{32{v[31]}}, v};
  endfunction
  function automatic logic [63:0] zext32(input logic [31:0] v);
    zext32 = {32'b0, v};
  endfunction
  function automatic logic [31:0] sat32(input logic [31:0] v, input int w);
    logic [31:0] lim;
    lim = (w >= 32) ? 32'hFFFF_FFFF : ((32'd1 << w) - 32'd1);
    sat32 = (v > lim) ? lim : v;
  endfunction

  /* verilator lint_off UNUSEDSIGNAL */
  logic [63:0] delta64 [AXES];
  logic [63:0] center64 [2];
  logic [63:0] end64 [2];
  logic [63:0] ops64;
  logic [31:0] feed_w32, cmd_feed_w32;
  logic [31:0] step_len32, step_space32, dir_setup32, dir_hold32;
  logic [FULL_W-1:0]  push_all;      // the entry with every field (the RAM takes ENTRY_W bits)
  /* verilator lint_on UNUSEDSIGNAL */
  logic [ENTRY_W-1:0] push_entry;
  logic [MV_W-1:0]    push_move;

  // The per-axis registers as arrays (the map has them as single instances).
  logic [31:0] delta_reg [6];
  assign delta_reg[0] = hwif_out_i.cmd_delta0.value.value;
  assign delta_reg[1] = hwif_out_i.cmd_delta1.value.value;
  assign delta_reg[2] = hwif_out_i.cmd_delta2.value.value;
  assign delta_reg[3] = hwif_out_i.cmd_delta3.value.value;
  assign delta_reg[4] = hwif_out_i.cmd_delta4.value.value;
  assign delta_reg[5] = hwif_out_i.cmd_delta5.value.value;

  always_comb begin
    for (int i = 0; i < AXES; i++) delta64[i] = sext32(delta_reg[i]);
    center64[0] = sext32(hwif_out_i.cmd_center0.value.value);
    center64[1] = sext32(hwif_out_i.cmd_center1.value.value);
    end64[0]    = sext32(hwif_out_i.cmd_end0.value.value);
    end64[1]    = sext32(hwif_out_i.cmd_end1.value.value);
    ops64        = zext32(hwif_out_i.cmd_ops.value.value);
    // Feed words saturate at 2^FEED_W (full feed).
    cmd_feed_w32 = (hwif_out_i.cmd_feed.value.value > (32'd1 << FEED_W)) ? (32'd1 << FEED_W)
                                                                         : hwif_out_i.cmd_feed.value.value;
    feed_w32     = (hwif_out_i.feed.value.value > (32'd1 << FEED_W)) ? (32'd1 << FEED_W)
                                                                     : hwif_out_i.feed.value.value;
    step_len32   = sat32(hwif_out_i.step_len.value.value, TIM_W);
    step_space32 = sat32(hwif_out_i.step_space.value.value, TIM_W);
    dir_setup32  = sat32(hwif_out_i.dir_setup.value.value, TIM_W);
    dir_hold32   = sat32(hwif_out_i.dir_hold.value.value, TIM_W);

    push_all = '0;
    push_all[E_ARC] = hwif_out_i.cmd_flags.arc.value;
    for (int i = 0; i < AXES; i++) push_all[E_DELTA + i*ACC_W +: ACC_W] = delta64[i][ACC_W-1:0];
    push_all[E_PLANE +: 2] = hwif_out_i.cmd_flags.plane.value;
    for (int i = 0; i < 2; i++) begin
      push_all[E_CENTER + i*COORD_W +: COORD_W] = center64[i][COORD_W-1:0];
      push_all[E_END + i*COORD_W +: COORD_W]    = end64[i][COORD_W-1:0];
    end
    push_all[E_CCW] = hwif_out_i.cmd_flags.ccw.value;
    push_all[E_OPS +: OPS_W] = ops64[OPS_W-1:0];
    push_all[E_FEED +: FEED_W + 1] = cmd_feed_w32[FEED_W:0];
    push_all[E_TIMED] = hwif_out_i.cmd_flags.timed.value;
    push_all[E_AT +: 64] = {hwif_out_i.cmd_at.hi.value, hwif_out_i.cmd_at.lo.value};
    push_entry = push_all[ENTRY_W-1:0];

    push_move = '0;
    push_move[M_OPS +: MV_OPS_W]      = MV_OPS_W'(hwif_out_i.cmd_mv_ops.value.value);
    push_move[M_TARGET +: PROF_LVL_W] = PROF_LVL_W'(hwif_out_i.cmd_mv_target.value.value);
    push_move[M_END +: PROF_LVL_W]    = PROF_LVL_W'(hwif_out_i.cmd_mv_end.value.value);
    push_move[M_MAX +: PROF_LVL_W]    = PROF_LVL_W'(hwif_out_i.cmd_mv_max.value.value);
  end

  // ---------------------------------------------------------------------------
  // Time, and the stop and abort conditions.
  logic [63:0] time_q, time_d;
  logic [31:0] time_hi_q, time_hi_d;
  logic [1:0]  estop_s_q, estop_s_d;
  logic        estop;
  logic        stopped;
  logic        bite;
  logic        latch_fire, latch_stop;
  logic        abort;
  logic        wstop_q, wstop_d;     // the watchdog's controlled stop is under way (PROFILE)
  logic        wstop_done;           // ... and the profile and motion_top are at rest
  logic        prof_clr_q, prof_clr_d;  // the profile's reset on this clock (after an abort)
  logic        prof_rest;            // the profile's speed and feed word 0, no step output high

  assign time_d    = time_q + 64'd1;
  // Reading TIME_LO latches TIME_HI from the same clock's TIME.
  assign time_hi_d = hwif_out_i.time_lo.count.swacc ? time_q[63:32] : time_hi_q;
  assign estop_s_d = {estop_s_q[0], estop_i};
  assign estop     = estop_s_q[1];
  assign stopped   = hwif_out_i.events.wdog.value || hwif_out_i.events.estop.value || wstop_q;
  // Without the profile the bite aborts; with it, the controlled stop's end does.
  assign abort     = hwif_out_i.ctrl.abort_motion.value || (PROFILE == 0 && bite) || wstop_done ||
                     estop || latch_stop;
  assign wstop_done = PROFILE != 0 && wstop_q && prof_rest;
  assign wstop_d    = PROFILE != 0 && !abort && (bite || wstop_q);
  assign prof_clr_d = PROFILE != 0 && abort;

  // ---------------------------------------------------------------------------
  // Watchdog.
  logic [31:0] wdog_left_q, wdog_left_d;
  logic        wdog_kick_q, wdog_kick_d;
  logic        wdog_run, wdog_kick;

  // A kick (a write of WDOG_KICK or WDOG_PERIOD) reloads the count on its
  // clock and the next (a written period is in its register from then on).
  assign wdog_run    = hwif_out_i.wdog_period.period.value != 32'd0 && !hwif_out_i.events.wdog.value;
  assign wdog_kick   = hwif_out_i.wdog_kick.kick.swmod || hwif_out_i.wdog_period.period.swmod;
  assign wdog_kick_d = wdog_kick;
  assign bite        = wdog_run && !wdog_kick && !wdog_kick_q && wdog_left_q <= 32'd1;
  always_comb begin
    if (!wdog_run || wdog_kick || wdog_kick_q) wdog_left_d = hwif_out_i.wdog_period.period.value;
    else if (bite)                             wdog_left_d = 32'd0;
    else                                       wdog_left_d = wdog_left_q - 32'd1;
  end

  // ---------------------------------------------------------------------------
  // Command FIFO: cnt words in the RAM, and the head (the RAM's read register).
  logic                push;
  logic                push_ok, push_full, push_refused;
  logic [PTR_W-1:0]    wptr_q, wptr_d, rptr_q, rptr_d;
  logic [LVL_W-1:0]    cnt_q, cnt_d;
  logic                head_q, head_d;
  logic [LVL_W-1:0]    level;
  logic                full;
  logic                re;
  logic [ENTRY_W-1:0]  head_entry;
  logic [FULL_W-1:0]   head_all;  // head_entry, the fields PROFILE = 1 leaves out 0
  logic                head_due, head_late;
  logic                cmd_valid, cmd_ready, cmd_take;
  logic [63:0]         head_at;
  // The moves' side (PROFILE): read pointer, count, head and RAM of its own.
  logic [PTR_W-1:0]    mrptr_q, mrptr_d;
  logic [LVL_W-1:0]    mcnt_q, mcnt_d;
  logic                mhead_q, mhead_d;
  logic [LVL_W-1:0]    level_c, level_m;
  logic                mre;
  logic [MV_W-1:0]     head_move;
  logic                mv_valid, mv_ready, mv_take;
  logic                stop_open_q, stop_open_d;  // an exact stop taken and not yet at rest
  logic                stop_wait;                 // ... and the profile still busy
  logic                cmd_hold;                  // motion_top's next command waits for it
  logic                prof_busy;

  // The push: the clock of the write of CMD_PUSH (the staged values are in
  // their registers since the writes before it).
  assign push         = hwif_out_i.cmd_push.push.swmod;
  assign level_c      = cnt_q + LVL_W'(head_q);
  assign level_m      = mcnt_q + LVL_W'(mhead_q);
  assign level        = (level_m > level_c) ? level_m : level_c;
  assign full         = level == LVL_W'(FIFO_DEPTH);
  assign push_refused = push && (stopped || abort
                                 || (PROFILE == 1 && hwif_out_i.cmd_flags.timed.value));
  assign push_full    = push && !push_refused && full;
  assign push_ok      = push && !push_refused && !full;

  assign head_all = FULL_W'(head_entry);
  assign head_at   = head_all[E_AT +: 64];
  assign head_due  = !head_all[E_TIMED] || time_q >= head_at;
  assign head_late = head_all[E_TIMED] && time_q > head_at;
  assign stop_wait = stop_open_q && prof_busy;
  assign cmd_hold  = stop_wait && level_c <= level_m;
  assign cmd_valid = head_q && head_due && !abort && !cmd_hold;
  assign cmd_take  = cmd_valid && cmd_ready;
  assign re        = !abort && cnt_q != '0 && (!head_q || cmd_take);
  assign mv_valid  = mhead_q && !abort && !stop_wait && !prof_clr_q;
  assign mv_take   = mv_valid && mv_ready;
  assign mre       = !abort && mcnt_q != '0 && (!mhead_q || mv_take);
  assign stop_open_d = !abort && (mv_take ? head_move[M_END +: PROF_LVL_W] == '0 : stop_wait);

  always_comb begin
    wptr_d = wptr_q;
    rptr_d = rptr_q;
    cnt_d  = cnt_q;
    head_d = head_q;
    mrptr_d = mrptr_q;
    mcnt_d  = mcnt_q;
    mhead_d = mhead_q;
    if (abort) begin
      rptr_d = wptr_q;
      cnt_d  = '0;
      head_d = 1'b0;
      mrptr_d = wptr_q;
      mcnt_d  = '0;
      mhead_d = 1'b0;
    end else begin
      if (push_ok) wptr_d = (wptr_q == PTR_W'(FIFO_DEPTH - 1)) ? '0 : wptr_q + PTR_W'(1);
      if (re)      rptr_d = (rptr_q == PTR_W'(FIFO_DEPTH - 1)) ? '0 : rptr_q + PTR_W'(1);
      cnt_d  = cnt_q + LVL_W'(push_ok) - LVL_W'(re);
      head_d = re || (head_q && !cmd_take);
      if (PROFILE != 0) begin
        if (mre) mrptr_d = (mrptr_q == PTR_W'(FIFO_DEPTH - 1)) ? '0 : mrptr_q + PTR_W'(1);
        mcnt_d  = mcnt_q + LVL_W'(push_ok) - LVL_W'(mre);
        mhead_d = mre || (mhead_q && !mv_take);
      end
    end
  end

  // The RAM never reads and writes one word in a clock: a word is read only
  // while cnt_q != 0 and written only while the FIFO is not full, and the
  // pointers are equal only when cnt_q is 0 or FIFO_DEPTH (not full needs
  // cnt_q < FIFO_DEPTH then).
  prim_ram_1r1w #(
    .WIDTH       (ENTRY_W),
    .DEPTH       (FIFO_DEPTH),
    .SAME_WORD_RW(1'b0)
  ) u_fifo_ram (
    .clk_i,
    .we_i   (push_ok && !abort),
    .waddr_i(wptr_q),
    .wdata_i(push_entry),
    .re_i   (re),
    .raddr_i(rptr_q),
    .rdata_o(head_entry)
  );

  // The moves' RAM: the same words written, read through the moves' own
  // pointer (the same argument: the level bounds both counts).
  if (PROFILE != 0) begin : g_move_ram
    prim_ram_1r1w #(
      .WIDTH       (MV_W),
      .DEPTH       (FIFO_DEPTH),
      .SAME_WORD_RW(1'b0)
    ) u_move_ram (
      .clk_i,
      .we_i   (push_ok && !abort),
      .waddr_i(wptr_q),
      .wdata_i(push_move),
      .re_i   (mre),
      .raddr_i(mrptr_q),
      .rdata_o(head_move)
    );
  end else begin : g_no_move_ram
    assign head_move = '0;
  end

  // ---------------------------------------------------------------------------
  // The core.
  logic [AXES-1:0]       step, dir;
  logic [AXES*POS_W-1:0] pos;
  logic                  busy, done;
  logic [FEED_W:0]       feed_word, prof_feed, core_feed;
  logic [PROF_LVL_W-1:0] prof_level;
  logic [SPD_W:0]        prof_speed;
  logic                  prof_rst_n, prof_hold;
  logic [SPD_W-1:0]      prof_q;
  logic [LEN_W:0]        prof_len;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [63:0]           prof_q64;
  /* verilator lint_on UNUSEDSIGNAL */

  assign feed_word = feed_w32[FEED_W:0];
  assign core_feed = (PROFILE != 0) ? prof_feed : feed_word;

  // The profile's registers: q modulo 2^SPD_W, L saturated at 2^LEN_W.
  assign prof_q64  = {hwif_out_i.prof_q.hi.value, hwif_out_i.prof_q.lo.value};
  assign prof_q    = prof_q64[SPD_W-1:0];
  assign prof_len  = (hwif_out_i.prof_len.value.value > (32'd1 << LEN_W)) ? (LEN_W + 1)'(1 << LEN_W)
                                                                          : hwif_out_i.prof_len.value.value[LEN_W:0];
  assign prof_hold = hwif_out_i.prof_ctrl.hold.value || wstop_q;
  assign prof_rst_n = rst_ni && !prof_clr_q;

  if (PROFILE != 0) begin : g_profile
    feed_profile #(
      .FEED_W(FEED_W),
      .SPD_W (SPD_W),
      .TICK_W(TICK_W),
      .LEN_W (LEN_W),
      .LVL_W (PROF_LVL_W),
      .OPS_W (MV_OPS_W)
    ) u_profile (
      .clk_i,
      .rst_ni      (prof_rst_n),
      .q_i         (prof_q),
      .len_i       (prof_len),
      .cmd_valid_i (mv_valid),
      .cmd_ready_o (mv_ready),
      .cmd_ops_i   (head_move[M_OPS +: MV_OPS_W]),
      .cmd_target_i(head_move[M_TARGET +: PROF_LVL_W]),
      .cmd_end_i   (head_move[M_END +: PROF_LVL_W]),
      .cmd_max_i   (head_move[M_MAX +: PROF_LVL_W]),
      .hold_i      (prof_hold),
      .ovr_i       (hwif_out_i.prof_ctrl.ovr.value),
      .feed_o      (prof_feed),
      .level_o     (prof_level),
      .speed_o     (prof_speed),
      .busy_o      (prof_busy)
    );
  end else begin : g_no_profile
    assign mv_ready   = 1'b0;
    assign prof_feed  = '0;
    assign prof_level = '0;
    assign prof_speed = '0;
    assign prof_busy  = 1'b0;
    logic unused_prof;
    assign unused_prof = ^{prof_q, prof_len, prof_hold, prof_rst_n, push_move, head_move, mv_valid};
  end

  motion_top #(
    .AXES   (AXES),
    .ACC_W  (ACC_W),
    .COORD_W(COORD_W),
    .OPS_W  (OPS_W),
    .POS_W  (POS_W),
    .TIM_W  (TIM_W),
    .FEED_W (FEED_W)
  ) u_core (
    .clk_i,
    .rst_ni,
    .cmd_valid_i (cmd_valid),
    .cmd_ready_o (cmd_ready),
    .cmd_arc_i   (head_entry[E_ARC]),
    .cmd_delta_i (head_entry[E_DELTA +: AXES * ACC_W]),
    .cmd_plane_i (head_entry[E_PLANE +: 2]),
    .cmd_center_i(head_entry[E_CENTER +: 2 * COORD_W]),
    .cmd_end_i   (head_entry[E_END +: 2 * COORD_W]),
    .cmd_ccw_i   (head_entry[E_CCW]),
    .cmd_ops_i   (head_entry[E_OPS +: OPS_W]),
    .cmd_feed_i  (head_entry[E_FEED +: FEED_W + 1]),
    .feed_i      (core_feed),
    .step_len_i  (step_len32[TIM_W-1:0]),
    .step_space_i(step_space32[TIM_W-1:0]),
    .dir_setup_i (dir_setup32[TIM_W-1:0]),
    .dir_hold_i  (dir_hold32[TIM_W-1:0]),
    .abort_i     (abort),
    .step_o      (step),
    .dir_o       (dir),
    .pos_o       (pos),
    .busy_o      (busy),
    .done_o      (done)
  );

  // ---------------------------------------------------------------------------
  // Per-axis speed (clocks between steps) and the step output types.
  logic [AXES-1:0]  step_prev_q, step_prev_d;
  logic [AXES-1:0]  seen_q, seen_d;
  logic [AXES-1:0]  neg_q, neg_d;
  logic [AXES*31-1:0] since_q, since_d;    // clocks since the last step, axis i at [i*31 +: 31]
  logic [AXES*31-1:0] period_q, period_d;  // clocks between the last two steps
  // over_q[i] == (since > period) of axis i, kept without a magnitude compare:
  // since counts up by one a clock (saturating) while period holds, so it
  // passes period on the clock after it equals it (unless saturated there),
  // and a step clears both sides (since 0, period since + 1 or held).
  logic [AXES-1:0]  over_q, over_d;
  logic [1:0]       type_reg [6];
  logic [AXES-1:0]  rise;
  logic [31:0]      speed [AXES];
  logic [30:0]      since_inc [AXES];

  assign type_reg[0] = hwif_out_i.step_type.axis0.value;
  assign type_reg[1] = hwif_out_i.step_type.axis1.value;
  assign type_reg[2] = hwif_out_i.step_type.axis2.value;
  assign type_reg[3] = hwif_out_i.step_type.axis3.value;
  assign type_reg[4] = hwif_out_i.step_type.axis4.value;
  assign type_reg[5] = hwif_out_i.step_type.axis5.value;
  assign step_prev_d = step;
  assign prof_rest   = prof_speed == '0 && prof_feed == '0 && step == '0;
  assign rise        = step & ~step_prev_q;

  always_comb begin
    for (int i = 0; i < AXES; i++) begin
      seen_d[i]   = seen_q[i] || rise[i];
      neg_d[i]    = rise[i] ? dir[i] : neg_q[i];
      since_inc[i] = &since_q[i*31 +: 31] ? since_q[i*31 +: 31] : since_q[i*31 +: 31] + 31'd1;
      since_d[i*31 +: 31]  = rise[i] ? 31'd0 : since_inc[i];
      period_d[i*31 +: 31] = (rise[i] && seen_q[i]) ? since_inc[i] : period_q[i*31 +: 31];
      over_d[i]   = !rise[i] && (over_q[i] || (since_q[i*31 +: 31] == period_q[i*31 +: 31] &&
                                                   !(&since_q[i*31 +: 31])));
      speed[i]    = !seen_q[i] ? 32'd0
                  : {neg_q[i], over_q[i] ? since_q[i*31 +: 31] : period_q[i*31 +: 31]};
    end
  end

`ifndef SYNTHESIS
  // over_q stands for the compare since > period: simulation checks it.
  always_ff @(posedge clk_i) begin
    for (int i = 0; i < AXES; i++) begin
      if (over_q[i] != (since_q[i*31 +: 31] > period_q[i*31 +: 31])) begin
        $error("motion_soc: axis %0d: over_q %0b is not since > period", i, over_q[i]);
      end
    end
  end
`endif

  for (genvar i = 0; i < AXES; i++) begin : g_encode
    step_encode u_encode (
      .clk_i,
      .rst_ni,
      .type_i(type_reg[i]),
      .step_i(step[i]),
      .dir_i (dir[i]),
      .a_o   (out_a_o[i]),
      .b_o   (out_b_o[i])
    );
  end

  // ---------------------------------------------------------------------------
  // Probe filter and latch, snapshot.
  logic [1:0]  probe_s_q, probe_s_d;
  logic        probe_f_q, probe_f_d;
  logic [15:0] probe_n_q, probe_n_d;
  logic        probe_edge;
  logic        latch_armed_q, latch_armed_d, latch_armed;
  logic        snap_armed_q, snap_armed_d, snap_armed;
  logic        snap_fire;
  logic [63:0] snap_at;
  logic [63:0] snap_time_q, snap_time_d, latch_time_q, latch_time_d;
  logic [AXES*64-1:0] snap_pos_q, snap_pos_d;      // axis i at [i*64 +: 64]
  logic [AXES*32-1:0] snap_speed_q, snap_speed_d;  // axis i at [i*32 +: 32]
  logic [AXES*64-1:0] latch_pos_q, latch_pos_d;
  logic [63:0] pos64 [AXES];

  assign probe_s_d = {probe_s_q[0], probe_i};
  always_comb begin
    probe_f_d = probe_f_q;
    probe_n_d = '0;
    if (probe_s_q[1] != probe_f_q) begin
      if (probe_n_q >= hwif_out_i.probe_cfg.filter.value) probe_f_d = probe_s_q[1];
      else probe_n_d = probe_n_q + 16'd1;
    end
  end
  assign probe_edge = hwif_out_i.probe_cfg.falling.value ? (probe_f_q && !probe_f_d)
                                                         : (!probe_f_q && probe_f_d);
  // An arm acts from the clock after its write (the singlepulse field's).
  assign latch_armed   = latch_armed_q || hwif_out_i.latch_ctrl.arm.value;
  assign latch_fire    = latch_armed && probe_edge;
  assign latch_stop    = latch_fire && hwif_out_i.probe_cfg.stop.value;
  assign latch_armed_d = latch_armed && !probe_edge;

  assign snap_at      = {hwif_out_i.snap_at.hi.value, hwif_out_i.snap_at.lo.value};
  assign snap_armed   = snap_armed_q || hwif_out_i.snap_ctrl.arm.value;
  assign snap_fire    = snap_armed && time_q >= snap_at;
  assign snap_armed_d = snap_armed && !snap_fire;

  always_comb begin
    snap_time_d  = snap_fire ? time_q : snap_time_q;
    latch_time_d = latch_fire ? time_q : latch_time_q;
    for (int i = 0; i < AXES; i++) begin
      pos64[i]        = 64'(signed'(pos[i*POS_W +: POS_W]));
      snap_pos_d[i*64 +: 64]   = snap_fire ? pos64[i] : snap_pos_q[i*64 +: 64];
      snap_speed_d[i*32 +: 32] = snap_fire ? speed[i] : snap_speed_q[i*32 +: 32];
      latch_pos_d[i*64 +: 64]  = latch_fire ? pos64[i] : latch_pos_q[i*64 +: 64];
    end
  end

  // ---------------------------------------------------------------------------
  // The events, the status and the ID.
  logic [6*64-1:0] snap_pos6, latch_pos6;
  logic [6*32-1:0] snap_speed6;
  assign snap_pos6   = (6*64)'(snap_pos_q);
  assign latch_pos6  = (6*64)'(latch_pos_q);
  assign snap_speed6 = (6*32)'(snap_speed_q);
  always_comb begin
    hwif_in_o = '0;
    hwif_in_o.id_build.axes.next       = 4'(AXES);
    hwif_in_o.id_build.core.next       = 4'd1;
    hwif_in_o.id_build.bus.next        = 2'(BUS);
    hwif_in_o.id_build.step_types.next = 3'b111;
    hwif_in_o.id_build.profile.next    = PROFILE != 0;
    if (PROFILE != 0) begin
      hwif_in_o.id_profile.spd_w.next  = 8'(SPD_W);
      hwif_in_o.id_profile.tick_w.next = 8'(TICK_W);
      hwif_in_o.id_profile.len_w.next  = 8'(LEN_W);
      hwif_in_o.id_profile.lvl_w.next  = 8'(PROF_LVL_W);
    end
    hwif_in_o.prof_level.c.next      = 32'(prof_level);
    hwif_in_o.prof_speed.speed.next  = 64'(prof_speed);
    hwif_in_o.status.prof_busy.next     = prof_busy;
    hwif_in_o.status.wdog_stopping.next = wstop_q;
    hwif_in_o.id_build.fifo_depth.next = 16'(FIFO_DEPTH);
    hwif_in_o.id_widths.acc_w.next     = 8'(ACC_W);
    hwif_in_o.id_widths.coord_w.next   = 8'(COORD_W);
    hwif_in_o.id_widths.ops_w.next     = 8'(OPS_W);
    hwif_in_o.id_widths.pos_w.next     = 8'(POS_W);
    hwif_in_o.id_widths2.tim_w.next    = 8'(TIM_W);
    hwif_in_o.id_widths2.feed_w.next   = 8'(FEED_W);
    hwif_in_o.id_clock.hz.next         = 32'(CLK_HZ);

    hwif_in_o.status.busy.next        = busy;
    hwif_in_o.status.fifo_empty.next  = level == '0;
    hwif_in_o.status.fifo_full.next   = full;
    hwif_in_o.status.low.next         = 16'(level) <= hwif_out_i.fifo_low.mark.value;
    hwif_in_o.status.probe.next       = probe_f_q;
    hwif_in_o.status.wdog_run.next    = wdog_run;
    hwif_in_o.status.stopped.next     = stopped;
    hwif_in_o.status.snap_armed.next  = snap_armed;
    hwif_in_o.status.latch_armed.next = latch_armed;
    hwif_in_o.status.waiting.next     = head_q && !head_due;

    hwif_in_o.events.overflow.next  = push_full;
    hwif_in_o.events.refused.next   = push_refused;
    hwif_in_o.events.late.next      = cmd_take && head_late;
    hwif_in_o.events.wdog.next      = bite;
    hwif_in_o.events.snap.next      = snap_fire;
    hwif_in_o.events.latch.next     = latch_fire;
    hwif_in_o.events.low_water.next = 16'(level) <= hwif_out_i.fifo_low.mark.value;
    hwif_in_o.events.estop.next     = estop;
    hwif_in_o.events.done.next      = done;

    hwif_in_o.fifo_level.fill.next = 16'(level);
    hwif_in_o.fifo_level.room.next = 16'(FIFO_DEPTH) - 16'(level);
    hwif_in_o.time_lo.count.next   = time_q[31:0];
    hwif_in_o.time_hi.count.next   = time_hi_q;
    hwif_in_o.wdog_left.left.next  = wdog_left_q;

    hwif_in_o.snap_time.count.next  = snap_time_q;
    hwif_in_o.latch_time.count.next = latch_time_q;
    // Axes the build does not have read 0.
    hwif_in_o.snap_pos0.pos.next = snap_pos6[0*64 +: 64];
    hwif_in_o.snap_pos1.pos.next = snap_pos6[1*64 +: 64];
    hwif_in_o.snap_pos2.pos.next = snap_pos6[2*64 +: 64];
    hwif_in_o.snap_pos3.pos.next = snap_pos6[3*64 +: 64];
    hwif_in_o.snap_pos4.pos.next = snap_pos6[4*64 +: 64];
    hwif_in_o.snap_pos5.pos.next = snap_pos6[5*64 +: 64];
    hwif_in_o.latch_pos0.pos.next = latch_pos6[0*64 +: 64];
    hwif_in_o.latch_pos1.pos.next = latch_pos6[1*64 +: 64];
    hwif_in_o.latch_pos2.pos.next = latch_pos6[2*64 +: 64];
    hwif_in_o.latch_pos3.pos.next = latch_pos6[3*64 +: 64];
    hwif_in_o.latch_pos4.pos.next = latch_pos6[4*64 +: 64];
    hwif_in_o.latch_pos5.pos.next = latch_pos6[5*64 +: 64];
    {hwif_in_o.snap_speed0.neg.next, hwif_in_o.snap_speed0.period.next} = snap_speed6[0*32 +: 32];
    {hwif_in_o.snap_speed1.neg.next, hwif_in_o.snap_speed1.period.next} = snap_speed6[1*32 +: 32];
    {hwif_in_o.snap_speed2.neg.next, hwif_in_o.snap_speed2.period.next} = snap_speed6[2*32 +: 32];
    {hwif_in_o.snap_speed3.neg.next, hwif_in_o.snap_speed3.period.next} = snap_speed6[3*32 +: 32];
    {hwif_in_o.snap_speed4.neg.next, hwif_in_o.snap_speed4.period.next} = snap_speed6[4*32 +: 32];
    {hwif_in_o.snap_speed5.neg.next, hwif_in_o.snap_speed5.period.next} = snap_speed6[5*32 +: 32];
  end
  // irq_o: the events enabled in IRQ_EN (computed here: an `enable` in the
  // description would give the events register a mangled type name in the
  // generated header).
  assign irq_o = (hwif_out_i.events.overflow.value  && hwif_out_i.irq_en.overflow.value)
              || (hwif_out_i.events.refused.value   && hwif_out_i.irq_en.refused.value)
              || (hwif_out_i.events.late.value      && hwif_out_i.irq_en.late.value)
              || (hwif_out_i.events.wdog.value      && hwif_out_i.irq_en.wdog.value)
              || (hwif_out_i.events.snap.value      && hwif_out_i.irq_en.snap.value)
              || (hwif_out_i.events.latch.value     && hwif_out_i.irq_en.latch.value)
              || (hwif_out_i.events.low_water.value && hwif_out_i.irq_en.low_water.value)
              || (hwif_out_i.events.estop.value     && hwif_out_i.irq_en.estop.value)
              || (hwif_out_i.events.done.value      && hwif_out_i.irq_en.done.value);

  // ---------------------------------------------------------------------------
  // Registers.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      time_q        <= '0;
      time_hi_q     <= '0;
      estop_s_q     <= '0;
      wdog_left_q   <= '0;
      wdog_kick_q   <= 1'b0;
      wptr_q        <= '0;
      rptr_q        <= '0;
      cnt_q         <= '0;
      head_q        <= 1'b0;
      mrptr_q       <= '0;
      mcnt_q        <= '0;
      mhead_q       <= 1'b0;
      stop_open_q   <= 1'b0;
      wstop_q       <= 1'b0;
      prof_clr_q    <= 1'b0;
      step_prev_q   <= '0;
      seen_q        <= '0;
      neg_q         <= '0;
      probe_s_q     <= '0;
      probe_f_q     <= 1'b0;
      probe_n_q     <= '0;
      latch_armed_q <= 1'b0;
      snap_armed_q  <= 1'b0;
      snap_time_q   <= '0;
      latch_time_q  <= '0;
      since_q       <= '0;
      period_q      <= '0;
      over_q        <= '0;
      snap_pos_q    <= '0;
      snap_speed_q  <= '0;
      latch_pos_q   <= '0;
    end else begin
      time_q        <= time_d;
      time_hi_q     <= time_hi_d;
      estop_s_q     <= estop_s_d;
      wdog_left_q   <= wdog_left_d;
      wdog_kick_q   <= wdog_kick_d;
      wptr_q        <= wptr_d;
      rptr_q        <= rptr_d;
      cnt_q         <= cnt_d;
      head_q        <= head_d;
      mrptr_q       <= mrptr_d;
      mcnt_q        <= mcnt_d;
      mhead_q       <= mhead_d;
      stop_open_q   <= stop_open_d;
      wstop_q       <= wstop_d;
      prof_clr_q    <= prof_clr_d;
      step_prev_q   <= step_prev_d;
      seen_q        <= seen_d;
      neg_q         <= neg_d;
      probe_s_q     <= probe_s_d;
      probe_f_q     <= probe_f_d;
      probe_n_q     <= probe_n_d;
      latch_armed_q <= latch_armed_d;
      snap_armed_q  <= snap_armed_d;
      snap_time_q   <= snap_time_d;
      latch_time_q  <= latch_time_d;
      since_q       <= since_d;
      period_q      <= period_d;
      over_q        <= over_d;
      snap_pos_q    <= snap_pos_d;
      snap_speed_q  <= snap_speed_d;
      latch_pos_q   <= latch_pos_d;
    end
  end
endmodule

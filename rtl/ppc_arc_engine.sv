// ppc_arc_engine: the point-by-point comparison (PPC) circular-arc engine of
// rule M (models/ppc.h, models::PpcArcStream: the arc, its bound and its
// derivation), shared by ppc_arc (its whole engine) and motion_top (its arcs).
// It holds the running arc and decides, per operation, which plane axis
// steps; the caller owns the command buffer, the feed and the step/dir stage.
//
// Rule M: the PPC arc on the circle through s until, in the final pass
// (after `laps` quadrant entries), the axis the arc would step has nothing
// left towards e in its motion direction; then the guarded PPC line from p
// to e (rtl/ppc_line_step.sv). No multiplier: the state is kept in motion
// coordinates,
//   m_a  the motion sign of each axis (mneg_q: 1 = negative)
//   a_a = p_a m_a  (< 0 on the inward axis, the one moving towards the centre)
//   g_a = (e_a - p_a) m_a  (what is left towards e in the motion direction)
// so that one operation is: pick the axis (F >= 0: the inward one, else the
// outward one), F += 2 a + 1 (one adder: {a, 1}), a += 1, g -= 1. A step that
// lands the stepped coordinate on 0 (a = -1 before it) enters the next
// quadrant: the other axis's motion sign flips (its a and g negate) and the
// lap count falls by one.
//
// Set-up, when the engine takes a command: the quadrant of s and of e (a
// point on an axis belongs to the quadrant the motion enters) give the motion
// signs and laps = entries from s's quadrant to e's (0..3; same quadrant: 0
// if e is ahead of s, 4 if it is behind on both axes, E * m <= 0 per axis;
// s == e is a full circle, 4). Degenerate commands (|s|^2 < 2, or e == c)
// have no arc phase.
//
// Operations:
//   arc phase   one step; in the final pass, if the picked axis has g <= 0,
//               the operation steps nothing and loads the closing line with
//               |e - p| = |g| (the switch); a step that lands on e in the
//               final pass (g = 1 on the stepped axis, 0 on the other) is the
//               command's last operation, with no closing line (every arc
//               whose end is on the circle ends this way);
//   closing     the guarded PPC line, |dx| + |dy| operations; a degenerate
//               command spends one operation loading it (and a zero-length
//               one a second, empty one).
//
// Internal widths (no accepted command overflows):
//   s, e, and a = p_a * m_a   PW = COORD_W + 1 (|e_a| <= 2^COORD_W - 1,
//                             |p_a| < |s| + 1 <= 2^(COORD_W - 1/2) + 1)
//   g = (e_a - p_a) * m_a     GW = COORD_W + 2 (|g| < 2^COORD_W + |p_a|)
//   F = |p|^2 - |s|^2         FW = COORD_W + 2 (-2|s| + 1 <= F < 2|s| + 1)
//   closing line |e - p|      MW = COORD_W + 1
//
// Look-ahead. The engine runs one operation ahead of the caller: the
// operation the caller does this clock (its outputs, step_o ... last_o) is a
// set of registers, and the arc state (F, a, g, the flags, the closing line)
// is the state after it, from which the next operation is decided. When the
// caller does the operation (advance_i), or the operation register is empty
// and the caller lets it fill (fill_i), the decided operation moves into the
// operation register and the state takes it. So every output is a register,
// the step/dir stage is told a clock ahead which axes the next clock's
// operation steps (step_next_o, want_dir_next_o: its registered stall,
// READY_Q = 1), and the clock's late signal (advance_i) only enables
// registers: it never waits on the arc's arithmetic, and the arithmetic
// never waits on it.
//
// Taking a command. The caller's buffer offers a command (ld_valid_i: a
// command the engine has not started). The engine copies it into its state
// when the state has no operation left (the previous command's last
// operation has moved into the operation register, or the engine is idle);
// the copy is pending until its first operation moves into the operation
// register (start_o: the caller frees the buffer). So commands chain without
// a gap as long as the next one is buffered before the clock on which the
// previous one's last operation is done; a command buffered later (or when
// the engine is idle) starts two clocks after it is buffered (the copy, then
// its first operation).
//
// Timing: the compares an operation needs on the picked axis (a == -1: a
// quadrant entry; g <= 0: the switch; g == 1, g == 0: landing on e) are
// registers per axis, decided a clock ahead by compares of the registers
// themselves (a + 1 == -1 iff a == -2, -g == 1 iff g == -1, ...), never of the
// next values: choosing the axis (F's sign) selects flags, not COORD_W-bit
// words. Each flag equals its compare at every clock. F's two possible next
// values (after an x step, after a y step) are summed from registers and the
// pick selects one after the carry chains. The arc registers' enable is the
// take and the phase (arc_en), not the operation's arithmetic: the state
// also steps on the switch (after the closing line took |g|) and is set up
// from whatever is offered on a last operation, values nothing reads until
// a command is loaded.
//
// hls/ppc_arc_engine.h is the same arithmetic in C++ (hls/ppc_arc.h and
// hls/motion_top.h model the look-ahead's start rule).
module ppc_arc_engine #(
  parameter int COORD_W = 24  // width of the command's signed coordinates (3..60)
) (
  input  logic                 clk_i,            // clock
  input  logic                 rst_ni,           // asynchronous, active low
  // The caller's buffer
  input  logic                 ld_valid_i,       // a command the engine has not started is offered
  input  logic [6*COORD_W+3:0] ld_prep_i,        // its s, e, E (rtl/ppc_arc_prep.sv)
  input  logic                 ld_ccw_i,         // its direction, 1: counter-clockwise
  output logic                 pending_o,        // the offered command is copied, not started
  output logic                 start_o,          // its first operation moves in this clock (free the buffer)
  // The caller
  input  logic                 fill_i,           // an empty operation register may take the next operation
  input  logic                 advance_i,        // the caller does this clock's operation (implies run_o)
  input  logic                 abort_i,          // drop the running and the offered command
  // This clock's operation (registers)
  output logic                 run_o,            // there is one: a command runs
  output logic [1:0]           step_o,           // it steps the axis (x bit 0)
  output logic [1:0]           want_valid_o,     // the command may still step the axis (x bit 0)
  output logic [1:0]           want_dir_o,       // the axis's direction, 1: negative (x bit 0)
  output logic                 last_o,           // it is the command's last
  // The next clock's (the registers' next values)
  output logic                 run_next_o,       // run_o of the next clock
  output logic [1:0]           step_next_o,      // step_o of the next clock
  output logic [1:0]           want_dir_next_o   // want_dir_o of the next clock
);
  // Parameter check at elaboration: Verilator and Yosys stop with the message
  // (Icarus 11 has no elaboration system tasks: it skips the check). The
  // range is the HLS face's (hls/ppc_arc_engine.h), and so the lockstep
  // verification's.
`ifndef __ICARUS__
  if (COORD_W < 3 || COORD_W > 60) begin : g_bad_coord_w
    $error("ppc_arc_engine: parameter COORD_W must be 3..60");
  end
`endif

  localparam int PW = COORD_W + 1;  // s, e, a = p m
  localparam int GW = COORD_W + 2;  // g = (e - p) m
  localparam int FW = COORD_W + 2;  // F = |p|^2 - |s|^2
  localparam int MW = COORD_W + 1;  // closing line magnitudes
  localparam logic [PW-1:0] PMinus1 = {PW{1'b1}};

  // ---------------------------------------------------------------------------
  // Set-up of the offered command: quadrants, motion signs, laps, start state.
  logic [PW-1:0]      ld_sx, ld_sy, ld_ex, ld_ey;
  logic [COORD_W-1:0] ld_dx, ld_dy;
  logic          sx_neg, sy_neg, sx_zero, sy_zero, ex_neg, ey_neg, ex_zero, ey_zero;
  logic          qsx_neg, qsy_neg, qex_neg, qey_neg;  // quadrant signs of s and e
  logic [1:0]    ks, ke, kdiff;  // quadrant indices I..IV = 0..3, entries between them
  logic          ld_mneg_x, ld_mneg_y;  // motion signs at s (1: negative)
  logic          ld_behind;  // e behind s on both axes (or e == s)
  logic [2:0]    ld_laps;
  logic          ld_degenerate;  // |s|^2 < 2 or e == c: no arc phase
  logic          sx_small, sy_small;  // |s_a| <= 1
  logic [PW-1:0] ld_ax, ld_ay;  // a = s m
  logic [GW-1:0] ld_gx, ld_gy;  // g = E m
  logic [GW-1:0] dx_ext, dy_ext;

  assign ld_sx   = ld_prep_i[0 +: PW];
  assign ld_sy   = ld_prep_i[PW +: PW];
  assign ld_ex   = ld_prep_i[2*PW +: PW];
  assign ld_ey   = ld_prep_i[3*PW +: PW];
  assign ld_dx   = ld_prep_i[4*PW +: COORD_W];
  assign ld_dy   = ld_prep_i[4*PW+COORD_W +: COORD_W];
  assign sx_neg  = ld_sx[PW-1];
  assign sy_neg  = ld_sy[PW-1];
  assign sx_zero = ld_sx == '0;
  assign sy_zero = ld_sy == '0;
  assign ex_neg  = ld_ex[PW-1];
  assign ey_neg  = ld_ey[PW-1];
  assign ex_zero = ld_ex == '0;
  assign ey_zero = ld_ey == '0;
  // A point on an axis belongs to the quadrant the motion enters:
  // CCW (x, 0) has the sign of x for y, (0, y) the opposite of y for x;
  // CW the other way round (models/ppc.cpp motion_at()).
  assign qsy_neg = sy_zero ? (sx_neg ^ !ld_ccw_i) : sy_neg;
  assign qsx_neg = sx_zero ? (sy_neg ^ ld_ccw_i) : sx_neg;
  assign qey_neg = ey_zero ? (ex_neg ^ !ld_ccw_i) : ey_neg;
  assign qex_neg = ex_zero ? (ey_neg ^ ld_ccw_i) : ex_neg;
  assign ks = {qsy_neg, qsx_neg ^ qsy_neg};
  assign ke = {qey_neg, qex_neg ^ qey_neg};
  assign kdiff = ld_ccw_i ? ke - ks : ks - ke;
  // Motion CCW (-qy, qx), CW (qy, -qx).
  assign ld_mneg_x = qsy_neg ^ ld_ccw_i;
  assign ld_mneg_y = qsx_neg ^ !ld_ccw_i;
  // E_a m_a <= 0: E_a is 0 or has the sign opposite to m_a.
  assign ld_behind = (ld_dx == '0 || ld_dx[COORD_W-1] != ld_mneg_x) &&
                     (ld_dy == '0 || ld_dy[COORD_W-1] != ld_mneg_y);
  assign ld_laps = kdiff != 2'd0 ? {1'b0, kdiff} : (ld_behind ? 3'd4 : 3'd0);
  assign sx_small = ld_sx[PW-1:1] == '0 || ld_sx == PMinus1;
  assign sy_small = ld_sy[PW-1:1] == '0 || ld_sy == PMinus1;
  assign ld_degenerate = (sx_small && sy_zero) || (sx_zero && sy_small) || (ex_zero && ey_zero);
  assign ld_ax = ld_mneg_x ? -ld_sx : ld_sx;
  assign ld_ay = ld_mneg_y ? -ld_sy : ld_sy;
  assign dx_ext = {{2{ld_dx[COORD_W-1]}}, ld_dx};
  assign dy_ext = {{2{ld_dy[COORD_W-1]}}, ld_dy};
  assign ld_gx = ld_mneg_x ? -dx_ext : dx_ext;
  assign ld_gy = ld_mneg_y ? -dy_ext : dy_ext;

  // ---------------------------------------------------------------------------
  // The arc state: after the operation in the operation register.
  logic          fin_q, fin_d;  // no operation left (idle, or the last one has moved on)
  logic          pend_q, pend_d;  // the state holds an offered command, not started
  logic          sw_q, sw_d;  // the next operation loads the closing line (degenerate)
  logic          line_q, line_d;  // the closing line runs
  logic [PW-1:0] ax_q, ax_d, ay_q, ay_d;  // a = p m
  logic [GW-1:0] gx_q, gx_d, gy_q, gy_d;  // g = (e - p) m
  logic [FW-1:0] f_q, f_d;  // F = |p|^2 - |s|^2
  logic [1:0]    mneg_q, mneg_d;  // motion signs in the arc (1: negative)
  logic [1:0]    lneg_q, lneg_d;  // directions of the closing line
  logic [2:0]    laps_q, laps_d;  // quadrant entries before the final pass
  // Per axis (x bit 0, y bit 1): a == -1, g <= 0, g == 0, g == 1.
  logic [1:0]    am1_q, am1_d, gle0_q, gle0_d, gz_q, gz_d, gone_q, gone_d;

  // The operation register: this clock's operation.
  logic          cur_q, cur_d;  // valid
  logic [1:0]    st_q, st_d, wv_q, wv_d, wd_q, wd_d;  // steps, want_valid, want_dir
  logic          last_q, last_d;

  // The next operation, decided from the state.
  logic          arc;  // the arc phase
  logic          pick_x;  // the arc steps x (else y)
  logic [FW-1:0] f_sx, f_sy;  // F + 2 a + 1 after an x step, after a y step
  logic          final_pass, arc_switch, entry, land, arc_last;
  logic          line_load;  // the operation loads the closing line with |g|
  logic [1:0]    dec_st, dec_wv, dec_wd;
  logic          dec_last;
  logic          take;  // the operation moves into the operation register, the state takes it
  logic          load;  // the state takes the offered command
  logic          arc_en;  // the arc registers take their next values
  logic          use_ld;  // ...to the offered command's set-up (else the stepped state)
  logic [MW-1:0] mag_x, mag_y;  // |g|
  logic          l_x_left, l_y_left, l_step_x, l_step_y, l_last;
  logic [1:0]    l_dir;  // direction of e - p: the sign of g, turned by the motion sign
  logic [1:0]    flip;  // a quadrant entry flips the other axis's motion sign
  // Compares of the registers for the flags' next values, per axis.
  logic [1:0]    am2, ap1, gtwo, gm1, gneg;  // a == -2, a == 1, g == 2, g == -1, g < 0
  logic [1:0]    ld_am1, ld_gle0, ld_gz, ld_gone;  // the flags of the offered set-up

  assign arc        = !fin_q && !sw_q && !line_q;
  // F >= 0 picks the inward axis (a < 0), F < 0 the outward one.
  assign pick_x     = f_q[FW-1] ^ ax_q[PW-1];
  // Both sums from registers; the pick only selects one (after the carry
  // chains, not in front of them).
  assign f_sx       = f_q + {ax_q, 1'b1};
  assign f_sy       = f_q + {ay_q, 1'b1};
  assign final_pass = laps_q == 3'd0;
  assign arc_switch = final_pass && (pick_x ? gle0_q[0] : gle0_q[1]);
  assign entry      = pick_x ? am1_q[0] : am1_q[1];
  assign land       = pick_x ? gone_q[0] && gz_q[1] : gone_q[1] && gz_q[0];
  // A landing step (g = 1 on the stepped axis) is never a switch (g <= 0).
  assign arc_last   = (final_pass || (laps_q == 3'd1 && entry)) && land;
  assign mag_x      = MW'(gx_q[GW-1] ? -gx_q : gx_q);
  assign mag_y      = MW'(gy_q[GW-1] ? -gy_q : gy_q);
  assign l_dir      = {gy_q[GW-1] ^ mneg_q[1], gx_q[GW-1] ^ mneg_q[0]};
  assign flip       = pick_x ? 2'b10 : 2'b01;
  assign line_load  = sw_q || (arc && arc_switch);

  assign dec_st   = arc ? {!arc_switch && !pick_x, !arc_switch && pick_x} :
                    (line_q && !fin_q) ? {l_step_y, l_step_x} : 2'b00;
  assign dec_wv   = arc ? 2'b11 : (line_q && !fin_q) ? {l_y_left, l_x_left} : 2'b00;
  assign dec_wd   = line_q ? lneg_q : mneg_q;
  assign dec_last = line_q ? l_last : !sw_q && arc_last;

  assign take   = (advance_i || (!cur_q && fill_i)) && !abort_i && !fin_q;
  assign load   = ld_valid_i && !pend_q && !abort_i && (fin_q || (take && dec_last));
  assign use_ld = fin_q || dec_last;
  // The arc registers' enable waits on no arc arithmetic: every operation
  // of the arc phase (the switch and a degenerate command's line load too)
  // steps them, a closing line's operation keeps them unless it is the last,
  // and a last operation sets them up from the offered command whether or
  // not one is offered (the state is finished then: nothing reads them
  // until a command is loaded). Only the data (use_ld) waits on "last".
  assign arc_en = (take && (!line_q || l_last)) || (fin_q && ld_valid_i && !pend_q && !abort_i);

  assign am2  = {ay_q == PW'(-2), ax_q == PW'(-2)};
  assign ap1  = {ay_q == PW'(1), ax_q == PW'(1)};
  assign gtwo = {gy_q == GW'(2), gx_q == GW'(2)};
  assign gm1  = {gy_q == {GW{1'b1}}, gx_q == {GW{1'b1}}};
  assign gneg = {gy_q[GW-1], gx_q[GW-1]};
  // The set-up's flags from s and E before the motion sign turns them (no
  // negation on the way): a = s m == -1 iff s == -m; g = E m <= 0 iff E m <= 0.
  assign ld_am1  = {ld_mneg_y ? ld_sy == PW'(1) : ld_sy == PMinus1,
                    ld_mneg_x ? ld_sx == PW'(1) : ld_sx == PMinus1};
  assign ld_gz   = {ld_dy == '0, ld_dx == '0};
  assign ld_gle0 = {ld_mneg_y ? !ld_dy[COORD_W-1] : ld_dy[COORD_W-1],
                    ld_mneg_x ? !ld_dx[COORD_W-1] : ld_dx[COORD_W-1]} | ld_gz;
  assign ld_gone = {ld_mneg_y ? ld_dy == '1 : ld_dy == COORD_W'(1),
                    ld_mneg_x ? ld_dx == '1 : ld_dx == COORD_W'(1)};

  assign pending_o       = pend_q;
  assign start_o         = take && pend_q;
  assign run_o           = cur_q;
  assign step_o          = st_q;
  assign want_valid_o    = wv_q;
  assign want_dir_o      = wd_q;
  assign last_o          = last_q;
  assign run_next_o      = cur_d;
  assign step_next_o     = st_d;
  assign want_dir_next_o = wd_d;

  ppc_line_step #(
    .MAG_W(MW)
  ) u_line (
    .clk_i,
    .rst_ni,
    .load_i    (take && line_load),
    .load_ax_i (mag_x),
    .load_ay_i (mag_y),
    .load_nz_i (~gz_q),
    .load_le1_i(gz_q | gone_q | gm1),  // |g| <= 1
    .advance_i (take && line_q),
    .x_left_o  (l_x_left),
    .y_left_o  (l_y_left),
    .step_x_o  (l_step_x),
    .step_y_o  (l_step_y),
    .last_o    (l_last)
  );

  // The operation register: the decided operation on a take; empty after the
  // caller did the operation with nothing decided, or on an abort.
  always_comb begin
    cur_d  = cur_q;
    st_d   = st_q;
    wv_d   = wv_q;
    wd_d   = wd_q;
    last_d = last_q;
    if (take) begin
      cur_d  = 1'b1;
      st_d   = dec_st;
      wv_d   = dec_wv;
      wd_d   = dec_wd;
      last_d = dec_last;
    end else if (advance_i || abort_i) begin
      cur_d  = 1'b0;
      st_d   = 2'b00;
      wv_d   = 2'b00;
      last_d = 1'b0;
    end
  end

  // The state's phase and the closing line's directions.
  always_comb begin
    fin_d  = fin_q;
    pend_d = pend_q;
    sw_d   = sw_q;
    line_d = line_q;
    lneg_d = lneg_q;
    if (take) begin
      pend_d = 1'b0;
      if (dec_last) begin
        fin_d = 1'b1;
      end else if (line_load) begin
        sw_d   = 1'b0;
        line_d = 1'b1;
        lneg_d = l_dir;
      end
    end
    if (load) begin
      fin_d  = 1'b0;
      pend_d = 1'b1;
      sw_d   = ld_degenerate;
      line_d = 1'b0;
    end
    if (abort_i) begin
      fin_d  = 1'b1;
      pend_d = 1'b0;
    end
  end

  // The arc registers: the set-up (a command taken while the state has no
  // operation left, use_ld) or the stepped state. The flags of the stepped
  // axis (a + 1, g - 1) and, on an entry, of the other one (-a, -g), from
  // compares of today's registers.
  always_comb begin
    ax_d   = ax_q;
    ay_d   = ay_q;
    gx_d   = gx_q;
    gy_d   = gy_q;
    f_d    = f_q;
    mneg_d = mneg_q;
    laps_d = laps_q;
    am1_d  = am1_q;
    gle0_d = gle0_q;
    gz_d   = gz_q;
    gone_d = gone_q;
    if (arc_en) begin
      if (use_ld) begin
        ax_d   = ld_ax;
        ay_d   = ld_ay;
        gx_d   = ld_gx;
        gy_d   = ld_gy;
        f_d    = '0;
        mneg_d = {ld_mneg_y, ld_mneg_x};
        laps_d = ld_laps;
        am1_d  = ld_am1;
        gle0_d = ld_gle0;
        gz_d   = ld_gz;
        gone_d = ld_gone;
      end else begin
        f_d = pick_x ? f_sx : f_sy;  // F += 2 p_a m_a + 1
        for (int i = 0; i < 2; i++) begin
          if (pick_x == (i == 0)) begin
            am1_d[i]  = am2[i];
            gle0_d[i] = gle0_q[i] || gone_q[i];
            gz_d[i]   = gone_q[i];
            gone_d[i] = gtwo[i];
          end else if (entry) begin
            am1_d[i]  = ap1[i];
            gle0_d[i] = !gneg[i];
            gone_d[i] = gm1[i];
          end
        end
        if (pick_x) begin
          ax_d = ax_q + PW'(1);
          gx_d = gx_q - GW'(1);
          if (entry) begin
            ay_d = -ay_q;
            gy_d = -gy_q;
          end
        end else begin
          ay_d = ay_q + PW'(1);
          gy_d = gy_q - GW'(1);
          if (entry) begin
            ax_d = -ax_q;
            gx_d = -gx_q;
          end
        end
        if (entry) begin
          mneg_d = mneg_q ^ flip;
          laps_d = laps_q - 3'd1;
        end
      end
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      fin_q  <= 1'b1;
      pend_q <= 1'b0;
      sw_q   <= 1'b0;
      line_q <= 1'b0;
      ax_q   <= '0;
      ay_q   <= '0;
      gx_q   <= '0;
      gy_q   <= '0;
      f_q    <= '0;
      mneg_q <= '0;
      lneg_q <= '0;
      laps_q <= '0;
      am1_q  <= '0;
      gle0_q <= '1;
      gz_q   <= '1;
      gone_q <= '0;
      cur_q  <= 1'b0;
      st_q   <= '0;
      wv_q   <= '0;
      wd_q   <= '0;
      last_q <= 1'b0;
    end else begin
      fin_q  <= fin_d;
      pend_q <= pend_d;
      sw_q   <= sw_d;
      line_q <= line_d;
      ax_q   <= ax_d;
      ay_q   <= ay_d;
      gx_q   <= gx_d;
      gy_q   <= gy_d;
      f_q    <= f_d;
      mneg_q <= mneg_d;
      lneg_q <= lneg_d;
      laps_q <= laps_d;
      am1_q  <= am1_d;
      gle0_q <= gle0_d;
      gz_q   <= gz_d;
      gone_q <= gone_d;
      cur_q  <= cur_d;
      st_q   <= st_d;
      wv_q   <= wv_d;
      wd_q   <= wd_d;
      last_q <= last_d;
    end
  end

`ifdef FORMAL
  // Formal (scripts/formal.sh, in ppc_arc's and motion_top's proofs): each
  // flag equals the compare of the register it stands for, at every clock
  // while no g has been the most negative GW-bit value (where g - 1 and -g
  // wrap; no command the widths above accept comes near it, but the proof
  // has no bound on g: the circle is not in the state); the operation
  // register holds no step, no want and no last while it is empty; a
  // pending command has not started, so the state has an operation; the
  // state and the operation register agree (a_state_run, a_cur_*).
  localparam logic [GW-1:0] GMin = {1'b1, {(GW - 1) {1'b0}}};
  logic f_g_ok, f_g_ok_q, f_g_ok_d;
  assign f_g_ok   = f_g_ok_q && gx_q != GMin && gy_q != GMin;
  assign f_g_ok_d = f_g_ok;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) f_g_ok_q <= 1'b1;
    else f_g_ok_q <= f_g_ok_d;
  end
  always_comb begin
    if (rst_ni) begin
      a_arc_flags: assert(!f_g_ok || (
          am1_q == {ay_q == PMinus1, ax_q == PMinus1} &&
          gz_q == {gy_q == '0, gx_q == '0} &&
          gone_q == {gy_q == GW'(1), gx_q == GW'(1)} &&
          gle0_q == {gy_q[GW-1] || gy_q == '0, gx_q[GW-1] || gx_q == '0}));
      a_empty: assert(cur_q || (st_q == '0 && wv_q == '0 && !last_q));
      a_pending: assert(!pend_q || !fin_q);
      // The state and the operation register agree: a state with operations
      // left that is not a pending copy belongs to the running command, whose
      // operation the register holds; a held operation that is not the last
      // leaves operations in the state (its command's), a held last one
      // leaves none of its command's.
      a_state_run: assert(fin_q || pend_q || cur_q);
      a_cur_mid: assert(!(cur_q && !last_q) || (!fin_q && !pend_q));
      a_cur_last: assert(!(cur_q && last_q) || fin_q || pend_q);
    end
  end
`endif
endmodule

// ppc_arc: 2-axis point-by-point comparison (PPC) circular-arc interpolator,
// CW and CCW, crossing quadrants, ending exactly on the commanded end point
// even when it is off the circle through the start ("rule M", models/ppc.h,
// models::PpcArcStream: the arc, its bound and its derivation).
//
// command stream -> buffer (s, e) -> set-up (quadrants, laps) -> PPC arc engine
//                -> closing PPC line (rtl/ppc_line_step.sv) -> step_stage
//
// Command, taken on a clock where cmd_valid_i && cmd_ready_o (one-entry
// buffer, cmd_ready_o a register, back-to-back commands gapless), all signed
// COORD_W-bit lattice offsets from the start, which is wherever the axes are:
//   cmd_center_i  centre - start (G-code I, J): I at [0 +: COORD_W], J above
//   cmd_end_i     end - start, x at [0 +: COORD_W], y above
//   cmd_ccw_i     1: counter-clockwise, 0: clockwise
// Relative to the centre: s = start - c = -(I, J), e = end - c, p the current
// point. Internal widths (no accepted command overflows):
//   s, e, and a = p_a * m_a   PW = COORD_W + 1 (|e_a| <= 2^COORD_W - 1,
//                             |p_a| < |s| + 1 <= 2^(COORD_W - 1/2) + 1)
//   g = (e_a - p_a) * m_a     GW = COORD_W + 2 (|g| < 2^COORD_W + |p_a|)
//   F = |p|^2 - |s|^2         FW = COORD_W + 2 (-2|s| + 1 <= F < 2|s| + 1)
//   closing line |e - p|      MW = COORD_W + 1
//
// Rule M (models/ppc.h): the PPC arc on the circle through s until, in the
// final pass (after `laps` quadrant entries), the axis the arc would step has
// nothing left towards e in its motion direction; then the guarded PPC line
// from p to e. No multiplier: the state is kept in motion coordinates,
//   m_a  the motion sign of each axis (mneg_q: 1 = negative; dir_o in the arc)
//   a_a = p_a m_a  (< 0 on the inward axis, the one moving towards the centre)
//   g_a = (e_a - p_a) m_a  (what is left towards e in the motion direction)
// so that one operation is: pick the axis (F >= 0: the inward one, else the
// outward one), F += 2 a + 1 (one adder: {a, 1}), a += 1, g -= 1. A step that
// lands the stepped coordinate on 0 (a = -1 before it) enters the next
// quadrant: the other axis's motion sign flips (its a and g negate) and the
// lap count falls by one.
//
// Set-up, on the clock the engine loads a command (from the buffer, which
// holds s = -(I, J), e = E - (I, J) and E): the quadrant of s and of e (a
// point on an axis belongs to the quadrant the motion enters) give the motion
// signs and laps = entries from s's quadrant to e's (0..3; same quadrant: 0
// if e is ahead of s, 4 if it is behind on both axes, E * m <= 0 per axis;
// s == e is a full circle, 4). Degenerate commands (|s|^2 < 2, or e == c)
// have no arc phase.
//
// Operations (one per feed tick, each an engine "operation" of the model):
//   arc phase   one step; in the final pass, if the picked axis has g <= 0,
//               the operation steps nothing and loads the closing line with
//               |e - p| = |g| (the switch); a step that lands on e in the
//               final pass (g = 1 on the stepped axis, 0 on the other) is the
//               command's last operation, with no closing line (every arc
//               whose end is on the circle ends this way);
//   closing     the guarded PPC line (rtl/ppc_line_step.sv, shared with
//               ppc_line), |dx| + |dy| operations; a degenerate command
//               spends one operation loading it (and a zero-length one a
//               second, empty one).
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
  parameter int COORD_W = 24,  // width of the command's signed coordinates
  parameter int POS_W   = 32,  // position counter width (wraps)
  parameter int TIM_W   = 16,  // width of the step/dir timing settings and counters
  parameter int FEED_W  = 16   // feed phase width; feed_i = 2^FEED_W is full feed
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
  localparam int PW = COORD_W + 1;  // s, e, a = p m
  localparam int GW = COORD_W + 2;  // g = (e - p) m
  localparam int FW = COORD_W + 2;  // F = |p|^2 - |s|^2
  localparam int MW = COORD_W + 1;  // closing line magnitudes
  localparam logic [PW-1:0] PMinus1 = {PW{1'b1}};

  // ---------------------------------------------------------------------------
  // Command buffer (one entry): s = -C, e = E - C and E, sign extended.
  logic               buf_valid_q, buf_valid_d;
  logic [PW-1:0]      buf_sx_q, buf_sy_q;  // s = start - centre
  logic [PW-1:0]      buf_ex_q, buf_ey_q;  // e = end - centre
  logic [COORD_W-1:0] buf_dx_q, buf_dy_q;  // E = end - start
  logic               buf_ccw_q;
  logic               cmd_take;  // a command is taken this clock
  logic               buf_take;  // the engine loads the buffer this clock
  logic [PW-1:0]      cmd_cx, cmd_cy, cmd_dx, cmd_dy;  // sign extended

  assign cmd_ready_o = !buf_valid_q;
  assign cmd_take    = cmd_valid_i && !buf_valid_q;
  assign cmd_cx = {cmd_center_i[COORD_W-1], cmd_center_i[0 +: COORD_W]};
  assign cmd_cy = {cmd_center_i[2*COORD_W-1], cmd_center_i[COORD_W +: COORD_W]};
  assign cmd_dx = {cmd_end_i[COORD_W-1], cmd_end_i[0 +: COORD_W]};
  assign cmd_dy = {cmd_end_i[2*COORD_W-1], cmd_end_i[COORD_W +: COORD_W]};

  // ---------------------------------------------------------------------------
  // Set-up of the buffered command: quadrants, motion signs, laps, start state.
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

  assign sx_neg  = buf_sx_q[PW-1];
  assign sy_neg  = buf_sy_q[PW-1];
  assign sx_zero = buf_sx_q == '0;
  assign sy_zero = buf_sy_q == '0;
  assign ex_neg  = buf_ex_q[PW-1];
  assign ey_neg  = buf_ey_q[PW-1];
  assign ex_zero = buf_ex_q == '0;
  assign ey_zero = buf_ey_q == '0;
  // A point on an axis belongs to the quadrant the motion enters:
  // CCW (x, 0) has the sign of x for y, (0, y) the opposite of y for x;
  // CW the other way round (models/ppc.cpp motion_at()).
  assign qsy_neg = sy_zero ? (sx_neg ^ !buf_ccw_q) : sy_neg;
  assign qsx_neg = sx_zero ? (sy_neg ^ buf_ccw_q) : sx_neg;
  assign qey_neg = ey_zero ? (ex_neg ^ !buf_ccw_q) : ey_neg;
  assign qex_neg = ex_zero ? (ey_neg ^ buf_ccw_q) : ex_neg;
  assign ks = {qsy_neg, qsx_neg ^ qsy_neg};
  assign ke = {qey_neg, qex_neg ^ qey_neg};
  assign kdiff = buf_ccw_q ? ke - ks : ks - ke;
  // Motion CCW (-qy, qx), CW (qy, -qx).
  assign ld_mneg_x = qsy_neg ^ buf_ccw_q;
  assign ld_mneg_y = qsx_neg ^ !buf_ccw_q;
  // E_a m_a <= 0: E_a is 0 or has the sign opposite to m_a.
  assign ld_behind = (buf_dx_q == '0 || buf_dx_q[COORD_W-1] != ld_mneg_x) &&
                     (buf_dy_q == '0 || buf_dy_q[COORD_W-1] != ld_mneg_y);
  assign ld_laps = kdiff != 2'd0 ? {1'b0, kdiff} : (ld_behind ? 3'd4 : 3'd0);
  assign sx_small = buf_sx_q[PW-1:1] == '0 || buf_sx_q == PMinus1;
  assign sy_small = buf_sy_q[PW-1:1] == '0 || buf_sy_q == PMinus1;
  assign ld_degenerate = (sx_small && sy_zero) || (sx_zero && sy_small) || (ex_zero && ey_zero);
  assign ld_ax = ld_mneg_x ? -buf_sx_q : buf_sx_q;
  assign ld_ay = ld_mneg_y ? -buf_sy_q : buf_sy_q;
  assign dx_ext = {{2{buf_dx_q[COORD_W-1]}}, buf_dx_q};
  assign dy_ext = {{2{buf_dy_q[COORD_W-1]}}, buf_dy_q};
  assign ld_gx = ld_mneg_x ? -dx_ext : dx_ext;
  assign ld_gy = ld_mneg_y ? -dy_ext : dy_ext;

  // ---------------------------------------------------------------------------
  // Engine.
  logic            act_q, act_d;  // a command is running
  logic            sw_q, sw_d;  // the next operation loads the closing line (degenerate)
  logic            line_q, line_d;  // the closing line runs
  logic [PW-1:0]   ax_q, ax_d, ay_q, ay_d;  // a = p m
  logic [GW-1:0]   gx_q, gx_d, gy_q, gy_d;  // g = (e - p) m
  logic [FW-1:0]   f_q, f_d;  // F = |p|^2 - |s|^2
  logic [AXES-1:0] mneg_q, mneg_d;  // motion signs in the arc (1: negative)
  logic [AXES-1:0] lneg_q, lneg_d;  // directions of the closing line
  logic [2:0]      laps_q, laps_d;  // quadrant entries before the final pass
  logic            done_q;

  logic            arc;  // the arc phase runs
  logic            pick_x;  // the arc steps x (else y)
  logic [PW-1:0]   a_c;  // a of the picked axis
  logic [GW-1:0]   g_c, g_o;  // g of the picked and the other axis
  logic            final_pass, arc_switch, entry, land, arc_last;
  logic            line_load;  // load the closing line with |g| this clock
  logic [MW-1:0]   mag_x, mag_y;  // |g|
  logic            l_x_left, l_y_left, l_step_x, l_step_y, l_last;
  logic [AXES-1:0] l_dir;  // direction of e - p: the sign of g, turned by the motion sign
  logic [AXES-1:0] flip;  // a quadrant entry flips the other axis's motion sign
  logic [AXES-1:0] carry;  // this operation steps the axis
  logic [AXES-1:0] want_valid;  // the running command may step the axis
  logic [AXES-1:0] ready;  // the axis may start a pulse on the next clock
  logic            tick, stall, advance, last;

  assign arc        = act_q && !sw_q && !line_q;
  // F >= 0 picks the inward axis (a < 0), F < 0 the outward one.
  assign pick_x     = f_q[FW-1] ^ ax_q[PW-1];
  assign a_c        = pick_x ? ax_q : ay_q;
  assign g_c        = pick_x ? gx_q : gy_q;
  assign g_o        = pick_x ? gy_q : gx_q;
  assign final_pass = laps_q == 3'd0;
  assign arc_switch = final_pass && (g_c[GW-1] || g_c == '0);
  assign entry      = a_c == PMinus1;
  assign land       = g_c == GW'(1) && g_o == '0;
  assign arc_last   = !arc_switch && (final_pass || (laps_q == 3'd1 && entry)) && land;
  assign mag_x      = MW'(gx_q[GW-1] ? -gx_q : gx_q);
  assign mag_y      = MW'(gy_q[GW-1] ? -gy_q : gy_q);
  assign l_dir      = {gy_q[GW-1] ^ mneg_q[1], gx_q[GW-1] ^ mneg_q[0]};
  assign flip       = pick_x ? 2'b10 : 2'b01;

  assign carry = arc    ? {!arc_switch && !pick_x, !arc_switch && pick_x} :
                 line_q ? {act_q && l_step_y, act_q && l_step_x} : 2'b00;
  assign want_valid = arc    ? 2'b11 :
                      line_q ? {act_q && l_y_left, act_q && l_x_left} : 2'b00;
  assign stall     = |(carry & ~ready);
  assign advance   = tick && !stall && !abort_i;
  assign line_load = advance && act_q && (sw_q || (arc && arc_switch));
  assign last      = advance && ((arc && arc_last) || (act_q && line_q && l_last));
  assign buf_take  = buf_valid_q && (!act_q || last) && !abort_i;

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
    .MAG_W(MW)
  ) u_line (
    .clk_i,
    .rst_ni,
    .load_i   (line_load),
    .load_ax_i(mag_x),
    .load_ay_i(mag_y),
    .advance_i(advance && act_q && line_q),
    .x_left_o (l_x_left),
    .y_left_o (l_y_left),
    .step_x_o (l_step_x),
    .step_y_o (l_step_y),
    .last_o   (l_last)
  );

  always_comb begin
    act_d  = act_q;
    sw_d   = sw_q;
    line_d = line_q;
    ax_d   = ax_q;
    ay_d   = ay_q;
    gx_d   = gx_q;
    gy_d   = gy_q;
    f_d    = f_q;
    mneg_d = mneg_q;
    lneg_d = lneg_q;
    laps_d = laps_q;
    if (line_load) begin
      sw_d   = 1'b0;
      line_d = 1'b1;
      lneg_d = l_dir;
    end else if (advance && arc) begin
      f_d = f_q + {a_c, 1'b1};  // F += 2 p_a m_a + 1
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
    if (last) act_d = 1'b0;
    if (buf_take) begin
      act_d  = 1'b1;
      sw_d   = ld_degenerate;
      line_d = 1'b0;
      ax_d   = ld_ax;
      ay_d   = ld_ay;
      gx_d   = ld_gx;
      gy_d   = ld_gy;
      f_d    = '0;
      mneg_d = {ld_mneg_y, ld_mneg_x};
      laps_d = ld_laps;
    end
    if (abort_i) act_d = 1'b0;
    buf_valid_d = !abort_i && (cmd_take || (buf_valid_q && !buf_take));
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      buf_valid_q <= 1'b0;
      buf_sx_q    <= '0;
      buf_sy_q    <= '0;
      buf_ex_q    <= '0;
      buf_ey_q    <= '0;
      buf_dx_q    <= '0;
      buf_dy_q    <= '0;
      buf_ccw_q   <= 1'b0;
      act_q       <= 1'b0;
      sw_q        <= 1'b0;
      line_q      <= 1'b0;
      ax_q        <= '0;
      ay_q        <= '0;
      gx_q        <= '0;
      gy_q        <= '0;
      f_q         <= '0;
      mneg_q      <= '0;
      lneg_q      <= '0;
      laps_q      <= '0;
      done_q      <= 1'b0;
    end else begin
      buf_valid_q <= buf_valid_d;
      if (cmd_take) begin
        buf_sx_q  <= -cmd_cx;
        buf_sy_q  <= -cmd_cy;
        buf_ex_q  <= cmd_dx - cmd_cx;
        buf_ey_q  <= cmd_dy - cmd_cy;
        buf_dx_q  <= cmd_end_i[0 +: COORD_W];
        buf_dy_q  <= cmd_end_i[COORD_W +: COORD_W];
        buf_ccw_q <= cmd_ccw_i;
      end
      act_q  <= act_d;
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
      done_q <= last;
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
    .want_valid_i(want_valid),
    .want_dir_i  (line_q ? lneg_q : mneg_q),
    .fire_i      ({AXES{advance}} & carry),
    .ready_o     (ready),
    .step_o,
    .dir_o,
    .pos_o
  );

  assign busy_o = act_q || buf_valid_q || (|step_o);
  assign done_o = done_q;
endmodule

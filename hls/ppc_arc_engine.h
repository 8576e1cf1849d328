// ppc_arc_engine, HLS face: the PPC circular-arc engine of rule M
// (rtl/ppc_arc_engine.sv documents the rule, the set-up, the operations and
// the internal widths; models/ppc.h derives them), shared by PpcArc
// (hls/ppc_arc.h) and MotionTop (hls/motion_top.h). It holds one arc and
// decides, per operation, which plane axis steps; the caller owns the
// command buffer, the feed, abort and the step/dir stage.
//
// prepare() is rtl/ppc_arc_prep.sv (done when a command is buffered);
// op(run) is this clock's operation (in the RTL a register: the engine runs
// one operation ahead, rtl/ppc_arc_engine.sv "Look-ahead"; the clock on
// which a buffered command may start is the caller's rule, hls/ppc_arc.h and
// hls/motion_top.h); clock() is one rising edge. Synthesizable subset:
// SystemC integers, no heap.
#pragma once

#include <systemc>

#include "hls/ppc_line_step.h"

namespace hwinterp::hls {

template <int COORD_W>
class PpcArcEngine {
 public:
  static_assert(COORD_W >= 3 && COORD_W <= 60, "COORD_W out of range");
  static constexpr int PW = COORD_W + 1;  // s, e, a = p m
  static constexpr int GW = COORD_W + 2;  // g = (e - p) m
  static constexpr int FW = COORD_W + 2;  // F = |p|^2 - |s|^2
  static constexpr int MW = COORD_W + 1;  // closing line magnitudes

  using coord_t = sc_dt::sc_uint<COORD_W>;  // a pin field (two's complement bits)
  using p_t = sc_dt::sc_int<PW>;
  using g_t = sc_dt::sc_int<GW>;
  using f_t = sc_dt::sc_int<FW>;
  using Line = PpcLineStep<MW>;

  // What a buffer holds for the engine (rtl/ppc_arc_prep.sv):
  // s = start - centre, e = end - centre, E = end - start, and the direction.
  struct Prep {
    p_t s[2] = {};
    p_t e[2] = {};
    coord_t d[2] = {};
    bool ccw = false;
  };

  // This clock's outputs (x at index 0).
  struct Op {
    bool step[2];        // the operation steps the axis
    bool want_valid[2];  // the command may still step the axis
    bool want_dir[2];    // the axis's direction (true: negative)
    bool last;           // the operation is the command's last
  };

  static Prep prepare(const coord_t (&center)[2], const coord_t (&end)[2], bool ccw) {
    Prep p;
    for (int i = 0; i < 2; ++i) {
      const p_t cen = signed_coord(center[i]), e = signed_coord(end[i]);
      p.s[i] = -cen;
      p.e[i] = e - cen;
      p.d[i] = end[i];
    }
    p.ccw = ccw;
    return p;
  }

  PpcArcEngine() { reset(); }

  void reset() {
    sw_q_ = line_q_ = false;
    f_q_ = 0;
    laps_q_ = 0;
    for (int i = 0; i < 2; ++i) {
      a_q_[i] = 0;
      g_q_[i] = 0;
      mneg_q_[i] = lneg_q_[i] = false;
    }
    line_.reset();
  }

  // The outputs while `run` (the caller's running flag) holds.
  Op op(bool run) const {
    const Pick k = pick(run);
    Op o;
    if (k.arc) {
      o.step[0] = !k.arc_switch && k.c == 0;
      o.step[1] = !k.arc_switch && k.c == 1;
      o.want_valid[0] = o.want_valid[1] = true;
    } else if (run && line_q_) {
      o.step[0] = line_.step_x();
      o.step[1] = line_.step_y();
      o.want_valid[0] = line_.x_left();
      o.want_valid[1] = line_.y_left();
    } else {
      o.step[0] = o.step[1] = o.want_valid[0] = o.want_valid[1] = false;
    }
    for (int i = 0; i < 2; ++i) o.want_dir[i] = line_q_ ? lneg_q_[i] : mneg_q_[i];
    o.last = (k.arc && k.arc_last) || (run && line_q_ && line_.last());
    return o;
  }

  // One rising edge: load (wins) or, with advance (which implies run), this
  // clock's operation.
  void clock(bool load, const Prep& ld, bool advance) {
    const Pick k = pick(advance);
    const bool line_load = advance && (sw_q_ || (k.arc && k.arc_switch));
    line_.clock(line_load, magnitude(g_q_[0]), magnitude(g_q_[1]), advance && line_q_);
    if (line_load) {
      sw_q_ = false;
      line_q_ = true;
      // Direction of e - p: the sign of g, turned by the motion sign.
      for (int i = 0; i < 2; ++i) lneg_q_[i] = (g_q_[i] < 0) != mneg_q_[i];
    } else if (advance && k.arc) {
      const int c = k.c, o = 1 - c;
      f_q_ = f_q_ + 2 * a_q_[c] + 1;  // F += 2 p_a m_a + 1
      a_q_[c] = a_q_[c] + 1;
      g_q_[c] = g_q_[c] - 1;
      if (k.entry) {
        // The stepped coordinate reached 0: the next quadrant; the other
        // axis's motion sign flips.
        a_q_[o] = -a_q_[o];
        g_q_[o] = -g_q_[o];
        mneg_q_[o] = !mneg_q_[o];
        laps_q_ = laps_q_ - 1;
      }
    }
    if (load) set_up(ld);
  }

 private:
  // The arc phase's choice this clock.
  struct Pick {
    bool arc;  // the arc phase runs
    int c;     // the picked axis
    bool arc_switch, entry, arc_last;
  };

  Pick pick(bool run) const {
    Pick k;
    k.arc = run && !sw_q_ && !line_q_;
    // F >= 0 picks the inward axis (a < 0), F < 0 the outward one.
    k.c = ((f_q_ < 0) != (a_q_[0] < 0)) ? 0 : 1;
    const int o = 1 - k.c;
    const bool final_pass = laps_q_ == 0;
    k.arc_switch = final_pass && g_q_[k.c] <= 0;
    k.entry = a_q_[k.c] == -1;
    const bool land = g_q_[k.c] == 1 && g_q_[o] == 0;
    k.arc_last = !k.arc_switch && (final_pass || (laps_q_ == 1 && k.entry)) && land;
    return k;
  }

  static p_t signed_coord(const coord_t& v) {
    return p_t(sc_dt::sc_int<COORD_W>(v.to_uint64()).to_int64());
  }
  static typename Line::mag_t magnitude(const g_t& g) {
    return typename Line::mag_t(g < 0 ? g_t(-g).to_int64() : g.to_int64());
  }

  // Set-up: the quadrants of s and e, the motion signs at s, the laps, the
  // start state (rtl/ppc_arc_engine.sv "Set-up"). A point on an axis belongs
  // to the quadrant the motion enters.
  void set_up(const Prep& ld) {
    const bool ccw = ld.ccw;
    bool qs_neg[2], qe_neg[2];  // quadrant signs of s and e, per axis
    quadrant(ld.s, ccw, qs_neg);
    quadrant(ld.e, ccw, qe_neg);
    const int ks = (qs_neg[1] ? 2 : 0) + (qs_neg[0] != qs_neg[1] ? 1 : 0);
    const int ke = (qe_neg[1] ? 2 : 0) + (qe_neg[0] != qe_neg[1] ? 1 : 0);
    const int kdiff = ((ccw ? ke - ks : ks - ke) + 4) % 4;
    // Motion CCW (-qy, qx), CW (qy, -qx).
    const bool mneg[2] = {qs_neg[1] != ccw, qs_neg[0] != !ccw};
    bool behind = true;  // E_a m_a <= 0 on both axes
    for (int i = 0; i < 2; ++i) {
      const bool d_neg = ld.d[i][COORD_W - 1];
      behind = behind && (ld.d[i] == 0 || d_neg != mneg[i]);
    }
    auto small = [](const p_t& v) { return v >= -1 && v <= 1; };
    const bool degenerate = (small(ld.s[0]) && ld.s[1] == 0) || (ld.s[0] == 0 && small(ld.s[1])) ||
                            (ld.e[0] == 0 && ld.e[1] == 0);
    sw_q_ = degenerate;
    line_q_ = false;
    f_q_ = 0;
    laps_q_ = kdiff != 0 ? kdiff : (behind ? 4 : 0);
    for (int i = 0; i < 2; ++i) {
      mneg_q_[i] = mneg[i];
      a_q_[i] = mneg[i] ? p_t(-ld.s[i]) : ld.s[i];
      const g_t d = sc_dt::sc_int<COORD_W>(ld.d[i].to_uint64()).to_int64();
      g_q_[i] = mneg[i] ? g_t(-d) : d;
    }
  }

  static void quadrant(const p_t (&v)[2], bool ccw, bool (&q_neg)[2]) {
    const bool x_neg = v[0] < 0, y_neg = v[1] < 0;
    q_neg[1] = v[1] == 0 ? (x_neg != !ccw) : y_neg;
    q_neg[0] = v[0] == 0 ? (y_neg != ccw) : x_neg;
  }

  bool sw_q_, line_q_;        // next operation loads the line; the line runs
  p_t a_q_[2];                // a = p m
  g_t g_q_[2];                // g = (e - p) m
  f_t f_q_;                   // F = |p|^2 - |s|^2
  bool mneg_q_[2];            // motion signs in the arc (true: negative)
  bool lneg_q_[2];            // directions of the closing line
  sc_dt::sc_uint<3> laps_q_;  // quadrant entries before the final pass
  Line line_;
};

}  // namespace hwinterp::hls

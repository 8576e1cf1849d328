// ppc_arc, HLS face: the cycle behaviour of rtl/ppc_arc.sv as a synthesizable
// C++ class (registers as members, tick() computes one rising clock edge).
// rtl/ppc_arc.sv documents the behaviour and the internal widths;
// models/ppc.h states rule M, its bound and their derivation. Synthesizable
// subset: SystemC integers, fixed-size arrays, no floats, no heap.
// hwinterp::hls::StepperModule<PpcArc<Cfg>> is its SC_MODULE.
//
// `Cfg` is a generated variant struct (cmake/cores.cmake): AXES (= 2),
// COORD_W, POS_W, TIM_W, FEED_W.
#pragma once

#include <systemc>

#include "hls/feed_accum.h"
#include "hls/pin_types.h"
#include "hls/ppc_line_step.h"
#include "hls/step_stage.h"
#include "hls/stepper_io.h"

namespace hwinterp::hls {

template <class CfgT>
class PpcArc {
 public:
  using Cfg = CfgT;
  static constexpr int AXES = Cfg::AXES;
  static constexpr int COORD_W = Cfg::COORD_W;
  static constexpr int POS_W = Cfg::POS_W;
  static constexpr int TIM_W = Cfg::TIM_W;
  static constexpr int FEED_W = Cfg::FEED_W;
  static_assert(AXES == 2, "PPC is a planar method: AXES must be 2");
  static_assert(COORD_W >= 3 && COORD_W <= 60, "COORD_W out of range");
  static_assert(POS_W >= 2 && POS_W <= 64, "POS_W out of range");
  static constexpr int PW = COORD_W + 1;  // s, e, a = p m
  static constexpr int GW = COORD_W + 2;  // g = (e - p) m
  static constexpr int FW = COORD_W + 2;  // F = |p|^2 - |s|^2
  static constexpr int MW = COORD_W + 1;  // closing line magnitudes

  using coord_t = sc_dt::sc_uint<COORD_W>;  // a pin field (two's complement bits)
  using p_t = sc_dt::sc_int<PW>;
  using g_t = sc_dt::sc_int<GW>;
  using f_t = sc_dt::sc_int<FW>;
  using Line = PpcLineStep<MW>;

  // The core's own inputs: cmd_center_i (I, J), cmd_end_i, cmd_ccw_i.
  struct Own {
    coord_t center[AXES] = {};
    coord_t end[AXES] = {};
    bool ccw = false;
  };
  using Inputs = StepperInputs<Own, FEED_W, TIM_W>;
  using Outputs = StepperOutputs<AXES, POS_W>;

  // The own ports of the SC_MODULE face (hls/stepper_module.h).
  struct OwnPorts {
    sc_core::sc_in<pin_t<AXES * COORD_W>> cmd_center_i{"cmd_center_i"};
    sc_core::sc_in<pin_t<AXES * COORD_W>> cmd_end_i{"cmd_end_i"};
    sc_core::sc_in<bool> cmd_ccw_i{"cmd_ccw_i"};
    void read(Own& own) const {
      const pin_t<AXES* COORD_W>& c = cmd_center_i.read();
      const pin_t<AXES* COORD_W>& e = cmd_end_i.read();
      for (int i = 0; i < AXES; ++i) {
        own.center[i] = pin_field<AXES * COORD_W>(c, i * COORD_W, COORD_W);
        own.end[i] = pin_field<AXES * COORD_W>(e, i * COORD_W, COORD_W);
      }
      own.ccw = cmd_ccw_i.read();
    }
  };

  PpcArc() { reset(); }

  void reset() {
    buf_valid_q_ = false;
    buf_ccw_q_ = false;
    act_q_ = sw_q_ = line_q_ = false;
    f_q_ = 0;
    laps_q_ = 0;
    done_q_ = false;
    for (int i = 0; i < AXES; ++i) {
      buf_s_q_[i] = buf_e_q_[i] = 0;
      buf_d_q_[i] = 0;
      a_q_[i] = 0;
      g_q_[i] = 0;
      mneg_q_[i] = lneg_q_[i] = false;
    }
    line_.reset();
    feed_.reset();
    out_.reset();
  }

  // One rising clock edge (or, with rst_n low, the reset).
  void tick(const Inputs& in) {
    if (!in.rst_n) {
      reset();
      return;
    }
    // Combinational part, from the current registers and the inputs.
    const bool arc = act_q_ && !sw_q_ && !line_q_;
    // F >= 0 picks the inward axis (a < 0), F < 0 the outward one.
    const bool pick_x = (f_q_ < 0) != (a_q_[0] < 0);
    const int c = pick_x ? 0 : 1, o = 1 - c;
    const bool final_pass = laps_q_ == 0;
    const bool arc_switch = final_pass && g_q_[c] <= 0;
    const bool entry = a_q_[c] == -1;
    const bool land = g_q_[c] == 1 && g_q_[o] == 0;
    const bool arc_last = !arc_switch && (final_pass || (laps_q_ == 1 && entry)) && land;

    bool carry[AXES];
    typename StepStage<AXES, POS_W, TIM_W>::Request want;
    if (arc) {
      carry[0] = !arc_switch && pick_x;
      carry[1] = !arc_switch && !pick_x;
      want.want_valid[0] = want.want_valid[1] = true;
    } else if (line_q_) {
      carry[0] = act_q_ && line_.step_x();
      carry[1] = act_q_ && line_.step_y();
      want.want_valid[0] = act_q_ && line_.x_left();
      want.want_valid[1] = act_q_ && line_.y_left();
    } else {
      carry[0] = carry[1] = false;
      want.want_valid[0] = want.want_valid[1] = false;
    }
    bool stall = false;
    for (int i = 0; i < AXES; ++i) {
      want.want_dir[i] = line_q_ ? lneg_q_[i] : mneg_q_[i];
      if (carry[i] && !out_.ready(i, want)) stall = true;
    }
    const bool tick = feed_.tick(act_q_);
    const bool advance = tick && !stall && !in.abort;
    const bool line_load = advance && act_q_ && (sw_q_ || (arc && arc_switch));
    const bool last = advance && ((arc && arc_last) || (act_q_ && line_q_ && line_.last()));
    const bool buf_take = buf_valid_q_ && (!act_q_ || last) && !in.abort;
    const bool cmd_take = in.cmd_valid && !buf_valid_q_;

    // Output stage, feed and line engine first: they read the registers before they update.
    bool fire[AXES];
    for (int i = 0; i < AXES; ++i) fire[i] = advance && carry[i];
    out_.clock(in.timing, want, fire);
    feed_.clock(in.feed, act_q_, stall);
    line_.clock(line_load, magnitude(g_q_[0]), magnitude(g_q_[1]), advance && act_q_ && line_q_);

    // Engine registers.
    if (line_load) {
      sw_q_ = false;
      line_q_ = true;
      // Direction of e - p: the sign of g, turned by the motion sign.
      for (int i = 0; i < AXES; ++i) lneg_q_[i] = (g_q_[i] < 0) != mneg_q_[i];
    } else if (advance && arc) {
      f_q_ = f_q_ + 2 * a_q_[c] + 1;  // F += 2 p_a m_a + 1
      a_q_[c] = a_q_[c] + 1;
      g_q_[c] = g_q_[c] - 1;
      if (entry) {
        // The stepped coordinate reached 0: the next quadrant; the other
        // axis's motion sign flips.
        a_q_[o] = -a_q_[o];
        g_q_[o] = -g_q_[o];
        mneg_q_[o] = !mneg_q_[o];
        laps_q_ = laps_q_ - 1;
      }
    }
    if (last) act_q_ = false;
    if (buf_take) load_engine();
    if (in.abort) act_q_ = false;
    // Command buffer: s = -C, e = E - C, E.
    if (cmd_take) {
      for (int i = 0; i < AXES; ++i) {
        const p_t cen = signed_coord(in.cmd.center[i]), end = signed_coord(in.cmd.end[i]);
        buf_s_q_[i] = -cen;
        buf_e_q_[i] = end - cen;
        buf_d_q_[i] = in.cmd.end[i];
      }
      buf_ccw_q_ = in.cmd.ccw;
    }
    buf_valid_q_ = !in.abort && (cmd_take || (buf_valid_q_ && !buf_take));
    done_q_ = last;
  }

  Outputs outputs() const { return out_.outputs(!buf_valid_q_, act_q_ || buf_valid_q_, done_q_); }

 private:
  static p_t signed_coord(const coord_t& v) {
    return p_t(sc_dt::sc_int<COORD_W>(v.to_uint64()).to_int64());
  }
  static typename Line::mag_t magnitude(const g_t& g) {
    return typename Line::mag_t(g < 0 ? g_t(-g).to_int64() : g.to_int64());
  }

  // Set-up: the quadrants of s and e, the motion signs at s, the laps, the
  // start state (rtl/ppc_arc.sv "Set-up"). A point on an axis belongs to the
  // quadrant the motion enters.
  void load_engine() {
    const bool ccw = buf_ccw_q_;
    bool qs_neg[AXES], qe_neg[AXES];  // quadrant signs of s and e, per axis
    quadrant(buf_s_q_, ccw, qs_neg);
    quadrant(buf_e_q_, ccw, qe_neg);
    const int ks = (qs_neg[1] ? 2 : 0) + (qs_neg[0] != qs_neg[1] ? 1 : 0);
    const int ke = (qe_neg[1] ? 2 : 0) + (qe_neg[0] != qe_neg[1] ? 1 : 0);
    const int kdiff = ((ccw ? ke - ks : ks - ke) + 4) % 4;
    // Motion CCW (-qy, qx), CW (qy, -qx).
    const bool mneg[AXES] = {qs_neg[1] != ccw, qs_neg[0] != !ccw};
    bool behind = true;  // E_a m_a <= 0 on both axes
    for (int i = 0; i < AXES; ++i) {
      const bool d_neg = buf_d_q_[i][COORD_W - 1];
      behind = behind && (buf_d_q_[i] == 0 || d_neg != mneg[i]);
    }
    auto small = [](const p_t& v) { return v >= -1 && v <= 1; };
    const bool degenerate = (small(buf_s_q_[0]) && buf_s_q_[1] == 0) ||
                            (buf_s_q_[0] == 0 && small(buf_s_q_[1])) ||
                            (buf_e_q_[0] == 0 && buf_e_q_[1] == 0);
    act_q_ = true;
    sw_q_ = degenerate;
    line_q_ = false;
    f_q_ = 0;
    laps_q_ = kdiff != 0 ? kdiff : (behind ? 4 : 0);
    for (int i = 0; i < AXES; ++i) {
      mneg_q_[i] = mneg[i];
      a_q_[i] = mneg[i] ? p_t(-buf_s_q_[i]) : buf_s_q_[i];
      const g_t d = sc_dt::sc_int<COORD_W>(buf_d_q_[i].to_uint64()).to_int64();
      g_q_[i] = mneg[i] ? g_t(-d) : d;
    }
  }

  static void quadrant(const p_t (&v)[AXES], bool ccw, bool (&q_neg)[AXES]) {
    const bool x_neg = v[0] < 0, y_neg = v[1] < 0;
    q_neg[1] = v[1] == 0 ? (x_neg != !ccw) : y_neg;
    q_neg[0] = v[0] == 0 ? (y_neg != ccw) : x_neg;
  }

  // One-entry command buffer.
  bool buf_valid_q_;
  p_t buf_s_q_[AXES];      // s = start - centre
  p_t buf_e_q_[AXES];      // e = end - centre
  coord_t buf_d_q_[AXES];  // E = end - start
  bool buf_ccw_q_;
  // Engine.
  bool act_q_, sw_q_, line_q_;  // running; next operation loads the line; line runs
  p_t a_q_[AXES];               // a = p m
  g_t g_q_[AXES];               // g = (e - p) m
  f_t f_q_;                     // F = |p|^2 - |s|^2
  bool mneg_q_[AXES];           // motion signs in the arc (true: negative)
  bool lneg_q_[AXES];           // directions of the closing line
  sc_dt::sc_uint<3> laps_q_;    // quadrant entries before the final pass
  bool done_q_;
  Line line_;
  FeedAccum<FEED_W> feed_;
  StepStage<AXES, POS_W, TIM_W> out_;
};

}  // namespace hwinterp::hls

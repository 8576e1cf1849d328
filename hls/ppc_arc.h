// ppc_arc, HLS face: the cycle behaviour of rtl/ppc_arc.sv as a synthesizable
// C++ class (registers as members, tick() computes one rising clock edge).
// rtl/ppc_arc.sv documents the behaviour, rtl/ppc_arc_engine.sv the engine
// (hls/ppc_arc_engine.h here) and its internal widths;
// models/ppc.h states rule M, its bound and their derivation. Synthesizable
// subset: SystemC integers, fixed-size arrays, no floats, no heap.
// hwinterp::hls::StepperModule<PpcArc<Cfg>> is its SC_MODULE.
//
// `Cfg` is a generated variant struct (cmake/cores.cmake): AXES (= 2),
// COORD_W, POS_W, TIM_W, FEED_W.
#pragma once

#include <systemc>

#include "hls/feed_accum.h"
#include "hls/fields.h"
#include "hls/pin_types.h"
#include "hls/ppc_arc_engine.h"
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
  using Engine = PpcArcEngine<COORD_W>;
  using coord_t = typename Engine::coord_t;  // a pin field (two's complement bits)

  // The core's own inputs: cmd_center_i (I, J), cmd_end_i, cmd_ccw_i.
  struct Own {
    coord_t center[AXES] = {};
    coord_t end[AXES] = {};
    bool ccw = false;
    static auto fields() {  // hls/fields.h
      return std::make_tuple(HWINTERP_FIELD(cmd_center_i, &Own::center, kSigned),
                             HWINTERP_FIELD(cmd_end_i, &Own::end, kSigned),
                             HWINTERP_FIELD(cmd_ccw_i, &Own::ccw, kUnsigned));
    }
  };
  using Inputs = StepperInputs<Own, FEED_W, TIM_W>;
  using Outputs = StepperOutputs<AXES, POS_W>;

  PpcArc() { reset(); }

  void reset() {
    buf_valid_q_ = buf_aged_q_ = false;
    buf_ = typename Engine::Prep();
    act_q_ = false;
    done_q_ = false;
    engine_.reset();
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
    const typename Engine::Op op = engine_.op(act_q_);
    typename StepStage<AXES, POS_W, TIM_W>::Request want;
    bool stall = false;
    for (int i = 0; i < AXES; ++i) {
      want.want_valid[i] = op.want_valid[i];
      want.want_dir[i] = op.want_dir[i];
    }
    for (int i = 0; i < AXES; ++i)
      if (op.step[i] && !out_.ready(i, want)) stall = true;
    const bool tick = feed_.tick(act_q_);
    const bool advance = tick && !stall && !in.abort;
    const bool last = advance && act_q_ && op.last;
    // The engine starts a command only once it has been buffered for a clock
    // (rtl/ppc_arc_engine.sv copies it into its look-ahead state first).
    const bool buf_take = buf_valid_q_ && buf_aged_q_ && (!act_q_ || last) && !in.abort;
    const bool cmd_take = in.cmd_valid && !buf_valid_q_;

    // Output stage, feed and engine first: they read the registers before they update.
    bool fire[AXES];
    for (int i = 0; i < AXES; ++i) fire[i] = advance && op.step[i];
    out_.clock(in.timing, want, fire);
    feed_.clock(in.feed, act_q_, stall);
    engine_.clock(buf_take, buf_, advance && act_q_);

    if (last) act_q_ = false;
    if (buf_take) act_q_ = true;
    if (in.abort) act_q_ = false;
    // Command buffer: s, e, E (rtl/ppc_arc_prep.sv).
    if (cmd_take) buf_ = Engine::prepare(in.cmd.center, in.cmd.end, in.cmd.ccw);
    const bool buf_valid_next = !in.abort && (cmd_take || (buf_valid_q_ && !buf_take));
    buf_aged_q_ = buf_valid_next && buf_valid_q_;
    buf_valid_q_ = buf_valid_next;
    done_q_ = last;
  }

  Outputs outputs() const { return out_.outputs(!buf_valid_q_, act_q_ || buf_valid_q_, done_q_); }

 private:
  bool buf_valid_q_;  // one-entry command buffer
  bool buf_aged_q_;   // ...valid on the clock before too
  typename Engine::Prep buf_;
  bool act_q_;  // a command is running
  bool done_q_;
  Engine engine_;
  FeedAccum<FEED_W> feed_;
  StepStage<AXES, POS_W, TIM_W> out_;
};

}  // namespace hwinterp::hls

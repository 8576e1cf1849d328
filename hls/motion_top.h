// motion_top, HLS face: the cycle behaviour of rtl/motion_top.sv as a
// synthesizable C++ class (registers as members, tick() computes one rising
// clock edge). rtl/motion_top.sv documents the behaviour (command, buffers,
// the DDA and PPC arc engines, the slaved axes, feed, abort, status);
// models/motion_top_model.h states the mathematics move for move.
// Synthesizable subset: SystemC integers, fixed-size arrays, loops bounded by
// template parameters, no floats, no heap.
// hwinterp::hls::StepperModule<MotionTop<Cfg>> is its SC_MODULE.
//
// `Cfg` is a generated variant struct (cmake/cores.cmake): AXES, ACC_W,
// COORD_W, OPS_W, POS_W, TIM_W, FEED_W.
#pragma once

#include <systemc>

#include "hls/dda_axis.h"
#include "hls/dda_norm.h"
#include "hls/feed_accum.h"
#include "hls/fields.h"
#include "hls/pin_types.h"
#include "hls/ppc_arc_engine.h"
#include "hls/step_stage.h"
#include "hls/stepper_io.h"

namespace hwinterp::hls {

template <class CfgT>
class MotionTop {
 public:
  using Cfg = CfgT;
  static constexpr int AXES = Cfg::AXES;
  static constexpr int ACC_W = Cfg::ACC_W;
  static constexpr int COORD_W = Cfg::COORD_W;
  static constexpr int OPS_W = Cfg::OPS_W;
  static constexpr int POS_W = Cfg::POS_W;
  static constexpr int TIM_W = Cfg::TIM_W;
  static constexpr int FEED_W = Cfg::FEED_W;
  static_assert(AXES >= 3 && AXES <= 6, "motion_top has 3 to 6 axes (the arc planes use 0-2)");
  static_assert(ACC_W >= 4 && ACC_W <= 62, "ACC_W out of range");
  static_assert(OPS_W < ACC_W, "the slaved accumulators need OPS_W < ACC_W");

  using acc_t = sc_dt::sc_uint<ACC_W>;
  using feed_t = sc_dt::sc_uint<FEED_W + 1>;
  using dc_t = sc_dt::sc_uint<ACC_W + 1>;  // a DDA axis's increment after a carry
  using Arc = PpcArcEngine<COORD_W>;
  using coord_t = typename Arc::coord_t;

  // The core's own inputs (the command payload; rtl/motion_top.sv).
  struct Own {
    bool arc = false;
    acc_t delta[AXES] = {};
    sc_dt::sc_uint<2> plane = 0;
    coord_t center[2] = {}, end[2] = {};
    bool ccw = false;
    sc_dt::sc_uint<OPS_W> ops = 0;
    feed_t feed = 0;
    static auto fields() {  // hls/fields.h
      return std::make_tuple(HWINTERP_FIELD(cmd_arc_i, &Own::arc, kUnsigned),
                             HWINTERP_FIELD(cmd_delta_i, &Own::delta, kSigned),
                             HWINTERP_FIELD(cmd_plane_i, &Own::plane, kUnsigned),
                             HWINTERP_FIELD(cmd_center_i, &Own::center, kSigned),
                             HWINTERP_FIELD(cmd_end_i, &Own::end, kSigned),
                             HWINTERP_FIELD(cmd_ccw_i, &Own::ccw, kUnsigned),
                             HWINTERP_FIELD(cmd_ops_i, &Own::ops, kUnsigned),
                             HWINTERP_FIELD(cmd_feed_i, &Own::feed, kUnsigned));
    }
  };
  using Inputs = StepperInputs<Own, FEED_W, TIM_W>;
  using Outputs = StepperOutputs<AXES, POS_W>;

  MotionTop() { reset(); }

  void reset() {
    a_ = Buffer();
    b_ = Buffer();
    a_valid_q_ = b_valid_q_ = b_aged_q_ = false;
    a_any_q_ = a_negn_q_ = 0;
    b_low_q_ = b_a0_q_ = 0;
    b_low_zero_q_ = false;
    act_q_ = arc_q_ = false;
    left_q_ = 0;
    left_zero_q_ = false;
    feed_q_ = 0;
    hold_q_ = true;
    pin_q_ = 0;
    b_pin_q_ = cur_pin_q_ = false;
    done_q_ = false;
    for (int i = 0; i < AXES; ++i) {
      on_x_q_[i] = on_y_q_[i] = false;
      neg_q_[i] = moves_q_[i] = false;
      acc_[i].reset();
    }
    arc_.reset();
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
    const bool arc_run = act_q_ && arc_q_;
    const typename Arc::Op op = arc_.op(arc_run);
    const bool cur_last = arc_q_ ? op.last : left_zero_q_;
    // An arc in buffer B loads only once it has been there for a clock
    // (rtl/ppc_arc_engine.sv copies it into its look-ahead state first).
    const bool pre_load = b_valid_q_ && (!act_q_ || cur_last) && (!b_.arc || b_aged_q_);
    bool carry[AXES], fire[AXES], stall = false;
    typename StepStage<AXES, POS_W, TIM_W>::Request want;
    for (int i = 0; i < AXES; ++i) {
      carry[i] = acc_[i].carry() || (on_x_q_[i] && op.step[0]) || (on_y_q_[i] && op.step[1]);
      want.want_valid[i] = on_x_q_[i]   ? op.want_valid[0]
                           : on_y_q_[i] ? op.want_valid[1]
                                        : moves_q_[i];
      want.want_dir[i] = on_x_q_[i] ? op.want_dir[0] : on_y_q_[i] ? op.want_dir[1] : neg_q_[i];
      if (carry[i] && !out_.ready(i, want)) stall = true;
    }
    const bool tick = feed_.tick(act_q_);
    const bool advance = tick && !stall && !in.abort;
    const bool last = advance && cur_last;
    const bool load = pre_load && (!act_q_ || advance) && !in.abort;
    const bool idle_load = pre_load && !act_q_ && !in.abort;
    const bool a_to_b = a_valid_q_ && !b_valid_q_ && !in.abort;
    const bool cmd_take = in.cmd_valid && !a_valid_q_;

    // Output stage, feed and the arc engine first: they read the registers
    // before they update.
    for (int i = 0; i < AXES; ++i) fire[i] = advance && carry[i];
    out_.clock(in.timing, want, fire);
    // A move whose feed word is 0 runs at the pin's word (a feed profile).
    const bool pin = pre_load ? b_pin_q_ : cur_pin_q_;
    feed_.clock(hold_q_ ? feed_t(0) : (pin ? pin_q_ : (pre_load ? b_.feed : feed_q_)), act_q_,
                stall);
    arc_.clock(load && b_.arc, b_.prep, advance && arc_run);
    for (int i = 0; i < AXES; ++i)
      acc_[i].clock(pre_load, load, load || advance, b_a0_q_, b_.mag[i], b_.dc[i], acc_t(0));

    // Engine registers.
    for (int i = 0; i < AXES; ++i)
      moves_q_[i] = advance ? (pre_load ? b_.moves[i] : moves_q_[i] && !cur_last)
                            : (idle_load ? b_.moves[i] : moves_q_[i] && !in.abort);
    const bool left_zero_next = advance ? (pre_load ? b_low_zero_q_ : left_q_ == 1)
                                        : (idle_load ? b_low_zero_q_ : left_zero_q_);
    left_q_ =
        advance ? (pre_load ? b_low_q_ : acc_t(left_q_ - 1)) : (idle_load ? b_low_q_ : left_q_);
    left_zero_q_ = left_zero_next;
    act_q_ = advance ? (pre_load || !cur_last) : ((act_q_ && !in.abort) || idle_load);
    if (load) {
      arc_q_ = b_.arc;
      feed_q_ = b_.feed;
      cur_pin_q_ = b_pin_q_;
      const unsigned p = b_.plane.to_uint();
      const int x = p == 0 ? 0 : p == 1 ? 2 : 1, y = p == 0 ? 1 : p == 1 ? 0 : 2;
      for (int i = 0; i < AXES; ++i) {
        on_x_q_[i] = b_.arc && i == x;
        on_y_q_[i] = b_.arc && i == y;
        neg_q_[i] = b_.neg[i];
      }
    }
    hold_q_ = in.feed == 0;
    pin_q_ = in.feed;
    done_q_ = last;

    // Buffer B from buffer A: the masks, a0 and dc.
    const bool b_valid_next = advance ? (a_to_b || (b_valid_q_ && !pre_load))
                                      : (!in.abort && (a_to_b || (b_valid_q_ && !idle_load)));
    if (a_to_b) {
      const DdaMasks<ACC_W> m = dda_norm<ACC_W>(a_any_q_);
      b_ = a_;
      b_pin_q_ = a_.feed == 0;
      b_low_q_ = a_.arc ? acc_t(0) : m.low;
      b_low_zero_q_ = a_.arc || a_any_q_ == 0;
      // An arc: -N >>> 1 = -ceil(N/2); a line: hm.
      b_a0_q_ = a_.arc ? acc_t((a_negn_q_ >> 1) | (a_negn_q_ & (acc_t(1) << (ACC_W - 1)))) : m.hm;
      for (int i = 0; i < AXES; ++i)
        // |delta| <= N: dc reaches 2^ACC_W (ACC_W + 1 bits) for an axis stepping every operation.
        b_.dc[i] = a_.arc ? dc_t(dc_t(a_.mag[i]) + dc_t(a_negn_q_)) : dc_t(a_.mag[i] | m.hm);
    }
    b_aged_q_ = b_valid_next && b_valid_q_;
    b_valid_q_ = b_valid_next;
    // Buffer A: the offered command's magnitudes and the arc's prep.
    if (cmd_take) take(in.cmd);
    a_valid_q_ = !in.abort && (cmd_take || (a_valid_q_ && !a_to_b));
  }

  Outputs outputs() const {
    return out_.outputs(!a_valid_q_, act_q_ || a_valid_q_ || b_valid_q_, done_q_);
  }

 private:
  // A buffered command (buffers A and B; dc only in B).
  struct Buffer {
    bool arc = false, ccw = false;
    sc_dt::sc_uint<2> plane = 0;
    feed_t feed = 0;
    acc_t mag[AXES] = {};
    dc_t dc[AXES] = {};
    bool neg[AXES] = {}, moves[AXES] = {};
    typename Arc::Prep prep;
  };

  void take(const Own& cmd) {
    acc_t any = 0;
    for (int i = 0; i < AXES; ++i) {
      a_.neg[i] = cmd.delta[i][ACC_W - 1];
      a_.mag[i] = a_.neg[i] ? acc_t(-cmd.delta[i]) : cmd.delta[i];
      a_.moves[i] = cmd.delta[i] != 0;
      any |= a_.mag[i];
    }
    a_any_q_ = any;
    a_negn_q_ = acc_t(0) - acc_t(cmd.ops.to_uint64());
    a_.arc = cmd.arc;
    a_.ccw = cmd.ccw;
    a_.plane = cmd.plane;
    a_.feed = cmd.feed;
    a_.prep = Arc::prepare(cmd.center, cmd.end, cmd.ccw);
  }

  // Buffers.
  Buffer a_, b_;
  bool a_valid_q_, b_valid_q_;
  bool b_aged_q_;             // buffer B was valid on the clock before too (the same command)
  acc_t a_any_q_, a_negn_q_;  // OR of the magnitudes; 2^ACC_W - N
  acc_t b_low_q_, b_a0_q_;
  bool b_low_zero_q_;
  // Engine.
  bool act_q_, arc_q_;
  bool on_x_q_[AXES], on_y_q_[AXES];  // the running arc's plane axes
  bool neg_q_[AXES], moves_q_[AXES];
  acc_t left_q_;
  bool left_zero_q_;
  feed_t feed_q_;
  bool hold_q_;
  feed_t pin_q_;              // feed_i, for the moves whose feed word is 0
  bool b_pin_q_, cur_pin_q_;  // buffer B's / the running move's feed word is 0
  bool done_q_;
  DdaAxis<ACC_W, false> acc_[AXES];
  Arc arc_;
  FeedAccum<FEED_W> feed_;
  StepStage<AXES, POS_W, TIM_W> out_;
};

}  // namespace hwinterp::hls

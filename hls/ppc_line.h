// ppc_line, HLS face: the cycle behaviour of rtl/ppc_line.sv as a
// synthesizable C++ class (registers as members, tick() computes one rising
// clock edge). rtl/ppc_line.sv documents the behaviour; models/ppc.h states
// the mathematics. Synthesizable subset: SystemC integers, fixed-size arrays,
// no floats, no heap. hwinterp::hls::StepperModule<PpcLine<Cfg>> is its
// SC_MODULE.
//
// `Cfg` is a generated variant struct (cmake/cores.cmake): AXES (= 2), ACC_W,
// POS_W, TIM_W, FEED_W.
#pragma once

#include <systemc>

#include "hls/feed_accum.h"
#include "hls/fields.h"
#include "hls/pin_types.h"
#include "hls/ppc_line_step.h"
#include "hls/step_stage.h"
#include "hls/stepper_io.h"

namespace hwinterp::hls {

template <class CfgT>
class PpcLine {
 public:
  using Cfg = CfgT;
  static constexpr int AXES = Cfg::AXES;
  static constexpr int ACC_W = Cfg::ACC_W;
  static constexpr int POS_W = Cfg::POS_W;
  static constexpr int TIM_W = Cfg::TIM_W;
  static constexpr int FEED_W = Cfg::FEED_W;
  static_assert(AXES == 2, "PPC is a planar method: AXES must be 2");
  static_assert(ACC_W >= 3 && ACC_W <= 62, "ACC_W out of range (rtl/ppc_line.sv: 3..62)");
  static_assert(POS_W >= 2 && POS_W <= 64, "POS_W out of range");

  using acc_t = sc_dt::sc_uint<ACC_W>;
  using Line = PpcLineStep<ACC_W>;

  // The core's own input: cmd_delta_i (two's complement dx, dy).
  struct Own {
    acc_t delta[AXES] = {};
    static auto fields() {  // hls/fields.h
      return std::make_tuple(HWINTERP_FIELD(cmd_delta_i, &Own::delta, kSigned));
    }
  };
  using Inputs = StepperInputs<Own, FEED_W, TIM_W>;
  using Outputs = StepperOutputs<AXES, POS_W>;

  PpcLine() { reset(); }

  void reset() {
    buf_valid_q_ = false;
    act_q_ = false;
    done_q_ = false;
    for (int i = 0; i < AXES; ++i) {
      buf_mag_q_[i] = 0;
      buf_neg_q_[i] = false;
      neg_q_[i] = false;
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
    const bool carry[AXES] = {act_q_ && line_.step_x(), act_q_ && line_.step_y()};
    typename StepStage<AXES, POS_W, TIM_W>::Request want;
    want.want_valid[0] = act_q_ && line_.x_left();
    want.want_valid[1] = act_q_ && line_.y_left();
    bool stall = false;
    for (int i = 0; i < AXES; ++i) {
      want.want_dir[i] = neg_q_[i];
      if (carry[i] && !out_.ready(i, want)) stall = true;
    }
    const bool tick = feed_.tick(act_q_);
    const bool advance = tick && !stall && !in.abort;
    const bool last = advance && line_.last();
    const bool buf_take = buf_valid_q_ && (!act_q_ || last) && !in.abort;
    const bool cmd_take = in.cmd_valid && !buf_valid_q_;

    // Output stage and feed first: they read the engine registers before they update.
    bool fire[AXES];
    for (int i = 0; i < AXES; ++i) fire[i] = advance && carry[i];
    out_.clock(in.timing, want, fire);
    feed_.clock(in.feed, act_q_, stall);

    // Engine registers.
    line_.clock(buf_take, buf_mag_q_[0], buf_mag_q_[1], advance);
    if (last) act_q_ = false;
    if (buf_take) {
      act_q_ = true;
      for (int i = 0; i < AXES; ++i) neg_q_[i] = buf_neg_q_[i];
    }
    if (in.abort) act_q_ = false;
    // Command buffer: magnitudes and signs of the offered command.
    if (cmd_take) {
      for (int i = 0; i < AXES; ++i) {
        buf_neg_q_[i] = in.cmd.delta[i][ACC_W - 1];
        buf_mag_q_[i] = buf_neg_q_[i] ? acc_t(-in.cmd.delta[i]) : in.cmd.delta[i];
      }
    }
    buf_valid_q_ = !in.abort && (cmd_take || (buf_valid_q_ && !buf_take));
    done_q_ = last;
  }

  Outputs outputs() const { return out_.outputs(!buf_valid_q_, act_q_ || buf_valid_q_, done_q_); }

 private:
  // One-entry command buffer.
  bool buf_valid_q_;
  acc_t buf_mag_q_[AXES];  // |dx|, |dy| (|-2^(ACC_W-1)| still fits ACC_W bits)
  bool buf_neg_q_[AXES];
  // Engine.
  bool act_q_;
  bool neg_q_[AXES];
  bool done_q_;
  Line line_;
  FeedAccum<FEED_W> feed_;
  StepStage<AXES, POS_W, TIM_W> out_;
};

}  // namespace hwinterp::hls

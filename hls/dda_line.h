// dda_line, HLS face: the cycle behaviour of rtl/dda_line.sv as a synthesizable
// C++ class (registers as members, tick() computes one rising clock edge).
// rtl/dda_line.sv documents the behaviour; models/dda_line_model.h states its
// mathematics. Synthesizable subset: SystemC integers, fixed-size arrays,
// loops bounded by template parameters, no floats, no heap.
// hwinterp::hls::StepperModule<DdaLine<Cfg>> is its SC_MODULE.
//
// `Cfg` is a generated variant struct (cmake/cores.cmake): AXES, ACC_W, POS_W,
// TIM_W, FEED_W.
#pragma once

#include <systemc>

#include "hls/dda_axis.h"
#include "hls/dda_norm.h"
#include "hls/feed_accum.h"
#include "hls/fields.h"
#include "hls/pin_types.h"
#include "hls/step_stage.h"
#include "hls/stepper_io.h"

namespace hwinterp::hls {

template <class CfgT>
class DdaLine {
 public:
  using Cfg = CfgT;
  static constexpr int AXES = Cfg::AXES;
  static constexpr int ACC_W = Cfg::ACC_W;
  static constexpr int POS_W = Cfg::POS_W;
  static constexpr int TIM_W = Cfg::TIM_W;
  static constexpr int FEED_W = Cfg::FEED_W;
  static_assert(AXES >= 1 && AXES <= 32, "AXES out of range");
  static_assert(ACC_W >= 2 && ACC_W <= 62,
                "ACC_W out of range (the iteration count needs ACC_W+1 bits)");
  static_assert(POS_W >= 2 && POS_W <= 64, "POS_W out of range");
  using acc_t = sc_dt::sc_uint<ACC_W>;
  using sum_t = sc_dt::sc_uint<ACC_W + 1>;

  // The core's own inputs: cmd_delta_i (two's complement, one per axis) and
  // half_preload_i (sampled with the command).
  struct Own {
    acc_t delta[AXES] = {};
    bool half_preload = false;
    static auto fields() {  // hls/fields.h
      return std::make_tuple(HWINTERP_FIELD(cmd_delta_i, &Own::delta, kSigned),
                             HWINTERP_FIELD(half_preload_i, &Own::half_preload, kUnsigned));
    }
  };
  using Inputs = StepperInputs<Own, FEED_W, TIM_W>;
  using Outputs = StepperOutputs<AXES, POS_W>;

  DdaLine() { reset(); }

  void reset() {
    a_valid_q_ = b_valid_q_ = false;
    a_any_q_ = 0;
    a_half_q_ = false;
    b_low_q_ = b_hm_q_ = b_a0_q_ = 0;
    act_q_ = false;
    left_q_ = 0;
    left_zero_q_ = false;
    hm_q_ = 0;
    done_q_ = false;
    for (int i = 0; i < AXES; ++i) {
      a_mag_q_[i] = b_mag_q_[i] = 0;
      acc_[i].reset();
      a_neg_q_[i] = b_neg_q_[i] = neg_q_[i] = false;
      a_moves_q_[i] = b_moves_q_[i] = moves_q_[i] = false;
    }
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
    bool carry[AXES], fire[AXES], stall = false;
    typename StepStage<AXES, POS_W, TIM_W>::Request want;
    for (int i = 0; i < AXES; ++i) {
      carry[i] = acc_[i].carry();
      want.want_valid[i] = moves_q_[i];
      want.want_dir[i] = neg_q_[i];
      // (The RTL has this per axis as a register, the stage's block_o.)
      if (carry[i] && !out_.ready(i, want)) stall = true;
    }
    const bool tick = feed_.tick(act_q_);
    const bool advance = tick && !stall && !in.abort;
    const bool last = advance && left_zero_q_;
    const bool load = b_valid_q_ && (!act_q_ || last) && !in.abort;
    const bool a_to_b = a_valid_q_ && !b_valid_q_ && !in.abort;
    const bool cmd_take = in.cmd_valid && !a_valid_q_;

    // Output stage and feed first: they read the engine registers before they update.
    for (int i = 0; i < AXES; ++i) fire[i] = advance && carry[i];
    out_.clock(in.timing, want, fire);
    feed_.clock(in.feed, act_q_, stall);

    // Engine: one accumulator per axis (written only on a load or an
    // advance, and then the operands' select pre_load equals load).
    const bool pre_load = b_valid_q_ && (!act_q_ || left_zero_q_);
    for (int i = 0; i < AXES; ++i)
      acc_[i].clock(pre_load, load, load || advance, b_a0_q_, b_mag_q_[i], acc_t(0), hm_q_);
    if (advance) {
      left_zero_q_ = left_q_ == 1;
      left_q_ = left_q_ - 1;
      if (last) act_q_ = false;
    }
    for (int i = 0; i < AXES; ++i)
      if (last || in.abort) moves_q_[i] = false;
    if (load) {
      act_q_ = true;
      left_q_ = b_low_q_;
      left_zero_q_ = b_low_q_ == 0;
      hm_q_ = b_hm_q_;
      for (int i = 0; i < AXES; ++i) {
        neg_q_[i] = b_neg_q_[i];
        moves_q_[i] = b_moves_q_[i];
      }
    }
    if (in.abort) act_q_ = false;
    done_q_ = last;

    // Buffer B from buffer A: the masks from the OR of the magnitudes.
    if (a_to_b) {
      const DdaMasks<ACC_W> m = dda_norm<ACC_W>(a_any_q_);
      b_low_q_ = m.low;
      b_hm_q_ = m.hm;
      b_a0_q_ = m.hm | (a_half_q_ ? m.top : acc_t(0));
      for (int i = 0; i < AXES; ++i) {
        b_mag_q_[i] = a_mag_q_[i];
        b_neg_q_[i] = a_neg_q_[i];
        b_moves_q_[i] = a_moves_q_[i];
      }
    }
    b_valid_q_ = !in.abort && (a_to_b || (b_valid_q_ && !load));
    // Buffer A: the offered command's magnitudes and their OR.
    if (cmd_take) load_buffer(in.cmd);
    a_valid_q_ = !in.abort && (cmd_take || (a_valid_q_ && !a_to_b));
  }

  Outputs outputs() const {
    return out_.outputs(!a_valid_q_, act_q_ || a_valid_q_ || b_valid_q_, done_q_);
  }

 private:
  void load_buffer(const Own& cmd) {
    acc_t any = 0;
    for (int i = 0; i < AXES; ++i) {
      a_neg_q_[i] = cmd.delta[i][ACC_W - 1];
      a_mag_q_[i] = a_neg_q_[i] ? acc_t(-cmd.delta[i]) : cmd.delta[i];
      a_moves_q_[i] = cmd.delta[i] != 0;
      any |= a_mag_q_[i];
    }
    a_any_q_ = any;
    a_half_q_ = cmd.half_preload;
  }

  // Buffer A: the taken command.
  bool a_valid_q_;
  acc_t a_mag_q_[AXES];
  bool a_neg_q_[AXES], a_moves_q_[AXES];
  acc_t a_any_q_;
  bool a_half_q_;
  // Buffer B: the command normalised.
  bool b_valid_q_;
  acc_t b_mag_q_[AXES];
  bool b_neg_q_[AXES], b_moves_q_[AXES];
  acc_t b_low_q_, b_hm_q_, b_a0_q_;
  // Engine.
  bool act_q_;
  DdaAxis<ACC_W, true> acc_[AXES];
  bool neg_q_[AXES], moves_q_[AXES];
  acc_t hm_q_;
  acc_t left_q_;
  bool left_zero_q_;
  bool done_q_;
  FeedAccum<FEED_W> feed_;
  StepStage<AXES, POS_W, TIM_W> out_;
};

}  // namespace hwinterp::hls

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

#include "hls/feed_accum.h"
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
  static constexpr int EXP_W = [] {  // $clog2(ACC_W + 1)
    int w = 0;
    while ((1 << w) < ACC_W + 1) ++w;
    return w;
  }();

  using acc_t = sc_dt::sc_uint<ACC_W>;
  using sum_t = sc_dt::sc_uint<ACC_W + 1>;
  using left_t = sc_dt::sc_uint<ACC_W + 1>;
  using exp_t = sc_dt::sc_uint<EXP_W>;

  // The core's own inputs: cmd_delta_i (two's complement, one per axis) and
  // half_preload_i (sampled with the command).
  struct Own {
    acc_t delta[AXES] = {};
    bool half_preload = false;
  };
  using Inputs = StepperInputs<Own, FEED_W, TIM_W>;
  using Outputs = StepperOutputs<AXES, POS_W>;

  // The own ports of the SC_MODULE face (hls/stepper_module.h).
  struct OwnPorts : DeltaPort<AXES, ACC_W> {
    sc_core::sc_in<bool> half_preload_i{"half_preload_i"};
    void read(Own& own) const {
      DeltaPort<AXES, ACC_W>::read(own);
      own.half_preload = half_preload_i.read();
    }
  };

  DdaLine() { reset(); }

  void reset() {
    buf_valid_q_ = false;
    buf_exp_q_ = 0;
    buf_half_q_ = false;
    act_q_ = false;
    left_q_ = 0;
    done_q_ = false;
    for (int i = 0; i < AXES; ++i) {
      buf_mag_q_[i] = 0;
      buf_neg_q_[i] = false;
      acc_q_[i] = 0;
      inc_q_[i] = 0;
      neg_q_[i] = false;
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
    sum_t sum[AXES];
    typename StepStage<AXES, POS_W, TIM_W>::Request want;
    for (int i = 0; i < AXES; ++i) {
      sum[i] = sum_t(acc_q_[i]) + sum_t(inc_q_[i]);
      carry[i] = sum[i][ACC_W];
      want.want_valid[i] = act_q_ && inc_q_[i] != 0;
      want.want_dir[i] = neg_q_[i];
      if (carry[i] && !out_.ready(i, want)) stall = true;
    }
    const bool tick = feed_.tick(in.feed, act_q_);
    const bool advance = tick && !stall && !in.abort;
    const bool last = advance && left_q_ == 1;
    const bool buf_take = buf_valid_q_ && (!act_q_ || last) && !in.abort;
    const bool cmd_take = in.cmd_valid && !buf_valid_q_;

    // Output stage and feed first: they read the engine registers before they update.
    for (int i = 0; i < AXES; ++i) fire[i] = advance && carry[i];
    out_.clock(in.timing, want, fire);
    feed_.clock(in.feed, act_q_, stall);

    // Engine registers.
    if (advance) {
      left_q_ = left_q_ - 1;
      for (int i = 0; i < AXES; ++i) acc_q_[i] = sum[i].range(ACC_W - 1, 0);
      if (last) act_q_ = false;
    }
    if (buf_take) {
      act_q_ = true;
      left_q_ = left_t(1) << buf_exp_q_.to_uint();
      for (int i = 0; i < AXES; ++i) {
        acc_q_[i] = buf_half_q_ ? acc_t(acc_t(1) << (ACC_W - 1)) : acc_t(0);
        inc_q_[i] = shifted(buf_mag_q_[i], buf_exp_q_.to_uint());
        neg_q_[i] = buf_neg_q_[i];
      }
    }
    if (in.abort) act_q_ = false;
    // Command buffer: magnitudes and exponent of the offered command.
    if (cmd_take) load_buffer(in.cmd);
    buf_valid_q_ = !in.abort && (cmd_take || (buf_valid_q_ && !buf_take));
    done_q_ = last;
  }

  Outputs outputs() const { return out_.outputs(!buf_valid_q_, act_q_ || buf_valid_q_, done_q_); }

 private:
  // Taking a command stores the magnitudes and n, the bit length of the
  // largest one (the OR of the magnitudes has the same bit length as their
  // maximum); the engine shifts them as it loads the command. Same split as
  // the RTL, which keeps each clock's logic path short.
  void load_buffer(const Own& cmd) {
    acc_t any = 0;
    for (int i = 0; i < AXES; ++i) {
      buf_neg_q_[i] = cmd.delta[i][ACC_W - 1];
      buf_mag_q_[i] = buf_neg_q_[i] ? acc_t(-cmd.delta[i]) : cmd.delta[i];
      any |= buf_mag_q_[i];
    }
    int n = 0;
    for (int b = 0; b < ACC_W; ++b)
      if (any[b]) n = b + 1;
    buf_exp_q_ = n;
    buf_half_q_ = cmd.half_preload;
  }

  // |delta| << (ACC_W - n); n = 0 only for an all-zero command.
  static acc_t shifted(const acc_t& mag, unsigned n) {
    return n == 0 ? acc_t(0) : acc_t(mag << (ACC_W - n));
  }

  // One-entry command buffer.
  bool buf_valid_q_;
  acc_t buf_mag_q_[AXES];
  bool buf_neg_q_[AXES];
  exp_t buf_exp_q_;
  bool buf_half_q_;
  // Engine.
  bool act_q_;
  acc_t acc_q_[AXES];
  acc_t inc_q_[AXES];
  bool neg_q_[AXES];
  left_t left_q_;
  bool done_q_;
  FeedAccum<FEED_W> feed_;
  StepStage<AXES, POS_W, TIM_W> out_;
};

}  // namespace hwinterp::hls

// fixed_ratio, HLS face: the cycle behaviour of rtl/fixed_ratio.sv as a
// synthesizable C++ class (registers as members, tick() computes one rising
// clock edge). rtl/fixed_ratio.sv documents the behaviour (buffer, rate
// dividers, latency and gaps, engine, abort, status);
// models/fixed_ratio_model.h states its mathematics and error bound.
// Synthesizable subset: SystemC integers, fixed-size arrays, loops bounded by
// template parameters, no floats, no heap.
// hwinterp::hls::StepperModule<FixedRatio<Cfg>> is its SC_MODULE.
//
// `Cfg` is a generated variant struct (cmake/cores.cmake): AXES, ACC_W,
// FRAC_W, POS_W, TIM_W, FEED_W.
#pragma once

#include <systemc>

#include "hls/feed_accum.h"
#include "hls/fields.h"
#include "hls/pin_types.h"
#include "hls/step_stage.h"
#include "hls/stepper_io.h"

namespace hwinterp::hls {

template <class CfgT>
class FixedRatio {
 public:
  using Cfg = CfgT;
  static constexpr int AXES = Cfg::AXES;
  static constexpr int ACC_W = Cfg::ACC_W;
  static constexpr int FRAC_W = Cfg::FRAC_W;
  static constexpr int POS_W = Cfg::POS_W;
  static constexpr int TIM_W = Cfg::TIM_W;
  static constexpr int FEED_W = Cfg::FEED_W;
  static_assert(AXES >= 1 && AXES <= 32, "AXES out of range");
  static_assert(ACC_W >= 2 && ACC_W <= 63, "ACC_W out of range (rem - M needs ACC_W + 1 bits)");
  static_assert(FRAC_W >= ACC_W + 1,
                "FRAC_W < ACC_W + 1: a minor axis could lag past tick M "
                "(models/fixed_ratio_model.h), or the divider's dividend bits come too early "
                "(rtl/fixed_ratio.sv)");
  static_assert(FRAC_W <= 62, "FRAC_W out of range (phase + rate needs FRAC_W + 1 bits)");
  static_assert(POS_W >= 2 && POS_W <= 64, "POS_W out of range");
  static constexpr int DIV_N =
      FRAC_W + 2;                    // divider clocks: compares, integer bit, FRAC_W fraction bits
  static constexpr int DIV_W = [] {  // $clog2(DIV_N + 1)
    int w = 0;
    while ((1 << w) < DIV_N + 1) ++w;
    return w;
  }();

  using mag_t = sc_dt::sc_uint<ACC_W>;
  using diff_t = sc_dt::sc_uint<ACC_W + 1>;
  using rate_t = sc_dt::sc_uint<FRAC_W + 1>;  // also the quotient and phase + rate
  using low_t = sc_dt::sc_uint<FRAC_W>;
  using div_t = sc_dt::sc_uint<DIV_W>;

  // The core's own input: cmd_delta_i (two's complement, one per axis).
  struct Own {
    mag_t delta[AXES] = {};
    static auto fields() {  // hls/fields.h
      return std::make_tuple(HWINTERP_FIELD(cmd_delta_i, &Own::delta, kSigned));
    }
  };
  using Inputs = StepperInputs<Own, FEED_W, TIM_W>;
  using Outputs = StepperOutputs<AXES, POS_W>;

  FixedRatio() { reset(); }

  void reset() {
    buf_valid_q_ = false;
    buf_max_q_ = 0;
    div_left_q_ = 0;
    for (bool& p : ph_q_) p = false;
    for (bool& m : is_max_q_) m = false;
    low_q_ = 0;
    act_q_ = false;
    done_q_ = false;
    for (int i = 0; i < AXES; ++i) {
      buf_mag_q_[i] = 0;
      buf_neg_q_[i] = false;
      rem_q_[i] = 0;
      quot_q_[i] = 0;
      rate_q_[i] = 0;
      sum_q_[i] = 0;
      cnt_q_[i] = 0;
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
    bool left[AXES], carry[AXES], must[AXES], fire[AXES], stall = false, all_fin = true;
    typename StepStage<AXES, POS_W, TIM_W>::Request want;
    for (int i = 0; i < AXES; ++i) {
      carry[i] = sum_q_[i][FRAC_W];
      left[i] = cnt_q_[i] != 0;
      must[i] = carry[i] && left[i];
      all_fin = all_fin && (!left[i] || (cnt_q_[i] == 1 && carry[i]));
      want.want_valid[i] = act_q_ && left[i];
      want.want_dir[i] = neg_q_[i];
      // (The RTL has this per axis as a register, the stage's block_o.)
      if (must[i] && !out_.ready(i, want)) stall = true;
    }
    const bool tick = feed_.tick(act_q_);
    const bool advance = tick && !stall && !in.abort;
    // The RTL keeps this as a register from a major axis's counter (last_q,
    // rtl/fixed_ratio.sv); both are "the command's tick max(M, 1)".
    const bool last = advance && all_fin;
    const bool div_run = buf_valid_q_ && div_left_q_ != 0;
    // Ready once the division is done (the clock after its last clock).
    const bool buf_ready = buf_valid_q_ && div_left_q_ == 0;
    const bool buf_take = buf_ready && (!act_q_ || last) && !in.abort;
    const bool cmd_take = in.cmd_valid && !buf_valid_q_;

    // Output stage and feed first: they read the engine registers before they update.
    for (int i = 0; i < AXES; ++i) fire[i] = advance && must[i];
    out_.clock(in.timing, want, fire);
    feed_.clock(in.feed, act_q_, stall);

    // Buffer: one divider clock (rtl/fixed_ratio.sv): 1. every pair of
    // magnitudes compared; 2. M and the integer bits (|delta_i| = M: rem
    // becomes 0 or 2 |delta_i|); 3.. one restoring-division step, the
    // dividend's next low bit (of M - 1) shifted in (the RTL divides
    // non-restoring: the same quotient bits, its remainder minus M kept,
    // each bit a clock later, the last one the final remainder's sign; a
    // maximal axis's R set to 2^FRAC_W at the load). quot is the quotient
    // with this clock's bit: after the last clock, the rate word
    // ceil(|delta_i| 2^FRAC_W / M).
    rate_t quot[AXES];
    for (int i = 0; i < AXES; ++i) quot[i] = quot_q_[i];
    if (div_run) {
      mag_t max = 0;
      for (int i = 0; i < AXES; ++i)
        if (is_max_q_[i]) max |= buf_mag_q_[i];
      const bool shift_in = low_q_[FRAC_W - 1];
      for (int i = 0; i < AXES; ++i) {
        const diff_t diff = diff_t(rem_q_[i]) - diff_t(buf_max_q_);
        const bool ge = ph_q_[1] ? is_max_q_[i] : !diff[ACC_W];
        const mag_t rem = ph_q_[1] ? (is_max_q_[i] ? mag_t(0) : buf_mag_q_[i])
                          : ge     ? mag_t(diff.range(ACC_W - 1, 0))
                                   : rem_q_[i];
        // rem < M <= 2^(ACC_W-1): nothing shifts out.
        rem_q_[i] = mag_t((rem << 1) | mag_t(shift_in ? 1 : 0));
        quot[i] = rate_t((quot_q_[i] << 1) | rate_t(ge ? 1 : 0));
        quot_q_[i] = quot[i];
      }
      if (ph_q_[0])
        for (int i = 0; i < AXES; ++i) {
          is_max_q_[i] = true;
          for (int j = 0; j < AXES; ++j)
            is_max_q_[i] = is_max_q_[i] && buf_mag_q_[i] >= buf_mag_q_[j];
        }
      if (ph_q_[1]) buf_max_q_ = max;
      div_left_q_ = div_left_q_ - 1;
    }
    // The dividend's low bits, M - 1: cleared in clock 1, loaded in clock 3
    // (aligned for clock 4's shift), shifted left on every other clock.
    if (ph_q_[2]) {
      low_q_ = low_t((uint64_t(mag_t(buf_max_q_ - 1))) << 2);
    } else if (ph_q_[0]) {
      low_q_ = 0;
    } else {
      low_q_ = low_t(low_q_ << 1);
    }
    for (int k = 2; k > 0; --k) ph_q_[k] = ph_q_[k - 1] && !in.abort;
    const bool take_zero = cmd_take && cmd_zero(in.cmd);  // a zero-length command: no division
    ph_q_[0] = cmd_take && !in.abort && !take_zero;

    // Engine registers: the phase kept as phase + R (its carry is the next
    // tick's step; the RTL keeps that carry and the tick after's phase + R).
    for (int i = 0; i < AXES; ++i) {
      if (buf_take) {
        rate_q_[i] = quot[i];
        neg_q_[i] = buf_neg_q_[i];
        // The phase starts at one half.
        sum_q_[i] = (uint64_t{1} << (FRAC_W - 1)) + quot[i];
        cnt_q_[i] = buf_mag_q_[i];
      } else if (advance) {
        sum_q_[i] = rate_t(sum_q_[i].range(FRAC_W - 1, 0)) + rate_q_[i];
        if (must[i]) cnt_q_[i] = cnt_q_[i] - 1;
      }
    }
    if (last) act_q_ = false;
    if (buf_take) act_q_ = true;
    if (in.abort) act_q_ = false;
    if (cmd_take) load_buffer(in.cmd, take_zero);
    buf_valid_q_ = !in.abort && (cmd_take || (buf_valid_q_ && !buf_take));
    done_q_ = last;
  }

  Outputs outputs() const { return out_.outputs(!buf_valid_q_, act_q_ || buf_valid_q_, done_q_); }

 private:
  static bool cmd_zero(const Own& cmd) {
    bool zero = true;
    for (int i = 0; i < AXES; ++i) zero = zero && cmd.delta[i] == 0;
    return zero;
  }

  // Taking a command stores the magnitudes and the signs, and starts the
  // dividers; a zero-length command needs no division.
  void load_buffer(const Own& cmd, bool zero) {
    for (int i = 0; i < AXES; ++i) {
      buf_neg_q_[i] = cmd.delta[i][ACC_W - 1];
      // |-2^(ACC_W-1)| = 2^(ACC_W-1) still fits ACC_W unsigned bits.
      buf_mag_q_[i] = buf_neg_q_[i] ? mag_t(-cmd.delta[i]) : cmd.delta[i];
    }
    div_left_q_ = zero ? 0 : DIV_N;
  }

  // One-entry command buffer and its dividers.
  bool buf_valid_q_;
  mag_t buf_mag_q_[AXES];
  bool buf_neg_q_[AXES];
  mag_t buf_max_q_;  // M, from divider clock 3 on (the RTL keeps ~M)
  div_t div_left_q_;
  bool ph_q_[3];         // divider clocks 1, 2, 3
  bool is_max_q_[AXES];  // |delta_i| = M: the integer quotient bit (the RTL keeps the pairwise
                         // compares)
  low_t low_q_;          // the dividend's low bits still to shift in, next in the MSB
  mag_t rem_q_[AXES];
  rate_t quot_q_[AXES];
  // Engine.
  bool act_q_;
  rate_t rate_q_[AXES];  // R = ceil(|delta_i| 2^FRAC_W / M)
  rate_t sum_q_[AXES];   // phase + R
  mag_t cnt_q_[AXES];
  bool neg_q_[AXES];
  bool done_q_;
  FeedAccum<FEED_W> feed_;
  StepStage<AXES, POS_W, TIM_W> out_;
};

}  // namespace hwinterp::hls

// dda_line, HLS face: the cycle behaviour of rtl/dda_line.sv as a synthesizable
// C++ class (registers as members, tick() computes one rising clock edge).
// rtl/dda_line.sv documents the behaviour; models/dda_line_model.h states its
// mathematics. Synthesizable subset: SystemC integers, fixed-size arrays,
// loops bounded by template parameters, no floats, no heap.
//
// `Cfg` is a generated variant struct (cmake/cores.cmake): AXES, ACC_W, POS_W,
// TIM_W, FEED_W.
#pragma once

#include <systemc>

#include "hls/stepdir_axis.h"

namespace hwinterp::hls {

template <class Cfg>
class DdaLine {
 public:
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
  using pos_t = sc_dt::sc_uint<POS_W>;
  using feed_t = sc_dt::sc_uint<FEED_W>;
  using Settings = StepdirSettings<TIM_W>;

  // Pins sampled at a rising edge (rst_n is the asynchronous active-low reset).
  struct Inputs {
    bool rst_n = false;
    bool cmd_valid = false;
    acc_t cmd_delta[AXES] = {};  // two's complement, one per axis
    sc_dt::sc_uint<FEED_W + 1> feed = 0;
    bool half_preload = false;
    Settings timing = {};
  };

  // Registered outputs after the edge.
  struct Outputs {
    bool cmd_ready;
    sc_dt::sc_uint<AXES> step, dir;
    pos_t pos[AXES];
    bool busy, done;
  };

  DdaLine() { reset(); }

  void reset() {
    buf_valid_q_ = false;
    buf_exp_q_ = 0;
    buf_half_q_ = false;
    act_q_ = false;
    left_q_ = 0;
    feed_q_ = 0;
    done_q_ = false;
    for (int i = 0; i < AXES; ++i) {
      buf_mag_q_[i] = 0;
      buf_neg_q_[i] = false;
      acc_q_[i] = 0;
      inc_q_[i] = 0;
      neg_q_[i] = false;
      pos_q_[i] = 0;
      axis_[i].reset();
    }
  }

  // One rising clock edge (or, with rst_n low, the reset).
  void tick(const Inputs& in) {
    if (!in.rst_n) {
      reset();
      return;
    }
    // Combinational part, from the current registers and the inputs.
    bool carry[AXES], moves[AXES], stall = false;
    sum_t sum[AXES];
    for (int i = 0; i < AXES; ++i) {
      sum[i] = sum_t(acc_q_[i]) + sum_t(inc_q_[i]);
      carry[i] = sum[i][ACC_W];
      moves[i] = act_q_ && inc_q_[i] != 0;
      if (carry[i] && !axis_[i].ready(in.timing, moves[i], neg_q_[i])) stall = true;
    }
    const bool feed_full = in.feed[FEED_W];
    const sc_dt::sc_uint<FEED_W + 1> feed_sum =
        sc_dt::sc_uint<FEED_W + 1>(feed_q_) + in.feed.range(FEED_W - 1, 0);
    const bool tick = act_q_ && (feed_full || feed_sum[FEED_W]);
    const bool advance = tick && !stall;
    const bool last = advance && left_q_ == 1;
    const bool buf_take = buf_valid_q_ && (!act_q_ || last);
    const bool cmd_take = in.cmd_valid && !buf_valid_q_;

    // Output stage first: it reads the engine registers before they update.
    for (int i = 0; i < AXES; ++i)
      axis_[i].tick(in.timing, moves[i], neg_q_[i], advance && carry[i]);

    // Engine registers.
    if (act_q_ && !feed_full && !(tick && stall)) feed_q_ = feed_sum.range(FEED_W - 1, 0);
    if (advance) {
      left_q_ = left_q_ - 1;
      for (int i = 0; i < AXES; ++i) {
        acc_q_[i] = sum[i].range(ACC_W - 1, 0);
        if (carry[i]) pos_q_[i] = neg_q_[i] ? pos_t(pos_q_[i] - 1) : pos_t(pos_q_[i] + 1);
      }
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
    // Command buffer: magnitudes and exponent of the offered command.
    if (cmd_take) load_buffer(in);
    buf_valid_q_ = cmd_take || (buf_valid_q_ && !buf_take);
    done_q_ = last;
  }

  Outputs outputs() const {
    Outputs o;
    o.cmd_ready = !buf_valid_q_;
    o.step = 0;
    o.dir = 0;
    bool any_step = false;
    for (int i = 0; i < AXES; ++i) {
      o.step[i] = axis_[i].step();
      o.dir[i] = axis_[i].dir();
      o.pos[i] = pos_q_[i];
      any_step = any_step || axis_[i].step();
    }
    o.busy = act_q_ || buf_valid_q_ || any_step;
    o.done = done_q_;
    return o;
  }

 private:
  // Taking a command stores the magnitudes and n, the bit length of the
  // largest one (the OR of the magnitudes has the same bit length as their
  // maximum); the engine shifts them as it loads the command. Same split as
  // the RTL, which keeps each clock's logic path short.
  void load_buffer(const Inputs& in) {
    acc_t any = 0;
    for (int i = 0; i < AXES; ++i) {
      buf_neg_q_[i] = in.cmd_delta[i][ACC_W - 1];
      buf_mag_q_[i] = buf_neg_q_[i] ? acc_t(-in.cmd_delta[i]) : in.cmd_delta[i];
      any |= buf_mag_q_[i];
    }
    int n = 0;
    for (int b = 0; b < ACC_W; ++b)
      if (any[b]) n = b + 1;
    buf_exp_q_ = n;
    buf_half_q_ = in.half_preload;
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
  feed_t feed_q_;
  pos_t pos_q_[AXES];
  bool done_q_;
  // Output stage.
  StepdirAxis<TIM_W> axis_[AXES];
};

}  // namespace hwinterp::hls

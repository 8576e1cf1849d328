// Step/dir output stage of one axis: the cycle behaviour of rtl/stepdir_axis.sv.
// See that file for the timing contract (a phase keeps the setting of the
// clock it starts on) and how the counters and flags work; the C++ mirrors it
// register for register. Synthesizable subset: SystemC integers, no floats,
// no heap.
#pragma once

#include <systemc>

#include "hls/stepdir_timing.h"

namespace hwinterp::hls {

template <int TIM_W>
class StepdirAxis {
 public:
  using tim_t = sc_dt::sc_uint<TIM_W>;
  using Prepared = StepdirPrepared<TIM_W>;

  void reset() {
    step_q_ = dir_q_ = false;
    tim_q_ = hold_q_ = setup_q_ = 0;
    v_q_ = w_q_ = true;
    tim_one_q_ = hold_ok_q_ = setup_ok_q_ = pulse_ok_q_ = false;
  }

  // A pulse may start on the next clock (combinational, like ready_o).
  bool ready(bool want_valid, bool want_dir) const {
    return pulse_ok_q_ && want_valid && want_dir == dir_q_;
  }

  // One rising clock edge.
  void tick(const Prepared& p, bool want_valid, bool want_dir, bool fire) {
    const bool turn = hold_ok_q_ && want_valid && want_dir != dir_q_;
    bool step_d = step_q_, v_d = v_q_, tim_one_d = tim_one_q_, hold_ok_d = hold_ok_q_;
    tim_t tim_d = tim_q_, hold_d = hold_q_;
    if (p.fresh) {
      tim_d = p.space;
      hold_d = p.hold;
      tim_one_d = p.space_two;
      hold_ok_d = p.hold_two;
    } else if (step_q_) {
      if (tim_one_q_) {
        step_d = false;
        tim_d = p.space;
        hold_d = p.hold;
        v_d = false;
        tim_one_d = p.space_one;
        hold_ok_d = p.hold_one;
      } else {
        tim_d = tim_q_ - 1;
        tim_one_d = le2_off(tim_q_, false);
      }
    } else if (fire) {
      step_d = true;
      tim_d = p.len;
      v_d = false;
      tim_one_d = p.len_one;
      hold_ok_d = false;
    } else {
      if (!tim_one_q_) {
        tim_d = tim_q_ - 1;
        tim_one_d = le2_off(tim_q_, v_q_);
      }
      if (!hold_ok_q_) {
        hold_d = hold_q_ - 1;
        hold_ok_d = le2_off(hold_q_, v_q_);
      }
    }

    bool dir_d = dir_q_, w_d = w_q_, setup_ok_d = setup_ok_q_;
    tim_t setup_d = setup_q_;
    if (p.fresh) {
      setup_d = p.setup;
      setup_ok_d = p.setup_two;
    } else if (turn) {
      dir_d = want_dir;
      setup_d = p.setup;
      w_d = false;
      setup_ok_d = p.setup_one;
    } else if (!setup_ok_q_) {
      setup_d = setup_q_ - 1;
      setup_ok_d = le2_off(setup_q_, w_q_);
    }

    step_q_ = step_d;
    dir_q_ = dir_d;
    tim_q_ = tim_d;
    hold_q_ = hold_d;
    setup_q_ = setup_d;
    v_q_ = v_d;
    w_q_ = w_d;
    tim_one_q_ = tim_one_d;
    hold_ok_q_ = hold_ok_d;
    setup_ok_q_ = setup_ok_d;
    pulse_ok_q_ = !step_d && tim_one_d && setup_ok_d;
  }

  bool step() const { return step_q_; }
  bool dir() const { return dir_q_; }

 private:
  // c - off <= 2 (off: the counter's offset of one until its first phase after reset).
  static bool le2_off(const tim_t& c, bool off) { return c.to_uint64() <= (off ? 3u : 2u); }

  bool step_q_ = false, dir_q_ = false;
  tim_t tim_q_ = 0, hold_q_ = 0, setup_q_ = 0;
  bool v_q_ = true, w_q_ = true;
  bool tim_one_q_ = false, hold_ok_q_ = false, setup_ok_q_ = false, pulse_ok_q_ = false;
};

}  // namespace hwinterp::hls

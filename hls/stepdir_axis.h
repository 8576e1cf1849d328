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
    tim_one_q_ = hold_ok_q_ = setup_ok_q_ = ok_pos_q_ = ok_neg_q_ = false;
  }

  // A pulse in direction want_dir may start on the next clock (ready_o with
  // READY_Q = 0; with READY_Q = 1 the RTL registers the same value a clock
  // ahead from the engine's next want_dir, and block_o, "wanted and not
  // ready", from its next want: the engines here compute their stall from
  // this instead; want_valid is the engine's business).
  bool ready(bool want_dir) const { return want_dir ? ok_neg_q_ : ok_pos_q_; }

  // One rising clock edge.
  void tick(const Prepared& p, bool want_valid, bool want_dir, bool fire) {
    const bool turn = hold_ok_q_ && want_valid && want_dir != dir_q_;
    // The next state without a pulse starting, then fire on top (as the RTL).
    bool step_nf = step_q_, v_nf = v_q_, tim_one_nf = tim_one_q_, hold_ok_nf = hold_ok_q_;
    tim_t tim_nf = tim_q_, hold_d = hold_q_;
    if (p.fresh) {
      tim_nf = p.space;
      hold_d = p.hold;
      tim_one_nf = p.space_two;
      hold_ok_nf = p.hold_two;
    } else if (step_q_) {
      if (tim_one_q_) {
        step_nf = false;
        tim_nf = p.space;
        hold_d = p.hold;
        v_nf = false;
        tim_one_nf = p.space_one;
        hold_ok_nf = p.hold_one;
      } else {
        tim_nf = tim_q_ - 1;
        tim_one_nf = le2_off(tim_q_, false);
      }
    } else {
      if (!tim_one_q_) {
        tim_nf = tim_q_ - 1;
        tim_one_nf = le2_off(tim_q_, v_q_);
      }
      if (!hold_ok_q_) {
        hold_d = hold_q_ - 1;
        hold_ok_nf = le2_off(hold_q_, v_q_);
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
    const bool pulse_nf = !step_nf && tim_one_nf && setup_ok_d;

    step_q_ = step_nf || fire;
    dir_q_ = dir_d;
    tim_q_ = fire ? p.len : tim_nf;
    hold_q_ = hold_d;
    setup_q_ = setup_d;
    v_q_ = v_nf && !fire;
    w_q_ = w_d;
    tim_one_q_ = fire ? p.len_one : tim_one_nf;
    hold_ok_q_ = hold_ok_nf && !fire;
    setup_ok_q_ = setup_ok_d;
    ok_pos_q_ = pulse_nf && !fire && !dir_d;
    ok_neg_q_ = pulse_nf && !fire && dir_d;
  }

  bool step() const { return step_q_; }
  bool dir() const { return dir_q_; }

 private:
  // c - off <= 2 (off: the counter's offset of one until its first phase after reset).
  static bool le2_off(const tim_t& c, bool off) { return c.to_uint64() <= (off ? 3u : 2u); }

  bool step_q_ = false, dir_q_ = false;
  tim_t tim_q_ = 0, hold_q_ = 0, setup_q_ = 0;
  bool v_q_ = true, w_q_ = true;
  bool tim_one_q_ = false, hold_ok_q_ = false, setup_ok_q_ = false;
  bool ok_pos_q_ = false, ok_neg_q_ = false;
};

}  // namespace hwinterp::hls

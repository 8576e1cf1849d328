// The step/dir timing settings as every axis takes them, computed once for
// all axes: the cycle behaviour of rtl/stepdir_timing.sv (see there).
// Synthesizable subset: SystemC integers, no floats, no heap.
#pragma once

#include <systemc>

namespace hwinterp::hls {

// The four hostmot2 settings as on the core's pins (0 acts as 1).
template <int TIM_W>
struct StepdirSettings {
  sc_dt::sc_uint<TIM_W> step_len, step_space, dir_setup, dir_hold;
};

// The settings at least 1, with the compares the axes need at a phase start,
// and `fresh` (the first clock after reset).
template <int TIM_W>
struct StepdirPrepared {
  sc_dt::sc_uint<TIM_W> len, space, setup, hold;
  bool len_one, space_one, setup_one, hold_one;  // == 1
  bool space_two, setup_two, hold_two;           // <= 2
  bool fresh;
};

template <int TIM_W>
class StepdirTiming {
 public:
  static_assert(TIM_W >= 2, "TIM_W must be at least 2");
  using tim_t = sc_dt::sc_uint<TIM_W>;

  void reset() { fresh_q_ = true; }

  // The combinational outputs from the pins and the fresh register.
  StepdirPrepared<TIM_W> prepare(const StepdirSettings<TIM_W>& s) const {
    StepdirPrepared<TIM_W> p;
    p.len = at_least_one(s.step_len);
    p.space = at_least_one(s.step_space);
    p.setup = at_least_one(s.dir_setup);
    p.hold = at_least_one(s.dir_hold);
    p.len_one = s.step_len <= 1;
    p.space_one = s.step_space <= 1;
    p.setup_one = s.dir_setup <= 1;
    p.hold_one = s.dir_hold <= 1;
    p.space_two = s.step_space <= 2;
    p.setup_two = s.dir_setup <= 2;
    p.hold_two = s.dir_hold <= 2;
    p.fresh = fresh_q_;
    return p;
  }

  // One rising clock edge.
  void clock() { fresh_q_ = false; }

 private:
  static tim_t at_least_one(const tim_t& v) { return v == 0 ? tim_t(1) : v; }
  bool fresh_q_ = true;
};

}  // namespace hwinterp::hls

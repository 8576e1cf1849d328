// Step/dir output stage of one axis: the cycle behaviour of rtl/stepdir_axis.sv.
// See that file for the timing contract; the comments here say how the C++
// mirrors it. Synthesizable subset: SystemC integers, no floats, no heap.
#pragma once

#include <systemc>

namespace hwinterp::hls {

template <int TIM_W>
struct StepdirSettings {
  sc_dt::sc_uint<TIM_W> step_len, step_space, dir_setup, dir_hold;
};

template <int TIM_W>
class StepdirAxis {
 public:
  using tim_t = sc_dt::sc_uint<TIM_W>;
  using Settings = StepdirSettings<TIM_W>;

  // The reset counts as the end of a pulse and a change of dir (see the RTL).
  void reset() {
    step_q_ = false;
    dir_q_ = false;
    high_q_ = 0;
    low_q_ = 1;
    dir_age_q_ = 1;
  }

  // A pulse may start on the next clock (combinational, like ready_o).
  bool ready(const Settings& s, bool want_valid, bool want_dir) const {
    return !step_q_ && want_valid && want_dir == dir_q_ && low_q_ >= at_least_one(s.step_space) &&
           dir_age_q_ >= at_least_one(s.dir_setup);
  }

  // One rising clock edge.
  void tick(const Settings& s, bool want_valid, bool want_dir, bool fire) {
    const bool dir_change =
        !step_q_ && want_valid && want_dir != dir_q_ && low_q_ >= at_least_one(s.dir_hold);
    bool step_d = step_q_;
    tim_t high_d = high_q_, low_d = low_q_;
    if (step_q_) {
      if (high_q_ >= at_least_one(s.step_len)) {
        step_d = false;
        low_d = 1;
      } else {
        high_d = high_q_ + 1;
      }
    } else if (fire) {
      step_d = true;
      high_d = 1;
    } else if (low_q_ != kSat) {
      low_d = low_q_ + 1;
    }
    tim_t dir_age_d = dir_age_q_ != kSat ? tim_t(dir_age_q_ + 1) : dir_age_q_;
    if (dir_change) {
      dir_q_ = want_dir;
      dir_age_d = 1;
    }
    step_q_ = step_d;
    high_q_ = high_d;
    low_q_ = low_d;
    dir_age_q_ = dir_age_d;
  }

  bool step() const { return step_q_; }
  bool dir() const { return dir_q_; }

 private:
  static constexpr uint64_t kSat = (uint64_t{1} << TIM_W) - 1;
  static tim_t at_least_one(const tim_t& v) { return v == 0 ? tim_t(1) : v; }

  bool step_q_ = false;
  bool dir_q_ = false;
  tim_t high_q_ = 0;     // cycles step has been high, this one included
  tim_t low_q_ = 1;      // cycles step has been low (saturating)
  tim_t dir_age_q_ = 1;  // cycles dir has held its value (saturating)
};

}  // namespace hwinterp::hls

// The step output types of rtl/step_encode.sv read back from the pins, per
// axis: each type's waveform turned into the steps it stands for, and
// checked against the step/dir timing set the step stage was given.
// Independent of the encoder's implementation: it sees out_a, out_b, each
// axis's type and the settings.
//
//   step/dir    StepdirMonitor on (a, b) (tb/monitor/stepdir_monitor.h);
//   up/down     a pulse on a is a positive step, on b a negative: a | b is
//               checked as a step line (step_len, step_space), and
//               "updown_both" (a and b high together), "updown_turn" (a
//               pulse of the other direction sooner than dir_hold +
//               dir_setup after the last one fell);
//   quadrature  each change of (a, b) one Gray step, 00 10 11 01 forward:
//               "quad_state" (both changed), "quad_dwell" (a state held
//               fewer than step_len + step_space clocks; the first change
//               after reset is not measured).
// Events: steps are reported one clock after the step stage's rising step,
// on every type (a quadrature state changes one clock after it), so the
// axes of one clock stay together whatever their types.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tb/base/case_result.h"
#include "tb/base/stepdir_timing.h"
#include "tb/monitor/stepdir_monitor.h"

namespace hwinterp::tb {

// STEP_TYPE's values (rtl/step_encode.sv).
enum class StepType : uint8_t { kStepDir = 0, kUpDown = 1, kQuadrature = 2 };

// "stepdir", "updown", "quad"; false for another name.
bool parse_step_type(const std::string& name, StepType& t);
const char* step_type_name(StepType t);

class StepOutputMonitors {
 public:
  explicit StepOutputMonitors(const std::vector<StepType>& types);

  // The pins after clock edge `cycle` (bit i: axis i); returns the axes
  // that stepped (see above for when), with their directions (1: negative)
  // in `dir`.
  uint32_t observe(uint64_t cycle, uint32_t a, uint32_t b, const StepdirTiming& t, uint32_t& dir,
                   std::vector<TimingViolation>& kept, uint64_t& count) {
    if (a == a_ && b == b_ && pending_ == 0 && !after_reset_) return 0;
    return observe_change(cycle, a, b, t, dir, kept, count);
  }
  // rst_ni was low at edge `cycle`: every axis idle (quadrature state 00).
  void reset(uint64_t cycle);

 private:
  struct Axis {
    StepType type;
    StepdirMonitor line;  // step/dir: (a, b); up/down: (a | b, 0)
    uint64_t fall = 0;    // up/down: the last pulse's fall
    bool have_fall = false, last_neg = false, have_last = false;
    uint64_t change = 0;  // quadrature: the last state change
    bool have_change = false;
  };
  uint32_t observe_change(uint64_t cycle, uint32_t a, uint32_t b, const StepdirTiming& t,
                          uint32_t& dir, std::vector<TimingViolation>& kept, uint64_t& count);

  std::vector<Axis> axes_;
  uint32_t a_ = 0, b_ = 0;
  uint32_t pending_ = 0, pending_dir_ = 0;  // the last clock's rising steps (step/dir, up/down)
  bool after_reset_ = false;
};

}  // namespace hwinterp::tb

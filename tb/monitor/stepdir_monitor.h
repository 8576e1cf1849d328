// Step/dir timing monitor for one axis: checks the waveform a core drives
// against the hostmot2 timing set it was given. Independent of any core's
// implementation: it only sees step_o, dir_o and the settings.
#pragma once

#include <cstdint>
#include <vector>

#include "tb/base/case_result.h"
#include "tb/base/stepdir_timing.h"

namespace hwinterp::tb {

class StepdirMonitor {
 public:
  explicit StepdirMonitor(int axis) : axis_(axis) {}

  // The axis outputs after clock edge `cycle`, and the settings sampled at that
  // edge. A phase keeps the setting of the edge it starts on
  // (rtl/stepdir_axis.sv): a pulse the step_len of its rise, the space and
  // the hold those of the fall, the setup that of the turn of dir.
  // Inline for the clocks where nothing happens (most of them): no edge and
  // no reset to take the settings from leaves the monitor as it is.
  void observe(uint64_t cycle, bool step, bool dir, const StepdirTiming& timing,
               std::vector<TimingViolation>& kept, uint64_t& count) {
    if (step != step_ || dir != dir_ || after_reset_)
      observe_edge(cycle, step, dir, timing, kept, count);
  }

  // rst_ni was low at edge `cycle`: the outputs are idle, and the reset
  // counts as the end of a pulse and a change of dir (rtl/stepdir_axis.sv):
  // the next pulse must keep step_space and dir_setup from it, a turn of dir
  // dir_hold, with the settings of the first edge after the reset.
  void reset(uint64_t cycle);

  // The step_len the pulse now high started with (0 acts as 1); 0 when the
  // step is low.
  uint32_t high_len() const { return step_ ? (len_ == 0 ? 1 : len_) : 0; }

 private:
  void observe_edge(uint64_t cycle, bool step, bool dir, const StepdirTiming& timing,
                    std::vector<TimingViolation>& kept, uint64_t& count);
  // A phase of `measured` clocks against its setting (0 acts as 1).
  void check(uint64_t cycle, const char* rule, uint64_t measured, uint32_t setting,
             std::vector<TimingViolation>& kept, uint64_t& count) const {
    const uint64_t required = setting == 0 ? 1 : setting;
    if (measured < required) violation(cycle, rule, measured, required, kept, count);
  }
  void violation(uint64_t cycle, const char* rule, uint64_t measured, uint64_t required,
                 std::vector<TimingViolation>& kept, uint64_t& count) const;

  int axis_;
  bool step_ = false, dir_ = false;
  // Cycle of the last edge; unset before the first reset (nothing to measure against).
  bool have_rise_ = false, have_fall_ = false, have_dir_change_ = false;
  uint64_t rise_ = 0, fall_ = 0, dir_change_ = 0;
  // The settings each running phase started with.
  uint32_t len_ = 1, space_ = 1, hold_ = 1, setup_ = 1;
  bool after_reset_ = false;  // the next edge is the first after a reset
};

// The monitors of every axis of a core, fed the core's step_o and dir_o words
// (bit i: axis i). A clock on which no axis's step or dir changed, and that
// is not the first after a reset, leaves every monitor as it is: it costs
// one inline compare of the two words, not a call per axis.
class StepdirMonitors {
 public:
  explicit StepdirMonitors(int axes);

  // The outputs after clock edge `cycle` (StepdirMonitor::observe per axis).
  void observe(uint64_t cycle, uint32_t step, uint32_t dir, const StepdirTiming& timing,
               std::vector<TimingViolation>& kept, uint64_t& count) {
    if (((step ^ step_) | (dir ^ dir_)) != 0 || after_reset_)
      observe_edges(cycle, step, dir, timing, kept, count);
  }
  // rst_ni was low at edge `cycle` (StepdirMonitor::reset per axis).
  void reset(uint64_t cycle);
  // The longest step_len a pulse now high started with (0 acts as 1); 0 when
  // no step is high.
  uint32_t high_len() const;

 private:
  void observe_edges(uint64_t cycle, uint32_t step, uint32_t dir, const StepdirTiming& timing,
                     std::vector<TimingViolation>& kept, uint64_t& count);

  std::vector<StepdirMonitor> axes_;
  uint32_t step_ = 0, dir_ = 0;  // the words the monitors last saw
  bool after_reset_ = false;     // a reset came after them
};

}  // namespace hwinterp::tb

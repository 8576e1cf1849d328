#include "tb/monitor/stepdir_monitor.h"

#include <algorithm>

namespace hwinterp::tb {

void StepdirMonitor::reset(uint64_t cycle) {
  step_ = dir_ = false;
  have_rise_ = false;
  have_fall_ = have_dir_change_ = true;
  fall_ = dir_change_ = cycle;
  after_reset_ = true;
}

void StepdirMonitor::violation(uint64_t cycle, const char* rule, uint64_t measured,
                               uint64_t required, std::vector<TimingViolation>& kept,
                               uint64_t& count) const {
  record_capped(kept, count, {cycle, axis_, rule, measured, required});
}

void StepdirMonitor::observe_edge(uint64_t cycle, bool step, bool dir, const StepdirTiming& t,
                                  std::vector<TimingViolation>& kept, uint64_t& count) {
  const bool rise = step && !step_, fall = !step && step_, dir_change = dir != dir_;
  if (after_reset_) {
    after_reset_ = false;
    space_ = t.step_space;
    hold_ = t.dir_hold;
    setup_ = t.dir_setup;
  }
  // A value seen after edge c was first driven at edge c: a pulse that rose
  // at r and fell at f was high for f - r cycles.
  if (rise) {
    if (have_fall_) check(cycle, "step_space", cycle - fall_, space_, kept, count);
    // Setup counts from the cycle dir took its value; a change on the rise
    // edge itself gives 0.
    if (dir_change)
      check(cycle, "dir_setup", 0, t.dir_setup, kept, count);
    else if (have_dir_change_)
      check(cycle, "dir_setup", cycle - dir_change_, setup_, kept, count);
  }
  if (fall && have_rise_) check(cycle, "step_len", cycle - rise_, len_, kept, count);
  if (dir_change) {
    if (step_ || step)
      check(cycle, "dir_hold", 0, t.dir_hold, kept, count);  // changed while high
    else if (have_fall_)
      check(cycle, "dir_hold", cycle - fall_, hold_, kept, count);
  }
  if (rise) rise_ = cycle, have_rise_ = true, len_ = t.step_len;
  if (fall) fall_ = cycle, have_fall_ = true, space_ = t.step_space, hold_ = t.dir_hold;
  if (dir_change) dir_change_ = cycle, have_dir_change_ = true, setup_ = t.dir_setup;
  step_ = step;
  dir_ = dir;
}

StepdirMonitors::StepdirMonitors(int axes) {
  axes_.reserve(static_cast<size_t>(axes));
  for (int i = 0; i < axes; ++i) axes_.emplace_back(i);
}

void StepdirMonitors::observe_edges(uint64_t cycle, uint32_t step, uint32_t dir,
                                    const StepdirTiming& timing, std::vector<TimingViolation>& kept,
                                    uint64_t& count) {
  for (size_t i = 0; i < axes_.size(); ++i)
    axes_[i].observe(cycle, (step >> i) & 1, (dir >> i) & 1, timing, kept, count);
  step_ = step;
  dir_ = dir;
  after_reset_ = false;
}

void StepdirMonitors::reset(uint64_t cycle) {
  for (auto& m : axes_) m.reset(cycle);
  step_ = dir_ = 0;
  after_reset_ = true;
}

uint32_t StepdirMonitors::high_len() const {
  uint32_t len = 0;
  for (const auto& m : axes_) len = std::max(len, m.high_len());
  return len;
}

}  // namespace hwinterp::tb

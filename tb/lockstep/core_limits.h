// What the testbench knows of one core variant without being a template over
// it: its name, the widths of the shared port contract, its timing defaults
// and every RTL parameter (from the generated <variant>_cfg.h, i.e.
// cmake/cores.cmake). Stimulus is validated against it.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tb/monitor/stepdir_monitor.h"

namespace hwinterp::tb {

// The testbench's per-axis arrays hold this many axes.
inline constexpr int kMaxAxes = 8;

struct CoreLimits {
  std::string core, variant;
  int axes = 0, pos_w = 0, tim_w = 0, feed_w = 0;  // the shared contract's widths
  StepdirTiming default_timing;
  std::vector<std::pair<std::string, int>> params;  // every RTL parameter, cores.cmake order

  // An RTL parameter by name; a core's adapter asks for its own widths.
  int param(const std::string& name) const {
    for (const auto& [k, v] : params)
      if (k == name) return v;
    throw std::logic_error(variant + " has no parameter " + name);
  }
  uint64_t full_feed() const { return uint64_t{1} << feed_w; }
  uint64_t tim_max() const { return (uint64_t{1} << tim_w) - 1; }
  int64_t pos_max() const { return pos_w >= 64 ? INT64_MAX : (int64_t{1} << (pos_w - 1)) - 1; }
  int64_t pos_min() const { return -pos_max() - 1; }
};

template <class Cfg>
CoreLimits limits_of() {
  static_assert(Cfg::AXES >= 1 && Cfg::AXES <= kMaxAxes,
                "raise kMaxAxes in tb/lockstep/core_limits.h");
  CoreLimits l;
  l.core = Cfg::kCore;
  l.variant = Cfg::kVariant;
  l.axes = Cfg::AXES;
  l.pos_w = Cfg::POS_W;
  l.tim_w = Cfg::TIM_W;
  l.feed_w = Cfg::FEED_W;
  l.default_timing = {Cfg::DEFAULT_STEP_LEN, Cfg::DEFAULT_STEP_SPACE, Cfg::DEFAULT_DIR_SETUP,
                      Cfg::DEFAULT_DIR_HOLD};
  for (int i = 0; i < Cfg::kParamCount; ++i)
    l.params.emplace_back(Cfg::kParamNames[i], Cfg::kParamValues[i]);
  return l;
}

}  // namespace hwinterp::tb

// The documented bound on a core's normal path error (in steps), as every
// model states it and the scoreboard checks it.
#pragma once

namespace hwinterp::models {

// `strict` tells whether the bound is strict (<) or attained (<=).
struct ErrorBound {
  double value;
  bool strict;
};

// True when `error` satisfies `bound` (with 1e-12 slack for rounding).
inline bool within_bound(double error, ErrorBound bound) {
  return bound.strict ? error < bound.value + 1e-12 : error <= bound.value + 1e-12;
}

}  // namespace hwinterp::models

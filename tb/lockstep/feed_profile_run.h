// Runs a stream of moves through the feed profile (hls/feed_profile.h) with
// an engine behind it that takes an operation on every carry of feed_accum's
// phase (no stalls), clock by clock: what `hwinterp profile` reports and the
// Ruckig comparison (tests/profile/) reads.
#pragma once

#include <cstdint>
#include <vector>

#include "models/feed_profile_model.h"
#include "tb/lockstep/profile_feed.h"

namespace hwinterp::tb {

// The block's build as the harness instantiates it.
models::ProfileBuild feed_profile_build(double clock_hz);

struct ProfileMove {
  uint64_t ops = 0;         // engine operations (>= 1)
  double target_speed = 0;  // ops/s (rounded down to a level; 0: the limit)
  double end_speed = 0;     // ops/s when its last operation is taken
  double max_speed = 0;     // ops/s its cruise speed is capped at under the override (0: the limit)
};

struct ProfileRunResult {
  models::ProfileRegisters regs;
  std::vector<uint64_t> move_end_clock;  // the clock each move's last operation was taken
  std::vector<double> move_end_speed;    // the speed (ops/s) in force then
  uint64_t rest_clock = 0;               // the first clock at speed 0 after the last operation
  uint64_t ops = 0;                      // operations taken
  // Per tick: the speed (ops/s) in force; the highest |speed|, |accel|, |jerk|
  // seen from one tick to the next (ops/s, /s^2, /s^3).
  std::vector<double> tick_speed;
  double peak_speed = 0, peak_accel = 0, peak_jerk = 0;
  double tick_seconds = 0;
  double estimated_clocks = 0;  // the clocks estimated before the run
};

// Throws std::invalid_argument (naming the value) for bad limits or moves,
// and when the moves would take more than `max_clocks` (estimated before the
// run: models::profile_move_clocks); std::runtime_error when the run passes it.
// `override`: the feed override's steps (ovr_i, hls/feed_profile.h) in clock
// order; none: 100 %.
ProfileRunResult run_feed_profile(const models::PathLimits& limits, double clock_hz,
                                  const std::vector<ProfileMove>& moves, bool keep_trace,
                                  const std::vector<OverrideStep>& override = {},
                                  double max_clocks = 1e11);

}  // namespace hwinterp::tb

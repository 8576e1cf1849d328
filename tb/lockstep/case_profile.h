// A feed profile in front of any core for one case (Case::profile, issue 25):
// the block's two faces (tb/lockstep/profile_feed.h, built at the core's
// FEED_W) drive feed_i; the core and its checks are the bench's as always
// (HLS = RTL every clock, both against the reference model, exact end
// points). What the profile adds is checked here, at the case's end.
//
// Moves. Each command is one rest-to-rest move of exactly its engine
// operations (A::operations: the feed ticks it takes), offered to the
// profile once the core has taken the command (a core that waits for its
// command loses no distance) and the block is at rest (an exact stop,
// tb/lockstep/profile_feed.h). Its cruise level is the feed word in force
// when the command is offered, capped at one operation every timing round
// + 2 clocks (len + space + setup + hold of the slowest settings of the
// case, see timing_round()), so the step/dir stage never stalls the engine:
// the profile is open loop, and a stalled engine would fall behind it for
// good. At least level 1.
//
// Checks (CaseResult::scoreboard_errors):
//   - the profile's RTL and HLS faces agree on every clock;
//   - every move was taken and the engine did not strand (the bench's
//     budget and ProfileFeed::stranded());
//   - the step stream's kinematics (tb/monitor/kinematics.h, windows of a
//     whole number of ticks) within the block's limits: along the path's
//     operations the speed is at most the highest cruise level's and, per
//     tick, |dv| <= qL and |d2v| <= q. An axis of a core whose commands move
//     each axis a fixed fraction of the operations (A::kAxisFollowsPath:
//     lines) moves at most one step an operation, so its speed,
//     acceleration and jerk are checked against the path's limits; on any
//     other core (arcs, curves: the direction turns within a command) its
//     speed only. Tolerance: the estimator's for e = 2 steps (the step
//     count truncates the operations, which truncate the profile's
//     distance).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tb/base/case_result.h"
#include "tb/base/variant_spec.h"
#include "tb/lockstep/harness_profile.h"
#include "tb/lockstep/profile_feed.h"
#include "tb/monitor/kinematics.h"
#include "tb/stimulus/case.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb {

// The block's registers for a case's limits, and the limits they give, in
// operations per clock^k.
struct ProfileClockLimits {
  uint64_t q = 0;    // speed quantum, operations/clock * 2^SPD_W
  unsigned len = 1;  // L
  double level = 0;  // speed of one level: q L / 2^SPD_W
  double accel = 0;  // q L / 2^SPD_W per tick
  double jerk = 0;   // q / 2^SPD_W per tick^2
};

inline ProfileClockLimits profile_clock_limits(const CaseProfile& p) {
  ProfileClockLimits l;
  l.len = std::clamp(p.len, 1u, 1u << kProfileLenW);
  l.q = static_cast<uint64_t>(std::ldexp(p.level, kProfileSpdW) / l.len);
  if (l.q == 0 || l.q >= (uint64_t(1) << kProfileSpdW))
    throw std::invalid_argument("feed profile: a level of " + std::to_string(p.level) +
                                " operations/clock is outside the block's speed bits");
  const double tick = double(uint64_t(1) << kProfileTickW);
  const double q = std::ldexp(static_cast<double>(l.q), -kProfileSpdW);
  l.level = q * l.len;
  l.accel = l.level / tick;
  l.jerk = q / (tick * tick);
  return l;
}

template <class A>
class CaseProfileRun {
 public:
  CaseProfileRun(const Case<A>& c, const VariantSpec& spec)
      : spec_(spec), limits_(profile_clock_limits(*c.profile)) {
    using Kind = typename Item<A>::Kind;
    // The slowest timing of the case caps every move.
    uint64_t round = timing_round(c.settings.timing);
    for (const auto& it : c.items)
      if (it.kind == Kind::kSettings) round = std::max(round, timing_round(it.settings.timing));
    const double cap = 1.0 / static_cast<double>(round + 2);
    const uint64_t max_level = (uint64_t(1) << kProfileLvlW) - 1;
    uint64_t feed = c.settings.feed;
    const double tick = double(uint64_t(1) << kProfileTickW);
    for (const auto& it : c.items) {
      if (it.kind == Kind::kSettings) feed = it.settings.feed;
      if (it.kind != Kind::kCommand) continue;
      const uint64_t ops = A::operations(it.cmd, spec);
      const double speed =
          std::min({static_cast<double>(feed) / static_cast<double>(spec.full_feed()), 1.0, cap});
      const uint64_t level = std::clamp<uint64_t>(
          static_cast<uint64_t>(std::floor(speed / limits_.level)), 1, max_level);
      moves_.push_back({ops, static_cast<uint32_t>(level), 0});
      top_level_ = std::max(top_level_, level);
      // Rest to rest: cruise, one ramp up and one down of at most the
      // level's speed over A plus the moving sum (L ticks each), and the
      // ticks a move may wait for its boundary and settle.
      const double v = static_cast<double>(level) * limits_.level;
      budget_ += static_cast<uint64_t>(static_cast<double>(ops) / v +
                                       2 * (v / limits_.accel + tick * limits_.len) + 8 * tick);
    }
    feed_ = std::make_unique<ProfileFeed>(
        limits_.q, limits_.len,
        [this](ProfileWords& w) {
          // Asked only when source_ready() below says so.
          if (given_ >= moves_.size()) return false;
          w = moves_[given_++];
          return true;
        },
        spec.feed_w);
    // A move is offered once the core has taken its command; a command of
    // no operation needs none.
    feed_->source_ready([this] {
      while (given_ < moves_.size() && moves_[given_].ops == 0 && given_ < released_) ++given_;
      return given_ >= moves_.size() || given_ < released_;
    });
    // Windows of whole ticks, long enough that the estimator's tolerance
    // (e = 2) is at most a quarter of the acceleration and jerk limits.
    const double w_accel = std::sqrt(4 * 2 / (0.25 * limits_.accel));
    const double w_jerk = std::cbrt(8 * 2 / (0.25 * limits_.jerk));
    window_ = static_cast<uint64_t>(std::ceil(std::max(w_accel, w_jerk) / tick)) *
              (uint64_t(1) << kProfileTickW);
    kin_ = std::make_unique<KinematicsMonitor>(spec.axes, std::vector<double>(spec.axes, 1.0),
                                               window_);
  }

  ProfileFeed& feed() { return *feed_; }
  // The core took the case's next command: its move may be offered.
  void command_taken() { ++released_; }
  // Clocks the moves may take, with margin (added to the case's budget).
  uint64_t budget() const { return 2 * budget_ + 4 * window_; }
  // Pulses that rose on `clock` of the case (bit i: axis i; dir bit: -1).
  void pulses(uint64_t clock, uint32_t rising, uint32_t dir) { kin_->pulses(clock, rising, dir); }

  void finish(uint64_t clock, CaseResult& r) {
    auto error = [&](const std::string& e) {
      record_capped(r.scoreboard_errors, r.scoreboard_error_count, "feed profile: " + e);
    };
    if (feed_->failed()) error(feed_->failure());
    if (feed_->moves_taken() != static_cast<uint64_t>(std::count_if(moves_.begin(), moves_.end(),
                                                                    [](auto& m) { return m.ops; })))
      error("took " + std::to_string(feed_->moves_taken()) + " of " +
            std::to_string(moves_.size()) + " moves");
    kin_->finish(clock);
    const KinematicsMonitor::Peaks tol = kin_->tolerance();
    const double top = static_cast<double>(top_level_) * limits_.level;
    for (int i = 0; i < spec_.axes; ++i) {
      const KinematicsMonitor::Peaks& p = kin_->axis(i);
      auto check = [&](const char* what, const KinematicsMonitor::Peak& seen, double limit,
                       double t) {
        if (seen.value <= limit + 2 * t) return;
        std::ostringstream os;
        os << "axis " << i << " " << what << " " << seen.value << " steps/clock^k in the window "
           << "ending at case clock " << seen.clock << ", above the limit " << limit
           << " + tolerance " << 2 * t << " (windows of " << window_ << " clocks)";
        error(os.str());
      };
      check("speed", p.speed, top, tol.speed.value);
      if (A::kAxisFollowsPath) {
        check("acceleration", p.accel, limits_.accel, tol.accel.value);
        check("jerk", p.jerk, limits_.jerk, tol.jerk.value);
      }
    }
    r.core_check("profile_axis_speed_steps_per_clock", "profile_windows", top + 2 * tol.speed.value)
        .max = max_axis(&KinematicsMonitor::Peaks::speed);
    r.core_check("profile_axis_accel_steps_per_clock2", "profile_windows",
                 A::kAxisFollowsPath ? limits_.accel + 2 * tol.accel.value : -1)
        .max = max_axis(&KinematicsMonitor::Peaks::accel);
    r.core_check("profile_axis_jerk_steps_per_clock3", "profile_windows",
                 A::kAxisFollowsPath ? limits_.jerk + 2 * tol.jerk.value : -1)
        .max = max_axis(&KinematicsMonitor::Peaks::jerk);
    for (auto& cc : r.core_checks)
      if (cc.count_name == "profile_windows") cc.count = kin_->windows();
  }

 private:
  double max_axis(KinematicsMonitor::Peak KinematicsMonitor::Peaks::*which) const {
    double m = 0;
    for (int i = 0; i < spec_.axes; ++i) m = std::max(m, (kin_->axis(i).*which).value);
    return m;
  }

  VariantSpec spec_;
  ProfileClockLimits limits_;
  std::vector<ProfileWords> moves_;
  size_t given_ = 0;
  uint64_t released_ = 0;
  uint64_t top_level_ = 1;
  uint64_t budget_ = 0;
  uint64_t window_ = 1;
  std::unique_ptr<ProfileFeed> feed_;
  std::unique_ptr<KinematicsMonitor> kin_;
};

}  // namespace hwinterp::tb

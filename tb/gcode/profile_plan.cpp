#include "tb/gcode/profile_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "tb/base/args.h"
#include "tb/base/text_table.h"

namespace hwinterp::gcode {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kAccelShare = 0.8;  // of the smallest axis limit; the rest for arcs

using Steps = std::array<double, models::kMotionMaxAxes>;

// The cruise level at 100 % (the block's min(target, max)).
uint32_t cruise(const ProfileCommand& p) { return std::min(p.target, p.max); }

// Steps per engine operation along a plane tangent t (a PPC operation steps x
// or y: |s_x| + |s_y| = 1).
void plane_rate(Steps& s, const std::array<int, 2>& ax, double tx, double ty) {
  const double n = std::abs(tx) + std::abs(ty);
  if (n == 0) return;
  s[static_cast<size_t>(ax[0])] = tx / n;
  s[static_cast<size_t>(ax[1])] = ty / n;
}

}  // namespace

uint32_t motion_moved_axes(const models::MotionCommand& c, int axes) {
  uint32_t m = 0;
  for (int i = 0; i < axes; ++i)
    if (c.delta[static_cast<size_t>(i)] != 0) m |= 1u << i;
  if (c.kind == models::MotionKind::kArc)
    for (int a : models::motion_plane_axes(c.plane)) m |= 1u << a;
  return m;
}

ProfilePlanner::ProfilePlanner(const Machine& machine, int axes, const models::ProfileBuild& build,
                               size_t window, int feed_w, uint32_t moved)
    : machine_(machine),
      axes_(axes),
      build_(build),
      window_(std::max<size_t>(window, 1)),
      feed_w_(feed_w) {
  double a = kInf, j = kInf;
  int a_axis = 0, j_axis = 0;  // the axes whose limits (in steps) set a and j
  for (int i = 0; i < axes_; ++i) {
    if (!machine_.has_axis[static_cast<size_t>(i)]) continue;
    const AxisLimits& l = machine_.limits[static_cast<size_t>(i)];
    const double spu = static_cast<double>(machine_.steps_per_unit[static_cast<size_t>(i)]);
    const std::string name(1, kAxisNames[i]);
    if (!std::isfinite(l.accel))
      throw cli::UsageError("--machine: the feed profile needs max_accel for axis " + name);
    if (machine_.profile == ProfileKind::kScurve && !std::isfinite(l.jerk))
      throw cli::UsageError("--machine: the S-curve profile needs max_jerk for axis " + name);
    if (!(moved >> i & 1)) continue;
    if (l.accel * spu < a) a = l.accel * spu, a_axis = i;
    if (l.jerk * spu < j) j = l.jerk * spu, j_axis = i;
  }
  if (!std::isfinite(a)) a = j = 1;  // nothing moves: any registers do
  accel_ = kAccelShare * a;
  jerk_ = machine_.profile == ProfileKind::kScurve ? kAccelShare * j : 1e30;
  tick_s_ = std::ldexp(1.0, build_.tick_w) / build_.clock_hz;
  try {
    regs_ = models::profile_registers({build_.clock_hz, accel_, jerk_}, build_);
  } catch (const std::invalid_argument&) {
    // The smallest speed step the block holds (2^-SPD_W op a clock) needs
    // an acceleration and a jerk of at least one step a tick: say which
    // limit of which axis is below, in the file's units.
    const double f = build_.clock_hz, tick = std::ldexp(1.0, build_.tick_w);
    const double quantum = std::ldexp(1.0, -build_.spd_w);
    const double a_min = quantum * f * f / tick / kAccelShare;                   // steps/s^2
    const double j_min = 2 * quantum * f * f * f / (tick * tick) / kAccelShare;  // steps/s^3
    const bool accel_low = accel_ * tick / (f * f) < quantum;
    const int i = accel_low ? a_axis : j_axis;
    const double spu = static_cast<double>(machine_.steps_per_unit[static_cast<size_t>(i)]);
    const AxisLimits& l = machine_.limits[static_cast<size_t>(i)];
    std::ostringstream os;
    os << "--machine: " << (accel_low ? "max_accel." : "max_jerk.") << kAxisNames[i] << " = "
       << (accel_low ? l.accel : l.jerk) << " is below the feed profile's resolution at clock_hz "
       << f << ": at least " << (accel_low ? a_min : j_min) / spu
       << (accel_low ? " units/s^2" : " units/s^3") << " (" << spu
       << " steps a unit; the profile's speed step is 2^-" << build_.spd_w << " step a clock)";
    throw cli::UsageError(os.str());
  }
  if (machine_.profile == ProfileKind::kScurve) jerk_ = regs_.jerk;
  accel_ = regs_.accel;
}

uint32_t ProfilePlanner::brake_level(uint64_t ops, uint32_t next_end) const {
  // The block's cost in level-ticks (models::profile_entry_cost).
  const double budget = static_cast<double>(ops) / (regs_.level_speed * tick_s_);
  const auto cost = [&](double e) { return models::profile_entry_cost(e, next_end, regs_.len); };
  uint32_t lo = 0, hi = regs_.max_level;
  while (lo < hi) {
    const uint32_t mid = lo + (hi - lo + 1) / 2;
    if (cost(mid) <= budget)
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}

ProfilePlanner::AxisCap ProfilePlanner::axis_cap(const models::MotionCommand& c) const {
  const double n = static_cast<double>(models::motion_operations(c));
  const double f = build_.clock_hz;
  // The step/dir stage must never stall the engine: the profile's distance
  // runs on whether or not the engine keeps up. An axis steps at most once
  // per step_len + step_space clocks, and a feed tick can come a clock early.
  const StepTiming& tm = machine_.timing;
  const double pulse_clocks = static_cast<double>(std::max<int64_t>(tm.step_len, 1) +
                                                  std::max<int64_t>(tm.step_space, 1) + 1);
  // An axis with s steps per operation on average steps after floor(1/s)
  // operations at the least (a DDA's or a PPC's steps are spread, not evenly
  // spaced), so the stall cap counts that gap, not the average. An arc's
  // plane axes step up to once an operation.
  const auto plane = models::motion_plane_axes(c.plane);
  AxisCap cap{f, -1, 0};
  for (int i = 0; i < axes_; ++i) {
    const bool in_plane = c.kind != models::MotionKind::kLine && (i == plane[0] || i == plane[1]);
    const double steps_per_op =
        in_plane ? 1.0 : std::abs(static_cast<double>(c.delta[static_cast<size_t>(i)])) / n;
    if (steps_per_op <= 0) continue;
    const AxisLimits& l = machine_.limits[static_cast<size_t>(i)];
    const double spu = static_cast<double>(machine_.steps_per_unit[static_cast<size_t>(i)]);
    if (std::isfinite(l.velocity) && l.velocity * spu / steps_per_op < cap.v)
      cap = {l.velocity * spu / steps_per_op, i, steps_per_op};
    const double stall = f * std::floor(1 / steps_per_op) / pulse_clocks;
    if (stall < cap.v) cap = {stall, -1, 0};
  }
  return cap;
}

void ProfilePlanner::check(const models::MotionCommand& c) const { check_cap(axis_cap(c)); }

void ProfilePlanner::check_cap(const AxisCap& cap) const {
  // The profile's slowest cruise is one level: an axis limit below it cannot
  // be kept (the move would run at a level anyway).
  if (cap.axis < 0 || models::profile_level(regs_, cap.v) > 0) return;
  const size_t i = static_cast<size_t>(cap.axis);
  const double spu = static_cast<double>(machine_.steps_per_unit[i]);
  throw cli::UsageError(
      "--machine: max_velocity." + std::string(1, kAxisNames[cap.axis]) + " = " +
      fmt("%g", machine_.limits[i].velocity) +
      " is below the feed profile's slowest speed at clock_hz " + fmt("%g", build_.clock_hz) +
      ": one level of the profile is " + fmt("%.3g", regs_.level_speed * cap.steps_per_op / spu) +
      " units/s along it (" + fmt("%.3g", regs_.level_speed) +
      " operations/s at these max_accel and max_jerk): raise max_velocity to it, or lower "
      "max_accel or max_jerk, or raise clock_hz");
}

double ProfilePlanner::programmed_speed(const models::MotionCommand& c) const {
  const double f = build_.clock_hz;
  return c.feed == 0 ? f : std::min(f, static_cast<double>(c.feed) * f / std::ldexp(1.0, feed_w_));
}

double ProfilePlanner::speed_cap(const models::MotionCommand& c, const AxisCap& cap) const {
  double v = cap.v;
  if (c.kind == models::MotionKind::kLine) return v;
  // An arc's centripetal acceleration (and, with an S-curve, its jerk) within
  // the share of the limits the path leaves it.
  const double r = std::hypot(static_cast<double>(c.center[0]), static_cast<double>(c.center[1]));
  if (r > 0) {
    v = std::min(v, std::sqrt((1 - kAccelShare) * accel_ / kAccelShare * r));
    if (machine_.profile == ProfileKind::kScurve) {
      v = std::min(v, std::cbrt(0.5 * (1 - kAccelShare) * jerk_ / kAccelShare * r * r));
      v = std::min(v, 0.5 * (1 - kAccelShare) / kAccelShare * jerk_ * r / (3 * accel_));
    }
  }
  return v;
}

double ProfilePlanner::planned_speed(const models::MotionCommand& c) const {
  return std::min(speed_cap(c, axis_cap(c)), programmed_speed(c));
}

void ProfilePlanner::push(const models::MotionCommand& c, bool stop_before) {
  const AxisCap cap = axis_cap(c);
  check_cap(cap);
  Entry e;
  e.p.ops = models::motion_operations(c);
  const double n = static_cast<double>(e.p.ops);
  // v: the cap by the machine (without the programmed feed, for the override)
  const double v = speed_cap(c, cap);
  const double programmed = programmed_speed(c);
  if (c.kind == models::MotionKind::kLine) {
    for (int i = 0; i < axes_; ++i) {
      const double d = static_cast<double>(c.delta[static_cast<size_t>(i)]);
      e.s_start[static_cast<size_t>(i)] = e.s_end[static_cast<size_t>(i)] = d / n;
    }
  } else {
    const auto ax = models::motion_plane_axes(c.plane);
    const double cx = static_cast<double>(c.center[0]), cy = static_cast<double>(c.center[1]);
    const double rx = static_cast<double>(c.end[0]) - cx, ry = static_cast<double>(c.end[1]) - cy;
    // Tangents: the radius turned by +90 degrees (counter-clockwise) or -90.
    const double sgn = c.ccw ? 1 : -1;
    plane_rate(e.s_start, ax, sgn * cy, -sgn * cx);
    plane_rate(e.s_end, ax, -sgn * ry, sgn * rx);
    for (int i = 0; i < axes_; ++i) {
      const double d = static_cast<double>(c.delta[static_cast<size_t>(i)]);
      if (i != ax[0] && i != ax[1])
        e.s_start[static_cast<size_t>(i)] = e.s_end[static_cast<size_t>(i)] = d / n;
    }
  }
  e.p.target_speed = std::min(v, programmed);
  // min(target, max) = max(1, level(min(v, programmed))): the cruise level at 100 %
  e.p.target = std::max<uint32_t>(1, models::profile_level(regs_, programmed));
  e.p.max = std::max<uint32_t>(1, models::profile_level(regs_, v));
  // The junction from the command before into this one.
  if (!q_.empty()) {
    Entry& prev = q_.back();
    double vj = kInf;
    for (int i = 0; i < axes_; ++i) {
      const double jump =
          std::abs(prev.s_end[static_cast<size_t>(i)] - e.s_start[static_cast<size_t>(i)]);
      if (jump == 0) continue;
      const double a = machine_.limits[static_cast<size_t>(i)].accel *
                       static_cast<double>(machine_.steps_per_unit[static_cast<size_t>(i)]);
      vj = std::min(vj, a * tick_s_ / jump);
    }
    prev.max_end = stop_before
                       ? 0
                       : std::min<double>({vj == kInf ? 1e300 : models::profile_level(regs_, vj),
                                           static_cast<double>(cruise(prev.p)),
                                           static_cast<double>(cruise(e.p))});
  }
  q_.push_back(e);
  plan_back();
}

void ProfilePlanner::finish() {
  finished_ = true;
  plan_back();
}

void ProfilePlanner::plan_back() {
  if (q_.empty()) return;
  // The last known command ends at rest until what follows is known.
  uint32_t next_end = 0;
  q_.back().p.end = 0;
  for (size_t k = q_.size() - 1; k-- > 0;) {
    const Entry& next = q_[k + 1];
    next_end = next.p.end;
    const uint32_t by_brake = brake_level(next.p.ops, next_end);
    q_[k].p.end = static_cast<uint32_t>(std::min<double>(q_[k].max_end, by_brake));
  }
}

bool ProfilePlanner::pop(ProfileCommand& out) {
  if (q_.empty() || (!finished_ && q_.size() <= window_)) return false;
  out = q_.front().p;
  q_.pop_front();
  return true;
}

}  // namespace hwinterp::gcode

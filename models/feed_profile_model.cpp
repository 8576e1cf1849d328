#include "models/feed_profile_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hwinterp::models {
namespace {

void require_positive(double v, const char* name) {
  if (!(v > 0) || !std::isfinite(v)) {
    std::ostringstream os;
    os << name << " " << v << " must be positive";
    throw std::invalid_argument(os.str());
  }
}

// Time to go from rest to speed v (and distance covered) with accel and jerk limits.
double ramp_time(double v, double a, double j) {
  return v >= a * a / j ? v / a + a / j : 2 * std::sqrt(v / j);
}

}  // namespace

ProfileRegisters profile_registers(const PathLimits& limits, const ProfileBuild& build) {
  require_positive(limits.velocity, "velocity");
  require_positive(limits.accel, "acceleration");
  require_positive(limits.jerk, "jerk");
  require_positive(build.clock_hz, "clock_hz");
  const double f = build.clock_hz, tick = std::ldexp(1.0, build.tick_w);
  const double a_tick = limits.accel * tick / (f * f);            // ops/clock a tick
  const double j_tick = limits.jerk * tick * tick / (f * f * f);  // ops/clock a tick^2
  const double max_len = std::ldexp(1.0, build.len_w);
  ProfileRegisters r;
  r.len = static_cast<unsigned>(std::min(max_len, std::max(1.0, std::ceil(a_tick / j_tick))));
  const double q = std::min(j_tick, a_tick / r.len);
  r.q = static_cast<uint64_t>(std::floor(std::ldexp(q, build.spd_w)));
  if (r.q == 0) {
    std::ostringstream os;
    os << "jerk " << limits.jerk << " is below the profile's resolution at clock_hz " << f
       << " (speed quantum < 2^-" << build.spd_w << " op/clock)";
    throw std::invalid_argument(os.str());
  }
  const double qd = std::ldexp(static_cast<double>(r.q), -build.spd_w);  // ops/clock
  r.level_speed = qd * r.len * f;
  r.accel = qd * r.len * f * f / tick;
  r.jerk = qd * f * f * f / (tick * tick);
  const double by_velocity = std::floor(limits.velocity / r.level_speed);
  const double by_clock = std::floor(f / r.level_speed);  // one op a clock at most
  const double by_bits = std::ldexp(1.0, build.lvl_w) - 1;
  r.max_level = static_cast<uint32_t>(std::max(0.0, std::min({by_velocity, by_clock, by_bits})));
  return r;
}

uint32_t profile_level(const ProfileRegisters& regs, double speed) {
  if (!(speed > 0)) return 0;
  const double l = std::floor(speed / regs.level_speed);
  return static_cast<uint32_t>(std::min<double>(l, regs.max_level));
}

double profile_entry_cost(double e, double next_end, unsigned len) {
  const double n = next_end, l = len;
  const double brake = e > n ? (e + n - 1) * (e - n) / 2 : 0;
  return e * (1 + l) + brake + n * (l - 1);
}

unsigned override_word(double percent) {
  if (!(percent >= 0 && percent <= 200)) {
    std::ostringstream os;
    os << "feed override " << percent << " % is outside 0..200";
    throw std::invalid_argument(os.str());
  }
  return static_cast<unsigned>(std::lround(percent * 128 / 100));
}

double profile_move_clocks(const ProfileRegisters& regs, const ProfileBuild& build, uint32_t entry,
                           uint64_t ops, uint32_t cruise, uint32_t end) {
  const double tick = std::ldexp(1.0, build.tick_w);   // clocks
  const double q = regs.level_speed / build.clock_hz;  // operations a clock of one level
  const double n = static_cast<double>(ops), e = entry, x = end;
  double t_in = 0, d_in = 0, t_out = 0, d_out = 0;
  const auto change = [&](double from, double to, double& clocks, double& dist) {
    clocks = from == to ? 0 : (std::fabs(to - from) + regs.len) * tick;
    dist = (from + to) / 2 * q * clocks;
  };
  const auto fits = [&](double c) {
    change(e, c, t_in, d_in);
    change(c, x, t_out, d_out);
    return d_in + d_out <= n;
  };
  double lo = std::max(e, x), hi = std::max(lo, static_cast<double>(cruise));
  if (!fits(hi)) {  // the highest cruise level whose changes fit, by bisection
    while (hi - lo > 1) {
      const double mid = std::floor((lo + hi) / 2);
      (fits(mid) ? lo : hi) = mid;
    }
    hi = lo;
    fits(hi);
  }
  if (hi <= 0 || q <= 0) return n;  // no speed to go by: one operation a clock
  return t_in + t_out + std::max(0.0, n - d_in - d_out) / (hi * q);
}

double optimal_move_time(double distance, const PathLimits& limits) {
  const double v = limits.velocity, a = limits.accel, j = limits.jerk;
  if (!(distance > 0)) return 0;
  const double t_full = ramp_time(v, a, j);
  const double d_full = v * t_full;  // both ramps: the mean speed v/2 over 2 t
  if (distance >= d_full) return 2 * t_full + (distance - d_full) / v;
  // The peak speed p is not reached: distance = p * ramp_time(p).
  double p = (-a / j + std::sqrt(a * a / (j * j) + 4 * distance / a)) * a / 2;
  if (p < a * a / j) p = std::cbrt(distance * distance * j / 4);
  return 2 * ramp_time(p, a, j);
}

}  // namespace hwinterp::models

#include "models/fixed_ratio.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace hwinterp::models {

namespace {

// Merges two pulse trains whose k-th pulse (k = 1..n_i) falls at the integer
// time key_i(k) (monotone); equal keys make one diagonal move.
template <typename KeyX, typename KeyY, typename TimeOf>
void merge_trains(StepPath& path, int64_t nx, int64_t ny, KeyX key_x, KeyY key_y, TimeOf time_of) {
  const int ux = path.end[0] < path.start[0] ? -1 : 1;
  const int uy = path.end[1] < path.start[1] ? -1 : 1;
  LatticePoint at = path.start;
  int64_t kx = 1, ky = 1;
  while (kx <= nx || ky <= ny) {
    bool sx = false, sy = false;
    if (kx > nx) {
      sy = true;
    } else if (ky > ny) {
      sx = true;
    } else {
      const auto tx = key_x(kx), ty = key_y(ky);
      sx = tx <= ty;
      sy = ty <= tx;
    }
    StepMove m;
    m.time = sx ? time_of(0, kx) : time_of(1, ky);
    if (sx) {
      at[0] += ux;
      m.step[0] = ux;
      ++kx;
    }
    if (sy) {
      at[1] += uy;
      m.step[1] = uy;
      ++ky;
    }
    m.point = at;
    path.moves.push_back(std::move(m));
  }
}

std::string num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

StepPath fixed_ratio_line(const LatticePoint& start, const LatticePoint& end) {
  check_line_2d(start, end, "fixed_ratio_line");
  const int64_t ax = std::abs(end[0] - start[0]), ay = std::abs(end[1] - start[1]);
  const int64_t m = std::max(ax, ay);
  StepPath path;
  path.start = start;
  path.end = end;
  // t_xk = (2k - 1) / (2 v |dx|): compare (2k - 1)|dy| with (2j - 1)|dx|,
  // exact in integers (no rounding can reorder or split a diagonal move).
  merge_trains(
      path, ax, ay, [&](int64_t k) { return (2 * k - 1) * ay; },
      [&](int64_t k) { return (2 * k - 1) * ax; },
      [&](int axis, int64_t k) {
        // In ticks of the faster axis: its pulse period is 1/(v max(|dx|,|dy|)).
        return (2.0 * k - 1) * static_cast<double>(m) / (2.0 * (axis ? ay : ax));
      });
  path.ticks = static_cast<double>(m);
  path.operations = 1;
  return path;
}

double fixed_ratio_error_bound(const LatticePoint& start, const LatticePoint& end) {
  const double ax = std::abs(static_cast<double>(end[0] - start[0]));
  const double ay = std::abs(static_cast<double>(end[1] - start[1]));
  if (ax == 0 || ay == 0) return 0;
  return (ax + ay) / (2 * std::hypot(ax, ay));
}

DividerPlan fixed_ratio_divider_plan(const LatticePoint& start, const LatticePoint& end,
                                     double velocity, double clock_hz) {
  check_line_2d(start, end, "fixed_ratio_divider");
  if (!(std::isfinite(velocity) && velocity > 0))
    throw std::invalid_argument("fixed ratio: velocity factor " + num(velocity) + " must be > 0");
  if (!(std::isfinite(clock_hz) && clock_hz > 0))
    throw std::invalid_argument("fixed ratio: clock " + num(clock_hz) + " Hz must be > 0");
  DividerPlan plan;
  plan.velocity = velocity;
  plan.clock_hz = clock_hz;
  int64_t shortest = 0;
  for (size_t i = 0; i < 2; ++i) {
    const int64_t d = std::abs(end[i] - start[i]);
    if (d == 0) continue;
    const double f = velocity * static_cast<double>(d);
    // Nearest integer half period, ties away from zero (2.5 -> 3).
    const double h = std::round(clock_hz / (2 * f));
    if (h < 1)
      throw std::invalid_argument("fixed ratio: axis " + std::to_string(i) + " frequency " +
                                  num(f) + " Hz exceeds the " + num(clock_hz) + " Hz clock");
    plan.half_period[i] = static_cast<int64_t>(h);
    plan.frequency_hz[i] = clock_hz / (2 * h);
    plan.completion_clocks = std::max(plan.completion_clocks, 2 * d * plan.half_period[i]);
    shortest =
        shortest == 0 ? 2 * plan.half_period[i] : std::min(shortest, 2 * plan.half_period[i]);
  }
  plan.tick_clocks = static_cast<double>(shortest);
  return plan;
}

StepPath fixed_ratio_divider_line(const LatticePoint& start, const LatticePoint& end,
                                  double velocity, double clock_hz) {
  const DividerPlan plan = fixed_ratio_divider_plan(start, end, velocity, clock_hz);
  const int64_t ax = std::abs(end[0] - start[0]), ay = std::abs(end[1] - start[1]);
  StepPath path;
  path.start = start;
  path.end = end;
  const int64_t hx = plan.half_period[0], hy = plan.half_period[1];
  // The k-th step is on the mid-period edge: clock (2k - 1) H.
  merge_trains(
      path, ax, ay, [&](int64_t k) { return (2 * k - 1) * hx; },
      [&](int64_t k) { return (2 * k - 1) * hy; },
      [&](int axis, int64_t k) { return static_cast<double>((2 * k - 1) * (axis ? hy : hx)); });
  path.ticks = static_cast<double>(plan.completion_clocks);
  path.operations = 1;
  return path;
}

double fixed_ratio_divider_bound(const LatticePoint& start, const LatticePoint& end,
                                 double velocity, double clock_hz) {
  const DividerPlan plan = fixed_ratio_divider_plan(start, end, velocity, clock_hz);
  const double ax = std::abs(static_cast<double>(end[0] - start[0]));
  const double ay = std::abs(static_cast<double>(end[1] - start[1]));
  if (ax == 0 || ay == 0) return 0;
  const double hx = static_cast<double>(plan.half_period[0]);
  const double hy = static_cast<double>(plan.half_period[1]);
  const double t1 = std::min((2 * ax - 1) * hx, (2 * ay - 1) * hy);
  const double drift = std::abs(ay / (2 * hx) - ax / (2 * hy));
  return ((ax + ay) / 2 + t1 * drift) / std::hypot(ax, ay);
}

}  // namespace hwinterp::models

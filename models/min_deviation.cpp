#include "models/min_deviation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace hwinterp::models {

namespace {

// The octant set-up both methods share: which axis is major, and the step
// directions. octant_walk() steps the major axis every tick and asks the
// method's decision (which keeps its own running state) whether the minor
// axis steps too.
struct Octant {
  int major = 0;               // axis index of the longer delta (x on a tie)
  int64_t big = 0, small = 0;  // |delta| of the major and minor axis
  int u[2] = {1, 1};           // step direction per axis
};

Octant octant_of(const LatticePoint& start, const LatticePoint& end) {
  Octant o;
  const int64_t ax = std::abs(end[0] - start[0]), ay = std::abs(end[1] - start[1]);
  o.major = ay > ax ? 1 : 0;
  o.big = std::max(ax, ay);
  o.small = std::min(ax, ay);
  o.u[0] = end[0] < start[0] ? -1 : 1;
  o.u[1] = end[1] < start[1] ? -1 : 1;
  return o;
}

template <typename Decide>
StepPath octant_walk(const LatticePoint& start, const LatticePoint& end, Decide diagonal) {
  const Octant o = octant_of(start, end);
  StepPath path;
  path.start = start;
  path.end = end;
  LatticePoint at = start;
  const int minor = 1 - o.major;
  for (int64_t k = 1; k <= o.big; ++k) {
    StepMove m;
    m.time = static_cast<double>(k);
    m.step[o.major] = o.u[o.major];
    at[o.major] += o.u[o.major];
    if (diagonal(o)) {
      m.step[minor] = o.u[minor];
      at[minor] += o.u[minor];
    }
    m.point = at;
    path.moves.push_back(std::move(m));
  }
  path.ticks = static_cast<double>(o.big);
  path.operations = static_cast<uint64_t>(o.big);
  return path;
}

}  // namespace

StepPath min_deviation_line(const LatticePoint& start, const LatticePoint& end) {
  check_line_2d(start, end, "min_deviation_line");
  int64_t f = 0;  // F = minor_steps * big - major_steps * small
  return octant_walk(start, end, [&f](const Octant& o) {
    const int64_t f_axis = f - o.small;          // major step only
    const int64_t f_diag = f - o.small + o.big;  // major and minor step
    const bool diag = std::abs(f_diag) <= std::abs(f_axis);
    f = diag ? f_diag : f_axis;
    return diag;
  });
}

StepPath bresenham_line(const LatticePoint& start, const LatticePoint& end) {
  check_line_2d(start, end, "bresenham_line");
  bool first = true;
  int64_t d = 0;
  return octant_walk(start, end, [&](const Octant& o) {
    if (first) {
      d = 2 * o.small - o.big;
      first = false;
    }
    const bool diag = d > 0;
    d += diag ? 2 * (o.small - o.big) : 2 * o.small;
    return diag;
  });
}

double min_deviation_error_bound(const LatticePoint& start, const LatticePoint& end) {
  const double ax = std::abs(static_cast<double>(end[0] - start[0]));
  const double ay = std::abs(static_cast<double>(end[1] - start[1]));
  if (ax == 0 || ay == 0) return 0;
  return std::max(ax, ay) / (2 * std::hypot(ax, ay));
}

}  // namespace hwinterp::models

#include "models/ppc.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace hwinterp::models {

namespace {
int sign_of(int64_t v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
}  // namespace

StepPath ppc_line(const LatticePoint& start, const LatticePoint& end, PpcLineRule rule) {
  check_line_2d(start, end, "ppc_line");
  const int64_t dx = end[0] - start[0], dy = end[1] - start[1];
  const int64_t ax = std::abs(dx), ay = std::abs(dy);
  // The textbook core has no zero direction: a zero delta steps "+".
  const int ux = dx < 0 ? -1 : 1, uy = dy < 0 ? -1 : 1;
  StepPath path;
  path.start = start;
  path.end = end;
  LatticePoint at = start;
  int64_t x = 0, y = 0, f = 0;  // counts along the line's own quadrant, F = y ax - x ay
  const int64_t total = ax + ay;
  for (int64_t op = 1; op <= total; ++op) {
    bool step_x = f >= 0;
    // The bare rule steps x whenever F >= 0, which on a vertical line (F = 0
    // forever) is every step. Guarded: an axis with no steps left never steps;
    // for dx != 0 this never overrides the bare rule (F < 0 once x == |dx|).
    if (rule == PpcLineRule::kGuarded) step_x = (step_x && x < ax) || y == ay;
    StepMove m;
    m.time = static_cast<double>(op);
    if (step_x) {
      ++x;
      f -= ay;
      m.step = {ux, 0};
      at[0] += ux;
    } else {
      ++y;
      f += ax;
      m.step = {0, uy};
      at[1] += uy;
    }
    m.point = at;
    path.moves.push_back(std::move(m));
  }
  path.ticks = static_cast<double>(total);
  path.operations = static_cast<uint64_t>(total);
  return path;
}

double ppc_line_error_bound(const LatticePoint& start, const LatticePoint& end) {
  const double dx = static_cast<double>(end[0] - start[0]);
  const double dy = static_cast<double>(end[1] - start[1]);
  const double len = std::hypot(dx, dy);
  if (len == 0 || dx == 0 || dy == 0) return 0;
  return std::max(std::abs(dx), std::abs(dy)) / len;
}

double radial_error(const LatticePoint& p, const LatticePoint& center, double radius) {
  const double x = static_cast<double>(p[0] - center[0]);
  const double y = static_cast<double>(p[1] - center[1]);
  return std::abs(std::hypot(x, y) - radius);
}

double ppc_arc_radial_error(const StepPath& arc, const LatticePoint& center) {
  const double r = std::hypot(static_cast<double>(arc.start[0] - center[0]),
                              static_cast<double>(arc.start[1] - center[1]));
  double worst = 0;
  for (const auto& p : arc.visited()) worst = std::max(worst, radial_error(p, center, r));
  return worst;
}

StepPath ppc_arc(const LatticePoint& center, const LatticePoint& start, const LatticePoint& end,
                 bool ccw) {
  check_line_2d(center, start, "ppc_arc");
  check_line_2d(center, end, "ppc_arc");
  const int64_t sx0 = start[0] - center[0], sy0 = start[1] - center[1];
  const int64_t ex0 = end[0] - center[0], ey0 = end[1] - center[1];
  const int64_t r2 = sx0 * sx0 + sy0 * sy0;
  // R = 1: the first inward step from an axis point lands on the centre,
  // where no quadrant (and no direction) is defined.
  if (r2 < 2)
    throw std::invalid_argument("ppc_arc: radius^2 " + std::to_string(r2) +
                                " is below 2 (the path would pass the centre)");
  if (ex0 * ex0 + ey0 * ey0 != r2)
    throw std::invalid_argument("ppc_arc: end is not on the circle through start (R^2 " +
                                std::to_string(r2) + " vs " +
                                std::to_string(ex0 * ex0 + ey0 * ey0) + ")");

  StepPath path;
  path.start = start;
  path.end = end;
  int64_t x = sx0, y = sy0;
  LatticePoint at = start;
  // A full circle takes 4 quadrants of at most 2R + 1 steps each; more means
  // the end is unreachable (a bug, not an input error).
  const int64_t limit = 8 * (static_cast<int64_t>(std::ceil(std::sqrt(double(r2)))) + 2);
  check_move_count(static_cast<uint64_t>(limit), "ppc_arc");
  int64_t op = 0;
  do {
    if (++op > limit) throw std::logic_error("ppc_arc: end point not reached");
    // Effective quadrant signs; a point on an axis belongs to the quadrant
    // the motion enters, so the path never turns back at an axis.
    int qx, qy;
    if (ccw) {
      qy = y != 0 ? sign_of(y) : sign_of(x);
      qx = x != 0 ? sign_of(x) : -sign_of(y);
    } else {
      qy = y != 0 ? sign_of(y) : -sign_of(x);
      qx = x != 0 ? sign_of(x) : sign_of(y);
    }
    // Motion direction per axis: CCW (-y, x), CW (y, -x).
    const int mx = ccw ? -qy : qy;
    const int my = ccw ? qx : -qx;
    const bool x_inward = (mx == -qx);
    const int64_t f = x * x + y * y - r2;
    const bool step_x = (f >= 0) == x_inward;  // F >= 0: go inward; F < 0: outward
    StepMove m;
    m.time = static_cast<double>(op);
    if (step_x) {
      x += mx;
      at[0] += mx;
      m.step = {mx, 0};
    } else {
      y += my;
      at[1] += my;
      m.step = {0, my};
    }
    m.point = at;
    path.moves.push_back(std::move(m));
  } while (at != end);
  path.ticks = static_cast<double>(op);
  path.operations = static_cast<uint64_t>(op);
  return path;
}

}  // namespace hwinterp::models

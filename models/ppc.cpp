#include "models/ppc.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "models/common.h"

namespace hwinterp::models {

namespace {

int sign_of(int64_t v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// The arc stream squares coordinates in int64: |v| < 2^30 keeps every
// product (and a sum of two) far inside 63 bits. The line stream only adds
// magnitudes: |v| < 2^61 keeps F and the differences inside 63 bits.
constexpr int kArcLimitBits = 30;
constexpr int kLineLimitBits = 61;

void check_stream_point(const LatticePoint& p, const char* who, const char* what,
                        int limit_bits = kArcLimitBits) {
  if (p.size() != 2)
    throw std::invalid_argument(std::string(who) + ": " + what + " must have 2 axes");
  const int64_t limit = int64_t{1} << limit_bits;
  for (const int64_t v : p)
    if (v >= limit || v <= -limit)
      throw std::invalid_argument(std::string(who) + ": " + what + " coordinate " +
                                  std::to_string(v) + " is beyond 2^" + std::to_string(limit_bits) +
                                  " steps");
}

// Quadrant and motion of a point relative to the centre. A point on an axis
// belongs to the quadrant the motion enters, so the path never turns back at
// an axis.
struct Motion {
  int mx, my;     // motion direction per axis: CCW (-y, x), CW (y, -x) of the quadrant
  bool x_inward;  // x is the axis that moves towards the centre
  int quadrant;   // 0..3 = I..IV (0 for the centre itself, which has none)
};

Motion motion_at(int64_t x, int64_t y, bool ccw) {
  int qx, qy;
  if (ccw) {
    qy = y != 0 ? sign_of(y) : sign_of(x);
    qx = x != 0 ? sign_of(x) : -sign_of(y);
  } else {
    qy = y != 0 ? sign_of(y) : -sign_of(x);
    qx = x != 0 ? sign_of(x) : sign_of(y);
  }
  Motion m;
  m.mx = ccw ? -qy : qy;
  m.my = ccw ? qx : -qx;
  m.x_inward = (m.mx == -qx);
  m.quadrant = qy >= 0 ? (qx >= 0 ? 0 : 1) : (qx < 0 ? 2 : 3);
  return m;
}

int64_t ceil_sqrt(int64_t v) {
  auto r = static_cast<int64_t>(std::sqrt(static_cast<double>(v)));
  while (r * r < v) ++r;
  while (r > 0 && (r - 1) * (r - 1) >= v) --r;
  return r;
}

}  // namespace

// --- line ---------------------------------------------------------------------

PpcLineStream::PpcLineStream(const LatticePoint& start, const LatticePoint& end, PpcLineRule rule)
    : rule_(rule), at_(start) {
  check_stream_point(start, "ppc_line", "start", kLineLimitBits);
  check_stream_point(end, "ppc_line", "end", kLineLimitBits);
  const int64_t dx = end[0] - start[0], dy = end[1] - start[1];
  ax_ = std::llabs(dx);
  ay_ = std::llabs(dy);
  // The textbook core has no zero direction: a zero delta steps "+".
  ux_ = dx < 0 ? -1 : 1;
  uy_ = dy < 0 ? -1 : 1;
}

bool PpcLineStream::next(StepMove& m) {
  if (op_ >= static_cast<uint64_t>(ax_ + ay_)) return false;
  bool step_x = f_ >= 0;
  // The bare rule steps x whenever F >= 0, which on a vertical line (F = 0
  // forever) is every step. Guarded: an axis with no steps left never steps;
  // for dx != 0 this never overrides the bare rule (F < 0 once x == |dx|).
  if (rule_ == PpcLineRule::kGuarded) step_x = (step_x && x_ < ax_) || y_ == ay_;
  ++op_;
  m.time = static_cast<double>(op_);
  if (step_x) {
    ++x_;
    f_ -= ay_;
    m.step = {ux_, 0};
    at_[0] += ux_;
  } else {
    ++y_;
    f_ += ax_;
    m.step = {0, uy_};
    at_[1] += uy_;
  }
  m.point = at_;
  return true;
}

StepPath ppc_line(const LatticePoint& start, const LatticePoint& end, PpcLineRule rule) {
  check_line_2d(start, end, "ppc_line");
  StepPath path;
  path.start = start;
  path.end = end;
  PpcLineStream stream(start, end, rule);
  const uint64_t total = stream.total();
  path.moves.reserve(total);
  for (StepMove m; stream.next(m);) path.moves.push_back(m);
  path.ticks = static_cast<double>(total);
  path.operations = total;
  return path;
}

double ppc_line_error_bound(const LatticePoint& start, const LatticePoint& end) {
  const double dx = static_cast<double>(end[0] - start[0]);
  const double dy = static_cast<double>(end[1] - start[1]);
  const double len = std::hypot(dx, dy);
  if (len == 0 || dx == 0 || dy == 0) return 0;
  return std::max(std::abs(dx), std::abs(dy)) / len;
}

// --- arc (rule M) ----------------------------------------------------------------

PpcArcStream::PpcArcStream(const LatticePoint& center, const LatticePoint& start,
                           const LatticePoint& end, bool ccw)
    : ccw_(ccw), c_(center) {
  check_stream_point(center, "ppc_arc", "centre");
  check_stream_point(start, "ppc_arc", "start");
  check_stream_point(end, "ppc_arc", "end");
  x_ = start[0] - center[0];
  y_ = start[1] - center[1];
  ex_ = end[0] - center[0];
  ey_ = end[1] - center[1];
  check_stream_point({x_, y_}, "ppc_arc", "start - centre");
  check_stream_point({ex_, ey_}, "ppc_arc", "end - centre");
  r2_ = x_ * x_ + y_ * y_;
  rs_ceil_ = ceil_sqrt(r2_);
  re_ceil_ = ceil_sqrt(ex_ * ex_ + ey_ * ey_);
  // R = 1 (or 0): the first inward step from an axis point would land on the
  // centre, where no quadrant (and no direction) is defined; an end on the
  // centre has no quadrant either. Both are a line from the start.
  degenerate_ = r2_ < 2 || (ex_ == 0 && ey_ == 0);
  if (degenerate_) {
    phase_ = kSwitch;
    return;
  }
  const Motion ms = motion_at(x_, y_, ccw), me = motion_at(ex_, ey_, ccw);
  laps_ = ((ccw ? me.quadrant - ms.quadrant : ms.quadrant - me.quadrant) + 4) % 4;
  if (laps_ == 0) {
    const bool same = x_ == ex_ && y_ == ey_;
    const bool behind =
        sign_of(ex_ - x_) * ms.mx <= 0 && sign_of(ey_ - y_) * ms.my <= 0;  // on both axes
    if (same || behind) laps_ = 4;
  }
}

uint64_t PpcArcStream::operation_bound() const {
  const auto rs1 = static_cast<uint64_t>(rs_ceil_ + 1);
  const uint64_t arc = degenerate_ ? 0 : 10 * rs1;
  // The closing line spans at most |e| + |p| per axis, |p| < rs + 1.
  const uint64_t line = 2 * static_cast<uint64_t>(re_ceil_) + 2 * rs1;
  return arc + 1 + std::max<uint64_t>(line, 1);
}

void PpcArcStream::start_line() {
  line_ = PpcLineStream({c_[0] + x_, c_[1] + y_}, {c_[0] + ex_, c_[1] + ey_});
}

bool PpcArcStream::next(StepMove& m) {
  for (;;) {
    switch (phase_) {
      case kDone:
        return false;
      case kSwitch:
        // One operation loads the line engine with |e - p|; a zero-length
        // line (a degenerate command with end == start) spends one more.
        ++op_;
        start_line();
        phase_ = kLine;
        if (line_.total() == 0) {
          ++op_;
          phase_ = kDone;
          return false;
        }
        continue;
      case kLine: {
        if (!line_.next(line_move_)) {
          phase_ = kDone;
          return false;
        }
        ++op_;
        m.time = static_cast<double>(op_);
        m.step = line_move_.step;
        m.point = line_move_.point;
        x_ = line_move_.point[0] - c_[0];
        y_ = line_move_.point[1] - c_[1];
        return true;
      }
      case kArc:
        break;
    }
    const Motion q = motion_at(x_, y_, ccw_);
    const int64_t f = x_ * x_ + y_ * y_ - r2_;
    const bool step_x = (f >= 0) == q.x_inward;  // F >= 0: go inward; F < 0: outward
    if (laps_ == 0) {
      // Final pass: stop the arc where the chosen axis has nothing left
      // towards e in its motion direction.
      const int64_t left = step_x ? (ex_ - x_) * q.mx : (ey_ - y_) * q.my;
      if (left <= 0) {
        phase_ = kSwitch;
        continue;
      }
    }
    if (++op_ > operation_bound())
      throw std::logic_error("ppc_arc: operation bound exceeded (rule M did not end)");
    bool entry;
    if (step_x) {
      x_ += q.mx;
      m.step = {q.mx, 0};
      entry = x_ == 0;
    } else {
      y_ += q.my;
      m.step = {0, q.my};
      entry = y_ == 0;
    }
    if (entry) {
      if (laps_ == 0) throw std::logic_error("ppc_arc: the final pass left the end's quadrant");
      --laps_;
    }
    if (laps_ == 0 && x_ == ex_ && y_ == ey_) phase_ = kDone;  // arrived: no closing line
    m.time = static_cast<double>(op_);
    m.point = {c_[0] + x_, c_[1] + y_};
    return true;
  }
}

StepPath ppc_arc(const LatticePoint& center, const LatticePoint& start, const LatticePoint& end,
                 bool ccw) {
  check_line_2d(center, start, "ppc_arc");
  check_line_2d(center, end, "ppc_arc");
  const int64_t sx = start[0] - center[0], sy = start[1] - center[1];
  const int64_t ex = end[0] - center[0], ey = end[1] - center[1];
  // A full circle takes 4 quadrants of at most 2R + 1 steps each (a refused
  // radius is one whose circle would not fit the stored moves); the closing
  // line adds at most its own length.
  const int64_t limit = 8 * (ceil_sqrt(sx * sx + sy * sy) + 2);
  check_move_count(static_cast<uint64_t>(limit), "ppc_arc");
  check_move_count(static_cast<uint64_t>(limit + std::llabs(ex) + std::llabs(ey)), "ppc_arc");

  StepPath path;
  path.start = start;
  path.end = end;
  PpcArcStream stream(center, start, end, ccw);
  for (StepMove m; stream.next(m);) path.moves.push_back(m);
  path.ticks = static_cast<double>(stream.operations());
  path.operations = stream.operations();
  return path;
}

// --- ideal spiral and error -------------------------------------------------------

namespace {}

PpcArcIdeal::PpcArcIdeal(const LatticePoint& center, const LatticePoint& start,
                         const LatticePoint& end, bool ccw)
    : c_(center), ccw_(ccw) {
  check_stream_point(center, "ppc_arc", "centre");
  check_stream_point(start, "ppc_arc", "start");
  check_stream_point(end, "ppc_arc", "end");
  sx_ = start[0] - center[0];
  sy_ = start[1] - center[1];
  const int64_t ex = end[0] - center[0], ey = end[1] - center[1];
  rs2_ = sx_ * sx_ + sy_ * sy_;
  const int64_t re2 = ex * ex + ey * ey;
  rs_ = std::sqrt(static_cast<double>(rs2_));
  const double re = std::sqrt(static_cast<double>(re2));
  // re - rs = (re^2 - rs^2) / (re + rs): exact integers on top, no cancellation.
  dr_ = re + rs_ > 0 ? static_cast<double>(re2 - rs2_) / (re + rs_) : 0.0;
  theta_ = angle_from_start(ex, ey);
  if (theta_ <= 0) theta_ = kTwoPi;  // same direction (or a zero vector): a whole turn
}

double PpcArcIdeal::angle_from_start(int64_t x, int64_t y) const {
  // atan2(cross, dot) is exact in direction for lattice vectors: equal
  // directions give exactly 0.
  const auto cross = static_cast<double>(sx_ * y - sy_ * x);
  const auto dot = static_cast<double>(sx_ * x + sy_ * y);
  double a = std::atan2(ccw_ ? cross : -cross, dot);
  if (a < 0) a += kTwoPi;
  return a;
}

double PpcArcIdeal::error(const LatticePoint& p) const {
  const int64_t x = p[0] - c_[0], y = p[1] - c_[1];
  const int64_t p2 = x * x + y * y;
  const double rp = std::sqrt(static_cast<double>(p2));
  // |p| - rs without cancellation, like dr_.
  const double dp = rp + rs_ > 0 ? static_cast<double>(p2 - rs2_) / (rp + rs_) : 0.0;
  // An end on the circle (dr = 0, the usual arc): the spiral is the circle,
  // and the angle (an atan2 per point) would only be multiplied by 0.
  if (dr_ == 0.0) return std::abs(dp);
  const double phi = angle_from_start(x, y);
  const double t = std::min(phi, theta_) / theta_;
  return std::abs(dp - dr_ * t);
}

std::vector<std::vector<double>> PpcArcIdeal::polyline(int segments) const {
  std::vector<std::vector<double>> out;
  const double a0 = std::atan2(static_cast<double>(sy_), static_cast<double>(sx_));
  for (int k = 0; k <= segments; ++k) {
    const double phi = theta_ * k / segments;
    const double r = rs_ + dr_ * k / segments;
    const double a = ccw_ ? a0 + phi : a0 - phi;
    out.push_back({static_cast<double>(c_[0]) + r * std::cos(a),
                   static_cast<double>(c_[1]) + r * std::sin(a)});
  }
  return out;
}

double ppc_arc_spiral_error(const LatticePoint& p, const LatticePoint& center,
                            const LatticePoint& start, const LatticePoint& end, bool ccw) {
  return PpcArcIdeal(center, start, end, ccw).error(p);
}

ErrorBound ppc_arc_error_bound(const LatticePoint& center, const LatticePoint& start,
                               const LatticePoint& end) {
  return PpcArcIdeal(center, start, end, true).bound();
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

}  // namespace hwinterp::models

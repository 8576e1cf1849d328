#include "models/motion_top_model.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/common.h"

namespace hwinterp::models {

namespace {

[[noreturn]] void reject(const std::string& what) {
  throw std::invalid_argument("motion_top: " + what);
}

void check_axes(const LatticePoint& start, const MotionCommand& c, int axes) {
  if (axes < 3 || axes > kMotionMaxAxes)
    reject("axes must be 3.." + std::to_string(kMotionMaxAxes) + ", not " + std::to_string(axes));
  if (start.size() != static_cast<size_t>(axes))
    reject("the start has " + std::to_string(start.size()) + " coordinates for " +
           std::to_string(axes) + " axes");
  for (int i = axes; i < kMotionMaxAxes; ++i)
    if (c.delta[static_cast<size_t>(i)] != 0)
      reject("delta[" + std::to_string(i) + "] = " +
             std::to_string(c.delta[static_cast<size_t>(i)]) + " on an axis the core lacks");
}

bool in_plane(const std::array<int, 2>& plane, int axis) {
  return axis == plane[0] || axis == plane[1];
}

}  // namespace

std::array<int, 2> motion_plane_axes(int plane) {
  switch (plane) {
    case 0:
      return {0, 1};  // XY: x = X, y = Y
    case 1:
      return {2, 0};  // ZX: x = Z, y = X
    case 2:
      return {1, 2};  // YZ: x = Y, y = Z
    default:
      reject("plane must be 0 (XY), 1 (ZX) or 2 (YZ), not " + std::to_string(plane));
  }
}

uint64_t motion_arc_ops(const std::array<int64_t, 2>& center, const std::array<int64_t, 2>& end,
                        bool ccw) {
  PpcArcStream s({center[0], center[1]}, {0, 0}, {end[0], end[1]}, ccw);
  StepMove m;
  while (s.next(m)) {
  }
  return s.operations();
}

std::array<int64_t, kMotionMaxAxes> motion_displacement(const MotionCommand& c) {
  std::array<int64_t, kMotionMaxAxes> d = c.delta;
  if (c.kind == MotionKind::kArc) {
    const auto p = motion_plane_axes(c.plane);
    d[static_cast<size_t>(p[0])] = c.end[0];
    d[static_cast<size_t>(p[1])] = c.end[1];
  }
  return d;
}

uint64_t motion_operations(const MotionCommand& c) {
  if (c.kind == MotionKind::kArc) return c.ops;
  return dda_iterations(std::vector<int64_t>(c.delta.begin(), c.delta.end()));
}

// --- move stream ------------------------------------------------------------------

MotionMoveStream::MotionMoveStream(const LatticePoint& start, const MotionCommand& c, int axes)
    : c_(c), axes_(axes), at_(start) {
  check_axes(start, c, axes);
  if (c.kind == MotionKind::kLine) {
    dda_.emplace(start, std::vector<int64_t>(c.delta.begin(), c.delta.begin() + axes),
                 Preload::kZero);
    return;
  }
  plane_axes_ = motion_plane_axes(c.plane);
  for (const int a : plane_axes_)
    if (c.delta[static_cast<size_t>(a)] != 0)
      reject("arc delta[" + std::to_string(a) +
             "] = " + std::to_string(c.delta[static_cast<size_t>(a)]) +
             " on a plane axis (the plane's motion is `end`)");
  // PpcArcStream validates the coordinates (|v| < 2^30) with invalid_argument.
  ppc_.emplace(LatticePoint{c.center[0], c.center[1]}, LatticePoint{0, 0},
               LatticePoint{c.end[0], c.end[1]}, c.ccw);
  const uint64_t n = motion_arc_ops(c.center, c.end, c.ccw);
  if (c.ops != n)
    reject("arc ops = " + std::to_string(c.ops) + " but the PPC arc takes " + std::to_string(n) +
           " operations");
  for (int j = 0; j < axes; ++j) {
    const int64_t d = c.delta[static_cast<size_t>(j)];
    if (in_plane(plane_axes_, j) || d == 0) continue;
    if (magnitude(d) > n)
      reject("slaved axis " + std::to_string(j) + " delta " + std::to_string(d) +
             " needs more than one step per operation (the arc has " + std::to_string(n) +
             " operations)");
    const auto s = static_cast<size_t>(slaved_);
    slaved_axis_[s] = j;
    magnitude_[s] = magnitude(d);
    err_[s] = n / 2;
    ++slaved_;
  }
}

bool MotionMoveStream::next(MotionMove& m) {
  return c_.kind == MotionKind::kLine ? next_line(m) : next_arc(m);
}

bool MotionMoveStream::next_line(MotionMove& m) {
  if (!dda_->next(dda_move_)) return false;
  op_ = dda_move_.iteration;
  m.op = op_;
  m.step.fill(0);
  for (int i = 0; i < axes_; ++i)
    m.step[static_cast<size_t>(i)] = static_cast<int8_t>(dda_move_.step[static_cast<size_t>(i)]);
  at_ = dda_move_.point;
  m.point = at_;
  return true;
}

bool MotionMoveStream::next_arc(MotionMove& m) {
  for (;;) {
    if (!have_plane_move_ && !plane_done_) {
      have_plane_move_ = ppc_->next(plane_move_);
      plane_done_ = !have_plane_move_;
    }
    const auto plane_op = have_plane_move_ ? static_cast<uint64_t>(plane_move_.time) : 0;
    uint64_t k;
    if (slaved_ == 0) {
      // Nothing is due between plane moves: jump to the next one.
      if (!have_plane_move_) return false;
      k = plane_op;
    } else {
      if (op_ >= c_.ops) return false;
      k = op_ + 1;
    }
    op_ = k;
    bool any = false;
    m.step.fill(0);
    for (int s = 0; s < slaved_; ++s) {
      const auto i = static_cast<size_t>(s);
      err_[i] += magnitude_[i];
      if (err_[i] >= c_.ops) {
        err_[i] -= c_.ops;
        const auto a = static_cast<size_t>(slaved_axis_[i]);
        m.step[a] = c_.delta[a] < 0 ? -1 : 1;
        at_[a] += m.step[a];
        any = true;
      }
    }
    if (have_plane_move_ && plane_op == k) {
      for (size_t e = 0; e < 2; ++e) {
        const auto a = static_cast<size_t>(plane_axes_[e]);
        m.step[a] = static_cast<int8_t>(plane_move_.step[e]);
        at_[a] += plane_move_.step[e];
      }
      have_plane_move_ = false;
      any = true;
    }
    if (any) {
      m.op = k;
      m.point = at_;
      return true;
    }
  }
}

// --- ideal path and deviation -------------------------------------------------------

MotionIdeal::MotionIdeal(const LatticePoint& start, const MotionCommand& c, int axes)
    : c_(c), axes_(axes), start_(start), end_(start), plane_point_(2, 0) {
  check_axes(start, c, axes);
  const auto d = motion_displacement(c);
  for (int i = 0; i < axes; ++i) end_[static_cast<size_t>(i)] += d[static_cast<size_t>(i)];
  if (c.kind == MotionKind::kLine) {
    int moving = 0;
    for (int i = 0; i < axes; ++i) moving += d[static_cast<size_t>(i)] != 0;
    bound_ = dda_error_bound(moving > 0 ? moving : 1, Preload::kZero);
    line_.emplace(start_, end_);
    return;
  }
  if (c.ops == 0) reject("arc ops = 0");
  plane_axes_ = motion_plane_axes(c.plane);
  ideal_.emplace(LatticePoint{c.center[0], c.center[1]}, LatticePoint{0, 0},
                 LatticePoint{c.end[0], c.end[1]}, c.ccw);
  int slaved = 0;
  for (int j = 0; j < axes; ++j)
    slaved += !in_plane(plane_axes_, j) && c.delta[static_cast<size_t>(j)] != 0;
  const double planar = ideal_->bound().value;
  bound_ = {std::sqrt(planar * planar + slaved / 4.0), false};
}

double MotionIdeal::planar_error(const LatticePoint& p) const {
  if (c_.kind == MotionKind::kLine) return 0;
  for (size_t e = 0; e < 2; ++e) {
    const auto a = static_cast<size_t>(plane_axes_[e]);
    plane_point_[e] = p[a] - start_[a];
  }
  return ideal_->error(plane_point_);
}

double MotionIdeal::slaved_lag(const LatticePoint& p, int axis, uint64_t op) const {
  const auto a = static_cast<size_t>(axis);
  // ((p - s) N - delta k) / N in 128-bit integers, then one division.
  const __int128 num = static_cast<__int128>(p[a] - start_[a]) * static_cast<__int128>(c_.ops) -
                       static_cast<__int128>(c_.delta[a]) * static_cast<__int128>(op);
  return static_cast<double>(num) / static_cast<double>(c_.ops);
}

double MotionIdeal::error(const LatticePoint& p, uint64_t op) const {
  if (c_.kind == MotionKind::kLine) return (*line_)(p);
  const double planar = planar_error(p);
  double sum = planar * planar;
  for (int j = 0; j < axes_; ++j) {
    if (in_plane(plane_axes_, j) || c_.delta[static_cast<size_t>(j)] == 0) continue;
    const double s = slaved_lag(p, j, op);
    sum += s * s;
  }
  return std::sqrt(sum);
}

}  // namespace hwinterp::models

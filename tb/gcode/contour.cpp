#include "tb/gcode/contour.h"

#include <algorithm>
#include <cmath>

#include "models/common.h"

namespace hwinterp::gcode {

namespace {
using models::kPi;
using models::kTwoPi;

using Vec = std::array<double, 6>;

// sum_i w_i (p_i - q_i)^2
double dist2(const Vec& p, const Vec& q, const Vec& w) {
  double s = 0;
  for (size_t i = 0; i < 6; ++i)
    if (w[i] > 0) s += w[i] * (p[i] - q[i]) * (p[i] - q[i]);
  return s;
}

}  // namespace

ContourPath::ContourPath(const Machine& machine, const std::array<double, 6>& start,
                         const Move& move)
    : s_(start), e_(move.end) {
  for (size_t i = 0; i < 6; ++i) {
    has_[i] = machine.has_axis[i];
    spu_[i] = static_cast<double>(machine.steps_per_unit[i]);
  }
  if (move.kind == MoveKind::kArc) helix_.emplace(start, move);
}

ContourError ContourPath::error(const std::array<int64_t, 6>& lattice) const {
  Vec p = s_;  // an axis the machine lacks sits on the path (weight 0 below)
  for (size_t i = 0; i < 6; ++i)
    if (has_[i]) p[i] = static_cast<double>(lattice[i]) / spu_[i];
  return error_at(p);
}

ContourError ContourPath::error_at(const std::array<double, 6>& point) const {
  Vec unit{}, steps{};
  for (size_t i = 0; i < 6; ++i) {
    unit[i] = has_[i] ? 1 : 0;
    steps[i] = has_[i] ? spu_[i] * spu_[i] : 0;
  }
  return {distance(point, unit), distance(point, steps)};
}

double ContourPath::distance(const Vec& p, const Vec& w) const {
  if (!helix_) {
    // Weighted projection onto the segment.
    double dd = 0, wd = 0;
    for (size_t i = 0; i < 6; ++i) {
      const double di = e_[i] - s_[i];
      dd += w[i] * di * di;
      wd += w[i] * (p[i] - s_[i]) * di;
    }
    const double t = dd > 0 ? std::clamp(wd / dd, 0.0, 1.0) : 0.0;
    Vec q{};
    for (size_t i = 0; i < 6; ++i) q[i] = s_[i] + (e_[i] - s_[i]) * t;
    return std::sqrt(dist2(p, q, w));
  }
  const Helix& h = *helix_;
  const double theta = h.theta();
  const auto f = static_cast<size_t>(h.first()), g = static_cast<size_t>(h.second());
  Vec c{}, dc{}, ddc{};
  auto g_at = [&](double phi) {
    h.at_angle(phi, c, dc, ddc);
    return dist2(p, c, w);
  };
  // The end points and the same-angle points bound the distance ...
  double best = std::min(dist2(p, s_, w), dist2(p, e_, w));
  const double phi0 = h.angle_of(p[f], p[g]);
  for (double phi = phi0; phi <= theta; phi += kTwoPi) best = std::min(best, g_at(phi));
  // A circle with nothing else moving, weighed alike on both plane axes: the
  // same-angle point is the nearest (the radial deviation).
  bool planar = h.r1() == h.r2() && w[f] == w[g];
  for (size_t i = 0; i < 6; ++i)
    if (i != f && i != g && w[i] > 0 && e_[i] != s_[i]) planar = false;
  if (planar) return std::sqrt(best);
  // ... so the nearest point lies within asin(d / r_min) of p's angle on
  // some turn (r_min: the smallest radius, scaled to the weighted space).
  const double rho = std::min(h.r1(), h.r2()) * std::sqrt(std::min(w[f], w[g]));
  const double d = std::sqrt(best);
  const double delta = d < rho ? std::asin(d / rho) : kPi;
  const double k_lo = std::ceil((-delta - phi0) / kTwoPi);
  const double k_hi = std::floor((theta + delta - phi0) / kTwoPi);
  for (double k = k_lo; k <= k_hi; ++k) {
    const double centre = phi0 + kTwoPi * k;
    const double lo = std::max(0.0, centre - delta), hi = std::min(theta, centre + delta);
    if (lo > hi) continue;
    // Safeguarded Newton on G(phi) = |p - C(phi)|^2_w within [lo, hi]:
    // a step is taken only when it lowers G (else halved).
    double phi = std::clamp(centre, lo, hi);
    double gv = g_at(phi);  // c, dc, ddc now hold C at phi
    for (int it = 0; it < 12; ++it) {
      double d1 = 0, d2 = 0;
      for (size_t i = 0; i < 6; ++i) {
        if (w[i] <= 0) continue;
        const double r = p[i] - c[i];
        d1 += -2 * w[i] * r * dc[i];
        d2 += 2 * w[i] * (dc[i] * dc[i] - r * ddc[i]);
      }
      double step = d2 > 0 ? -d1 / d2 : (d1 > 0 ? -1 : 1) * (hi - lo) / 4;
      bool moved = false;
      for (int tries = 0; tries < 30; ++tries, step /= 2) {
        const double cand = std::clamp(phi + step, lo, hi);
        if (cand == phi) break;
        const double gc = g_at(cand);
        if (gc < gv) {
          moved = std::abs(cand - phi) > 1e-13 * (1 + std::abs(phi));
          phi = cand;
          gv = gc;
          break;
        }
      }
      if (!moved) break;
      h.at_angle(phi, c, dc, ddc);  // (g_at of a rejected candidate may have run last)
    }
    best = std::min(best, gv);
  }
  return std::sqrt(best);
}

}  // namespace hwinterp::gcode

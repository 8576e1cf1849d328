#include "tb/gcode/helix.h"

#include <cmath>
#include <cstdlib>

#include "models/common.h"

namespace hwinterp::gcode {

using models::kTwoPi;

Helix::Helix(const std::array<double, 6>& start, const Move& arc) : s_(start), e_(arc.end) {
  const PlaneAxes pa = plane_axes(arc.plane);
  first_ = pa.first;
  second_ = pa.second;
  third_ = pa.third;
  ccw_ = arc.rotation > 0;
  c1_ = arc.center[0];
  c2_ = arc.center[1];
  const auto f = static_cast<size_t>(first_), g = static_cast<size_t>(second_);
  r1_ = std::hypot(s_[f] - c1_, s_[g] - c2_);
  r2_ = std::hypot(e_[f] - c1_, e_[g] - c2_);
  a0_ = std::atan2(s_[g] - c2_, s_[f] - c1_);
  double base = angle_of(e_[f], e_[g]);
  if (base <= 0) base = kTwoPi;  // the same direction: a full circle
  const int turns = std::abs(arc.rotation);
  theta_ = base + kTwoPi * (turns > 1 ? turns - 1 : 0);
}

double Helix::angle_of(double u, double v) const {
  double a = (ccw_ ? 1 : -1) * (std::atan2(v - c2_, u - c1_) - a0_);
  a = std::fmod(a, kTwoPi);
  if (a < 0) a += kTwoPi;
  if (a >= kTwoPi) a = 0;
  return a;
}

std::array<double, 6> Helix::point(double t) const {
  if (t >= 1) return e_;
  std::array<double, 6> p{};
  for (size_t i = 0; i < 6; ++i) p[i] = s_[i] + (e_[i] - s_[i]) * t;
  const double r = r1_ + (r2_ - r1_) * t;
  const double a = a0_ + (ccw_ ? 1 : -1) * theta_ * t;
  p[static_cast<size_t>(first_)] = c1_ + r * std::cos(a);
  p[static_cast<size_t>(second_)] = c2_ + r * std::sin(a);
  return p;
}

void Helix::at_angle(double phi, std::array<double, 6>& c, std::array<double, 6>& dc,
                     std::array<double, 6>& ddc) const {
  for (size_t i = 0; i < 6; ++i) {
    dc[i] = (e_[i] - s_[i]) / theta_;
    c[i] = s_[i] + dc[i] * phi;
    ddc[i] = 0;
  }
  const double d = ccw_ ? 1 : -1;
  const double k = (r2_ - r1_) / theta_;  // dr / dphi
  const double r = r1_ + k * phi;
  const double a = a0_ + d * phi;
  const double ca = std::cos(a), sa = std::sin(a);
  const auto f = static_cast<size_t>(first_), g = static_cast<size_t>(second_);
  c[f] = c1_ + r * ca;
  c[g] = c2_ + r * sa;
  dc[f] = k * ca - r * d * sa;
  dc[g] = k * sa + r * d * ca;
  ddc[f] = -2 * k * d * sa - r * ca;
  ddc[g] = 2 * k * d * ca - r * sa;
}

double Helix::length(double t0, double t1) const {
  // The integrand over the angle, sqrt(r^2 + r'^2 + h'^2), by Simpson's rule
  // on 64 intervals (smooth: far below a micrometre on any real arc).
  const double dr = (r2_ - r1_) / theta_;
  const auto h = static_cast<size_t>(third_);
  const double dh = (e_[h] - s_[h]) / theta_;
  auto f = [&](double phi) {
    const double r = r1_ + dr * phi;
    return std::sqrt(r * r + dr * dr + dh * dh);
  };
  constexpr int n = 64;
  const double a = theta_ * t0, b = theta_ * t1, step = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + step * i) * (i % 2 ? 4 : 2);
  return sum * step / 3;
}

}  // namespace hwinterp::gcode

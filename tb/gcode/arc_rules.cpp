#include "tb/gcode/arc_rules.h"

#include <algorithm>
#include <cmath>

namespace hwinterp::gcode {

ArcTolerance linuxcnc_arc_tolerance(bool inch) {
  // LinuxCNC: RADIUS_TOLERANCE_INCH 0.00005 (the mm value is 25.4 times it),
  // CENTER_ARC_RADIUS_TOLERANCE 2 * 0.001 * sqrt(2) in, 2 * 0.01 * sqrt(2) mm,
  // SPIRAL_RELATIVE_TOLERANCE 0.001.
  const double sqrt2 = std::sqrt(2.0);
  if (inch) return ArcTolerance{0.00005, 2 * 0.001 * sqrt2, 0.001};
  return ArcTolerance{0.00005 * 25.4, 2 * 0.01 * sqrt2, 0.001};
}

CenterCheck check_center_arc(double s1, double s2, double e1, double e2, double c1, double c2,
                             const ArcTolerance& tol) {
  CenterCheck c;
  c.r_start = std::hypot(c1 - s1, c2 - s2);
  c.r_end = std::hypot(c1 - e1, c2 - e2);
  if (c.r_start < tol.radius || c.r_end < tol.radius) {
    c.verdict = CenterCheck::kZeroRadius;
    return c;
  }
  c.abs_err = std::fabs(c.r_start - c.r_end);
  c.rel_err = c.abs_err / std::max(c.r_start, c.r_end);
  const bool off = c.abs_err > 100.0 * tol.spiral_abs ||
                   (c.abs_err > tol.spiral_abs && c.rel_err > tol.spiral_rel);
  c.verdict = off ? CenterCheck::kOffCircle : CenterCheck::kOk;
  return c;
}

RadiusCenter center_from_radius(double s1, double s2, double e1, double e2, double r,
                                bool clockwise, const ArcTolerance& tol) {
  RadiusCenter out;
  if (s1 == e1 && s2 == e2) {
    out.verdict = RadiusCenter::kSamePoint;
    return out;
  }
  const double d1 = e1 - s1, d2 = e2 - s2;
  const double chord = std::hypot(d1, d2);
  const double radius = std::fabs(r);
  out.half_chord = chord / 2;
  if (out.half_chord - radius > tol.radius) {
    out.verdict = RadiusCenter::kTooSmall;
    return out;
  }
  // Distance from the chord's midpoint to the centre; a chord within the
  // tolerance of the diameter is a half circle.
  const double ratio = out.half_chord / radius;
  const double h = ratio > 1 - 1e-12 ? 0.0 : radius * std::sqrt(1 - ratio * ratio);
  // Unit normal on the right of the chord (start to end).
  const double n1 = d2 / chord, n2 = -d1 / chord;
  const bool right = clockwise == (r > 0);
  const double side = right ? 1.0 : -1.0;
  out.c1 = (s1 + e1) / 2 + side * h * n1;
  out.c2 = (s2 + e2) / 2 + side * h * n2;
  return out;
}

}  // namespace hwinterp::gcode

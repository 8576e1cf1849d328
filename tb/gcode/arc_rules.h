// LinuxCNC 2.9's rules for G2/G3 arcs, as its interpreter (rs274) applies
// them, in program units (mm or inch), in the arc's plane (canon order).
//
// Centre format (IJK), with r1 = |start - centre|, r2 = |end - centre|:
//   - zero radius: r1 or r2 below the radius tolerance (0.00127 mm, 0.00005 in);
//   - the end is off the circle when |r1 - r2| > 100 x spiral_abs, or when
//     |r1 - r2| > spiral_abs and |r1 - r2| / max(r1, r2) > 0.001;
//     spiral_abs = 2 x 0.01 x sqrt(2) mm (0.0283 mm), 2 x 0.001 x sqrt(2) in.
//   An accepted arc keeps its programmed end and centre exactly (the path
//   spirals from r1 to r2).
// Radius format (R):
//   - start == end (exactly) is refused: no centre can be found;
//   - the radius is too small when half the chord exceeds |R| by more than
//     the radius tolerance; within it the arc is a half circle;
//   - the centre lies on the chord's perpendicular bisector, on the right of
//     the chord for G2 with R > 0 and G3 with R < 0 (the shorter arc for
//     R > 0, the longer for R < 0), on the left otherwise.
// Measured against rs274 on this machine (tests/gcode/arc_rules_test.cpp
// holds the edges, found with rs274 to 1e-5 mm).
#pragma once

namespace hwinterp::gcode {

struct ArcTolerance {
  double radius;      // minimum radius; how far R may fall short of half the chord
  double spiral_abs;  // allowed |r1 - r2| (times 100 unconditionally)
  double spiral_rel;  // allowed |r1 - r2| / max(r1, r2) above spiral_abs
};
ArcTolerance linuxcnc_arc_tolerance(bool inch);

struct CenterCheck {
  enum Verdict { kOk, kZeroRadius, kOffCircle } verdict = kOk;
  double r_start = 0, r_end = 0, abs_err = 0, rel_err = 0;
};
CenterCheck check_center_arc(double s1, double s2, double e1, double e2, double c1, double c2,
                             const ArcTolerance& tol);

struct RadiusCenter {
  enum Verdict { kOk, kSamePoint, kTooSmall } verdict = kOk;
  double c1 = 0, c2 = 0;
  double half_chord = 0;
};
// `clockwise`: G2. `r`: the programmed R (its sign picks the arc).
RadiusCenter center_from_radius(double s1, double s2, double e1, double e2, double r,
                                bool clockwise, const ArcTolerance& tol);

}  // namespace hwinterp::gcode

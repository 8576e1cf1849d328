// Contour error (tb/gcode/contour.h) at known points of lines, arcs,
// spirals and helices, in mm and in steps; and LinuxCNC's helix geometry
// (tb/gcode/helix.h) it shares with the motion compiler.
#include "tb/gcode/contour.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "models/common.h"
#include "tb/gcode/helix.h"

namespace hwinterp::gcode {
namespace {
using models::kPi;

Move line_to(std::array<double, 6> end) {
  Move m;
  m.kind = MoveKind::kFeed;
  m.end = end;
  return m;
}

Move arc_to(std::array<double, 6> end, std::array<double, 2> center, int rotation,
            Plane plane = Plane::kXY) {
  Move m;
  m.kind = MoveKind::kArc;
  m.end = end;
  m.center = center;
  m.rotation = rotation;
  m.plane = plane;
  return m;
}

// The nearest path point by brute force: 400 001 samples of the angle, in mm.
double brute_mm(const ContourPath& path, const std::array<double, 6>& p) {
  const Helix& h = *path.helix();
  double best = 1e300;
  std::array<double, 6> c{}, dc{}, ddc{};
  const int n = 400000;
  for (int i = 0; i <= n; ++i) {
    h.at_angle(h.theta() * i / n, c, dc, ddc);
    double s = 0;
    for (size_t k = 0; k < 6; ++k) s += (p[k] - c[k]) * (p[k] - c[k]);
    best = std::min(best, s);
  }
  return std::sqrt(best);
}

TEST(Contour, LineSegment) {
  const Machine m;  // 1000 steps/mm
  const ContourPath p(m, {0, 0, 0, 0, 0, 0}, line_to({10, 0, 0, 0, 0, 0}));
  EXPECT_NEAR(p.error_at({5, 1, 0, 0, 0, 0}).mm, 1, 1e-12);
  EXPECT_NEAR(p.error_at({5, 1, 0, 0, 0, 0}).steps, 1000, 1e-9);
  EXPECT_NEAR(p.error_at({5, 0.003, -0.004, 0, 0, 0}).mm, 0.005, 1e-12);
  // Beyond the end: the distance to the end point.
  EXPECT_NEAR(p.error_at({12, 0, 0, 0, 0, 0}).mm, 2, 1e-12);
  EXPECT_NEAR(p.error_at({-3, 4, 0, 0, 0, 0}).mm, 5, 1e-12);
  // A lattice point: steps / steps per unit.
  EXPECT_NEAR(p.error({7000, 2, 0, 0, 0, 0}).steps, 2, 1e-9);
  EXPECT_NEAR(p.error({7000, 2, 0, 0, 0, 0}).mm, 0.002, 1e-12);
}

TEST(Contour, UnequalStepsWeighEachAxisByItsOwn) {
  Machine m;
  m.steps_per_unit = {1000, 400, 1000, 100, 100, 100};
  const ContourPath p(m, {0, 0, 0, 0, 0, 0}, line_to({10, 0, 0, 0, 0, 0}));
  // 1 step off in Y is 0.0025 mm and 1 step.
  EXPECT_NEAR(p.error({3000, 1, 0, 0, 0, 0}).mm, 0.0025, 1e-12);
  EXPECT_NEAR(p.error({3000, 1, 0, 0, 0, 0}).steps, 1, 1e-9);
  // A diagonal line: normal to it in mm, and normal to it in step space,
  // where it runs (10000, 4000) and the point is 0.8 steps of Y above it.
  const ContourPath d(m, {0, 0, 0, 0, 0, 0}, line_to({10, 10, 0, 0, 0, 0}));
  const ContourError e = d.error_at({5, 5.002, 0, 0, 0, 0});
  EXPECT_NEAR(e.mm, 0.002 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(e.steps, 0.8 * 10000 / std::hypot(10000.0, 4000.0), 1e-9);
}

TEST(Contour, RotaryAxisCountsDegreesAsUnits) {
  const Machine m;  // A: 100 steps/deg
  const ContourPath p(m, {0, 0, 0, 0, 0, 0}, line_to({0, 0, 0, 90, 0, 0}));
  EXPECT_NEAR(p.error({0, 0, 0, 4500, 0, 0}).mm, 0, 1e-12);
  EXPECT_NEAR(p.error({1, 0, 0, 4500, 0, 0}).steps, 1, 1e-9);
  EXPECT_NEAR(p.error({1, 0, 0, 4500, 0, 0}).mm, 0.001, 1e-12);
}

TEST(Contour, ArcRadialAtThePointsOwnAngle) {
  const Machine m;
  // Quarter circle of 10 mm, CCW from (10, 0) to (0, 10).
  const ContourPath p(m, {10, 0, 0, 0, 0, 0}, arc_to({0, 10, 0, 0, 0, 0}, {0, 0}, 1));
  EXPECT_NEAR(p.helix()->theta(), kPi / 2, 1e-12);
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  EXPECT_NEAR(p.error_at({10.1 * c, 10.1 * s, 0, 0, 0, 0}).mm, 0.1, 1e-12);
  EXPECT_NEAR(p.error_at({9.9 * c, 9.9 * s, 0, 0, 0, 0}).steps, 100, 1e-7);
  EXPECT_NEAR(p.error_at({0, 10, 0, 0, 0, 0}).mm, 0, 1e-12);
  // Outside the sweep: the nearer end point.
  EXPECT_NEAR(p.error_at({-10, 0, 0, 0, 0, 0}).mm, std::sqrt(200.0), 1e-12);
  EXPECT_NEAR(p.error_at({7, -7, 0, 0, 0, 0}).mm, std::hypot(3.0, 7.0), 1e-12);
  // The same quarter CW is the other three quarters.
  const ContourPath cw(m, {10, 0, 0, 0, 0, 0}, arc_to({0, 10, 0, 0, 0, 0}, {0, 0}, -1));
  EXPECT_NEAR(cw.helix()->theta(), 1.5 * kPi, 1e-12);
  EXPECT_NEAR(cw.error_at({-10.2, 0, 0, 0, 0, 0}).mm, 0.2, 1e-12);
}

TEST(Contour, SpiralRadiusGoesLinearlyOverTheSweep) {
  const Machine m;
  // From r = 10 at 0 degrees to r = 12 at 90 degrees (CCW): r = 11 at 45.
  const ContourPath p(m, {10, 0, 0, 0, 0, 0}, arc_to({0, 12, 0, 0, 0, 0}, {0, 0}, 1));
  const double h = std::sqrt(0.5);
  EXPECT_NEAR(p.error_at({11 * h, 11 * h, 0, 0, 0, 0}).mm, 0, 1e-12);
  // 1 mm inside at the same angle; the spiral's normal leans by its pitch
  // (dr/ds = (2 / (pi/2)) / 11), so the nearest point is a little closer.
  const std::array<double, 6> in{10 * h, 10 * h, 0, 0, 0, 0};
  EXPECT_NEAR(p.error_at(in).mm, brute_mm(p, in), 1e-7);
  EXPECT_NEAR(p.error_at(in).mm, std::cos(std::atan(4 / kPi / 11)), 1e-3);
  EXPECT_LT(p.error_at(in).mm, 1);
  const Helix& helix = *p.helix();
  const auto mid = helix.point(0.5);
  EXPECT_NEAR(mid[0], 11 * h, 1e-12);
  EXPECT_NEAR(mid[1], 11 * h, 1e-12);
  EXPECT_EQ(helix.point(1), (std::array<double, 6>{0, 12, 0, 0, 0, 0}));
}

TEST(Contour, HelixAxisAtThatAngleOnEveryTurn) {
  const Machine m;
  // One turn CCW from (10, 0, 0) about (0, 0), Z down 4 mm.
  const ContourPath p(m, {10, 0, 0, 0, 0, 0}, arc_to({10, 0, -4, 0, 0, 0}, {0, 0}, 1));
  EXPECT_NEAR(p.helix()->theta(), 2 * kPi, 1e-12);
  EXPECT_NEAR(p.error_at({0, 10, -1, 0, 0, 0}).mm, 0, 1e-12);
  // 0.5 mm above the path at that angle: the helix climbs 4 mm per 20 pi mm,
  // so the normal distance is 0.5 cos(atan(4 / (20 pi))).
  const double lean = std::cos(std::atan(4 / (20 * kPi)));
  const std::array<double, 6> above{0, 10, -0.5, 0, 0, 0};
  EXPECT_NEAR(p.error_at(above).mm, 0.5 * lean, 1e-6);
  EXPECT_NEAR(p.error_at(above).mm, brute_mm(p, above), 1e-7);
  EXPECT_NEAR(p.error_at(above).steps, 1000 * p.error_at(above).mm, 1e-6);
  const std::array<double, 6> off{0, 10.3, -1.4, 0, 0, 0};
  EXPECT_NEAR(p.error_at(off).mm, brute_mm(p, off), 1e-7);
  EXPECT_LT(p.error_at(off).mm, 0.5);
  // Two turns (P2), Z down 8: the point of the second turn is on the path.
  const ContourPath two(m, {10, 0, 0, 0, 0, 0}, arc_to({10, 0, -8, 0, 0, 0}, {0, 0}, 2));
  EXPECT_NEAR(two.helix()->theta(), 4 * kPi, 1e-12);
  EXPECT_NEAR(two.error_at({0, 10, -5, 0, 0, 0}).mm, 0, 1e-12);
  EXPECT_NEAR(two.error_at({-10, 0, -2, 0, 0, 0}).mm, 0, 1e-12);
  const std::array<double, 6> between{-10, 0, -3, 0, 0, 0};  // between turns 1 and 2
  EXPECT_NEAR(two.error_at(between).mm, brute_mm(two, between), 1e-7);
  EXPECT_NEAR(two.error_at(between).mm, std::cos(std::atan(8 / (40 * kPi))), 1e-6);
  // XYZ length: the helix's.
  EXPECT_NEAR(two.helix()->length(0, 1), std::hypot(4 * kPi * 10, 8.0), 1e-9);
}

TEST(Contour, SteepHelixCountsTheAxialOffsetOnlyAsFarAsItIsNormal) {
  const Machine m;
  // A quarter of 1 mm radius falling 5 mm: 1 mm of Z offset at an angle is
  // mostly along the path.
  const ContourPath p(m, {1, 0, 0, 0, 0, 0}, arc_to({0, 1, -5, 0, 0, 0}, {0, 0}, 1));
  const double a = kPi / 6;
  const std::array<double, 6> q{std::cos(a), std::sin(a), -5.0 / 3 + 0.1, 0, 0, 0};
  const double slope = 5 / (kPi / 2);  // dz / d(arc length)
  EXPECT_NEAR(p.error_at(q).mm, 0.1 / std::hypot(1.0, slope), 1e-3);
  EXPECT_NEAR(p.error_at(q).mm, brute_mm(p, q), 1e-7);
}

TEST(Contour, UnequalPlaneStepsMeasureTheStepLattice) {
  Machine m;
  m.steps_per_unit = {1000, 400, 1000, 100, 100, 100};
  const ContourPath p(m, {10, 0, 0, 0, 0, 0}, arc_to({0, 10, 0, 0, 0, 0}, {0, 0}, 1));
  // On the X axis end of the quarter (10, 0): 1 step of X outside is 0.001 mm
  // and 1 step; 1 step of Y beyond the end (0, 10) is 0.0025 mm and 1 step.
  EXPECT_NEAR(p.error({10001, 0, 0, 0, 0, 0}).steps, 1, 1e-6);
  EXPECT_NEAR(p.error({0, 4001, 0, 0, 0, 0}).steps, 1, 1e-6);
  EXPECT_NEAR(p.error({0, 4001, 0, 0, 0, 0}).mm, 0.0025, 1e-9);
}

TEST(Contour, OtherPlanes) {
  const Machine m;
  // G18: canon order (Z, X); centre (Z, X) = (0, 10); CW from (0,0,0) to X 20.
  const ContourPath p(m, {0, 0, 0, 0, 0, 0}, arc_to({20, 0, 0, 0, 0, 0}, {0, 10}, -1, Plane::kXZ));
  EXPECT_NEAR(p.helix()->theta(), kPi, 1e-12);
  // The half circle passes (X, Z) = (10, 10) or (10, -10): CW in (Z, X)
  // from angle -90 degrees (Z = 0, X = 0 relative (0, -10)) goes to
  // angle -180: Z = -10.
  EXPECT_NEAR(p.error_at({10, 0, -10, 0, 0, 0}).mm, 0, 1e-12);
  EXPECT_NEAR(p.error_at({10, 5, -10.5, 0, 0, 0}).mm, std::hypot(5.0, 0.5), 1e-12);
  // G19: (Y, Z).
  const ContourPath q(m, {0, 0, 0, 0, 0, 0}, arc_to({0, 20, 0, 0, 0, 0}, {10, 0}, 1, Plane::kYZ));
  EXPECT_NEAR(q.error_at({0, 10, -10, 0, 0, 0}).mm, 0, 1e-12);
}

}  // namespace
}  // namespace hwinterp::gcode

// The program's reach before it runs (tb/gcode/limits.h): the interval each
// move sweeps, the machine's travel and the core's position counters, each
// refusal naming the line and the axis.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "gcode_test_util.h"
#include "tb/gcode/helix.h"
#include "tb/gcode/limits.h"
#include "tb/gcode/ngc_reader.h"

namespace hwinterp::gcode {
namespace {

using test::mentions;

std::string check(const std::string& program, const Machine& machine, int pos_w = 32) {
  return test::error_of([&] {
    std::istringstream in(program + "M2\n");
    NgcReader r(in, "t.ngc");
    check_reach(r, machine, pos_w, "motion_top_n4", "t.ngc");
  });
}

Move arc(double x, double y, double cx, double cy, int rotation) {
  Move m;
  m.kind = MoveKind::kArc;
  m.end = {x, y, 0, 0, 0, 0};
  m.center = {cx, cy};
  m.rotation = rotation;
  return m;
}

TEST(Reach, ALineSweepsTheIntervalBetweenItsEnds) {
  Move m;
  m.kind = MoveKind::kFeed;
  m.end = {-3, 5, 2, 10, 0, 0};
  const Reach r = move_reach({1, 1, 2, 0, 0, 0}, m);
  EXPECT_EQ(r.lo[kX], -3);
  EXPECT_EQ(r.hi[kX], 1);
  EXPECT_EQ(r.lo[kY], 1);
  EXPECT_EQ(r.hi[kY], 5);
  EXPECT_EQ(r.lo[kZ], 2);
  EXPECT_EQ(r.hi[kZ], 2);
  EXPECT_EQ(r.hi[kA], 10);
}

TEST(Reach, AQuarterArcReachesNoFurtherThanItsEnds) {
  // CCW from (10, 0) to (0, 10) about the origin: x and y in [0, 10].
  const Reach r = move_reach({10, 0, 0, 0, 0, 0}, arc(0, 10, 0, 0, 1));
  EXPECT_NEAR(r.lo[kX], 0, 1e-12);
  EXPECT_NEAR(r.hi[kX], 10, 1e-12);
  EXPECT_NEAR(r.lo[kY], 0, 1e-12);
  EXPECT_NEAR(r.hi[kY], 10, 1e-12);
}

TEST(Reach, AnArcReachesTheExtremesItsSweepCrosses) {
  // CW from (0, 10) to (0, -10) about the origin passes (10, 0): x up to 10.
  Reach r = move_reach({0, 10, 0, 0, 0, 0}, arc(0, -10, 0, 0, -1));
  EXPECT_NEAR(r.hi[kX], 10, 1e-12);
  EXPECT_NEAR(r.lo[kX], 0, 1e-12);
  // The same ends CCW pass (-10, 0).
  r = move_reach({0, 10, 0, 0, 0, 0}, arc(0, -10, 0, 0, 1));
  EXPECT_NEAR(r.lo[kX], -10, 1e-12);
  EXPECT_NEAR(r.hi[kX], 0, 1e-12);
  // A full circle from (5, 0) about (0, 0): the whole box, whatever the start.
  r = move_reach({5, 0, 0, 0, 0, 0}, arc(5, 0, 0, 0, 1));
  EXPECT_NEAR(r.lo[kX], -5, 1e-12);
  EXPECT_NEAR(r.lo[kY], -5, 1e-12);
  EXPECT_NEAR(r.hi[kY], 5, 1e-12);
}

TEST(Reach, ASampledArcNeverLeavesItsReach) {
  // Spirals and helices in every direction: every sampled point inside.
  for (int k = 0; k < 40; ++k) {
    const double a = k * 0.37, b = k * 1.1;
    Move m = arc(7 * std::cos(b), 7 * std::sin(b) + 0.5 * (k % 3), 0.25, -0.5, k % 2 ? 1 : -2);
    m.end[kZ] = k - 20;
    const std::array<double, 6> start{4 * std::cos(a), 4 * std::sin(a), 0, 0, 0, 0};
    const Reach r = move_reach(start, m);
    const Helix h(start, m);
    for (int s = 0; s <= 2000; ++s) {
      const auto p = h.point(s / 2000.0);
      for (size_t i = 0; i < 3; ++i) {
        // A spiral's extreme may lie past the quadrant point by a little.
        const double slack = std::abs(h.r2() - h.r1()) * 0.25 + 1e-9;
        EXPECT_GE(p[i], r.lo[i] - slack) << k << " axis " << i;
        EXPECT_LE(p[i], r.hi[i] + slack) << k << " axis " << i;
      }
    }
  }
}

TEST(Reach, AProgramInsideTheTravelPasses) {
  Machine m;
  m.travel[kX] = {-1, 50};
  m.travel[kY] = {0, 50};
  EXPECT_EQ(check("G0 X10 Y10\nG2 X30 Y10 I10 J0 F100\nG1 X50\n", m), "");
  // The same arc counterclockwise passes y = 0 and still fits; one more
  // millimetre of radius does not (y = -1).
  EXPECT_EQ(check("G0 X10 Y10\nG3 X30 Y10 I10 J0 F100\n", m), "");
  EXPECT_NE(check("G0 X10 Y10\nG3 X32 Y10 I11 J0 F100\n", m), "");
}

TEST(Reach, LeavingTheTravelNamesTheLineAndTheAxis) {
  Machine m;
  m.travel[kY] = {-5, 50};
  // The arc's ends are inside; its bottom (y = 10 - 20 = -10) is not
  // (counterclockwise from the left end, it passes below the centre).
  EXPECT_TRUE(mentions(check("G0 X10 Y10\nG1 X10 F100\nG3 X50 Y10 I20 J0\n", m),
                       {"t.ngc:3:", "Y reaches -10 mm", "travel [-5, 50]"}));
  m.travel[kZ] = {-80, 0};
  EXPECT_TRUE(mentions(check("G0 Z-10\nG1 Z0.001 F10\n", m),
                       {"t.ngc:2:", "Z reaches 0.001 mm", "travel [-80, 0]"}));
}

TEST(Reach, APositionBeyondTheCountersNamesTheLineAndTheAxis) {
  const Machine m;
  EXPECT_TRUE(mentions(check("G0 X1\nG1 X100000000 F100\n", m),
                       {"t.ngc:2:", "X reaches 1e+08 mm", "1e+11 steps", "motion_top_n4",
                        "POS_W 32", "2147483647"}));
  // 2^14 - 1 = 16383 steps fit POS_W 15; one more does not.
  EXPECT_EQ(check("G1 X16.383 F100\n", m, 15), "");
  EXPECT_TRUE(mentions(check("G1 X-16.384 F100\n", m, 15), {"X reaches -16.384 mm"}));
  // On an arc's plane the engine's step of slack counts.
  EXPECT_TRUE(mentions(check("G0 X16.383\nG2 X16.383 Y0 I-1 J0 F100\n", m, 15),
                       {"t.ngc:2:", "X reaches 16.383"}));
}

}  // namespace
}  // namespace hwinterp::gcode

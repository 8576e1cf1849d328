// LinuxCNC 2.9's arc rules at their edges (arc_edges.h: what rs274 did with
// each; long/rs274_oracle_test.cpp checks the table against rs274 itself):
// the ngc reader must agree, and an accepted arc keeps its programmed end
// and centre exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "arc_edges.h"
#include "gcode_test_util.h"
#include "tb/gcode/arc_rules.h"

namespace hwinterp::gcode {
namespace {

class Rs274ArcEdge : public ::testing::TestWithParam<test::Edge> {};

TEST_P(Rs274ArcEdge, AcceptedExactlyWhenRs274AcceptsIt) {
  const test::Edge& e = GetParam();
  const std::string program = std::string(e.units) + " F100\nG0 X0 Y0\n" + e.arc + "\nM2\n";
  const std::string msg = test::ngc_error(program);
  if (e.accepted) {
    EXPECT_EQ(msg, "") << e.arc;
  } else {
    EXPECT_TRUE(test::mentions(msg, {"t.ngc:3:", e.arc})) << e.arc;
  }
}

INSTANTIATE_TEST_SUITE_P(Rs274, Rs274ArcEdge, ::testing::ValuesIn(test::kArcEdges),
                         [](const auto& info) {
                           return test::test_name(
                               info.index, std::string(info.param.units) + " " + info.param.arc);
                         });

TEST(ArcRules, AnAcceptedOffCircleArcKeepsItsProgrammedEndAndCentre) {
  const auto r = test::ngc("G0 X0 Y0\nG2 X20.028 Y0.001 I10 J0 F100\nM2\n");
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_EQ(r.moves[1].end[kX], 20.028);
  EXPECT_EQ(r.moves[1].end[kY], 0.001);
  EXPECT_EQ(r.moves[1].center, (std::array<double, 2>{10, 0}));
}

TEST(ArcRules, Tolerances) {
  const ArcTolerance mm = linuxcnc_arc_tolerance(false);
  const ArcTolerance in = linuxcnc_arc_tolerance(true);
  EXPECT_DOUBLE_EQ(mm.radius, 0.00127);
  EXPECT_DOUBLE_EQ(in.radius, 0.00005);
  EXPECT_DOUBLE_EQ(mm.spiral_abs, 0.02 * std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(in.spiral_abs, 0.002 * std::sqrt(2.0));
  EXPECT_EQ(mm.spiral_rel, 0.001);
}

TEST(ArcRules, CenterCheckVerdicts) {
  const ArcTolerance t = linuxcnc_arc_tolerance(false);
  EXPECT_EQ(check_center_arc(0, 0, 20, 0, 10, 0, t).verdict, CenterCheck::kOk);
  const CenterCheck off = check_center_arc(0, 0, 20.1, 0, 10, 0, t);
  EXPECT_EQ(off.verdict, CenterCheck::kOffCircle);
  EXPECT_DOUBLE_EQ(off.r_start, 10);
  EXPECT_NEAR(off.abs_err, 0.1, 1e-12);
  EXPECT_NEAR(off.rel_err, 0.1 / 10.1, 1e-12);
  EXPECT_EQ(check_center_arc(0, 0, 0.001, 0, 0.0005, 0, t).verdict, CenterCheck::kZeroRadius);
}

TEST(ArcRules, RadiusCentreSides) {
  const ArcTolerance t = linuxcnc_arc_tolerance(false);
  // (0,0) to (10,0), radius 13: the centre is 12 off the chord's middle.
  const auto at = [&](double r, bool cw) {
    const RadiusCenter c = center_from_radius(0, 0, 10, 0, r, cw, t);
    EXPECT_EQ(c.verdict, RadiusCenter::kOk);
    EXPECT_NEAR(c.c1, 5, 1e-12);
    return c.c2;
  };
  EXPECT_NEAR(at(13, true), -12, 1e-12);  // G2, shorter: centre on the right
  EXPECT_NEAR(at(-13, true), 12, 1e-12);  // G2, longer: on the left
  EXPECT_NEAR(at(13, false), 12, 1e-12);  // G3, shorter: on the left
  EXPECT_NEAR(at(-13, false), -12, 1e-12);
  EXPECT_EQ(center_from_radius(1, 1, 1, 1, 5, true, t).verdict, RadiusCenter::kSamePoint);
  EXPECT_EQ(center_from_radius(0, 0, 10, 0, 4, true, t).verdict, RadiusCenter::kTooSmall);
  // Within the tolerance of the diameter: a half circle about the middle.
  const RadiusCenter half = center_from_radius(0, 0, 10, 0, 4.9995, true, t);
  EXPECT_EQ(half.verdict, RadiusCenter::kOk);
  EXPECT_EQ(half.c1, 5);
  EXPECT_EQ(half.c2, 0);
}

}  // namespace
}  // namespace hwinterp::gcode

#include "models/inflection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/cam_profile.h"

namespace hwinterp::models {
namespace {

// OLI paper, section 3.1: Cam 2's pitch curve turns from convex to concave
// at 6.656011 deg and back at 19.825680 deg.
TEST(Inflection, Cam2PointsBAndC) {
  const RotatingCam cam2(CamLaw::kModifiedSine, 40, 30, 100 * M_PI / 180);
  const std::vector<double> t = find_inflections(cam2);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0] * 180 / M_PI, 6.656011, 5e-7);
  EXPECT_NEAR(t[1] * 180 / M_PI, 19.825680, 5e-7);
  RecordProperty("inflection_B_deg", std::to_string(t[0] * 180 / M_PI));
  RecordProperty("inflection_C_deg", std::to_string(t[1] * 180 / M_PI));
  // Portion I convex, II concave, III convex: the curvature signs alternate.
  EXPECT_GT(cam2.curvature(0.5 * t[0]), 0);
  EXPECT_LT(cam2.curvature(0.5 * (t[0] + t[1])), 0);
  EXPECT_GT(cam2.curvature(0.5 * (t[1] + cam2.t_end())), 0);
  EXPECT_EQ(curvature_sign(cam2, t[0], t[1]), -1);
}

// Cam 1 is point-symmetric about (50, 20): one inflection at x = 50; the zero
// curvature of the modified sine law at both ends is not an inflection.
TEST(Inflection, Cam1SplitsAtItsCentre) {
  const TranslatingCam cam1(CamLaw::kModifiedSine, 100, 40);
  const std::vector<double> t = find_inflections(cam1);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_NEAR(t[0], 50, 1e-9);
}

TEST(Inflection, EveryLawHasOneInTheMiddleOfATranslatingCam) {
  for (CamLaw law : {CamLaw::kCycloidal, CamLaw::kModifiedTrapezoid, CamLaw::kPolynomial345,
                     CamLaw::kHarmonic}) {
    const TranslatingCam cam(law, 30, 10);
    const std::vector<double> t = find_inflections(cam);
    ASSERT_EQ(t.size(), 1u) << cam_law_name(law);
    EXPECT_NEAR(t[0], 15, 1e-9) << cam_law_name(law);
  }
}

TEST(Inflection, NoneOnAnArcAndSingularCurvesAreRefused) {
  const ArcCurve arc({0, 0}, 5, 0, 3);
  EXPECT_TRUE(find_inflections(arc).empty());
  const FunctionCurve cusp([](double t) { return Vec2(t * t * t, t * t); },
                           [](double t) { return Vec2(3 * t * t, 2 * t); },
                           [](double t) { return Vec2(6 * t, 2.0); }, -1, 1);
  EXPECT_THROW(find_inflections(cusp), std::invalid_argument);
}

TEST(Inflection, TooManySignChangesAreRefused) {
  const ExplicitCurve wiggle([](double x) { return std::sin(x); },
                             [](double x) { return std::cos(x); },
                             [](double x) { return -std::sin(x); }, 0.5, 200);
  InflectionOptions opt;
  opt.max_count = 10;
  EXPECT_THROW(find_inflections(wiggle, opt), std::invalid_argument);
  opt.max_count = 256;
  EXPECT_EQ(find_inflections(wiggle, opt).size(), 63u);  // k pi in (0.5, 200)
}

}  // namespace
}  // namespace hwinterp::models

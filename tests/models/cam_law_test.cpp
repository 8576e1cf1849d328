#include "models/cam_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "models/cam_profile.h"

namespace hwinterp::models {
namespace {

const CamLaw kLaws[] = {CamLaw::kModifiedSine, CamLaw::kCycloidal, CamLaw::kModifiedTrapezoid,
                        CamLaw::kPolynomial345, CamLaw::kHarmonic};

TEST(CamLaw, EndsAndSymmetry) {
  for (CamLaw law : kLaws) {
    SCOPED_TRACE(cam_law_name(law));
    EXPECT_NEAR(evaluate_cam_law(law, 0).s, 0, 1e-15);
    EXPECT_NEAR(evaluate_cam_law(law, 1).s, 1, 1e-15);
    EXPECT_NEAR(evaluate_cam_law(law, 0).ds, 0, 1e-15);
    EXPECT_NEAR(evaluate_cam_law(law, 1).ds, 0, 1e-14);
    // All five are point-symmetric about (1/2, 1/2) and rise monotonically.
    for (int k = 0; k <= 200; ++k) {
      const double T = k / 200.0;
      const CamLawValue a = evaluate_cam_law(law, T), b = evaluate_cam_law(law, 1 - T);
      EXPECT_NEAR(a.s + b.s, 1, 1e-14) << T;
      EXPECT_NEAR(a.ds, b.ds, 1e-13) << T;
      EXPECT_NEAR(a.dds, -b.dds, 1e-12) << T;
      EXPECT_GE(a.ds, -1e-15) << T;
    }
  }
}

// Central differences of S must match S', and of S' match S'', everywhere
// including across the piece boundaries of the piecewise laws.
TEST(CamLaw, DerivativesMatchFiniteDifferences) {
  const double h = 1e-6;
  for (CamLaw law : kLaws) {
    SCOPED_TRACE(cam_law_name(law));
    for (int k = 1; k < 1000; ++k) {
      const double T = k / 1000.0;
      const CamLawValue v = evaluate_cam_law(law, T);
      const CamLawValue lo = evaluate_cam_law(law, T - h), hi = evaluate_cam_law(law, T + h);
      EXPECT_NEAR((hi.s - lo.s) / (2 * h), v.ds, 1e-8) << T;
      EXPECT_NEAR((hi.ds - lo.ds) / (2 * h), v.dds, 2e-6) << T;
    }
  }
}

// The pieces of the piecewise laws meet with continuous S, S' and S''.
TEST(CamLaw, PiecewiseLawsAreContinuous) {
  for (CamLaw law : {CamLaw::kModifiedSine, CamLaw::kModifiedTrapezoid}) {
    for (double T : {0.125, 0.375, 0.5, 0.625, 0.875}) {
      const CamLawValue a = evaluate_cam_law(law, T - 1e-12), b = evaluate_cam_law(law, T + 1e-12);
      EXPECT_NEAR(a.s, b.s, 1e-11) << cam_law_name(law) << " " << T;
      EXPECT_NEAR(a.ds, b.ds, 1e-10) << cam_law_name(law) << " " << T;
      EXPECT_NEAR(a.dds, b.dds, 1e-9) << cam_law_name(law) << " " << T;
    }
  }
}

// Peak accelerations from the laws' closed forms: modified sine 4 pi^2 /
// (4 + pi), modified trapezoid 8 pi / (pi + 2), cycloidal 2 pi,
// 3-4-5 polynomial 10 sqrt(3) / 3, harmonic pi^2 / 2.
TEST(CamLaw, PeakAccelerations) {
  const double pi = M_PI;
  const std::pair<CamLaw, double> peaks[] = {{CamLaw::kModifiedSine, 4 * pi * pi / (4 + pi)},
                                             {CamLaw::kModifiedTrapezoid, 8 * pi / (pi + 2)},
                                             {CamLaw::kCycloidal, 2 * pi},
                                             {CamLaw::kPolynomial345, 10 * std::sqrt(3.0) / 3},
                                             {CamLaw::kHarmonic, pi * pi / 2}};
  for (const auto& [law, peak] : peaks) {
    double m = 0;
    for (int k = 0; k <= 100000; ++k) m = std::max(m, std::abs(evaluate_cam_law(law, k / 1e5).dds));
    EXPECT_NEAR(m, peak, 1e-6) << cam_law_name(law);
  }
}

TEST(CamLaw, NamesRoundTripAndUnknownNamesAreRejected) {
  for (CamLaw law : kLaws) EXPECT_EQ(parse_cam_law(cam_law_name(law)), law);
  try {
    parse_cam_law("parabolic");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("parabolic"), std::string::npos);
  }
}

// Central differences of the profiles' point() must match d1() and of d1()
// match d2(); jet() must agree with the three calls.
void expect_profile_consistent(const PlanarCurve& c) {
  const double span = c.t_end() - c.t_begin();
  const double h = 1e-6 * span;
  for (int k = 1; k < 200; ++k) {
    const double t = c.t_begin() + span * k / 200;
    const Vec2 fd1 = (c.point(t + h) - c.point(t - h)) / (2 * h);
    const Vec2 fd2 = (c.d1(t + h) - c.d1(t - h)) / (2 * h);
    EXPECT_LT((fd1 - c.d1(t)).norm(), 1e-6 * (1 + c.d1(t).norm())) << t;
    EXPECT_LT((fd2 - c.d2(t)).norm(), 1e-5 * (1 + c.d2(t).norm())) << t;
    const CurveJetValue j = c.jet(t);
    EXPECT_EQ(j.p, c.point(t));
    EXPECT_EQ(j.d1, c.d1(t));
    EXPECT_EQ(j.d2, c.d2(t));
  }
}

TEST(CamProfile, DerivativesOfEveryLawAndKind) {
  for (CamLaw law : kLaws) {
    SCOPED_TRACE(cam_law_name(law));
    const TranslatingCam t(law, 100, 40);
    expect_profile_consistent(t);
    const RotatingCam r(law, 40, 30, 100 * M_PI / 180);
    expect_profile_consistent(r);
    EXPECT_NEAR((t.point(100) - Vec2(100, 40)).norm(), 0, 1e-12);
    EXPECT_NEAR((r.point(r.t_end()) - 70 * Vec2(std::cos(r.t_end()), std::sin(r.t_end()))).norm(),
                0, 1e-12);
  }
}

TEST(CamProfile, RejectsNonsenseDimensions) {
  EXPECT_THROW(TranslatingCam(CamLaw::kCycloidal, 0, 40), std::invalid_argument);
  EXPECT_THROW(TranslatingCam(CamLaw::kCycloidal, 100, -1), std::invalid_argument);
  EXPECT_THROW(TranslatingCam(CamLaw::kCycloidal, NAN, 1), std::invalid_argument);
  EXPECT_THROW(RotatingCam(CamLaw::kHarmonic, 0, 30, 1), std::invalid_argument);
  EXPECT_THROW(RotatingCam(CamLaw::kHarmonic, 40, 30, 7), std::invalid_argument);
  EXPECT_THROW(RotatingCam(CamLaw::kHarmonic, 40, 30, -1), std::invalid_argument);
}

}  // namespace
}  // namespace hwinterp::models

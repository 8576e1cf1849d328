#include "models/optimal_linear.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "models/cam_profile.h"
#include "models/polyline_verifier.h"

namespace hwinterp::models {
namespace {

// Slack of the independent verifier over the planner's e (docs/papers.md).
constexpr double kVerifySlack = 1e-9;

const TranslatingCam& cam1() {
  static const TranslatingCam c(CamLaw::kModifiedSine, 100, 40);
  return c;
}

const RotatingCam& cam2() {
  static const RotatingCam c(CamLaw::kModifiedSine, 40, 30, 100 * M_PI / 180);
  return c;
}

PolylineCheck verify(const PlanarCurve& c, const OliPlan& plan, double side) {
  PolylineCheckOptions o;
  o.side_sign = side;
  return verify_polyline(c, plan.vertices, o);
}

// What every plan must satisfy, independent of any paper figure: e <= E,
// the verifier's max |error| <= e (+ slack) on a polyline from the curve's
// start to its end, the extremes reached on both sides, and no interval
// coverable by one segment fewer at E.
void expect_valid_plan(const PlanarCurve& c, const OliPlan& plan, double tol, double side) {
  ASSERT_FALSE(plan.intervals.empty());
  EXPECT_LE(plan.error, tol);
  ASSERT_EQ(plan.vertices.size(), static_cast<size_t>(plan.segments) + 1);
  EXPECT_NEAR((plan.vertices.front() - c.point(c.t_begin())).norm(), 0, 1e-12);
  EXPECT_NEAR((plan.vertices.back() - c.point(c.t_end())).norm(), 0, 1e-12);
  const PolylineCheck chk = verify(c, plan, side);
  EXPECT_LE(chk.max_abs_error, plan.error + kVerifySlack);
  EXPECT_EQ(chk.samples_past_ends, 0);
  int sum = 0;
  for (const OliInterval& iv : plan.intervals) {
    sum += iv.segments;
    EXPECT_LE(iv.error, tol);
    EXPECT_LE(iv.error, plan.error);
    if (iv.process2_evaluations > 0 && !iv.second_stopping_rule) {
      EXPECT_GE(iv.end_gap_mm, 0);
      EXPECT_LE(iv.end_gap_mm, 1e-8);
    }
    // One segment fewer at the full tolerance falls short of the interval end.
    EXPECT_LT(oli_chain_end_gap(c, iv.t_begin, iv.t_end, iv.segments - 1, tol), 0)
        << "interval [" << iv.t_begin << ", " << iv.t_end << "] n = " << iv.segments;
  }
  EXPECT_EQ(sum, plan.segments);
}

struct PaperCase {
  double tol;
  int paper_n;
};

// Table 1 of the OLI paper: Cam 1, whole curve (both halves).
class Table1 : public ::testing::TestWithParam<PaperCase> {};

TEST_P(Table1, SegmentCountMatchesThePaper) {
  const PaperCase pc = GetParam();
  const OliPlan plan = plan_optimal_linear(cam1(), pc.tol);
  RecordProperty("paper_n", pc.paper_n);
  RecordProperty("ours_n", plan.segments);
  RecordProperty("ours_e", std::to_string(plan.error));
  EXPECT_EQ(plan.segments, pc.paper_n) << "E = " << pc.tol;
  ASSERT_EQ(plan.intervals.size(), 2u);
  // Point symmetry: both halves need the same count and error (to what the
  // 1e-8 mm convergence limit on the end gap pins e down, ~1e-10 relative).
  EXPECT_EQ(plan.intervals[0].segments, plan.intervals[1].segments);
  EXPECT_NEAR(plan.intervals[0].error, plan.intervals[1].error, 1e-9 * pc.tol);
  expect_valid_plan(cam1(), plan, pc.tol, cam1().outward_sign());
}

INSTANTIATE_TEST_SUITE_P(OliPaper, Table1,
                         ::testing::Values(PaperCase{0.1, 10}, PaperCase{0.05, 14},
                                           PaperCase{0.02, 22}, PaperCase{0.01, 30},
                                           PaperCase{0.005, 40}, PaperCase{0.002, 62},
                                           PaperCase{0.001, 88}, PaperCase{0.0005, 124},
                                           PaperCase{0.00025, 174}, PaperCase{0.0002, 194},
                                           PaperCase{0.0001, 274}, PaperCase{0.00005, 388},
                                           PaperCase{0.00002, 612}, PaperCase{0.00001, 864}));

// Table 3: Cam 2, whole profile.
class Table3 : public ::testing::TestWithParam<PaperCase> {};

TEST_P(Table3, SegmentCountMatchesThePaper) {
  const PaperCase pc = GetParam();
  const OliPlan plan = plan_optimal_linear(cam2(), pc.tol);
  RecordProperty("paper_n", pc.paper_n);
  RecordProperty("ours_n", plan.segments);
  RecordProperty("ours_e", std::to_string(plan.error));
  EXPECT_EQ(plan.segments, pc.paper_n) << "E = " << pc.tol;
  EXPECT_EQ(plan.intervals.size(), 3u);
  expect_valid_plan(cam2(), plan, pc.tol, cam2().outward_sign());
}

INSTANTIATE_TEST_SUITE_P(OliPaper, Table3,
                         ::testing::Values(PaperCase{0.1, 12}, PaperCase{0.05, 17},
                                           PaperCase{0.02, 26}, PaperCase{0.01, 35},
                                           PaperCase{0.005, 49}, PaperCase{0.002, 75},
                                           PaperCase{0.001, 106}, PaperCase{0.0005, 149},
                                           PaperCase{0.00025, 210}, PaperCase{0.0002, 234},
                                           PaperCase{0.0001, 331}, PaperCase{0.00005, 466}));

// Section 3.2: at +-0.0005 mm Cam 1 needs 124 segments and reaches
// +-0.000489 mm (0.0004888 to 4 digits).
TEST(OptimalLinear, Cam1At0005ReachesThePapersError) {
  const OliPlan plan = plan_optimal_linear(cam1(), 0.0005);
  EXPECT_EQ(plan.segments, 124);
  EXPECT_NEAR(plan.error, 0.0004888, 5e-8);
  const PolylineCheck chk = verify(cam1(), plan, cam1().outward_sign());
  // Every segment reaches +e inside and the joints -e outside.
  EXPECT_NEAR(chk.most_positive.error, plan.error, 1e-12);
  EXPECT_NEAR(chk.most_negative.error, -plan.error, 1e-12);
}

// Table 3's row at +-0.0005 mm: portions 6 + 7 + 136, whole error 0.000496
// from Portion III; Portion I 0.000426, Portion II 0.000479.
TEST(OptimalLinear, Cam2At0005Portions) {
  const OliPlan plan = plan_optimal_linear(cam2(), 0.0005);
  ASSERT_EQ(plan.intervals.size(), 3u);
  EXPECT_EQ(plan.intervals[0].segments, 6);
  EXPECT_EQ(plan.intervals[1].segments, 7);
  EXPECT_EQ(plan.intervals[2].segments, 136);
  EXPECT_NEAR(plan.error, 0.000496, 5e-7);
  EXPECT_NEAR(plan.intervals[0].error, 0.000426, 5e-7);
  EXPECT_NEAR(plan.intervals[1].error, 0.000479, 5e-7);
  EXPECT_EQ(plan.error, plan.intervals[2].error);
  // Portions meet at the inflection points B and C, on the curve.
  const std::vector<double> infl = find_inflections(cam2());
  EXPECT_NEAR(plan.intervals[0].t_end, infl[0], 1e-15);
  EXPECT_NEAR(plan.intervals[2].t_begin, infl[1], 1e-15);
  EXPECT_NEAR((plan.vertices[6] - cam2().point(infl[0])).norm(), 0, 1e-12);
}

// A single segment is the chord; at +-0.1 mm Portions I and II of Cam 2 are
// one chord each, with the paper's 0.0319 and 0.0577 mm.
TEST(OptimalLinear, SingleSegmentIsTheChord) {
  const OliPlan plan = plan_optimal_linear(cam2(), 0.1);
  EXPECT_EQ(plan.intervals[0].segments, 1);
  EXPECT_EQ(plan.intervals[1].segments, 1);
  EXPECT_NEAR(plan.intervals[0].error, 0.0319, 5e-5);
  EXPECT_NEAR(plan.intervals[1].error, 0.0577, 5e-5);
}

// The tangent arc that extends an interval past its end only steers root
// searches: the result must not depend on its radius.
TEST(OptimalLinear, ResultDoesNotDependOnTheExtensionRadius) {
  for (double tol : {0.1, 0.0005}) {
    for (const PlanarCurve* c :
         {static_cast<const PlanarCurve*>(&cam1()), static_cast<const PlanarCurve*>(&cam2())}) {
      OliOptions o;
      const OliPlan ref = plan_optimal_linear(*c, tol, o);
      for (double r : {1.0, 5.0, 500.0, 5000.0}) {
        o.extension_radius_mm = r;
        const OliPlan p = plan_optimal_linear(*c, tol, o);
        EXPECT_EQ(p.segments, ref.segments) << "R = " << r;
        EXPECT_NEAR(p.error, ref.error, 1e-9 * tol) << "R = " << r;
        ASSERT_EQ(p.vertices.size(), ref.vertices.size());
        for (size_t i = 0; i < p.vertices.size(); ++i)
          EXPECT_NEAR((p.vertices[i] - ref.vertices[i]).norm(), 0, 1e-7) << "R = " << r;
      }
    }
  }
}

// The planner works on any PlanarCurve: Cam 1 written as an ExplicitCurve
// gives the same plan as the TranslatingCam.
TEST(OptimalLinear, ExplicitCurveGivesTheSamePlan) {
  const auto S = [](double x) { return evaluate_cam_law(CamLaw::kModifiedSine, x / 100); };
  const ExplicitCurve explicit_cam1([&](double x) { return 40 * S(x).s; },
                                    [&](double x) { return 0.4 * S(x).ds; },
                                    [&](double x) { return 0.004 * S(x).dds; }, 0, 100);
  for (double tol : {0.01, 0.0005}) {
    const OliPlan a = plan_optimal_linear(explicit_cam1, tol);
    const OliPlan b = plan_optimal_linear(cam1(), tol);
    EXPECT_EQ(a.segments, b.segments);
    EXPECT_NEAR(a.error, b.error, 1e-9 * tol);
    expect_valid_plan(explicit_cam1, a, tol, 1);
  }
}

// Beyond the paper: other laws and dimensions, translating and rotating,
// each checked by the verifier (and the n - 1 test).
TEST(OptimalLinear, OtherLawsAndDimensions) {
  const CamLaw laws[] = {CamLaw::kModifiedSine, CamLaw::kCycloidal, CamLaw::kModifiedTrapezoid,
                         CamLaw::kPolynomial345, CamLaw::kHarmonic};
  for (CamLaw law : laws) {
    for (const auto& [stroke, lift] : {std::pair{30.0, 10.0}, std::pair{200.0, 5.0}}) {
      const TranslatingCam c(law, stroke, lift);
      for (double tol : {0.01, 0.0002}) {
        SCOPED_TRACE(cam_law_name(law) + " translating " + std::to_string(stroke) + "/" +
                     std::to_string(lift) + " E " + std::to_string(tol));
        expect_valid_plan(c, plan_optimal_linear(c, tol), tol, c.outward_sign());
      }
    }
    for (const auto& [r0, lift, deg] :
         {std::tuple{20.0, 10.0, 60.0}, std::tuple{5.0, 30.0, 180.0}}) {
      const RotatingCam c(law, r0, lift, deg * M_PI / 180);
      for (double tol : {0.01, 0.0002}) {
        SCOPED_TRACE(cam_law_name(law) + " rotating " + std::to_string(r0) + "/" +
                     std::to_string(lift) + "/" + std::to_string(deg) + " E " +
                     std::to_string(tol));
        expect_valid_plan(c, plan_optimal_linear(c, tol), tol, c.outward_sign());
      }
    }
  }
}

// An interval whose tangent turns by more than 120 degrees is split (the
// method's equations are monotone only below 180): a full-turn rotating cam
// has no inflection but several intervals, each turning at most 120.
TEST(OptimalLinear, LongTurnsAreSplit) {
  const RotatingCam c(CamLaw::kCycloidal, 50, 5, 2 * M_PI);
  const OliPlan plan = plan_optimal_linear(c, 0.001);
  EXPECT_GE(plan.intervals.size(), 3u);
  for (const OliInterval& iv : plan.intervals)
    EXPECT_LE(std::abs(tangent_turn(c, iv.t_begin, iv.t_end)), 120.001 * M_PI / 180);
  expect_valid_plan(c, plan, 0.001, c.outward_sign());
}

// A parametric curve that is not a cam: an ellipse quadrant, and a straight
// line (one exact segment).
TEST(OptimalLinear, EllipseAndLine) {
  const FunctionCurve ellipse([](double t) { return Vec2(30 * std::cos(t), 10 * std::sin(t)); },
                              [](double t) { return Vec2(-30 * std::sin(t), 10 * std::cos(t)); },
                              [](double t) { return Vec2(-30 * std::cos(t), -10 * std::sin(t)); },
                              0, M_PI / 2);
  expect_valid_plan(ellipse, plan_optimal_linear(ellipse, 0.001), 0.001, 1);
  const LineCurve line({0, 0}, {4, 3});
  const OliPlan p = plan_optimal_linear(line, 0.001);
  EXPECT_EQ(p.segments, 1);
  EXPECT_EQ(p.error, 0);
}

// The second stopping rule: with Process II's evaluations capped, the plan
// either stops early on a chain that still reaches the interval end (valid,
// with a slightly larger e) or is refused; never an invalid polyline.
TEST(OptimalLinear, SecondStoppingRuleKeepsThePlanValid) {
  bool stopped_early = false;
  for (int budget = 1; budget <= 8; ++budget) {
    OliOptions o;
    o.max_process2_evaluations = budget;
    try {
      const OliPlan plan = plan_optimal_linear(cam1(), 0.0005, o);
      EXPECT_EQ(plan.segments, 124) << budget;
      for (const OliInterval& iv : plan.intervals) stopped_early |= iv.second_stopping_rule;
      expect_valid_plan(cam1(), plan, 0.0005, cam1().outward_sign());
    } catch (const std::invalid_argument&) {
    }
  }
  EXPECT_TRUE(stopped_early);
}

TEST(OptimalLinear, RefusesToleranceItCannotHonour) {
  EXPECT_THROW(plan_optimal_linear(cam1(), 0), std::invalid_argument);
  EXPECT_THROW(plan_optimal_linear(cam1(), -0.1), std::invalid_argument);
  EXPECT_THROW(plan_optimal_linear(cam1(), NAN), std::invalid_argument);
  // Cam 1's smallest radius of curvature is ~45 mm: 10 mm is too coarse.
  EXPECT_THROW(plan_optimal_linear(cam1(), 10), std::invalid_argument);
  OliOptions o;
  o.max_segments = 50;
  EXPECT_THROW(plan_optimal_linear(cam1(), 0.0001, o), std::invalid_argument);
}

}  // namespace
}  // namespace hwinterp::models

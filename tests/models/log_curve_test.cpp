#include "models/log_curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "models/inscribed_chord.h"
#include "models/paper_data_001_003_004.h"

namespace hwinterp::models {
namespace {

namespace pd = paper;

// A printed value with `decimals` decimals stands for anything within half a
// unit of its last place; several of the paper's values sit on that boundary,
// so compare with the half unit (plus rounding noise), not string-equal.
void expect_printed(double ours, double printed, int decimals, const std::string& what) {
  const double half = 0.5 * std::pow(10.0, -decimals);
  EXPECT_LE(std::abs(ours - printed), half + 1e-12)
      << what << ": ours " << ours << ", paper " << printed;
}

// A figure printed as m.mmmm e-k: half a unit of its 5th significant digit.
void expect_sig5(double ours, double printed, const std::string& what) {
  const double half = 0.5e-4 * std::pow(10.0, std::floor(std::log10(std::abs(printed))));
  EXPECT_LE(std::abs(ours - printed), half * (1 + 1e-9))
      << what << ": ours " << ours << ", paper " << printed;
}

TEST(LogCurve, Constants) {
  const LogCurveParams p;  // the paper's case
  EXPECT_NEAR(log_a(p), std::tan(M_PI / 6) / std::tan(M_PI / 36), 1e-14);
  EXPECT_NEAR(log_b(p), 2 * std::tan(M_PI / 36) / 10, 1e-16);
}

TEST(LogCurve, PaperRunDl02) {
  const LogRun run = run_log_interpolation(LogCurveParams{});
  EXPECT_EQ(run.count(), static_cast<size_t>(pd::kLogPoints02));
  expect_printed(run.x_last(), pd::kLogXLast02, 4, "last X");
  expect_sig5(run.max_all.abs, pd::kLogMaxErr02, "MaxErPA");
  expect_sig5(run.max_odd.abs, pd::kLogMaxErr02, "MaxErPAo");
  expect_sig5(run.max_even.abs, pd::kLogMaxErrEven02, "MaxErPAe");
  EXPECT_EQ(run.max_all.index, 1u);
  EXPECT_EQ(run.max_odd.index, 1u);
  EXPECT_EQ(run.max_even.index, 152u);
  // The interpolated A is ahead of the curve: ErPA = PA - A is negative.
  EXPECT_LT(run.max_all.value, 0);
}

TEST(LogCurve, PaperTable1AllCells) {
  const LogRun run = run_log_interpolation(LogCurveParams{});
  int cells = 0;
  for (const auto& row : pd::kLogTable1) {
    ASSERT_LT(static_cast<size_t>(row.point), run.points.size());
    const LogPoint& p = run.points[row.point];
    const std::string at = "point " + std::to_string(row.point);
    expect_printed(p.x, row.x, 4, at + " X");
    expect_printed(p.a, row.a, 4, at + " A");
    expect_printed(p.pa, row.pa, 4, at + " PA");
    expect_printed(p.error * 1e4, row.err_e4, 4, at + " ErPA x 1e4");
    cells += 4;
  }
  EXPECT_EQ(cells, 80);
}

TEST(LogCurve, PaperRunDl05) {
  LogCurveParams p;
  p.dl_mm = 0.5;
  const LogRun run = run_log_interpolation(p);
  EXPECT_EQ(run.count(), static_cast<size_t>(pd::kLogPoints05));
  expect_printed(run.x_last(), pd::kLogXLast05, 4, "last X");
  expect_sig5(run.max_all.abs, pd::kLogMaxErr05, "MaxErPA");
}

// The stop rule: whole cycles until an even point reaches x_end; stopping at
// the first point past 30 would give 151 points.
TEST(LogCurve, StopRuleWholeCycles) {
  const LogRun run = run_log_interpolation(LogCurveParams{});
  EXPECT_EQ(run.count() % 2, 0u);
  EXPECT_GE(run.points.back().x, 30.0);
  EXPECT_LT(run.points[run.count() - 2].x, 30.0);
  EXPECT_GE(run.points[run.count() - 1].x, 30.0);  // point 151 is already past 30
}

TEST(LogCurve, FourAxesFollowX) {
  const LogCurveParams p;
  const LogRun run = run_log_interpolation(p);
  const double tc = std::tan(p.cone_deg * M_PI / 180);
  const double sr = std::sin(p.rake_deg * M_PI / 180);
  for (const LogPoint& q : run.points) {
    EXPECT_NEAR(q.y, q.x * tc, 1e-12 * (1 + q.x));
    EXPECT_NEAR(q.z, q.x * tc * sr, 1e-12 * (1 + q.x));
    EXPECT_NEAR(q.pa, run.a * std::log(1 + run.b * q.x), 1e-12);
    EXPECT_DOUBLE_EQ(q.error, q.pa - q.a);
  }
}

// Odd steps are exactly dl long (Eqs. 8/9); the third-order even steps are dl
// long up to the terms Eqs. 14/15 drop.
TEST(LogCurve, StepLengths) {
  const LogCurveParams p;
  const LogRun run = run_log_interpolation(p);
  for (size_t k = 1; k < run.points.size(); ++k) {
    const LogPoint &a = run.points[k - 1], &b = run.points[k];
    const double len = std::hypot(b.x - a.x, b.a - a.a);
    EXPECT_NEAR(len, p.dl_mm, b.odd() ? 1e-14 : 1e-9) << "step " << k;
  }
}

// The even-point error drifts one way (about -1.1e-8 per cycle at first) and
// levels off; the exact even step removes the drift.
TEST(LogCurve, EvenDriftAndExactEvenStep) {
  const LogRun paper = run_log_interpolation(LogCurveParams{});
  EXPECT_LT(paper.points[2].error, -1.0e-8);
  EXPECT_GT(paper.points[2].error, -1.2e-8);
  double prev = 0, prev_drop = 1;
  for (size_t k = 2; k < paper.points.size(); k += 2) {
    const double drop = prev - paper.points[k].error;
    EXPECT_GT(drop, 0) << "even point " << k;
    EXPECT_LT(drop, prev_drop * (1 + 1e-6)) << "even point " << k;  // levels off
    prev = paper.points[k].error;
    prev_drop = drop;
  }

  const LogRun exact = run_log_interpolation(LogCurveParams{}, EvenStep::kExact);
  EXPECT_EQ(exact.count(), paper.count());
  EXPECT_LE(exact.max_even.abs, 1e-14);
  for (size_t k = 1; k < exact.points.size(); ++k) {
    const LogPoint &a = exact.points[k - 1], &b = exact.points[k];
    EXPECT_NEAR(std::hypot(b.x - a.x, b.a - a.a), 0.2, 1e-13);
  }
  // The odd-step error is the tangent's; the exact even step leaves it alone.
  EXPECT_NEAR(exact.max_odd.abs, paper.max_odd.abs, 1e-9);
}

// The exact even step agrees with the general inscribed-chord intersection on
// the same curve (two independent root finders).
TEST(LogCurve, ExactEvenStepMatchesChordIntersection) {
  const LogCurveParams p;
  const double a = log_a(p), b = log_b(p);
  const ExplicitCurve curve = log_planar_curve(a, b, 40);
  for (double x0 : {0.0, 3.0, 17.5, 29.9}) {
    const LogCycle c = log_cycle_paper(a, b, p.dl_mm, x0);
    const double x1 = x0 + c.dx10, a1 = a * std::log1p(b * x0) + c.da10;
    const double x2 = log_exact_even_x(a, b, p.dl_mm, x1, a1);
    const double t2 = next_circle_intersection(curve, Vec2(x1, a1), p.dl_mm, x1, x1 + 1);
    EXPECT_NEAR(x2, t2, 1e-12) << "x0 " << x0;
    EXPECT_NEAR(std::hypot(x2 - x1, a * std::log1p(b * x2) - a1), p.dl_mm, 1e-13);
  }
}

// Arc length of the true curve over [0, x] (Simpson).
double arc_length(const LogRun& run, double x) {
  const int n = 4000;
  const double h = x / n;
  auto speed = [&](double u) { return std::hypot(1.0, run.a * run.b / (1 + run.b * u)); };
  double s = speed(0) + speed(x);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4 : 2) * speed(k * h);
  return s * h / 3;
}

// Other cutters and lengths (seeded). Measured behaviour the tests pin down:
//  - an odd point's error is its cycle start's error plus the tangent step's,
//    and the tangent step's is at most max|A''| dX^2 / 2 <= a b^2 dl^2 / 2;
//  - the error is second order in dl: halving dl quarters MaxErPA;
//  - the even points stay below the odd ones (at most 0.15 of MaxErPAo in
//    these cases; 1/114 in the paper's; the drift matters for small D1 with a
//    large cone angle);
//  - the point count matches the curve length in steps of dl;
//  - the exact even step puts every even point on the curve.
TEST(LogCurve, OtherParametersProperties) {
  std::mt19937_64 rng(20240611);
  auto uni = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  for (int i = 0; i < 25; ++i) {
    LogCurveParams p{uni(4, 40), uni(10, 45), uni(1, 20), uni(1, 30), uni(0.02, 0.5), uni(5, 60)};
    SCOPED_TRACE("case " + std::to_string(i) + " D1 " + std::to_string(p.d1_mm) + " C " +
                 std::to_string(p.cone_deg) + " dl " + std::to_string(p.dl_mm));
    const LogRun run = run_log_interpolation(p);
    const double tangent_bound = 0.5 * run.a * run.b * run.b * p.dl_mm * p.dl_mm;
    for (size_t k = 1; k < run.points.size(); k += 2)
      EXPECT_LE(std::abs(run.points[k].error),
                std::abs(run.points[k - 1].error) + tangent_bound * (1 + 1e-9))
          << "odd point " << k;
    EXPECT_LE(run.max_even.abs, 0.25 * run.max_odd.abs);
    EXPECT_EQ(run.count() % 2, 0u);
    EXPECT_GE(run.x_last(), p.x_end_mm);
    EXPECT_LT(run.points[run.count() - 2].x, p.x_end_mm);

    LogCurveParams half = p;
    half.dl_mm /= 2;
    const double order = run.max_all.abs / run_log_interpolation(half).max_all.abs;
    EXPECT_GT(order, 3.8);
    EXPECT_LT(order, 4.2);

    const double chords = static_cast<double>(run.count()) * p.dl_mm;
    EXPECT_NEAR(chords, arc_length(run, run.x_last()), 1e-4 * chords);

    // Exact even steps: P0 and P2 on the (convex) curve, so the arc between
    // them lies between the chord P0P2 and the path P0P1P2 of length 2 dl.
    const LogRun exact = run_log_interpolation(p, EvenStep::kExact);
    EXPECT_LE(exact.max_even.abs, 1e-13);
    double direct = 0;
    for (size_t k = 2; k < exact.points.size(); k += 2)
      direct += std::hypot(exact.points[k].x - exact.points[k - 2].x,
                           exact.points[k].a - exact.points[k - 2].a);
    const double arc = arc_length(exact, exact.x_last());
    EXPECT_LE(arc, static_cast<double>(exact.count()) * p.dl_mm * (1 + 1e-9));
    EXPECT_GE(arc, direct * (1 - 1e-9));
  }
}

void expect_invalid(const std::function<void(LogCurveParams&)>& change, const std::string& named) {
  LogCurveParams p;
  change(p);
  try {
    run_log_interpolation(p);
    FAIL() << "no std::invalid_argument for " << named;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
  }
}

TEST(LogCurve, RejectsBadParametersNamingTheValue) {
  expect_invalid([](LogCurveParams& p) { p.d1_mm = 0; }, "D1 0");
  expect_invalid([](LogCurveParams& p) { p.d1_mm = -3; }, "D1 -3");
  expect_invalid([](LogCurveParams& p) { p.spiral_deg = 90; }, "spiral angle 90");
  expect_invalid([](LogCurveParams& p) { p.cone_deg = 0; }, "cone angle 0");
  expect_invalid([](LogCurveParams& p) { p.rake_deg = -1; }, "rake -1");
  expect_invalid([](LogCurveParams& p) { p.cone_deg = NAN; }, "cone angle nan");
  expect_invalid([](LogCurveParams& p) { p.dl_mm = 0; }, "dl 0");
  expect_invalid([](LogCurveParams& p) { p.dl_mm = -0.2; }, "dl -0.2");
  expect_invalid([](LogCurveParams& p) { p.x_end_mm = 0; }, "x_end 0");
  expect_invalid([](LogCurveParams& p) { p.dl_mm = 1e-7; }, "dl 1e-07");  // point limit
  expect_invalid([](LogCurveParams& p) { p.dl_mm = 31; }, "dl 31 mm is longer than x_end 30");
}

}  // namespace
}  // namespace hwinterp::models

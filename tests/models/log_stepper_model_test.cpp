// The log_stepper's bit-exact fixed-point model (models/log_stepper_model.h)
// against exact integer arithmetic and against the double-precision model
// (models/log_curve.h): the primitives are floors of the exact values, the
// paper's curve makes the paper's 152 points, every point of the paper's and
// of random accepted curves lies within 1 step of the double model's on every
// axis, and the refused commands say why.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "models/log_stepper_model.h"

namespace hwinterp::models {
namespace {

using u128 = unsigned __int128;
const LogFixedFormat kFormat{10, 30};  // log_stepper_n4 (cmake/cores.cmake)

TEST(LogStepperModel, PrimitivesAreFloorsOfTheExactValues) {
  std::mt19937_64 rng(7);
  const LogFixedFormat f = kFormat;
  for (int k = 0; k < 20000; ++k) {
    // x in [1.0, 2^(INT_W-1)).
    const uint64_t x = f.one() + rng() % (f.max_word() / 2 - f.one());
    const uint64_t y = rng() % (f.max_word() / 64);
    // mul: floor(x y / 2^F), kept to W bits as the register it is written to.
    EXPECT_EQ(log_mul(x, y, f), static_cast<uint64_t>((u128{x} * y) >> f.frac_w) & f.max_word());
    // sqrt: r = floor(sqrt(x 2^F)) <=> r^2 <= x 2^F < (r + 1)^2.
    const u128 n = u128{x} << f.frac_w;
    const u128 r = log_sqrt(x, f);
    EXPECT_LE(r * r, n);
    EXPECT_GT((r + 1) * (r + 1), n);
    // recip: q = floor(2^2F / x) <=> q x <= 2^2F < (q + 1) x.
    const u128 q = log_recip(x, f), num = u128{1} << (2 * f.frac_w);
    EXPECT_LE(q * x, num);
    EXPECT_GT((q + 1) * x, num);
  }
  // Rounding to nearest of the lattice position: 2.5 steps round up, 2.49 down.
  const uint64_t k1 = uint64_t{1} << (f.frac_w - kLogPosShift);  // 1 step per unit
  EXPECT_EQ(log_pos(f.one() * 5 / 2, k1, f), 3);
  EXPECT_EQ(log_pos(f.one() * 249 / 100, k1, f), 2);
}

// The paper's case: 152 points (the double model's, the paper's stop rule),
// each one rounded to the same lattice point as the double model's at 1000
// steps per mm and per degree, X and A within 1e-6 of the double model.
TEST(LogStepperModel, PaperCurveMakesThePapersPointsOnTheDoubleModelsLattice) {
  const LogCurveParams p;
  const LogStepScale s;
  const LogRun exact = run_log_interpolation(p);
  const LogFixedCommand c = log_fixed_command(p, s, kFormat);
  ASSERT_EQ(log_fixed_check(c, kFormat, 16, 32), "");
  LogFixedStream stream(c, kFormat);
  LogFixedPoint q;
  size_t n = 0;
  double worst_mm = 0;
  while (stream.next(q)) {
    ++n;
    ASSERT_LT(q.index, exact.points.size());
    const LogPoint& e = exact.points[q.index];
    EXPECT_EQ(q.pos, log_lattice(e, p, s)) << "point " << q.index;
    worst_mm =
        std::max({worst_mm, std::abs(std::ldexp(static_cast<double>(q.x), -kFormat.frac_w) - e.x),
                  std::abs(std::ldexp(static_cast<double>(q.a), -kFormat.frac_w) - e.a)});
  }
  EXPECT_EQ(n, 152u);
  EXPECT_EQ(n, exact.count());
  EXPECT_LT(worst_mm, 1e-6);  // 0.06 steps at 1000 steps/deg
  RecordProperty("worst_x_or_a_difference", std::to_string(worst_mm));
}

// Random accepted curves (the ranges of the testbench's random commands and
// beyond, longer curves): every point within 1 step on every axis, and the
// same number of points as the double model.
TEST(LogStepperModel, RandomCurvesStayWithinOneStepOfTheDoubleModel) {
  std::mt19937_64 rng(2026);
  auto uni = [&](double lo, double hi) {
    return lo + (hi - lo) * std::uniform_real_distribution<double>(0, 1)(rng);
  };
  int accepted = 0;
  int64_t worst = 0;
  for (int k = 0; k < 300; ++k) {
    LogCurveParams p;
    p.d1_mm = uni(2, 40);
    p.spiral_deg = uni(10, 45);
    p.cone_deg = uni(2, 30);
    p.rake_deg = uni(1, 30);
    p.dl_mm = uni(0.05, 1);
    p.x_end_mm = uni(p.dl_mm, 40);
    LogStepScale s;
    s.x_per_mm = s.y_per_mm = s.z_per_mm = std::round(uni(10, 2000));
    s.a_per_deg = std::round(uni(5, 1000));
    const LogFixedCommand c = log_fixed_command(p, s, kFormat);
    if (!log_fixed_check(c, kFormat, 16, 32).empty()) continue;
    ++accepted;
    const LogRun exact = run_log_interpolation(p);
    LogFixedStream stream(c, kFormat);
    LogFixedPoint q;
    size_t n = 0;
    while (stream.next(q)) {
      ++n;
      ASSERT_LT(q.index, exact.points.size());
      const auto want = log_lattice(exact.points[q.index], p, s);
      for (size_t i = 0; i < 4; ++i)
        worst = std::max<int64_t>(worst, std::llabs(q.pos[i] - want[i]));
    }
    EXPECT_EQ(n, exact.count()) << "curve " << k;
  }
  EXPECT_GT(accepted, 150);
  EXPECT_LE(worst, 1);
  RecordProperty("accepted", std::to_string(accepted));
  RecordProperty("worst_steps", std::to_string(worst));
}

TEST(LogStepperModel, RefusedCommandsSayWhy) {
  LogCurveParams p;
  LogStepScale s;
  // d' = b dl / sqrt(1 + ab^2) >= 3/8: a wide cone on a thin cutter, long dl.
  p.d1_mm = 2;
  p.cone_deg = 40;
  p.dl_mm = 1;
  EXPECT_NE(log_fixed_check(log_fixed_command(p, s, kFormat), kFormat, 16, 32).find("3/8"),
            std::string::npos);
  // A segment wider than 16-bit deltas: 100000 steps per degree.
  p = LogCurveParams{};
  s.a_per_deg = 100000;
  EXPECT_NE(log_fixed_check(log_fixed_command(p, s, kFormat), kFormat, 16, 32).find("segment"),
            std::string::npos);
  // The curve past the integer part: q^2 grows with b X.
  p = LogCurveParams{};
  s = LogStepScale{};
  s.x_per_mm = s.y_per_mm = s.z_per_mm = s.a_per_deg = 1;
  p.cone_deg = 30;
  p.d1_mm = 2;
  p.x_end_mm = 500;
  EXPECT_NE(log_fixed_check(log_fixed_command(p, s, kFormat), kFormat, 16, 32).find("integer part"),
            std::string::npos);
}

}  // namespace
}  // namespace hwinterp::models

// The fixed_ratio core's reference model (models/fixed_ratio_model.h): its
// rate words are what the hardware's restoring dividers give, it is the
// paper's exact-frequency generator (models/fixed_ratio.h) tick for tick
// wherever rounding cannot move a step, every axis sends exactly |d_i| pulses
// in exactly M ticks, and the path error stays within the stated bound.
#include "models/fixed_ratio_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

#include "models/fixed_ratio.h"

namespace hwinterp::models {
namespace {

// The shipped FRAC_W (cmake/cores.cmake): ACC_W + 3.
constexpr int kFracWide = 35;    // fixed_ratio_n2, fixed_ratio_n4 (ACC_W = 32)
constexpr int kFracNarrow = 14;  // fixed_ratio_edge (ACC_W = 11)

uint64_t mag(int64_t v) { return static_cast<uint64_t>(std::llabs(v)); }

// The RTL's divider, bit by bit (rtl/fixed_ratio.sv): remainder |d|, each
// clock bit = rem >= M, rem -= M when set, rem <<= 1; frac_w + 1 bits, then
// the quotient rounded up when the remainder is not 0.
uint64_t restoring_divider(uint64_t d, uint64_t m, int frac_w) {
  uint64_t rem = d, quot = 0;
  for (int b = 0; b <= frac_w; ++b) {
    const bool ge = rem >= m;
    if (ge) rem -= m;
    rem <<= 1;
    quot = (quot << 1) | (ge ? 1 : 0);
  }
  return quot + (rem != 0 ? 1 : 0);
}

TEST(FixedRatioModel, RateWordsAreTheDividersRoundedUp) {
  EXPECT_EQ(fixed_ratio_rate(0, 0, 4), 0u);
  EXPECT_EQ(fixed_ratio_rate(7, 7, 4), 16u);  // the major axis: exactly 1.0
  EXPECT_EQ(fixed_ratio_rate(1, 3, 4), 6u);   // 16/3 = 5.33 -> 6
  EXPECT_EQ(fixed_ratio_rate(2, 4, 4), 8u);   // exact: no rounding
  EXPECT_EQ(fixed_ratio_rate(0, 5, 4), 0u);
  EXPECT_THROW(fixed_ratio_rate(6, 5, 4), std::invalid_argument);
  EXPECT_THROW(fixed_ratio_rate(1, 5, 0), std::invalid_argument);
  std::mt19937_64 rng(1);
  for (int n = 0; n < 20000; ++n) {
    const int acc_w = 2 + static_cast<int>(rng() % 31);  // 2..32
    const uint64_t top = uint64_t{1} << (acc_w - 1);     // |-2^(ACC_W-1)|
    const uint64_t m = 1 + rng() % top;
    const uint64_t d = rng() % 4 == 0 ? m : rng() % (m + 1);
    const int frac_w = acc_w + 3;
    const uint64_t r = fixed_ratio_rate(d, m, frac_w);
    ASSERT_EQ(r, restoring_divider(d, m, frac_w)) << d << "/" << m;
    ASSERT_LE(r, uint64_t{1} << frac_w);
    // 0 <= R/2^F - d/M < 2^-F, i.e. 0 <= R M - d 2^F < M.
    const unsigned __int128 lhs = static_cast<unsigned __int128>(r) * m;
    const unsigned __int128 exact = static_cast<unsigned __int128>(d) << frac_w;
    ASSERT_GE(lhs, exact);
    ASSERT_LT(lhs - exact, m);
  }
}

// The paper's exact-frequency generator's moves merged per tick: its major
// axis steps at times k - 1/2 (in its ticks), so tick k of the hardware
// covers the times (k - 1, k].
std::vector<FixedRatioMove> exact_per_tick(const LatticePoint& a, const LatticePoint& b) {
  const StepPath p = fixed_ratio_line(a, b);
  std::vector<FixedRatioMove> out;
  for (const StepMove& m : p.moves) {
    const auto tick = static_cast<uint64_t>(std::ceil(m.time));
    if (out.empty() || out.back().tick != tick) out.push_back({tick, {0, 0}, {}});
    out.back().step[0] += m.step[0];
    out.back().step[1] += m.step[1];
    out.back().point = m.point;
  }
  return out;
}

// Every 2-axis line with |dx|, |dy| <= 40 (all octants), at both shipped
// FRAC_W: the same moves on the same ticks as the exact generator, hence the
// same points and never a larger error than its bound (|dx| + |dy|) / (2 L).
TEST(FixedRatioModel, EveryLineUpTo40IsTheExactGeneratorTickForTick) {
  for (const int frac_w : {kFracNarrow, kFracWide}) {
    for (int64_t dx = -40; dx <= 40; ++dx) {
      for (int64_t dy = -40; dy <= 40; ++dy) {
        if (!dx && !dy) continue;
        const LatticePoint a{-3, 7}, b{-3 + dx, 7 + dy};
        const auto hw = fixed_ratio_hw_moves(a, {dx, dy}, frac_w);
        const auto ex = exact_per_tick(a, b);
        ASSERT_EQ(hw.size(), ex.size()) << dx << "," << dy;
        for (size_t k = 0; k < hw.size(); ++k) {
          ASSERT_EQ(hw[k].tick, ex[k].tick) << dx << "," << dy << " move " << k;
          ASSERT_EQ(hw[k].step, ex[k].step) << dx << "," << dy << " move " << k;
          ASSERT_EQ(hw[k].point, ex[k].point) << dx << "," << dy << " move " << k;
        }
        std::vector<LatticePoint> visited{a};
        for (const auto& m : hw) visited.push_back(m.point);
        const double e = max_line_error(visited, a, b).max_error;
        ASSERT_LE(e, fixed_ratio_error_bound(a, b) + 1e-12) << dx << "," << dy;
        ASSERT_LE(e, fixed_ratio_hw_bound({dx, dy}, frac_w).value + 1e-12) << dx << "," << dy;
      }
    }
  }
}

// Why the rate words are rounded up and not to nearest: on (6, 5) the minor
// axis's third step is due exactly on tick 3 (3 * 5/6 + 1/2 = 3); a rate
// rounded down (to nearest, at any FRAC_W where 5/6 rounds down) misses it by
// a tick, the rounded-up one never does.
TEST(FixedRatioModel, RoundingUpKeepsStepsDueExactlyOnATick) {
  for (int frac_w = 4; frac_w <= 40; ++frac_w) {
    const uint64_t up = fixed_ratio_rate(5, 6, frac_w);
    const uint64_t nearest = (((uint64_t{5} << (frac_w + 1)) / 6) + 1) >> 1;
    EXPECT_EQ(fixed_ratio_phase_steps(up, frac_w, 3), 3u) << frac_w;
    if (nearest * 6 < (uint64_t{5} << frac_w))  // rounded down
      EXPECT_EQ(fixed_ratio_phase_steps(nearest, frac_w, 3), 2u) << frac_w;
  }
}

// N axes, M up to 2^((F-1)/2) (2 M^2 <= 2^F): the hardware's counts after
// every tick are the exact rates' floor(k |d| / M + 1/2).
TEST(FixedRatioModel, ExactRatesWhereverTwoMSquaredFitsTheFraction) {
  std::mt19937_64 rng(7);
  for (const int frac_w : {kFracNarrow, kFracWide}) {
    const auto limit = static_cast<int64_t>(std::floor(std::ldexp(1.0, (frac_w - 1) / 2)));
    for (int n = 0; n < 40; ++n) {
      const size_t axes = 2 + rng() % 3;
      std::vector<int64_t> d(axes);
      for (auto& v : d) v = static_cast<int64_t>(rng() % static_cast<uint64_t>(limit + 1));
      if (n % 2) d[0] = limit;  // the largest M the statement covers
      for (auto& v : d) v = rng() % 2 ? v : -v;
      const uint64_t m = fixed_ratio_major(d);
      if (m == 0) continue;
      ASSERT_LE(2 * m * m, uint64_t{1} << frac_w);
      FixedRatioMoveStream s(LatticePoint(axes, 0), d, frac_w);
      std::vector<uint64_t> taken(axes, 0);
      FixedRatioMove mv;
      while (s.next(mv)) {
        for (size_t i = 0; i < axes; ++i) {
          taken[i] += mv.step[i] != 0;
          ASSERT_EQ(taken[i], fixed_ratio_exact_steps(mag(d[i]), m, mv.tick))
              << "axis " << i << " tick " << mv.tick << " line " << n;
        }
      }
      EXPECT_EQ(s.ticks(), m);
    }
  }
}

// Exact counts in exactly M ticks, the major axis on every tick; zero-length
// commands take one tick and no step.
TEST(FixedRatioModel, ExactCountsInMTicks) {
  FixedRatioMoveStream zero({1, 2, 3}, {0, 0, 0}, kFracNarrow);
  FixedRatioMove mv;
  EXPECT_FALSE(zero.next(mv));
  EXPECT_EQ(zero.ticks(), 1u);
  EXPECT_EQ(fixed_ratio_ticks({0, 0}), 1u);
  EXPECT_EQ(fixed_ratio_ticks({-9, 4}), 9u);
  std::mt19937_64 rng(3);
  for (int n = 0; n < 300; ++n) {
    const size_t axes = 1 + rng() % 4;
    std::vector<int64_t> d(axes);
    for (auto& v : d) v = static_cast<int64_t>(rng() % 3000) - 1500;
    const uint64_t m = fixed_ratio_major(d);
    if (m == 0) continue;
    LatticePoint end(axes, 0);
    for (size_t i = 0; i < axes; ++i) end[i] = 5 + d[i];
    FixedRatioMoveStream s(LatticePoint(axes, 5), d, kFracNarrow);
    std::vector<uint64_t> steps(axes, 0);
    uint64_t moves = 0;
    while (s.next(mv)) {
      ++moves;
      ASSERT_EQ(mv.tick, moves);  // a move on every tick: the major axis
      for (size_t i = 0; i < axes; ++i) {
        steps[i] += mv.step[i] != 0;
        if (mv.step[i]) ASSERT_EQ(mv.step[i], d[i] < 0 ? -1 : 1);
      }
    }
    EXPECT_EQ(moves, m);
    EXPECT_EQ(s.ticks(), m);
    EXPECT_TRUE(s.finished());
    for (size_t i = 0; i < axes; ++i) EXPECT_EQ(steps[i], mag(d[i]));
    EXPECT_EQ(mv.point, end);
  }
}

// At the widths' limits (|d| up to 2^(ACC_W-1), too long to step through):
// the phase count reaches exactly |d_i| at tick M and not before M - ...,
// i.e. the pulse counters never clip (FRAC_W >= ACC_W).
TEST(FixedRatioModel, CountersNeverClipAtTheWidthLimits) {
  std::mt19937_64 rng(11);
  for (const auto& [acc_w, frac_w] : {std::pair{32, kFracWide}, std::pair{11, kFracNarrow}}) {
    const uint64_t top = uint64_t{1} << (acc_w - 1);
    for (int n = 0; n < 5000; ++n) {
      const uint64_t m = n < 10 ? top - static_cast<uint64_t>(n) : 1 + rng() % top;
      const uint64_t d = n % 3 == 0 ? m - 1 : rng() % (m + 1);
      const uint64_t r = fixed_ratio_rate(d, m, frac_w);
      ASSERT_EQ(fixed_ratio_phase_steps(r, frac_w, m), d) << d << "/" << m;
      ASSERT_LE(fixed_ratio_phase_steps(r, frac_w, m - 1), d);
    }
  }
}

// With too few fraction bits (F < ACC_W) rates rounded up make a minor axis
// early, never late: the counter clips it, counts stay exact and the command
// still ends on tick M. (Hence FRAC_W >= ACC_W: the counters never act.)
TEST(FixedRatioModel, TooFewFractionBitsClipButNeverLag) {
  std::mt19937_64 rng(5);
  int clipped = 0;
  for (int n = 0; n < 400; ++n) {
    std::vector<int64_t> d{static_cast<int64_t>(rng() % 200), static_cast<int64_t>(rng() % 200),
                           static_cast<int64_t>(rng() % 200)};
    const uint64_t m = fixed_ratio_major(d);
    if (m == 0) continue;
    const int frac_w = 3;
    FixedRatioMoveStream s({0, 0, 0}, d, frac_w);
    std::vector<uint64_t> steps(3, 0);
    FixedRatioMove mv;
    while (s.next(mv))
      for (size_t i = 0; i < 3; ++i) steps[i] += mv.step[i] != 0;
    EXPECT_EQ(s.ticks(), m);
    for (size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(steps[i], mag(d[i]));
      clipped += fixed_ratio_phase_steps(s.rates()[i], frac_w, m) > mag(d[i]);
    }
  }
  EXPECT_GT(clipped, 10);
}

// The bound, exhaustively on small lines: every 3-axis line with
// |d_i| <= 10 at the shipped narrow FRAC_W and at FRAC_W = 6 (where the
// rounding term M e_i is large), every 2-axis one up to 40 at FRAC_W = 7;
// the 2-axis bound is (M/L)(1/2 + M e); no bound exceeds the worst-case one.
TEST(FixedRatioModel, BoundHoldsOnEverySmallLine) {
  for (const int frac_w : {6, kFracNarrow}) {
    double worst = 0, worst_ratio = 0;
    for (int64_t x = -10; x <= 10; ++x)
      for (int64_t y = -10; y <= 10; ++y)
        for (int64_t z = -10; z <= 10; ++z) {
          const std::vector<int64_t> d{x, y, z};
          const LatticePoint a{0, 0, 0}, b{x, y, z};
          std::vector<LatticePoint> visited{a};
          for (const auto& m : fixed_ratio_hw_moves(a, d, frac_w)) visited.push_back(m.point);
          const double e = max_line_error(visited, a, b).max_error;
          const ErrorBound bound = fixed_ratio_hw_bound(d, frac_w);
          ASSERT_TRUE(within_bound(e, bound)) << x << "," << y << "," << z << ": " << e;
          ASSERT_LE(bound.value, fixed_ratio_hw_worst_bound(3, 5, frac_w) + 1e-12);
          worst = std::max(worst, e);
          if (bound.value > 0) worst_ratio = std::max(worst_ratio, e / bound.value);
        }
    EXPECT_LT(worst, 1.0);
    EXPECT_GT(worst_ratio, 0.9);  // the bound is close to what the lines reach
    RecordProperty("worst_3axis_frac" + std::to_string(frac_w), std::to_string(worst));
  }
  const int frac_w = 7;
  for (int64_t dx = -40; dx <= 40; ++dx)
    for (int64_t dy = -40; dy <= 40; ++dy) {
      const LatticePoint a{0, 0}, b{dx, dy};
      std::vector<LatticePoint> visited{a};
      for (const auto& m : fixed_ratio_hw_moves(a, {dx, dy}, frac_w)) visited.push_back(m.point);
      const double e = max_line_error(visited, a, b).max_error;
      const double bound = fixed_ratio_hw_bound({dx, dy}, frac_w).value;
      ASSERT_LE(e, bound + 1e-12) << dx << "," << dy;
      const uint64_t m = std::max(mag(dx), mag(dy)), n = std::min(mag(dx), mag(dy));
      if (n == 0 || n == m) {
        EXPECT_EQ(bound, 0.0);
        continue;
      }
      const double len = std::hypot(static_cast<double>(dx), static_cast<double>(dy));
      const double me = static_cast<double>(fixed_ratio_rate(n, m, frac_w) * m - (n << frac_w)) /
                        std::ldexp(1.0, frac_w);
      EXPECT_NEAR(bound, static_cast<double>(m) / len * (0.5 + me), 1e-12) << dx << "," << dy;
      EXPECT_LE(bound, fixed_ratio_error_bound(a, b) +
                           std::ldexp(static_cast<double>(m * m), -frac_w) / len + 1e-12);
    }
}

// Long random lines at the shipped wide FRAC_W (M up to 10^6, 2 to 4 axes,
// near-diagonal ones among them): within the per-command bound, and the
// per-command bound within the variant's worst case, below 1 step.
TEST(FixedRatioModel, BoundHoldsOnLongLines) {
  std::mt19937_64 rng(13);
  double worst = 0;
  for (int n = 0; n < 24; ++n) {
    const size_t axes = 2 + static_cast<size_t>(n % 3);
    const int64_t len = 100000 + static_cast<int64_t>(rng() % 900001);
    std::vector<int64_t> d(axes);
    for (size_t i = 0; i < axes; ++i)
      d[i] = n % 2 ? len - static_cast<int64_t>(i ? rng() % 5 : 0)
                   : static_cast<int64_t>(rng() % static_cast<uint64_t>(len + 1));
    d[0] = len;
    for (auto& v : d) v = rng() % 2 ? v : -v;
    const LatticePoint a(axes, 0);
    LatticePoint b(axes, 0);
    for (size_t i = 0; i < axes; ++i) b[i] = d[i];
    FixedRatioMoveStream s(a, d, kFracWide);
    FixedRatioMove mv;
    double e = 0;
    while (s.next(mv)) e = std::max(e, point_line_distance(mv.point, a, b));
    ASSERT_EQ(mv.point, b);
    ASSERT_EQ(s.ticks(), static_cast<uint64_t>(len));
    const ErrorBound bound = fixed_ratio_hw_bound(d, kFracWide);
    EXPECT_TRUE(within_bound(e, bound)) << n << ": " << e << " > " << bound.value;
    EXPECT_LE(bound.value,
              fixed_ratio_hw_worst_bound(static_cast<int>(axes), 32, kFracWide) + 1e-12);
    worst = std::max(worst, e);
  }
  EXPECT_LT(worst, 1.0);
  RecordProperty("worst_long", std::to_string(worst));
}

TEST(FixedRatioModel, WorstCaseBoundsOfTheShippedVariants) {
  EXPECT_DOUBLE_EQ(fixed_ratio_hw_worst_bound(2, 32, kFracWide), 0.5625);
  EXPECT_NEAR(fixed_ratio_hw_worst_bound(4, 32, kFracWide), std::sqrt(3.0) * 0.5625, 1e-15);
  EXPECT_LT(fixed_ratio_hw_worst_bound(4, 32, kFracWide), 1.0);
  EXPECT_NEAR(fixed_ratio_hw_worst_bound(3, 11, kFracNarrow), std::sqrt(2.0) * 0.5625, 1e-15);
  // One bit fewer would not keep 4 axes below a step.
  EXPECT_GT(fixed_ratio_hw_worst_bound(4, 32, kFracWide - 1), 1.0);
  EXPECT_EQ(fixed_ratio_hw_worst_bound(1, 32, kFracWide), 0.0);
}

}  // namespace
}  // namespace hwinterp::models

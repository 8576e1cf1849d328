// The fine line interpolators of paper 004 side by side: fixed ratio, PPC,
// DDA (plain and half preload, from models/dda_line_model), minimum deviation
// and Bresenham. Common properties: exact pulse counts, exact end point,
// normal error within each method's bound, completion ticks as paper 004 counts them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "models/fixed_ratio.h"
#include "models/min_deviation.h"
#include "models/paper_data_001_003_004.h"
#include "models/ppc.h"

namespace hwinterp::models {
namespace {

namespace pd = paper;

struct Method {
  std::string name;
  std::function<StepPath(const LatticePoint&, const LatticePoint&)> run;
  std::function<double(int64_t, int64_t)> ticks;  // expected completion ticks
  // Bound check for a line; `strict` means error < bound.
  std::function<double(const LatticePoint&, const LatticePoint&)> bound;
  bool strict;
};

uint64_t mag(int64_t v) { return static_cast<uint64_t>(v < 0 ? -v : v); }

std::vector<Method> methods() {
  auto dda_ticks = [](int64_t dx, int64_t dy) {
    return static_cast<double>(dda_iterations({dx, dy}));
  };
  auto maxd = [](int64_t dx, int64_t dy) {
    return static_cast<double>(std::max(mag(dx), mag(dy)));
  };
  return {
      {"fixed ratio", fixed_ratio_line, maxd, fixed_ratio_error_bound, false},
      {"PPC", [](auto& a, auto& b) { return ppc_line(a, b); },
       [](int64_t dx, int64_t dy) { return static_cast<double>(mag(dx) + mag(dy)); },
       ppc_line_error_bound, false},
      {"DDA plain", [](auto& a, auto& b) { return dda_step_path(a, b, Preload::kZero); }, dda_ticks,
       [](auto&, auto&) { return dda_error_bound(2, Preload::kZero).value; }, true},
      {"DDA half", [](auto& a, auto& b) { return dda_step_path(a, b, Preload::kHalf); }, dda_ticks,
       [](auto&, auto&) { return dda_error_bound(2, Preload::kHalf).value; }, false},
      {"min deviation", min_deviation_line, maxd, min_deviation_error_bound, false},
      {"Bresenham", bresenham_line, maxd, min_deviation_error_bound, false},
  };
}

// Checks one line; returns its error.
double check_line(const Method& m, const LatticePoint& a, const LatticePoint& b) {
  const int64_t dx = b[0] - a[0], dy = b[1] - a[1];
  const StepPath p = m.run(a, b);
  const std::string what = m.name + " " + std::to_string(dx) + "," + std::to_string(dy);
  EXPECT_EQ(p.pulses(), (std::array<uint64_t, 2>{mag(dx), mag(dy)})) << what;
  EXPECT_EQ(p.last_point(), b) << what;
  EXPECT_DOUBLE_EQ(p.ticks, m.ticks(dx, dy)) << what;
  for (size_t k = 1; k < p.moves.size(); ++k)
    EXPECT_GE(p.moves[k].time, p.moves[k - 1].time) << what;
  const double e = p.line_error().max_error;
  const double bound = m.bound(a, b);
  // The metric loses ~1e-9 to cancellation on lines thousands of steps long.
  if (m.strict)
    EXPECT_LT(e, bound + 1e-9) << what;
  else
    EXPECT_LE(e, bound + 1e-9) << what;
  return e;
}

TEST(FineLines, PaperLines) {
  for (const Method& m : methods()) {
    for (const auto& l : pd::kRatioLines) check_line(m, {l[0], l[1]}, {l[2], l[3]});
  }
}

// Every line with |dx|, |dy| <= 40: the bounds paper 004 reports, and how
// close each method comes to them.
TEST(FineLines, AllLinesUpTo40) {
  const std::vector<Method> all = methods();
  std::vector<double> worst(all.size(), 0);
  for (int64_t dx = -40; dx <= 40; ++dx) {
    for (int64_t dy = -40; dy <= 40; ++dy) {
      const LatticePoint a{-7, 11}, b{-7 + dx, 11 + dy};
      for (size_t i = 0; i < all.size(); ++i)
        worst[i] = std::max(worst[i], check_line(all[i], a, b));
      if (HasFailure()) return;
    }
  }
  // Paper 004: fixed ratio <= 0.707, PPC < 1, DDA < 1 (0.70 half), min
  // deviation and Bresenham <= 0.5; and the bounds are nearly reached.
  EXPECT_LE(worst[0], std::sqrt(0.5) + 1e-12);
  EXPECT_GT(worst[0], 0.68);
  EXPECT_LT(worst[1], 1.0);
  EXPECT_GT(worst[1], 0.95);
  EXPECT_LT(worst[2], 1.0);
  EXPECT_GT(worst[2], 0.95);
  EXPECT_LE(worst[3], std::sqrt(0.5) + 1e-12);
  EXPECT_GT(worst[3], 0.68);
  EXPECT_LE(worst[4], 0.5 + 1e-12);
  EXPECT_GT(worst[4], 0.49);
  EXPECT_LE(worst[5], 0.5 + 1e-12);
  for (size_t i = 0; i < all.size(); ++i)
    RecordProperty("worst_" + std::to_string(i), std::to_string(worst[i]));
}

// Random long lines, all octants, with zero and axis-parallel deltas mixed in.
TEST(FineLines, RandomLines) {
  std::mt19937_64 rng(4004);
  std::uniform_int_distribution<int64_t> pos(-100000, 100000), len(-3000, 3000);
  const std::vector<Method> all = methods();
  for (int i = 0; i < 200; ++i) {
    int64_t dx = len(rng), dy = len(rng);
    if (i % 10 == 1) dx = 0;
    if (i % 10 == 2) dy = 0;
    if (i % 10 == 3) dy = (rng() % 2 ? dx : -dx);
    if (i == 4) dx = dy = 0;
    const LatticePoint a{pos(rng), pos(rng)}, b{a[0] + dx, a[1] + dy};
    for (const Method& m : all) check_line(m, a, b);
    if (HasFailure()) return;
  }
}

// Every move is stored: paths beyond kMaxStepMoves are refused up front.
TEST(FineLines, RefusesPathsTooLongToStore) {
  const LatticePoint a{0, 0}, b{int64_t{1} << 24, 1};
  EXPECT_THROW(fixed_ratio_line(a, b), std::invalid_argument);
  EXPECT_THROW(ppc_line(a, b), std::invalid_argument);
  EXPECT_THROW(min_deviation_line(a, b), std::invalid_argument);
  EXPECT_THROW(bresenham_line(a, b), std::invalid_argument);
  EXPECT_THROW(ppc_arc({0, 0}, {int64_t{1} << 22, 0}, {0, int64_t{1} << 22}, true),
               std::invalid_argument);
  EXPECT_THROW(ppc_line({0, 0}, {int64_t{1} << 29, 0}), std::invalid_argument);
}

TEST(FixedRatio, SimultaneousPulsesMakeDiagonalMoves) {
  const StepPath p = fixed_ratio_line({-10, -10}, {-40, -40});
  EXPECT_EQ(p.moves.size(), 30u);
  for (const auto& m : p.moves) EXPECT_EQ(m.step, (std::array<int, 2>{-1, -1}));
  EXPECT_EQ(p.line_error().max_error, 0);
  EXPECT_EQ(p.operations, 1u);
  // (0,0)->(20,40): x pulses at odd multiples of 1/80, y at odd multiples of
  // 1/160 of the line time (in ticks: 1, 3, 5, ... and 0.5, 1.5, ...).
  const StepPath l1 = fixed_ratio_line({0, 0}, {20, 40});
  EXPECT_DOUBLE_EQ(l1.moves[0].time, 0.5);
  EXPECT_EQ(l1.moves[0].step, (std::array<int, 2>{0, 1}));
  EXPECT_DOUBLE_EQ(l1.moves[1].time, 1.0);
  EXPECT_EQ(l1.moves[1].step, (std::array<int, 2>{1, 0}));
}

// Integer clock dividers: the realised rate ratio differs from the slope, the
// axes drift apart and the error grows; it stays within the divider bound
// stated at the generator's own clock.
TEST(FixedRatio, IntegerDividerAtOneMegahertz) {
  const LatticePoint a{0, 0}, b{20, 40};
  const DividerPlan plan = fixed_ratio_divider_plan(a, b, pd::kRatioVelocity, 1e6);
  EXPECT_EQ(plan.half_period[0], 5);  // 100 kHz: exact
  EXPECT_EQ(plan.half_period[1], 3);  // 200 kHz wants 2.5 clocks: 3 -> 166.7 kHz
  const StepPath p = fixed_ratio_divider_line(a, b, pd::kRatioVelocity, 1e6);
  EXPECT_EQ(p.pulses(), (std::array<uint64_t, 2>{20, 40}));
  EXPECT_TRUE(p.ends_on_end());
  const double e = p.line_error().max_error;
  EXPECT_NEAR(e, 3.1, 0.05);  // reproduced: 3.1 steps on line 1 at 1 MHz
  EXPECT_GT(e, fixed_ratio_error_bound(a, b));
  EXPECT_LE(e, fixed_ratio_divider_bound(a, b, pd::kRatioVelocity, 1e6) + 1e-12);
  EXPECT_EQ(p.ticks, 240);  // 40 y pulses of 6 clocks
}

TEST(FixedRatio, DividerBoundHoldsForRandomLinesAndClocks) {
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int64_t> len(-200, 200);
  const double clocks[] = {1e6, 2.5e6, 7.3e6, 50e6};
  double worst_ratio = 0;
  for (int i = 0; i < 300; ++i) {
    const LatticePoint a{len(rng), len(rng)}, b{a[0] + len(rng), a[1] + len(rng)};
    const double clk = clocks[i % 4];
    const double v = 1000;  // up to 200 kHz per axis
    const StepPath p = fixed_ratio_divider_line(a, b, v, clk);
    ASSERT_EQ(p.pulses(), (std::array<uint64_t, 2>{mag(b[0] - a[0]), mag(b[1] - a[1])}));
    ASSERT_TRUE(p.ends_on_end());
    const double bound = fixed_ratio_divider_bound(a, b, v, clk);
    const double e = p.line_error().max_error;
    ASSERT_LE(e, bound + 1e-9) << i;
    if (bound > 0) worst_ratio = std::max(worst_ratio, e / bound);
  }
  EXPECT_GT(worst_ratio, 0.7);  // the bound is not vacuous
}

// When the clock divides every axis frequency exactly, the divider generator
// is the exact one, move for move.
TEST(FixedRatio, ExactDividersReproduceExactFrequencies) {
  const LatticePoint a{3, 4}, b{3 + 12, 4 - 8};
  // v = 1000: 12 kHz and 8 kHz; 48 MHz / (2 * 12 kHz) = 2000, / (2 * 8 kHz) = 3000.
  const StepPath d = fixed_ratio_divider_line(a, b, 1000, 48e6);
  const StepPath e = fixed_ratio_line(a, b);
  EXPECT_EQ(d.visited(), e.visited());
  EXPECT_NEAR(fixed_ratio_divider_bound(a, b, 1000, 48e6), fixed_ratio_error_bound(a, b), 1e-12);
}

TEST(FixedRatio, RejectsImpossibleClocks) {
  EXPECT_THROW(fixed_ratio_divider_line({0, 0}, {20, 40}, 5000, 1e5), std::invalid_argument);
  EXPECT_THROW(fixed_ratio_divider_line({0, 0}, {20, 40}, 0, 1e6), std::invalid_argument);
  EXPECT_THROW(fixed_ratio_divider_line({0, 0}, {20, 40}, 5000, -1), std::invalid_argument);
}

// Away from ties (an odd major delta can't produce one) the two forms walk
// the same path; with ties they differ only in the tie-break.
TEST(MinDeviation, SameAsBresenhamWithoutTies) {
  int differing = 0;
  for (int64_t dx = -25; dx <= 25; ++dx) {
    for (int64_t dy = -25; dy <= 25; ++dy) {
      const LatticePoint a{0, 0}, b{dx, dy};
      const auto md = min_deviation_line(a, b).visited();
      const auto br = bresenham_line(a, b).visited();
      if (std::max(mag(dx), mag(dy)) % 2 == 1) {
        ASSERT_EQ(md, br) << dx << "," << dy;
      } else {
        differing += md != br;
      }
    }
  }
  EXPECT_GT(differing, 0);
}

}  // namespace
}  // namespace hwinterp::models

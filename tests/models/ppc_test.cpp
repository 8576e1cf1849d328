#include "models/ppc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "models/paper_data_001_003_004.h"

namespace hwinterp::models {
namespace {

namespace pd = paper;

TEST(Ppc, PaperLine) {
  const StepPath p = ppc_line({0, 0}, {4, 3});
  ASSERT_EQ(p.moves.size(), pd::kPpcLine.size());
  for (size_t k = 0; k < p.moves.size(); ++k)
    EXPECT_EQ(p.moves[k].point, (LatticePoint{pd::kPpcLine[k][0], pd::kPpcLine[k][1]})) << k;
  EXPECT_EQ(p.operations, 7u);
  EXPECT_EQ(p.ticks, 7);
}

TEST(Ppc, PaperArc) {
  const StepPath p = ppc_arc({0, 0}, {4, 0}, {0, 4}, true);
  ASSERT_EQ(p.moves.size(), pd::kPpcArc.size());
  for (size_t k = 0; k < p.moves.size(); ++k)
    EXPECT_EQ(p.moves[k].point, (LatticePoint{pd::kPpcArc[k][0], pd::kPpcArc[k][1]})) << k;
  EXPECT_EQ(p.operations, 8u);
}

TEST(Ppc, SixtyOperationsOnLine1) {
  const auto& l = pd::kRatioLines[0];
  EXPECT_EQ(ppc_line({l[0], l[1]}, {l[2], l[3]}).operations,
            static_cast<uint64_t>(pd::kPpcOperationsLine1));
}

// The bare rule steps x first on a vertical line and misses the end; the
// guarded rule does not, and agrees with the bare one whenever dx != 0.
TEST(Ppc, VerticalLine) {
  const StepPath bare = ppc_line({0, 0}, {0, 3}, PpcLineRule::kTextbook);
  EXPECT_FALSE(bare.ends_on_end());
  EXPECT_EQ(bare.moves.front().point, (LatticePoint{1, 0}));
  const StepPath guarded = ppc_line({0, 0}, {0, 3});
  EXPECT_TRUE(guarded.ends_on_end());
  EXPECT_EQ(guarded.pulses(), (std::array<uint64_t, 2>{0, 3}));
  EXPECT_EQ(guarded.line_error().max_error, 0);
  for (int64_t dx = -6; dx <= 6; ++dx) {
    if (dx == 0) continue;
    for (int64_t dy = -6; dy <= 6; ++dy) {
      const StepPath a = ppc_line({1, 2}, {1 + dx, 2 + dy}, PpcLineRule::kTextbook);
      const StepPath b = ppc_line({1, 2}, {1 + dx, 2 + dy});
      ASSERT_EQ(a.visited(), b.visited()) << dx << "," << dy;
    }
  }
}

// All lattice points on the circle x^2 + y^2 = r2.
std::vector<LatticePoint> circle_points(int64_t r2) {
  std::vector<LatticePoint> out;
  const auto r = static_cast<int64_t>(std::floor(std::sqrt(static_cast<double>(r2))));
  for (int64_t x = -r; x <= r; ++x) {
    const int64_t y2 = r2 - x * x;
    const auto y = static_cast<int64_t>(std::llround(std::sqrt(static_cast<double>(y2))));
    if (y * y != y2) continue;
    out.push_back({x, y});
    if (y != 0) out.push_back({x, -y});
  }
  return out;
}

// Random arcs (seeded): CW and CCW, any start and end on the circle (so
// quadrant crossings of every kind, full circles when start == end). Exact
// end; one axis per step; every visited point within 1 step of the circle
// (radial error | |p - c| - R | <= 1, the bound tested; 1 is reached, e.g. by
// the paper arc's (3,0) on R = 4, where F = 0 at the start steps inwards).
TEST(Ppc, RandomArcsExactEndWithinOneStep) {
  std::mt19937_64 rng(12345);
  std::uniform_int_distribution<int64_t> coord(-50, 50), big(1, 40);
  double worst = 0;
  int arcs = 0, crossing = 0;
  for (int i = 0; i < 400; ++i) {
    const int64_t sx = big(rng) * (rng() % 2 ? 1 : -1), sy = coord(rng) % 41;
    const int64_t r2 = sx * sx + sy * sy;
    if (r2 < 2) continue;  // R = 1 is refused (its path would cross the centre)
    const auto on = circle_points(r2);
    const LatticePoint c{coord(rng), coord(rng)};
    const LatticePoint rel_end = on[rng() % on.size()];
    const LatticePoint start{c[0] + sx, c[1] + sy}, end{c[0] + rel_end[0], c[1] + rel_end[1]};
    for (const bool ccw : {true, false}) {
      const StepPath p = ppc_arc(c, start, end, ccw);
      ++arcs;
      ASSERT_TRUE(p.ends_on_end()) << "arc " << i;
      ASSERT_EQ(p.operations, p.moves.size());
      bool quadrant_change = false;
      for (size_t k = 0; k < p.moves.size(); ++k) {
        const auto& m = p.moves[k];
        ASSERT_EQ(std::abs(m.step[0]) + std::abs(m.step[1]), 1);
        const LatticePoint& prev = k ? p.moves[k - 1].point : start;
        if ((prev[0] - c[0]) * (m.point[0] - c[0]) <= 0 ||
            (prev[1] - c[1]) * (m.point[1] - c[1]) <= 0)
          quadrant_change = true;
      }
      crossing += quadrant_change;
      const double e = ppc_arc_radial_error(p, c);
      ASSERT_LE(e, 1.0 + 1e-12) << "arc " << i << " ccw " << ccw;
      worst = std::max(worst, e);
    }
  }
  EXPECT_GT(crossing, arcs / 2);  // most arcs cross an axis
  RecordProperty("worst_radial_error", std::to_string(worst));
}

// Exhaustive on small circles: every lattice start with |x|, |y| <= 12
// (R^2 >= 2), every lattice end on its circle, both directions.
TEST(Ppc, EveryArcOnSmallCircles) {
  int arcs = 0;
  for (int64_t sx = -12; sx <= 12; ++sx) {
    for (int64_t sy = -12; sy <= 12; ++sy) {
      const int64_t r2 = sx * sx + sy * sy;
      if (r2 < 2) continue;
      for (const LatticePoint& e : circle_points(r2)) {
        for (const bool ccw : {true, false}) {
          const StepPath p = ppc_arc({0, 0}, {sx, sy}, e, ccw);
          ASSERT_TRUE(p.ends_on_end());
          ASSERT_LE(ppc_arc_radial_error(p, {0, 0}), 1.0 + 1e-12);
          ++arcs;
        }
      }
    }
  }
  RecordProperty("arcs", arcs);
}

TEST(Ppc, FullCircleAndDirections) {
  const StepPath ccw = ppc_arc({0, 0}, {5, 0}, {5, 0}, true);
  const StepPath cw = ppc_arc({0, 0}, {5, 0}, {5, 0}, false);
  // A full circle of radius 5 travels 4 * 2R = 40 steps.
  EXPECT_EQ(ccw.moves.size(), 40u);
  EXPECT_EQ(cw.moves.size(), 40u);
  // F = 0 at the start: both step inwards first, then away on their own side.
  EXPECT_EQ(ccw.moves.front().point, (LatticePoint{4, 0}));
  EXPECT_EQ(ccw.moves[1].point, (LatticePoint{4, 1}));
  EXPECT_EQ(cw.moves.front().point, (LatticePoint{4, 0}));
  EXPECT_EQ(cw.moves[1].point, (LatticePoint{4, -1}));
  // CW (0,4)->(4,0) stays in one quadrant: |dx| + |dy| steps.
  const StepPath back = ppc_arc({0, 0}, {0, 4}, {4, 0}, false);
  EXPECT_EQ(back.moves.size(), 8u);
  EXPECT_TRUE(back.ends_on_end());
}

TEST(Ppc, RejectsBadArcs) {
  EXPECT_THROW(ppc_arc({0, 0}, {0, 0}, {0, 0}, true), std::invalid_argument);
  EXPECT_THROW(ppc_arc({0, 0}, {1, 0}, {0, 1}, true), std::invalid_argument);
  EXPECT_THROW(ppc_arc({0, 0}, {4, 0}, {3, 3}, true), std::invalid_argument);
  EXPECT_THROW(ppc_line({0, 0, 0}, {1, 2, 3}), std::invalid_argument);
}

}  // namespace
}  // namespace hwinterp::models

#include "models/ppc.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// Rule M accepts what the on-circle arc refused (R^2 < 2, ends off the
// circle) and ends exactly on the end; 3-axis points are still refused.
TEST(Ppc, RejectsBadArcs) {
  EXPECT_TRUE(ppc_arc({0, 0}, {0, 0}, {0, 0}, true).ends_on_end());
  EXPECT_TRUE(ppc_arc({0, 0}, {1, 0}, {0, 1}, true).ends_on_end());
  EXPECT_TRUE(ppc_arc({0, 0}, {4, 0}, {3, 3}, true).ends_on_end());
  EXPECT_THROW(ppc_line({0, 0, 0}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(ppc_arc({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, true), std::invalid_argument);
  EXPECT_THROW(PpcArcStream({0, 0}, {int64_t{1} << 30, 0}, {0, 0}, true), std::invalid_argument);
}

// --- streams and rule M ------------------------------------------------------

// The PPC line decided afresh at every point from the closed form
// F = y |dx| - x |dy| (not the incremental update the stream uses).
std::vector<LatticePoint> closed_form_line(const LatticePoint& a, const LatticePoint& b) {
  const int64_t dx = b[0] - a[0], dy = b[1] - a[1];
  const int64_t ax = std::llabs(dx), ay = std::llabs(dy);
  std::vector<LatticePoint> out;
  LatticePoint at = a;
  for (int64_t x = 0, y = 0; x + y < ax + ay;) {
    const bool step_x = (y * ax - x * ay >= 0 && x < ax) || y == ay;
    if (step_x) {
      ++x;
      at[0] += dx < 0 ? -1 : 1;
    } else {
      ++y;
      at[1] += dy < 0 ? -1 : 1;
    }
    out.push_back(at);
  }
  return out;
}

std::vector<LatticePoint> points_of(const StepPath& p) {
  std::vector<LatticePoint> out;
  for (const auto& m : p.moves) out.push_back(m.point);
  return out;
}

// The on-circle PPC arc as it was before rule M: run until the end is reached.
std::vector<LatticePoint> legacy_on_circle_arc(const LatticePoint& c, const LatticePoint& s,
                                               const LatticePoint& e, bool ccw) {
  auto sign_of = [](int64_t v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); };
  int64_t x = s[0] - c[0], y = s[1] - c[1];
  const int64_t r2 = x * x + y * y;
  LatticePoint at = s;
  std::vector<LatticePoint> out;
  do {
    int qx, qy;
    if (ccw) {
      qy = y != 0 ? sign_of(y) : sign_of(x);
      qx = x != 0 ? sign_of(x) : -sign_of(y);
    } else {
      qy = y != 0 ? sign_of(y) : -sign_of(x);
      qx = x != 0 ? sign_of(x) : sign_of(y);
    }
    const int mx = ccw ? -qy : qy, my = ccw ? qx : -qx;
    const bool step_x = (x * x + y * y - r2 >= 0) == (mx == -qx);
    if (step_x) {
      x += mx;
      at[0] += mx;
    } else {
      y += my;
      at[1] += my;
    }
    out.push_back(at);
  } while (at != e && out.size() < 100000);
  return out;
}

TEST(PpcStreams, LineStreamEqualsStepPathAndClosedForm) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int64_t> d(-60, 60);
  for (int i = 0; i < 2000; ++i) {
    const LatticePoint a{d(rng), d(rng)};
    LatticePoint b{a[0] + d(rng), a[1] + d(rng)};
    if (i % 7 == 0) b[0] = a[0];   // vertical
    if (i % 11 == 0) b[1] = a[1];  // horizontal
    if (i % 97 == 0) b = a;        // zero length
    PpcLineStream stream(a, b);
    std::vector<LatticePoint> streamed;
    StepMove m;
    uint64_t op = 0;
    while (stream.next(m)) {
      ASSERT_EQ(m.time, static_cast<double>(++op));
      streamed.push_back(m.point);
    }
    ASSERT_EQ(streamed, points_of(ppc_line(a, b))) << i;
    ASSERT_EQ(streamed, closed_form_line(a, b)) << i;
    ASSERT_EQ(op, stream.total());
  }
}

TEST(PpcStreams, ArcStreamEqualsStepPath) {
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<int64_t> d(-30, 30);
  for (int i = 0; i < 2000; ++i) {
    const LatticePoint c{d(rng), d(rng)}, s{d(rng), d(rng)}, e{d(rng), d(rng)};
    const bool ccw = i % 2;
    PpcArcStream stream(c, s, e, ccw);
    std::vector<LatticePoint> streamed;
    double last_op = 0;
    for (StepMove m; stream.next(m);) {
      ASSERT_GT(m.time, last_op);  // operations strictly increase
      last_op = m.time;
      streamed.push_back(m.point);
    }
    const StepPath p = ppc_arc(c, s, e, ccw);
    ASSERT_EQ(streamed, points_of(p)) << i;
    ASSERT_EQ(stream.operations(), p.operations);
    ASSERT_TRUE(p.ends_on_end()) << i;
  }
}

// Every start with |s| <= 12 and every end on its circle, both directions:
// rule M gives exactly the moves of the plain on-circle PPC arc run until it
// first reaches the end, with no closing line (operations == moves).
TEST(PpcRuleM, OnCircleArcsUnchanged) {
  int arcs = 0;
  for (int64_t sx = -12; sx <= 12; ++sx)
    for (int64_t sy = -12; sy <= 12; ++sy) {
      const int64_t r2 = sx * sx + sy * sy;
      if (r2 < 2 || r2 > 144) continue;
      for (const LatticePoint& e : circle_points(r2))
        for (const bool ccw : {true, false}) {
          const StepPath p = ppc_arc({0, 0}, {sx, sy}, e, ccw);
          ASSERT_EQ(points_of(p), legacy_on_circle_arc({0, 0}, {sx, sy}, e, ccw))
              << sx << "," << sy << " -> " << e[0] << "," << e[1] << " ccw " << ccw;
          ASSERT_EQ(p.operations, p.moves.size());
          ++arcs;
        }
    }
  EXPECT_GT(arcs, 5000);
}

// Every lattice start and end with |s|, |e| <= 12 and a radius mismatch
// ||e| - |s|| <= 3, both directions: exact end, one axis a move, every
// visited point within 1 + |re - rs| of the ideal spiral. The bound is
// reached exactly (on-circle arcs: radial error 1); over the off-circle arcs
// the worst point stays 0.0062 below it (s = (-8,0), e = (-4,-7), CW, at
// (0,-7)).
TEST(PpcRuleM, EveryArcSmallWithinBound) {
  std::vector<LatticePoint> pts;
  for (int64_t x = -12; x <= 12; ++x)
    for (int64_t y = -12; y <= 12; ++y)
      if (x * x + y * y <= 144) pts.push_back({x, y});
  int64_t arcs = 0, closing = 0;
  double worst = 0, worst_excess = -1e9, worst_excess_off = -1e9;
  for (const auto& s : pts)
    for (const auto& e : pts) {
      const double rs = std::hypot(s[0], s[1]), re = std::hypot(e[0], e[1]);
      if (std::abs(re - rs) > 3) continue;
      const bool on_circle = s[0] * s[0] + s[1] * s[1] == e[0] * e[0] + e[1] * e[1];
      for (const bool ccw : {true, false}) {
        PpcArcStream stream({0, 0}, s, e, ccw);
        const PpcArcIdeal ideal({0, 0}, s, e, ccw);
        const double bound = ideal.bound().value;
        ASSERT_NEAR(bound, 1 + std::abs(re - rs), 1e-12);
        LatticePoint at = s;
        uint64_t moves = 0;
        for (StepMove m; stream.next(m); ++moves) {
          ASSERT_EQ(std::abs(m.step[0]) + std::abs(m.step[1]), 1);
          at[0] += m.step[0];
          at[1] += m.step[1];
          ASSERT_EQ(at, m.point);
          const double err = ideal.error(at);
          ASSERT_TRUE(within_bound(err, ideal.bound()))
              << "s " << s[0] << "," << s[1] << " e " << e[0] << "," << e[1] << " ccw " << ccw
              << " at " << at[0] << "," << at[1] << ": " << err << " > " << bound;
          worst = std::max(worst, err);
          worst_excess = std::max(worst_excess, err - bound);
          if (!on_circle) worst_excess_off = std::max(worst_excess_off, err - bound);
        }
        ASSERT_EQ(at, e) << "s " << s[0] << "," << s[1] << " e " << e[0] << "," << e[1];
        closing += stream.operations() != moves;
        ++arcs;
      }
    }
  EXPECT_GT(arcs, 200000);
  EXPECT_GT(closing, arcs / 2);           // most off-circle arcs end on a closing line
  EXPECT_NEAR(worst_excess, 0.0, 1e-12);  // the bound is reached...
  EXPECT_LT(worst_excess_off, -0.006);    // ...and off the circle stays just below it
  EXPECT_GT(worst_excess_off, -0.007);
  RecordProperty("arcs", std::to_string(arcs));
  RecordProperty("worst_deviation", std::to_string(worst));
  RecordProperty("worst_off_circle_excess", std::to_string(worst_excess_off));
}

// An end rounded from a real point at angle `a` on the circle of radius r,
// pushed `off` steps radially.
LatticePoint rounded_end(double r, double a, double off) {
  return {std::llround((r + off) * std::cos(a)), std::llround((r + off) * std::sin(a))};
}

// Random centres, radii up to 3000 with any sweep (full laps included) and
// radii up to 2^23 with short sweeps; ends on the circle or rounded from a
// real point on it, sometimes a few steps off; both directions.
TEST(PpcRuleM, RandomLargeWithinBound) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(0, 1);
  double worst_excess = -1e9;
  int arcs = 0;
  for (int i = 0; i < 600; ++i) {
    const bool huge = i % 3 == 0;
    const double r = huge ? 1e5 + unit(rng) * ((1 << 23) - 1e5) : 2 + unit(rng) * 3000;
    const double a0 = unit(rng) * 2 * M_PI;
    // Huge radii: at most ~3000 steps of arc.
    const double sweep = huge ? (20 + unit(rng) * 2000) / r : unit(rng) * 2 * M_PI;
    const bool ccw = i % 2;
    const double a1 = a0 + (ccw ? sweep : -sweep);
    const double off = i % 4 == 0 ? std::round((unit(rng) - 0.5) * 6) : 0;
    const LatticePoint c{std::llround((unit(rng) - 0.5) * 2e6),
                         std::llround((unit(rng) - 0.5) * 2e6)};
    const LatticePoint rs = rounded_end(r, a0, 0), re = rounded_end(r, a1, off);
    const LatticePoint s{c[0] + rs[0], c[1] + rs[1]}, e{c[0] + re[0], c[1] + re[1]};
    PpcArcStream stream(c, s, e, ccw);
    const PpcArcIdeal ideal(c, s, e, ccw);
    LatticePoint at = s;
    for (StepMove m; stream.next(m);) {
      at = m.point;
      const double err = ideal.error(at);
      ASSERT_TRUE(within_bound(err, ideal.bound())) << i << ": " << err;
      worst_excess = std::max(worst_excess, err - ideal.bound().value);
    }
    ASSERT_EQ(at, e) << i;
    ASSERT_LE(stream.operations(), stream.operation_bound());
    ++arcs;
  }
  RecordProperty("worst_excess", std::to_string(worst_excess));
}

TEST(PpcRuleM, DegenerateCommandsAreLines) {
  // Start on the centre, start one step from it, end on the centre.
  for (const auto& [s, e] : std::vector<std::pair<LatticePoint, LatticePoint>>{
           {{0, 0}, {5, -3}}, {{1, 0}, {-4, 2}}, {{0, -1}, {0, 6}}, {{7, 2}, {0, 0}}}) {
    for (const bool ccw : {true, false}) {
      PpcArcStream stream({0, 0}, s, e, ccw);
      EXPECT_TRUE(stream.degenerate());
      const StepPath p = ppc_arc({0, 0}, s, e, ccw);
      EXPECT_EQ(points_of(p), closed_form_line(s, e));
      EXPECT_EQ(p.operations, p.moves.size() + 1);  // the switch to the line
    }
  }
  // A zero-length degenerate command: the switch and one empty operation.
  const StepPath z = ppc_arc({3, 3}, {3, 4}, {3, 4}, true);
  EXPECT_TRUE(z.moves.empty());
  EXPECT_EQ(z.operations, 2u);
  EXPECT_FALSE(PpcArcStream({0, 0}, {1, 1}, {1, 1}, true).degenerate());  // R^2 = 2 is an arc
}

TEST(PpcRuleM, LapsFullCirclesAndOffCircleEnds) {
  // Same quadrant ahead: no lap; behind on both axes: a full lap first.
  EXPECT_EQ(PpcArcStream({0, 0}, {5, 0}, {3, 4}, true).laps(), 0);
  EXPECT_EQ(PpcArcStream({0, 0}, {3, 4}, {5, 0}, true).laps(), 4);
  EXPECT_EQ(PpcArcStream({0, 0}, {4, 0}, {0, 4}, true).laps(), 1);
  EXPECT_EQ(PpcArcStream({0, 0}, {4, 0}, {0, 4}, false).laps(), 3);
  // Full circles (start == end), on- and off-axis starts: 8R steps for R = 5.
  for (const LatticePoint& s : {LatticePoint{5, 0}, LatticePoint{3, 4}, LatticePoint{-4, -3}})
    for (const bool ccw : {true, false}) {
      PpcArcStream stream({0, 0}, s, s, ccw);
      EXPECT_EQ(stream.laps(), 4);
      const StepPath p = ppc_arc({0, 0}, s, s, ccw);
      EXPECT_EQ(p.moves.size(), 40u);
      EXPECT_TRUE(p.ends_on_end());
    }
  // End one step outside, behind on both axes: a full lap, then the closing line.
  const StepPath lap = ppc_arc({0, 0}, {5, 0}, {6, 0}, true);
  EXPECT_TRUE(lap.ends_on_end());
  EXPECT_GT(lap.moves.size(), 40u);
  EXPECT_EQ(lap.operations, lap.moves.size() + 1);
  // Mixed (behind on x, ahead on y) counts as ahead: a short path.
  PpcArcStream mixed({0, 0}, {5, 0}, {6, 1}, true);
  EXPECT_EQ(mixed.laps(), 0);
  const StepPath m = ppc_arc({0, 0}, {5, 0}, {6, 1}, true);
  EXPECT_TRUE(m.ends_on_end());
  EXPECT_LE(m.moves.size(), 4u);
  // The paper arc's end pulled one step out: the arc phase, then a short line.
  const StepPath out = ppc_arc({0, 0}, {4, 0}, {0, 5}, true);
  EXPECT_TRUE(out.ends_on_end());
  EXPECT_EQ(out.operations, out.moves.size() + 1);
  for (size_t k = 0; k < 4; ++k)  // (3,0),(3,1),(3,2),(3,3) as on the circle
    EXPECT_EQ(out.moves[k].point, (LatticePoint{pd::kPpcArc[k][0], pd::kPpcArc[k][1]}));
}

TEST(PpcRuleM, SpiralMetric) {
  // On one circle it is the radial error.
  EXPECT_NEAR(ppc_arc_spiral_error({3, 0}, {0, 0}, {4, 0}, {0, 4}, true), 1.0, 1e-12);
  EXPECT_NEAR(ppc_arc_spiral_error({3, 3}, {0, 0}, {4, 0}, {0, 4}, true), std::sqrt(18.0) - 4,
              1e-12);
  // Radius 4 -> 8 over a quarter turn: half way the spiral is at 6.
  EXPECT_NEAR(ppc_arc_spiral_error({4, 4}, {0, 0}, {4, 0}, {0, 8}, true), 6 - std::sqrt(32.0),
              1e-12);
  // CW measures the other way round: (4,0) -> (0,8) CW sweeps 3/4 of a turn;
  // (4,-4) is 1/6 of it, (4,4) lies past the end (the spiral has reached 8).
  EXPECT_NEAR(ppc_arc_spiral_error({4, -4}, {0, 0}, {4, 0}, {0, 8}, false),
              std::sqrt(32.0) - (4 + 4.0 / 6), 1e-12);
  EXPECT_NEAR(ppc_arc_spiral_error({4, 4}, {0, 0}, {4, 0}, {0, 8}, false), 8 - std::sqrt(32.0),
              1e-12);
  EXPECT_DOUBLE_EQ(ppc_arc_error_bound({0, 0}, {4, 0}, {0, 8}).value, 5.0);
  EXPECT_FALSE(ppc_arc_error_bound({0, 0}, {4, 0}, {0, 8}).strict);
  // Equal directions: theta is a whole turn (a full circle has no radius change).
  EXPECT_NEAR(PpcArcIdeal({0, 0}, {5, 0}, {5, 0}, true).theta(), 2 * M_PI, 1e-15);
}

}  // namespace
}  // namespace hwinterp::models

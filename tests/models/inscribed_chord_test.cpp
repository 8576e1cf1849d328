#include "models/inscribed_chord.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "models/paper_data_001_003_004.h"

namespace hwinterp::models {
namespace {

namespace pd = paper;

// Table I: r = 1 on (0,0)->(4,3): 5 chords of exactly 1, ending on (4,3).
TEST(InscribedChord, PaperTable1Line) {
  const ChordResult line = inscribed_chord_line({0, 0}, {4, 3}, 1.0);
  ASSERT_EQ(line.steps.size(), static_cast<size_t>(pd::kTable3ChordLine));
  Vec2 center(0, 0);
  for (size_t k = 0; k < line.steps.size(); ++k) {
    EXPECT_NEAR((line.steps[k].center - center).norm(), 0, 1e-15) << k;
    EXPECT_NEAR(line.steps[k].point.x(), pd::kChordTable1[k][0], 1e-12) << k;
    EXPECT_NEAR(line.steps[k].point.y(), pd::kChordTable1[k][1], 1e-12) << k;
    EXPECT_NEAR(line.steps[k].chord, 1.0, 1e-12);
    center = line.steps[k].point;
  }
  EXPECT_TRUE(line.exact_end);
  EXPECT_EQ(line.steps.back().point, Vec2(4, 3));  // exactly, not nearly
  EXPECT_EQ(line.overshoot, 0);
}

// Table II: r = 0.9 on the CCW arc (4,0)->(0,4), R = 4: the printed points
// are the exact chain truncated to 3 decimals; the 7th passes the end.
TEST(InscribedChord, PaperTable2Arc) {
  const ChordResult arc = inscribed_chord_arc({0, 0}, {4, 0}, {0, 4}, true, 0.9);
  ASSERT_EQ(arc.steps.size(), static_cast<size_t>(pd::kTable3ChordArc));
  for (size_t k = 0; k < arc.steps.size(); ++k) {
    const Vec2& p = arc.steps[k].point;
    EXPECT_NEAR(truncate_to(p.x(), 3), pd::kChordTable2[k][0], 1e-12) << "point " << k + 1;
    EXPECT_NEAR(truncate_to(p.y(), 3), pd::kChordTable2[k][1], 1e-12) << "point " << k + 1;
    EXPECT_NEAR(p.norm(), 4.0, 1e-12);
    EXPECT_NEAR(arc.steps[k].chord, 0.9, 1e-12);
  }
  const Vec2& last = arc.steps.back().point;
  EXPECT_NEAR(last.x(), -0.030180, 5e-7);
  EXPECT_NEAR(last.y(), 3.999886, 5e-7);
  EXPECT_FALSE(arc.exact_end);
  EXPECT_NEAR(arc.overshoot, 0.03, 0.0005);
  // Rounding (not truncating) would print 3.899 for point 1: the table truncates.
  EXPECT_NE(std::round(arc.steps[0].point.x() * 1000) / 1000, pd::kChordTable2[0][0]);
}

TEST(InscribedChord, TruncateTo) {
  EXPECT_EQ(truncate_to(3.8987, 3), 3.898);
  EXPECT_EQ(truncate_to(-0.03018, 3), -0.030);
  EXPECT_EQ(truncate_to(2.48, 3), 2.48);
}

// Clamping ends on the end point with a short last chord.
TEST(InscribedChord, ClampEndsOnTheEnd) {
  const ChordResult arc = inscribed_chord_arc({0, 0}, {4, 0}, {0, 4}, true, 0.9, ChordEnd::kClamp);
  ASSERT_EQ(arc.steps.size(), 7u);
  EXPECT_TRUE(arc.exact_end);
  EXPECT_NEAR((arc.steps.back().point - Vec2(0, 4)).norm(), 0, 1e-15);
  EXPECT_LT(arc.steps.back().chord, 0.9);
  const ChordResult line = inscribed_chord_line({0, 0}, {4, 3.5}, 1.0, ChordEnd::kClamp);
  EXPECT_EQ(line.steps.back().point, Vec2(4, 3.5));
  const ChordResult over = inscribed_chord_line({0, 0}, {4, 3.5}, 1.0);
  EXPECT_GT(over.overshoot, 0);
  EXPECT_LT(over.overshoot, 1.0);
}

// The general root finder on LineCurve / ArcCurve reproduces the closed forms.
TEST(InscribedChord, GeneralCurveMatchesClosedForms) {
  const ChordResult line = inscribed_chord(LineCurve({0, 0}, {4, 3}), 1.0);
  ASSERT_EQ(line.steps.size(), 5u);
  for (size_t k = 0; k < 5; ++k)
    EXPECT_NEAR((line.steps[k].point - Vec2(pd::kChordTable1[k][0], pd::kChordTable1[k][1])).norm(),
                0, 1e-12);
  EXPECT_TRUE(line.exact_end);

  std::mt19937_64 rng(7);
  auto uni = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  for (int i = 0; i < 40; ++i) {
    const Vec2 c(uni(-10, 10), uni(-10, 10));
    const double radius = uni(0.5, 20), a0 = uni(-M_PI, M_PI), sweep = uni(0.1, 6.2);
    const bool ccw = i % 2 == 0;
    const double a1 = a0 + (ccw ? sweep : -sweep);
    const double r = uni(0.05, 1.5) * radius * std::min(1.0, sweep);
    const Vec2 s = c + radius * Vec2(std::cos(a0), std::sin(a0));
    const Vec2 e = c + radius * Vec2(std::cos(a1), std::sin(a1));
    for (const ChordEnd mode : {ChordEnd::kOvershoot, ChordEnd::kClamp}) {
      const ChordResult closed = inscribed_chord_arc(c, s, e, ccw, r, mode);
      const ChordResult general = inscribed_chord(ArcCurve(c, radius, a0, a1), r, mode);
      ASSERT_EQ(closed.steps.size(), general.steps.size()) << "case " << i;
      for (size_t k = 0; k < closed.steps.size(); ++k)
        EXPECT_NEAR((closed.steps[k].point - general.steps[k].point).norm(), 0, 1e-9 * radius)
            << "case " << i << " point " << k;
      EXPECT_EQ(closed.exact_end, general.exact_end);
      EXPECT_NEAR(closed.overshoot, general.overshoot, 1e-9 * radius);
      EXPECT_NEAR(closed.max_chord_error, general.max_chord_error,
                  1e-3 * closed.max_chord_error + 1e-12);
    }
  }
}

// A general curve (a parabola): every point on the curve, every chord r long
// but a clamped last one, the chain ends at the end, chord height ~ r^2 k / 8.
TEST(InscribedChord, GeneralCurveParabola) {
  const ExplicitCurve parabola([](double x) { return 0.1 * x * x; },
                               [](double x) { return 0.2 * x; }, [](double) { return 0.2; }, -5, 5);
  const double r = 0.3;
  const ChordResult res = inscribed_chord(parabola, r, ChordEnd::kClamp);
  ASSERT_GT(res.steps.size(), 10u);
  for (size_t k = 0; k < res.steps.size(); ++k) {
    const ChordStep& s = res.steps[k];
    EXPECT_NEAR(s.point.y(), 0.1 * s.point.x() * s.point.x(), 1e-12);
    if (k + 1 < res.steps.size()) EXPECT_NEAR(s.chord, r, 1e-12);
    if (k > 0) EXPECT_GT(s.t, res.steps[k - 1].t);
  }
  EXPECT_TRUE(res.exact_end);
  EXPECT_EQ(res.steps.back().point, Vec2(5, 2.5));
  // Max curvature 0.2 at the vertex: sagitta <= r^2 kmax / 8 (to first order).
  EXPECT_LE(res.max_chord_error, r * r * 0.2 / 8 * 1.01);
  EXPECT_GT(res.max_chord_error, r * r * 0.2 / 8 * 0.5);
}

// The circle may be centred off the curve (the log model's exact even step).
TEST(InscribedChord, OffCurveCentre) {
  const LineCurve l({0, 0}, {10, 0});
  const double t = next_circle_intersection(l, Vec2(2, 0.6), 1.0, 0.0, 1.0);
  EXPECT_NEAR(t * 10, 2.8, 1e-12);  // (2.8, 0) is 1 from (2, 0.6)
}

TEST(InscribedChord, RejectsBadInput) {
  EXPECT_THROW(inscribed_chord_line({0, 0}, {4, 3}, 0), std::invalid_argument);
  EXPECT_THROW(inscribed_chord_line({0, 0}, {4, 3}, -1), std::invalid_argument);
  EXPECT_THROW(inscribed_chord_line({1, 1}, {1, 1}, 1), std::invalid_argument);
  EXPECT_THROW(inscribed_chord_arc({0, 0}, {4, 0}, {0, 4}, true, 8.5), std::invalid_argument);
  EXPECT_THROW(inscribed_chord_line({0, 0}, {4, 3}, 1e-7), std::invalid_argument);
  EXPECT_THROW(next_circle_intersection(LineCurve({0, 0}, {1, 0}), Vec2(0, 0), 5, 0, 1),
               std::runtime_error);
}

// Full circle: start == end goes once around.
TEST(InscribedChord, FullCircle) {
  const ChordResult full =
      inscribed_chord_arc({1, 1}, {3, 1}, {3, 1}, false, 0.5, ChordEnd::kClamp);
  const double step = 2 * std::asin(0.5 / 4);
  EXPECT_EQ(full.steps.size(), static_cast<size_t>(std::ceil(2 * M_PI / step)));
  EXPECT_NEAR((full.steps.back().point - Vec2(3, 1)).norm(), 0, 1e-12);
}

}  // namespace
}  // namespace hwinterp::models

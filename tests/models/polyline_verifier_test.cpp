#include "models/polyline_verifier.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hwinterp::models {
namespace {

// Chords of a circle of radius r spanning angle a each: the error is known in
// closed form, the sagitta r (1 - cos(a / 2)), inside (towards the centre).
TEST(PolylineVerifier, ChordsOfACircleHaveTheSagitta) {
  const double r = 20, a = 0.2;
  const ArcCurve arc({1, 2}, r, 0, 1.0);  // counter-clockwise: centre on the left
  std::vector<Vec2> v;
  for (int i = 0; i <= 5; ++i) v.push_back(arc.point(a * i));
  const PolylineCheck c = verify_polyline(arc, v);
  const double sagitta = r * (1 - std::cos(a / 2));
  EXPECT_NEAR(c.max_abs_error, sagitta, 1e-12);
  EXPECT_NEAR(c.most_positive.error, sagitta, 1e-12);  // left of travel
  EXPECT_NEAR(c.most_negative.error, 0, 1e-12);        // the vertices lie on the arc
  EXPECT_EQ(c.segments, 5);
  EXPECT_EQ(c.samples_past_ends, 0);
  // The extreme is at a chord's midpoint; its foot at the mid-angle.
  const double mid_t = a * (c.worst.segment + 0.5);
  EXPECT_NEAR(c.worst.t_foot, mid_t, 1e-7);
  // side_sign flips the reported sides.
  PolylineCheckOptions o;
  o.side_sign = -1;
  EXPECT_NEAR(verify_polyline(arc, v, o).most_negative.error, -sagitta, 1e-12);
}

// Moving one vertex outwards by d shows up as an error of d there.
TEST(PolylineVerifier, SeesADisplacedVertex) {
  const ArcCurve arc({0, 0}, 10, 0, 1.0);
  std::vector<Vec2> v;
  for (int i = 0; i <= 10; ++i) v.push_back(arc.point(0.1 * i));
  const double d = 0.003;
  v[4] = v[4] * (1 + d / 10);  // radially outwards
  const PolylineCheck c = verify_polyline(arc, v);
  EXPECT_NEAR(c.most_negative.error, -d, 1e-12);
  EXPECT_EQ(c.most_negative.segment == 3 || c.most_negative.segment == 4, true);
  EXPECT_NEAR((c.most_negative.point - v[4]).norm(), 0, 1e-9);
}

// A polyline that runs past the end of the curve is flagged, not excused.
TEST(PolylineVerifier, FlagsAPolylineRunningPastTheCurve) {
  const LineCurve line({0, 0}, {10, 0});
  const PolylineCheck c = verify_polyline(line, {{0, 0}, {12, 0.5}});
  EXPECT_GT(c.samples_past_ends, 0);
  EXPECT_GT(c.max_abs_error, 0.5);
}

TEST(PolylineVerifier, ErrorSamplesFollowThePolyline) {
  const ArcCurve arc({0, 0}, 10, 0, 1.0);
  const std::vector<Vec2> v{arc.point(0), arc.point(0.5), arc.point(1.0)};
  const auto s = sample_polyline_error(arc, v, 8);
  ASSERT_EQ(s.size(), 17u);
  EXPECT_NEAR(s.front().arc_length, 0, 1e-12);
  EXPECT_NEAR(s.back().arc_length, 10, 1e-9);  // radius x angle
  for (size_t i = 1; i < s.size(); ++i) EXPECT_GT(s[i].t_foot, s[i - 1].t_foot);
  EXPECT_NEAR(s[4].error, 10 * (1 - std::cos(0.25)), 1e-12);  // mid-chord
}

}  // namespace
}  // namespace hwinterp::models

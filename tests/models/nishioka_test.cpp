#include "models/nishioka.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "models/cam_profile.h"
#include "models/polyline_verifier.h"

namespace hwinterp::models {
namespace {

// Eq. A-4, evaluated here independently of the planner.
double nominal(const PlanarCurve& c, double t0, double t1) {
  return (c.point(0.5 * (t0 + t1)) - 0.5 * (c.point(t0) + c.point(t1))).norm();
}

void expect_chords_exact(const PlanarCurve& c, const NishiokaPlan& p, double tol) {
  ASSERT_EQ(p.t.size(), static_cast<size_t>(p.segments) + 1);
  for (int i = 0; i < p.segments; ++i) {
    const double d = nominal(c, p.t[i], p.t[i + 1]);
    if (i + 1 < p.segments) {
      EXPECT_NEAR(d, tol, 1e-12) << "chord " << i;
    } else {
      EXPECT_LE(d, tol + 1e-12);
    }
  }
}

// Paper section 3.2: Nishioka needs 180 segments for Cam 1 at 0.0005 mm,
// 90 per half, the halves done separately; its true normal errors exceed the
// nominal value (+0.000513 / -0.000501 mm in the reproduction).
TEST(Nishioka, Cam1Halves) {
  const TranslatingCam cam1(CamLaw::kModifiedSine, 100, 40);
  const NishiokaPlan left = plan_nishioka(cam1, 0, 50, 0.0005);
  const NishiokaPlan right = plan_nishioka(cam1, 50, 100, 0.0005);
  EXPECT_EQ(left.segments, 90);
  EXPECT_EQ(right.segments, 90);
  expect_chords_exact(cam1, left, 0.0005);
  const NishiokaPlan both = plan_nishioka_by_intervals(cam1, 0.0005);
  EXPECT_EQ(both.segments, 180);
  PolylineCheckOptions o;
  o.side_sign = cam1.outward_sign();
  const PolylineCheck chk = verify_polyline(cam1, both.vertices, o);
  RecordProperty("true_error_positive", std::to_string(chk.most_positive.error));
  RecordProperty("true_error_negative", std::to_string(chk.most_negative.error));
  EXPECT_GT(chk.max_abs_error, 0.0005);
  EXPECT_NEAR(chk.most_positive.error, 0.000513, 5e-7);  // concave left half: chords outside
  EXPECT_NEAR(chk.most_negative.error, -0.000501, 5e-7);
}

// In one pass a chord spans Cam 1's inflection and errs by -0.000693 mm.
TEST(Nishioka, Cam1OnePassChordAcrossTheInflection) {
  const TranslatingCam cam1(CamLaw::kModifiedSine, 100, 40);
  const NishiokaPlan p = plan_nishioka(cam1, 0, 100, 0.0005);
  PolylineCheckOptions o;
  o.side_sign = cam1.outward_sign();
  const PolylineCheck chk = verify_polyline(cam1, p.vertices, o);
  EXPECT_NEAR(chk.most_negative.error, -0.000693, 5e-7);
  const int s = chk.most_negative.segment;
  EXPECT_LT(p.t[s], 50);
  EXPECT_GT(p.t[s + 1], 50);
}

// Paper section 3.3: 228 for Cam 2; one pass gives 229 chords, the last of
// which all but vanishes.
TEST(Nishioka, Cam2OnePass) {
  const RotatingCam cam2(CamLaw::kModifiedSine, 40, 30, 100 * M_PI / 180);
  const NishiokaPlan p = plan_nishioka(cam2, 0, cam2.t_end(), 0.0005);
  EXPECT_EQ(p.segments, 229);
  double shortest_other = 1e9;
  for (int i = 0; i + 1 < p.segments; ++i)
    shortest_other = std::min(shortest_other, (p.vertices[i + 1] - p.vertices[i]).norm());
  RecordProperty("last_chord_mm", std::to_string(p.last_chord_mm));
  EXPECT_LT(p.last_chord_mm, 0.01 * shortest_other);
  expect_chords_exact(cam2, p, 0.0005);
  EXPECT_NEAR((p.vertices.back() - cam2.point(cam2.t_end())).norm(), 0, 1e-12);
}

TEST(Nishioka, RejectsBadInput) {
  const TranslatingCam cam1(CamLaw::kModifiedSine, 100, 40);
  EXPECT_THROW(plan_nishioka(cam1, 0, 100, 0), std::invalid_argument);
  EXPECT_THROW(plan_nishioka(cam1, 10, 10, 0.001), std::invalid_argument);
}

}  // namespace
}  // namespace hwinterp::models

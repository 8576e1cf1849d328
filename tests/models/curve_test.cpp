#include "models/curve.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hwinterp::models {
namespace {

// Central differences of point() must match d1(), and of d1() match d2().
void expect_derivatives_consistent(const PlanarCurve& c) {
  const double h = 1e-5;
  for (int k = 1; k < 10; ++k) {
    const double t = c.t_begin() + (c.t_end() - c.t_begin()) * k / 10.0;
    const Vec2 fd1 = (c.point(t + h) - c.point(t - h)) / (2 * h);
    const Vec2 fd2 = (c.d1(t + h) - c.d1(t - h)) / (2 * h);
    EXPECT_LT((fd1 - c.d1(t)).norm(), 1e-6 * (1 + c.d1(t).norm())) << t;
    EXPECT_LT((fd2 - c.d2(t)).norm(), 1e-6 * (1 + c.d2(t).norm())) << t;
  }
}

TEST(Curve, ArcDerivativesAndCurvatureSign) {
  const ArcCurve ccw({0, 0}, 4, 0, M_PI / 2), cw({1, 2}, 3, M_PI, 0);
  expect_derivatives_consistent(ccw);
  expect_derivatives_consistent(cw);
  EXPECT_NEAR(ccw.curvature(0.3), 0.25, 1e-12);
  EXPECT_NEAR(cw.curvature(0.3), -1.0 / 3, 1e-12);
  EXPECT_NEAR((ccw.point(ccw.t_end()) - Vec2(0, 4)).norm(), 0, 1e-12);
  EXPECT_NEAR((cw.point(cw.t_end()) - Vec2(4, 2)).norm(), 0, 1e-12);
}

TEST(Curve, ExplicitAndLine) {
  const ExplicitCurve c([](double x) { return std::sin(x); }, [](double x) { return std::cos(x); },
                        [](double x) { return -std::sin(x); }, 0, 3);
  expect_derivatives_consistent(c);
  // y = sin x: curvature -sin x / (1 + cos^2 x)^(3/2), negative (turns right) on (0, pi).
  const double k = -std::sin(1.0) / std::pow(1 + std::cos(1.0) * std::cos(1.0), 1.5);
  EXPECT_NEAR(c.curvature(1.0), k, 1e-12);
  EXPECT_LT(c.curvature(1.0), 0);
  const LineCurve l({0, 0}, {4, 3});
  EXPECT_DOUBLE_EQ(l.curvature(0.5), 0);
  EXPECT_NEAR((l.unit_normal(0.2) - Vec2(-0.6, 0.8)).norm(), 0, 1e-15);
}

}  // namespace
}  // namespace hwinterp::models

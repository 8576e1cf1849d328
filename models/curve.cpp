#include "models/curve.h"

#include <cmath>
#include <stdexcept>

namespace hwinterp::models {

double PlanarCurve::curvature(double t) const {
  const Vec2 v = d1(t);
  const double speed = v.norm();
  return cross2(v, d2(t)) / (speed * speed * speed);
}

Vec2 PlanarCurve::unit_tangent(double t) const { return d1(t).normalized(); }

Vec2 PlanarCurve::unit_normal(double t) const {
  const Vec2 u = unit_tangent(t);
  return {-u.y(), u.x()};
}

FunctionCurve::FunctionCurve(Fn p, Fn dp, Fn ddp, double t0, double t1)
    : p_(std::move(p)), dp_(std::move(dp)), ddp_(std::move(ddp)), t0_(t0), t1_(t1) {
  if (!(t1 > t0)) throw std::invalid_argument("FunctionCurve: empty parameter range");
}

ExplicitCurve::ExplicitCurve(Fn f, Fn df, Fn ddf, double x0, double x1)
    : f_(std::move(f)), df_(std::move(df)), ddf_(std::move(ddf)), x0_(x0), x1_(x1) {
  if (!(x1 > x0)) throw std::invalid_argument("ExplicitCurve: empty x range");
}

ArcCurve::ArcCurve(Vec2 center, double r, double angle0, double angle1)
    : c_(std::move(center)),
      r_(r),
      a0_(angle0),
      sweep_(std::abs(angle1 - angle0)),
      sign_(angle1 >= angle0 ? 1.0 : -1.0) {
  if (!(r > 0)) throw std::invalid_argument("ArcCurve: radius must be positive");
  if (!(sweep_ > 0)) throw std::invalid_argument("ArcCurve: zero sweep");
}

Vec2 ArcCurve::point(double t) const {
  const double a = a0_ + sign_ * t;
  return c_ + r_ * Vec2(std::cos(a), std::sin(a));
}

Vec2 ArcCurve::d1(double t) const {
  const double a = a0_ + sign_ * t;
  return sign_ * r_ * Vec2(-std::sin(a), std::cos(a));
}

Vec2 ArcCurve::d2(double t) const {
  const double a = a0_ + sign_ * t;
  return -r_ * Vec2(std::cos(a), std::sin(a));
}

}  // namespace hwinterp::models

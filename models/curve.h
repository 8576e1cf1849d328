// Planar curves with analytic first and second derivatives: what the planners
// (optimal linear interpolation, Nishioka, inscribed chord) and the polyline
// verifier work on. Everything is in the curve parameter t, with tangent and
// normal vectors rather than slopes, so vertical tangents (Cam 2 at theta = 0)
// and zero slopes need no special case.
#pragma once

#include <Eigen/Dense>
#include <functional>

namespace hwinterp::models {

using Vec2 = Eigen::Vector2d;

// z-component of the 2-D cross product a x b.
inline double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// A point and both derivatives at one parameter.
struct CurveJetValue {
  Vec2 p, d1, d2;
};

class PlanarCurve {
 public:
  virtual ~PlanarCurve() = default;
  virtual Vec2 point(double t) const = 0;
  virtual Vec2 d1(double t) const = 0;  // dP/dt
  virtual Vec2 d2(double t) const = 0;  // d2P/dt2
  // All three at once. Curves whose evaluations share work override it (the
  // cam profiles evaluate their cam law once instead of three times: that is
  // what keeps the planner inside its 5 ms budget).
  virtual CurveJetValue jet(double t) const { return {point(t), d1(t), d2(t)}; }
  virtual double t_begin() const = 0;
  virtual double t_end() const = 0;

  // Signed curvature (positive: the curve turns left, counter-clockwise).
  double curvature(double t) const;
  // Unit tangent and left unit normal (tangent rotated +90 degrees).
  Vec2 unit_tangent(double t) const;
  Vec2 unit_normal(double t) const;
};

// A curve given by three callables over [t0, t1].
class FunctionCurve : public PlanarCurve {
 public:
  using Fn = std::function<Vec2(double)>;
  FunctionCurve(Fn p, Fn dp, Fn ddp, double t0, double t1);
  Vec2 point(double t) const override { return p_(t); }
  Vec2 d1(double t) const override { return dp_(t); }
  Vec2 d2(double t) const override { return ddp_(t); }
  double t_begin() const override { return t0_; }
  double t_end() const override { return t1_; }

 private:
  Fn p_, dp_, ddp_;
  double t0_, t1_;
};

// y = f(x) on [x0, x1], parameterised by t = x.
class ExplicitCurve : public PlanarCurve {
 public:
  using Fn = std::function<double(double)>;
  ExplicitCurve(Fn f, Fn df, Fn ddf, double x0, double x1);
  Vec2 point(double x) const override { return {x, f_(x)}; }
  Vec2 d1(double x) const override { return {1.0, df_(x)}; }
  Vec2 d2(double x) const override { return {0.0, ddf_(x)}; }
  double t_begin() const override { return x0_; }
  double t_end() const override { return x1_; }

 private:
  Fn f_, df_, ddf_;
  double x0_, x1_;
};

// Straight segment a -> b, t in [0, 1].
class LineCurve : public PlanarCurve {
 public:
  LineCurve(Vec2 a, Vec2 b) : a_(std::move(a)), b_(std::move(b)) {}
  Vec2 point(double t) const override { return a_ + t * (b_ - a_); }
  Vec2 d1(double) const override { return b_ - a_; }
  Vec2 d2(double) const override { return Vec2::Zero(); }
  double t_begin() const override { return 0; }
  double t_end() const override { return 1; }

 private:
  Vec2 a_, b_;
};

// Circular arc around `center` of radius r; t is the polar angle (radians)
// from `angle0` to `angle1` (angle1 > angle0: counter-clockwise; < : clockwise;
// the parameter then runs backwards, see t_begin/t_end and point()).
class ArcCurve : public PlanarCurve {
 public:
  ArcCurve(Vec2 center, double r, double angle0, double angle1);
  Vec2 point(double t) const override;
  Vec2 d1(double t) const override;
  Vec2 d2(double t) const override;
  // t runs from 0 to |angle1 - angle0|; the polar angle is angle0 + s t, s = +-1.
  double t_begin() const override { return 0; }
  double t_end() const override { return sweep_; }
  double radius() const { return r_; }
  const Vec2& center() const { return c_; }
  bool ccw() const { return sign_ > 0; }

 private:
  Vec2 c_;
  double r_, a0_, sweep_, sign_;
};

}  // namespace hwinterp::models

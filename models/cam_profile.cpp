#include "models/cam_profile.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hwinterp::models {
namespace {

void require_positive(double v, const char* what) {
  if (!(v > 0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(what) + " must be positive and finite, got " +
                                std::to_string(v));
}

}  // namespace

TranslatingCam::TranslatingCam(CamLaw law, double stroke, double lift)
    : law_(law), stroke_(stroke), lift_(lift) {
  require_positive(stroke, "stroke");
  require_positive(lift, "lift");
}

Vec2 TranslatingCam::point(double x) const {
  return {x, lift_ * evaluate_cam_law(law_, x / stroke_).s};
}

Vec2 TranslatingCam::d1(double x) const {
  return {1.0, lift_ / stroke_ * evaluate_cam_law(law_, x / stroke_).ds};
}

Vec2 TranslatingCam::d2(double x) const {
  return {0.0, lift_ / (stroke_ * stroke_) * evaluate_cam_law(law_, x / stroke_).dds};
}

CurveJetValue TranslatingCam::jet(double x) const {
  const CamLawValue s = evaluate_cam_law(law_, x / stroke_);
  return {
      {x, lift_ * s.s}, {1.0, lift_ / stroke_ * s.ds}, {0.0, lift_ / (stroke_ * stroke_) * s.dds}};
}

RotatingCam::RotatingCam(CamLaw law, double r0, double lift, double theta_d)
    : law_(law), r0_(r0), lift_(lift), theta_d_(theta_d) {
  require_positive(r0, "r0");
  require_positive(lift, "lift");
  require_positive(theta_d, "theta_d");
  if (theta_d > 2 * M_PI * (1 + 1e-15))
    throw std::invalid_argument("theta_d must not exceed one turn (2 pi), got " +
                                std::to_string(theta_d));
}

CamLawValue RotatingCam::radius(double theta) const {
  const CamLawValue s = evaluate_cam_law(law_, theta / theta_d_);
  return {r0_ + lift_ * s.s, lift_ / theta_d_ * s.ds, lift_ / (theta_d_ * theta_d_) * s.dds};
}

Vec2 RotatingCam::point(double theta) const {
  return radius(theta).s * Vec2(std::cos(theta), std::sin(theta));
}

Vec2 RotatingCam::d1(double theta) const {
  const CamLawValue r = radius(theta);
  const Vec2 e(std::cos(theta), std::sin(theta)), e_perp(-std::sin(theta), std::cos(theta));
  return r.ds * e + r.s * e_perp;
}

Vec2 RotatingCam::d2(double theta) const {
  const CamLawValue r = radius(theta);
  const Vec2 e(std::cos(theta), std::sin(theta)), e_perp(-std::sin(theta), std::cos(theta));
  return (r.dds - r.s) * e + 2 * r.ds * e_perp;
}

}  // namespace hwinterp::models

namespace hwinterp::models {

CurveJetValue RotatingCam::jet(double theta) const {
  const CamLawValue r = radius(theta);
  const Vec2 e(std::cos(theta), std::sin(theta)), e_perp(-std::sin(theta), std::cos(theta));
  return {r.s * e, r.ds * e + r.s * e_perp, (r.dds - r.s) * e + 2 * r.ds * e_perp};
}

}  // namespace hwinterp::models

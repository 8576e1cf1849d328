// Cam pitch curves built from a cam law (cam_law.h), as the planners see them:
// PlanarCurves with analytic first and second derivatives.
//
// Sign convention of the OLI paper: an interpolation error is positive on the
// non-substantial side of the contour (away from the cam body) and negative on
// the substantial side. outward_sign() says how that side relates to the
// curve's left normal, so a verifier can report errors with the paper's signs.
#pragma once

#include "models/cam_law.h"
#include "models/curve.h"

namespace hwinterp::models {

// Translating cam (the paper's Cam 1): y = lift * S(x / stroke), x in
// [0, stroke], parameter t = x. The follower rides on top, so the body lies
// below the curve (to the right of the +x direction of travel).
class TranslatingCam : public PlanarCurve {
 public:
  // Throws std::invalid_argument when stroke or lift is not positive and finite.
  TranslatingCam(CamLaw law, double stroke, double lift);
  Vec2 point(double x) const override;
  Vec2 d1(double x) const override;
  Vec2 d2(double x) const override;
  CurveJetValue jet(double x) const override;
  double t_begin() const override { return 0; }
  double t_end() const override { return stroke_; }
  double outward_sign() const { return 1; }

 private:
  CamLaw law_;
  double stroke_, lift_;
};

// Rotating cam with a radial (reciprocating, in-line) follower (the paper's
// Cam 2): r(theta) = r0 + lift * S(theta / theta_d), point = r (cos, sin)(theta),
// theta in [0, theta_d] radians, parameter t = theta. Travelled
// counter-clockwise with the body inside, so the body is on the left.
class RotatingCam : public PlanarCurve {
 public:
  // Throws std::invalid_argument unless r0 > 0, lift > 0 and 0 < theta_d <= 2 pi.
  RotatingCam(CamLaw law, double r0, double lift, double theta_d);
  Vec2 point(double theta) const override;
  Vec2 d1(double theta) const override;
  Vec2 d2(double theta) const override;
  CurveJetValue jet(double theta) const override;
  double t_begin() const override { return 0; }
  double t_end() const override { return theta_d_; }
  double outward_sign() const { return -1; }

 private:
  // Radius and its first two derivatives in theta.
  CamLawValue radius(double theta) const;
  CamLaw law_;
  double r0_, lift_, theta_d_;
};

}  // namespace hwinterp::models

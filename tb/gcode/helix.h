// The programmed path of an arc move as LinuxCNC interpolates it, in program
// units (mm; A B C in degrees): the one geometry the motion compiler
// (lattice points, lengths) and the contour error share.
//
// In the arc's plane (canon axes first, second: Move::center's order) the
// path is the spiral about the centre c whose radius goes linearly from
// r1 = |start - c| to r2 = |end - c| over the sweep theta: the angle from the
// start to the end about c in the arc's direction (CCW for rotation > 0), in
// (0, 2 pi] (a full circle when the directions coincide), plus 2 pi for each
// extra turn (|rotation| - 1). Every other axis (the helix axis, A B C) goes
// linearly with the swept angle. With parameter t in [0, 1] (phi = theta t):
//     first, second = c + r(t) (cos(a0 + d phi), sin(a0 + d phi)),
//     r(t) = r1 + (r2 - r1) t, d = +1 CCW, -1 CW, a0 the start's angle;
//     other axes = start + (end - start) t;
// and exactly the programmed end at t = 1.
#pragma once

#include <array>

#include "tb/gcode/move.h"

namespace hwinterp::gcode {

class Helix {
 public:
  Helix(const std::array<double, 6>& start, const Move& arc);

  std::array<double, 6> point(double t) const;
  // The path at swept angle phi (t = phi / theta, by the formula, also
  // beyond [0, theta]) and its first and second derivatives in phi.
  void at_angle(double phi, std::array<double, 6>& c, std::array<double, 6>& dc,
                std::array<double, 6>& ddc) const;
  // XYZ length between parameters t0 <= t1 (the plane's spiral and the helix
  // axis; A B C do not count, as LinuxCNC's feed applies to XYZ).
  double length(double t0, double t1) const;
  // The angle of plane point (u, v) about the centre, from the start's
  // direction in the arc's direction, in [0, 2 pi).
  double angle_of(double u, double v) const;

  int first() const { return first_; }
  int second() const { return second_; }
  int third() const { return third_; }
  bool ccw() const { return ccw_; }
  double theta() const { return theta_; }
  double r1() const { return r1_; }
  double r2() const { return r2_; }
  double c1() const { return c1_; }
  double c2() const { return c2_; }
  const std::array<double, 6>& start() const { return s_; }
  const std::array<double, 6>& end() const { return e_; }

 private:
  std::array<double, 6> s_, e_;
  int first_, second_, third_;
  bool ccw_;
  double c1_, c2_, a0_, r1_, r2_, theta_;
};

}  // namespace hwinterp::gcode

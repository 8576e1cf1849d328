// Contour error: how far a visited lattice point is from the programmed path
// of the move it belongs to (tb/gcode/move.h), in mm and in steps.
//
// Units. A lattice point is converted to program units by axis:
// p_i = steps_i / steps_per_unit_i (mm on X Y Z, degrees on A B C); an axis
// the machine does not have sits on the path (no deviation).
//
// Path, from the move's programmed start (the previous move's programmed
// end) to its programmed end:
//   line (G0, G1): the segment.
//   arc (G2, G3): LinuxCNC's helix (tb/gcode/helix.h): in the plane the
//     spiral about the centre whose radius goes linearly from the start's r1
//     to the end's r2 over the sweep theta (a circle when r1 = r2), the helix
//     axis and every other axis linear in the swept angle.
//
// Error = the distance from the point to the nearest point of the path:
//   mm:    Euclidean over the six axes in program units (degrees counted as
//          mm; on moves without rotary motion, the plain distance in mm);
//   steps: Euclidean in step space, each axis scaled by its steps per unit
//          (the path scaled to steps, not rounded): with equal steps per unit
//          on the axes involved it is the mm distance times steps/mm; with
//          unequal ones (or a rotary axis beside X Y Z) it is the normal
//          distance in the step lattice, which the mm figure does not scale to.
// Each is minimised in its own space. Lines: the projection onto the segment
// (clamped to its ends). Arcs: for a point at angle phi0 about the centre (in
// [0, 2 pi) from the start, in the arc's direction), the path point at the
// same angle on each turn k (phi0 + 2 pi k <= theta) -- whose planar part is
// the radial deviation | |p - c| - r(phi) | combined with the helix axis's
// deviation at that angle -- refined by a safeguarded Newton search over the
// angle within the bracket that distance allows (a closer path point lies
// within 2 asin(d / r_min) of it), and the two end points; the smallest.
// For planar arcs this is the radial deviation from the spiral (the
// paper's radial error on circles); on helices it also counts the helix
// axis's offset only as far as it is normal to the path.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "tb/gcode/helix.h"
#include "tb/gcode/machine.h"
#include "tb/gcode/move.h"

namespace hwinterp::gcode {

struct ContourError {
  double mm = 0;
  double steps = 0;
};

// The programmed path of one move and the error of points against it.
class ContourPath {
 public:
  // `start`: the move's programmed start (the previous programmed end).
  ContourPath(const Machine& machine, const std::array<double, 6>& start, const Move& move);
  // A visited lattice point (steps per axis, X Y Z A B C).
  ContourError error(const std::array<int64_t, 6>& lattice) const;
  // A point in program units (mm, degrees).
  ContourError error_at(const std::array<double, 6>& point) const;
  // Arcs: the programmed helix; lines: none.
  const std::optional<Helix>& helix() const { return helix_; }

 private:
  // Distance to the path with weights w_i per axis (0: the axis does not count).
  double distance(const std::array<double, 6>& p, const std::array<double, 6>& w) const;

  std::array<bool, 6> has_{};
  std::array<double, 6> spu_{};
  std::array<double, 6> s_{}, e_{};
  std::optional<Helix> helix_;
};

}  // namespace hwinterp::gcode

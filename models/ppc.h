// Point-by-point comparison (PPC) reference sequences, lines and arcs (papers
// 003_b291717b57510359.txt and 004_dc68f1177cad466f.txt). One axis steps per
// operation, chosen by the sign of a deviation function F:
//   line: F = y |dx| - x |dy| (x, y counted from the start towards the end);
//         F >= 0 steps x, F < 0 steps y; |dx| + |dy| operations.
//   arc : F = x^2 + y^2 - R^2 (x, y from the centre); F >= 0 steps the axis
//         that moves towards the centre, F < 0 the one that moves away; which
//         axis that is depends on the quadrant and the direction (CW/CCW).
// One operation = one deviation test + one step + one deviation update; one
// tick per operation, so a line completes in |dx| + |dy| ticks.
#pragma once

#include "models/step_path.h"

namespace hwinterp::models {

enum class PpcLineRule {
  kGuarded,   // F >= 0 steps x only while x still has steps left: always exact
  kTextbook,  // the bare rule for exactly |dx| + |dy| operations; on a vertical
              // line (dx = 0) it steps x first and misses the end
};

StepPath ppc_line(const LatticePoint& start, const LatticePoint& end,
                  PpcLineRule rule = PpcLineRule::kGuarded);

// Upper bound on the PPC line's normal error: -|dy| <= F < |dx| after every
// operation, so the error is at most max(|dx|, |dy|) / L, which is < 1 step
// (and 0 on axis-parallel lines, where F stays 0).
double ppc_line_error_bound(const LatticePoint& start, const LatticePoint& end);

// PPC circular arc around a lattice centre from `start` to `end` (both on the
// lattice at the same squared radius R^2 >= 2; start == end is a full circle). CCW when
// `ccw`, else CW. Crosses quadrants: the quadrant is taken at every point from
// the current position, points on an axis belonging to the quadrant the motion
// is entering. Runs until the end point is reached. Radii whose full circle
// would exceed kMaxStepMoves steps (R above about 2 million) are refused.
// Radial error | |p - c| - R | <= 1 at every visited point: an inward step is
// taken only from |p| >= R and shortens |p| by at most 1, an outward one only
// from |p| < R and lengthens it by at most 1 (the inward axis never has a zero
// coordinate, by the axis rule above). 1 is reached: (3,0) on the paper arc.
StepPath ppc_arc(const LatticePoint& center, const LatticePoint& start, const LatticePoint& end,
                 bool ccw);

// Radial error of a lattice point: | |p - c| - R | in steps.
double radial_error(const LatticePoint& p, const LatticePoint& center, double radius);
// Max radial error over the path's visited points (radius from its start).
double ppc_arc_radial_error(const StepPath& arc, const LatticePoint& center);

}  // namespace hwinterp::models

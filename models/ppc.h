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
//
// The streams (PpcLineStream, PpcArcStream) yield one move at a time, for
// the testbench scoreboard, which must not store whole paths; the StepPath
// functions collect them. The arc stream takes coordinates whose squares fit
// (|coordinate| < 2^30), the line stream |coordinate| < 2^61; the StepPath
// functions keep their storage limits (check_line_2d, kMaxStepMoves).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "models/error_bound.h"
#include "models/step_path.h"

namespace hwinterp::models {

enum class PpcLineRule {
  kGuarded,   // F >= 0 steps x only while x still has steps left: always exact
  kTextbook,  // the bare rule for exactly |dx| + |dy| operations; on a vertical
              // line (dx = 0) it steps x first and misses the end
};

// The moves of one PPC line, one at a time. StepMove::time is the operation
// number (1-based; every operation steps one axis, so it is also the move
// number). A zero-length line has no moves (the hardware spends one engine
// tick on it; see rtl/ppc_line.sv).
class PpcLineStream {
 public:
  PpcLineStream() = default;  // an empty line
  PpcLineStream(const LatticePoint& start, const LatticePoint& end,
                PpcLineRule rule = PpcLineRule::kGuarded);
  bool next(StepMove& m);
  uint64_t total() const { return ax_ + ay_; }  // operations of the whole line

 private:
  int64_t ax_ = 0, ay_ = 0;  // |dx|, |dy|
  int ux_ = 1, uy_ = 1;      // step directions (a zero delta steps "+")
  PpcLineRule rule_ = PpcLineRule::kGuarded;
  int64_t x_ = 0, y_ = 0, f_ = 0;  // counts along the line's own quadrant, F = y ax - x ay
  uint64_t op_ = 0;
  LatticePoint at_{0, 0};
};

StepPath ppc_line(const LatticePoint& start, const LatticePoint& end,
                  PpcLineRule rule = PpcLineRule::kGuarded);

// Upper bound on the PPC line's normal error: -|dy| <= F < |dx| after every
// operation, so the error is at most max(|dx|, |dy|) / L, which is < 1 step
// (and 0 on axis-parallel lines, where F stays 0).
double ppc_line_error_bound(const LatticePoint& start, const LatticePoint& end);

// -----------------------------------------------------------------------------
// PPC circular arc around a lattice centre c from `start` to `end`, CCW when
// `ccw`, else CW: "rule M", which ends exactly on `end` whether or not it lies
// on the circle through `start` (G-code arcs rarely do once rounded to steps),
// with no multiplication in the hardware. Coordinates relative to the centre:
// s = start - c, e = end - c, p = the current point (p = s at the start).
//
// Quadrants and motion. The quadrant of a point is taken from its signs, a
// point on an axis belonging to the quadrant the motion enters; the motion
// signs (mx, my) are CCW (-y, x), CW (y, -x) of that quadrant. In every
// quadrant one coordinate moves towards 0 (the inward axis) and the other
// away from it (outward); the inward coordinate of a point is never 0 (a 0
// puts the point in the next quadrant), so p enters a new quadrant exactly
// when a step lands the inward coordinate on 0 (a "quadrant entry").
//
// Laps. n = the quadrant entries from s's quadrant to e's, in the motion
// direction (0..3). When both are in the same quadrant: n = 0 if e is ahead
// of s, 4 (a full lap first) if it is behind. e is behind only when it is
// behind on both axes: (ex - sx) mx <= 0 and (ey - sy) my <= 0 (s != e);
// s == e is a full circle (n = 4). A mixed case (ahead on one axis, behind on
// the other, possible only for off-circle ends close to s) counts as ahead:
// the closing line below then goes back on the axis that is behind.
//
// Arc phase: the PPC arc on the circle through s, R^2 = |s|^2. F = |p|^2 - R^2
// (kept incrementally in hardware: an x step by mx adds 2 x mx + 1), F >= 0
// steps the inward axis, F < 0 the outward one: exactly the on-circle PPC
// arc's choice. Once n entries have been counted (the final pass), before
// each step: if the chosen axis a has nothing left towards e in its motion
// direction, (e_a - p_a) m_a <= 0, the arc phase ends (instead of stepping).
// A step that lands on e in the final pass ends the command at once.
//
// Closing phase: the guarded PPC line (PpcLineStream) from p to e; it ends
// exactly on e. It costs one operation without a step first (the hardware
// loads the line engine with |e - p|), then its own operations.
//
// Degenerate commands: R^2 < 2 (start within one step of the centre) or
// e == c (an arc into its centre): no arc phase, the closing line from s.
//
// On-circle ends (|e| = |s|): the arc phase lands on e, with no closing
// phase; the moves are the plain PPC arc's, run until it first reaches e in
// the final pass (the paper arc: 8 steps). Why, in quadrant I CCW (the others
// are mirror images): in the final pass x only falls and y only rises, and
// both start short of e. If x reaches e_x first, at (e_x, y) with y < e_y,
// then F = y^2 - e_y^2 < 0 there and at every point up to e, so the arc steps
// y (still short) until it lands on e; if y reaches e_y first, F = x^2 - e_x^2
// > 0 and x steps until e. (An end on the next axis, e_x = 0, is landed on by
// the entry step out of quadrant I: the step onto x = 0 needs F(1, y) >= 0,
// i.e. y >= e_y, so y gets there first.) So no final-pass step finds its axis
// at or past e. That the final pass does start short of e (every lattice point of
// the circle is visited, across axis crossings too) is checked exhaustively:
// tests/models/ppc_test.cpp PpcRuleM.OnCircleArcsUnchanged (every start with
// |s| <= 12, every end on its circle, both directions: the old run-until-end
// PPC path, operations == moves).
//
// Error metric (ppc_arc_spiral_error): the ideal path is the spiral about c
// from s to e, r(phi) = rs + (re - rs) min(phi, theta) / theta, rs = |s|,
// re = |e|, theta in (0, 2 pi] the angle from s to e in the motion direction
// (2 pi when the directions are equal), phi in [0, 2 pi) the angle from s to
// the visited point p in the motion direction; deviation = | |p| - r(phi) |.
// With both ends on one circle it is the paper's radial error | |p| - R |.
//
// Bound (ppc_arc_error_bound): deviation <= 1 + |re - rs| at every visited
// point. Derivation. r(phi) always lies between rs and re. (1) Arc phase: the
// PPC arc keeps rs - 1 <= |p| < rs + 1 (an inward step only from |p| >= rs,
// an outward one only from |p| < rs, each changing |p| by at most 1), so
// | |p| - r | <= 1 + |r - rs| <= 1 + |re - rs|. (2) Closing line from the
// switch point p to e: in the final pass p never leaves e's quadrant (e's
// inward coordinate is not 0 and steps stop at e's coordinates) and an axis
// is stepped only while it is short of e, so at the switch the chosen axis
// is at or past e and the other is short of, at or past e; taking absolute
// coordinates in that closed quadrant, either e dominates p on both axes
// (chosen inward past, other short), or p dominates e (chosen outward past,
// other short), or p and e share a coordinate (every other case: an axis can
// be strictly past only if it has not moved since the final pass began, and
// both strictly past at once means e behind s, which is not a final pass,
// or an entry point, whose outward coordinate 0 cannot be past). The guarded
// line stays in the box spanned by p and e, so every closing point q has
// |q| between |p| and re. Hence |q| and r(phi) both lie in the hull of
// [rs - 1, rs + 1) and [rs, re]: deviation <= 1 + |re - rs|. (3) Degenerate
// commands (rs <= 1, or re = 0): every point q of the line lies in the box of
// s and e, so 0 <= |q| <= sqrt(max(rs,re)^2 + min(rs,re)^2) <= rs + re, and
// the deviation is at most max(rs, re) <= 1 + |re - rs|.
// Checked exhaustively (tests/models/ppc_test.cpp, PpcRuleM.*): every lattice
// s, e with |s|, |e| <= 12 and ||e| - |s|| <= 3, both directions (213 746
// arcs): all end on e, all within the bound; it is reached (radial error 1 on
// on-circle arcs, e.g. (3,0) of the paper arc), and over the off-circle arcs
// the worst point is 0.0062 below it (s = (-8,0), e = (-4,-7), CW, at
// (0,-7)); the largest deviation seen is 3.62. 600 random arcs with radii up
// to 2^23 stay within it too.
class PpcArcStream {
 public:
  PpcArcStream(const LatticePoint& center, const LatticePoint& start, const LatticePoint& end,
               bool ccw);
  // The next move; false when the command has no more. StepMove::time is the
  // engine operation it happens in (1-based; the switch to the closing line
  // is an operation without a move).
  bool next(StepMove& m);

  int laps() const { return laps_; }                // n: quadrant entries before the final pass
  bool degenerate() const { return degenerate_; }   // no arc phase
  bool closing() const { return phase_ == kLine; }  // in the closing line
  uint64_t operations() const { return op_; }       // engine operations so far
  // Upper bound on the engine operations of the whole command (arc phase at
  // most 5 quadrant passes of 2 (R + 1) steps each, the switch, the line).
  uint64_t operation_bound() const;

 private:
  enum Phase { kArc, kSwitch, kLine, kDone };  // kSwitch: the next operation loads the line
  void start_line();

  bool ccw_ = true;
  LatticePoint c_;
  int64_t x_ = 0, y_ = 0;    // p - c
  int64_t ex_ = 0, ey_ = 0;  // e - c
  int64_t r2_ = 0;           // |s|^2
  int64_t rs_ceil_ = 0, re_ceil_ = 0;
  int laps_ = 0;  // entries still to count before the final pass
  bool degenerate_ = false;
  Phase phase_ = kArc;
  PpcLineStream line_;
  StepMove line_move_;  // the closing line's move (kept: no allocation per move)
  uint64_t op_ = 0;
};

// The on-circle PPC arc (start and end on one circle, R^2 >= 2) and, by rule
// M above, any other arc; start == end is a full circle. CCW when `ccw`, else
// CW. Radii whose full circle would exceed kMaxStepMoves steps (R above about
// 2 million) are refused. ticks = operations (the switch included).
// On-circle radial error | |p - c| - R | <= 1 at every visited point: an
// inward step is taken only from |p| >= R and shortens |p| by at most 1, an
// outward one only from |p| < R and lengthens it by at most 1 (the inward
// axis never has a zero coordinate, by the axis rule above). 1 is reached:
// (3,0) on the paper arc.
StepPath ppc_arc(const LatticePoint& center, const LatticePoint& start, const LatticePoint& end,
                 bool ccw);

// The ideal spiral of an arc command (see PpcArcStream) and the deviation of
// a lattice point from it, in steps.
class PpcArcIdeal {
 public:
  PpcArcIdeal(const LatticePoint& center, const LatticePoint& start, const LatticePoint& end,
              bool ccw);
  double error(const LatticePoint& p) const;
  // 1 + |re - rs| (not strict: reached).
  ErrorBound bound() const { return {1.0 + std::abs(dr_), false}; }
  double theta() const { return theta_; }
  // The spiral as a polyline of `segments` segments, in absolute
  // coordinates (for plots).
  std::vector<std::vector<double>> polyline(int segments) const;

 private:
  double angle_from_start(int64_t x, int64_t y) const;  // phi in [0, 2 pi)
  LatticePoint c_;
  bool ccw_;
  int64_t sx_, sy_;
  int64_t rs2_;
  double rs_, dr_, theta_;  // dr_ = re - rs, computed without cancellation
};

double ppc_arc_spiral_error(const LatticePoint& p, const LatticePoint& center,
                            const LatticePoint& start, const LatticePoint& end, bool ccw);
ErrorBound ppc_arc_error_bound(const LatticePoint& center, const LatticePoint& start,
                               const LatticePoint& end);

// Radial error of a lattice point: | |p - c| - R | in steps.
double radial_error(const LatticePoint& p, const LatticePoint& center, double radius);
// Max radial error over the path's visited points (radius from its start).
double ppc_arc_radial_error(const StepPath& arc, const LatticePoint& center);

}  // namespace hwinterp::models

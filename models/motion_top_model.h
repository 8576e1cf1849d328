// Reference model of the `motion_top` core: one command stream tagged line
// or arc, lines on the dda_line engine over all axes, arcs on the ppc_arc
// engine (rule M) in the selected plane with every other moving axis slaved
// to the arc's engine operations. The HLS and RTL faces are made to match
// this model move for move; the rules below are the contract.
//
// Axes. A core has `axes` machine axes, 3 to 6, in the order X Y Z A B C
// (motion_top: 3 or 4). A command's steps on axis i are delta[i] (lines) or
// the plane's end / delta[i] (arcs); entries at or beyond `axes` must be 0.
//
// Line (kLine): exactly models::DdaMoveStream over the `axes` axes with a
// plain preload (no half preload): 2^n operations, n the bit length of
// max |delta_i|; after k of them axis i has taken floor(k |delta_i| / 2^n)
// steps. Operation k of the line is DDA iteration k.
//
// Arc (kArc): the plane's two axes (plane 0 = XY: engine x = X, y = Y;
// 1 = ZX: x = Z, y = X; 2 = YZ: x = Y, y = Z; LinuxCNC's canon order of
// G17, G18, G19) run models::PpcArcStream from the start (engine origin) with
// centre `center` and end `end`, both relative to the start, CCW when `ccw`:
// rule M, which ends exactly on `end` whether or not it lies on the circle.
// N = `ops` is the arc's whole operation count, PpcArcStream's own (the
// switch to the closing line and a zero-length line's extra operation
// included); it must equal motion_arc_ops(center, end, ccw), which the
// stream checks when it is built.
// Slaved axes: every axis j not in the plane with delta[j] != 0 (the helix
// axis and the rotary axes). Bresenham over the N operations:
//     err_j = floor(N / 2) at the start;
//     on every operation k = 1..N (the switch operation too, which has no
//     plane step): err_j += |delta_j|; if err_j >= N: err_j -= N and axis j
//     steps once in the direction of sign(delta_j)
// on the same operation as that operation's plane step (one move).
// So after k operations axis j has taken floor((floor(N/2) + k |delta_j|) / N)
// steps: exactly |delta_j| after N, never more than one per operation. The
// model requires |delta_j| <= N and throws std::invalid_argument otherwise
// (as for every malformed command: a plane axis with a non-zero delta, a
// coordinate the PPC model cannot take (|v| >= 2^30), ops != N).
// A move is one engine operation on which at least one axis steps; an
// operation with no step (e.g. the switch, with no slaved step due) yields
// nothing.
//
// Deviation metric (MotionIdeal), in steps, of the lattice point p reached
// on operation k (the point after that operation's move):
//   line: models::point_line_distance(p, start, start + delta), the normal
//         distance from the line. Bound: dda_error_bound(m, kZero) =
//         sqrt(m - 1), strict, m = the number of axes that move (an axis that
//         does not move keeps a zero lag, so the line is an m-axis DDA).
//   arc:  sqrt(P^2 + sum_j S_j^2) over the slaved axes j, where
//         P   = models::PpcArcIdeal(center, start, end, ccw).error(p's plane
//               coordinates): | |p - c| - r(phi) |, the planar deviation from
//               the ideal spiral (radius from rs = |s - c| to re = |e - c|
//               linearly over the sweep, phi p's angle from the start);
//         S_j = (p_j - s_j) - delta_j k / N: the slaved axis's deviation from
//               linear interpolation along the arc's progress, the progress
//               being the engine's, k / N (operations done / the arc's
//               operations).
//         Bound: sqrt((1 + |re - rs|)^2 + m / 4), not strict, m = the number
//         of slaved axes. Derivation: P <= 1 + |re - rs| at every visited
//         point (models/ppc.h, PpcArcIdeal::bound(): rule M's bound, reached);
//         and with q = floor(N/2), after k operations the slaved lag is
//         S_j = (q - r) / N, r = (q + k |delta_j|) mod N in [0, N - 1], so
//         S_j in [(q - N + 1) / N, q / N], within [-1/2, 1/2] for even and
//         odd N (1/2 reached for even N); P is in the plane and the S_j on
//         axes orthogonal to it and to each other. Checked exhaustively on
//         small arcs and helices in every plane and on thousands of random
//         ones (tests/models/motion_top_model_test.cpp).
// Note: the slaved axes follow the engine's progress, which is the PPC
// path's L1 length (one axis step per operation), not the arc's angle: a
// helix axis is off the programmed (angle-linear) helix by up to 2.1 % of
// its travel per quadrant. The motion compiler (tb/gcode/motion_compiler.h,
// "Arc tolerance") cuts such arcs into pieces to keep that within a step;
// tb/gcode/contour.h measures the distance to the programmed path.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "models/dda_line_model.h"
#include "models/lattice_path.h"
#include "models/ppc.h"

namespace hwinterp::models {

constexpr int kMotionMaxAxes = 6;

enum class MotionKind { kLine, kArc };

struct MotionCommand {
  MotionKind kind = MotionKind::kLine;
  // line: signed steps per machine axis. arc: the steps of the axes NOT in
  // the plane (helical/slaved axes); 0 for the two plane axes.
  std::array<int64_t, kMotionMaxAxes> delta{};
  // arc: 0 = XY (engine x = X, y = Y), 1 = ZX (x = Z, y = X), 2 = YZ (x = Y,
  // y = Z): LinuxCNC's canon order (G17, G18, G19).
  int plane = 0;
  std::array<int64_t, 2> center{};  // arc: centre - start in the plane (engine x, y), steps
  std::array<int64_t, 2> end{};     // arc: end - start in the plane, steps
  bool ccw = true;
  // arc: the PPC engine operations of the whole arc (PpcArcStream's count, the
  // switch op included); the slaved axes' Bresenham modulus.
  uint64_t ops = 0;
  // Engine operations per clock = feed / 2^FEED_W (>= 2^FEED_W: full feed).
  uint32_t feed = 0;
};

// The plane's engine axes as machine axis indices (X = 0, Y = 1, Z = 2):
// {x, y}. Throws std::invalid_argument for a plane other than 0, 1, 2.
std::array<int, 2> motion_plane_axes(int plane);

// N for an arc: PpcArcStream's operation count for centre and end relative
// to the start (runs the stream once: time O(N), memory O(1)).
uint64_t motion_arc_ops(const std::array<int64_t, 2>& center, const std::array<int64_t, 2>& end,
                        bool ccw);

// The steps the command moves each machine axis (the end minus the start).
std::array<int64_t, kMotionMaxAxes> motion_displacement(const MotionCommand& c);

// Engine operations the command takes (line: 2^n; arc: ops).
uint64_t motion_operations(const MotionCommand& c);

// One move: the axes that step on one engine operation.
struct MotionMove {
  uint64_t op = 0;                            // 1-based engine operation of the command
  std::array<int8_t, kMotionMaxAxes> step{};  // -1, 0, +1 per machine axis
  LatticePoint point;                         // the lattice point after the move
};

// The moves of one command from `start` (a lattice point of `axes`
// coordinates), one at a time, in operation order; O(1) memory per command
// and no allocation per move once `m.point` has its size.
class MotionMoveStream {
 public:
  // Throws std::invalid_argument for a malformed command (see the top).
  MotionMoveStream(const LatticePoint& start, const MotionCommand& c, int axes);
  // The next move; false when the command has no more.
  bool next(MotionMove& m);
  // The engine operation of the last move returned (0 before the first).
  uint64_t operations() const { return op_; }

 private:
  bool next_line(MotionMove& m);
  bool next_arc(MotionMove& m);

  MotionCommand c_;
  int axes_;
  LatticePoint at_;
  uint64_t op_ = 0;
  // line
  std::optional<DdaMoveStream> dda_;
  DdaMove dda_move_;
  // arc (PpcArcStream relative to the start: the start is the engine origin)
  std::optional<PpcArcStream> ppc_;
  StepMove plane_move_;
  bool have_plane_move_ = false;
  bool plane_done_ = false;
  std::array<int, 2> plane_axes_{};
  int slaved_ = 0;                                 // slaved axes in use
  std::array<int, kMotionMaxAxes> slaved_axis_{};  // their machine axes
  std::array<uint64_t, kMotionMaxAxes> err_{};     // Bresenham errors
  std::array<uint64_t, kMotionMaxAxes> magnitude_{};
};

// The ideal path of one command and the deviation metric (see the top).
class MotionIdeal {
 public:
  MotionIdeal(const LatticePoint& start, const MotionCommand& c, int axes);
  // Deviation of the lattice point `p` reached on engine operation `op`
  // (lines ignore `op`), in steps.
  double error(const LatticePoint& p, uint64_t op) const;
  // Its planar part (arcs; 0 for lines) and one slaved axis's lag S_j.
  double planar_error(const LatticePoint& p) const;
  double slaved_lag(const LatticePoint& p, int axis, uint64_t op) const;
  ErrorBound bound() const { return bound_; }

 private:
  MotionCommand c_;
  int axes_;
  LatticePoint start_, end_;
  std::array<int, 2> plane_axes_{};
  std::optional<PpcArcIdeal> ideal_;  // arcs, relative to the start
  std::optional<LineDistance> line_;  // lines: from start_ to end_
  ErrorBound bound_{0, false};
  mutable LatticePoint plane_point_;  // scratch: no allocation per call
};

}  // namespace hwinterp::models

// Optimal linear interpolation of a planar curve (OLI paper,
// 000_2f193053e3097a65.txt): the fewest straight segments whose error,
// measured along the curve normal, stays within +-E.
//
// The curve is split at its inflections; each single-convex or single-concave
// interval is interpolated on its own. Within an interval every segment has
// the same error extremum e on both sides: segment i runs from the previous
// vertex (e outside the curve, or the interval start A on the curve), dips to
// +e inside at its tangent-parallel point P_i (Eq. 4), crosses the curve at
// R_i (Eq. 5) and ends where its outside error is back to e, on the normal of
// T_i (Eq. 7). Process I fixes the count n at e = E; Process II lowers e until
// R_n lands on the interval end B, so the polyline starts and ends on the curve.
//
// Everything works in the curve parameter with tangent and normal vectors
// (the paper's Eq. 12 generalisation), so vertical tangents need no care.
//
// Where this implementation chooses (see the .cpp for the reasons):
// - Roots: Newton inside a bracket that grows or bisects as needed, to
//   ~1e-13 mm; the paper used plain Newton-Raphson with numerical slopes.
// - Process II finds the same e as the paper's 5 % steps and bisection, but
//   with a predicted first e (segment counts scale with 1 / sqrt(e)) and
//   secant steps inside the bracket. Its first stopping rule is one-sided:
//   R_n at or past B by at most epsilon, so the last segment, cut back to B,
//   never bulges more than e. Process I keeps the paper's two-sided test.
// - The end gap is measured on the osculating parabola at B, not on the
//   R = 50 mm arc (whose different bend would put a kink in the gap).
// - n = 1 is the chord A B; its bulge is computed directly.
// - Intervals turning by more than 120 degrees are split (never in the paper).
#pragma once

#include <limits>
#include <vector>

#include "models/curve.h"
#include "models/inflection.h"

namespace hwinterp::models {

struct OliOptions {
  // The paper's convergence limit epsilon (mm): Process II stops once R_n is
  // past B by at most this much.
  double convergence_mm = 1e-8;
  // Radius of the tangent circular arc that extends an interval past its end
  // (the paper's R, Eq. 8-10). Only root searches past B use it; the result
  // does not depend on it.
  double extension_radius_mm = 50;
  // Process II evaluations (Step 4 and Step 5 together) before the second
  // stopping rule ends it.
  int max_process2_evaluations = 200;
  // Refuse to plan more segments than this (a tolerance too fine for the curve).
  int max_segments = 200000;
  // An interval whose tangent turns by more than this is split into equal
  // turns: the method's equations are monotone only while the tangent turns
  // by less than 180 degrees. The paper's intervals turn by at most 99
  // degrees (Cam 2, Portion III), so they are never split.
  double max_interval_turn_deg = 120;
  InflectionOptions inflections;
};

// One single-convex or single-concave interval [t_begin, t_end] of the curve.
struct OliInterval {
  double t_begin = 0, t_end = 0;
  int sign = 0;      // curvature sign: +1 turns left, -1 right, 0 straight
  int segments = 0;  // n
  // Achieved e, the interval's largest |error|: every segment reaches +e on
  // the inside of the bend and the joints lie e outside (n = 1: the chord's
  // bulge; a straight interval: 0).
  double error = 0;
  // n + 1 vertices: curve(t_begin), the n - 1 joints (each e outside the
  // curve), curve(t_end).
  std::vector<Vec2> vertices;
  // Curve parameters of each segment's inside extremum P_i and crossing R_i.
  std::vector<double> t_extremum, t_crossing;
  int process2_evaluations = 0;       // chains evaluated by Process II (0: not needed)
  double end_gap_mm = 0;              // R_n past B at the final e (0 <= gap <= convergence_mm)
  bool second_stopping_rule = false;  // Process II ended by the second rule
};

// The whole curve: the intervals in order, n their sum, e their maximum.
struct OliPlan {
  std::vector<OliInterval> intervals;
  std::vector<Vec2> vertices;  // the whole polyline (segments + 1 points)
  int segments = 0;
  double error = 0;
};

// Splits `curve` at its inflections (and where an interval turns too far, see
// OliOptions) and plans every interval with tolerance E.
// Throws std::invalid_argument when the tolerance is not positive and finite,
// is too coarse for the curve (more than 1/8 of its smallest radius of
// curvature: the segments would turn by more than the method's geometry
// allows), too fine (more than max_segments), or the curve cannot be split
// (see find_inflections).
OliPlan plan_optimal_linear(const PlanarCurve& curve, double tolerance, const OliOptions& opt = {});

// One interval [t0, t1] of a single curvature sign.
OliInterval plan_optimal_linear_interval(const PlanarCurve& curve, double t0, double t1,
                                         double tolerance, const OliOptions& opt = {});

// Process I with a fixed count: chains `segments` segments of error extremum
// e0 from the start of [t0, t1] and returns how far (mm, signed) the last
// crossing point R_n lies past the interval end (first order; the sign is
// exact). Negative (-infinity when far short, or for n <= 0): n segments at
// e0 cannot reach the end; +infinity: an earlier segment already passed it.
double oli_chain_end_gap(const PlanarCurve& curve, double t0, double t1, int segments, double e0,
                         const OliOptions& opt = {});

// Largest |curvature| over uniform samples of the curve (1/mm).
double max_abs_curvature(const PlanarCurve& curve, int samples = 2048);

// Signed angle (radians) the tangent turns through over [t0, t1].
double tangent_turn(const PlanarCurve& curve, double t0, double t1, int samples = 512);

}  // namespace hwinterp::models

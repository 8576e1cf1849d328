// Double-precision reference model of the odd-even steps third-order approach
// interpolation of the logarithmic curve A = a ln(1 + b X) (paper
// 001_46110e999325a38e.txt): 4-axis (X, Y, Z, A) grinding of conical mills with
// constant spiral angle S, cone angle C and rake r, end diameter D1:
//     a = tan S / tan C,  b = 2 tan C / D1,  Y = X tan C,  Z = X tan C sin r.
//
// One interpolation cycle starts at P0 = (X0, A0) and makes two steps of length
// dl in the (X, A) plane:
//   odd step  P0 -> P1: along the tangent at X0 (Eqs. 8-11);
//   even step P1 -> P2: Eqs. 14/15 exactly as printed (third-order Taylor
//             approach; sin^2 theta is the tangent angle at the cycle start P0,
//             and Eq. 15's numerator has no sin^2 theta), or, for comparison,
//             the exact step: the circle of radius dl around P1 cut with the
//             true curve.
// Only X feeds back into the formulas; A is the running sum of its increments
// (that is what a stepper does: it can only add the increments it is given).
// The run makes whole odd+even cycles until an even point reaches X >= x_end.
//
// This is the model a fixed-point log_stepper core states its error against.
#pragma once

#include <cstddef>
#include <vector>

#include "models/curve.h"

namespace hwinterp::models {

struct LogCurveParams {
  double d1_mm = 10;       // end diameter D1 of the cutter, > 0
  double spiral_deg = 30;  // spiral angle S, in (0, 90)
  double cone_deg = 5;     // cone angle C, in (0, 90)
  double rake_deg = 8;     // rake r, in (0, 90)
  double dl_mm = 0.2;      // instruction interpolation length, > 0
  double x_end_mm = 30;    // the run stops at the first even point with X >= x_end, > 0
};

enum class EvenStep {
  kPaper,  // Eqs. 14 and 15 as printed
  kExact,  // circle of radius dl around P1 intersected with the true curve
};

// Runs longer than this are refused (std::invalid_argument naming dl and x_end).
inline constexpr size_t kLogMaxPoints = 2'000'000;

struct LogPoint {
  size_t index = 0;                   // 0 = start point, odd indices end odd steps
  double x = 0, y = 0, z = 0, a = 0;  // interpolated axis positions (mm, mm, mm, rad)
  double pa = 0;                      // theoretical A = a ln(1 + b X) at the interpolated X
  double error = 0;                   // ErPA = pa - a (signed, rad)
  bool odd() const { return index % 2 == 1; }
};

// Largest |ErPA| over a set of points, with the signed value and its index.
struct LogMaxError {
  double abs = 0;    // |ErPA|
  double value = 0;  // ErPA at that point (signed)
  size_t index = 0;  // point index (0 when the set is empty)
};

struct LogRun {
  LogCurveParams params;
  EvenStep even_step = EvenStep::kPaper;
  double a = 0, b = 0;                     // curve constants
  std::vector<LogPoint> points;            // points[0] is the start (0, 0, 0, 0)
  LogMaxError max_all, max_odd, max_even;  // over points 1..N
  double x_last() const { return points.back().x; }
  size_t count() const { return points.size() - 1; }  // interpolated points (paper's count)
};

// Throws std::invalid_argument, naming the offending value, for D1 <= 0,
// angles outside (0, 90) degrees, dl <= 0, x_end <= 0, dl > x_end, non-finite
// input, or a run that would exceed kLogMaxPoints points.
void validate(const LogCurveParams& p);

// a = tan S / tan C and b = 2 tan C / D1.
double log_a(const LogCurveParams& p);
double log_b(const LogCurveParams& p);

// The curve (X, a ln(1 + b X)) for X in [0, x_end], t = X, for planners and
// cross-checks; defined (and analytic) for every X > -1/b.
ExplicitCurve log_planar_curve(double a, double b, double x_end);

// Increments of one cycle from X0 (A0 does not enter: only X feeds back).
struct LogCycle {
  double dx10, da10;  // odd step
  double dx21, da21;  // even step
  double sin2_theta;  // sin^2 of the tangent angle at P0
};
// Paper formulas (Eqs. 8, 9, 14, 15).
LogCycle log_cycle_paper(double a, double b, double dl, double x0);

// Forward intersection of the circle of radius dl around (x1, a1) with the
// true curve, searched in [x1, x1 + dl]: the exact even step's end X.
double log_exact_even_x(double a, double b, double dl, double x1, double a1);

LogRun run_log_interpolation(const LogCurveParams& p, EvenStep even = EvenStep::kPaper);

}  // namespace hwinterp::models

// Inflection points of a PlanarCurve: where the signed curvature changes sign.
// The optimal linear interpolation works on single-convex or single-concave
// intervals, so the curve is split at these points first (OLI paper, 2.3).
#pragma once

#include <vector>

#include "models/curve.h"

namespace hwinterp::models {

struct InflectionOptions {
  // Uniform samples of the curvature sign over [t_begin, t_end] (the paper's
  // "appropriate increment"); a sign change between neighbours is refined by
  // bisection to machine precision.
  int samples = 2048;
  // More inflections than this: the planner refuses the curve.
  int max_count = 256;
};

// Parameters of the inflections, sorted, strictly inside (t_begin, t_end).
// Curvature that vanishes only at an end (the cam laws at T = 0 and 1) is not
// an inflection; a run of zero curvature between opposite signs is split where
// the first sign ends. Throws std::invalid_argument when the curve is singular
// at a sample (zero or non-finite speed, non-finite curvature) or has more
// than max_count inflections.
std::vector<double> find_inflections(const PlanarCurve& curve, const InflectionOptions& opt = {});

// Sign of the curvature over [t0, t1] (+1 turns left, -1 right, 0 straight),
// from the sample of largest magnitude; meant for intervals between inflections.
int curvature_sign(const PlanarCurve& curve, double t0, double t1, int samples = 64);

}  // namespace hwinterp::models

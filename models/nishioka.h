// Nishioka's chord method (OLI paper, Appendix A), kept for comparison with
// the optimal linear interpolation: chords between curve points p(t_{i-1})
// and p(t_i), each chosen so that its midpoint lies exactly `tolerance` from
// the curve point at the mid-parameter, p((t_{i-1} + t_i) / 2) (Eq. A-4).
// That nominal error is neither measured along the normal nor at the
// chord's worst point, so the true normal error (polyline_verifier.h)
// exceeds it; the chords of a concave and a convex stretch lie on opposite
// sides of the curve.
#pragma once

#include <vector>

#include "models/curve.h"

namespace hwinterp::models {

struct NishiokaPlan {
  std::vector<double> t;       // chord end parameters, t.front() = t0, t.back() = t1
  std::vector<Vec2> vertices;  // the curve points at t
  int segments = 0;            // number of chords
  double last_chord_mm = 0;    // length of the last chord (it can all but vanish)
};

// One pass over [t0, t1]: each chord as long as the nominal error allows
// (the first parameter where it reaches `tolerance`); the last chord ends at
// t1 with a nominal error of at most `tolerance`. Throws
// std::invalid_argument on a non-positive tolerance or empty range.
NishiokaPlan plan_nishioka(const PlanarCurve& curve, double t0, double t1, double tolerance);

// Each single-convex or single-concave interval (split at the inflections,
// as the paper's comparison does for Cam 1's halves) in its own pass; the
// chords are concatenated.
NishiokaPlan plan_nishioka_by_intervals(const PlanarCurve& curve, double tolerance);

}  // namespace hwinterp::models

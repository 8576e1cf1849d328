// Independent check of any polyline against the PlanarCurve it approximates:
// the error of a point is its distance from the curve along the curve normal
// through it (the ISO/JIS form deviation the OLI paper uses), signed by side.
// The check knows nothing of how the polyline was made: it samples every
// segment, finds each sample's foot of the normal on the true curve by a
// nearest-point search in t, and refines the extremes of every segment.
#pragma once

#include <vector>

#include "models/curve.h"

namespace hwinterp::models {

struct PolylineCheckOptions {
  // Uniform samples per segment (ends included); the largest and smallest
  // sample errors are then refined by golden-section search.
  int samples_per_segment = 32;
  // Errors are positive on the side of the curve's left normal times this:
  // pass a cam's outward_sign() for the paper's convention (positive away
  // from the cam body).
  double side_sign = 1;
  // Curve samples that seed the nearest-point search.
  int curve_samples = 4096;
};

struct ErrorExtreme {
  double error = 0;           // signed (see side_sign)
  int segment = -1;           // 0-based segment index
  Vec2 point = Vec2::Zero();  // where on the polyline
  double t_foot = 0;          // curve parameter of its foot
};

struct PolylineCheck {
  double max_abs_error = 0;
  ErrorExtreme worst;          // largest |error|
  ErrorExtreme most_positive;  // largest error (0 when none is positive)
  ErrorExtreme most_negative;  // smallest error (0 when none is negative)
  int segments = 0;
  // Samples whose nearest curve point is an end of the curve and off its
  // normal there: the polyline runs past the curve (should be 0).
  int samples_past_ends = 0;
};

PolylineCheck verify_polyline(const PlanarCurve& curve, const std::vector<Vec2>& vertices,
                              const PolylineCheckOptions& opt = {});

// The error along the polyline, for plots like the paper's error curves.
struct ErrorSample {
  int segment = 0;
  double t_foot = 0;      // curve parameter of the foot of the normal
  double arc_length = 0;  // curve length from t_begin to the foot (mm)
  Vec2 point = Vec2::Zero();
  double error = 0;
};

// `samples_per_segment` uniform samples per segment (the shared vertex is
// listed once).
std::vector<ErrorSample> sample_polyline_error(const PlanarCurve& curve,
                                               const std::vector<Vec2>& vertices,
                                               int samples_per_segment = 16, double side_sign = 1);

}  // namespace hwinterp::models

// Inscribed-chord planner of paper 003_b291717b57510359.txt: from the current
// point (on the curve) draw the circle of radius r, the interpolation segment
// length, and take its next intersection with the curve, forward along the
// curve, as the next point. Every point lies on the curve; every chord is r long
// except, optionally, the last.
//
// End handling. The paper stops at the first point that reaches or passes the
// end: Table I's line (0,0)->(4,3) with r = 1 lands exactly on (4,3) after 5
// chords, Table II's arc (4,0)->(0,4) with r = 0.9 passes the end with its 7th
// point (-0.030180, 3.999886), 0.03 mm beyond it on the continued circle
// (kOvershoot). For a core that must stop on the end point, kClamp makes the
// last chord end exactly there (shorter than r).
#pragma once

#include <vector>

#include "models/curve.h"

namespace hwinterp::models {

enum class ChordEnd { kOvershoot, kClamp };

struct ChordStep {
  Vec2 center;       // the circle's centre: the previous point
  Vec2 point;        // its intersection with the curve: the new point
  double t = 0;      // curve parameter of `point` (> t_end when it overshoots)
  double chord = 0;  // |point - center|: r, except a clamped last chord
};

struct ChordResult {
  Vec2 start, end;  // the curve's end points
  std::vector<ChordStep> steps;
  bool exact_end = false;  // the last point is the end point
  double overshoot = 0;    // |last point - end| when the last point passed the end
  // Largest distance between a chord and the curve (chord height, sampled on
  // the curve between the two intersections).
  double max_chord_error = 0;
};

// Next parameter t > t_from at which the curve leaves the circle of radius r
// around `center`: the first crossing of |C(t) - center| = r from inside (or
// on) to outside, scanning forward from t_from in steps of r/8 of arc length
// (a loop of the curve shorter than that can be missed), then bisecting to
// adjacent doubles. `center` need not lie on the curve. The curve's formulas
// are used past t_end up to t_max. Throws std::runtime_error when there is no
// crossing before t_max.
double next_circle_intersection(const PlanarCurve& curve, const Vec2& center, double r,
                                double t_from, double t_max);

// General curve (t from t_begin to t_end; with kOvershoot the curve's
// formulas must be valid past t_end).
ChordResult inscribed_chord(const PlanarCurve& curve, double r,
                            ChordEnd end = ChordEnd::kOvershoot);

// Closed forms: a line a -> b (fixed step r along it), an arc around `center`
// from `start` to `end` (radius |start - center|, `end` projected onto the
// circle; start == end is a full circle), each chord turning by 2 asin(r / 2R).
ChordResult inscribed_chord_line(const Vec2& a, const Vec2& b, double r,
                                 ChordEnd end = ChordEnd::kOvershoot);
ChordResult inscribed_chord_arc(const Vec2& center, const Vec2& start, const Vec2& end, bool ccw,
                                double r, ChordEnd end_mode = ChordEnd::kOvershoot);

// Truncation towards zero to `decimals` places (how Table II prints).
double truncate_to(double v, int decimals);

}  // namespace hwinterp::models

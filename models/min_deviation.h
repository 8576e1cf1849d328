// Minimum-deviation and Bresenham line reference sequences (the third method of
// paper 004_dc68f1177cad466f.txt, and its integer-error-term form). Both work
// in the line's octant: every tick steps the major axis (the longer delta) and,
// when that is closer to the line, the minor axis too (a diagonal move), so a
// line completes in max(|dx|, |dy|) ticks and the minor coordinate is always the
// nearest lattice value: normal error <= max(|dx|, |dy|) / (2 L) <= 1/2 step.
//
//  - minimum deviation: evaluates the deviation F = minor |D| - major |d| of
//    both candidate moves and takes the smaller |F|; on a tie (the line passes
//    exactly midway) it takes the diagonal move.
//  - Bresenham: the decision variable D = 2|d| - |D|, updated by additions
//    only; it takes the diagonal when D > 0, so on a tie the axis move.
// Away from ties the two paths are identical.
#pragma once

#include "models/step_path.h"

namespace hwinterp::models {

StepPath min_deviation_line(const LatticePoint& start, const LatticePoint& end);
StepPath bresenham_line(const LatticePoint& start, const LatticePoint& end);

// max(|dx|, |dy|) / (2 L): the bound both methods meet (0 when axis-parallel).
double min_deviation_error_bound(const LatticePoint& start, const LatticePoint& end);

}  // namespace hwinterp::models

// The path-error metric shared by every fine interpolator (DDA, PPC, fixed
// ratio, minimum deviation, Bresenham): the normal (perpendicular) distance of
// each visited lattice point from the ideal straight line, in steps.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hwinterp::models {

// A point on the step lattice, one coordinate per axis (any number of axes).
using LatticePoint = std::vector<int64_t>;

// Normal distance of `p` from the infinite line through `a` and `b` (steps).
// When a == b the "line" is a point and the distance is |p - a|.
double point_line_distance(const LatticePoint& p, const LatticePoint& a, const LatticePoint& b);

struct PathError {
  double max_error = 0;  // max normal distance over the visited points
  size_t argmax = 0;     // index of the worst point in the visited list
};

// Max normal distance of `visited` from the line a -> b.
PathError max_line_error(const std::vector<LatticePoint>& visited, const LatticePoint& a,
                         const LatticePoint& b);

}  // namespace hwinterp::models

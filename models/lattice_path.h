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

// point_line_distance(p, a, b) for many points p of one line: the line's
// direction and squared length are computed once (a scoreboard measures
// every visited point of a move this way). The same exact arithmetic, the
// same results.
class LineDistance {
 public:
  // Throws std::invalid_argument when a and b have different axis counts.
  LineDistance(const LatticePoint& a, const LatticePoint& b);
  // Throws std::invalid_argument when p has another axis count than a.
  double operator()(const LatticePoint& p) const;

 private:
  LatticePoint a_;
  std::vector<__int128> d_;   // b - a
  unsigned __int128 dd_ = 0;  // |b - a|^2
};

struct PathError {
  double max_error = 0;  // max normal distance over the visited points
  size_t argmax = 0;     // index of the worst point in the visited list
};

// Max normal distance of `visited` from the line a -> b.
PathError max_line_error(const std::vector<LatticePoint>& visited, const LatticePoint& a,
                         const LatticePoint& b);

}  // namespace hwinterp::models

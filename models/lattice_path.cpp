#include "models/lattice_path.h"

#include <cmath>
#include <stdexcept>

namespace hwinterp::models {

double point_line_distance(const LatticePoint& p, const LatticePoint& a, const LatticePoint& b) {
  return LineDistance(a, b)(p);
}

LineDistance::LineDistance(const LatticePoint& a, const LatticePoint& b) : a_(a) {
  if (a.size() != b.size()) throw std::invalid_argument("point_line_distance: axis counts differ");
  d_.reserve(a.size());
  for (size_t i = 0; i < a.size(); ++i) {
    const __int128 di = __int128{b[i]} - a[i];
    d_.push_back(di);
    dd_ += static_cast<unsigned __int128>(di * di);
  }
}

double LineDistance::operator()(const LatticePoint& p) const {
  if (p.size() != a_.size()) throw std::invalid_argument("point_line_distance: axis counts differ");
  // |w x d| / |d| with w = p - a, d = b - a: the squared norm of the cross
  // product, sum over i < j of (w_i d_j - w_j d_i)^2, exact in 128-bit
  // integers. (|w|^2 - (w.d)^2/|d|^2 in doubles cancels catastrophically: it
  // lost ~1e-4 steps on lines of 10^4 steps, more than a bound's slack.)
  // Exact while the differences stay below 2^60 (every sum of products fits).
  using i128 = __int128;
  unsigned __int128 cross2 = 0;
  i128 ww = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const i128 wi = i128{p[i]} - a_[i], di = d_[i];
    ww += wi * wi;
    for (size_t j = i + 1; j < p.size(); ++j) {
      const i128 c = wi * d_[j] - (i128{p[j]} - a_[j]) * di;
      cross2 += static_cast<unsigned __int128>(c * c);
    }
  }
  if (dd_ == 0) return std::sqrt(static_cast<double>(ww));
  return std::sqrt(static_cast<double>(cross2) / static_cast<double>(dd_));
}

PathError max_line_error(const std::vector<LatticePoint>& visited, const LatticePoint& a,
                         const LatticePoint& b) {
  PathError out;
  for (size_t i = 0; i < visited.size(); ++i) {
    const double e = point_line_distance(visited[i], a, b);
    if (e > out.max_error) {
      out.max_error = e;
      out.argmax = i;
    }
  }
  return out;
}

}  // namespace hwinterp::models

#include "models/lattice_path.h"

#include <cmath>
#include <stdexcept>

namespace hwinterp::models {

double point_line_distance(const LatticePoint& p, const LatticePoint& a, const LatticePoint& b) {
  if (p.size() != a.size() || a.size() != b.size())
    throw std::invalid_argument("point_line_distance: axis counts differ");
  // |w|^2 - (w.u)^2 with w = p - a and u the unit direction; computed from
  // integer differences so long lines keep their precision.
  double ww = 0, wd = 0, dd = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const double w = static_cast<double>(p[i] - a[i]);
    const double d = static_cast<double>(b[i] - a[i]);
    ww += w * w;
    wd += w * d;
    dd += d * d;
  }
  if (dd == 0) return std::sqrt(ww);
  const double perp2 = ww - wd * wd / dd;
  return perp2 > 0 ? std::sqrt(perp2) : 0.0;
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

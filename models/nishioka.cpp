#include "models/nishioka.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "models/inflection.h"

namespace hwinterp::models {
namespace {

// Eq. A-4: distance between the chord midpoint and the mid-parameter point.
double nominal_error(const PlanarCurve& c, double ta, const Vec2& pa, double t) {
  return (c.point(0.5 * (ta + t)) - 0.5 * (pa + c.point(t))).norm();
}

}  // namespace

NishiokaPlan plan_nishioka(const PlanarCurve& curve, double t0, double t1, double tolerance) {
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("tolerance must be positive and finite");
  if (!(t1 > t0)) throw std::invalid_argument("Nishioka: empty parameter range");
  NishiokaPlan out;
  out.t.push_back(t0);
  out.vertices.push_back(curve.point(t0));
  const double span = t1 - t0;
  const double tol_t =
      4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(t0), std::abs(t1)) +
      1e-15 * span;
  double ta = t0;
  while (ta < t1) {
    if (out.t.size() > 10000000) throw std::invalid_argument("Nishioka: too many chords");
    const Vec2 pa = out.vertices.back();
    // Step guess from the local circle: a chord of parameter length h has
    // nominal error ~ |curvature| (v h)^2 / 8.
    const double k = std::abs(curve.curvature(ta)), v = curve.d1(ta).norm();
    double h = k > 0 ? std::sqrt(8 * tolerance / k) / v : span / 16;
    h = std::min(h, span / 16);
    double lo = ta, hi = std::nan("");
    // March in quarter steps to the first parameter where the nominal error
    // reaches the tolerance (it need not grow monotonically across an
    // inflection), then bisect.
    for (double x = ta + 0.5 * h;; x += 0.25 * h) {
      if (x >= t1) {
        if (nominal_error(curve, ta, pa, t1) <= tolerance) {
          lo = t1;
        } else {
          hi = t1;
        }
        break;
      }
      if (nominal_error(curve, ta, pa, x) >= tolerance) {
        hi = x;
        break;
      }
      lo = x;
    }
    double tb = lo;
    if (!std::isnan(hi)) {
      for (int it = 0; it < 200 && hi - lo > tol_t; ++it) {
        const double mid = 0.5 * (lo + hi);
        (nominal_error(curve, ta, pa, mid) < tolerance ? lo : hi) = mid;
      }
      tb = lo;
    }
    if (!(tb > ta)) tb = std::min(t1, ta + tol_t);  // never stall
    out.t.push_back(tb);
    out.vertices.push_back(curve.point(tb));
    ta = tb;
  }
  out.segments = static_cast<int>(out.t.size()) - 1;
  out.last_chord_mm = (out.vertices.back() - out.vertices[out.vertices.size() - 2]).norm();
  return out;
}

NishiokaPlan plan_nishioka_by_intervals(const PlanarCurve& curve, double tolerance) {
  std::vector<double> cuts{curve.t_begin()};
  for (double t : find_inflections(curve)) cuts.push_back(t);
  cuts.push_back(curve.t_end());
  NishiokaPlan out;
  for (size_t j = 0; j + 1 < cuts.size(); ++j) {
    const NishiokaPlan part = plan_nishioka(curve, cuts[j], cuts[j + 1], tolerance);
    const size_t skip = out.t.empty() ? 0 : 1;  // shared end point
    out.t.insert(out.t.end(), part.t.begin() + skip, part.t.end());
    out.vertices.insert(out.vertices.end(), part.vertices.begin() + skip, part.vertices.end());
    out.segments += part.segments;
    out.last_chord_mm = part.last_chord_mm;
  }
  return out;
}

}  // namespace hwinterp::models

#include "models/inflection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hwinterp::models {
namespace {

// cross(P', P'') has the sign of the curvature and, unlike the curvature, no
// division: cheap and exact in sign where the speed is regular.
double turn(const PlanarCurve& c, double t) { return cross2(c.d1(t), c.d2(t)); }

int sign_of(double v, double zero) { return v > zero ? 1 : (v < -zero ? -1 : 0); }

}  // namespace

std::vector<double> find_inflections(const PlanarCurve& curve, const InflectionOptions& opt) {
  const int n = std::max(opt.samples, 8);
  const double t0 = curve.t_begin(), t1 = curve.t_end();
  std::vector<double> ts(n + 1), hs(n + 1);
  double scale = 0;
  for (int j = 0; j <= n; ++j) {
    ts[j] = j == n ? t1 : t0 + (t1 - t0) * j / n;
    const Vec2 v = curve.d1(ts[j]);
    const double speed = v.norm();
    hs[j] = turn(curve, ts[j]);
    if (!(speed > 0) || !std::isfinite(speed) || !std::isfinite(hs[j]))
      throw std::invalid_argument("curve is singular at t = " + std::to_string(ts[j]) +
                                  " (zero or non-finite speed or curvature)");
    scale = std::max(scale, std::abs(hs[j]));
  }
  // Values this small relative to the largest are rounding noise around a zero.
  const double zero = 1e-13 * scale;

  std::vector<double> out;
  int last_sign = 0;
  int last_index = -1;
  for (int j = 0; j <= n; ++j) {
    const int s = sign_of(hs[j], zero);
    if (s == 0) continue;
    if (last_sign != 0 && s != last_sign) {
      // Bisect on "still the left sign": converges to where that sign ends.
      double lo = ts[last_index], hi = ts[j];
      for (int k = 0; k < 200 && hi - lo > 2 * std::numeric_limits<double>::epsilon() *
                                               std::max(std::abs(lo), std::abs(hi));
           ++k) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (sign_of(turn(curve, mid), 0) == last_sign ? lo : hi) = mid;
      }
      out.push_back(0.5 * (lo + hi));
      if (static_cast<int>(out.size()) > opt.max_count)
        throw std::invalid_argument("curvature changes sign more than " +
                                    std::to_string(opt.max_count) + " times");
    }
    last_sign = s;
    last_index = j;
  }
  return out;
}

int curvature_sign(const PlanarCurve& curve, double t0, double t1, int samples) {
  double best = 0;
  for (int j = 0; j <= samples; ++j) {
    const double h = turn(curve, t0 + (t1 - t0) * j / samples);
    if (std::abs(h) > std::abs(best)) best = h;
  }
  return best > 0 ? 1 : (best < 0 ? -1 : 0);
}

}  // namespace hwinterp::models

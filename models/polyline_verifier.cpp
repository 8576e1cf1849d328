#include "models/polyline_verifier.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hwinterp::models {
namespace {

// Nearest point of the curve to a query point: a scan of precomputed curve
// samples near the previous answer (everywhere when that fails), then Newton
// on d/dt |P(t) - q|^2 / 2 = (P - q) . P' inside the bracketing samples.
class FootFinder {
 public:
  struct Foot {
    double t = 0;
    Vec2 p, d1;
    bool off_end = false;  // nearest point is a curve end, not a normal foot
  };

  FootFinder(const PlanarCurve& c, int samples) : c_(c) {
    const int m = std::max(samples, 16);
    t_.resize(m + 1);
    p_.resize(m + 1);
    s_.resize(m + 1);
    const double t0 = c.t_begin(), t1 = c.t_end();
    for (int j = 0; j <= m; ++j) {
      t_[j] = j == m ? t1 : t0 + (t1 - t0) * j / m;
      p_[j] = c.point(t_[j]);
    }
    // Arc length at the samples: 2-point Gauss-Legendre per sample interval.
    s_[0] = 0;
    const double g = 0.5 / std::sqrt(3.0);
    for (int j = 0; j < m; ++j) {
      const double mid = 0.5 * (t_[j] + t_[j + 1]), h = t_[j + 1] - t_[j];
      s_[j + 1] = s_[j] + 0.5 * h * (c.d1(mid - g * h).norm() + c.d1(mid + g * h).norm());
    }
    double extent = 0;
    for (const Vec2& p : p_) extent = std::max(extent, p.norm());
    tol_ = 4 * std::numeric_limits<double>::epsilon() *
           std::max({extent, std::abs(t0), std::abs(t1), 1.0});
  }

  // `hint`: sample index of a nearby earlier foot (-1: none, scan all
  // samples); updated.
  Foot find(const Vec2& q, int* hint) const {
    const int m = static_cast<int>(t_.size()) - 1;
    const int j = *hint < 0 ? nearest_sample(q) : descend(q, *hint);
    *hint = j;
    // The foot lies between the neighbours of the nearest sample when the
    // samples are dense against the curvature (they are: thousands over a
    // cam); Newton from the sample converges there. Only when it leaves that
    // bracket is the bracket checked and widened, and bisection takes over.
    int lo = std::max(j - 1, 0), hi = std::min(j + 1, m);
    double a = t_[lo], b = t_[hi];
    bool checked = false;
    double t = t_[j];
    for (int it = 0; it < 200; ++it) {
      const CurveJetValue v = c_.jet(t);
      const Vec2 r = v.p - q;
      const double d = r.dot(v.d1), dd = v.d1.squaredNorm() + r.dot(v.d2);
      if (checked) (d < 0 ? a : b) = t;
      double next = dd > 0 ? t - d / dd : std::nan("");
      if (!(next >= a && next <= b)) {
        if (!checked) {
          // Widen until the slope of the squared distance changes sign, or
          // a curve end is the minimum.
          for (int k = 0; k < m && lo > 0 && slope(q, t_[lo]) > 0; ++k) --lo;
          for (int k = 0; k < m && hi < m && slope(q, t_[hi]) < 0; ++k) ++hi;
          if (slope(q, t_[lo]) >= 0) return end_foot(q, t_[lo]);  // before the start
          if (slope(q, t_[hi]) <= 0) return end_foot(q, t_[hi]);  // past the end
          a = t_[lo];
          b = t_[hi];
          checked = true;
        }
        next = 0.5 * (a + b);
      }
      if (std::abs(next - t) <= tol_ || b - a <= tol_) {
        t = next;
        break;
      }
      t = next;
    }
    const CurveJetValue v = c_.jet(t);
    Foot f;
    f.t = t;
    f.p = v.p;
    f.d1 = v.d1;
    return f;
  }

  // Arc length from t_begin to t (mm), interpolated between the samples.
  double arc_length(double t) const {
    const auto it = std::upper_bound(t_.begin(), t_.end(), t);
    if (it == t_.begin()) return 0;
    if (it == t_.end()) return s_.back();
    const size_t j = static_cast<size_t>(it - t_.begin()) - 1;
    return s_[j] + (s_[j + 1] - s_[j]) * (t - t_[j]) / (t_[j + 1] - t_[j]);
  }

 private:
  int nearest_sample(const Vec2& q) const {
    int best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for (int j = 0; j < static_cast<int>(p_.size()); ++j) {
      const double d = (p_[j] - q).squaredNorm();
      if (d < best_d) {
        best_d = d;
        best = j;
      }
    }
    return best;
  }

  // From a sample near the answer, walk downhill in distance.
  int descend(const Vec2& q, int j) const {
    const int m = static_cast<int>(p_.size()) - 1;
    double d = (p_[j] - q).squaredNorm();
    for (const int step : {1, -1}) {
      while (j + step >= 0 && j + step <= m) {
        const double dn = (p_[j + step] - q).squaredNorm();
        if (dn >= d) break;
        d = dn;
        j += step;
      }
    }
    return j;
  }

  double slope(const Vec2& q, double t) const {
    const CurveJetValue v = c_.jet(t);
    return (v.p - q).dot(v.d1);
  }

  Foot end_foot(const Vec2& q, double t) const {
    const CurveJetValue v = c_.jet(t);
    Foot f;
    f.t = t;
    f.p = v.p;
    f.d1 = v.d1;
    // Off the normal unless the query lies on it (within rounding).
    const Vec2 u = v.d1.normalized();
    f.off_end = std::abs((q - v.p).dot(u)) > 1e3 * tol_;
    return f;
  }

  const PlanarCurve& c_;
  std::vector<double> t_;
  std::vector<Vec2> p_;
  std::vector<double> s_;
  double tol_ = 0;
};

struct Probe {
  double error = 0;
  Vec2 point;
  double t_foot = 0;
  bool off_end = false;
  int index = -1;  // curve sample nearest to the foot (a hint for neighbours)
};

Probe probe(const FootFinder& finder, const Vec2& q, int* hint, double side) {
  const FootFinder::Foot f = finder.find(q, hint);
  const Vec2 u = f.d1.normalized();
  const Vec2 left(-u.y(), u.x());
  const Vec2 r = q - f.p;
  Probe out;
  out.point = q;
  out.t_foot = f.t;
  out.off_end = f.off_end;
  out.index = *hint;
  // On the normal the offset is all along `left`; off an end, keep the
  // whole distance with the side it lies on.
  const double along = r.dot(left);
  out.error = side * (f.off_end ? std::copysign(r.norm(), along) : along);
  return out;
}

// The extreme of sign `dir` (+1 max, -1 min) of the error on the segment
// a + lambda (b - a), from three samples lambda0 < lambda1 < lambda2 whose
// middle one is the most extreme: successive parabolic interpolation (the
// error is smooth and nearly a parabola at its extreme), with a
// golden-section step whenever the parabola is unusable.
Probe refine(const FootFinder& finder, const Vec2& a, const Vec2& b, double l0, double l1,
             double l2, Probe p1, int* hint, double side, double dir) {
  const double golden = 0.5 * (3 - std::sqrt(5.0));
  double x[3] = {l0, l1, l2};
  double y[3] = {dir * probe(finder, a + l0 * (b - a), hint, side).error, dir * p1.error,
                 dir * probe(finder, a + l2 * (b - a), hint, side).error};
  Probe best = p1;
  for (int it = 0; it < 60 && x[2] - x[0] > 1e-9; ++it) {
    // Vertex of the parabola through the three points.
    const double d1 = (x[1] - x[0]) * (y[1] - y[2]), d2 = (x[1] - x[2]) * (y[1] - y[0]);
    const double den = 2 * (d1 - d2);
    double xn = den != 0 ? x[1] - ((x[1] - x[0]) * d1 - (x[1] - x[2]) * d2) / den : std::nan("");
    const double room = 1e-3 * (x[2] - x[0]);
    if (!(xn > x[0] + room && xn < x[2] - room) || std::abs(xn - x[1]) < 1e-12) {
      // Golden step into the larger side.
      xn =
          x[1] - x[0] > x[2] - x[1] ? x[1] - golden * (x[1] - x[0]) : x[1] + golden * (x[2] - x[1]);
    }
    const Probe pn = probe(finder, a + xn * (b - a), hint, side);
    const double yn = dir * pn.error;
    if (yn > y[1]) {  // new centre; the old centre bounds its side
      if (xn < x[1]) {
        x[2] = x[1];
        y[2] = y[1];
      } else {
        x[0] = x[1];
        y[0] = y[1];
      }
      x[1] = xn;
      y[1] = yn;
      best = pn;
    } else if (xn < x[1]) {
      x[0] = xn;
      y[0] = yn;
    } else {
      x[2] = xn;
      y[2] = yn;
    }
    if (std::abs(xn - x[1]) < 1e-9 && it > 2) break;
  }
  return best;
}

void keep(ErrorExtreme& slot, const Probe& p, int segment, bool better) {
  if (!better) return;
  slot.error = p.error;
  slot.segment = segment;
  slot.point = p.point;
  slot.t_foot = p.t_foot;
}

}  // namespace

PolylineCheck verify_polyline(const PlanarCurve& curve, const std::vector<Vec2>& vertices,
                              const PolylineCheckOptions& opt) {
  if (vertices.size() < 2) throw std::invalid_argument("verify_polyline: fewer than 2 vertices");
  const int k = std::max(opt.samples_per_segment, 2);
  const FootFinder finder(curve, opt.curve_samples);
  PolylineCheck out;
  out.segments = static_cast<int>(vertices.size()) - 1;
  int hint = -1;
  std::vector<Probe> probes(k + 1);
  for (int seg = 0; seg < out.segments; ++seg) {
    const Vec2& a = vertices[seg];
    const Vec2& b = vertices[seg + 1];
    for (int j = 0; j <= k; ++j) {
      probes[j] = probe(finder, a + (static_cast<double>(j) / k) * (b - a), &hint, opt.side_sign);
      out.samples_past_ends += probes[j].off_end;
    }
    for (const double dir : {1.0, -1.0}) {
      int best = 0;
      for (int j = 1; j <= k; ++j)
        if (dir * probes[j].error > dir * probes[best].error) best = j;
      Probe p = probes[best];
      if (best > 0 && best < k) {
        int h = probes[best].index;
        const Probe r = refine(finder, a, b, (best - 1.0) / k, static_cast<double>(best) / k,
                               (best + 1.0) / k, probes[best], &h, opt.side_sign, dir);
        if (dir * r.error > dir * p.error) p = r;
      }
      ErrorExtreme& slot = dir > 0 ? out.most_positive : out.most_negative;
      keep(slot, p, seg, dir * p.error > dir * slot.error);
      keep(out.worst, p, seg, std::abs(p.error) > out.max_abs_error);
      out.max_abs_error = std::max(out.max_abs_error, std::abs(p.error));
    }
  }
  return out;
}

std::vector<ErrorSample> sample_polyline_error(const PlanarCurve& curve,
                                               const std::vector<Vec2>& vertices,
                                               int samples_per_segment, double side_sign) {
  if (vertices.size() < 2)
    throw std::invalid_argument("sample_polyline_error: fewer than 2 vertices");
  const int k = std::max(samples_per_segment, 1);
  const FootFinder finder(curve, 4096);
  std::vector<ErrorSample> out;
  int hint = -1;
  for (size_t seg = 0; seg + 1 < vertices.size(); ++seg) {
    const Vec2& a = vertices[seg];
    const Vec2& b = vertices[seg + 1];
    for (int j = seg == 0 ? 0 : 1; j <= k; ++j) {
      const Probe p = probe(finder, a + (static_cast<double>(j) / k) * (b - a), &hint, side_sign);
      ErrorSample s;
      s.segment = static_cast<int>(seg);
      s.t_foot = p.t_foot;
      s.arc_length = finder.arc_length(p.t_foot);
      s.point = p.point;
      s.error = p.error;
      out.push_back(s);
    }
  }
  return out;
}

}  // namespace hwinterp::models

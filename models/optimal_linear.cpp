#include "models/optimal_linear.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/common.h"

namespace hwinterp::models {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Local geometry at one parameter, oriented to the interval: n points towards
// the centre of curvature and k >= 0 is the curvature about it.
struct Frame {
  Vec2 p;
  double v = 0;  // speed |dP/dt|
  Vec2 u;        // unit tangent
  Vec2 n;        // unit normal towards the inside of the bend
  double k = 0;  // curvature towards n
};

struct ValueSlope {
  double f = 0, df = 0;
};

struct Root {
  double t = 0;
  bool found = false;  // false: f < 0 all the way to t_max
};

// Root of a nondecreasing f on [lo, t_max] with f(lo) < 0 (not evaluated).
// Newton from `guess`, kept inside the bracket known so far; bisection when
// Newton leaves it or stalls; doubling steps while no upper end is known.
// Several of the paper's equations have a zero derivative at their lower end
// (Eq. 5 at P, Eq. 4 at the interval start), which is why Newton alone is
// not enough.
template <typename Fn>
Root solve_rising(const Fn& fn, double lo, double guess, double t_max, double tol) {
  const double lo0 = lo;
  double last_step = kInf;
  double hi = t_max;
  bool hi_known = false;
  double x = guess;
  if (!(x > lo)) x = lo + std::min(t_max - lo, 1e3 * tol);
  if (x > t_max) x = t_max;
  for (int it = 0; it < 300; ++it) {
    const ValueSlope r = fn(x);
    if (r.f == 0) return {x, true};
    if (r.f < 0) {
      lo = x;
      if (!hi_known && lo >= t_max) return {t_max, false};
    } else {
      hi = x;
      hi_known = true;
    }
    if (hi_known && hi - lo <= tol) return {0.5 * (lo + hi), true};
    const double xn = r.df > 0 && std::isfinite(r.df) ? x - r.f / r.df : std::nan("");
    // Newton only while it stays strictly inside what is known, and only for
    // a bounded number of steps: bisection always finishes.
    if (it < 20 && xn > lo && xn < hi) {
      // Quadratic convergence: after steps d1 then d2 the error left at xn
      // is about d2^3 / d1^2, so a small enough step is accepted unevaluated.
      // Before any step, the curvature of f sets the scale instead: these
      // equations bend over the distance from their lower end, about
      // f'' / (2 f') ~ 1 / (2 (x - lo0)), so the error is step^2 / (2 (x - lo0)).
      const double step = std::abs(xn - x);
      const double left = std::isfinite(last_step) ? step * step * step / (last_step * last_step)
                                                   : step * step / (2 * (x - lo0));
      if (step <= tol || left <= tol) return {xn, true};
      last_step = step;
      x = xn;
    } else if (hi_known) {
      last_step = kInf;
      x = 0.5 * (lo + hi);
    } else {
      last_step = kInf;
      x = std::min(t_max, lo + std::max(2 * (lo - lo0), 16 * tol));
    }
  }
  return {0.5 * (lo + hi), hi_known};
}

// Next length in a slowly varying sequence ..., older, last (linear trend),
// falling back to `last` when the trend would shrink it by half or more.
double extrapolate(double last, double older) {
  const double d = 2 * last - older;
  return d > 0.5 * last ? d : last;
}

// One segment of the chain: from S (on the curve normal at t_start, `offset`
// outside the curve) along the line parallel to the tangent at P.
struct Segment {
  double t_start = 0, offset = 0;
  Vec2 start;
  double e0 = 0;                  // error extremum it was solved for
  double tp = 0, tr = 0, tt = 0;  // P, R, T parameters (-inf: not solved)
  Vec2 line_normal;               // inward normal at P: the line's normal
  Vec2 end;                       // V: where the line meets the normal at T
  double end_offset = 0;          // |TV|
};

class IntervalSolver {
 public:
  IntervalSolver(const PlanarCurve& c, double ta, double tb, int sign, const OliOptions& opt)
      : c_(c), ta_(ta), tb_(tb), sign_(sign), opt_(opt) {
    if (!(opt.extension_radius_mm > 0))
      throw std::invalid_argument("OLI: extension radius must be positive");
    fb_ = curve_frame(tb);
    radius_ = opt.extension_radius_mm;
    // A quarter of the tangent arc is far more than any root search needs
    // past B; the arc turns by 90 degrees there.
    t_max_ = tb + 0.5 * kPi * radius_ / fb_.v;
    double v_max = std::max(fb_.v, curve_frame(ta).v);
    for (int j = 1; j < 16; ++j) v_max = std::max(v_max, curve_frame(ta + (tb - ta) * j / 16).v);
    const double scale = std::max({std::abs(ta), std::abs(tb), std::abs(t_max_)});
    tol_t_ = std::max(1e-13 / v_max, 8 * std::numeric_limits<double>::epsilon() * scale);
  }

  Frame frame(double t) const { return t <= tb_ ? curve_frame(t) : extension_frame(t); }

  // The feature points of one segment, each solved from the previous one;
  // `hint` (a neighbouring or earlier solution) scales into the first guess.
  // Each returns false when its root lies beyond the end of the extension.
  bool solve_p(Segment& s, const Segment* hint, const Segment* hint2) const {
    double guess;
    if (hint) {
      // Segment lengths scale with sqrt(e0) on a circle; two earlier
      // segments of the same kind also give the trend along the curve.
      double d =
          (hint->tp - hint->t_start) * std::sqrt((s.offset + s.e0) / (hint->offset + hint->e0));
      if (hint2 && (hint2->offset > 0) == (hint->offset > 0))
        d = extrapolate(d, (hint2->tp - hint2->t_start) *
                               std::sqrt((s.offset + s.e0) / (hint2->offset + hint2->e0)));
      guess = s.t_start + d;
    } else {
      // Circle of the local curvature: the line e0 inside reaches its
      // tangent-parallel point sqrt(2 rho (offset + e0)) along.
      const Frame f0 = frame(s.t_start);
      const double room = tb_ - s.t_start;
      guess = f0.k > 0 ? s.t_start + std::min(std::sqrt(2 * (s.offset + s.e0) / f0.k) / f0.v,
                                              room > 0 ? room : t_max_ - s.t_start)
                       : s.t_start + 0.5 * (t_max_ - s.t_start);
    }
    const Vec2 S = s.start;
    const double e0 = s.e0;
    // Eq. 4: distance from P to the line through S parallel to its tangent.
    const auto F = [&](double t) {
      const Frame f = frame(t);
      return ValueSlope{(S - f.p).dot(f.n) - e0, f.k * f.v * (f.p - S).dot(f.u)};
    };
    const Root r = solve_rising(F, s.t_start, guess, t_max_, tol_t_);
    s.tp = r.t;
    s.line_normal = frame(r.t).n;
    return r.found;
  }

  bool solve_r(Segment& s, const Segment* hint, const Segment* hint2) const {
    double guess = s.tp + (s.tp - s.t_start) * std::sqrt(s.e0 / (s.offset + s.e0));
    if (hint) {
      double d = (hint->tr - hint->tp) * std::sqrt(s.e0 / hint->e0);
      if (hint2) d = extrapolate(d, (hint2->tr - hint2->tp) * std::sqrt(s.e0 / hint2->e0));
      guess = s.tp + d;
    }
    const Vec2 S = s.start, nl = s.line_normal;
    // Eq. 5: the curve crosses the line.
    const auto G = [&](double t) {
      const Frame f = frame(t);
      return ValueSlope{(f.p - S).dot(nl), f.v * f.u.dot(nl)};
    };
    const Root r = solve_rising(G, s.tp, guess, t_max_, tol_t_);
    s.tr = r.t;
    return r.found;
  }

  bool solve_t(Segment& s, const Segment* hint, const Segment* hint2) const {
    double guess = s.tr + (s.tr - s.tp) * (std::sqrt(2.0) - 1);
    if (hint && hint->tt > hint->tr) {
      double d = (hint->tt - hint->tr) * std::sqrt(s.e0 / hint->e0);
      if (hint2 && hint2->tt > hint2->tr)
        d = extrapolate(d, (hint2->tt - hint2->tr) * std::sqrt(s.e0 / hint2->e0));
      guess = s.tr + d;
    }
    const Vec2 S = s.start, nl = s.line_normal;
    const double e0 = s.e0;
    // Eq. 6 and 7: the normal at T meets the line e0 outside the curve.
    const auto H = [&](double t) {
      const Frame f = frame(t);
      const double c = f.n.dot(nl);
      // Normals turned by ~84 degrees from the line's no longer meet it
      // usefully; the tolerance guard keeps real segments far from here.
      if (c < 0.1) return ValueSlope{e0, 0};
      const double g = (f.p - S).dot(nl), dg = f.v * f.u.dot(nl);
      const double dc = -f.k * f.v * f.u.dot(nl);
      return ValueSlope{g / c - e0, (dg * c - g * dc) / (c * c)};
    };
    const Root r = solve_rising(H, s.tr, guess, t_max_, tol_t_);
    s.tt = r.t;
    if (r.found) {
      const Frame f = frame(r.t);
      const double lambda = -(f.p - S).dot(nl) / f.n.dot(nl);
      s.end = f.p + lambda * f.n;  // exactly on the line, on the normal at T
      s.end_offset = -lambda;
    }
    return r.found;
  }

  Segment first_segment(double e0) const {
    Segment s;
    s.t_start = ta_;
    s.offset = 0;
    s.start = c_.point(ta_);
    s.e0 = e0;
    s.tr = s.tt = -kInf;
    return s;
  }

  static Segment next_segment(const Segment& prev) {
    Segment s;
    s.t_start = prev.tt;
    s.offset = prev.end_offset;
    s.start = prev.end;
    s.e0 = prev.e0;
    s.tr = s.tt = -kInf;
    return s;
  }

  // Where the last segment's crossing R lies relative to B (mm along the
  // curve, > 0 past B), for the stopping tests and Process II's search over
  // e0. R is taken on the osculating parabola at B, B + d u + k d^2 / 2 n:
  // exact in sign, second order in size, and smooth in e0 as R moves across
  // B (the R = 50 mm extension arc, which generally bends differently from
  // the curve at B, would put a kink there and stall the search). +inf when
  // P lies past B (so does R).
  double end_gap(const Segment& s) const {
    if (s.tp >= tb_) return kInf;
    const double depth = -(fb_.p - s.start).dot(s.line_normal);  // B outside the line
    const double b = fb_.u.dot(s.line_normal);                   // > 0 past P
    const double a = 0.5 * fb_.k * fb_.n.dot(s.line_normal);
    const double disc = b * b + 4 * a * depth;
    if (b <= 0) return kInf;
    if (disc < 0) return -kInf;  // far short of B: the parabola misses the line
    return 2 * depth / (b + std::sqrt(disc));
  }

  // Process I with a free count at e0.
  struct Process1 {
    int segments = 0;   // n
    bool done = false;  // R_n within the convergence limit of B: no Process II
    double gap = kInf;  // end gap of R_n at e0 (+inf: segment n would start past B)
  };

  Process1 process1(double e0) {
    chain_.clear();
    Process1 out;
    Segment s = first_segment(e0);
    for (int i = 1;; ++i) {
      if (i > opt_.max_segments)
        throw std::invalid_argument("tolerance too fine: more than " +
                                    std::to_string(opt_.max_segments) + " segments");
      const Segment* hint = chain_.empty() ? nullptr : &chain_.back();
      const Segment* hint2 = chain_.size() < 2 ? nullptr : &chain_[chain_.size() - 2];
      out.segments = i;
      // Step 1: P past B.
      if (!solve_p(s, hint, hint2)) {
        chain_.push_back(s);
        return out;
      }
      // Step 2: R within the convergence limit of B (either side: the
      // paper's rule), or past it.
      out.gap = end_gap(s);
      if (std::abs(out.gap) <= opt_.convergence_mm) {
        chain_.push_back(s);
        out.done = true;
        return out;
      }
      if (out.gap > 0) {
        chain_.push_back(s);
        return out;
      }
      // Step 3: T past B means one more segment.
      solve_r(s, hint, hint2);
      const bool t_found = solve_t(s, hint, hint2);
      chain_.push_back(s);
      if (!t_found || s.tt >= tb_) {
        out.segments = i + 1;
        out.gap = kInf;
        return out;
      }
      s = next_segment(s);
    }
  }

  // How many segments of the current chain's e0 would fit the interval
  // exactly (fractional): the segments up to the last crossing R before B,
  // plus the stretch R..B at the local rate. A segment of error e spans
  // 4 sqrt(e / k) on a circle of curvature k (from one crossing to the
  // next), so the stretch holds integral sqrt(k) ds / (4 sqrt(e)) of them.
  // NaN when no crossing before B is known.
  double fitted_count() const {
    for (size_t i = chain_.size(); i-- > 0;) {
      const Segment& s = chain_[i];
      if (!(s.tr > s.tp && s.tr < tb_)) continue;
      // 8-point Gauss-Legendre over [tr, tb] in the curve parameter.
      static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                  0.9602898564975363};
      static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                  0.1012285362903763};
      const double mid = 0.5 * (s.tr + tb_), half = 0.5 * (tb_ - s.tr);
      double sum = 0;
      for (int j = 0; j < 4; ++j) {
        for (double sgn : {-1.0, 1.0}) {
          const Frame f = frame(mid + sgn * half * x[j]);
          sum += w[j] * std::sqrt(std::max(f.k, 0.0)) * f.v;
        }
      }
      return static_cast<double>(i + 1) + half * sum / (4 * std::sqrt(s.e0));
    }
    return std::nan("");
  }

  // Process I with a fixed count n at e0 (Steps 4 and 5 of Process II):
  // where segment n ends. Warm-started from the previous chain once e0 has
  // settled.
  double chain(int n, double e0) {
    next_.clear();
    Segment s = first_segment(e0);
    size_t j = 1;  // old segment at or before s's start (joint-started ones: index >= 1)
    Segment blend;
    for (int i = 0; i < n; ++i) {
      // Guesses from the previous chain, whose segments have the shape this
      // one needs but have slid along the curve: its segments around this
      // start, interpolated in the start parameter (the first segment starts
      // at A in both). Without it, this chain's own previous segments.
      const Segment* hint = nullptr;
      const Segment* hint2 = nullptr;
      if (i == 0 && !chain_.empty()) {
        hint = &chain_[0];
      } else if (i > 0 && interpolate_old(s.t_start, &j, &blend)) {
        hint = &blend;
      } else if (!next_.empty()) {
        hint = &next_.back();
        hint2 = next_.size() < 2 ? nullptr : &next_[next_.size() - 2];
      }
      const bool last = i == n - 1;
      if (!solve_p(s, hint, hint2) || (!last && s.tp >= tb_)) return finish_chain(s, kInf);
      if (last) return finish_chain(s, end_gap(s));
      if (!solve_r(s, hint, hint2) || s.tr >= tb_) return finish_chain(s, kInf);
      if (!solve_t(s, hint, hint2) || s.tt >= tb_) return finish_chain(s, kInf);
      next_.push_back(s);
      s = next_segment(s);
    }
    return -kInf;  // n == 0: nothing reaches anything
  }

  // The shape (P, R, T relative to the start) of a joint-started segment of
  // the previous chain starting at t, interpolated between its neighbours;
  // `j` walks forward with t. False when t lies outside what they cover.
  bool interpolate_old(double t, size_t* j, Segment* out) const {
    const auto complete = [](const Segment& g) { return g.tt > g.tr && g.tr > g.tp; };
    while (*j + 1 < chain_.size() && chain_[*j + 1].t_start <= t) ++*j;
    if (*j + 1 >= chain_.size() || chain_[*j].t_start > t) return false;
    const Segment& a = chain_[*j];
    const Segment& b = chain_[*j + 1];
    if (!complete(a) || !complete(b) || a.e0 != b.e0) return false;
    const double f = (t - a.t_start) / (b.t_start - a.t_start);
    const auto lerp = [f](double x, double y) { return x + f * (y - x); };
    *out = a;
    out->t_start = t;
    out->offset = lerp(a.offset, b.offset);
    out->tp = t + lerp(a.tp - a.t_start, b.tp - b.t_start);
    out->tr = out->tp + lerp(a.tr - a.tp, b.tr - b.tp);
    out->tt = out->tr + lerp(a.tt - a.tr, b.tt - b.tr);
    return true;
  }

  // A single segment must be the chord A B; its error extremum lies where
  // the tangent is parallel to it (bisection on the side the tangent points
  // to, monotone while the interval turns by less than 180 degrees). This is
  // the value Process II converges to for n = 1, computed directly.
  double chord_bulge(double* t_extremum) const {
    const Vec2 a = c_.point(ta_), b = c_.point(tb_);
    const Vec2 w = (b - a).normalized();
    const auto side = [&](double t) { return cross2(w, c_.d1(t)); };
    const double s0 = side(ta_);
    double lo = ta_, hi = tb_;
    for (int it = 0; it < 200 && hi - lo > tol_t_; ++it) {
      const double mid = 0.5 * (lo + hi);
      ((side(mid) > 0) == (s0 > 0) ? lo : hi) = mid;
    }
    *t_extremum = 0.5 * (lo + hi);
    return std::abs(cross2(w, c_.point(*t_extremum) - a));
  }

  // Final polyline of the current chain: A, the joints V_1..V_{n-1}, B.
  void export_chain(OliInterval& out) const {
    out.vertices.clear();
    out.t_extremum.clear();
    out.t_crossing.clear();
    out.vertices.push_back(c_.point(ta_));
    for (size_t i = 0; i < chain_.size(); ++i) {
      if (i + 1 < chain_.size()) out.vertices.push_back(chain_[i].end);
      out.t_extremum.push_back(chain_[i].tp);
      // R_n was not solved where the end gap sufficed: it is B to eps.
      out.t_crossing.push_back(chain_[i].tr > chain_[i].tp ? chain_[i].tr : tb_);
    }
    out.vertices.push_back(c_.point(tb_));
  }

  // Keeps the chain just computed by chain() as the current one.
  void accept_chain() { chain_.swap(next_); }

 private:
  double finish_chain(const Segment& s, double gap) {
    next_.push_back(s);
    return gap;
  }

  Frame curve_frame(double t) const {
    Frame f;
    const CurveJetValue j = c_.jet(t);
    const Vec2& d1 = j.d1;
    const Vec2& d2 = j.d2;
    f.p = j.p;
    f.v = d1.norm();
    f.u = d1 / f.v;
    const Vec2 left(-f.u.y(), f.u.x());
    f.n = sign_ * left;
    f.k = sign_ * cross2(d1, d2) / (f.v * f.v * f.v);
    return f;
  }

  // The tangent circular arc of radius R past B, bending the same way as the
  // interval (Eq. 8-10), parameterised to continue t at B's speed.
  Frame extension_frame(double t) const {
    const double phi = (t - tb_) * fb_.v / radius_;
    const double c = std::cos(phi), s = std::sin(phi);
    Frame f;
    f.p = fb_.p + radius_ * s * fb_.u + radius_ * (1 - c) * fb_.n;
    f.v = fb_.v;
    f.u = c * fb_.u + s * fb_.n;
    f.n = -s * fb_.u + c * fb_.n;
    f.k = 1 / radius_;
    return f;
  }

  const PlanarCurve& c_;
  double ta_, tb_;
  double sign_;
  const OliOptions& opt_;
  Frame fb_;
  double radius_ = 0, t_max_ = 0, tol_t_ = 0;
  std::vector<Segment> chain_, next_;
};

}  // namespace

double max_abs_curvature(const PlanarCurve& curve, int samples) {
  double k = 0;
  for (int j = 0; j <= samples; ++j) {
    const double t = curve.t_begin() + (curve.t_end() - curve.t_begin()) * j / samples;
    k = std::max(k, std::abs(curve.curvature(t)));
  }
  return k;
}

double tangent_turn(const PlanarCurve& curve, double t0, double t1, int samples) {
  double sum = 0;
  Vec2 prev = curve.d1(t0);
  for (int j = 1; j <= samples; ++j) {
    const Vec2 d = curve.d1(t0 + (t1 - t0) * j / samples);
    sum += std::atan2(cross2(prev, d), prev.dot(d));
    prev = d;
  }
  return sum;
}

namespace {

// Cuts [t0, t1] into pieces that each turn by at most `limit` radians, at
// equal turns (interpolated between samples of the cumulative turn).
void split_by_turn(const PlanarCurve& curve, double t0, double t1, double limit,
                   std::vector<double>& cuts) {
  const int m = 512;
  std::vector<double> ts(m + 1), turn(m + 1, 0.0);
  Vec2 prev = curve.d1(t0);
  ts[0] = t0;
  for (int j = 1; j <= m; ++j) {
    ts[j] = j == m ? t1 : t0 + (t1 - t0) * j / m;
    const Vec2 d = curve.d1(ts[j]);
    turn[j] = turn[j - 1] + std::abs(std::atan2(cross2(prev, d), prev.dot(d)));
    prev = d;
  }
  const int pieces = static_cast<int>(std::ceil(turn[m] / limit - 1e-9));
  for (int p = 1; p < pieces; ++p) {
    const double target = turn[m] * p / pieces;
    const int j =
        static_cast<int>(std::lower_bound(turn.begin(), turn.end(), target) - turn.begin());
    const double f = (target - turn[j - 1]) / (turn[j] - turn[j - 1]);
    cuts.push_back(ts[j - 1] + f * (ts[j] - ts[j - 1]));
  }
}

}  // namespace

OliInterval plan_optimal_linear_interval(const PlanarCurve& curve, double t0, double t1,
                                         double tolerance, const OliOptions& opt) {
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("tolerance must be positive and finite");
  if (!(t1 > t0)) throw std::invalid_argument("OLI: empty interval");
  OliInterval out;
  out.t_begin = t0;
  out.t_end = t1;
  out.sign = curvature_sign(curve, t0, t1);
  if (out.sign == 0) {  // straight: one exact segment
    out.segments = 1;
    out.vertices = {curve.point(t0), curve.point(t1)};
    out.t_extremum = {t0};
    out.t_crossing = {t1};
    return out;
  }
  IntervalSolver solver(curve, t0, t1, out.sign, opt);
  const IntervalSolver::Process1 p1 = solver.process1(tolerance);
  const int n = p1.segments;
  out.segments = n;
  if (p1.done) {
    out.error = tolerance;
    out.end_gap_mm = p1.gap;
    solver.export_chain(out);
    return out;
  }
  if (n == 1) {
    double tp = 0;
    out.error = solver.chord_bulge(&tp);
    out.vertices = {curve.point(t0), curve.point(t1)};
    out.t_extremum = {tp};
    out.t_crossing = {t1};
    return out;
  }

  // Process II: find e0 <= E where R_n lands on B (end gap 0, see end_gap()).
  // The paper lowers E0 by 5 % until R_n falls short of B (Step 4), then
  // bisects (Step 5). Same root here, in fewer chains: segment counts scale
  // with 1 / sqrt(e0), so the count a chain fits at e0 (fitted_count())
  // predicts the first e0; a step of 1e-5 of it gives the local slope of
  // the gap; secant steps follow, kept inside the bracket [e1, e2] known so
  // far, with the 5 % step (no lower end yet) or bisection as the fallback.
  // The first stopping rule is one-sided (R_n at or past B by at most eps),
  // so the last segment, cut back to B, bulges no more than e0. The second
  // rule ends the search when the bracket is down to rounding or the
  // evaluation budget is spent; it takes the upper end, whose chain reaches B.
  const double eps = opt.convergence_mm;
  double e2 = tolerance, g2 = p1.gap;           // R_n past B
  double e1 = 0;                                // R_n short of B (0: none seen yet)
  double ea = std::nan(""), ga = std::nan("");  // the previous finite evaluation
  const double c = solver.fitted_count();
  double e0 = tolerance * (c / n) * (c / n);
  if (!(e0 > 0 && e0 < tolerance)) e0 = 0.95 * tolerance;
  int evals = 0;
  for (;;) {
    const double g = solver.chain(n, e0);
    solver.accept_chain();
    ++evals;
    if (g >= 0 && g <= eps) {
      out.error = e0;
      out.end_gap_mm = g;
      break;
    }
    if (g > 0) {
      e2 = e0;
      g2 = g;
    } else {
      e1 = e0;
    }
    const bool collapsed = e2 - e1 <= 8 * std::numeric_limits<double>::epsilon() * e2;
    // 0.95^540 ~ 1e-12: an interval still overshooting there is straight
    // to within rounding.
    if (collapsed || evals >= opt.max_process2_evaluations || (e1 == 0 && evals > 540)) {
      // The upper end's chain reaches B: cut back to B, its last segment
      // bulges less than e2. The lower end's falls short and would bulge
      // more than e1, acceptable only when the two ends agree to rounding.
      if (!std::isfinite(g2) && !(collapsed && e1 > 0))
        throw std::invalid_argument(
            "OLI: Process II ran out of evaluations without a chain reaching the interval end "
            "at t = " +
            std::to_string(t1));
      out.second_stopping_rule = true;
      e0 = std::isfinite(g2) ? e2 : e1;
      out.error = e0;
      out.end_gap_mm = solver.chain(n, e0);
      solver.accept_chain();
      ++evals;
      break;
    }
    double next = std::nan("");
    if (std::isfinite(g)) {
      if (std::isfinite(ga) && g != ga) {
        next = e0 - g * (e0 - ea) / (g - ga);
      } else {
        next = e0 * (g < 0 ? 1 + 1e-5 : 1 - 1e-5);
      }
      ea = e0;
      ga = g;
    }
    if (!(next > e1 && next < e2)) next = e1 > 0 ? 0.5 * (e1 + e2) : 0.95 * e2;
    e0 = next;
  }
  out.process2_evaluations = evals;
  solver.export_chain(out);
  // Only a chain that failed early (never past B at any e0) is short.
  if (out.vertices.size() != static_cast<size_t>(n) + 1)
    throw std::invalid_argument("OLI: Process II found no e0 for the interval ending at t = " +
                                std::to_string(t1));
  return out;
}

double oli_chain_end_gap(const PlanarCurve& curve, double t0, double t1, int segments, double e0,
                         const OliOptions& opt) {
  if (segments <= 0) return -kInf;
  const int sign = curvature_sign(curve, t0, t1);
  if (sign == 0) return 0;
  IntervalSolver solver(curve, t0, t1, sign, opt);
  return solver.chain(segments, e0);
}

OliPlan plan_optimal_linear(const PlanarCurve& curve, double tolerance, const OliOptions& opt) {
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("tolerance must be positive and finite");
  const double k_max = max_abs_curvature(curve, opt.inflections.samples);
  if (tolerance * 8 * k_max > 1) {
    char msg[200];
    std::snprintf(msg, sizeof msg,
                  "tolerance %g mm is too coarse for this curve: its smallest radius of curvature "
                  "is %g mm and the tolerance may be at most 1/8 of that (%g mm)",
                  tolerance, 1 / k_max, 0.125 / k_max);
    throw std::invalid_argument(msg);
  }
  std::vector<double> inflections{curve.t_begin()};
  for (double t : find_inflections(curve, opt.inflections)) {
    // An inflection within rounding of a cut would leave an empty interval.
    if (t - inflections.back() > 1e-12 * (curve.t_end() - curve.t_begin()))
      inflections.push_back(t);
  }
  if (inflections.size() > 1 &&
      curve.t_end() - inflections.back() <= 1e-12 * (curve.t_end() - curve.t_begin()))
    inflections.pop_back();
  inflections.push_back(curve.t_end());
  const double max_turn = opt.max_interval_turn_deg * kPi / 180;
  if (!(max_turn > 0 && max_turn < kPi))
    throw std::invalid_argument("OLI: the interval turn limit must lie in (0, 180) degrees");
  std::vector<double> cuts{curve.t_begin()};
  for (size_t j = 0; j + 1 < inflections.size(); ++j) {
    split_by_turn(curve, inflections[j], inflections[j + 1], max_turn, cuts);
    cuts.push_back(inflections[j + 1]);
  }

  OliPlan plan;
  for (size_t j = 0; j + 1 < cuts.size(); ++j) {
    OliInterval iv = plan_optimal_linear_interval(curve, cuts[j], cuts[j + 1], tolerance, opt);
    plan.segments += iv.segments;
    if (plan.segments > opt.max_segments)
      throw std::invalid_argument("tolerance too fine: more than " +
                                  std::to_string(opt.max_segments) + " segments");
    plan.error = std::max(plan.error, iv.error);
    // Intervals share their end points: keep one copy.
    plan.vertices.insert(plan.vertices.end(), iv.vertices.begin() + (j == 0 ? 0 : 1),
                         iv.vertices.end());
    plan.intervals.push_back(std::move(iv));
  }
  return plan;
}

}  // namespace hwinterp::models

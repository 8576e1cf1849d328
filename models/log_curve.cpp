#include "models/log_curve.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "models/common.h"

namespace hwinterp::models {

namespace {

double rad(double deg) { return deg * kPi / 180.0; }

std::string num(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

// The message is built only on failure: validate() runs on every model call
// (the benchmarks time whole runs).
template <typename Message>
void require(bool ok, Message&& what) {
  if (!ok) throw std::invalid_argument(what());
}

void check_angle(double deg, const char* name) {
  require(std::isfinite(deg) && deg > 0 && deg < 90,
          [&] { return std::string(name) + " " + num(deg) + " deg is outside (0, 90)"; });
}

void fold_max(LogMaxError& m, const LogPoint& p) {
  if (std::abs(p.error) > m.abs) {
    m.abs = std::abs(p.error);
    m.value = p.error;
    m.index = p.index;
  }
}

}  // namespace

double log_a(const LogCurveParams& p) {
  return std::tan(rad(p.spiral_deg)) / std::tan(rad(p.cone_deg));
}
double log_b(const LogCurveParams& p) { return 2 * std::tan(rad(p.cone_deg)) / p.d1_mm; }

void validate(const LogCurveParams& p) {
  require(std::isfinite(p.d1_mm) && p.d1_mm > 0,
          [&] { return "D1 " + num(p.d1_mm) + " mm must be > 0"; });
  check_angle(p.spiral_deg, "spiral angle");
  check_angle(p.cone_deg, "cone angle");
  check_angle(p.rake_deg, "rake");
  require(std::isfinite(p.dl_mm) && p.dl_mm > 0,
          [&] { return "dl " + num(p.dl_mm) + " mm must be > 0"; });
  require(std::isfinite(p.x_end_mm) && p.x_end_mm > 0,
          [&] { return "x_end " + num(p.x_end_mm) + " mm must be > 0"; });
  // The third-order even step assumes short steps; one longer than the whole
  // run is a typo, not a request.
  require(p.dl_mm <= p.x_end_mm, [&] {
    return "dl " + num(p.dl_mm) + " mm is longer than x_end " + num(p.x_end_mm) + " mm";
  });
  // Every step advances X by at least dl cos(theta_max); the slope is largest
  // at X = 0, so this over-estimates the point count without running.
  const double ab = log_a(p) * log_b(p);
  const double estimate = p.x_end_mm * std::sqrt(1 + ab * ab) / p.dl_mm + 2;
  require(estimate <= static_cast<double>(kLogMaxPoints), [&] {
    return "the curve's slope at X = 0, a b = 2 tan(spiral " + num(p.spiral_deg) + " deg) / d1 " +
           num(p.d1_mm) + " mm = " + num(ab) + ", makes dl " + num(p.dl_mm) + " mm to x_end " +
           num(p.x_end_mm) + " mm about " + num(std::ceil(estimate)) + " points (limit " +
           std::to_string(kLogMaxPoints) + ")";
  });
}

ExplicitCurve log_planar_curve(double a, double b, double x_end) {
  return ExplicitCurve([a, b](double x) { return a * std::log1p(b * x); },
                       [a, b](double x) { return a * b / (1 + b * x); },
                       [a, b](double x) { return -a * b * b / ((1 + b * x) * (1 + b * x)); }, 0.0,
                       x_end);
}

LogCycle log_cycle_paper(double a, double b, double dl, double x0) {
  LogCycle c;
  const double q = 1 + b * x0;
  const double ab = a * b;
  const double root = std::sqrt(q * q + ab * ab);
  // Eqs. 8 and 9: a tangent step of length dl.
  c.dx10 = q * dl / root;
  c.da10 = ab * dl / root;
  c.sin2_theta = ab * ab / (q * q + ab * ab);
  const double s2 = c.sin2_theta, d = c.da10;
  // Eq. 14 and Eq. 15 as printed: the readings that reproduce Table 1.
  const double den14 = 3 * a * a * a - 2 * a * d * s2 * (3 * a - 4 * d);
  const double num14 = 3 * a * a * a - 2 * d * d * s2 * (3 * a - 8 * d);
  const double den15 = 3 * a * a - 2 * d * s2 * (3 * a - 4 * d);
  const double num15 = 3 * a * a - 2 * d * (3 * a - 4 * d);
  // With 0 <= sin^2 <= 1 these stay positive for every dA10 (their negative
  // parts peak at a^3/8, 9a^3/8 and 9a^2/8); checked anyway, since a
  // division by a non-positive value would silently turn the path around.
  if (!(den14 > 0 && den15 > 0 && num14 > 0))
    throw std::invalid_argument("dl " + num(dl) + " mm breaks the third-order even step (Eq. 14)");
  c.dx21 = num14 / den14 * c.dx10;
  c.da21 = num15 / den15 * c.da10;
  return c;
}

double log_exact_even_x(double a, double b, double dl, double x1, double a1) {
  // g < 0 inside the circle. At X1 the curve is off P1 by the odd-step error
  // only (far below dl); at X1 + dl it is at least dl away. One sign change in
  // between: the curve is monotone in X and concave, and P0 lies behind X1.
  auto g = [&](double x) {
    const double dx = x - x1, da = a * std::log1p(b * x) - a1;
    return dx * dx + da * da - dl * dl;
  };
  double lo = x1, hi = x1 + dl;
  if (!(g(lo) < 0)) throw std::invalid_argument("exact even step: P1 is dl away from the curve");
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // interval down to adjacent doubles
    (g(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

LogRun run_log_interpolation(const LogCurveParams& p, EvenStep even) {
  validate(p);
  LogRun run;
  run.params = p;
  run.even_step = even;
  run.a = log_a(p);
  run.b = log_b(p);
  const double a = run.a, b = run.b;
  const double tc = std::tan(rad(p.cone_deg));
  const double tcs = tc * std::sin(rad(p.rake_deg));

  run.points.push_back(LogPoint{});
  LogPoint cur;
  auto advance = [&](double dx, double da) {
    cur.index += 1;
    cur.x += dx;
    cur.a += da;
    // Eqs. 10/11 and 16/17: Y and Z follow X's increments.
    cur.y += dx * tc;
    cur.z += dx * tcs;
    cur.pa = a * std::log1p(b * cur.x);
    cur.error = cur.pa - cur.a;
    run.points.push_back(cur);
    fold_max(run.max_all, cur);
    fold_max(cur.odd() ? run.max_odd : run.max_even, cur);
  };

  do {
    const LogCycle c = log_cycle_paper(a, b, p.dl_mm, cur.x);
    advance(c.dx10, c.da10);
    if (even == EvenStep::kPaper) {
      advance(c.dx21, c.da21);
    } else {
      const double x2 = log_exact_even_x(a, b, p.dl_mm, cur.x, cur.a);
      advance(x2 - cur.x, a * std::log1p(b * x2) - cur.a);
    }
  } while (cur.x < p.x_end_mm);
  return run;
}

}  // namespace hwinterp::models

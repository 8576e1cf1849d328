#include "models/inscribed_chord.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "models/common.h"

namespace hwinterp::models {

namespace {

constexpr size_t kMaxChords = 10'000'000;

void check_r(double r) {
  if (!(std::isfinite(r) && r > 0)) {
    std::ostringstream os;
    os << "inscribed chord: segment length r " << r << " must be > 0";
    throw std::invalid_argument(os.str());
  }
}

// Distance from q to the segment a-b.
double segment_distance(const Vec2& q, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double s = l2 > 0 ? std::clamp((q - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (q - (a + s * ab)).norm();
}

std::optional<double> find_crossing(const PlanarCurve& curve, const Vec2& center, double r,
                                    double t_from, double t_max) {
  auto f = [&](double t) { return (curve.point(t) - center).squaredNorm() - r * r; };
  double t = t_from, ft = f(t);
  for (size_t i = 0; i < 100'000'000 && t < t_max; ++i) {
    const double speed = curve.d1(t).norm();
    const double h = speed > 0 ? r / (8 * speed) : r / 8;
    const double tn = std::min(t + h, t_max);
    const double fn = f(tn);
    if (ft <= 0 && fn > 0) {
      double lo = t, hi = tn;  // f(lo) <= 0 < f(hi)
      for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (f(mid) <= 0 ? lo : hi) = mid;
      }
      // The side whose radius is closer to r.
      return std::abs(f(lo)) <= std::abs(f(hi)) ? lo : hi;
    }
    t = tn;
    ft = fn;
  }
  return std::nullopt;
}

double sampled_chord_error(const PlanarCurve& curve, double t0, double t1, const Vec2& a,
                           const Vec2& b) {
  double worst = 0;
  constexpr int kSamples = 32;
  for (int i = 1; i < kSamples; ++i) {
    const double t = t0 + (t1 - t0) * i / kSamples;
    worst = std::max(worst, segment_distance(curve.point(t), a, b));
  }
  return worst;
}

}  // namespace

double truncate_to(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  // A value printed as 2.480 may be stored as 2.47999...: nudge by a few ulps
  // of the scaled value before cutting, so exact decimals stay themselves.
  const double s = v * scale;
  const double nudge = 4 * std::numeric_limits<double>::epsilon() * std::abs(s);
  return std::trunc(s + (s >= 0 ? nudge : -nudge)) / scale;
}

double next_circle_intersection(const PlanarCurve& curve, const Vec2& center, double r,
                                double t_from, double t_max) {
  check_r(r);
  const auto t = find_crossing(curve, center, r, t_from, t_max);
  if (!t) {
    std::ostringstream os;
    os << "inscribed chord: no intersection of the radius-" << r << " circle with the curve in t ["
       << t_from << ", " << t_max << "]";
    throw std::runtime_error(os.str());
  }
  return *t;
}

ChordResult inscribed_chord(const PlanarCurve& curve, double r, ChordEnd end_mode) {
  check_r(r);
  ChordResult out;
  const double t0 = curve.t_begin(), t1 = curve.t_end();
  out.start = curve.point(t0);
  out.end = curve.point(t1);
  const double end_speed = curve.d1(t1).norm();
  // A chord from a point before the end reaches at most about r of arc length
  // past it; 4 r leaves room for curvature.
  const double t_max =
      end_mode == ChordEnd::kOvershoot ? t1 + (end_speed > 0 ? 4 * r / end_speed : 4 * r) : t1;
  const double t_tol = 1e-12 * std::max(1.0, std::abs(t1));
  double t = t0;
  Vec2 p = out.start;
  while (true) {
    if (out.steps.size() >= kMaxChords)
      throw std::invalid_argument("inscribed chord: more than 1e7 chords; r is too small");
    const auto found = find_crossing(curve, p, r, t, t_max);
    ChordStep s;
    s.center = p;
    bool last = false;
    if (!found) {
      if (end_mode != ChordEnd::kClamp)
        throw std::runtime_error("inscribed chord: the circle does not cut the continued curve");
      s.t = t1;  // the end lies inside the circle: a short last chord
      s.point = out.end;
      last = true;
      out.exact_end = true;
    } else {
      s.t = *found;
      s.point = curve.point(s.t);
      if (s.t >= t1 - t_tol || (s.point - out.end).norm() <= 1e-9 * r) {
        last = true;
        if (std::abs(s.t - t1) <= t_tol || (s.point - out.end).norm() <= 1e-9 * r ||
            end_mode == ChordEnd::kClamp) {
          s.t = t1;
          s.point = out.end;
          out.exact_end = true;
        } else {
          out.overshoot = (s.point - out.end).norm();
        }
      }
    }
    s.chord = (s.point - s.center).norm();
    out.max_chord_error =
        std::max(out.max_chord_error, sampled_chord_error(curve, t, s.t, s.center, s.point));
    out.steps.push_back(s);
    if (last) break;
    t = s.t;
    p = s.point;
  }
  return out;
}

ChordResult inscribed_chord_line(const Vec2& a, const Vec2& b, double r, ChordEnd end_mode) {
  check_r(r);
  const double len = (b - a).norm();
  if (!(len > 0)) throw std::invalid_argument("inscribed chord: line of zero length");
  if (len / r > static_cast<double>(kMaxChords))
    throw std::invalid_argument("inscribed chord: more than 1e7 chords; r is too small");
  ChordResult out;
  out.start = a;
  out.end = b;
  const Vec2 u = (b - a) / len;
  const double exact = len / r;
  // Chords whose count lands within rounding of an integer end exactly there.
  const auto n = static_cast<size_t>(std::ceil(exact * (1 - 1e-12)));
  Vec2 prev = a;
  for (size_t k = 1; k <= n; ++k) {
    ChordStep s;
    s.center = prev;
    const double along = static_cast<double>(k) * r;
    s.t = along / len;
    s.point = a + along * u;
    if (k == n) {
      if (std::abs(along - len) <= 1e-12 * len || end_mode == ChordEnd::kClamp) {
        s.t = 1;
        s.point = b;
        out.exact_end = true;
      } else {
        out.overshoot = (s.point - b).norm();
      }
    }
    s.chord = (s.point - s.center).norm();
    out.steps.push_back(s);
    prev = s.point;
  }
  return out;
}

ChordResult inscribed_chord_arc(const Vec2& center, const Vec2& start, const Vec2& end, bool ccw,
                                double r, ChordEnd end_mode) {
  check_r(r);
  const double radius = (start - center).norm();
  if (!(radius > 0)) throw std::invalid_argument("inscribed chord: arc of radius 0");
  if (r > 2 * radius) {
    std::ostringstream os;
    os << "inscribed chord: segment length r " << r << " exceeds the arc's diameter " << 2 * radius;
    throw std::invalid_argument(os.str());
  }
  const double a0 = std::atan2(start.y() - center.y(), start.x() - center.x());
  const double a1 = std::atan2(end.y() - center.y(), end.x() - center.x());
  double sweep = ccw ? a1 - a0 : a0 - a1;
  sweep = std::fmod(sweep, kTwoPi);
  if (sweep <= 1e-15) sweep += kTwoPi;  // start == end: a full circle
  const double sign = ccw ? 1.0 : -1.0;
  const double step = 2 * std::asin(r / (2 * radius));
  if (sweep / step > static_cast<double>(kMaxChords))
    throw std::invalid_argument("inscribed chord: more than 1e7 chords; r is too small");
  const auto n = static_cast<size_t>(std::ceil(sweep / step * (1 - 1e-12)));
  auto at = [&](double ang) { return Vec2(center + radius * Vec2(std::cos(ang), std::sin(ang))); };
  ChordResult out;
  out.start = start;
  out.end = at(a0 + sign * sweep);  // end projected onto the circle
  Vec2 prev = start;
  for (size_t k = 1; k <= n; ++k) {
    ChordStep s;
    s.center = prev;
    s.t = static_cast<double>(k) * step;
    s.point = at(a0 + sign * s.t);
    if (k == n) {
      if (std::abs(s.t - sweep) <= 1e-12 * sweep || end_mode == ChordEnd::kClamp) {
        s.t = sweep;
        s.point = out.end;
        out.exact_end = true;
      } else {
        out.overshoot = (s.point - out.end).norm();
      }
    }
    s.chord = (s.point - s.center).norm();
    // Chord height (sagitta) of the chord's arc.
    out.max_chord_error =
        std::max(out.max_chord_error, radius * (1 - std::cos((s.t - (k - 1) * step) / 2)));
    out.steps.push_back(s);
    prev = s.point;
  }
  return out;
}

}  // namespace hwinterp::models

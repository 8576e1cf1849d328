#include "models/cam_law.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/common.h"

namespace hwinterp::models {
namespace {

// Modified sine, in the reading that reproduces paper 000's tables
// (docs/papers.md; the paper's Appendix B formula was lost in extraction). The three pieces meet
// with continuous S, S', S''.
CamLawValue modified_sine(double T) {
  const double d = 4 + kPi;
  if (T <= 0.125) {
    const double w = 4 * kPi * T;
    const double c = kPi / d;
    return {c * (T - std::sin(w) / (4 * kPi)), c * (1 - std::cos(w)), c * 4 * kPi * std::sin(w)};
  }
  if (T <= 0.875) {
    const double w = kPi / 3 + 4 * kPi * T / 3;
    return {(2 + kPi * T - 2.25 * std::sin(w)) / d, (kPi - 3 * kPi * std::cos(w)) / d,
            4 * kPi * kPi * std::sin(w) / d};
  }
  const double w = 4 * kPi * T;
  return {(4 + kPi * T - 0.25 * std::sin(w)) / d, (kPi - kPi * std::cos(w)) / d,
          4 * kPi * kPi * std::sin(w) / d};
}

CamLawValue cycloidal(double T) {
  const double w = 2 * kPi * T;
  return {T - std::sin(w) / (2 * kPi), 1 - std::cos(w), 2 * kPi * std::sin(w)};
}

// Modified trapezoid on [0, 1/2]: quarter-sine rise of the acceleration on
// [0, 1/8], constant peak A on [1/8, 3/8], cosine fall through zero at 1/2.
// A = 8 pi / (pi + 2) makes S(1/2) = 1/2; the second half follows from the
// point symmetry S(T) = 1 - S(1 - T).
CamLawValue modified_trapezoid_first_half(double T) {
  const double a = 8 * kPi / (kPi + 2);
  const double w = 4 * kPi;
  const double v1 = a / w;                         // S' at 1/8
  const double s1 = a / w * (0.125 - 1 / w);       // S at 1/8
  const double v2 = v1 + a * 0.25;                 // S' at 3/8
  const double s2 = s1 + v1 * 0.25 + a * 0.03125;  // S at 3/8
  if (T <= 0.125) {
    return {a / w * (T - std::sin(w * T) / w), a / w * (1 - std::cos(w * T)), a * std::sin(w * T)};
  }
  if (T <= 0.375) {
    const double u = T - 0.125;
    return {s1 + v1 * u + 0.5 * a * u * u, v1 + a * u, a};
  }
  const double u = T - 0.375;
  return {s2 + v2 * u + a / (w * w) * (1 - std::cos(w * u)), v2 + a / w * std::sin(w * u),
          a * std::cos(w * u)};
}

CamLawValue modified_trapezoid(double T) {
  if (T <= 0.5) return modified_trapezoid_first_half(T);
  const CamLawValue m = modified_trapezoid_first_half(1 - T);
  return {1 - m.s, m.ds, -m.dds};
}

CamLawValue polynomial_345(double T) {
  const double t2 = T * T, t3 = t2 * T;
  return {t3 * (10 - 15 * T + 6 * t2), 30 * t2 * (1 - 2 * T + t2), 60 * T * (1 - 3 * T + 2 * t2)};
}

CamLawValue harmonic(double T) {
  const double w = kPi * T;
  return {0.5 * (1 - std::cos(w)), 0.5 * kPi * std::sin(w), 0.5 * kPi * kPi * std::cos(w)};
}

}  // namespace

CamLawValue evaluate_cam_law(CamLaw law, double T) {
  T = std::clamp(T, 0.0, 1.0);
  switch (law) {
    case CamLaw::kModifiedSine:
      return modified_sine(T);
    case CamLaw::kCycloidal:
      return cycloidal(T);
    case CamLaw::kModifiedTrapezoid:
      return modified_trapezoid(T);
    case CamLaw::kPolynomial345:
      return polynomial_345(T);
    case CamLaw::kHarmonic:
      return harmonic(T);
  }
  throw std::invalid_argument("evaluate_cam_law: unknown law");
}

const std::vector<std::string>& cam_law_names() {
  static const std::vector<std::string> names{"ms", "cycloidal", "modified-trapezoid",
                                              "polynomial-345", "harmonic"};
  return names;
}

std::string cam_law_name(CamLaw law) { return cam_law_names().at(static_cast<size_t>(law)); }

CamLaw parse_cam_law(const std::string& name) {
  const auto& names = cam_law_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) {
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown cam law '" + name + "' (known: " + known + ")");
  }
  return static_cast<CamLaw>(it - names.begin());
}

}  // namespace hwinterp::models

// The standard dimensionless cam laws: displacement S(T) for T in [0, 1],
// S(0) = 0, S(1) = 1, with analytic first and second derivatives in T. They
// feed the cam profiles (cam_profile.h) that the planners interpolate.
#pragma once

#include <string>
#include <vector>

namespace hwinterp::models {

enum class CamLaw {
  kModifiedSine,       // "ms": the law of the OLI paper's Cam 1 and Cam 2
  kCycloidal,          // "cycloidal"
  kModifiedTrapezoid,  // "modified-trapezoid"
  kPolynomial345,      // "polynomial-345"
  kHarmonic,           // "harmonic" (simple harmonic)
};

// S, dS/dT and d2S/dT2 at one T.
struct CamLawValue {
  double s = 0;
  double ds = 0;
  double dds = 0;
};

// T outside [0, 1] is clamped: a cam law has no meaning past its rise.
CamLawValue evaluate_cam_law(CamLaw law, double T);

// Command-line names ("ms", "cycloidal", ...), in the order of the enum.
const std::vector<std::string>& cam_law_names();
std::string cam_law_name(CamLaw law);
// Throws std::invalid_argument naming `name` when it is not a known law.
CamLaw parse_cam_law(const std::string& name);

}  // namespace hwinterp::models

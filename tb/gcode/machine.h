// The machine description (`--machine FILE`): what turns millimetres and
// degrees into steps and clocks.
//
// Format: one JSON object; every key is optional and takes its default when
// missing (tests/data/gcode/machine_default.json spells out the defaults):
//
//   {
//     "comment": "any text",                      // ignored
//     "axes": ["X", "Y", "Z", "A"],               // the axes the machine has: a
//                                                 //   non-empty set of X Y Z A B C
//     "steps_per_unit": {"X": 1000, "Y": 1000, "Z": 1000, "A": 100},
//                                                 // integers in [1, 10^7]: steps/mm on
//                                                 //   X Y Z, steps/deg on A B C; only
//                                                 //   for axes the machine has
//     "clock_hz": 50000000,                       // integer in [1, 10^10]
//     "rapid_mm_per_min": 5000,                   // number in (0, 10^7]
//     "timing_clocks": {"step_len": 2, "step_space": 2, "dir_setup": 3, "dir_hold": 3},
//                                                 // the hostmot2 step/dir timing, in
//                                                 //   clocks, integers in [1, 65535]
//     "travel": {"X": [-10, 300], "Z": [-80, 0]}, // [min, max] of an axis's programmed
//                                                 //   coordinate, mm (deg on A B C),
//                                                 //   min < max; unlisted: unlimited
//     "max_velocity": {"X": 100},                 // per axis, mm/s (deg/s), > 0
//     "max_accel": {"X": 2000},                   //   mm/s^2 (deg/s^2), > 0
//     "max_jerk": {"X": 100000}                   //   mm/s^3 (deg/s^3), > 0; unlisted:
//                                                 //   unlimited
//   }
//
// The travel is checked before anything runs (tb/gcode/limits.h): a program
// whose path leaves it exits 2 naming the line and the axis. The kinematic
// limits are what the run's kinematics report sets each axis's highest
// speed, acceleration and jerk beside.
//
// Defaults (the project's, cmake/cores.cmake): axes X Y Z A, 1000 steps/mm
// on X Y Z, 100 steps/deg on A (and on B and C when listed), 50 MHz,
// rapid 5000 mm/min, timing 2/2/3/3 clocks.
// An unknown or repeated key, a value of the wrong type, a value out of
// range, a fraction where an integer is needed, or JSON that does not parse
// throws cli::UsageError naming the file, the key and the value.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <istream>
#include <limits>
#include <string>

#include "tb/gcode/move.h"

namespace hwinterp::gcode {

struct StepTiming {  // in clocks
  int64_t step_len = 2;
  int64_t step_space = 2;
  int64_t dir_setup = 3;
  int64_t dir_hold = 3;
};

// A closed range of an axis's coordinate; unlimited by default.
struct Travel {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool limited() const { return std::isfinite(min) || std::isfinite(max); }
};

// Per axis, in units of the axis (mm or deg) per s, s^2, s^3; infinity: no
// limit.
struct AxisLimits {
  double velocity = std::numeric_limits<double>::infinity();
  double accel = std::numeric_limits<double>::infinity();
  double jerk = std::numeric_limits<double>::infinity();
};

// The feed profile a run uses (rtl/feed_profile.sv in front of motion_top):
// off (every move at its feed word, as before), an S-curve (acceleration and
// jerk limited), or a trapezoid (acceleration limited: the moving sum is one
// tick long).
enum class ProfileKind { kOff, kScurve, kTrapezoid };
// "off", "scurve", "trapezoid"; parse_profile throws cli::UsageError naming
// `what` and the value for anything else.
const char* profile_name(ProfileKind k);
ProfileKind parse_profile(const std::string& text, const std::string& what);

struct Machine {
  std::array<bool, kAxes> has_axis{true, true, true, true, false, false};  // X Y Z A B C
  std::array<int64_t, kAxes> steps_per_unit{1000, 1000, 1000, 100, 100, 100};
  int64_t clock_hz = 50'000'000;
  double rapid_mm_per_min = 5000;
  StepTiming timing;
  std::array<Travel, kAxes> travel{};
  std::array<AxisLimits, kAxes> limits{};
  ProfileKind profile = ProfileKind::kOff;

  std::string axes() const;  // "XYZA"
};

// Reads a machine description; `name` names the file in error messages.
Machine read_machine(std::istream& in, const std::string& name);
// Opens and reads `path` (a missing or unreadable file is a UsageError).
Machine load_machine(const std::string& path);

}  // namespace hwinterp::gcode

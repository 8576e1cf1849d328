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
//     "timing_clocks": {"step_len": 2, "step_space": 2, "dir_setup": 3, "dir_hold": 3}
//                                                 // the hostmot2 step/dir timing, in
//                                                 //   clocks, integers in [1, 65535]
//   }
//
// Defaults (the project's, cmake/cores.cmake): axes X Y Z A, 1000 steps/mm
// on X Y Z, 100 steps/deg on A (and on B and C when listed), 50 MHz,
// rapid 5000 mm/min, timing 2/2/3/3 clocks.
// An unknown or repeated key, a value of the wrong type, a value out of
// range, a fraction where an integer is needed, or JSON that does not parse
// throws cli::UsageError naming the file, the key and the value.
#pragma once

#include <array>
#include <cstdint>
#include <istream>
#include <string>

#include "tb/gcode/move.h"

namespace hwinterp::gcode {

struct StepTiming {  // in clocks
  int64_t step_len = 2;
  int64_t step_space = 2;
  int64_t dir_setup = 3;
  int64_t dir_hold = 3;
};

struct Machine {
  std::array<bool, kAxes> has_axis{true, true, true, true, false, false};  // X Y Z A B C
  std::array<int64_t, kAxes> steps_per_unit{1000, 1000, 1000, 100, 100, 100};
  int64_t clock_hz = 50'000'000;
  double rapid_mm_per_min = 5000;
  StepTiming timing;

  std::string axes() const;  // "XYZA"
};

// Reads a machine description; `name` names the file in error messages.
Machine read_machine(std::istream& in, const std::string& name);
// Opens and reads `path` (a missing or unreadable file is a UsageError).
Machine load_machine(const std::string& path);

}  // namespace hwinterp::gcode

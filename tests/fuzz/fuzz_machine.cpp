// libFuzzer target: the machine description reader (tb/gcode/machine.h).
// Bad input must end in cli::UsageError; anything else (a crash, a sanitizer
// report, another exception such as one of nlohmann-json's, a machine
// outside the documented ranges) is a finding.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "tb/base/args.h"
#include "tb/gcode/machine.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  hwinterp::gcode::Machine m;
  try {
    m = hwinterp::gcode::read_machine(in, "fuzz.json");
  } catch (const hwinterp::cli::UsageError&) {
    return 0;
  }
  if (m.axes().empty()) std::abort();
  for (const int64_t s : m.steps_per_unit)
    if (s < 1 || s > 10'000'000) std::abort();
  if (m.clock_hz < 1 || !(m.rapid_mm_per_min > 0) || !std::isfinite(m.rapid_mm_per_min))
    std::abort();
  for (const int64_t t :
       {m.timing.step_len, m.timing.step_space, m.timing.dir_setup, m.timing.dir_hold})
    if (t < 1 || t > 65535) std::abort();
  return 0;
}

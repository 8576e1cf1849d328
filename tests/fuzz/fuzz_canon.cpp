// libFuzzer target: the canonical-command reader (tb/gcode/canon_reader.h),
// every move of the input. Bad input must end in cli::UsageError; anything
// else (a crash, a sanitizer report, another exception, a non-finite
// number, an arc without a rotation) is a finding.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "tb/base/args.h"
#include "tb/gcode/canon_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  hwinterp::gcode::CanonReader reader(in, "fuzz.canon");
  try {
    hwinterp::gcode::Move m;
    while (reader.next(m)) {
      for (const double v : m.end)
        if (!std::isfinite(v)) std::abort();
      if (!std::isfinite(m.feed) || m.feed < 0) std::abort();
      const bool arc = m.kind == hwinterp::gcode::MoveKind::kArc;
      if (arc != (m.rotation != 0)) std::abort();
      if (!std::isfinite(m.center[0]) || !std::isfinite(m.center[1])) std::abort();
    }
  } catch (const hwinterp::cli::UsageError&) {
    return 0;
  }
  return 0;
}

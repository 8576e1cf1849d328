// libFuzzer target: the RS274/NGC reader (tb/gcode/ngc_reader.h), every move
// of the input. Bad input must end in cli::UsageError; anything else (a
// crash, a sanitizer report, another exception, a move that breaks the
// reader's contract: a non-finite number, an arc without a rotation, a
// non-arc with one) is a finding.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "tb/base/args.h"
#include "tb/gcode/ngc_reader.h"

namespace {

void check(const hwinterp::gcode::Move& m) {
  using hwinterp::gcode::MoveKind;
  for (const double v : m.end)
    if (!std::isfinite(v)) std::abort();
  if (!std::isfinite(m.feed) || m.feed < 0) std::abort();
  if (m.kind == MoveKind::kArc) {
    if (m.rotation == 0 || !std::isfinite(m.center[0]) || !std::isfinite(m.center[1])) std::abort();
    if (m.feed <= 0) std::abort();  // LinuxCNC refuses arcs at feed 0
  } else if (m.rotation != 0) {
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  hwinterp::gcode::NgcReader reader(in, "fuzz.ngc");
  try {
    hwinterp::gcode::Move m;
    uint64_t n = 0;
    while (reader.next(m)) {
      check(m);
      if (m.line == 0 || m.line < n) std::abort();  // lines in program order
      n = m.line;
    }
  } catch (const hwinterp::cli::UsageError&) {
    return 0;  // refused, with a message: what bad input must get
  }
  return 0;
}

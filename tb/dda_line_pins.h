// The dda_line pins as plain integers: what the testbench drives at a clock
// edge (DdaLineFrame) and reads after it (DdaLinePins). The runners convert
// them to and from the HLS core's and the Verilated models' own types.
#pragma once

#include <array>
#include <cstdint>

#include "stepdir_monitor.h"

namespace hwinterp::tb {

inline constexpr int kMaxAxes = 8;

struct DdaLineFrame {
  bool rst_n = false;
  bool cmd_valid = false;
  std::array<int64_t, kMaxAxes> cmd_delta{};
  uint64_t feed = 0;
  bool half_preload = false;
  StepdirTiming timing;
};

struct DdaLinePins {
  bool cmd_ready = false;
  uint32_t step = 0, dir = 0;            // bit i: axis i
  std::array<uint64_t, kMaxAxes> pos{};  // POS_W bits, two's complement
  bool busy = false, done = false;

  bool operator==(const DdaLinePins& o) const {
    return cmd_ready == o.cmd_ready && step == o.step && dir == o.dir && pos == o.pos &&
           busy == o.busy && done == o.done;
  }
  bool operator!=(const DdaLinePins& o) const { return !(*this == o); }
};

}  // namespace hwinterp::tb

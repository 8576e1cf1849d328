// The shared outputs of every core (cmd_ready_o, step_o, dir_o, pos_o,
// busy_o, done_o) as plain integers: what the runners read from both DUTs
// after a clock edge and the bench, the monitors and the scoreboard see.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "tb/base/variant_spec.h"

namespace hwinterp::tb {

struct OutPins {
  bool cmd_ready = false;
  uint32_t step = 0, dir = 0;            // bit i: axis i
  std::array<uint64_t, kMaxAxes> pos{};  // POS_W bits, two's complement
  bool busy = false, done = false;

  // Every clock of every run compares two of these: the positions are
  // folded with XOR/OR (no early exit, no memcmp call; the compiler vectorises it).
  [[gnu::always_inline]] bool operator==(const OutPins& o) const {
    uint64_t pos_diff = 0;
    for (size_t i = 0; i < kMaxAxes; ++i) pos_diff |= pos[i] ^ o.pos[i];
    return pos_diff == 0 && cmd_ready == o.cmd_ready && step == o.step && dir == o.dir &&
           busy == o.busy && done == o.done;
  }
  bool operator!=(const OutPins& o) const { return !(*this == o); }
};

}  // namespace hwinterp::tb

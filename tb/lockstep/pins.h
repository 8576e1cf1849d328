// The shared port contract as plain integers: what the testbench drives at a
// clock edge (Frame<A>, A a core adapter) and reads after it (OutPins). The
// runners convert them to and from the HLS core's and the Verilated models'
// own types; only the command payload and the per-command setup (A::Command,
// A::Setup) are the core's.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "tb/lockstep/core_limits.h"
#include "tb/monitor/stepdir_monitor.h"

namespace hwinterp::tb {

template <class A>
struct Frame {
  bool rst_n = false;
  bool cmd_valid = false;
  typename A::Command cmd{};  // cmd_*_i: the payload (zero while cmd_valid_i is low)
  typename A::Setup setup{};  // the core's own run-time inputs (e.g. half_preload_i)
  uint64_t feed = 0;
  StepdirTiming timing;
  bool abort = false;
};

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

// One input port of a core as the trace and the frame dump see it: `count`
// elements of `width` bits, element i in bits [i*width +: width] (the RTL's
// flat per-axis vectors). Element values are at most 64 bits.
struct PortSpec {
  std::string name;
  int count = 1;
  int width = 1;
};

}  // namespace hwinterp::tb

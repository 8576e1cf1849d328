// What the testbench drives at a clock edge, as plain integers: the shared
// port contract around the core's own payload. The runners convert it to the
// HLS core's and the Verilated models' own types; only the command payload
// and the per-command setup (A::Command, A::Setup) are the core's. (What they
// read back after the edge: tb/base/out_pins.h.)
#pragma once

#include <cstdint>

#include "tb/base/stepdir_timing.h"

namespace hwinterp::tb {

template <class A>
class Frame {
 public:
  bool rst_n = false;
  bool cmd_valid = false;
  uint64_t feed = 0;
  StepdirTiming timing;
  bool abort = false;

  // cmd_*_i: the payload (zero while cmd_valid_i is low), and the core's own
  // run-time inputs (e.g. half_preload_i).
  const typename A::Command& cmd() const { return cmd_; }
  const typename A::Setup& setup() const { return setup_; }
  void set_cmd(const typename A::Command& c) {
    cmd_ = c;
    ++payload_serial_;
  }
  void set_setup(const typename A::Setup& s) {
    setup_ = s;
    ++payload_serial_;
  }
  // Changes whenever cmd or setup is set: the runners convert the payload
  // to the DUTs' pins only then, not on every clock.
  uint64_t payload_serial() const { return payload_serial_; }

 private:
  typename A::Command cmd_{};
  typename A::Setup setup_{};
  uint64_t payload_serial_ = 0;
};

}  // namespace hwinterp::tb

// Cycle trace of a co-simulation, for any core: the inputs (scope tb) and
// both DUTs' outputs (scopes tb.hls, tb.rtl) in one VCD, either the whole run
// or only the last N cycles before the run ended (the window around a first
// mismatch, kept in a ring allocated up front and refused when it would take
// more than a quarter of the machine's memory). A .fst path is written as VCD
// and converted with gtkwave's vcd2fst. The file appears under its name only
// when complete (written as NAME.partial and renamed); a run that does not
// end normally leaves no file.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tb/base/out_pins.h"
#include "tb/report/vcd_writer.h"

namespace hwinterp::tb {

class Trace {
 public:
  // Most input elements a frame has (the shared ones and the core's own).
  static constexpr int kMaxInputs = 40;

  // `inputs`: the core's input ports in frame order (input_ports()); the
  // outputs are the shared contract's for `axes` and `pos_w`. `window` = 0
  // traces every cycle; otherwise only the last `window` cycles.
  Trace(const std::string& path, std::vector<PortSpec> inputs, int axes, int pos_w,
        uint64_t window);
  ~Trace();
  // `in`: one value per input element, in port order.
  void record(uint64_t cycle, const uint64_t* in, const OutPins& hls, const OutPins& rtl);
  // Writes what is buffered, then renames the file into place or converts it
  // to FST. Throws std::runtime_error when it cannot be written or converted.
  void close();

 private:
  struct Sample {
    uint64_t cycle;
    uint64_t in[kMaxInputs];
    OutPins hls, rtl;
  };
  void declare();
  void write(const Sample& s);

  std::string path_, vcd_path_;
  std::vector<PortSpec> inputs_;
  int axes_, pos_w_, input_count_ = 0;
  uint64_t window_;
  std::unique_ptr<VcdWriter> vcd_;
  std::vector<Sample> ring_;  // the last window_ samples; ring_[next_] is the oldest when full
  size_t next_ = 0;
  bool closed_ = false;
  // Signal ids.
  int clk_ = 0;
  std::vector<int> in_ids_;  // one per input element
  struct Outs {
    int ready, busy, done, step[kMaxAxes], dir[kMaxAxes], pos[kMaxAxes];
  } hls_{}, rtl_{};
};

}  // namespace hwinterp::tb

// Cycle trace of a dda_line co-simulation: the inputs and both DUTs' outputs
// (scopes tb, tb.hls, tb.rtl) in one VCD, either the whole run or only the
// last N cycles before the run ended (the window around a first mismatch).
// A .fst path is written as VCD and converted with gtkwave's vcd2fst.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>

#include "dda_line_pins.h"
#include "dda_line_stimulus.h"
#include "vcd_writer.h"

namespace hwinterp::tb {

class DdaLineTrace {
 public:
  // `window` = 0 traces every cycle; otherwise only the last `window` cycles.
  DdaLineTrace(const std::string& path, const DdaLineLimits& limits, uint64_t window);
  ~DdaLineTrace();
  void record(uint64_t cycle, const DdaLineFrame& in, const DdaLinePins& hls,
              const DdaLinePins& rtl);
  // Writes what is buffered and converts to FST when asked. Throws
  // std::runtime_error when the file cannot be written or converted.
  void close();

 private:
  struct Sample {
    uint64_t cycle;
    DdaLineFrame in;
    DdaLinePins hls, rtl;
  };
  void declare();
  void write(const Sample& s);

  std::string path_, vcd_path_;
  DdaLineLimits limits_;
  uint64_t window_;
  std::unique_ptr<VcdWriter> vcd_;
  std::deque<Sample> buffer_;
  bool closed_ = false;
  // Signal ids.
  int clk_, rst_, valid_, feed_, half_, len_, space_, setup_, hold_;
  int delta_[kMaxAxes];
  struct Outs {
    int ready, busy, done, step[kMaxAxes], dir[kMaxAxes], pos[kMaxAxes];
  } hls_, rtl_;
};

}  // namespace hwinterp::tb

// The step stream as a user analyses it (`--step-times FILE`): one CSV row
// per step pulse on the wire, header `clock,axis,dir`: the clock edge of the
// run (1-based, counted from the run's first edge, as --abort-at and the
// traces count) on which the pulse's rising edge was seen, the axis letter
// (X Y Z A B C in port order: axis i of step_o is the i-th letter) and the
// direction the pulse moved it, +1 or -1 (dir_o high is -1, the scoreboard's
// convention). Pulses on one clock are written in axis order. Written as the
// run goes, so memory does not grow with the stream.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>

namespace hwinterp::tb {

class StepTimesCsv {
 public:
  // Throws std::runtime_error when `path` cannot be written.
  StepTimesCsv(const std::string& path, int axes);
  // One row per set bit of `rising` (bit i: axis i), directions from `dir`.
  void write(uint64_t clock, uint32_t rising, uint32_t dir) {
    for (int i = 0; i < axes_; ++i)
      if ((rising >> i) & 1) row(clock, i, (dir >> i) & 1);
  }
  // Throws std::runtime_error when a row could not be written.
  void close();

 private:
  void row(uint64_t clock, int axis, bool negative);

  std::string path_;
  int axes_;
  std::ofstream out_;
};

}  // namespace hwinterp::tb

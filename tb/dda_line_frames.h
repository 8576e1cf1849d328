// Exports the input frames a dda_line co-simulation applied, one line per
// clock edge, for replay in any Verilog simulator (tb/verilog/
// dda_line_replay_tb.sv reads them with $fscanf("%h")). Each line is one hex
// word, most significant field first, the fields packed with no padding:
//   rst_ni, cmd_valid_i, cmd_delta_i[AXES-1] .. cmd_delta_i[0] (ACC_W each),
//   feed_i (FEED_W + 1), half_preload_i, step_len_i, step_space_i,
//   dir_setup_i, dir_hold_i (TIM_W each)
// Replaying the frames open loop reproduces the run exactly: the core is
// deterministic, so it answers cmd_valid_i with the same cmd_ready_o.
#pragma once

#include <fstream>
#include <string>

#include "dda_line_pins.h"
#include "dda_line_stimulus.h"

namespace hwinterp::tb {

class DdaLineFrameWriter {
 public:
  // Throws std::runtime_error naming `path` when it cannot be written.
  DdaLineFrameWriter(const std::string& path, const DdaLineLimits& limits);
  void write(const DdaLineFrame& f);
  void close();  // throws on a write error

  // Width of one frame in bits for these limits.
  static int frame_bits(const DdaLineLimits& limits);

 private:
  void field(uint64_t value, int width);

  std::string path_;
  DdaLineLimits limits_;
  std::ofstream out_;
  std::string bits_;  // '0'/'1', most significant first
};

}  // namespace hwinterp::tb

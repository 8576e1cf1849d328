// Exports the input frames a co-simulation applied, one line per clock edge,
// for replay in any Verilog simulator, together with a replay testbench
// generated for the core and variant (FILE.sv next to FILE): it instantiates
// the core with the variant's parameters, reads the frames with
// $fscanf("%h"), and prints the cycle count, the steps per axis, the done
// pulses and the final outputs, for comparison with the co-simulation's
// report (scripts/bench_speed.sh runs it under Icarus Verilog).
//
// Each line is one hex word, most significant field first, the input ports
// in frame order (input_ports()) packed with no padding; a port of several
// elements has its highest element first, as the RTL's flat vector.
// Replaying the frames open loop reproduces the run exactly: the core is
// deterministic, so it answers cmd_valid_i with the same cmd_ready_o.
#pragma once

#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "tb/base/variant_spec.h"

namespace hwinterp::tb {

class FrameWriter {
 public:
  // Writes the frames to `path` and the replay testbench to `testbench`
  // (the command line's is the frames' name + ".sv"); throws
  // std::runtime_error naming the file when either cannot be written.
  FrameWriter(const std::string& path, const std::string& testbench, const VariantSpec& spec,
              std::vector<PortSpec> inputs);
  // `in`: one value per input element, in port order.
  void write(const uint64_t* in);
  void close();  // throws on a write error

  // Width of one frame in bits.
  int frame_bits() const;
  // The replay testbench's text (module <core>_replay_tb).
  static std::string replay_testbench(const VariantSpec& spec, const std::vector<PortSpec>& inputs);

 private:
  std::string path_;
  std::vector<PortSpec> inputs_;
  std::ofstream out_;
  std::string bits_;  // '0'/'1', most significant first
};

}  // namespace hwinterp::tb

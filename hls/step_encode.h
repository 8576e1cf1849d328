// One axis's step output type: the cycle behaviour of rtl/step_encode.sv
// (see there for the contract), bit for bit. Synthesizable subset.
#pragma once

#include <cstdint>

namespace hwinterp::hls {

class StepEncode {
 public:
  void reset() { step_q_ = type_q_ = phase_q_ = 0; }

  // The outputs on a clock with these step stage outputs (a_o, b_o).
  bool a(bool step, bool dir) const {
    return type_q_ == 1 ? step && !dir : type_q_ == 2 ? ((phase_q_ >> 1) ^ phase_q_) & 1 : step;
  }
  bool b(bool step, bool dir) const {
    return type_q_ == 1 ? step && dir : type_q_ == 2 ? (phase_q_ >> 1) & 1 : dir;
  }

  // One rising clock edge with type_i, step_i and dir_i before it.
  void clock(uint8_t type, bool step, bool dir) {
    if (step && !step_q_) phase_q_ = static_cast<uint8_t>((dir ? phase_q_ - 1 : phase_q_ + 1) & 3);
    if (!step) type_q_ = type & 3;
    step_q_ = step;
  }

 private:
  uint8_t step_q_ = 0, type_q_ = 0, phase_q_ = 0;
};

}  // namespace hwinterp::hls

// The hostmot2 step/dir timing set, as the testbench drives it (step_len_i,
// step_space_i, dir_setup_i, dir_hold_i) and the monitors check it.
#pragma once

#include <cstdint>

namespace hwinterp::tb {

// Settings in clock cycles; 0 acts as 1 (rtl/stepdir_axis.sv).
struct StepdirTiming {
  uint32_t step_len = 1, step_space = 1, dir_setup = 1, dir_hold = 1;
};

}  // namespace hwinterp::tb

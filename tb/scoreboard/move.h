// One move on the step lattice: the axes that step on the same clock, and
// in which direction. What a core's reference model yields and what the
// scoreboard reads off step_o/dir_o.
#pragma once

#include <array>
#include <cstdint>

#include "tb/base/variant_spec.h"

namespace hwinterp::tb {

struct Move {
  std::array<int8_t, kMaxAxes> step{};  // -1, 0, +1 per axis
  uint64_t index = 0;                   // the model's operation (iteration) number, for messages

  bool same_steps(const Move& o, int axes) const {
    for (int i = 0; i < axes; ++i)
      if (step[static_cast<size_t>(i)] != o.step[static_cast<size_t>(i)]) return false;
    return true;
  }
};

}  // namespace hwinterp::tb

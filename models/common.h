// Small things the models, the harness and the tests share, written once:
// pi, the axis letters, the magnitude of a signed step count.
#pragma once

#include <cstdint>

namespace hwinterp::models {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2 * kPi;

// Machine axis i is the i-th letter (X Y Z A B C: motion_top's port order).
inline constexpr char kAxisLetters[] = "XYZABC";

// |v| without overflow at INT64_MIN.
inline uint64_t magnitude(int64_t v) {
  return v < 0 ? uint64_t{0} - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
}

}  // namespace hwinterp::models

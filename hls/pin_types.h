// SystemC port types matching `verilator --sc --pins-sc-uint`: 1 bit -> bool,
// 2..64 bits -> sc_uint<W>, wider -> sc_bv<W>. The HLS SC_MODULEs use them so
// that they and the Verilated RTL bind to the same signals.
//
// Why not sc_biguint for the wide ports (--pins-sc-biguint): Verilator 5.006
// (Debian 12) writes sc_biguint outputs through their raw digits and leaves
// the sign field stale, so a changed output can compare equal to zero and the
// signal never updates (upstream verilator PR #4870, fixed in later releases).
// sc_bv has no sign field.
#pragma once

#include <cstdint>
#include <systemc>
#include <type_traits>

namespace hwinterp::hls {

template <int W>
using pin_t = std::conditional_t<
    W == 1, bool,
    std::conditional_t<(W <= 64), sc_dt::sc_uint<(W <= 64 ? W : 64)>, sc_dt::sc_bv<W>>>;

// Field [lsb +: width] (width <= 64) of a pin value: packed per-axis ports
// hold axis i in bits [i*W +: W], as the RTL's `[AXES-1:0][W-1:0]`.
template <int W>
uint64_t pin_field(const pin_t<W>& v, int lsb, int width) {
  if constexpr (W == 1) {
    return v ? 1 : 0;
  } else {
    return v.range(lsb + width - 1, lsb).to_uint64();
  }
}

template <int W>
void set_pin_field(pin_t<W>& v, int lsb, int width, uint64_t value) {
  const uint64_t mask = width >= 64 ? ~uint64_t{0} : (uint64_t{1} << width) - 1;
  if constexpr (W == 1) {
    v = (value & mask) != 0;
  } else if constexpr (W <= 64) {
    v.range(lsb + width - 1, lsb) = value & mask;
  } else {
    v.range(lsb + width - 1, lsb) = sc_dt::sc_bv<64>(value & mask).range(width - 1, 0);
  }
}

}  // namespace hwinterp::hls

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

#include <algorithm>
#include <cstdint>
#include <systemc>
#include <type_traits>

namespace hwinterp::hls {

template <int W>
using pin_t = std::conditional_t<
    W == 1, bool,
    std::conditional_t<(W <= 64), sc_dt::sc_uint<(W <= 64 ? W : 64)>, sc_dt::sc_bv<W>>>;

// Field [lsb +: width] (width <= 64) of a pin value: packed per-axis ports
// hold axis i in bits [i*W +: W], as the RTL's `[AXES-1:0][W-1:0]`. Wide
// (sc_bv) pins go word by word through get_word/set_word: these run for
// every wide port on every clock of the SystemC mode.
template <int W>
uint64_t pin_field(const pin_t<W>& v, int lsb, int width) {
  if constexpr (W == 1) {
    return v ? 1 : 0;
  } else if constexpr (W <= 64) {
    return v.range(lsb + width - 1, lsb).to_uint64();
  } else {
    uint64_t out = 0;
    for (int done = 0; done < width;) {
      const int bit = lsb + done, word = bit / 32, off = bit % 32;
      const int take = std::min(32 - off, width - done);
      const uint64_t mask = (uint64_t{1} << take) - 1;
      out |= ((static_cast<uint64_t>(v.get_word(word)) >> off) & mask) << done;
      done += take;
    }
    return out;
  }
}

template <int W>
void set_pin_field(pin_t<W>& v, int lsb, int width, uint64_t value) {
  if (width < 64) value &= (uint64_t{1} << width) - 1;
  if constexpr (W == 1) {
    v = value != 0;
  } else if constexpr (W <= 64) {
    v.range(lsb + width - 1, lsb) = value;
  } else {
    for (int done = 0; done < width;) {
      const int bit = lsb + done, word = bit / 32, off = bit % 32;
      const int take = std::min(32 - off, width - done);
      const uint32_t mask = static_cast<uint32_t>(((uint64_t{1} << take) - 1) << off);
      const uint32_t w = v.get_word(word);
      v.set_word(word, (w & ~mask) | ((static_cast<uint32_t>(value >> done) << off) & mask));
      done += take;
    }
  }
}

}  // namespace hwinterp::hls

// Packing per-axis fields into the ports of `verilator --cc` models: a packed
// `[AXES-1:0][W-1:0]` port holds axis i in bits [i*W +: W]. Ports are
// CData/SData/IData/QData up to 64 bits and VlWide<N> beyond; fields are at
// most 64 bits wide. (SystemC pins: hls/pin_types.h.)
#pragma once

#include <verilated.h>

#include <algorithm>
#include <cstdint>
#include <type_traits>

namespace hwinterp::tb {

inline uint64_t low_mask(int width) {
  return width >= 64 ? ~uint64_t{0} : (uint64_t{1} << width) - 1;
}

// Verilator --cc scalar ports.
template <typename T, typename = std::enable_if_t<std::is_integral_v<T>>>
void put_bits(T& port, int lsb, int width, uint64_t value) {
  const uint64_t m = low_mask(width) << lsb;
  port = static_cast<T>((static_cast<uint64_t>(port) & ~m) | ((value << lsb) & m));
}
template <typename T, typename = std::enable_if_t<std::is_integral_v<T>>>
uint64_t get_bits(const T& port, int lsb, int width) {
  return (static_cast<uint64_t>(port) >> lsb) & low_mask(width);
}

// Verilator --cc wide ports: 32-bit words, least significant first. A field
// spans at most three words; each is updated with one mask (this runs for
// every port on every clock of the direct mode).
template <std::size_t N>
void put_bits(VlWide<N>& port, int lsb, int width, uint64_t value) {
  value &= low_mask(width);
  for (int done = 0; done < width;) {
    const int bit = lsb + done, word = bit / 32, off = bit % 32;
    const int take = std::min(32 - off, width - done);
    const uint32_t m = static_cast<uint32_t>(low_mask(take)) << off;
    port[word] = (port[word] & ~m) | ((static_cast<uint32_t>(value >> done) << off) & m);
    done += take;
  }
}
template <std::size_t N>
uint64_t get_bits(const VlWide<N>& port, int lsb, int width) {
  uint64_t v = 0;
  for (int done = 0; done < width;) {
    const int bit = lsb + done, word = bit / 32, off = bit % 32;
    const int take = std::min(32 - off, width - done);
    v |= ((static_cast<uint64_t>(port[word]) >> off) & low_mask(take)) << done;
    done += take;
  }
  return v;
}

}  // namespace hwinterp::tb

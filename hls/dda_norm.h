// The DDA engine's normalisation of a command: the cycle behaviour of
// rtl/dda_norm.sv (see there). Synthesizable subset.
#pragma once

#include <systemc>

namespace hwinterp::hls {

template <int W>
struct DdaMasks {
  sc_dt::sc_uint<W> low, hm, top;  // 2^n - 1, its complement, 2^(n-1)
};

// From the OR of a command's magnitudes (bit length n).
template <int W>
DdaMasks<W> dda_norm(const sc_dt::sc_uint<W>& any) {
  const uint64_t v = any.to_uint64();
  const int n = v == 0 ? 0 : 64 - __builtin_clzll(v);
  DdaMasks<W> m;
  m.low = n >= 64 ? ~uint64_t{0} : (uint64_t{1} << n) - 1;
  m.hm = ~m.low;
  m.top = m.low ^ (m.low >> 1);
  return m;
}

}  // namespace hwinterp::hls

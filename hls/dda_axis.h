// One axis of the DDA engine: the cycle behaviour of rtl/dda_axis.sv (see
// there for the accumulator's offset form and the two moduli).
// Synthesizable subset: SystemC integers, no floats, no heap.
#pragma once

#include <systemc>

namespace hwinterp::hls {

template <int W, bool MODULUS_2N>
class DdaAxis {
 public:
  using word_t = sc_dt::sc_uint<W>;
  using sum_t = sc_dt::sc_uint<W + 1>;

  void reset() { mag_q_ = dc_q_ = s_q_ = 0; }

  // This iteration steps the axis (a register).
  bool carry() const { return s_q_[W]; }

  // One rising clock edge: `pre` the next add is a load's (a register),
  // `ld` load the next command's magnitude and dc, `en` take this clock's add.
  void clock(bool pre, bool ld, bool en, const word_t& a0, const word_t& b_mag, const sum_t& b_dc,
             const word_t& hm) {
    if (en) {
      const word_t low = s_q_.range(W - 1, 0);
      if (MODULUS_2N) {
        // s_q_ holds the mask itself; a load's sum has no carry but at bit n-1.
        if (pre) {
          s_q_ = (sum_t((a0 & b_mag) != 0) << W) | sum_t(a0 ^ b_mag);
        } else {
          const sum_t s = sum_t(low) + sum_t(mag_q_);
          s_q_ = s | sum_t(hm);
        }
      } else {
        const word_t x = pre ? a0 : low;
        // dc has W + 1 bits (rtl/dda_axis.sv): 2^W when the axis steps every iteration.
        const sum_t y = pre ? sum_t(b_mag) : (s_q_[W] ? dc_q_ : sum_t(mag_q_));
        s_q_ = sum_t(x) + y;
      }
    }
    if (ld) {
      mag_q_ = b_mag;
      if (!MODULUS_2N) dc_q_ = b_dc;
    }
  }

 private:
  word_t mag_q_ = 0;
  sum_t dc_q_ = 0;
  sum_t s_q_ = 0;  // accumulator + increment, one iteration ahead; bit W is the carry
                   // (MODULUS_2N: with the high mask ORed in)
};

}  // namespace hwinterp::hls

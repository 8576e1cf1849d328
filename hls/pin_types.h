// SystemC port types matching `verilator --sc --pins-sc-uint --pins-sc-biguint`:
// 1 bit -> bool, 2..64 bits -> sc_uint<W>, wider -> sc_biguint<W>. The HLS
// SC_MODULEs use them so that they and the Verilated RTL bind to the same signals.
#pragma once

#include <systemc>
#include <type_traits>

namespace hwinterp::hls {

template <int W>
using pin_t = std::conditional_t<
    W == 1, bool, std::conditional_t<(W <= 64), sc_dt::sc_uint<(W <= 64 ? W : 64)>,
                                     sc_dt::sc_biguint<W>>>;

}  // namespace hwinterp::hls

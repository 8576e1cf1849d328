// A core's payload (its own inputs: the command and any per-command
// setting) described once, as MatchLib's Marshall() describes a message:
// the payload struct `Own` of an HLS core lists its fields, in the RTL's
// port order, in one static function
//
//   struct Own {
//     acc_t delta[AXES] = {};
//     bool half_preload = false;
//     static auto fields() {
//       return std::make_tuple(HWINTERP_FIELD(cmd_delta_i, &Own::delta, kSigned),
//                              HWINTERP_FIELD(half_preload_i, &Own::half_preload, kUnsigned));
//     }
//   };
//
// and everything else is derived from that list: the SC_MODULE's own ports
// and their reads (FieldPorts below), the testbench's pins in both lockstep
// modes, the order and widths of traces and frame dumps, the JSON of the
// inputs, the range checks of stimulus values (tb/lockstep/payload_pins.h),
// and a unit test checks the list against the ports of rtl/<core>.sv.
//
// A field is one port: its name, the member holding it (bool, sc_uint<W> or
// sc_int<W>, or an array T[N] of them: N elements of W bits, element i at
// bits [i*W +: W] of the flat port, as the RTL's per-axis vectors), and
// whether its elements are two's complement numbers. Width and element count
// come from the member's type, so a field cannot disagree with the struct.
#pragma once

#include <cstddef>
#include <cstdint>
#include <systemc>
#include <tuple>
#include <type_traits>
#include <utility>

#include "hls/pin_types.h"

namespace hwinterp::hls {

enum class Sign { kUnsigned, kSigned };

// Bits of one element of a payload member.
template <class T>
struct ElementBits;
template <>
struct ElementBits<bool> {
  static constexpr int value = 1;
};
template <int W>
struct ElementBits<sc_dt::sc_uint<W>> {
  static constexpr int value = W;
};
template <int W>
struct ElementBits<sc_dt::sc_int<W>> {
  static constexpr int value = W;
};

// A member of type M: its element type and how many elements it has.
template <class M>
struct MemberShape {
  using Element = M;
  static constexpr int kCount = 1;
};
template <class T, std::size_t N>
struct MemberShape<T[N]> {
  using Element = T;
  static constexpr int kCount = static_cast<int>(N);
};

// One field of payload struct Own: member `member` on port `name`;
// port_of(model) is the member of that name of any model that has the
// port (the Verilated --cc and --sc models of the RTL).
template <class Own, class M, class PortOf>
struct Field {
  using Element = typename MemberShape<M>::Element;
  static constexpr int kWidth = ElementBits<Element>::value;
  static constexpr int kCount = MemberShape<M>::kCount;
  static constexpr int kBits = kWidth * kCount;  // the flat port's width
  static_assert(kWidth >= 1 && kWidth <= 64, "a payload element is 1 to 64 bits wide");

  const char* name;
  M Own::*member;
  PortOf port_of;
  Sign sign;

  // Element i: its low kWidth bits.
  uint64_t get(const Own& own, int i) const {
    const Element& e = element(own, i);
    uint64_t v;
    if constexpr (std::is_same_v<Element, bool>)
      v = e ? 1 : 0;
    else
      v = static_cast<uint64_t>(e.to_uint64());
    return kWidth == 64 ? v : v & ((uint64_t{1} << kWidth) - 1);
  }
  // Sets element i from the low kWidth bits of `v`.
  void set(Own& own, int i, uint64_t v) const {
    if constexpr (std::is_same_v<Element, bool>)
      element(own, i) = (v & 1) != 0;
    else
      element(own, i) = v;
  }

 private:
  template <class O>  // Own or const Own
  static auto& element_of(O& own, M Own::*member, int i) {
    if constexpr (kCount == 1) {
      (void)i;
      return own.*member;
    } else {
      return (own.*member)[i];
    }
  }
  Element& element(Own& own, int i) const { return element_of(own, member, i); }
  const Element& element(const Own& own, int i) const { return element_of(own, member, i); }
};

template <class Own, class M, class PortOf>
constexpr Field<Own, M, PortOf> field(const char* name, M Own::*member, PortOf port_of, Sign sign) {
  return {name, member, port_of, sign};
}

// A field on port `port` (an RTL port name), held in `member` (&Own::x),
// signedness kSigned or kUnsigned.
#define HWINTERP_FIELD(port, member, sign) \
  ::hwinterp::hls::field(                  \
      #port, member, [](auto& model) -> auto& { return model.port; }, ::hwinterp::hls::Sign::sign)

// The number of fields of Own, and f(field, index) for each in order.
template <class Own>
inline constexpr std::size_t kFieldCount = std::tuple_size_v<decltype(Own::fields())>;

template <class Own, class F>
void for_each_field(F&& f) {
  const auto fields = Own::fields();
  std::apply(
      [&](const auto&... fl) {
        std::size_t i = 0;
        (f(fl, i++), ...);
      },
      fields);
}

template <class Own, std::size_t I>
using FieldAt = std::tuple_element_t<I, decltype(Own::fields())>;

// The SC_MODULE face's own input ports (hls/stepper_module.h), one sc_in per
// field with the RTL's name and Verilator's pin type, and their reads.
template <class Own>
class FieldPorts {
  template <class Tuple>
  struct Ports;
  template <class... F>
  struct Ports<std::tuple<F...>> {
    using type = std::tuple<sc_core::sc_in<pin_t<F::kBits>>...>;
  };

 public:
  FieldPorts() : FieldPorts(std::make_index_sequence<kFieldCount<Own>>{}) {}

  // Every field from its port.
  void read(Own& own) const { read(own, std::make_index_sequence<kFieldCount<Own>>{}); }

  // The port of field I (the testbench binds it).
  template <std::size_t I>
  auto& own_port() {
    return std::get<I>(ports_);
  }

 private:
  template <std::size_t... I>
  explicit FieldPorts(std::index_sequence<I...>) : ports_(std::get<I>(Own::fields()).name...) {}

  template <std::size_t... I>
  void read(Own& own, std::index_sequence<I...>) const {
    const auto fields = Own::fields();
    (read_field(std::get<I>(fields), std::get<I>(ports_), own), ...);
  }
  template <class F, class Port>
  static void read_field(const F& f, const Port& port, Own& own) {
    const pin_t<F::kBits>& v = port.read();
    for (int i = 0; i < F::kCount; ++i)
      f.set(own, i, pin_field<F::kBits>(v, i * F::kWidth, F::kWidth));
  }

  typename Ports<decltype(Own::fields())>::type ports_;
};

}  // namespace hwinterp::hls

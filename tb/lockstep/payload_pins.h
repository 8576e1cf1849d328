// A core's payload as the testbench sees it, derived from the field list of
// its HLS payload struct (hls/fields.h): the own input ports of a variant's
// spec (frame dumps, traces, JSON, range checks), and the flat values of a
// command in that port order. An adapter A supplies one conversion,
//
//   template <class Own>
//   static void to_own(const A::Command&, const A::Setup&, Own& own);
//
// which fills the HLS core's payload struct (A::Hls<Cfg>::Own) from the
// testbench's command; the pins of both lockstep modes come from the same
// list (tb/lockstep/direct.h, tb/lockstep/systemc.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "hls/fields.h"
#include "tb/base/variant_spec.h"

namespace hwinterp::tb {

// The HLS payload struct of adapter A's core on variant Cfg.
template <class A, class Cfg>
using OwnOf = typename A::template Hls<Cfg>::Own;

// The payload's ports, in field (= RTL port) order.
template <class Own>
std::vector<PortSpec> own_port_specs() {
  std::vector<PortSpec> ports;
  hls::for_each_field<Own>([&](const auto& f, std::size_t) {
    using F = std::decay_t<decltype(f)>;
    ports.push_back({f.name, F::kCount, F::kWidth, f.sign == hls::Sign::kSigned});
  });
  return ports;
}

// Variant Cfg of adapter A's core: the configuration and the payload's ports.
template <class A, class Cfg>
VariantSpec spec_of() {
  VariantSpec s = spec_of_config<Cfg>();
  s.own_ports = own_port_specs<OwnOf<A, Cfg>>();
  return s;
}

// One value per payload element (the low bits of each), in port order;
// returns the count written.
template <class Own>
std::size_t flatten_own(const Own& own, uint64_t* out) {
  std::size_t k = 0;
  hls::for_each_field<Own>([&](const auto& f, std::size_t) {
    using F = std::decay_t<decltype(f)>;
    for (int i = 0; i < F::kCount; ++i) out[k++] = f.get(own, i);
  });
  return k;
}

// The same from the testbench's command and setup (traces and frame dumps:
// not per clock unless they are on).
template <class A, class Cfg>
std::size_t flatten_payload(const typename A::Command& c, const typename A::Setup& s,
                            uint64_t* out) {
  OwnOf<A, Cfg> own{};
  A::to_own(c, s, own);
  return flatten_own(own, out);
}

template <class A>
using FlattenPayload = std::size_t (*)(const typename A::Command&, const typename A::Setup&,
                                       uint64_t*);

}  // namespace hwinterp::tb

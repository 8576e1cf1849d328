// The typed lockstep run behind the registry's BenchRun: one Bench<A> of
// core adapter A and variant Cfg, clocked by the direct or the SystemC
// runner. The registry makes them from the command line, the job format and
// the regression; a command that knows its core (hwinterp gcode, which
// streams motion_top's commands from a part program) makes one itself.
#pragma once

#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "hwinterp_core_adapters.h"
#include "tb/lockstep/direct.h"
#include "tb/lockstep/payload_pins.h"
#include "tb/lockstep/registry.h"
#include "tb/lockstep/systemc.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb {

template <class T>
struct type_tag {
  using type = T;
};

template <class A, class Cfg>
class BenchRunOf final : public BenchRun {
 public:
  BenchRunOf(VariantSpec spec, std::vector<Case<A>> cases, const BenchOptions& options)
      : bench_(std::move(spec), std::move(cases), options, &flatten_payload<A, Cfg>) {}
  const VariantSpec& spec() const override { return bench_.spec(); }
  size_t case_count() const override { return bench_.case_count(); }
  void run_direct() override { tb::run_direct<A, Cfg>(bench_); }
  std::unique_ptr<sc_core::sc_module> systemc_module(ScRunControl& control) override {
    return std::make_unique<ScBench<A, Cfg>>(sc_core::sc_gen_unique_name(Cfg::kVariant), bench_,
                                             control);
  }
  bool finished() const override { return bench_.finished(); }
  const std::vector<CaseResult>& results() const override { return bench_.results(); }
  uint64_t cycles() const override { return bench_.cycles(); }
  void close() override { bench_.close(); }

 private:
  Bench<A> bench_;
};

// A run of validated cases; an output file that cannot be written is bad input.
template <class A, class Cfg>
std::unique_ptr<BenchRun> make_run(const VariantSpec& l, std::vector<Case<A>> cases,
                                   const BenchOptions& options) {
  for (const auto& c : cases) validate_case(c, l);
  try {
    return std::make_unique<BenchRunOf<A, Cfg>>(l, std::move(cases), options);
  } catch (const std::runtime_error& e) {
    throw cli::UsageError(e.what());
  }
}

// A variant of adapter A's core that runs any cases of A: for a command that
// knows its core and streams its own cases (hwinterp gcode).
template <class A>
struct TypedVariant {
  VariantSpec spec;
  std::unique_ptr<BenchRun> (*make)(const VariantSpec&, std::vector<Case<A>>, const BenchOptions&);
};

// Every variant of adapter A's core, in cores.cmake order.
template <class A>
std::vector<TypedVariant<A>> typed_variants() {
  std::vector<TypedVariant<A>> out;
  auto add = [&](auto adapter, auto cfg) {
    using Ad = typename decltype(adapter)::type;
    using Cfg = typename decltype(cfg)::type;
    if constexpr (std::is_same_v<Ad, A>) out.push_back({spec_of<A, Cfg>(), &make_run<A, Cfg>});
  };
#define HWINTERP_TYPED_VARIANT(core, variant) \
  add(type_tag<cores::core::Adapter>{}, type_tag<variant##_cfg>{});
  HWINTERP_VARIANTS(HWINTERP_TYPED_VARIANT)
#undef HWINTERP_TYPED_VARIANT
  return out;
}

}  // namespace hwinterp::tb

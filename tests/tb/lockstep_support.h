// Shared by the lockstep test suites (conformance, per-core, long): every
// core and variant as GoogleTest types, runs in both modes, and the pass
// conditions every clean run must meet.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "hwinterp_core_adapters.h"
#include "hwinterp_variants.h"
#include "tb/lockstep/direct.h"
#include "tb/lockstep/registry.h"
#include "tb/lockstep/systemc.h"

namespace hwinterp::tb::testing {

// One variant of one core: its adapter and its generated configuration.
template <class A, class C>
struct Variant {
  using Adapter = A;
  using Cfg = C;
  static CoreLimits limits() { return limits_of<C>(); }
};

template <class... T>
struct TypeList {};
template <class L>
struct GtestTypes;
template <class Dummy, class... T>
struct GtestTypes<TypeList<Dummy, T...>> {
  using type = ::testing::Types<T...>;
};

#define HWINTERP_TEST_VARIANT(core, variant) \
  , ::hwinterp::tb::testing::Variant<::hwinterp::tb::cores::core::Adapter, variant##_cfg>
// Every variant of every core in cmake/cores.cmake.
using AllVariants = GtestTypes<TypeList<void HWINTERP_VARIANTS(HWINTERP_TEST_VARIANT)>>::type;
#undef HWINTERP_TEST_VARIANT

// Names typed tests after the variant ("Conformance/dda_line_n2.ResetState").
struct VariantName {
  template <class V>
  static std::string GetName(int) {
    return V::Cfg::kVariant;
  }
};

template <class V>
std::vector<CaseResult> run_direct(std::vector<Case<typename V::Adapter>> cases,
                                   BenchOptions o = {}) {
  o.mode = "direct";
  for (const auto& c : cases) validate_case(c, V::limits());
  Bench<typename V::Adapter> bench(V::limits(), std::move(cases), o);
  tb::run_direct<typename V::Adapter, typename V::Cfg>(bench);
  return bench.results();
}

// One SystemC elaboration: call once per test (ctest runs every test in its
// own process).
template <class V>
std::vector<CaseResult> run_systemc(std::vector<Case<typename V::Adapter>> cases,
                                    BenchOptions o = {}) {
  o.mode = "systemc";
  for (const auto& c : cases) validate_case(c, V::limits());
  Bench<typename V::Adapter> bench(V::limits(), std::move(cases), o);
  ScRunControl control;
  ScBench<typename V::Adapter, typename V::Cfg> module("bench", bench, control);
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);
  sc_core::sc_start();
  return bench.results();
}

inline void expect_all_pass(const std::vector<CaseResult>& results) {
  ASSERT_FALSE(results.empty());
  for (const auto& r : results) {
    EXPECT_TRUE(r.passed()) << r.variant << " " << r.mode << " " << r.name << ": "
                            << r.to_json().dump();
    EXPECT_EQ(r.commands, r.commands_offered) << r.name;
    EXPECT_EQ(r.end_position, r.expected_end_position) << r.name;
  }
}

inline uint64_t total_cycles(const std::vector<CaseResult>& results) {
  uint64_t n = 0;
  for (const auto& r : results) n += r.cycles;
  return n;
}

}  // namespace hwinterp::tb::testing

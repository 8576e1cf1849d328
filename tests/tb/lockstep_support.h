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
#include "tb/lockstep/case_profile.h"
#include "tb/lockstep/direct.h"
#include "tb/lockstep/registry.h"
#include "tb/lockstep/systemc.h"
#include "tb/monitor/kinematics.h"
#include "tb/stimulus/delta_commands.h"

namespace hwinterp::tb::testing {

// One variant of one core: its adapter and its generated configuration.
template <class A, class C>
struct Variant {
  using Adapter = A;
  using Cfg = C;
  static VariantSpec spec() { return spec_of<A, C>(); }
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

// The variant's payload flattener (Bench's traces, frame dumps, reports).
template <class V>
FlattenPayload<typename V::Adapter> flatten() {
  return &flatten_payload<typename V::Adapter, typename V::Cfg>;
}

template <class V>
std::vector<CaseResult> run_direct(std::vector<Case<typename V::Adapter>> cases,
                                   BenchOptions o = {}) {
  o.mode = "direct";
  for (const auto& c : cases) validate_case(c, V::spec());
  Bench<typename V::Adapter> bench(V::spec(), std::move(cases), o, flatten<V>());
  tb::run_direct<typename V::Adapter, typename V::Cfg>(bench);
  return bench.results();
}

// One SystemC elaboration: call once per test (ctest runs every test in its
// own process).
template <class V>
std::vector<CaseResult> run_systemc(std::vector<Case<typename V::Adapter>> cases,
                                    BenchOptions o = {}) {
  o.mode = "systemc";
  for (const auto& c : cases) validate_case(c, V::spec());
  Bench<typename V::Adapter> bench(V::spec(), std::move(cases), o, flatten<V>());
  ScRunControl control;
  ScBench<typename V::Adapter, typename V::Cfg> module("bench", bench, control);
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);
  sc_core::sc_start();
  return bench.results();
}

// A failed case in a few lines: where, and the first findings.
inline std::string describe(const CaseResult& r) {
  std::string s = r.variant + " " + r.mode + " '" + r.name + "': cycles " +
                  std::to_string(r.cycles) + ", commands " + std::to_string(r.commands) + "/" +
                  std::to_string(r.commands_offered);
  if (r.first_mismatch)
    s += ", mismatch at cycle " + std::to_string(r.first_mismatch->cycle) + " on " +
         r.first_mismatch->signal;
  for (const auto& e : r.scoreboard_errors) s += "\n  scoreboard: " + e;
  for (const auto& v : r.timing_violations)
    s += "\n  timing: cycle " + std::to_string(v.cycle) + " axis " + std::to_string(v.axis) + " " +
         v.rule;
  if (r.timed_out) s += "\n  timed out";
  return s;
}

// Every case passed: no mismatch, violation or scoreboard error, every
// command taken, the exact end point (and, when given, `cases` cases ran).
inline void expect_all_pass(const std::vector<CaseResult>& results, size_t cases = 0) {
  ASSERT_FALSE(results.empty());
  if (cases) ASSERT_EQ(results.size(), cases);
  for (const auto& r : results) {
    EXPECT_TRUE(r.passed()) << describe(r);
    EXPECT_EQ(r.commands, r.commands_offered) << describe(r);
    EXPECT_EQ(r.end_position, r.expected_end_position) << describe(r);
  }
}

// Settings at which the step stage never stalls a core that steps one axis
// per operation: one operation every second clock (feed 1/2) with 1-clock
// pulses, spaces, setup and hold.
template <class A>
RunSettings<A> half_feed_unit_timing(const VariantSpec& l) {
  RunSettings<A> s = default_settings<A>(l);
  s.feed = l.full_feed() / 2;
  s.timing = {1, 1, 1, 1};
  return s;
}

// The registry's regression cases of `core` (random streams of 60 commands,
// seed 5) on every variant in both lockstep modes, the way `hwinterp regress`
// runs them (SystemC: every variant in one elaboration): all pass, `cases`
// cases each, and both modes run the same clocks. Elaborates SystemC.
inline void regression_both_modes(const std::string& core, size_t variants, size_t cases) {
  const CoreEntry& entry = find_core(core);
  ASSERT_EQ(entry.variants.size(), variants);
  std::vector<std::unique_ptr<BenchRun>> runs;
  std::vector<BenchRun*> sc;
  for (const auto& v : entry.variants) {
    BenchOptions o;
    o.mode = "direct";
    runs.push_back(v.regression(60, 5, o, {}));
    runs.back()->run_direct();
    o.mode = "systemc";
    runs.push_back(v.regression(60, 5, o, {}));
    sc.push_back(runs.back().get());
  }
  run_systemc(sc);
  for (size_t k = 0; k < runs.size(); ++k) {
    ASSERT_TRUE(runs[k]->finished());
    expect_all_pass(runs[k]->results(), cases);
    if (k % 2) EXPECT_EQ(runs[k]->cycles(), runs[k - 1]->cycles());  // modes agree
  }
}

inline uint64_t total_cycles(const std::vector<CaseResult>& results) {
  uint64_t n = 0;
  for (const auto& r : results) n += r.cycles;
  return n;
}

}  // namespace hwinterp::tb::testing

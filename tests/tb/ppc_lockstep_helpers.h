// Small helpers for the PPC cores' lockstep tests (tests/tb/ppc_*_test.cpp):
// run cases through the shared harness in the direct mode and describe a
// result when it fails.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "hls/stepper_io.h"  // before direct.h, which uses it without including it
#include "hwinterp_variants.h"
#include "tb/lockstep/direct.h"
#include "tb/lockstep/registry.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb::ppc_testing {

// Validates and runs `cases` on variant Cfg (direct mode: HLS tick() vs
// Verilated --cc RTL, both against the adapter's reference model).
template <class A, class Cfg>
std::vector<CaseResult> run_cases(std::vector<Case<A>> cases, BenchOptions options = {}) {
  const CoreLimits l = limits_of<Cfg>();
  for (const auto& c : cases) validate_case(c, l);
  options.mode = "direct";
  Bench<A> bench(l, std::move(cases), options);
  run_direct<A, Cfg>(bench);
  return bench.results();
}

inline std::string describe(const CaseResult& r) {
  std::string s = r.variant + " '" + r.name + "': cycles " + std::to_string(r.cycles) +
                  ", commands " + std::to_string(r.commands) + "/" +
                  std::to_string(r.commands_offered);
  if (r.first_mismatch)
    s += ", mismatch at cycle " + std::to_string(r.first_mismatch->cycle) + " on " +
         r.first_mismatch->signal;
  for (const auto& e : r.scoreboard_errors) s += "\n  scoreboard: " + e;
  for (const auto& v : r.timing_violations)
    s += "\n  timing: axis " + std::to_string(v.axis) + " " + v.rule;
  if (r.timed_out) s += "\n  timed out";
  return s;
}

inline void expect_all_passed(const std::vector<CaseResult>& results, size_t cases) {
  ASSERT_EQ(results.size(), cases);
  for (const auto& r : results) {
    EXPECT_TRUE(r.passed()) << describe(r);
    EXPECT_EQ(r.end_position, r.expected_end_position) << describe(r);
  }
}

// Settings at which the step stage never stalls a PPC core: one operation
// every second clock (feed 1/2) with 1-clock pulses and spaces, and
// directions that need 1 clock of setup and hold.
template <class A>
RunSettings<A> half_feed_unit_timing(const CoreLimits& l) {
  RunSettings<A> s = default_settings<A>(l);
  s.feed = l.full_feed() / 2;
  s.timing = {1, 1, 1, 1};
  return s;
}

// The registry's regression cases of `core` (a random stream of 60 commands,
// seed 5) on every variant in both lockstep modes (SystemC: every variant in
// one elaboration): all `cases` pass, and both modes run the same clocks.
inline void regression_both_modes(const std::string& core, size_t variants, size_t cases) {
  const CoreEntry& entry = find_core(core);
  ASSERT_EQ(entry.variants.size(), variants);
  std::vector<std::unique_ptr<BenchRun>> runs;
  std::vector<BenchRun*> sc;
  for (const auto& v : entry.variants) {
    BenchOptions o;
    o.mode = "direct";
    runs.push_back(v.regression(60, 5, o));
    runs.back()->run_direct();
    o.mode = "systemc";
    runs.push_back(v.regression(60, 5, o));
    sc.push_back(runs.back().get());
  }
  run_systemc(sc);
  for (size_t k = 0; k < runs.size(); ++k) {
    ASSERT_TRUE(runs[k]->finished());
    expect_all_passed(runs[k]->results(), cases);
    if (k % 2) EXPECT_EQ(runs[k]->cycles(), runs[k - 1]->cycles());  // modes agree
  }
}

}  // namespace hwinterp::tb::ppc_testing

// dda_line: HLS core and Verilated RTL in lockstep, both checked against the
// reference model, on random streams and the paper's lines, in both modes;
// and proof that the comparator, the monitors and the scoreboard can fail.
//
// SystemC tests elaborate once per process: run them through ctest, which
// gives every test its own process (gtest_discover_tests).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "dda_line_cosim.h"
#include "dda_line_test_support.h"

namespace hwinterp::tb {
namespace {

uint64_t total_cycles(const std::vector<CaseResult>& results) {
  uint64_t n = 0;
  for (const auto& r : results) n += r.cycles;
  return n;
}

// Random streams on both variants and several seeds: well over 10^5 cycles.
TEST(DdaLineLockstep, DirectRandomStreams) {
  uint64_t cycles = 0;
  for (const std::string& v : dda_line_variants()) {
    for (uint64_t seed : {1u, 2u, 3u}) {
      const auto results = run_direct(v, {random_case(dda_line_limits(v), 120, seed)});
      expect_all_pass(results);
      cycles += total_cycles(results);
    }
  }
  EXPECT_GT(cycles, 200000u);
  RecordProperty("cycles", std::to_string(cycles));
}

// The eight lines of 004 with plain and half preload: exact ends, and the
// errors the model predicts (every move was compared with it as well).
TEST(DdaLineLockstep, DirectPaperLines) {
  const DdaLineLimits l = dda_line_limits(dda_line_variant_for_axes(2));
  DdaLineSettings half = default_settings(l);
  half.half_preload = true;
  const auto plain = run_direct(l.variant, paper_lines_004(l, default_settings(l)));
  const auto halfr = run_direct(l.variant, paper_lines_004(l, half));
  expect_all_pass(plain);
  expect_all_pass(halfr);
  ASSERT_EQ(plain.size(), 8u);
  for (size_t i = 0; i < 8; ++i) {
    EXPECT_LT(plain[i].max_path_error_steps, 1.0);
    EXPECT_LE(halfr[i].max_path_error_steps, std::sqrt(0.5) + 1e-12);
    EXPECT_LE(halfr[i].max_path_error_steps, plain[i].max_path_error_steps + 1e-12);
  }
  // Line 1 (0,0)->(20,40): 20 and 40 steps.
  EXPECT_EQ(plain[0].steps, (std::vector<uint64_t>{20, 40}));
}

// Deltas on both sides of every power of two up to 2^12 (the normaliser's
// edge cases: bit length, shift), with both signs and both preloads, through
// HLS, RTL and the model, on both variants.
TEST(DdaLineLockstep, DirectPowerOfTwoEdgeDeltas) {
  for (const std::string& v : dda_line_variants()) {
    const DdaLineLimits l = dda_line_limits(v);
    for (const bool half : {false, true}) {
      DdaLineSettings s = default_settings(l);
      s.half_preload = half;
      s.timing = {1, 1, 1, 1};
      DdaLineCase c{"edges", models::LatticePoint(static_cast<size_t>(l.axes), 0), s, {}};
      for (int k = 0; k <= 12; ++k) {
        for (const int64_t m : {(int64_t{1} << k) - 1, int64_t{1} << k, (int64_t{1} << k) + 1}) {
          DdaLineItem it;
          it.delta.assign(static_cast<size_t>(l.axes), 0);
          it.delta[0] = m;
          it.delta[1] = -(m / 2 + 1);
          if (l.axes > 2) it.delta[static_cast<size_t>(l.axes) - 1] = k % 2 ? -m : m;
          c.items.push_back(it);
        }
      }
      expect_all_pass(run_direct(v, {c}));
    }
  }
}

// Full feed with hostmot2 timing L = 3, S = 2 on a single-axis move: the
// output stage never lets a step out early (monitors) and never holds one
// longer than the timing needs: one step every L + S = 5 clocks.
TEST(DdaLineLockstep, StepRateIsExactlyTheTimingLimit) {
  const DdaLineLimits l = dda_line_limits(dda_line_variant_for_axes(2));
  DdaLineSettings s = default_settings(l);
  s.timing = {3, 2, 1, 1};
  for (int64_t n : {16, 100}) {
    const auto r = run_direct(l.variant, {line_case(l, "x", {0, 0}, {n, 0}, s)});
    expect_all_pass(r);
    // Reset (2) + take (2) + n pulses 5 clocks apart + the last pulse's tail.
    const uint64_t overhead = r[0].cycles - static_cast<uint64_t>(5 * n);
    EXPECT_LE(overhead, 10u) << n;
    EXPECT_GE(r[0].cycles, static_cast<uint64_t>(5 * (n - 1) + 3)) << n;
  }
}

// A feed word of 1/4 of full: the engine iterates on one clock in four.
// Two line lengths (64 and 128 iterations) cancel the fixed overhead.
TEST(DdaLineLockstep, FeedWordSetsTheIterationRate) {
  const DdaLineLimits l = dda_line_limits(dda_line_variant_for_axes(2));
  DdaLineSettings full = default_settings(l), quarter = full;
  full.timing = quarter.timing = {1, 1, 1, 1};
  quarter.feed = l.full_feed() / 4;
  auto cycles = [&](const DdaLineSettings& s, int64_t dy) {
    // (0,0)->(0,dy) with dy a power of two: 2 dy iterations, a step every other one.
    const auto r = run_direct(l.variant, {line_case(l, "y", {0, 0}, {0, dy}, s)});
    expect_all_pass(r);
    return static_cast<double>(r[0].cycles);
  };
  const double full_64 = cycles(full, 64) - cycles(full, 32);  // 64 more iterations
  const double quarter_64 = cycles(quarter, 64) - cycles(quarter, 32);
  EXPECT_NEAR(full_64, 64, 1);
  EXPECT_NEAR(quarter_64, 256, 4);
}

// The comparator can fail: a one-cycle difference injected into the HLS
// outputs stops the run at that cycle, naming the signal and both values.
TEST(DdaLineLockstep, InjectedMismatchIsReported) {
  const DdaLineLimits l = dda_line_limits(dda_line_variant_for_axes(2));
  BenchOptions o;
  o.faults.flip_hls_step_at = 50;
  const auto r = run_direct(l.variant, paper_lines_004(l, default_settings(l)), o);
  ASSERT_EQ(r.size(), 1u);  // the first mismatch ends the run
  EXPECT_FALSE(r[0].passed());
  EXPECT_EQ(r[0].mismatches, 1u);
  ASSERT_TRUE(r[0].first_mismatch.has_value());
  EXPECT_EQ(r[0].first_mismatch->cycle, 50u);
  EXPECT_EQ(r[0].first_mismatch->signal, "step_o[0]");
  EXPECT_NE(r[0].first_mismatch->hls, r[0].first_mismatch->rtl);
  EXPECT_EQ(r[0].cycles, 50u);
}

// The monitors can fail. With L = S = 4 on (0,0)->(8,0) the pulses are 8
// clocks apart; a one-cycle glitch on step_o[0] anywhere among them either
// makes a pulse shorter than L or a gap shorter than S, so every glitch must
// be reported, between the glitched cycle and L clocks later (a short pulse
// is known when it falls). The run goes on (the DUTs
// still agree), and the scoreboard sees the extra or missing moves too.
TEST(DdaLineLockstep, EveryInjectedGlitchIsATimingViolation) {
  const DdaLineLimits l = dda_line_limits(dda_line_variant_for_axes(2));
  DdaLineSettings s = default_settings(l);
  s.timing = {4, 4, 1, 1};
  const std::vector<DdaLineCase> line = {line_case(l, "x", {0, 0}, {8, 0}, s)};
  const auto clean = run_direct(l.variant, line);
  expect_all_pass(clean);
  ASSERT_GT(clean[0].cycles, 60u);
  // From the first pulse on: a glitch just before it only moves the first
  // rising edge earlier, which no rule can measure (there is no edge before it).
  const uint64_t first = clean[0].first_step_cycle;
  ASSERT_GT(first, 2u);
  uint64_t scoreboard_hits = 0;
  for (uint64_t g = first; g <= first + 48; ++g) {
    BenchOptions o;
    o.faults.glitch_step_at = g;
    const auto r = run_direct(l.variant, line, o);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].mismatches, 0u) << "glitch at " << g;  // a pin fault, not an HLS/RTL difference
    ASSERT_GE(r[0].timing_violation_count, 1u) << "glitch at " << g << " went unnoticed";
    const TimingViolation& v = r[0].timing_violations.front();
    // A pulse cut short is known when it falls: up to L = 4 clocks later.
    EXPECT_TRUE(v.cycle >= g && v.cycle <= g + 4)
        << "glitch at " << g << ", reported at " << v.cycle;
    EXPECT_EQ(v.axis, 0);
    EXPECT_LT(v.measured, v.required);
    scoreboard_hits += r[0].scoreboard_error_count > 0;
  }
  // Glitches on a low cycle add a step: the scoreboard must see those.
  EXPECT_GT(scoreboard_hits, 20u);
  RecordProperty("first_step_cycle", std::to_string(first));
}

// Direct and SystemC modes are the same machine: one stimulus, identical
// cycle counts, steps, end points and errors. This test elaborates SystemC.
TEST(DdaLineLockstep, SystemcMatchesDirectOnRandomStreams) {
  std::vector<std::unique_ptr<DdaLineBench>> benches;
  std::vector<std::pair<std::string, DdaLineBench*>> sc;
  std::vector<std::vector<CaseResult>> direct;
  for (const std::string& v : dda_line_variants()) {
    const DdaLineLimits l = dda_line_limits(v);
    std::vector<DdaLineCase> cases = paper_lines_004(l, default_settings(l));
    cases.push_back(random_case(l, 100, 42));
    direct.push_back(run_direct(v, cases));
    BenchOptions o;
    o.mode = "systemc";
    benches.push_back(std::make_unique<DdaLineBench>(l, cases, o));
    sc.emplace_back(v, benches.back().get());
  }
  run_dda_line_systemc(sc);
  for (size_t k = 0; k < benches.size(); ++k) {
    const auto& a = direct[k];
    const auto& b = benches[k]->results();
    expect_all_pass(b);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].cycles, b[i].cycles) << a[i].variant << " " << a[i].name;
      EXPECT_EQ(a[i].steps, b[i].steps) << a[i].name;
      EXPECT_EQ(a[i].end_position, b[i].end_position) << a[i].name;
      EXPECT_DOUBLE_EQ(a[i].max_path_error_steps, b[i].max_path_error_steps) << a[i].name;
    }
  }
}

// The SystemC-mode comparator fails too, at the injected cycle.
TEST(DdaLineLockstep, SystemcInjectedMismatchIsReported) {
  const DdaLineLimits l = dda_line_limits(dda_line_variant_for_axes(4));
  BenchOptions o;
  o.mode = "systemc";
  o.faults.flip_hls_step_at = 123;
  DdaLineBench bench(l, {random_case(l, 20, 5)}, o);
  run_dda_line_systemc({{l.variant, &bench}});
  const auto& r = bench.results();
  ASSERT_EQ(r.size(), 1u);
  ASSERT_TRUE(r[0].first_mismatch.has_value());
  EXPECT_EQ(r[0].first_mismatch->cycle, 123u);
  EXPECT_EQ(r[0].first_mismatch->signal, "step_o[0]");
  EXPECT_FALSE(r[0].passed());
}

}  // namespace
}  // namespace hwinterp::tb

// dda_line in lockstep beyond the conformance suite: the paper's lines and
// the model's errors, the normaliser's power-of-two edges, exact step and
// feed rates, glitch sweeps, job files and the random generator's coverage.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "lockstep_support.h"
#include "run_hwinterp.h"

namespace hwinterp::tb::testing {
namespace {

using A = cores::dda_line::Adapter;
using N2 = Variant<A, dda_line_n2_cfg>;
using N4 = Variant<A, dda_line_n4_cfg>;
using Kind = Item<A>::Kind;

RunSettings<A> settings(const VariantSpec& l, StepdirTiming t, bool half = false) {
  RunSettings<A> s = default_settings<A>(l);
  s.timing = t;
  s.setup.half_preload = half;
  return s;
}

A::Command delta(std::initializer_list<int64_t> d) {
  A::Command c;
  std::copy(d.begin(), d.end(), c.delta.begin());
  return c;
}

// The eight lines of 004 with plain and half preload: exact ends, and the
// errors the model predicts (every move was compared with it as well).
TEST(DdaLine, PaperLines) {
  const VariantSpec l = N2::spec();
  RunSettings<A> plain = default_settings<A>(l), half = plain;
  half.setup.half_preload = true;
  const auto p = run_direct<N2>(paper_lines_004<A>(l, plain));
  const auto h = run_direct<N2>(paper_lines_004<A>(l, half));
  expect_all_pass(p);
  expect_all_pass(h);
  ASSERT_EQ(p.size(), 8u);
  for (size_t i = 0; i < 8; ++i) {
    EXPECT_LT(p[i].max_path_error_steps, 1.0);
    EXPECT_LE(h[i].max_path_error_steps, std::sqrt(0.5) + 1e-12);
    EXPECT_LE(h[i].max_path_error_steps, p[i].max_path_error_steps + 1e-12);
  }
  // Line 1 (0,0)->(20,40): 20 and 40 steps.
  EXPECT_EQ(p[0].steps, (std::vector<uint64_t>{20, 40}));
}

// Deltas on both sides of every power of two up to 2^12 (the normaliser's
// edge cases: bit length, shift), with both signs and both preloads.
template <class V>
void power_of_two_edges() {
  const VariantSpec l = V::spec();
  const int top = std::min(12, l.param("ACC_W") - 2);
  for (const bool half : {false, true}) {
    Case<A> c;
    c.name = "edges";
    c.start.assign(static_cast<size_t>(l.axes), 0);
    c.settings = settings(l, {1, 1, 1, 1}, half);
    for (int k = 0; k <= top; ++k)
      for (const int64_t m : {(int64_t{1} << k) - 1, int64_t{1} << k, (int64_t{1} << k) + 1}) {
        A::Command cmd;
        cmd.delta[0] = m;
        cmd.delta[1] = -(m / 2 + 1);
        if (l.axes > 2) cmd.delta[static_cast<size_t>(l.axes) - 1] = k % 2 ? -m : m;
        c.items.push_back(command_item<A>(cmd));
        // Back again, so the position stays inside small POS_W variants.
        for (auto& d : cmd.delta) d = -d;
        c.items.push_back(command_item<A>(cmd));
      }
    expect_all_pass(run_direct<V>({c}));
  }
}
TEST(DdaLine, PowerOfTwoEdgeDeltas) {
  power_of_two_edges<N2>();
  power_of_two_edges<N4>();
  power_of_two_edges<Variant<A, dda_line_edge_cfg>>();
}

// Full feed with hostmot2 timing L = 3, S = 2 on a single-axis move: the
// output stage never lets a step out early (monitors) and never holds one
// longer than the timing needs: one step every L + S = 5 clocks.
TEST(DdaLine, StepRateIsExactlyTheTimingLimit) {
  const VariantSpec l = N2::spec();
  for (int64_t n : {16, 100}) {
    const auto r =
        run_direct<N2>({delta_line_case<A>(l, "x", {0, 0}, {n, 0}, settings(l, {3, 2, 1, 1}))});
    expect_all_pass(r);
    // Reset (2) + take (2) + n pulses 5 clocks apart + the last pulse's tail.
    const uint64_t overhead = r[0].cycles - static_cast<uint64_t>(5 * n);
    EXPECT_LE(overhead, 10u) << n;
    EXPECT_GE(r[0].cycles, static_cast<uint64_t>(5 * (n - 1) + 3)) << n;
  }
}

// A feed word of 1/4 of full: the engine iterates on one clock in four.
// Two line lengths (64 and 128 iterations) cancel the fixed overhead.
TEST(DdaLine, FeedWordSetsTheIterationRate) {
  const VariantSpec l = N2::spec();
  RunSettings<A> full = settings(l, {1, 1, 1, 1}), quarter = full;
  quarter.feed = l.full_feed() / 4;
  auto cycles = [&](const RunSettings<A>& s, int64_t dy) {
    // (0,0)->(0,dy) with dy a power of two: 2 dy iterations, a step every other one.
    const auto r = run_direct<N2>({delta_line_case<A>(l, "y", {0, 0}, {0, dy}, s)});
    expect_all_pass(r);
    return static_cast<double>(r[0].cycles);
  };
  EXPECT_NEAR(cycles(full, 64) - cycles(full, 32), 64, 1);
  EXPECT_NEAR(cycles(quarter, 64) - cycles(quarter, 32), 256, 4);
}

// The monitors can fail. With L = S = 4 on (0,0)->(8,0) the pulses are 8
// clocks apart; a one-cycle glitch on step_o[0] anywhere among them either
// makes a pulse shorter than L or a gap shorter than S, so every glitch must
// be reported, between the glitched cycle and L clocks later (a short pulse
// is known when it falls). The run goes on (the DUTs still agree), and the
// scoreboard sees the extra or missing moves too.
TEST(DdaLine, EveryInjectedGlitchIsATimingViolation) {
  const VariantSpec l = N2::spec();
  const std::vector<Case<A>> line = {
      delta_line_case<A>(l, "x", {0, 0}, {8, 0}, settings(l, {4, 4, 1, 1}))};
  const auto clean = run_direct<N2>(line);
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
    const auto r = run_direct<N2>(line, o);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].mismatches, 0u) << "glitch at " << g;  // a pin fault, not an HLS/RTL difference
    ASSERT_GE(r[0].timing_violation_count, 1u) << "glitch at " << g << " went unnoticed";
    const TimingViolation& v = r[0].timing_violations.front();
    EXPECT_TRUE(v.cycle >= g && v.cycle <= g + 4)
        << "glitch at " << g << ", reported at " << v.cycle;
    EXPECT_EQ(v.axis, 0);
    EXPECT_LT(v.measured, v.required);
    scoreboard_hits += r[0].scoreboard_error_count > 0;
  }
  // Glitches on a low cycle add a step: the scoreboard must see those.
  EXPECT_GT(scoreboard_hits, 20u);
}

// Abort on the paper's line 1 at every clock of its run: always on the
// model's path, idle within the bound, and a second command afterwards ends
// exactly where the first would have.
TEST(DdaLine, AbortAtEveryCycleOfALineLandsOnItsPath) {
  const VariantSpec l = N2::spec();
  Case<A> c = delta_line_case<A>(l, "abort", {0, 0}, {20, 40}, settings(l, {2, 1, 1, 1}));
  const auto clean = run_direct<N2>({c});
  expect_all_pass(clean);
  const std::vector<models::DdaMove> path =
      models::dda_line_moves({0, 0}, {20, 40}, models::Preload::kZero);
  for (uint64_t at = 3; at < clean[0].cycles - 2; ++at) {
    BenchOptions o;
    o.abort_at = at;
    const auto r = run_direct<N2>({c}, o);
    ASSERT_EQ(r[0].aborts.size(), 1u) << at;
    const AbortRecord& a = r[0].aborts[0];
    EXPECT_TRUE(r[0].passed()) << at << ": " << r[0].to_json().dump();
    bool on_path = a.position == models::LatticePoint{0, 0};
    for (const auto& m : path) on_path = on_path || m.point == a.position;
    EXPECT_TRUE(on_path) << at;
    ASSERT_GE(a.idle_after_clocks, 0) << at;
    EXPECT_LE(a.idle_after_clocks, 1) << at;  // step_len 2: a pulse in flight ends a clock later
  }
}

// Every dda_line variant through the registry in both modes, the way
// `hwinterp regress` runs them: the paper lines (plain and half preload) and
// the two random streams.
TEST(DdaLine, RegistryRunsEveryVariantInBothModes) { regression_both_modes("dda_line", 3, 19); }

std::string write_job(const std::string& name, const std::string& text) {
  const std::string path = hwinterp::testing::scratch_dir("job") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(DdaLineStimulus, JobFileCasesCommandsAndSettings) {
  const VariantSpec l = N2::spec();
  const auto cases = parse_job<A>(write_job("ok.job",
                                            "# two cases\n"
                                            "case first\n"
                                            "start 10 10\n"
                                            "preload half\n"
                                            "step_len 5\n"
                                            "line 40 20      # absolute\n"
                                            "move -5 0\n"
                                            "feed 0.5\n"
                                            "dir_hold 7\n"
                                            "gap 3\n"
                                            "drain\n"
                                            "abort\n"
                                            "case second\n"
                                            "move 0 -4\n"),
                                  l, default_settings<A>(l));
  ASSERT_EQ(cases.size(), 2u);
  const Case<A>& a = cases[0];
  EXPECT_EQ(a.name, "first");
  EXPECT_EQ(a.start, (models::LatticePoint{10, 10}));
  EXPECT_TRUE(a.settings.setup.half_preload);
  EXPECT_EQ(a.settings.timing.step_len, 5u);
  ASSERT_EQ(a.items.size(), 6u);
  EXPECT_EQ(a.items[0].cmd.delta[0], 30);
  EXPECT_EQ(a.items[0].cmd.delta[1], 10);
  EXPECT_EQ(a.items[1].cmd.delta[0], -5);
  // Consecutive setting lines make one settings item, carrying what was in force.
  EXPECT_EQ(a.items[2].kind, Kind::kSettings);
  EXPECT_EQ(a.items[2].settings.feed, l.full_feed() / 2);
  EXPECT_EQ(a.items[2].settings.timing.dir_hold, 7u);
  EXPECT_EQ(a.items[2].settings.timing.step_len, 5u);
  EXPECT_TRUE(a.items[2].settings.setup.half_preload);
  EXPECT_EQ(a.items[3].kind, Kind::kGap);
  EXPECT_EQ(a.items[4].kind, Kind::kDrain);
  EXPECT_EQ(a.items[5].kind, Kind::kAbort);
  EXPECT_EQ(cases[1].items.at(0).cmd.delta[1], -4);
}

void expect_job_error(const std::string& text, const std::string& named) {
  const VariantSpec l = N2::spec();
  try {
    const auto cases = parse_job<A>(write_job("bad.job", text), l, default_settings<A>(l));
    for (const auto& c : cases) validate_case(c, l);
    FAIL() << "accepted: " << text;
  } catch (const cli::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
  }
}

TEST(DdaLineStimulus, BadJobLinesNameFileLineAndValue) {
  expect_job_error("move 1 2\nfrobnicate 3\n", "bad.job:2: unknown directive 'frobnicate'");
  expect_job_error("move 1 2x\n", "bad.job:1: '2x' is not an integer");
  expect_job_error("move 1 2 3\n", "3 coordinates given");
  expect_job_error("step_len 70000\nmove 1 1\n", "step_len 70000 is outside");
  expect_job_error("preload full\nmove 1 1\n", "'full'");
  expect_job_error("feed 1.5\nmove 1 1\n", "feed fraction 1.5");
  expect_job_error("move 1 1\nstart 3 3\n", "'start' must come before");
  expect_job_error("# nothing\n", "has no commands");
  expect_job_error("abort 3\nmove 1 1\n", "'abort' takes no value");
  expect_job_error("move 3000000000 0\n", "delta 3000000000 on axis 0 is wider than the 32-bit");
  // pos_o counts from reset: two moves that add up past 2^31 - 1 overflow it.
  expect_job_error("move 2147483647 0\nmove 1 0\n", "past the 32-bit position counter");
  // Feed hold is allowed, but nothing may wait under it, nor may a case end in it.
  expect_job_error("feed 0\nmove 1 1\n", "under feed 0 (hold) would wait forever");
  expect_job_error("move 1 1\nfeed 0\ndrain\n", "drain under feed 0");
  expect_job_error("move 1 1\nfeed 0\ngap 5\n", "ends in feed hold");
}

TEST(DdaLineStimulus, RandomCaseIsReproducibleAndCoversTheSpace) {
  const VariantSpec l = N4::spec();
  const Case<A> a = random_case<A>(l, 400, 99), b = random_case<A>(l, 400, 99),
                c = random_case<A>(l, 400, 100);
  auto same = [](const Case<A>& x, const Case<A>& y) {
    if (x.items.size() != y.items.size()) return false;
    for (size_t i = 0; i < x.items.size(); ++i)
      if (x.items[i].kind != y.items[i].kind || x.items[i].cmd.delta != y.items[i].cmd.delta)
        return false;
    return true;
  };
  EXPECT_TRUE(same(a, b));
  EXPECT_FALSE(same(a, c));
  // The extras change nothing of the plain stream's commands.
  const Case<A> d = random_case<A>(l, 400, 99, {true, true});
  std::vector<A::Command> plain_cmds, extra_cmds;
  for (const auto& it : a.items)
    if (it.kind == Kind::kCommand) plain_cmds.push_back(it.cmd);
  int aborts = 0, holds = 0;
  for (const auto& it : d.items) {
    if (it.kind == Kind::kCommand) extra_cmds.push_back(it.cmd);
    aborts += it.kind == Kind::kAbort;
    holds += it.kind == Kind::kSettings && it.settings.feed == 0;
  }
  ASSERT_EQ(plain_cmds.size(), extra_cmds.size());
  for (size_t i = 0; i < plain_cmds.size(); ++i)
    EXPECT_EQ(plain_cmds[i].delta, extra_cmds[i].delta);
  EXPECT_GT(aborts, 10);
  EXPECT_GT(holds, 10);
  // All 16 sign patterns of the four axes, zero moves, single-axis moves,
  // reversals, gaps, drains and setting changes all occur.
  std::vector<bool> octant(16, false);
  int zero = 0, single = 0, reversal = 0, gaps = 0, drains = 0, changes = 0;
  A::Command prev;
  for (const auto& it : a.items) {
    gaps += it.kind == Kind::kGap;
    drains += it.kind == Kind::kDrain;
    changes += it.kind == Kind::kSettings;
    if (it.kind != Kind::kCommand) continue;
    int nonzero = 0, pattern = 0;
    bool reversed = true;
    for (size_t i = 0; i < 4; ++i) {
      nonzero += it.cmd.delta[i] != 0;
      pattern |= (it.cmd.delta[i] < 0) << i;
      reversed = reversed && it.cmd.delta[i] == -prev.delta[i];
    }
    if (nonzero == 4) octant[static_cast<size_t>(pattern)] = true;
    zero += nonzero == 0;
    single += nonzero == 1;
    reversal += reversed && nonzero > 0;
    prev = it.cmd;
  }
  for (size_t p = 0; p < 16; ++p) EXPECT_TRUE(octant[p]) << "sign pattern " << p;
  EXPECT_GT(zero, 0);
  EXPECT_GT(single, 0);
  EXPECT_GT(reversal, 0);
  EXPECT_GT(gaps, 0);
  EXPECT_GT(drains, 0);
  EXPECT_GT(changes, 0);
  EXPECT_NO_THROW(validate_case(a, l));
  EXPECT_NO_THROW(validate_case(d, l));
}

}  // namespace
}  // namespace hwinterp::tb::testing

// fixed_ratio in lockstep (HLS vs RTL, both vs models::FixedRatioMoveStream),
// direct mode, on every variant: the paper's lines, completion in M ticks
// with its exact clock count, the divider's gap statement, the widest
// deltas, near-diagonal long lines, aborts, job files and the random
// generator's coverage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lockstep_support.h"
#include "models/fixed_ratio.h"
#include "models/fixed_ratio_model.h"
#include "models/paper_data_001_003_004.h"
#include "run_hwinterp.h"
#include "tb/base/json.h"

namespace hwinterp::tb::testing {
namespace {

using A = cores::fixed_ratio::Adapter;
using models::LatticePoint;
using Kind = Item<A>::Kind;
namespace pd = models::paper;

template <class Cfg>
class FixedRatioLockstep : public ::testing::Test {};
using Variants = ::testing::Types<fixed_ratio_n2_cfg, fixed_ratio_n4_cfg, fixed_ratio_edge_cfg>;
TYPED_TEST_SUITE(FixedRatioLockstep, Variants);

template <class Cfg>
using V = Variant<A, Cfg>;

A::Command delta(std::initializer_list<int64_t> d) {
  A::Command c;
  std::copy(d.begin(), d.end(), c.delta.begin());
  return c;
}

Case<A> commands_case(const VariantSpec& l, const std::vector<A::Command>& cmds,
                      const RunSettings<A>& s) {
  Case<A> c;
  c.name = "commands";
  c.start.assign(static_cast<size_t>(l.axes), 0);
  c.settings = s;
  for (const auto& cmd : cmds) c.items.push_back(command_item<A>(cmd));
  return c;
}

// Case cycles of the moves (rising steps) of a run, from its path CSV.
struct TimedMove {
  uint64_t cycle;
  LatticePoint point;
};
template <class Cfg>
std::vector<TimedMove> timed_moves(const Case<A>& c, std::vector<CaseResult>* results = nullptr) {
  const std::string path =
      hwinterp::testing::scratch_dir("fixed_ratio_path") + "/" + Cfg::kVariant + ".csv";
  BenchOptions o;
  o.path_csv = path;
  const auto r = run_direct<V<Cfg>>({c}, o);
  expect_all_pass(r, 1);
  if (results) *results = r;
  std::vector<TimedMove> out;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string w; std::getline(ss, w, ',');) f.push_back(w);
    if (f.size() < 3 || f[2] != "move") continue;
    TimedMove m{std::stoull(f[1]), {}};
    for (int i = 0; i < Cfg::AXES; ++i)
      m.point.push_back(std::stoll(f[3 + static_cast<size_t>(i)]));
    out.push_back(m);
  }
  return out;
}

// The eight lines of 004 at full feed and the default timing: exact counts
// and ends, every move the model's, and the paper's exact-frequency points
// (the hardware is that generator tick for tick on these lines), so the
// error is within the paper's (|dx| + |dy|) / (2 L) as well as the core's
// own bound, below 1.
TYPED_TEST(FixedRatioLockstep, PaperLines) {
  const VariantSpec l = spec_of<A, TypeParam>();
  BenchOptions o;
  o.record_path = true;
  const auto r = run_direct<V<TypeParam>>(paper_lines_004<A>(l, default_settings<A>(l)), o);
  expect_all_pass(r, 8);
  for (size_t k = 0; k < 8; ++k) {
    const auto& p = pd::kRatioLines[k];
    const LatticePoint a{p[0], p[1]}, b{p[2], p[3]};
    LatticePoint end(static_cast<size_t>(l.axes), 0), start = end;
    end[0] = b[0];
    end[1] = b[1];
    start[0] = a[0];
    start[1] = a[1];
    EXPECT_EQ(r[k].end_position, end) << k;
    EXPECT_EQ(r[k].steps[0], static_cast<uint64_t>(std::llabs(b[0] - a[0]))) << k;
    EXPECT_EQ(r[k].steps[1], static_cast<uint64_t>(std::llabs(b[1] - a[1]))) << k;
    const double bound =
        models::fixed_ratio_hw_bound({b[0] - a[0], b[1] - a[1]}, l.param("FRAC_W")).value;
    EXPECT_DOUBLE_EQ(r[k].error_bound, bound) << k;
    EXPECT_LE(r[k].max_path_error_steps, bound + 1e-12) << k;
    EXPECT_LE(r[k].max_path_error_steps, models::fixed_ratio_error_bound(a, b) + 1e-12) << k;
    EXPECT_LT(r[k].max_path_error_steps, 1.0) << k;
    // The exact-frequency generator's points at the tick instants: the
    // major axis steps at times k - 1/2, so the points after its steps.
    const models::StepPath exact = models::fixed_ratio_line(a, b);
    std::vector<LatticePoint> want{start};
    for (size_t m = 0; m < exact.moves.size(); ++m) {
      const bool tick_ends = m + 1 == exact.moves.size() ||
                             std::ceil(exact.moves[m + 1].time) != std::ceil(exact.moves[m].time);
      if (!tick_ends) continue;
      LatticePoint q = start;
      q[0] = exact.moves[m].point[0];
      q[1] = exact.moves[m].point[1];
      want.push_back(q);
    }
    EXPECT_EQ(r[k].visited, want) << k;
  }
}

// Completion in exactly M engine ticks. At feed 1/2 with step/dir timing
// 1,1,1,1 nothing stalls (a tick every second clock, an axis may pulse every
// second clock), so the clock count is exact: 2 reset edges, the edge that
// takes the command, FRAC_W + 2 divider edges, the edge that loads the
// engine, ticks on the 2nd, 4th, ... edge after it (the feed phase starts at
// 0), the edge the last pulse falls (busy_o low), 2 tail edges:
//     cycles = 2 + 1 + (FRAC_W + 2) + 1 + 2 M + 1 + 2 = 2 M + FRAC_W + 9,
// the first step on case cycle FRAC_W + 8, the major axis stepping on every
// tick: M moves 2 clocks apart.
TYPED_TEST(FixedRatioLockstep, CompletionInMTicksExactClocks) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const uint64_t frac_w = static_cast<uint64_t>(l.param("FRAC_W"));
  for (const auto& cmd : {delta({20, 40}), delta({-37, 12, 5}), delta({7, -7, 3, -2}),
                          delta({1, 0}), delta({0, -1})}) {
    std::vector<int64_t> d(cmd.delta.begin(), cmd.delta.begin() + l.axes);
    const uint64_t m = models::fixed_ratio_major(d);
    std::vector<CaseResult> r;
    const auto moves =
        timed_moves<TypeParam>(commands_case(l, {cmd}, half_feed_unit_timing<A>(l)), &r);
    EXPECT_EQ(r[0].cycles, 2 * m + frac_w + 9) << m;
    EXPECT_EQ(r[0].first_step_cycle, frac_w + 8) << m;
    ASSERT_EQ(moves.size(), m);
    for (size_t k = 0; k < moves.size(); ++k)
      EXPECT_EQ(moves[k].cycle, frac_w + 8 + 2 * k) << "move " << k;
  }
  // A zero-length command: take, no division, load, one tick (done_o,
  // busy_o falls), 2 tail edges.
  std::vector<CaseResult> r;
  EXPECT_TRUE(
      timed_moves<TypeParam>(commands_case(l, {A::Command{}}, half_feed_unit_timing<A>(l)), &r)
          .empty());
  EXPECT_EQ(r[0].cycles, 2u + 1 + 1 + 2 + 2);
}

// The divider's gap. A command's rate words are ready after the FRAC_W + 2
// divider clocks that follow the clock that took it, so it is loaded at the
// earliest FRAC_W + 3 clocks after its take and FRAC_W + 4 clocks after the
// previous command's load (the buffer frees on that load and takes the next
// command one clock later). Back-to-back commands run without a gap when
// each runs at least FRAC_W + 4 clocks from its load to its last tick;
// otherwise the engine idles FRAC_W + 4 minus that many clocks. At feed 1/2
// without stalls a command runs 2 max(M, 1) clocks:
//   - a long line followed by a short one: no gap, the major axis keeps
//     stepping every 2 clocks across the boundary (also for the shortest
//     line that is long enough, M = ceil((FRAC_W + 4) / 2));
//   - short lines back to back: one every FRAC_W + 4 clocks, the engine
//     idle FRAC_W + 4 - 2 M clocks between two.
TYPED_TEST(FixedRatioLockstep, DividerGapOnlyAfterShortLines) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const uint64_t frac_w = static_cast<uint64_t>(l.param("FRAC_W"));
  const int64_t no_gap = static_cast<int64_t>((frac_w + 4 + 1) / 2);  // 2 M >= FRAC_W + 4
  // Same directions throughout: no direction change may delay a step.
  for (const int64_t long_m : {int64_t{40}, no_gap}) {
    const auto moves = timed_moves<TypeParam>(
        commands_case(l, {delta({long_m, 1}), delta({1, 1})}, half_feed_unit_timing<A>(l)));
    ASSERT_EQ(moves.size(), static_cast<size_t>(long_m + 1));
    for (size_t k = 1; k < moves.size(); ++k)
      EXPECT_EQ(moves[k].cycle - moves[k - 1].cycle, 2u) << long_m << " move " << k;
  }
  for (const int64_t m : {no_gap - 1, int64_t{3}, int64_t{1}}) {
    // Five short lines: each starts FRAC_W + 4 clocks after the one before.
    const auto moves = timed_moves<TypeParam>(
        commands_case(l, std::vector<A::Command>(5, delta({m, 1})), half_feed_unit_timing<A>(l)));
    ASSERT_EQ(moves.size(), static_cast<size_t>(5 * m));
    for (size_t k = 1; k < moves.size(); ++k) {
      const uint64_t step = moves[k].cycle - moves[k - 1].cycle;
      if (k % static_cast<size_t>(m) == 0)  // first move of a line: after the gap
        EXPECT_EQ(step, 2 + (frac_w + 4 - 2 * static_cast<uint64_t>(m))) << m << " move " << k;
      else
        EXPECT_EQ(step, 2u) << m << " move " << k;
    }
  }
}

// Abort in the middle of a line, at every clock of its run (the division,
// the load, the ticks): always on the model's path, no step on the abort
// edge, busy_o down within the bound; a second command afterwards runs
// exactly from there.
TYPED_TEST(FixedRatioLockstep, AbortAtEveryCycleLandsOnThePath) {
  const VariantSpec l = spec_of<A, TypeParam>();
  RunSettings<A> s = default_settings<A>(l);
  s.timing = {2, 1, 1, 1};
  Case<A> c = commands_case(l, {delta({20, -13})}, s);
  Item<A> drain;
  drain.kind = Kind::kDrain;
  c.items.push_back(drain);
  c.items.push_back(command_item<A>(delta({-4, 9})));
  const auto clean = run_direct<V<TypeParam>>({c});
  expect_all_pass(clean);
  std::vector<int64_t> d(static_cast<size_t>(l.axes), 0);
  d[0] = 20;
  d[1] = -13;
  const auto path = models::fixed_ratio_hw_moves(LatticePoint(d.size(), 0), d, l.param("FRAC_W"));
  size_t mid_line = 0;
  for (uint64_t at = 3; at < clean[0].cycles - 2; ++at) {
    BenchOptions o;
    o.abort_at = at;
    const auto r = run_direct<V<TypeParam>>({c}, o);
    expect_all_pass(r, 1);  // the second command ran exactly from where the first stopped
    ASSERT_EQ(r[0].aborts.size(), 1u) << at;
    const AbortRecord& a = r[0].aborts[0];
    EXPECT_TRUE(a.on_reference_path) << at;
    for (const auto& m : path) mid_line += m.point == a.position && m.point != path.back().point;
    ASSERT_GE(a.idle_after_clocks, 0) << at;
    EXPECT_LE(a.idle_after_clocks, 1) << at;  // step_len 2: a pulse in flight ends a clock later
  }
  EXPECT_GT(mid_line, 20u);
}

// The narrow variant's widest deltas, 2^(ACC_W-1) - 1 and -2^(ACC_W-1), on
// every axis and against each other, back and forth inside POS_W: exact
// counts and ends, every move the model's, within the bound.
TEST(FixedRatioEdge, LongestAcceptedDeltas) {
  using Cfg = fixed_ratio_edge_cfg;
  const VariantSpec l = spec_of<A, Cfg>();
  const int64_t max = (int64_t{1} << (Cfg::ACC_W - 1)) - 1, min = -max - 1;
  const std::vector<A::Command> cmds = {
      delta({max, 0, 0}),          delta({min, 0, 0}),         delta({0, max, min}),
      delta({1, min, max}),        delta({max, max, max}),     delta({min, min, min}),
      delta({max, max - 1, 1}),    delta({min, -max + 1, -1}), delta({max, -max, max - 2}),
      delta({min, max, -max + 2}), delta({max, 1, -max}),      delta({min, -1, max})};
  RunSettings<A> s = default_settings<A>(l);
  const auto r = run_direct<V<Cfg>>({commands_case(l, cmds, s)});
  expect_all_pass(r, 1);
  LatticePoint end(3, 0);
  for (const auto& c : cmds)
    for (size_t i = 0; i < 3; ++i) end[i] += c.delta[i];
  EXPECT_EQ(r[0].end_position, end);
  EXPECT_LT(r[0].max_path_error_steps, 1.0);
  EXPECT_LE(r[0].error_bound,
            models::fixed_ratio_hw_worst_bound(3, Cfg::ACC_W, Cfg::FRAC_W) + 1e-12);
  RecordProperty("max_error", std::to_string(r[0].max_path_error_steps));
}

// Near-diagonal lines of 10^6 steps, where a rate word's rounding would
// drift first: exact ends, every move the model's, within the bound.
TEST(FixedRatioWide, NearDiagonalLongLines) {
  {
    using Cfg = fixed_ratio_n2_cfg;
    const VariantSpec l = spec_of<A, Cfg>();
    const int64_t n = 1000000;
    const auto r = run_direct<V<Cfg>>(
        {commands_case(l, {delta({n, n - 1}), delta({-n + 2, -n})}, half_feed_unit_timing<A>(l))});
    expect_all_pass(r, 1);
    EXPECT_EQ(r[0].end_position, (LatticePoint{2, -1}));
    EXPECT_EQ(r[0].steps, (std::vector<uint64_t>{2 * n - 2, 2 * n - 1}));
    EXPECT_LE(r[0].max_path_error_steps, r[0].error_bound + 1e-12);
    EXPECT_LT(r[0].max_path_error_steps, 1.0);
  }
  {
    using Cfg = fixed_ratio_n4_cfg;
    const VariantSpec l = spec_of<A, Cfg>();
    const int64_t n = 1000000;
    const auto r = run_direct<V<Cfg>>(
        {commands_case(l, {delta({n, -(n - 1), n - 3, -(n - 2)})}, half_feed_unit_timing<A>(l))});
    expect_all_pass(r, 1);
    EXPECT_EQ(r[0].end_position, (LatticePoint{n, -(n - 1), n - 3, -(n - 2)}));
    EXPECT_LT(r[0].max_path_error_steps, 1.0);
  }
}

// Every fixed_ratio variant through the registry in both modes, the way
// `hwinterp regress` runs them: the paper lines and the two random streams.
TEST(FixedRatio, RegistryRunsEveryVariantInBothModes) {
  regression_both_modes("fixed_ratio", 3, 11);
}

// The command line on the narrow variant: a random stream's input frames
// (hwinterp cosim --dump-frames) replayed into the RTL under Icarus Verilog
// give the same clocks, done pulses, steps and positions: Icarus reads the
// RTL as it is.
TEST(FixedRatio, DumpedFramesReplayInIcarus) {
  using hwinterp::testing::run_hwinterp;
  using hwinterp::testing::slurp;
  const std::string dir = hwinterp::testing::scratch_dir("fixed_ratio_frames");
  const auto r = run_hwinterp(
      "cosim --core fixed_ratio --variant fixed_ratio_edge --random 40 --seed 4 --mode direct "
      "--dump-frames " +
      dir + "/f.hex --json " + dir + "/f.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const std::string rtl = std::string(HWINTERP_SOURCE_DIR) + "/rtl/";
  std::string files;
  std::ifstream list(rtl + "fixed_ratio.f");
  for (std::string name; std::getline(list, name);) files += " " + rtl + name;
  const std::string cmd = "cd " + dir + " && iverilog -g2012 -s replay_tb -o replay f.hex.sv" +
                          files + " && vvp -n replay +frames=f.hex > replay.log";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const Json j = Json::parse(slurp(dir + "/f.json"));
  const std::string log = slurp(dir + "/replay.log");
  EXPECT_NE(log.find("cycles " + std::to_string(j["cycles"].get<int>()) + "\n"), std::string::npos)
      << log;
  EXPECT_NE(log.find("done_pulses " + std::to_string(j["commands"].get<int>()) + "\n"),
            std::string::npos)
      << log;
  for (int i = 0; i < 3; ++i)
    EXPECT_NE(log.find("axis " + std::to_string(i) + " steps " +
                       std::to_string(j["steps"][i].get<int>()) + " pos " +
                       std::to_string(j["end_position"][i].get<int>()) + "\n"),
              std::string::npos)
        << log;
}

std::string write_job(const std::string& name, const std::string& text) {
  const std::string path = hwinterp::testing::scratch_dir("fixed_ratio_job") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(FixedRatioStimulus, JobFileLinesAndMoves) {
  using Cfg = fixed_ratio_n2_cfg;
  const VariantSpec l = spec_of<A, Cfg>();
  const auto cases = parse_job<A>(write_job("ok.job",
                                            "case one\n"
                                            "start 10 10\n"
                                            "step_len 1\n"
                                            "line 40 20\n"
                                            "move -5 0\n"
                                            "feed 0.5\n"
                                            "gap 3\n"
                                            "move 0 0\n"
                                            "drain\n"
                                            "line -7 3\n"),
                                  l, default_settings<A>(l));
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].items[0].cmd.delta[0], 30);
  EXPECT_EQ(cases[0].items[0].cmd.delta[1], 10);
  const auto r = run_direct<V<Cfg>>(cases);
  expect_all_pass(r, 1);
  EXPECT_EQ(r[0].end_position, (LatticePoint{-7, 3}));
  EXPECT_EQ(r[0].commands, 4u);
  try {
    auto bad = parse_job<A>(write_job("bad.job", "move 3000000000 0\n"), l, default_settings<A>(l));
    validate_case(bad[0], l);
    FAIL() << "accepted a delta wider than ACC_W";
  } catch (const cli::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("delta 3000000000 on axis 0 is wider than the 32-bit"),
              std::string::npos)
        << e.what();
  }
}

// A 300-command stream covers what the random generator promises: zero
// lengths, axis-parallel lines, reversals, every sign pattern, near-diagonal
// long lines (10^5 to 10^6 steps on the 32-bit variants; up to the delta
// width on the narrow one, where the widest deltas appear too), all inside
// the position window.
template <class Cfg>
void random_coverage() {
  const VariantSpec l = spec_of<A, Cfg>();
  const int axes = l.axes;
  const int64_t max = (int64_t{1} << (Cfg::ACC_W - 1)) - 1;
  const bool narrow = l.pos_w < 20;
  const Case<A> c = random_case<A>(l, 300, 3);
  EXPECT_NO_THROW(validate_case(c, l));
  int zero = 0, parallel = 0, reversal = 0, near_diag = 0, widest = 0;
  std::vector<bool> pattern(size_t{1} << axes, false);
  A::Command prev;
  for (const auto& it : c.items) {
    if (it.kind != Kind::kCommand) continue;
    const auto& d = it.cmd.delta;
    int nonzero = 0, signs = 0;
    int64_t big = 0, small = INT64_MAX;
    bool reversed = true;
    for (int i = 0; i < axes; ++i) {
      const size_t a = static_cast<size_t>(i);
      nonzero += d[a] != 0;
      signs |= (d[a] < 0) << i;
      big = std::max<int64_t>(big, std::llabs(d[a]));
      small = std::min<int64_t>(small, std::llabs(d[a]));
      reversed = reversed && d[a] == -prev.delta[a];
      widest += d[a] == max || d[a] == -max - 1;
    }
    zero += nonzero == 0;
    parallel += nonzero == 1;
    reversal += reversed && nonzero > 0;
    if (nonzero == axes) pattern[static_cast<size_t>(signs)] = true;
    if (big - small <= 4 && big >= (narrow ? max / 2 : 100000)) ++near_diag;
    prev = it.cmd;
  }
  EXPECT_GT(zero, 0);
  EXPECT_GT(parallel, 10);
  EXPECT_GT(reversal, 10);
  EXPECT_GE(near_diag, 2);
  if (narrow) EXPECT_GT(widest, 2);
  for (size_t p = 0; p < pattern.size(); ++p) EXPECT_TRUE(pattern[p]) << "sign pattern " << p;
}
TEST(FixedRatioStimulus, RandomStreamsCoverTheSpace) {
  random_coverage<fixed_ratio_n2_cfg>();
  random_coverage<fixed_ratio_n4_cfg>();
  random_coverage<fixed_ratio_edge_cfg>();
}

}  // namespace
}  // namespace hwinterp::tb::testing

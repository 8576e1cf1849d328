// ppc_line in lockstep (HLS vs RTL, both vs models::PpcLineStream), direct
// mode, on every variant: the papers' figures from the hardware, random
// streams, vertical and zero-length commands, aborts, widths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "lockstep_support.h"
#include "models/paper_data_001_003_004.h"
#include "models/ppc.h"
#include "tb/cores/ppc_line/ppc_line_adapter.h"

namespace hwinterp::tb {
namespace {

using A = cores::ppc_line::Adapter;
using models::LatticePoint;
namespace pd = models::paper;

template <class Cfg>
class PpcLineLockstep : public ::testing::Test {};
using Variants = ::testing::Types<ppc_line_a32_cfg, ppc_line_edge_cfg>;
TYPED_TEST_SUITE(PpcLineLockstep, Variants);

Case<A> line(const VariantSpec& l, const LatticePoint& a, const LatticePoint& b,
             const RunSettings<A>& s) {
  return delta_line_case<A>(l, "line", a, b, s);
}

// 003's Fig. 4 from the hardware: (0,0)->(4,3) in 7 steps through the paper's points.
TYPED_TEST(PpcLineLockstep, PaperLine003) {
  const VariantSpec l = spec_of<A, TypeParam>();
  BenchOptions o;
  o.record_path = true;
  const auto r = testing::run_direct<testing::Variant<A, TypeParam>>(
      {line(l, {0, 0}, {4, 3}, default_settings<A>(l))}, o);
  testing::expect_all_pass(r, 1);
  ASSERT_EQ(r[0].visited.size(), pd::kPpcLine.size() + 1);
  EXPECT_EQ(r[0].visited[0], (LatticePoint{0, 0}));
  for (size_t k = 0; k < pd::kPpcLine.size(); ++k)
    EXPECT_EQ(r[0].visited[k + 1], (LatticePoint{pd::kPpcLine[k][0], pd::kPpcLine[k][1]})) << k;
}

// 004's line 1, (0,0)->(20,40): 60 operations, one step each. At feed 1/2
// with step/dir timing 1,1,1,1 the step stage never stalls (an axis may
// pulse every second clock, and an operation comes every second clock), so
// the clock count is exact: 2 reset edges, the edge that takes the command,
// the edge that loads the engine, operations on the 2nd, 4th, ... clock after
// it (the feed phase starts at 0: 6, 8, ..., 124), the edge the last pulse
// falls (busy_o low), 2 tail edges: 2 + 1 + 1 + 2 * 60 + 1 + 2 = 127.
TYPED_TEST(PpcLineLockstep, Line1SixtyOperationsExactClocks) {
  const VariantSpec l = spec_of<A, TypeParam>();
  BenchOptions o;
  o.record_path = true;
  const auto r = testing::run_direct<testing::Variant<A, TypeParam>>(
      {line(l, {0, 0}, {20, 40}, testing::half_feed_unit_timing<A>(l))}, o);
  testing::expect_all_pass(r, 1);
  EXPECT_EQ(r[0].cycles, 127u);
  EXPECT_EQ(r[0].first_step_cycle, 6u);
  ASSERT_EQ(r[0].visited.size(), 61u);  // the start and one point per operation
  EXPECT_EQ(r[0].steps, (std::vector<uint64_t>{20, 40}));
  const models::StepPath model = models::ppc_line({0, 0}, {20, 40});
  ASSERT_EQ(model.operations, static_cast<uint64_t>(pd::kPpcOperationsLine1));
  for (size_t k = 0; k < model.moves.size(); ++k)
    EXPECT_EQ(r[0].visited[k + 1], model.moves[k].point) << k;
  EXPECT_LT(r[0].max_path_error_steps, 1.0);
}

// The paper lines (004's eight, 003's one) at full feed and default timing,
// back to back in one case (positions chained) as well as one case each.
TYPED_TEST(PpcLineLockstep, PaperLines) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const auto cases = A::paper_lines(l, default_settings<A>(l));
  const auto r = testing::run_direct<testing::Variant<A, TypeParam>>(cases);
  testing::expect_all_pass(r, 9);
  for (size_t k = 0; k < 8; ++k) {
    const auto& p = pd::kRatioLines[k];
    EXPECT_EQ(r[k].end_position, (LatticePoint{p[2], p[3]})) << k;
    EXPECT_EQ(r[k].steps[0] + r[k].steps[1],
              static_cast<uint64_t>(std::llabs(p[2] - p[0]) + std::llabs(p[3] - p[1])));
    EXPECT_LT(r[k].max_path_error_steps, 1.0);
  }
}

// Vertical and horizontal lines end exactly (the bare rule would step x
// first on a vertical one); zero-length commands take one operation and
// give their done_o (the scoreboard counts one per command); all back to
// back, at full feed.
TYPED_TEST(PpcLineLockstep, VerticalHorizontalAndZeroLength) {
  const VariantSpec l = spec_of<A, TypeParam>();
  Case<A> c;
  c.name = "axes";
  c.start = {0, 0};
  c.settings = default_settings<A>(l);
  c.settings.timing = {1, 1, 1, 1};
  const int64_t deltas[][2] = {{0, 7}, {0, 0}, {0, -9}, {5, 0}, {0, 0}, {0, 0}, {-6, 0}, {0, 2}};
  for (const auto& d : deltas) {
    A::Command cmd;
    cmd.delta[0] = d[0];
    cmd.delta[1] = d[1];
    c.items.push_back(command_item<A>(cmd));
  }
  BenchOptions o;
  o.record_path = true;
  const auto r = testing::run_direct<testing::Variant<A, TypeParam>>({c}, o);
  testing::expect_all_pass(r, 1);
  EXPECT_EQ(r[0].commands, 8u);
  EXPECT_EQ(r[0].end_position, (LatticePoint{-1, 0}));
  EXPECT_EQ(r[0].max_path_error_steps, 0.0);  // every point on its line
  // The first 7 moves are the vertical line's: x never moves.
  for (size_t k = 1; k <= 7; ++k) EXPECT_EQ(r[0].visited[k], (LatticePoint{0, int64_t(k)}));
}

// A zero-length command alone: taken, loaded, one engine operation with no
// step, done_o; busy falls right after it.
TYPED_TEST(PpcLineLockstep, ZeroLengthTakesOneOperation) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const auto r = testing::run_direct<testing::Variant<A, TypeParam>>(
      {line(l, {3, -2}, {3, -2}, default_settings<A>(l))});
  testing::expect_all_pass(r, 1);
  EXPECT_EQ(r[0].steps, (std::vector<uint64_t>{0, 0}));
  // 2 reset, take, load, the operation (done_o, busy_o falls), 2 tail.
  EXPECT_EQ(r[0].cycles, 7u);
}

// Abort in the middle of a line: no step on the abort edge, the position is
// a point of the reference path, busy_o falls within max(step_len, 1) - 1.
TYPED_TEST(PpcLineLockstep, AbortMidLineLandsOnReferencePath) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const models::StepPath model = models::ppc_line({0, 0}, {300, -200});
  const std::vector<LatticePoint> path = model.visited();
  for (uint64_t at : {40u, 333u, 1001u}) {
    BenchOptions o;
    o.abort_at = at;
    RunSettings<A> s = default_settings<A>(l);
    s.timing = {3, 2, 2, 2};
    const auto r =
        testing::run_direct<testing::Variant<A, TypeParam>>({line(l, {0, 0}, {300, -200}, s)}, o);
    testing::expect_all_pass(r, 1);
    ASSERT_EQ(r[0].aborts.size(), 1u) << at;
    const AbortRecord& a = r[0].aborts[0];
    EXPECT_TRUE(a.on_reference_path);
    EXPECT_NE(std::find(path.begin(), path.end(), a.position), path.end());
    EXPECT_NE(a.position, path.back());  // really mid-line
    EXPECT_NE(a.position, path.front());
    EXPECT_GE(a.idle_after_clocks, 0);
    EXPECT_LE(a.idle_after_clocks, 2);  // step_len 3: at most 2 clocks
  }
}

// The widths: the longest deltas a variant takes, both signs (the most
// negative delta's magnitude needs all ACC_W bits), aborted after a while.
TYPED_TEST(PpcLineLockstep, FullWidthDeltasAborted) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const int64_t max = (int64_t{1} << (l.param("ACC_W") - 1)) - 1;
  const int64_t pos = std::min(max, l.pos_max());
  for (const auto& [dx, dy] : std::vector<std::pair<int64_t, int64_t>>{
           {-pos - 1, 3}, {pos, -pos - 1}, {7, -pos - 1}, {-pos - 1, -pos + 5}}) {
    BenchOptions o;
    o.abort_at = 3000;
    const auto r = testing::run_direct<testing::Variant<A, TypeParam>>(
        {line(l, {0, 0}, {dx, dy}, default_settings<A>(l))}, o);
    testing::expect_all_pass(r, 1);
    EXPECT_GT(r[0].steps[0] + r[0].steps[1], 500u);
  }
}

// The lockstep comparison can fail: a flipped HLS step bit is caught on its cycle.
TYPED_TEST(PpcLineLockstep, InjectedMismatchIsCaught) {
  const VariantSpec l = spec_of<A, TypeParam>();
  BenchOptions o;
  o.faults.flip_hls_step_at = 20;
  const auto r = testing::run_direct<testing::Variant<A, TypeParam>>(
      {line(l, {0, 0}, {20, 40}, default_settings<A>(l))}, o);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].passed());
  ASSERT_TRUE(r[0].first_mismatch.has_value());
  EXPECT_EQ(r[0].first_mismatch->cycle, 20u);
  EXPECT_EQ(r[0].first_mismatch->signal, "step_o[0]");
}

TEST(PpcLineJob, LineAndMoveDirectives) {
  const VariantSpec l = spec_of<A, ppc_line_edge_cfg>();
  const std::string path = ::testing::TempDir() + "/ppc_line.job";
  std::ofstream(path) << "case j\nstart 2 -3\nline 10 -3\nmove 0 -7\nfeed 0.5\nline 0 0\n";
  const auto cases = parse_job<A>(path, l, default_settings<A>(l));
  ASSERT_EQ(cases.size(), 1u);
  ASSERT_EQ(command_count(cases[0]), 3u);
  const auto r = testing::run_direct<testing::Variant<A, ppc_line_edge_cfg>>(cases);
  testing::expect_all_pass(r, 1);
  EXPECT_EQ(r[0].steps, (std::vector<uint64_t>{8 + 10, 7 + 10}));
  EXPECT_THROW(A::validate({{1024, 0}}, {0, 0}, l, "x"), cli::UsageError);
  EXPECT_NO_THROW(A::validate({{-1024, 1023}}, {0, 0}, l, "x"));
}

TEST(PpcLineRegistry, RegressionBothModes) { testing::regression_both_modes("ppc_line", 2, 12); }

}  // namespace
}  // namespace hwinterp::tb

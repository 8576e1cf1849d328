// log_stepper in lockstep (HLS vs RTL, both vs the bit-exact model and the
// double-precision model): the paper's curve in both modes (152 points,
// every point within 1 step of the double model), seeded random parameter
// sets, the coarse engine's documented clocks per cycle, the feed at which
// the fine stage waits, and the command line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "lockstep_support.h"
#include "run_hwinterp.h"
#include "tb/base/json.h"

namespace hwinterp::tb::testing {
namespace {

using A = cores::log_stepper::Adapter;

template <class Cfg>
class LogStepperLockstep : public ::testing::Test {};
using Variants = ::testing::Types<log_stepper_n4_cfg, log_stepper_edge_cfg, log_stepper_dsp_cfg>;
TYPED_TEST_SUITE(LogStepperLockstep, Variants);

template <class Cfg>
using V = Variant<A, Cfg>;

const CoreCheck* find_check(const CaseResult& r, const std::string& name) {
  for (const auto& c : r.core_checks)
    if (c.name == name) return &c;
  return nullptr;
}

// The paper's case: 152 coarse points, each within 1 step of the double
// model on every axis (exactly on it at the n4 variant's 1000 steps/mm and
// per degree), the exact end point.
TYPED_TEST(LogStepperLockstep, PaperCurveMakesThePapersPoints) {
  const VariantSpec l = V<TypeParam>::spec();
  const auto r = run_direct<V<TypeParam>>(A::paper_cases(l, default_settings<A>(l)));
  expect_all_pass(r, 1);
  const CoreCheck* points = find_check(r[0], "point_error_steps");
  ASSERT_NE(points, nullptr);
  EXPECT_EQ(points->count, 152u);
  EXPECT_LE(points->max, 1.0);
  const CoreCheck* erpa = find_check(r[0], "erpa_rad");
  ASSERT_NE(erpa, nullptr);
  EXPECT_GT(erpa->max, 0.0);
  this->RecordProperty("max_point_error_steps", std::to_string(points->max));
  this->RecordProperty("cycles", std::to_string(r[0].cycles));
}

// Seeded random parameter sets (tb/cores/log_stepper: short curves over the
// accepted ranges, random feeds and timing), back to back.
TYPED_TEST(LogStepperLockstep, RandomParameterSetsRunClean) {
  const VariantSpec l = V<TypeParam>::spec();
  uint64_t points = 0;
  for (const uint64_t seed : {1u, 2u}) {
    const auto r = run_direct<V<TypeParam>>({random_case<A>(l, 25, seed)});
    expect_all_pass(r, 1);
    const CoreCheck* c = find_check(r[0], "point_error_steps");
    ASSERT_NE(c, nullptr);
    EXPECT_LE(c->max, 1.0);
    points += c->count;
  }
  EXPECT_GT(points, 200u);
}

// The HLS core alone, driven at full feed with 1-clock timing, one curve.
// Returns the clock of every coarse point's emission and the underrun count.
template <class Cfg>
struct Emissions {
  std::vector<uint64_t> clocks;
  uint64_t underrun = 0, done_clock = 0;
};
template <class Cfg>
Emissions<Cfg> emissions(const A::Command& cmd, uint64_t feed) {
  using Core = hls::LogStepper<Cfg>;
  Core core;
  typename Core::Inputs in;
  in.rst_n = true;
  in.feed = feed;
  in.timing = {1, 1, 1, 1};
  in.cmd.b = cmd.words.b;
  in.cmd.ab = cmd.words.ab;
  in.cmd.dl = cmd.words.dl;
  in.cmd.x_end = cmd.words.x_end;
  for (int i = 0; i < 4; ++i) in.cmd.k[i] = cmd.words.k[static_cast<size_t>(i)];
  in.cmd_valid = true;
  Emissions<Cfg> e;
  uint64_t seen = 0;
  for (uint64_t clock = 1; clock < 50'000'000 && !e.done_clock; ++clock) {
    core.tick(in);
    in.cmd_valid = false;
    if (core.points_emitted() != seen) {
      seen = core.points_emitted();
      e.clocks.push_back(clock);
    }
    if (core.outputs().done) e.done_clock = clock;
  }
  e.underrun = core.underrun_clocks();
  return e;
}

// With segments far shorter than a point's computation the coarse engine
// sets the pace: one odd+even cycle every 25 M + 1 + max(1, SQRT_CYC + 2 -
// 2 M) + max(1, RECIP_CYC + 1 - 2 M) + max(1, RECIP_CYC - 1 - 7 M) clocks,
// M = MUL_CYC + 1 (rtl/log_stepper.sv), and the fine stage waits.
TYPED_TEST(LogStepperLockstep, CoarseEngineTakesTheDocumentedClocksPerCycle) {
  using Core = hls::LogStepper<TypeParam>;
  const VariantSpec l = V<TypeParam>::spec();
  models::LogStepScale tiny;
  tiny.x_per_mm = tiny.y_per_mm = tiny.z_per_mm = 10;
  tiny.a_per_deg = 2;
  models::LogCurveParams p;
  p.x_end_mm = 6;
  const A::Command cmd = A::make_command(p, tiny, l, "test");
  const auto e = emissions<TypeParam>(cmd, l.full_feed());
  ASSERT_EQ(e.clocks.size(), cmd.points);
  constexpr int64_t m = Core::MUL_CYC + 1;
  const auto wait = [](int64_t c) { return static_cast<uint64_t>(std::max<int64_t>(1, c)); };
  const uint64_t cycle = 25 * m + 1 + wait(Core::SQRT_CYC + 2 - 2 * m) +
                         wait(Core::RECIP_CYC + 1 - 2 * m) + wait(Core::RECIP_CYC - 1 - 7 * m);
  for (size_t k = 3; k < e.clocks.size(); k += 2)
    EXPECT_EQ(e.clocks[k] - e.clocks[k - 2], cycle) << "point " << k + 1;
  EXPECT_GT(e.underrun, 0u) << "1-step segments at full feed outrun the coarse engine";
  this->RecordProperty("clocks_per_cycle", std::to_string(cycle));
}

// The paper's curve at the n4 variant's 1000 steps/mm and per degree: every
// segment has a delta of 128 steps or more (2^8 DDA iterations and more), so
// at full feed the fine stage never waits on the coarse engine (about 100
// clocks a point).
TEST(LogStepperFeed, FineStageNeverWaitsOnThePaperCurveAtFullFeed) {
  const VariantSpec l = V<log_stepper_n4_cfg>::spec();
  const A::Command cmd = A::make_command({}, {}, l, "test");
  const auto e = emissions<log_stepper_n4_cfg>(cmd, l.full_feed());
  EXPECT_EQ(e.clocks.size(), 152u);
  EXPECT_EQ(e.underrun, 0u);
  EXPECT_GT(e.done_clock, 0u);
}

// Both lockstep modes give the same machine on the paper's curve and a
// random stream. Elaborates SystemC (own process).
TEST(LogStepperSystemc, PaperCurveAndRandomStreamMatchDirect) {
  using Vn = V<log_stepper_n4_cfg>;
  const VariantSpec l = Vn::spec();
  std::vector<Case<A>> cases = A::paper_cases(l, default_settings<A>(l));
  cases.push_back(random_case<A>(l, 8, 3));
  const auto direct = run_direct<Vn>(cases);
  const auto sc = run_systemc<Vn>(cases);
  expect_all_pass(sc, 2);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(direct[i].cycles, sc[i].cycles);
    EXPECT_EQ(direct[i].steps, sc[i].steps);
    EXPECT_EQ(find_check(sc[i], "point_error_steps")->count,
              find_check(direct[i], "point_error_steps")->count);
  }
  EXPECT_EQ(find_check(sc[0], "point_error_steps")->count, 152u);
}

TEST(LogStepperCli, CurveOptionsAndJson) {
  using hwinterp::testing::run_hwinterp;
  const std::string dir = hwinterp::testing::scratch_dir("log_stepper_cli");
  const auto r = run_hwinterp(
      "cosim --core log_stepper --d1 10 --spiral 30 --cone 5 --rake 8 --dl 0.5 --x-end 10 "
      "--steps-per-mm 500 --steps-per-deg 200 --mode direct --json " +
      dir + "/c.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const Json j = Json::parse(hwinterp::testing::slurp(dir + "/c.json"));
  EXPECT_TRUE(j["passed"].get<bool>());
  EXPECT_GT(j["points"].get<uint64_t>(), 10u);
  EXPECT_LE(j["max_point_error_steps"].get<double>(), 1.0);
  EXPECT_TRUE(j.contains("max_erpa_rad"));
  // Bad curves exit 2 and name the value.
  const auto bad = run_hwinterp("cosim --core log_stepper --d1 -3 --mode direct");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("D1 -3"), std::string::npos) << bad.err;
  const auto wide = run_hwinterp("cosim --core log_stepper --d1 2 --cone 40 --dl 1 --mode direct");
  EXPECT_EQ(wide.code, 2);
  EXPECT_NE(wide.err.find("3/8"), std::string::npos) << wide.err;
}

}  // namespace
}  // namespace hwinterp::tb::testing

// motion_top in lockstep (HLS vs RTL, both vs models::MotionMoveStream),
// direct mode, on every variant: what the shared conformance suite does not
// aim at: a slaved axis that steps on every arc operation (|delta| = N, the
// DDA axis's largest increment), the feed word each move carries, lines and
// arcs in every plane chained in one stream, and the job directives.
#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "lockstep_support.h"
#include "models/motion_top_model.h"
#include "tb/cores/motion_top/motion_top_adapter.h"

namespace hwinterp::tb {
namespace {

using A = cores::motion_top::Adapter;
using models::LatticePoint;

template <class Cfg>
class MotionTopLockstep : public ::testing::Test {};
using Variants = ::testing::Types<motion_top_n3_cfg, motion_top_n4_cfg, motion_top_edge_cfg>;
TYPED_TEST_SUITE(MotionTopLockstep, Variants);

template <class Cfg>
std::vector<CaseResult> run_job(const std::string& job, BenchOptions o = {}) {
  const VariantSpec l = spec_of<A, Cfg>();
  std::istringstream in(job);
  auto cases = parse_job<A>(in, "job", l, default_settings<A>(l));
  return testing::run_direct<testing::Variant<A, Cfg>>(std::move(cases), o);
}

// An arc in each plane whose slaved axis moves one step on every operation:
// dc = 2^ACC_W (rtl/dda_axis.sv), the value a W-bit register would lose.
TYPED_TEST(MotionTopLockstep, SlavedAxisSteppingEveryOperation) {
  const VariantSpec l = spec_of<A, TypeParam>();
  std::string job = "case every_op\n";
  int64_t z = 0, x = 0, y = 0;
  // XY: centre (5, 0) from the origin, a half circle to (10, 0) ccw, Z slaved.
  {
    const uint64_t n = models::motion_arc_ops({5, 0}, {10, 0}, true);
    z += static_cast<int64_t>(n);
    x += 10;
    job += "arc xy 5 0 10 0 ccw " + std::to_string(z) + (l.axes > 3 ? " 0" : "") + "\n";
  }
  // ZX (engine x = Z, y = X): a quarter circle, Y slaved downwards.
  {
    const uint64_t n = models::motion_arc_ops({0, -4}, {4, -4}, false);
    y -= static_cast<int64_t>(n);
    job += "arc zx " + std::to_string(z) + " " + std::to_string(x - 4) + " " +
           std::to_string(z + 4) + " " + std::to_string(x - 4) + " cw " + std::to_string(y) +
           (l.axes > 3 ? " 0" : "") + "\n";
    z += 4;
    x -= 4;
  }
  const auto r = run_job<TypeParam>(job);
  testing::expect_all_pass(r, 1);
  EXPECT_EQ(r[0].end_position[0], x);
  EXPECT_EQ(r[0].end_position[1], y);
  EXPECT_EQ(r[0].end_position[2], z);
}

// Each move runs at its own feed word: the same line at a quarter and at an
// eighth of full feed takes four and eight times its operations in clocks.
TYPED_TEST(MotionTopLockstep, EachMoveRunsAtItsFeedWord) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const uint64_t full = l.full_feed();
  const std::string zeros = l.axes > 3 ? " 0 0" : " 0";
  const std::string job =
      "case feeds\nstep_len 1\nstep_space 1\ndir_setup 1\ndir_hold 1\nmovefeed " +
      std::to_string(full / 4) + "\nmove 100" + zeros + " 0\nmovefeed " + std::to_string(full / 8) +
      "\nmove 100" + zeros + " 0\n";
  BenchOptions o;
  o.record_path = true;
  const auto r = run_job<TypeParam>(job, o);
  testing::expect_all_pass(r, 1);
  ASSERT_EQ(r[0].done_cycles.size(), 2u);
  // 100 steps: 2^7 = 128 DDA iterations.
  const double first = static_cast<double>(r[0].done_cycles[0]);
  const double second = static_cast<double>(r[0].done_cycles[1] - r[0].done_cycles[0]);
  EXPECT_NEAR(second, 8.0 * 128, 8.0) << "first done at " << first;
  EXPECT_LE(first, 4.0 * 128 + 16);
  EXPECT_GE(first, 4.0 * 128 - 8);
}

// Lines and arcs in all three planes, helices, back and forth, in one
// stream; the model's end point and path checks hold throughout.
TYPED_TEST(MotionTopLockstep, LinesAndArcsInEveryPlaneChain) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const std::string a = l.axes > 3 ? " 7" : "";
  const std::string job =
      "case chain\n"
      "line 20 0 0" +
      std::string(l.axes > 3 ? " 0" : "") +
      "\n"
      "arc xy 20 10 30 10 ccw 5" +
      a +
      "\n"  // quarter, Z (and A) slaved
      "arc xy 20 10 20 20 ccw 5" +
      a +
      "\n"  // quarter, no slaved motion
      "arc zx 5 15 5 10 cw 20" +
      a +
      "\n"  // half circle in ZX
      "arc yz 20 0 20 -5 ccw 0" +
      a +
      "\n"  // half circle in YZ, X slaved back
      "line 0 0 0" +
      std::string(l.axes > 3 ? " 0" : "") +
      "\n"
      "arc xy 3 4 0 0 cw 0" +
      std::string(l.axes > 3 ? " 0" : "") + "\n";  // full circle
  const auto r = run_job<TypeParam>(job);
  testing::expect_all_pass(r, 1);
  EXPECT_EQ(r[0].end_position, LatticePoint(static_cast<size_t>(l.axes), 0));
}

// Job directives name the bad value and exit through UsageError.
TYPED_TEST(MotionTopLockstep, BadJobLinesAreUsageErrors) {
  const VariantSpec l = spec_of<A, TypeParam>();
  auto parse = [&](const std::string& text) {
    std::istringstream in("case bad\n" + text);
    return parse_job<A>(in, "job", l, default_settings<A>(l));
  };
  EXPECT_THROW(parse("arc xq 1 1 2 2 cw\n"), cli::UsageError);
  EXPECT_THROW(parse("arc xy 5 0 10 0 left\n"), cli::UsageError);
  EXPECT_THROW(parse("movefeed 0\n"), cli::UsageError);
  EXPECT_THROW(parse("arc xy 5 0 10 0 ccw 1 2 3 4 5\n"), cli::UsageError);
  try {
    parse("arc xy 5 0 10 0 left\n");
  } catch (const cli::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("left"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hwinterp::tb

// ppc_arc in lockstep (HLS vs RTL, both vs models::PpcArcStream, rule M),
// direct mode, on every variant: the paper arc from the hardware, full
// circles, off-circle ends, degenerate commands, random streams, aborts,
// the widths, the random generator's coverage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "lockstep_support.h"
#include "models/paper_data_001_003_004.h"
#include "models/ppc.h"
#include "tb/cores/ppc_arc/ppc_arc_adapter.h"

namespace hwinterp::tb {
namespace {

using A = cores::ppc_arc::Adapter;
using models::LatticePoint;
namespace pd = models::paper;

template <class Cfg>
class PpcArcLockstep : public ::testing::Test {};
using Variants = ::testing::Types<ppc_arc_c24_cfg, ppc_arc_edge_cfg>;
TYPED_TEST_SUITE(PpcArcLockstep, Variants);

struct Arc {
  LatticePoint c, s, e;
  bool ccw;
};

Case<A> arc_case(const VariantSpec& l, const Arc& a, const RunSettings<A>& s) {
  return A::arc_case(l, "arc", a.c, a.s, a.e, a.ccw, s);
}

// The model's visited points (start first), from the stream (no storage limit).
std::vector<LatticePoint> model_points(const Arc& a) {
  std::vector<LatticePoint> out{a.s};
  models::PpcArcStream stream(a.c, a.s, a.e, a.ccw);
  for (models::StepMove m; stream.next(m);) out.push_back(m.point);
  return out;
}

// Runs the arcs one case each and checks every one against the model's path.
template <class Cfg>
std::vector<CaseResult> run_arcs(const std::vector<Arc>& arcs, const RunSettings<A>& s) {
  const VariantSpec l = spec_of<A, Cfg>();
  std::vector<Case<A>> cases;
  for (const auto& a : arcs) cases.push_back(arc_case(l, a, s));
  BenchOptions o;
  o.record_path = true;
  const auto r = testing::run_direct<testing::Variant<A, Cfg>>(cases, o);
  testing::expect_all_pass(r, arcs.size());
  for (size_t k = 0; k < r.size(); ++k) {
    EXPECT_EQ(r[k].visited, model_points(arcs[k])) << k << ": " << testing::describe(r[k]);
    EXPECT_EQ(r[k].end_position, arcs[k].e) << k;
  }
  return r;
}

// 003's Fig. 6 from the hardware: (4,0)->(0,4) CCW around (0,0), 8 steps
// through the paper's points, radial error 1 at (3,0).
TYPED_TEST(PpcArcLockstep, PaperArc003) {
  const VariantSpec l = spec_of<A, TypeParam>();
  BenchOptions o;
  o.record_path = true;
  const auto r = testing::run_direct<testing::Variant<A, TypeParam>>(
      A::paper_arcs(l, default_settings<A>(l)), o);
  testing::expect_all_pass(r, 1);
  ASSERT_EQ(r[0].visited.size(), pd::kPpcArc.size() + 1);
  for (size_t k = 0; k < pd::kPpcArc.size(); ++k)
    EXPECT_EQ(r[0].visited[k + 1], (LatticePoint{pd::kPpcArc[k][0], pd::kPpcArc[k][1]})) << k;
  EXPECT_DOUBLE_EQ(r[0].max_path_error_steps, 1.0);
  EXPECT_DOUBLE_EQ(r[0].error_bound, 1.0);
}

// The paper arc's 8 operations at feed 1/2, timing 1,1,1,1 (no stall): 2
// reset, take, the engine's copy of the command (rtl/ppc_arc_engine.sv,
// "Taking a command"), load, operations at clocks 7, 9, ..., 21 (the last one
// lands on the end and is the command's last: no closing line), the pulse
// falls, 2 tail edges: 2 + 1 + 1 + 1 + 2 * 8 + 1 + 2 = 24.
TYPED_TEST(PpcArcLockstep, PaperArcExactClocks) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const auto r = testing::run_direct<testing::Variant<A, TypeParam>>(
      {arc_case(l, {{0, 0}, {4, 0}, {0, 4}, true}, testing::half_feed_unit_timing<A>(l))});
  testing::expect_all_pass(r, 1);
  EXPECT_EQ(r[0].cycles, 24u);
}

// Full circles (end == start): 8R steps on R = 5, on- and off-axis starts,
// both directions, at full feed with direction reversals at every quadrant.
TYPED_TEST(PpcArcLockstep, FullCircles) {
  std::vector<Arc> arcs;
  for (const bool ccw : {true, false})
    for (const LatticePoint& s : {LatticePoint{5, 0}, LatticePoint{3, 4}, LatticePoint{0, -5}})
      arcs.push_back({{0, 0}, s, s, ccw});
  arcs.push_back({{-7, 3}, {-7, 13}, {-7, 13}, true});  // centre off the origin
  const VariantSpec l = spec_of<A, TypeParam>();
  const auto r = run_arcs<TypeParam>(arcs, default_settings<A>(l));
  for (size_t k = 0; k + 1 < r.size(); ++k) {
    EXPECT_EQ(r[k].visited.size(), 41u) << k;
    EXPECT_EQ(r[k].steps, (std::vector<uint64_t>{20, 20})) << k;
  }
}

// Ends off the circle through the start (outside, inside, behind: a full lap
// first, mixed: a short way back, far off), both directions: the hardware
// follows rule M move by move and ends exactly on the end, within the bound.
TYPED_TEST(PpcArcLockstep, OffCircleEnds) {
  const std::vector<Arc> arcs = {
      {{0, 0}, {4, 0}, {0, 5}, true},      {{0, 0}, {4, 0}, {0, 3}, true},
      {{0, 0}, {5, 0}, {6, 0}, true},      {{0, 0}, {5, 0}, {6, 1}, true},
      {{0, 0}, {10, 0}, {1, 14}, true},    {{2, -3}, {12, -3}, {-7, -10}, false},
      {{0, 0}, {-8, 0}, {-4, -7}, false},  {{0, 0}, {30, 1}, {-21, -22}, false},
      {{0, 0}, {30, 1}, {-21, -22}, true}, {{5, 5}, {5, 25}, {27, 4}, false}};
  const VariantSpec l = spec_of<A, TypeParam>();
  const auto r = run_arcs<TypeParam>(arcs, default_settings<A>(l));
  int closing = 0;
  for (size_t k = 0; k < arcs.size(); ++k) {
    const models::StepPath p = models::ppc_arc(arcs[k].c, arcs[k].s, arcs[k].e, arcs[k].ccw);
    closing += p.operations != p.moves.size();
    EXPECT_GT(r[k].error_bound, 1.0) << k;  // off the circle: the bound grows with |re - rs|
  }
  // 6 of the 10 end on a closing line; the other ends lie on the PPC track
  // of the start's circle (within a step of it), where the arc phase lands.
  EXPECT_EQ(closing, 6);
  EXPECT_GT(r[2].visited.size(), 40u);  // behind on both axes: a full lap first
}

// Degenerate commands (start on the centre or one step from it, end on the
// centre): the closing line only; a zero-length one steps nothing.
TYPED_TEST(PpcArcLockstep, DegenerateCommands) {
  const std::vector<Arc> arcs = {{{0, 0}, {0, 0}, {5, -3}, true}, {{0, 0}, {1, 0}, {-4, 2}, false},
                                 {{3, 3}, {3, 2}, {3, 9}, true},  {{0, 0}, {7, 2}, {0, 0}, true},
                                 {{1, 1}, {1, 1}, {1, 1}, false}, {{0, 0}, {1, 0}, {1, 0}, true}};
  const VariantSpec l = spec_of<A, TypeParam>();
  const auto r = run_arcs<TypeParam>(arcs, default_settings<A>(l));
  EXPECT_EQ(r[4].steps, (std::vector<uint64_t>{0, 0}));
  EXPECT_EQ(r[5].steps, (std::vector<uint64_t>{0, 0}));
}

// The widths: the largest radius the command coordinates allow (both
// offsets at their limit), a long arc on it with the end pushed 2 steps off
// the circle, both directions; on the narrow variant the most negative
// offset and a full circle.
TYPED_TEST(PpcArcLockstep, LargestRadius) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const int64_t m = (int64_t{1} << (l.param("COORD_W") - 1)) - 1;
  const LatticePoint c{-m, -m};  // start at the origin: s = (m, m)
  const double r = std::hypot(double(m), double(m));
  std::vector<Arc> arcs;
  for (const bool ccw : {true, false}) {
    // ~4000 steps of arc at most; the end offset must fit COORD_W too.
    const double sweep = std::min(4000.0 / r, 0.6);
    const double a1 = M_PI / 4 + (ccw ? sweep : -sweep);
    const LatticePoint e{c[0] + std::llround((r + 2) * std::cos(a1)),
                         c[1] + std::llround((r + 2) * std::sin(a1))};
    arcs.push_back({c, {0, 0}, e, ccw});
  }
  if (m < 1000) {
    arcs.push_back({{-m - 1, m}, {0, 0}, {0, 0}, false});      // I = -2^(COORD_W-1): full circle
    arcs.push_back({{-m - 1, 0}, {0, 0}, {-m - 1, m}, true});  // end one step inside
  }
  const auto res = run_arcs<TypeParam>(arcs, default_settings<A>(l));
  for (const auto& x : res) EXPECT_GT(x.steps[0] + x.steps[1], 200u) << testing::describe(x);
}

// Abort in the middle of an arc (in the arc phase and in a closing line):
// no step on the abort edge, the position is a point of the reference path,
// busy_o falls within max(step_len, 1) - 1 clocks.
TYPED_TEST(PpcArcLockstep, AbortMidArcLandsOnReferencePath) {
  const VariantSpec l = spec_of<A, TypeParam>();
  RunSettings<A> s = default_settings<A>(l);
  s.timing = {3, 2, 2, 2};
  for (const Arc& a :
       {Arc{{0, 0}, {40, 0}, {40, 0}, true}, Arc{{0, 0}, {4, 0}, {-30, 25}, false}}) {
    const uint64_t n =
        testing::run_direct<testing::Variant<A, TypeParam>>({arc_case(l, a, s)})[0].cycles;
    for (uint64_t at : {n / 10, n / 2, n * 9 / 10}) {
      BenchOptions o;
      o.abort_at = at;
      const auto r = testing::run_direct<testing::Variant<A, TypeParam>>({arc_case(l, a, s)}, o);
      testing::expect_all_pass(r, 1);
      ASSERT_EQ(r[0].aborts.size(), 1u);
      const AbortRecord& rec = r[0].aborts[0];
      const auto path = model_points(a);
      EXPECT_TRUE(rec.on_reference_path);
      EXPECT_NE(std::find(path.begin() + 1, path.end() - 1, rec.position), path.end() - 1)
          << "abort at " << at << " left " << point_text(rec.position);
      EXPECT_GE(rec.idle_after_clocks, 0);
      EXPECT_LE(rec.idle_after_clocks, 2);
    }
  }
}

// The lockstep comparison can fail: a flipped HLS step bit is caught on its cycle.
TYPED_TEST(PpcArcLockstep, InjectedMismatchIsCaught) {
  const VariantSpec l = spec_of<A, TypeParam>();
  BenchOptions o;
  o.faults.flip_hls_step_at = 12;
  const auto r = testing::run_direct<testing::Variant<A, TypeParam>>(
      A::paper_arcs(l, default_settings<A>(l)), o);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].passed());
  ASSERT_TRUE(r[0].first_mismatch.has_value());
  EXPECT_EQ(r[0].first_mismatch->cycle, 12u);
}

// The random generator covers what the brief asks for, on both variants:
// quadrant crossings, full circles, ends on and off the circle, both
// directions, small and large radii, degenerate starts; and every command
// fits the widths.
TYPED_TEST(PpcArcLockstep, RandomCoverage) {
  const VariantSpec l = spec_of<A, TypeParam>();
  const Case<A> c = random_case<A>(l, 3000, 99);
  validate_case(c, l);
  int crossing = 0, full = 0, on = 0, off = 0, ccw = 0, cw = 0, large = 0, degenerate = 0;
  for (const auto& it : c.items) {
    if (it.kind != Item<A>::Kind::kCommand) continue;
    const A::Command& k = it.cmd;
    models::PpcArcStream s({k.center[0], k.center[1]}, {0, 0}, {k.end[0], k.end[1]}, k.ccw);
    const int64_t rs2 = k.center[0] * k.center[0] + k.center[1] * k.center[1];
    const int64_t ex = k.end[0] - k.center[0], ey = k.end[1] - k.center[1];
    degenerate += s.degenerate();
    if (s.degenerate()) continue;
    crossing += s.laps() > 0;
    full += k.end[0] == 0 && k.end[1] == 0;
    (ex * ex + ey * ey == rs2 ? on : off) += 1;
    (k.ccw ? ccw : cw) += 1;
    large += rs2 >= 200 * 200;
  }
  for (const auto& [k, v] : {std::pair<const char*, int>{"crossing", crossing},
                             {"full", full},
                             {"on", on},
                             {"off", off},
                             {"ccw", ccw},
                             {"cw", cw},
                             {"large", large},
                             {"degenerate", degenerate}})
    ::testing::Test::RecordProperty(k, v);
  EXPECT_GT(crossing, 600);
  EXPECT_GT(full, 50);
  EXPECT_GT(on, 300);
  EXPECT_GT(off, 600);
  EXPECT_GT(ccw, 600);
  EXPECT_GT(cw, 600);
  EXPECT_GT(large, 100);
  EXPECT_GT(degenerate, 50);
}

TEST(PpcArcValidate, RefusesWhatWouldOverflow) {
  const VariantSpec l = spec_of<A, ppc_arc_edge_cfg>();  // COORD_W 9, POS_W 13
  A::Command ok;
  ok.center = {-256, 255};
  ok.end = {0, 0};
  EXPECT_NO_THROW(A::validate(ok, {0, 0}, l, "x"));
  A::Command wide = ok;
  wide.center = {256, 0};
  try {
    A::validate(wide, {0, 0}, l, "x");
    ADD_FAILURE() << "no error";
  } catch (const cli::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("256"), std::string::npos) << e.what();
  }
  wide = ok;
  wide.end = {0, -257};
  EXPECT_THROW(A::validate(wide, {0, 0}, l, "x"), cli::UsageError);
  // The circle (centre 3900, radius 200) would pass the 13-bit counters
  // (4095) although start and end are inside.
  A::Command far;
  far.center = {200, 0};
  far.end = {200, 200};
  try {
    A::validate(far, {3700, 0}, l, "x");
    ADD_FAILURE() << "no error";
  } catch (const cli::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("position counter"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(A::validate(far, {3600, 0}, l, "x"));
}

TEST(PpcArcJob, ArcDirective) {
  const VariantSpec l = spec_of<A, ppc_arc_edge_cfg>();
  const std::string path = ::testing::TempDir() + "/ppc_arc.job";
  std::ofstream(path) << "case j\nstart 4 0\narc 0 0 0 4 ccw\narc 0 0 4 0 cw\narc 0 0 0 5 ccw\n";
  const auto cases = parse_job<A>(path, l, default_settings<A>(l));
  ASSERT_EQ(cases.size(), 1u);
  ASSERT_EQ(command_count(cases[0]), 3u);
  const auto r = testing::run_direct<testing::Variant<A, ppc_arc_edge_cfg>>(cases);
  testing::expect_all_pass(r, 1);
  EXPECT_EQ(r[0].end_position, (LatticePoint{0, 5}));
  std::ofstream(path) << "arc 0 0 0 4 left\n";
  EXPECT_THROW(parse_job<A>(path, l, default_settings<A>(l)), cli::UsageError);
}

TEST(PpcArcRegistry, RegressionBothModes) { testing::regression_both_modes("ppc_arc", 2, 6); }

}  // namespace
}  // namespace hwinterp::tb

// The motion compiler (tb/gcode/motion_compiler.h): every committed program,
// through both readers, ends on its rounded programmed end with identical
// command streams, each command runs on motion_top's model within its bound;
// the chord fallback, line pieces, arc pieces, feed words and machining time
// by hand; refusals; and a 100 000-move program in bounded memory.
#include "tb/gcode/motion_compiler.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

#include "gcode_test_util.h"
#include "models/common.h"
#include "models/motion_top_model.h"
#include "tb/gcode/contour.h"
#include "tb/gcode/program_file.h"

namespace hwinterp::gcode {
namespace {
using models::kPi;

using models::MotionCommand;
using models::MotionKind;

std::string data(const std::string& name, const char* ext) {
  return std::string(HWINTERP_GCODE_DATA) + "/" + name + ext;
}

// Everything one compilation made, per command with its move.
struct Compiled {
  std::vector<MotionCommand> commands;
  std::vector<CommandInfo> infos;
  std::vector<Move> moves;                    // the move of each command
  std::vector<std::array<double, 6>> starts;  // that move's programmed start
  std::vector<MoveReport> reports;
  CompileTotals totals;
  std::array<int64_t, 6> end{};
  bool ends_on_reports = true;  // the position at each report is the move's end_steps
};

Compiled compile(MoveSource& src, const Machine& machine, const MotionWidths& w, FeedMode mode,
                 const std::string& name, const CompilerOptions& options = {}) {
  Compiled out;
  MotionCompiler* self = nullptr;
  MotionCompiler c(
      src, machine, w, mode, name,
      [&](const MoveReport& r) {
        out.reports.push_back(r);
        if (self->position() != r.end_steps) out.ends_on_reports = false;
      },
      options);
  self = &c;
  MotionCommand cmd;
  while (c.next(cmd)) {
    out.commands.push_back(cmd);
    out.infos.push_back(c.info());
    out.moves.push_back(c.move());
    out.starts.push_back(c.move_start());
  }
  out.totals = c.totals();
  out.end = c.position();
  return out;
}

Compiled compile_text(const std::string& text, const Machine& machine = Machine{},
                      const MotionWidths& w = MotionWidths{}, FeedMode mode = FeedMode::kFull,
                      const CompilerOptions& options = {}) {
  std::istringstream in(text);
  NgcReader r(in, "t.ngc");
  return compile(r, machine, w, mode, "t.ngc", options);
}

// No cuts for the arc tolerance: one engine arc per arc (or per sweep
// piece).
CompilerOptions uncut() {
  CompilerOptions o;
  o.arc_tolerance_steps = std::numeric_limits<double>::infinity();
  return o;
}

std::array<int64_t, 6> rounded(const std::array<double, 6>& end, const Machine& m) {
  std::array<int64_t, 6> l{};
  for (size_t i = 0; i < 6; ++i)
    if (m.has_axis[i]) l[i] = std::llround(end[i] * static_cast<double>(m.steps_per_unit[i]));
  return l;
}

bool same(const MotionCommand& a, const MotionCommand& b) {
  return a.kind == b.kind && a.delta == b.delta && a.plane == b.plane && a.center == b.center &&
         a.end == b.end && a.ccw == b.ccw && a.ops == b.ops && a.feed == b.feed;
}

std::string text(const MotionCommand& c) {
  std::ostringstream s;
  s << (c.kind == MotionKind::kArc ? "arc" : "line") << " d(";
  for (size_t i = 0; i < 6; ++i) s << (i ? "," : "") << c.delta[i];
  s << ")";
  if (c.kind == MotionKind::kArc)
    s << " plane " << c.plane << " c(" << c.center[0] << "," << c.center[1] << ") e(" << c.end[0]
      << "," << c.end[1] << ") " << (c.ccw ? "ccw" : "cw") << " ops " << c.ops;
  s << " feed " << c.feed;
  return s.str();
}

// Runs every command on motion_top's model from where the last one ended:
// every visited point within the model's bound, every end where the
// compiler says; the contour error of every visited point against its move.
struct ModelRun {
  uint64_t points = 0;
  double worst_ratio = 0;  // model deviation / bound
  double contour_line_steps = 0, contour_arc_steps = 0, contour_chord_steps = 0;
  double contour_mm = 0;
};

ModelRun run_on_model(const Compiled& c, const Machine& machine, int axes, bool contour = true) {
  ModelRun r;
  models::LatticePoint at(static_cast<size_t>(axes), 0);
  models::MotionMove m;
  for (size_t k = 0; k < c.commands.size(); ++k) {
    const CommandInfo& info = c.infos[k];
    for (int i = 0; i < axes; ++i)
      EXPECT_EQ(at[static_cast<size_t>(i)], info.start[static_cast<size_t>(i)]);
    const ContourPath path(machine, c.starts[k], c.moves[k]);
    models::MotionMoveStream s(at, c.commands[k], axes);
    const models::MotionIdeal ideal(at, c.commands[k], axes);
    while (s.next(m)) {
      ++r.points;
      const double e = ideal.error(m.point, m.op);
      EXPECT_TRUE(models::within_bound(e, ideal.bound())) << text(c.commands[k]) << ": " << e;
      r.worst_ratio =
          std::max(r.worst_ratio, ideal.bound().value > 0 ? e / ideal.bound().value : 0);
      if (!contour) continue;
      std::array<int64_t, 6> p{};
      for (int i = 0; i < axes; ++i) p[static_cast<size_t>(i)] = m.point[static_cast<size_t>(i)];
      const ContourError ce = path.error(p);
      double& worst = info.chord                               ? r.contour_chord_steps
                      : c.commands[k].kind == MotionKind::kArc ? r.contour_arc_steps
                                                               : r.contour_line_steps;
      worst = std::max(worst, ce.steps);
      r.contour_mm = std::max(r.contour_mm, ce.mm);
    }
    const auto d = models::motion_displacement(c.commands[k]);
    for (int i = 0; i < axes; ++i) at[static_cast<size_t>(i)] += d[static_cast<size_t>(i)];
  }
  for (int i = 0; i < axes; ++i)
    EXPECT_EQ(at[static_cast<size_t>(i)], c.end[static_cast<size_t>(i)]);
  return r;
}

struct Program {
  const char* name;
};
void PrintTo(const Program& p, std::ostream* os) { *os << p.name; }
const Program kPrograms[] = {{"arcs"},        {"engraving"}, {"inch"},
                             {"incremental"}, {"modal"},     {"words"}};

class CompiledProgram : public ::testing::TestWithParam<Program> {};

// No accumulated rounding: the last lattice point is the last programmed end
// rounded, and so is every move's end; every command runs on the model.
TEST_P(CompiledProgram, EndsOnTheRoundedProgrammedEndAndRunsOnTheModel) {
  const Machine machine = load_machine(data("machine_default", ".json"));
  for (const bool canon : {false, true}) {
    SCOPED_TRACE(canon ? "canon" : "ngc");
    const std::string file = data(GetParam().name, canon ? ".canon" : ".ngc");
    const auto src = canon ? open_canon(file) : open_ngc(file);
    const Compiled c = compile(*src, machine, MotionWidths{}, FeedMode::kFull, file);
    ASSERT_FALSE(c.reports.empty());
    EXPECT_EQ(c.reports.size(), src->stats().moves());
    EXPECT_TRUE(c.ends_on_reports);
    // The last move's programmed end, rounded.
    Move last;
    {
      const auto again = canon ? open_canon(file) : open_ngc(file);
      for (Move m; again->next(m);) last = m;
    }
    EXPECT_EQ(c.end, rounded(last.end, machine));
    EXPECT_EQ(c.reports.back().end_steps, c.end);
    for (const auto& r : c.reports) {
      EXPECT_LE(r.arc_commands, r.commands);
      if (r.kind != MoveKind::kArc) {
        EXPECT_EQ(r.arc_commands, 0u);
      }
    }
    // The contour error on the ngc run (the canon run's commands are the
    // same: NgcAndCanonGiveIdenticalCommands).
    const ModelRun run = run_on_model(c, machine, 4, !canon);
    if (canon) continue;
    std::printf(
        "[ motion ] %s.ngc: %llu moves, %llu commands (%llu arcs, %llu arc pieces, %llu chords), "
        "%llu points, model deviation/bound %.3f, contour steps: lines %.3f arcs %.3f chords "
        "%.3f (%.4f mm)\n",
        GetParam().name, static_cast<unsigned long long>(c.totals.moves),
        static_cast<unsigned long long>(c.totals.commands),
        static_cast<unsigned long long>(c.totals.arc_commands),
        static_cast<unsigned long long>(c.totals.arc_pieces),
        static_cast<unsigned long long>(c.totals.chords),
        static_cast<unsigned long long>(run.points), run.worst_ratio, run.contour_line_steps,
        run.contour_arc_steps, run.contour_chord_steps, run.contour_mm);
    // Lines: rounding of both ends (<= 0.71 step each in a plane, 0.87 in
    // space) plus the DDA's normal error (< sqrt(3)). Arcs: rule M's 1 step,
    // rounding, the arc tolerance (1 step) and the slaved lag (1/2).
    EXPECT_LT(run.contour_line_steps, 3.0);
    EXPECT_LT(run.contour_arc_steps, 3.5);
  }
}

TEST_P(CompiledProgram, NgcAndCanonGiveIdenticalCommands) {
  const Machine machine = load_machine(data("machine_default", ".json"));
  for (const FeedMode mode : {FeedMode::kFull, FeedMode::kProgrammed}) {
    const auto ngc = open_ngc(data(GetParam().name, ".ngc"));
    const auto canon = open_canon(data(GetParam().name, ".canon"));
    const Compiled a = compile(*ngc, machine, MotionWidths{}, mode, "a.ngc");
    const Compiled b = compile(*canon, machine, MotionWidths{}, mode, "b.canon");
    ASSERT_EQ(a.commands.size(), b.commands.size());
    // Programmed mode too: rs274's 4 decimals move no lattice point and no
    // feed word of these programs.
    for (size_t k = 0; k < a.commands.size(); ++k) {
      const MotionCommand& x = a.commands[k];
      const MotionCommand& y = b.commands[k];
      ASSERT_TRUE(same(x, y)) << "command " << k << " (ngc line " << a.infos[k].line
                              << ", canon line " << b.infos[k].line << "):\n  ngc   " << text(x)
                              << "\n  canon " << text(y);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Data, CompiledProgram, ::testing::ValuesIn(kPrograms),
                         [](const auto& info) { return std::string(info.param.name); });

// --- arcs: the engine, pieces, chords -----------------------------------------------

TEST(MotionCompiler, ArcOnTheEngineWithAHelixAxisSlaved) {
  // Quarter circle of 10 mm at 1000 steps/mm from (10, 0), CCW, Z down 1 mm.
  const std::string prog = "G0 X10 Y0\nG3 X0 Y10 I-10 J0 Z-1 F600\nM2\n";
  const Compiled c = compile_text(prog, Machine{}, MotionWidths{}, FeedMode::kFull, uncut());
  ASSERT_EQ(c.commands.size(), 2u);
  const MotionCommand& a = c.commands[1];
  EXPECT_EQ(a.kind, MotionKind::kArc);
  EXPECT_EQ(a.plane, 0);
  EXPECT_EQ(a.center, (std::array<int64_t, 2>{-10000, 0}));
  EXPECT_EQ(a.end, (std::array<int64_t, 2>{-10000, 10000}));
  EXPECT_TRUE(a.ccw);
  EXPECT_EQ(a.delta, (std::array<int64_t, 6>{0, 0, -1000, 0, 0, 0}));
  EXPECT_EQ(a.ops, models::motion_arc_ops(a.center, a.end, true));
  EXPECT_EQ(a.ops, 20000u);  // a quarter: 10 000 steps on each axis
  EXPECT_EQ(c.reports[1].chords, 0u);
  EXPECT_EQ(c.reports[1].arc_commands, 1u);
  EXPECT_NEAR(c.reports[1].length_mm, std::hypot(10 * kPi / 2, 1.0), 1e-9);
  const ModelRun one = run_on_model(c, Machine{}, 4);
  // Z follows the operations (the L1 path), not the angle: about 2 % of its
  // 1000 steps off the programmed helix in mid-quadrant. Cut into pieces
  // (the default, 1 step) it follows the helix.
  const Compiled cut = compile_text(prog);
  EXPECT_GT(cut.reports[1].pieces, 1u);
  EXPECT_EQ(cut.reports[1].arc_commands, cut.reports[1].pieces);
  EXPECT_EQ(cut.end, c.end);
  const ModelRun many = run_on_model(cut, Machine{}, 4);
  std::printf(
      "[ motion ] quarter helix, Z 1000 steps: 1 arc, contour %.2f steps; %llu pieces, "
      "%.2f steps\n",
      one.contour_arc_steps, static_cast<unsigned long long>(cut.reports[1].pieces),
      many.contour_arc_steps);
  EXPECT_GT(one.contour_arc_steps, 15);
  EXPECT_LT(many.contour_arc_steps, 3);
}

TEST(MotionCompiler, PlanesMapToTheEngineAxes) {
  // G18: canon order Z, X; G19: Y, Z. Half circles CW.
  const Compiled c =
      compile_text("G18 G2 X20 Z0 I10 K0 F100\nG19 G0 X0 Y0 Z0\nG2 Y20 Z0 J10 K0\nM2\n");
  ASSERT_EQ(c.commands.size(), 3u);
  EXPECT_EQ(c.commands[0].plane, 1);
  EXPECT_EQ(c.commands[0].center, (std::array<int64_t, 2>{0, 10000}));  // (Z, X)
  EXPECT_EQ(c.commands[0].end, (std::array<int64_t, 2>{0, 20000}));
  EXPECT_FALSE(c.commands[0].ccw);
  EXPECT_EQ(c.commands[2].plane, 2);
  EXPECT_EQ(c.commands[2].center, (std::array<int64_t, 2>{10000, 0}));  // (Y, Z)
  EXPECT_EQ(c.commands[2].end, (std::array<int64_t, 2>{20000, 0}));
  run_on_model(c, Machine{}, 4);
}

TEST(MotionCompiler, MultiTurnArcsRunAsPiecesOfAtMostThreeQuarters) {
  // Two turns (P2) with Z: 4 pi of sweep in ceil(4 pi / 1.5 pi) = 3 pieces.
  const Compiled c = compile_text("G0 X10 Y0\nG2 I-10 J0 Z-6 P2 F600\nM2\n", Machine{},
                                  MotionWidths{}, FeedMode::kFull, uncut());
  ASSERT_EQ(c.reports.size(), 2u);
  EXPECT_EQ(c.reports[1].pieces, 3u);
  EXPECT_EQ(c.reports[1].arc_commands, 3u);
  EXPECT_EQ(c.totals.split_arcs, 1u);
  int64_t z = 0;
  for (size_t k = 1; k < c.commands.size(); ++k) z += c.commands[k].delta[2];
  EXPECT_EQ(z, -6000);
  EXPECT_EQ(c.commands[1].delta[2], -2000);  // a third of the sweep, a third of Z
  // A one-turn full circle stays one command; 300 degrees are two.
  const Compiled f = compile_text("G0 X10 Y0\nG2 I-10 J0 F600\nG3 X5 Y-8.660254 I-10 J0\nM2\n");
  EXPECT_EQ(f.reports[1].commands, 1u);
  EXPECT_EQ(f.reports[2].pieces, 2u);
  EXPECT_EQ(f.reports[2].arc_commands, 2u);
  run_on_model(c, Machine{}, 4);
  run_on_model(f, Machine{}, 4);
}

// The worst distance of a chord (its exact ends on the programmed arc) from
// the arc, in steps of the finer plane axis: R (1 - cos(alpha / 2)).
double sagitta_steps(const Compiled& c, size_t move, const Machine& m) {
  const MoveReport& r = c.reports[move];
  double sweep = 0, radius = 0;
  for (size_t k = 0; k < c.commands.size(); ++k)
    if (c.infos[k].move_index == r.index) {
      const Helix h(c.starts[k], c.moves[k]);
      sweep = h.theta();
      const auto pa = plane_axes(c.moves[k].plane);
      radius = std::max(h.r1(), h.r2()) *
               static_cast<double>(std::max(m.steps_per_unit[static_cast<size_t>(pa.first)],
                                            m.steps_per_unit[static_cast<size_t>(pa.second)]));
      break;
    }
  return radius * (1 - std::cos(sweep / static_cast<double>(r.chords) / 2));
}

TEST(MotionCompiler, ChordsWhenThePlaneHasUnequalStepsPerUnit) {
  Machine m;
  m.steps_per_unit = {1000, 400, 1000, 100, 100, 100};
  const Compiled c = compile_text("G0 X10 Y0\nG3 X-10 Y0 I-10 J0 F600\nM2\n", m);
  const MoveReport& r = c.reports[1];
  EXPECT_EQ(r.arc_commands, 0u);
  EXPECT_GT(r.chords, 10u);
  EXPECT_EQ(r.commands, r.chords);
  EXPECT_STREQ(r.chord_reason, "the plane's axes have different steps per unit");
  EXPECT_EQ(c.totals.chord_arcs, 1u);
  // The exact chords stay within 0.4 step; one chord fewer would not.
  const double s = sagitta_steps(c, 1, m);
  EXPECT_LE(s, 0.4 + 1e-9);
  EXPECT_GT(10000 * (1 - std::cos(kPi / static_cast<double>(r.chords - 1) / 2)), 0.4);
  EXPECT_EQ(c.end, (std::array<int64_t, 6>{-10000, 0, 0, 0, 0, 0}));
  const ModelRun run = run_on_model(c, m, 4);
  // Visited points: the chord's 0.4 + rounding of its ends + the DDA's < 1.
  EXPECT_LT(run.contour_chord_steps, 2.2);
  std::printf("[ motion ] unequal steps: %llu chords, sagitta %.3f, contour %.3f steps\n",
              static_cast<unsigned long long>(r.chords), s, run.contour_chord_steps);
}

TEST(MotionCompiler, ChordsOnAHelixTooSteepForTheSlavedAxis) {
  // A quarter of 1 mm radius (about 2000 operations) with Z down 5 mm (5000
  // steps): more than one Z step per operation.
  const Compiled c = compile_text("G0 X1 Y0\nG3 X0 Y1 I-1 J0 Z-5 F600\nM2\n");
  const MoveReport& r = c.reports[1];
  EXPECT_EQ(r.arc_commands, 0u);
  EXPECT_GT(r.chords, 0u);
  EXPECT_STREQ(r.chord_reason, "a slaved axis needs more than one step per operation");
  EXPECT_EQ(c.end, (std::array<int64_t, 6>{0, 1000, -5000, 0, 0, 0}));
  int64_t z = 0;
  for (size_t k = 1; k < c.commands.size(); ++k) {
    EXPECT_EQ(c.commands[k].kind, MotionKind::kLine);
    z += c.commands[k].delta[2];
  }
  EXPECT_EQ(z, -5000);
  EXPECT_LE(sagitta_steps(c, 1, Machine{}), 0.4 + 1e-9);
  const ModelRun run = run_on_model(c, Machine{}, 4);
  EXPECT_LT(run.contour_chord_steps, 2.2);
  // A gentler helix on the same arc goes to the engine.
  const Compiled g = compile_text("G0 X1 Y0\nG3 X0 Y1 I-1 J0 Z-1 F600\nM2\n", Machine{},
                                  MotionWidths{}, FeedMode::kFull, uncut());
  EXPECT_EQ(g.reports[1].arc_commands, 1u);
}

TEST(MotionCompiler, ChordsForArcsBeyondCoordWOrOpsW) {
  MotionWidths w;
  w.coord_w = 12;  // |v| <= 2047 steps
  const Compiled c = compile_text("G0 X10 Y0\nG3 X0 Y10 I-10 J0 F600\nM2\n", Machine{}, w);
  EXPECT_STREQ(c.reports[1].chord_reason, "a coordinate exceeds COORD_W");
  EXPECT_EQ(c.reports[1].arc_commands, 0u);
  EXPECT_EQ(c.end, (std::array<int64_t, 6>{0, 10000, 0, 0, 0, 0}));
  MotionWidths o;
  o.ops_w = 14;  // ops <= 16383; the quarter takes 20 000
  const Compiled d = compile_text("G0 X10 Y0\nG3 X0 Y10 I-10 J0 F600\nM2\n", Machine{}, o);
  EXPECT_STREQ(d.reports[1].chord_reason, "ops exceeds OPS_W");
  EXPECT_EQ(d.end, (std::array<int64_t, 6>{0, 10000, 0, 0, 0, 0}));
  run_on_model(c, Machine{}, 4);
  run_on_model(d, Machine{}, 4);
}

TEST(MotionCompiler, ATinyArcRoundingOntoItsStartIsNotAFullCircle) {
  // 0.0004 mm of arc: the end rounds onto the start, where rule M would turn
  // a whole circle. It runs as chords: nothing moves on the lattice.
  const Compiled c = compile_text("G0 X10 Y0\nG3 X9.99999999 Y0.0004 I-10 J0 F600\nM2\n");
  EXPECT_EQ(c.reports[1].commands, 0u);
  EXPECT_STREQ(c.reports[1].chord_reason, "rule M would sweep another angle on the lattice");
  EXPECT_EQ(c.end, (std::array<int64_t, 6>{10000, 0, 0, 0, 0, 0}));
}

// --- lines -------------------------------------------------------------------------------

TEST(MotionCompiler, LongLinesSplitIntoPiecesRoundedFromTheLine) {
  MotionWidths w;
  w.acc_w = 12;  // |delta| <= 2047
  w.ops_w = 11;  // at most ACC_W - 1, as rtl/motion_top.sv takes it
  const Compiled c = compile_text("G1 X10 Y3.3333 Z-0.5 F600\nM2\n", Machine{}, w);
  // D = 10 000 steps: k = ceil(10 001 / 2046) = 5 pieces.
  ASSERT_EQ(c.commands.size(), 5u);
  EXPECT_EQ(c.reports[0].pieces, 5u);
  EXPECT_EQ(c.totals.split_lines, 1u);
  std::array<int64_t, 6> at{};
  for (size_t k = 0; k < 5; ++k) {
    const double t = static_cast<double>(k + 1) / 5;
    const std::array<int64_t, 6> want{
        std::llround(10000 * t), std::llround(3333.3 * t), std::llround(-500 * t), 0, 0, 0};
    for (size_t i = 0; i < 6; ++i) {
      EXPECT_LE(std::llabs(c.commands[k].delta[i]), 2047);
      at[i] += c.commands[k].delta[i];
    }
    EXPECT_EQ(at, want) << "piece " << k;
  }
  run_on_model(c, Machine{}, 4);
}

TEST(MotionCompiler, MovesWithNoLatticeMotionMakeNoCommand) {
  const Compiled c = compile_text("G1 X0.0004 F100\nG1 X0.0006\nM2\n");
  ASSERT_EQ(c.reports.size(), 2u);
  EXPECT_EQ(c.reports[0].commands, 0u);
  EXPECT_EQ(c.reports[1].commands, 1u);
  EXPECT_EQ(c.commands[0].delta[0], 1);
  EXPECT_GT(c.reports[0].programmed_s, 0);
}

// --- feed words and time ---------------------------------------------------------------------

TEST(MotionCompiler, FeedWordsAndMachiningTimeByHand) {
  Machine m;
  m.steps_per_unit = {100, 100, 100, 100, 100, 100};
  m.clock_hz = 1000;
  m.rapid_mm_per_min = 120;
  MotionWidths w;
  w.feed_w = 8;  // 256 = full
  const std::string prog = "G1 X1 F60\nG1 X2\nG0 X0\nG1 A90 F180\nM2\n";
  const Compiled p = compile_text(prog, m, w, FeedMode::kProgrammed);
  ASSERT_EQ(p.commands.size(), 4u);
  // G1 X1 F60: 100 steps, 2^7 = 128 operations, 1 mm at 60 mm/min = 1 s =
  // 1000 clocks: word ceil(128 * 256 / 1000) = 33; from phase 0 it takes
  // ceil(32768 / 33) = 993 clocks and leaves phase 993 * 33 - 32768 = 1.
  EXPECT_EQ(p.commands[0].feed, 33u);
  EXPECT_EQ(p.infos[0].operations, 128u);
  EXPECT_EQ(p.infos[0].clocks_programmed, 993u);
  EXPECT_DOUBLE_EQ(p.reports[0].programmed_s, 1.0);
  EXPECT_DOUBLE_EQ(p.reports[0].programmed_words_s, 0.993);
  // G1 X2: the same word; ceil((32768 - 1) / 33) = 993, phase 2.
  EXPECT_EQ(p.commands[1].feed, 33u);
  EXPECT_EQ(p.infos[1].clocks_programmed, 993u);
  // G0 X0: 200 steps, 256 operations, 2 mm at the rapid 120 mm/min = 1 s:
  // word ceil(65536 / 1000) = 66; ceil((65536 - 2) / 66) = 993, phase 4.
  EXPECT_EQ(p.commands[2].feed, 66u);
  EXPECT_EQ(p.infos[2].clocks_programmed, 993u);
  EXPECT_EQ(p.reports[2].kind, MoveKind::kTraverse);
  // G1 A90 F180: no XYZ motion, so 180 deg/min over 90 deg = 30 s = 30 000
  // clocks; 9000 steps, 2^14 = 16384 operations: word
  // ceil(16384 * 256 / 30000) = 140; ceil((4194304 - 4) / 140) = 29960.
  EXPECT_EQ(p.commands[3].feed, 140u);
  EXPECT_EQ(p.infos[3].clocks_programmed, 29960u);
  EXPECT_DOUBLE_EQ(p.reports[3].programmed_s, 30.0);
  EXPECT_DOUBLE_EQ(p.reports[3].length_mm, 90.0);
  // Totals: 33 s programmed, 993 * 3 + 29960 clocks with the words, and at
  // full feed one operation a clock: 128 + 128 + 256 + 16384.
  EXPECT_DOUBLE_EQ(p.totals.programmed_s, 33.0);
  EXPECT_EQ(p.totals.clocks_programmed, 993u * 3 + 29960u);
  EXPECT_EQ(p.totals.clocks_full, 128u + 128u + 256u + 16384u);
  EXPECT_DOUBLE_EQ(p.totals.full_s, 16.896);
  // Full mode: every word 2^FEED_W, the same clocks in the report.
  const Compiled f = compile_text(prog, m, w, FeedMode::kFull);
  for (const auto& c : f.commands) EXPECT_EQ(c.feed, 256u);
  EXPECT_EQ(f.totals.clocks_full, p.totals.clocks_full);
  EXPECT_EQ(f.totals.clocks_programmed, p.totals.clocks_programmed);
}

TEST(MotionCompiler, ArcFeedWordFromTheHelixLength) {
  Machine m;
  m.steps_per_unit = {100, 100, 100, 100, 100, 100};
  m.clock_hz = 1000;
  MotionWidths w;
  w.feed_w = 8;
  // A quarter of radius 1 mm at F60: pi/2 s = 1570.8 clocks.
  const Compiled p = compile_text("G0 X1\nG3 X0 Y1 I-1 J0 F60\nM2\n", m, w, FeedMode::kProgrammed);
  ASSERT_EQ(p.commands.size(), 2u);
  const MotionCommand& a = p.commands[1];
  ASSERT_EQ(a.kind, MotionKind::kArc);
  EXPECT_EQ(a.ops, 200u);
  EXPECT_NEAR(p.reports[1].programmed_s, kPi / 2, 1e-9);
  // ceil(200 * 256 / 1570.796) = ceil(32.59) = 33.
  EXPECT_EQ(a.feed, 33u);
  // Words clamp: faster than one operation a clock is full feed.
  EXPECT_EQ(feed_word(1000, 10, 8), 256u);
  EXPECT_EQ(feed_word(1, 1e9, 8), 1u);
  EXPECT_EQ(feed_word(5, 0, 8), 256u);
}

TEST(MotionCompiler, FeedClockCarriesThePhase) {
  FeedClock f(4);               // 16 = full
  EXPECT_EQ(f.run(3, 5), 10u);  // ceil(48 / 5) = 10, phase 50 - 48 = 2
  EXPECT_EQ(f.phase(), 2u);
  EXPECT_EQ(f.run(1, 7), 2u);  // ceil((16 - 2) / 7) = 2, phase 2 + 14 - 16 = 0
  EXPECT_EQ(f.phase(), 0u);
  EXPECT_EQ(f.run(9, 16), 9u);  // full: one a clock, the phase holds
  EXPECT_EQ(f.run(9, 40), 9u);
}

// --- refusals ---------------------------------------------------------------------------------

TEST(MotionCompiler, RefusesMotionOnAnAxisTheMachineLacks) {
  Machine xyz;
  xyz.has_axis = {true, true, true, false, false, false};
  const std::string e = test::error_of([&] { compile_text("G1 X1 F100\nG1 A10\nM2\n", xyz); });
  EXPECT_TRUE(test::mentions(e, {"t.ngc:2", "A", "no A axis"}));
  Machine xy_a;
  xy_a.has_axis = {true, true, false, true, false, false};
  const std::string arc =
      test::error_of([&] { compile_text("G18\nG2 X2 Z0 I1 K0 F100\nM2\n", xy_a); });
  EXPECT_TRUE(test::mentions(arc, {"t.ngc:2", "Z"}));
  // A canon feed at rate 0 cannot be timed.
  std::istringstream in("1 N..... STRAIGHT_FEED(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n");
  CanonReader r(in, "z.canon");
  const std::string zero =
      test::error_of([&] { compile(r, Machine{}, MotionWidths{}, FeedMode::kFull, "z.canon"); });
  EXPECT_TRUE(test::mentions(zero, {"z.canon:1", "feed rate 0"}));
  // An axis beyond the core's.
  Machine b;
  b.has_axis = {true, true, true, true, true, false};
  std::istringstream empty("M2\n");
  NgcReader none(empty, "e.ngc");
  EXPECT_THROW(MotionCompiler(none, b, MotionWidths{}, FeedMode::kFull, "e.ngc"), cli::UsageError);
  MotionWidths bad;
  bad.feed_w = 40;
  EXPECT_THROW(MotionCompiler(none, Machine{}, bad, FeedMode::kFull, "e.ngc"), cli::UsageError);
}

// --- random programs ----------------------------------------------------------------------

// Random moves as a reader would make them: lines and traverses on X Y Z A,
// arcs in every plane with both directions, ends on or a little off the
// circle (within LinuxCNC's 0.1 %), now and then extra turns, helix axis and
// A moving, radii from 0.05 to 20 mm.
class RandomMoves : public MoveSource {
 public:
  RandomMoves(uint64_t moves, uint64_t seed) : moves_(moves), rng_(seed) {}
  bool next(Move& m) override {
    if (n_ >= moves_) return false;
    ++n_;
    const Move prev = m_;
    m_ = Move{};
    m_.line = n_;
    m_.feed = 100 + uniform(0, 3000);
    m_.end = prev.end;
    const int kind = static_cast<int>(uniform(0, 9));
    if (kind < 4) {
      m_.kind = kind == 0 ? MoveKind::kTraverse : MoveKind::kFeed;
      for (size_t a = 0; a < 4; ++a)
        if (uniform(0, 2) > 0) m_.end[a] = std::round(uniform(-80, 80) * 1e4) / 1e4;
    } else {
      m_.kind = MoveKind::kArc;
      const Plane planes[] = {Plane::kXY, Plane::kXZ, Plane::kYZ};
      m_.plane = planes[static_cast<size_t>(uniform(0, 2.99))];
      const PlaneAxes pa = plane_axes(m_.plane);
      const auto f = static_cast<size_t>(pa.first), g = static_cast<size_t>(pa.second);
      const double r = std::exp(uniform(std::log(0.05), std::log(20)));
      const double a0 = uniform(0, 2 * kPi);
      m_.center = {prev.end[f] - r * std::cos(a0), prev.end[g] - r * std::sin(a0)};
      const double sweep = uniform(0.01, 2 * kPi);
      m_.rotation = (uniform(0, 1) < 0.5 ? 1 : -1) * (uniform(0, 1) < 0.1 ? 2 : 1);
      const double a1 = a0 + (m_.rotation > 0 ? sweep : -sweep);
      const double r1 = r * (1 + uniform(-0.0009, 0.0009));
      m_.end[f] = m_.center[0] + r1 * std::cos(a1);
      m_.end[g] = m_.center[1] + r1 * std::sin(a1);
      if (uniform(0, 1) < 0.5) m_.end[static_cast<size_t>(pa.third)] += uniform(-5, 5);
      if (uniform(0, 1) < 0.3) m_.end[kA] += uniform(-90, 90);
    }
    m = m_;
    stats_.count(m);
    return true;
  }
  const ReaderStats& stats() const override { return stats_; }

 private:
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  uint64_t moves_, n_ = 0;
  std::mt19937_64 rng_;
  Move m_;
  ReaderStats stats_;
};

struct RandomCase {
  const char* name;
  std::array<int64_t, 6> steps;
  MotionWidths widths;
};

TEST(MotionCompiler, RandomProgramsEndOnEveryMoveAndStayNearThePath) {
  MotionWidths narrow;
  narrow.acc_w = 14;
  narrow.coord_w = 15;
  narrow.ops_w = 13;  // at most ACC_W - 1, as rtl/motion_top.sv takes it
  const RandomCase cases[] = {
      {"default", {1000, 1000, 1000, 100, 100, 100}, MotionWidths{}},
      {"coarse", {80, 80, 200, 10, 10, 10}, MotionWidths{}},
      {"unequal", {1000, 640, 400, 100, 100, 100}, MotionWidths{}},
      {"narrow", {1000, 1000, 1000, 100, 100, 100}, narrow},
  };
  uint64_t seed = 100;
  for (const RandomCase& rc : cases) {
    Machine m;
    m.steps_per_unit = rc.steps;
    RandomMoves src(120, seed++);
    const Compiled c = compile(src, m, rc.widths, FeedMode::kProgrammed, rc.name);
    EXPECT_TRUE(c.ends_on_reports) << rc.name;
    EXPECT_EQ(c.reports.size(), 120u);
    for (const MotionCommand& cmd : c.commands) {
      EXPECT_GE(cmd.feed, 1u);
      EXPECT_LE(cmd.feed, uint32_t{1} << rc.widths.feed_w);
      const int64_t acc = (int64_t{1} << (rc.widths.acc_w - 1)) - 1;
      for (const int64_t d : cmd.delta) EXPECT_LE(std::llabs(d), acc);
      if (cmd.kind == MotionKind::kArc) {
        const int64_t co = (int64_t{1} << (rc.widths.coord_w - 1)) - 1;
        for (const int64_t v : {cmd.center[0], cmd.center[1], cmd.end[0], cmd.end[1]})
          EXPECT_LE(std::llabs(v), co);
        EXPECT_LT(cmd.ops, uint64_t{1} << rc.widths.ops_w);
      }
    }
    const ModelRun run = run_on_model(c, m, 4);
    std::printf(
        "[ motion ] random %s: %llu commands (%llu arcs, %llu chords), contour steps: lines "
        "%.3f arcs %.3f chords %.3f\n",
        rc.name, static_cast<unsigned long long>(c.totals.commands),
        static_cast<unsigned long long>(c.totals.arc_commands),
        static_cast<unsigned long long>(c.totals.chords), run.contour_line_steps,
        run.contour_arc_steps, run.contour_chord_steps);
    EXPECT_LT(run.contour_line_steps, 3.0) << rc.name;
    EXPECT_LT(run.contour_arc_steps, 3.5) << rc.name;
    EXPECT_LT(run.contour_chord_steps, 3.0) << rc.name;
  }
}

// --- streaming --------------------------------------------------------------------------------

// 100 000 moves made on demand: lines out along X and half circles back,
// with Z going up and down; nothing is stored.
class Generated : public MoveSource {
 public:
  explicit Generated(uint64_t moves) : moves_(moves) {}
  bool next(Move& m) override {
    if (n_ >= moves_) return false;
    ++n_;
    m = Move{};
    m.line = n_;
    m.feed = 1200;
    if (n_ % 2) {
      m.kind = MoveKind::kFeed;
      m.end = {0.2, 0, 0, 0, 0, 0};
    } else {
      m.kind = MoveKind::kArc;
      m.end = {0, 0, n_ % 4 ? 0.05 : 0.0, 0, 0, 0};
      m.center = {0.1, 0};
      m.rotation = 1;
    }
    stats_.count(m);
    return true;
  }
  const ReaderStats& stats() const override { return stats_; }

 private:
  uint64_t moves_, n_ = 0;
  ReaderStats stats_;
};

TEST(MotionCompiler, StreamsAHundredThousandMovesInBoundedMemory) {
  constexpr uint64_t kMoves = 100000;
  Generated src(kMoves);
  uint64_t reports = 0;
  size_t heap_at_10k = 0, heap_max_after = 0;
  MotionCompiler c(src, Machine{}, MotionWidths{}, FeedMode::kProgrammed, "gen",
                   [&](const MoveReport& r) {
                     ++reports;
                     const size_t heap = mallinfo2().uordblks;
                     if (r.index == 10000) heap_at_10k = heap;
                     if (r.index > 10000) heap_max_after = std::max(heap_max_after, heap);
                   });
  MotionCommand cmd;
  uint64_t commands = 0, arcs = 0;
  while (c.next(cmd)) {
    ++commands;
    arcs += cmd.kind == MotionKind::kArc;
  }
  EXPECT_EQ(reports, kMoves);
  EXPECT_EQ(commands, kMoves);
  EXPECT_EQ(arcs, kMoves / 2);
  EXPECT_EQ(c.position(), (std::array<int64_t, 6>{0, 0, 0, 0, 0, 0}));
  // Nothing grows per move: the heap after move 10 000 stays within a few
  // kilobytes of what it was there (90 000 moves later).
  ASSERT_GT(heap_at_10k, 0u);
  EXPECT_LT(heap_max_after, heap_at_10k + 16 * 1024)
      << "heap " << heap_at_10k << " at move 10000, up to " << heap_max_after << " later";
  std::printf(
      "[ motion ] 100000 moves: %llu commands, heap %zu bytes at move 10000, max %zu after\n",
      static_cast<unsigned long long>(commands), heap_at_10k, heap_max_after);
}

}  // namespace
}  // namespace hwinterp::gcode

// hwinterp reproduce --paper chord: paper 003's PPC line and arc sequences and
// inscribed-chord Tables I-III beside our models'.
#include <string>
#include <vector>

#include "models/inscribed_chord.h"
#include "models/paper_data_001_003_004.h"
#include "models/ppc.h"
#include "tb/reproduce/figure_rows.h"
#include "tb/reproduce/hardware.h"
#include "tb/reproduce/reproduce.h"

namespace hwinterp::cli {
namespace {

namespace pd = models::paper;
using models::LatticePoint;
using models::Vec2;

std::string lattice(const LatticePoint& p) {
  return "(" + std::to_string(p[0]) + "," + std::to_string(p[1]) + ")";
}
std::string point(const Vec2& p, const char* f) {
  return "(" + fmt(f, p.x()) + "," + fmt(f, p.y()) + ")";
}

// The paper's point list beside the model's and the hardware's (the core's
// HLS and RTL faces in lockstep, checked against the model on every move).
template <size_t N>
void ppc_rows(FigureRows& rows, const std::string& name, const models::StepPath& path,
              const std::array<std::array<int64_t, 2>, N>& paper, const std::string& core,
              const std::string& job) {
  std::string ps, os;
  for (const auto& q : paper) ps += lattice({q[0], q[1]});
  for (const auto& m : path.moves) os += lattice(m.point);
  rows.add(name + ": steps", std::to_string(N), std::to_string(path.moves.size()),
           path.moves.size() == N);
  rows.add(name + ": points", ps, os, ps == os);
  const HardwareRun hw = run_hardware(core, job);
  const size_t moves = hw.result.visited.size() - 1;
  rows.add(name + ": steps, hardware " + hw.variant, std::to_string(N), std::to_string(moves),
           moves == N && hw.result.passed());
  const std::string hs = moves_text(hw.result);
  rows.add(name + ": points, hardware " + hw.variant, ps, hs, hs == ps && hw.result.passed());
}

PaperReproduction reproduce_chord() {
  PaperReproduction out;
  FigureRows rows;

  const models::StepPath ppc_l = models::ppc_line({0, 0}, {4, 3});
  const models::StepPath ppc_a = models::ppc_arc({0, 0}, {4, 0}, {0, 4}, true);
  ppc_rows(rows, "PPC line (0,0)->(4,3)", ppc_l, pd::kPpcLine, "ppc_line", "line 4 3\n");
  ppc_rows(rows, "PPC arc (4,0)->(0,4) CCW", ppc_a, pd::kPpcArc, "ppc_arc",
           "start 4 0\narc 0 0 0 4 ccw\n");

  const models::ChordResult t1 = models::inscribed_chord_line({0, 0}, {4, 3}, 1.0);
  rows.add("Table I (r = 1): steps", std::to_string(pd::kChordTable1.size()),
           std::to_string(t1.steps.size()), t1.steps.size() == pd::kChordTable1.size());
  for (size_t k = 0; k < pd::kChordTable1.size() && k < t1.steps.size(); ++k) {
    const Vec2 paper(pd::kChordTable1[k][0], pd::kChordTable1[k][1]);
    const auto& s = t1.steps[k];
    rows.add("Table I step " + std::to_string(k + 1) + " from " + point(s.center, "%.1f"),
             point(paper, "%.1f"), point(s.point, "%.6f"), (s.point - paper).norm() < 1e-9);
  }
  rows.add("Table I: ends exactly on (4,3)", "yes", t1.exact_end ? "yes" : "no", t1.exact_end);

  const models::ChordResult t2 = models::inscribed_chord_arc({0, 0}, {4, 0}, {0, 4}, true, 0.9);
  rows.add("Table II (r = 0.9): steps", std::to_string(pd::kChordTable2.size()),
           std::to_string(t2.steps.size()), t2.steps.size() == pd::kChordTable2.size());
  for (size_t k = 0; k < pd::kChordTable2.size() && k < t2.steps.size(); ++k) {
    const auto& s = t2.steps[k];
    const Vec2 cut(models::truncate_to(s.point.x(), 3), models::truncate_to(s.point.y(), 3));
    const Vec2 paper(pd::kChordTable2[k][0], pd::kChordTable2[k][1]);
    rows.add("Table II step " + std::to_string(k + 1) + " (truncated to 3 decimals)",
             point(paper, "%.3f"), point(cut, "%.3f") + " from " + point(s.point, "%.6f"),
             (cut - paper).norm() < 1e-9);
  }
  const Vec2 last = t2.steps.empty() ? Vec2(0, 0) : t2.steps.back().point;
  rows.add("Table II point 7 (exact chain, 6 decimals)", "(-0.030180,3.999886)", point(last, "%.6f"),
           std::abs(last.x() + 0.030180) <= 5e-7 && std::abs(last.y() - 3.999886) <= 5e-7);
  rows.add("Table II: overshoot past (0,4) (mm)", "0.03", fmt("%.6f", t2.overshoot),
           std::abs(t2.overshoot - 0.03) < 0.0005);

  rows.add("Table III: PPC line steps", std::to_string(pd::kTable3PpcLine),
           std::to_string(ppc_l.moves.size()), ppc_l.moves.size() == size_t(pd::kTable3PpcLine));
  rows.add("Table III: chord line steps", std::to_string(pd::kTable3ChordLine),
           std::to_string(t1.steps.size()), t1.steps.size() == size_t(pd::kTable3ChordLine));
  rows.add("Table III: PPC arc steps", std::to_string(pd::kTable3PpcArc),
           std::to_string(ppc_a.moves.size()), ppc_a.moves.size() == size_t(pd::kTable3PpcArc));
  rows.add("Table III: chord arc steps", std::to_string(pd::kTable3ChordArc),
           std::to_string(t2.steps.size()), t2.steps.size() == size_t(pd::kTable3ChordArc));

  // Beyond the paper: the vertical-line trap, and the accuracy Table III only
  // ranks ("relatively lower" / "high").
  const models::StepPath vbare = models::ppc_line({0, 0}, {0, 3}, models::PpcLineRule::kTextbook);
  const models::StepPath vguard = models::ppc_line({0, 0}, {0, 3});
  const models::ChordResult t2clamp =
      models::inscribed_chord_arc({0, 0}, {4, 0}, {0, 4}, true, 0.9, models::ChordEnd::kClamp);
  std::string notes;
  notes += "\nBeyond the paper:\n";
  notes += "  vertical line (0,0)->(0,3): bare PPC rule ends at " + lattice(vbare.last_point()) +
           " (misses), guarded rule ends at " + lattice(vguard.last_point()) + "\n";
  notes += "  PPC line normal error max " + fmt("%.4f", ppc_l.line_error().max_error) +
           " step; chord line error 0 (every point on the line)\n";
  notes += "  PPC arc radial error max " +
           fmt("%.4f", models::ppc_arc_radial_error(ppc_a, {0, 0})) +
           " step; chord arc: chord height max " + fmt("%.6f", t2.max_chord_error) +
           " mm, points on the circle\n";
  notes += "  chord arc clamped to the end: " + std::to_string(t2clamp.steps.size()) +
           " chords, last one " + fmt("%.6f", t2clamp.steps.back().chord) + " mm\n";

  out.ok = rows.ok();
  out.text = rows.text() + notes;
  out.json["rows"] = rows.json();
  out.json["ppc_line_max_error"] = ppc_l.line_error().max_error;
  out.json["ppc_arc_radial_error"] = models::ppc_arc_radial_error(ppc_a, {0, 0});
  out.json["chord_arc_max_chord_error"] = t2.max_chord_error;
  out.json["chord_arc_overshoot"] = t2.overshoot;
  return out;
}

}  // namespace

HWINTERP_PAPER("chord", "003 inscribed chord vs point-by-point comparison (Tables I-III)", 30,
               reproduce_chord);

}  // namespace hwinterp::cli

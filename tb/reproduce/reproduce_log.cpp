// hwinterp reproduce --paper log: paper 001's odd-even log interpolation
// figures (Table 1, the point counts and maximum errors at dl = 0.2 and 0.5)
// beside the double-precision model's, and the log_stepper core's points
// (HLS and RTL in lockstep at 1000 steps per mm and per degree, the lattice
// positions where each coarse point's segment ends, converted back to mm and
// rad) beside both.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "models/common.h"
#include "models/log_curve.h"
#include "models/log_stepper_model.h"
#include "models/paper_data_001_003_004.h"
#include "tb/reproduce/figure_rows.h"
#include "tb/reproduce/hardware.h"
#include "tb/reproduce/reproduce.h"

namespace hwinterp::cli {
namespace {
using models::kPi;

namespace pd = models::paper;
using models::EvenStep;
using models::LogCurveParams;
using models::LogRun;

std::string sci(double v) { return fmt("%.4e", v); }

PaperReproduction reproduce_log() {
  PaperReproduction out;
  FigureRows rows;
  const LogRun r02 = models::run_log_interpolation(LogCurveParams{});
  LogCurveParams p05;
  p05.dl_mm = 0.5;
  const LogRun r05 = models::run_log_interpolation(p05);

  rows.add("dl 0.2: points", std::to_string(pd::kLogPoints02), std::to_string(r02.count()),
           r02.count() == static_cast<size_t>(pd::kLogPoints02));
  rows.add("dl 0.2: last X (mm)", fmt("%.4f", pd::kLogXLast02), fmt("%.6f", r02.x_last()),
           matches_printed(r02.x_last(), pd::kLogXLast02, 4));
  rows.add("dl 0.2: MaxErPA (rad)", sci(pd::kLogMaxErr02) + " (point 1)",
           sci(r02.max_all.abs) + " (point " + std::to_string(r02.max_all.index) + ")",
           matches_sig5(r02.max_all.abs, pd::kLogMaxErr02) && r02.max_all.index == 1);
  rows.add("dl 0.2: MaxErPAo (rad)", sci(pd::kLogMaxErr02) + " (point 1)",
           sci(r02.max_odd.abs) + " (point " + std::to_string(r02.max_odd.index) + ")",
           matches_sig5(r02.max_odd.abs, pd::kLogMaxErr02) && r02.max_odd.index == 1);
  rows.add("dl 0.2: MaxErPAe (rad)", sci(pd::kLogMaxErrEven02) + " (point 152)",
           sci(r02.max_even.abs) + " (point " + std::to_string(r02.max_even.index) + ")",
           matches_sig5(r02.max_even.abs, pd::kLogMaxErrEven02) && r02.max_even.index == 152);
  rows.add("dl 0.5: points", std::to_string(pd::kLogPoints05), std::to_string(r05.count()),
           r05.count() == static_cast<size_t>(pd::kLogPoints05));
  rows.add("dl 0.5: last X (mm)", fmt("%.4f", pd::kLogXLast05), fmt("%.6f", r05.x_last()),
           matches_printed(r05.x_last(), pd::kLogXLast05, 4));
  rows.add("dl 0.5: MaxErPA (rad)", sci(pd::kLogMaxErr05), sci(r05.max_all.abs),
           matches_sig5(r05.max_all.abs, pd::kLogMaxErr05));

  // The hardware: the paper's curve on log_stepper at 1000 steps/mm and
  // 1000 steps/deg; its coarse points where their segments end.
  constexpr double kSteps = 1000;
  const HardwareRun hw = run_hardware("log_stepper", "curve 10 30 5 8 0.2 30 1000 1000\n");
  const auto& pts = hw.result.checkpoints;
  models::LogStepScale scale;
  scale.x_per_mm = scale.y_per_mm = scale.z_per_mm = scale.a_per_deg = kSteps;
  int64_t hw_worst = 0;
  for (size_t k = 0; k < pts.size() && k + 1 < r02.points.size(); ++k) {
    const auto want = models::log_lattice(r02.points[k + 1], LogCurveParams{}, scale);
    for (size_t i = 0; i < 4; ++i)
      hw_worst = std::max<int64_t>(hw_worst, std::llabs(pts[k][i] - want[i]));
  }
  auto hw_x = [&](size_t point) { return static_cast<double>(pts.at(point - 1)[0]) / kSteps; };
  auto hw_a = [&](size_t point) {
    return static_cast<double>(pts.at(point - 1)[3]) / (kSteps * 180 / kPi);
  };
  rows.add("hardware (" + hw.variant + "): passed in lockstep", "yes",
           hw.result.passed() ? "yes" : "NO", hw.result.passed());
  rows.add("hardware: points at dl 0.2", std::to_string(pd::kLogPoints02),
           std::to_string(pts.size()), pts.size() == static_cast<size_t>(pd::kLogPoints02));
  rows.add("hardware: last X (mm, lattice)", fmt("%.4f", pd::kLogXLast02),
           pts.empty() ? "-" : fmt("%.3f", hw_x(pts.size())),
           !pts.empty() && std::abs(hw_x(pts.size()) - pd::kLogXLast02) < 0.001);
  rows.add("hardware: max |lattice - double model rounded| (steps)", "<= 1",
           std::to_string(hw_worst), hw_worst <= 1 && !pts.empty());

  // Table 1: 20 rows x 4 columns; each cell printed to 4 decimals. The
  // hardware's X and A are lattice points (1 um, 0.001 deg): they match the
  // double model rounded to steps, not to 4 decimals.
  TextTable t1({"No.", "X paper", "X ours", "X hw", "A paper", "A ours", "A hw", "PA paper",
                "PA ours", "ErPA*1e4 paper", "ErPA*1e4 ours", "match"});
  Json table = Json::array();
  int cells = 0, matched = 0;
  for (const auto& row : pd::kLogTable1) {
    const auto& q = r02.points.at(static_cast<size_t>(row.point));
    const bool mx = matches_printed(q.x, row.x, 4), ma = matches_printed(q.a, row.a, 4),
               mp = matches_printed(q.pa, row.pa, 4),
               me = matches_printed(q.error * 1e4, row.err_e4, 4);
    cells += 4;
    matched += mx + ma + mp + me;
    const bool all = mx && ma && mp && me;
    const auto point = static_cast<size_t>(row.point);
    const bool have_hw = point >= 1 && point <= pts.size();
    t1.add_row({std::to_string(row.point), fmt("%.4f", row.x), fmt("%.6f", q.x),
                have_hw ? fmt("%.3f", hw_x(point)) : "-", fmt("%.4f", row.a), fmt("%.6f", q.a),
                have_hw ? fmt("%.6f", hw_a(point)) : "-", fmt("%.4f", row.pa), fmt("%.6f", q.pa),
                fmt("%.4f", row.err_e4), fmt("%.6f", q.error * 1e4), all ? "yes" : "NO"});
    Json o = Json::object();
    o["point"] = row.point;
    o["paper"] = Json({{"x", row.x}, {"a", row.a}, {"pa", row.pa}, {"err_e4", row.err_e4}});
    o["ours"] = Json({{"x", q.x}, {"a", q.a}, {"pa", q.pa}, {"err_e4", q.error * 1e4}});
    if (have_hw) o["hardware"] = Json({{"x", hw_x(point)}, {"a", hw_a(point)}});
    o["match"] = all;
    table.push_back(std::move(o));
  }
  rows.add("Table 1 cells matching to 4 decimals", std::to_string(cells), std::to_string(matched),
           matched == cells);

  // Not in the paper: the even-point drift and the exact even step.
  const LogRun exact = models::run_log_interpolation(LogCurveParams{}, EvenStep::kExact);

  out.ok = rows.ok();
  out.text = rows.text() + "\nTable 1 (dl = 0.2 mm; paper values printed to 4 decimals):\n" +
             t1.render() + "\nBeyond the paper: the even points drift one way (ErPA " +
             sci(r02.points[2].error) + " at point 2, " + sci(r02.points.back().error) +
             " at point 152);\nwith the exact even step (circle around P1 cut with the curve) "
             "MaxErPAe = " +
             sci(exact.max_even.abs) + ", MaxErPAo = " + sci(exact.max_odd.abs) + ".\n";
  out.json["rows"] = rows.json();
  out.json["table1"] = std::move(table);
  out.json["hardware"] = Json({{"variant", hw.variant},
                               {"passed", hw.result.passed()},
                               {"points", pts.size()},
                               {"max_point_error_steps", hw_worst},
                               {"cycles", hw.result.cycles}});
  out.json["exact_even"] = Json({{"max_error_odd", exact.max_odd.abs},
                                 {"max_error_even", exact.max_even.abs},
                                 {"points", exact.count()}});
  return out;
}

}  // namespace

HWINTERP_PAPER("log", "001 odd-even third-order interpolation of A = a ln(1 + bX) (Table 1)", 20,
               reproduce_log);

}  // namespace hwinterp::cli

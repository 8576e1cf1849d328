// hwinterp reproduce --paper log: paper 001's odd-even log interpolation
// figures (Table 1, the point counts and maximum errors at dl = 0.2 and 0.5)
// beside the double-precision model's.
#include <string>

#include "models/log_curve.h"
#include "models/paper_data_001_003_004.h"
#include "tb/reproduce/figure_rows.h"
#include "tb/reproduce/reproduce.h"

namespace hwinterp::cli {
namespace {

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

  // Table 1: 20 rows x 4 columns; each cell printed to 4 decimals.
  TextTable t1({"No.", "X paper", "X ours", "A paper", "A ours", "PA paper", "PA ours",
                "ErPA*1e4 paper", "ErPA*1e4 ours", "match"});
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
    t1.add_row({std::to_string(row.point), fmt("%.4f", row.x), fmt("%.6f", q.x), fmt("%.4f", row.a),
                fmt("%.6f", q.a), fmt("%.4f", row.pa), fmt("%.6f", q.pa), fmt("%.4f", row.err_e4),
                fmt("%.6f", q.error * 1e4), all ? "yes" : "NO"});
    Json o = Json::object();
    o["point"] = row.point;
    o["paper"] = Json({{"x", row.x}, {"a", row.a}, {"pa", row.pa}, {"err_e4", row.err_e4}});
    o["ours"] = Json({{"x", q.x}, {"a", q.a}, {"pa", q.pa}, {"err_e4", q.error * 1e4}});
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
  out.json["exact_even"] = Json({{"max_error_odd", exact.max_odd.abs},
                                 {"max_error_even", exact.max_even.abs},
                                 {"points", exact.count()}});
  return out;
}

}  // namespace

HWINTERP_PAPER("log", "001 odd-even third-order interpolation of A = a ln(1 + bX) (Table 1)", 20,
               reproduce_log);

}  // namespace hwinterp::cli

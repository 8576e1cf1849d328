// hwinterp log: the double-precision odd-even third-order interpolation of
// A = a ln(1 + bX) (models/log_curve.h) for one conical-mill specification.
// Defaults are the paper's test case (D1 10, S 30, C 5, r 8, dl 0.2, X to 30).
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "models/log_curve.h"
#include "tb/base/text_table.h"
#include "tb/cli/subcommand.h"

namespace hwinterp::cli {
namespace {

using models::EvenStep;
using models::LogCurveParams;
using models::LogRun;

double positive(const Args& args, const std::string& name) {
  const double v = args.real(name);
  if (!(v > 0)) throw UsageError("--" + name + ": " + args.str(name) + " must be > 0");
  return v;
}

double angle(const Args& args, const std::string& name) {
  const double v = args.real(name);
  if (!(v > 0 && v < 90))
    throw UsageError("--" + name + ": " + args.str(name) + " degrees is outside (0, 90)");
  return v;
}

void write_csv(const std::string& path, const LogRun& run) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw UsageError("--csv: cannot write '" + path + "'");
  std::fprintf(f.get(), "index,parity,x,y,z,a,pa,error\n");
  for (const auto& p : run.points)
    std::fprintf(f.get(), "%zu,%s,%.15g,%.15g,%.15g,%.15g,%.15g,%.9e\n", p.index,
                 p.index == 0 ? "start" : (p.odd() ? "odd" : "even"), p.x, p.y, p.z, p.a, p.pa,
                 p.error);
  if (std::ferror(f.get())) throw UsageError("--csv: error writing '" + path + "'");
}

Json max_json(const models::LogMaxError& m) {
  Json o = Json::object();
  o["abs"] = m.abs;
  o["signed"] = m.value;
  o["index"] = m.index;
  return o;
}

int run_log(int argc, char** argv, int first) {
  Args args("log",
            "Odd-even steps third-order interpolation of the logarithmic curve A = a ln(1 + bX),\n"
            "a = tan S / tan C, b = 2 tan C / D1, for 4-axis (X, Y, Z, A) conical-mill grinding.\n"
            "Runs whole odd+even cycles until an even point reaches X >= x-end (paper 001).\n"
            "The error is ErPA = a ln(1 + bX) - A at every interpolated point (rad).");
  args.option("d1", "MM", "end diameter D1 of the cutter", "10");
  args.option("spiral", "DEG", "spiral angle S, in (0, 90)", "30");
  args.option("cone", "DEG", "cone angle C, in (0, 90)", "5");
  args.option("rake", "DEG", "rake r, in (0, 90)", "8");
  args.option("dl", "MM", "instruction interpolation length", "0.2");
  args.option("x-end", "MM", "X at which the run stops (after a whole cycle)", "30");
  args.option("csv", "FILE", "write every point: index, parity, X, Y, Z, A, PA, error");
  args.flag("exact-even",
            "even step = circle of radius dl around P1 cut with the true curve "
            "(instead of Eqs. 14/15)");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;

  LogCurveParams p;
  p.d1_mm = positive(args, "d1");
  p.spiral_deg = angle(args, "spiral");
  p.cone_deg = angle(args, "cone");
  p.rake_deg = angle(args, "rake");
  p.dl_mm = positive(args, "dl");
  p.x_end_mm = positive(args, "x-end");
  const EvenStep even = args.given("exact-even") ? EvenStep::kExact : EvenStep::kPaper;
  stage_outputs(args, {"csv"});

  LogRun run;
  try {
    run = models::run_log_interpolation(p, even);
  } catch (const std::invalid_argument& e) {
    // What is left after the per-option checks: dl against x-end, and the
    // point limit, which the spiral angle and d1 (the curve's slope) drive
    // as much as dl and x-end.
    throw UsageError(std::string("--spiral/--d1/--dl/--x-end: ") + e.what());
  }
  if (args.given("csv")) write_csv(output_path("csv"), run);

  const auto& last = run.points.back();
  std::cout << "log curve A = a ln(1 + bX): a = " << fmt("%.9g", run.a)
            << ", b = " << fmt("%.9g", run.b) << " 1/mm; even step "
            << (even == EvenStep::kExact ? "exact (circle cut)" : "Eqs. 14/15") << "\n";
  TextTable t({"figure", "value", "at point"});
  t.add_row({"points", std::to_string(run.count()), ""});
  t.add_row({"last X (mm)", fmt("%.4f", last.x), std::to_string(last.index)});
  t.add_row({"last Y, Z (mm)", fmt("%.4f", last.y) + ", " + fmt("%.4f", last.z), ""});
  t.add_row({"last A (rad)", fmt("%.4f", last.a), ""});
  t.add_row({"MaxErPA (rad)", fmt("%.4e", run.max_all.abs), std::to_string(run.max_all.index)});
  t.add_row({"MaxErPAo (rad)", fmt("%.4e", run.max_odd.abs), std::to_string(run.max_odd.index)});
  t.add_row({"MaxErPAe (rad)", fmt("%.4e", run.max_even.abs), std::to_string(run.max_even.index)});
  std::cout << t.render();

  Json params = Json::object();
  params["d1"] = p.d1_mm;
  params["spiral"] = p.spiral_deg;
  params["cone"] = p.cone_deg;
  params["rake"] = p.rake_deg;
  params["dl"] = p.dl_mm;
  params["x_end"] = p.x_end_mm;
  Json report = Json::object();
  report["points"] = run.count();
  report["x_last"] = last.x;
  report["y_last"] = last.y;
  report["z_last"] = last.z;
  report["a_last"] = last.a;
  report["max_error"] = run.max_all.abs;
  report["max_error_odd"] = run.max_odd.abs;
  report["max_error_even"] = run.max_even.abs;
  report["max_error_index"] = run.max_all.index;
  report["max_error_odd_index"] = run.max_odd.index;
  report["max_error_even_index"] = run.max_even.index;
  Json detail = Json::object();
  detail["all"] = max_json(run.max_all);
  detail["odd"] = max_json(run.max_odd);
  detail["even"] = max_json(run.max_even);
  report["max_error_detail"] = std::move(detail);
  report["even_step"] = even == EvenStep::kExact ? "exact" : "paper";
  report["a"] = run.a;
  report["b"] = run.b;
  report["parameters"] = std::move(params);
  report["csv"] = args.given("csv") ? Json(args.str("csv")) : Json();
  maybe_write_json(args, report);
  return kExitOk;
}

}  // namespace

HWINTERP_SUBCOMMAND("log", "odd-even third-order interpolation of A = a ln(1 + bX)", 40, run_log);

}  // namespace hwinterp::cli

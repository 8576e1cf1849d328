// hwinterp reproduce --paper ratio: paper 004's eight test lines through every
// fine line interpolator (fixed ratio, PPC, DDA plain/half, minimum deviation,
// Bresenham), the error bounds over all short lines, PPC's 60 operations, and
// the fixed-ratio generator built from integer clock dividers, and the eight
// lines on the hardware cores (fixed_ratio, dda_line, ppc_line) beside the
// exact-frequency and integer-divider models.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "fixed_ratio_n2_cfg.h"
#include "models/fixed_ratio.h"
#include "models/fixed_ratio_model.h"
#include "models/min_deviation.h"
#include "models/paper_data_001_003_004.h"
#include "models/ppc.h"
#include "tb/reproduce/figure_rows.h"
#include "tb/reproduce/hardware.h"
#include "tb/reproduce/reproduce.h"

namespace hwinterp::cli {
namespace {

namespace pd = models::paper;
using models::LatticePoint;
using models::StepPath;

struct Method {
  std::string name;
  std::function<StepPath(const LatticePoint&, const LatticePoint&)> run;
  std::function<double(const LatticePoint&, const LatticePoint&)> bound;
  bool strict;             // error < bound (else <=)
  std::string ticks_rule;  // paper 004's completion ticks
  std::function<double(int64_t, int64_t)> ticks;
  std::string accepted;  // the bound seen over |dx|, |dy| <= 40 (paper 004)
  double accepted_value;
};

int64_t mag(int64_t v) { return v < 0 ? -v : v; }

std::vector<Method> methods() {
  using namespace models;
  auto maxd = [](int64_t dx, int64_t dy) { return double(std::max(mag(dx), mag(dy))); };
  auto dda_ticks = [](int64_t dx, int64_t dy) { return double(dda_iterations({dx, dy})); };
  return {
      {"fixed ratio", fixed_ratio_line, fixed_ratio_error_bound, false, "max(|dx|,|dy|)", maxd,
       "<= (|dx|+|dy|)/(2L) <= 0.707", std::sqrt(0.5)},
      {"PPC", [](auto& a, auto& b) { return ppc_line(a, b); }, ppc_line_error_bound, false,
       "|dx|+|dy|", [](int64_t dx, int64_t dy) { return double(mag(dx) + mag(dy)); }, "< 1", 1.0},
      {"DDA plain", [](auto& a, auto& b) { return dda_step_path(a, b, Preload::kZero); },
       [](auto&, auto&) { return dda_error_bound(2, Preload::kZero).value; }, true, "2^n",
       dda_ticks, "< 1", 1.0},
      {"DDA half", [](auto& a, auto& b) { return dda_step_path(a, b, Preload::kHalf); },
       [](auto&, auto&) { return dda_error_bound(2, Preload::kHalf).value; }, false, "2^n",
       dda_ticks, "about 0.70", std::sqrt(0.5)},
      {"min deviation", min_deviation_line, min_deviation_error_bound, false, "max(|dx|,|dy|)",
       maxd, "<= 0.5", 0.5},
      {"Bresenham", bresenham_line, min_deviation_error_bound, false, "max(|dx|,|dy|)", maxd,
       "<= 0.5", 0.5},
  };
}

struct Check {
  bool pulses, end, bound, ticks;
  double error;
  bool all() const { return pulses && end && bound && ticks; }
};

Check check(const Method& m, const LatticePoint& a, const LatticePoint& b) {
  const StepPath p = m.run(a, b);
  const int64_t dx = b[0] - a[0], dy = b[1] - a[1];
  Check c;
  const auto n = p.pulses();
  c.pulses = n[0] == uint64_t(mag(dx)) && n[1] == uint64_t(mag(dy));
  c.end = p.ends_on_end();
  c.error = p.line_error().max_error;
  const double bnd = m.bound(a, b);
  c.bound = m.strict ? c.error < bnd + 1e-12 : c.error <= bnd + 1e-12;
  c.ticks = p.ticks == m.ticks(dx, dy);
  return c;
}

std::string line_name(const std::array<int64_t, 4>& l) {
  return "(" + std::to_string(l[0]) + "," + std::to_string(l[1]) + ")->(" + std::to_string(l[2]) +
         "," + std::to_string(l[3]) + ")";
}

// One of the paper's lines on a core's hardware (HLS core and RTL in lockstep
// against the core's model): the line's delta twice, back to back, at feed
// 1/2 with 1-clock pulse, space, setup and hold, so that no tick ever waits
// for the step stage and one engine tick takes exactly 2 clocks. The second
// command runs in steady state (its predecessor's setup overlapped), so the
// clocks between the two done_o pulses are 2 ticks per engine tick: the
// completion in ticks, read at the pins.
struct CoreLine {
  double error = 0;  // over both copies (the same path, translated)
  double ticks = 0;
  bool ok = false;  // lockstep clean, exact counts and end, within the core's bound
};

CoreLine core_line(const std::string& core, const std::string& setup,
                   const std::array<int64_t, 4>& l) {
  const std::string move =
      "move " + std::to_string(l[2] - l[0]) + " " + std::to_string(l[3] - l[1]) + "\n";
  const HardwareRun hw =
      run_hardware(core, "start " + std::to_string(l[0]) + " " + std::to_string(l[1]) +
                             "\nfeed 0.5\nstep_len 1\nstep_space 1\ndir_setup 1\ndir_hold 1\n" +
                             setup + move + move);
  const tb::CaseResult& r = hw.result;
  CoreLine c;
  c.error = r.max_path_error_steps;
  c.ok = r.passed() && r.done_cycles.size() == 2 && r.steps[0] == 2 * uint64_t(mag(l[2] - l[0])) &&
         r.steps[1] == 2 * uint64_t(mag(l[3] - l[1]));
  if (r.done_cycles.size() == 2) c.ticks = double(r.done_cycles[1] - r.done_cycles[0]) / 2;
  return c;
}

PaperReproduction reproduce_ratio() {
  PaperReproduction out;
  FigureRows rows;
  const std::vector<Method> all = methods();

  // The eight test lines through every method.
  TextTable lines({"line", "method", "pulses x,y", "end", "max error", "bound", "ticks", "ok"});
  Json line_json = Json::array();
  int checked = 0, passed = 0;
  double fixed_worst = 0;
  for (size_t li = 0; li < pd::kRatioLines.size(); ++li) {
    const auto& l = pd::kRatioLines[li];
    const LatticePoint a{l[0], l[1]}, b{l[2], l[3]};
    for (const Method& m : all) {
      const StepPath p = m.run(a, b);
      const Check c = check(m, a, b);
      ++checked;
      passed += c.all();
      if (m.name == "fixed ratio") fixed_worst = std::max(fixed_worst, c.error);
      const auto n = p.pulses();
      lines.add_row({"L" + std::to_string(li + 1) + " " + line_name(l), m.name,
                     std::to_string(n[0]) + "," + std::to_string(n[1]), c.end ? "yes" : "NO",
                     fmt("%.4f", c.error), fmt("%.4f", m.bound(a, b)),
                     fmt("%.0f", p.ticks) + " (" + m.ticks_rule + ")", c.all() ? "yes" : "NO"});
      Json o = Json::object();
      o["line"] = int(li + 1);
      o["method"] = m.name;
      o["pulses"] = Json(std::vector<uint64_t>{n[0], n[1]});
      o["ends_on_end"] = c.end;
      o["max_error"] = c.error;
      o["bound"] = m.bound(a, b);
      o["ticks"] = p.ticks;
      o["ok"] = c.all();
      line_json.push_back(std::move(o));
    }
  }
  rows.add("eight lines x 6 methods: |dx|,|dy| pulses, end point, error bound, ticks",
           std::to_string(checked) + " of " + std::to_string(checked),
           std::to_string(passed) + " of " + std::to_string(checked), passed == checked);
  rows.add("fixed ratio on the 8 lines: error < 1 step (Fig. 3)", "< 1", fmt("%.4f", fixed_worst),
           fixed_worst < 1);

  // Bounds over every line with |dx|, |dy| <= 40.
  std::vector<double> worst(all.size(), 0);
  bool exhaustive_ok = true;
  for (int64_t dx = -40; dx <= 40; ++dx)
    for (int64_t dy = -40; dy <= 40; ++dy)
      for (size_t i = 0; i < all.size(); ++i) {
        const Check c = check(all[i], {0, 0}, {dx, dy});
        exhaustive_ok = exhaustive_ok && c.all();
        worst[i] = std::max(worst[i], c.error);
      }
  Json bounds = Json::object();
  for (size_t i = 0; i < all.size(); ++i) {
    const Method& m = all[i];
    const bool within =
        m.accepted_value == 1.0 ? worst[i] < 1.0 : worst[i] <= m.accepted_value + 1e-12;
    rows.add("all |dx|,|dy| <= 40: " + m.name + " worst error", m.accepted, fmt("%.4f", worst[i]),
             within);
    bounds[m.name] = worst[i];
  }
  rows.add("all |dx|,|dy| <= 40: every method exact counts, end, own bound, ticks", "yes",
           exhaustive_ok ? "yes" : "no", exhaustive_ok);

  const auto& l1 = pd::kRatioLines[0];
  const StepPath ppc1 = models::ppc_line({l1[0], l1[1]}, {l1[2], l1[3]});
  rows.add("PPC operations on line 1", std::to_string(pd::kPpcOperationsLine1),
           std::to_string(ppc1.operations), ppc1.operations == uint64_t(pd::kPpcOperationsLine1));
  // The hardware: one operation (test, step, update) per engine tick, so the
  // steps are the operations. At feed 1/2 with 1-clock pulse, space, setup
  // and hold no operation ever waits for the step stage: the line takes
  // exactly 2 clocks an operation (+ reset 2, take 1, load 1, the last
  // pulse's fall 1, tail 2: tests/tb/ppc_line_test.cpp).
  const HardwareRun hw1 = run_hardware(
      "ppc_line", "start " + std::to_string(l1[0]) + " " + std::to_string(l1[1]) +
                      "\nfeed 0.5\nstep_len 1\nstep_space 1\ndir_setup 1\ndir_hold 1\nline " +
                      std::to_string(l1[2]) + " " + std::to_string(l1[3]) + "\n");
  const uint64_t hw_ops = hw1.result.steps[0] + hw1.result.steps[1];
  rows.add("PPC operations on line 1, hardware " + hw1.variant + " (engine ticks)",
           std::to_string(pd::kPpcOperationsLine1), std::to_string(hw_ops),
           hw_ops == uint64_t(pd::kPpcOperationsLine1) && hw1.result.passed());
  rows.add("  its clocks at feed 1/2: 2 per operation + 7", std::to_string(2 * hw_ops + 7),
           std::to_string(hw1.result.cycles), hw1.result.cycles == 2 * hw_ops + 7);
  const StepPath fr1 = models::fixed_ratio_line({l1[0], l1[1]}, {l1[2], l1[3]});
  rows.add("fixed ratio operations on line 1", "1", std::to_string(fr1.operations),
           fr1.operations == 1);

  // Integer clock dividers at 1 MHz.
  const double clk = 1e6, v = pd::kRatioVelocity;
  TextTable div({"line", "half periods x,y (clocks)", "f x,y (kHz)", "wanted (kHz)", "max error",
                 "bound at 1 MHz", "exact-f bound", "ok"});
  Json div_json = Json::array();
  bool div_ok = true;
  double line1_div = 0;
  for (size_t li = 0; li < pd::kRatioLines.size(); ++li) {
    const auto& l = pd::kRatioLines[li];
    const LatticePoint a{l[0], l[1]}, b{l[2], l[3]};
    const auto plan = models::fixed_ratio_divider_plan(a, b, v, clk);
    const StepPath p = models::fixed_ratio_divider_line(a, b, v, clk);
    const double e = p.line_error().max_error;
    const double bnd = models::fixed_ratio_divider_bound(a, b, v, clk);
    const auto n = p.pulses();
    const bool ok = e <= bnd + 1e-12 && p.ends_on_end() && n[0] == uint64_t(mag(l[2] - l[0])) &&
                    n[1] == uint64_t(mag(l[3] - l[1]));
    div_ok = div_ok && ok;
    if (li == 0) line1_div = e;
    div.add_row(
        {"L" + std::to_string(li + 1),
         std::to_string(plan.half_period[0]) + "," + std::to_string(plan.half_period[1]),
         fmt("%.1f", plan.frequency_hz[0] / 1e3) + "," + fmt("%.1f", plan.frequency_hz[1] / 1e3),
         fmt("%.1f", v * double(mag(l[2] - l[0])) / 1e3) + "," +
             fmt("%.1f", v * double(mag(l[3] - l[1])) / 1e3),
         fmt("%.4f", e), fmt("%.4f", bnd), fmt("%.4f", models::fixed_ratio_error_bound(a, b)),
         ok ? "yes" : "NO"});
    div_json.push_back(Json({{"line", int(li + 1)},
                             {"half_period_x", plan.half_period[0]},
                             {"half_period_y", plan.half_period[1]},
                             {"max_error", e},
                             {"bound", bnd},
                             {"ok", ok}}));
  }
  rows.add("integer dividers at 1 MHz: line 1 error (reproduced)", "3.1", fmt("%.4f", line1_div),
           std::abs(line1_div - 3.1) < 0.05);
  rows.add("integer dividers at 1 MHz: 8 lines within the divider bound", "yes",
           div_ok ? "yes" : "no", div_ok);

  // The same eight lines on the hardware cores, beside the exact-frequency
  // and integer-divider models: error (steps) / completion (ticks).
  // Each core is checked against its own model: fixed_ratio against its
  // bit-exact model at the variant's FRAC_W (a tick's steps merged into one
  // move, so its points are a subset of the exact-frequency generator's:
  // fewer, never farther), dda_line and ppc_line against the 004 models.
  struct CoreColumn {
    std::string core, setup, title, model_name;
    std::function<StepPath(const LatticePoint&, const LatticePoint&)> model;
  };
  const auto fixed_ratio_hw = [](const LatticePoint& a, const LatticePoint& b) {
    const std::vector<int64_t> d{b[0] - a[0], b[1] - a[1]};
    StepPath p;
    p.start = a;
    p.end = b;
    p.ticks = double(models::fixed_ratio_ticks(d));
    for (const auto& m : models::fixed_ratio_hw_moves(a, d, fixed_ratio_n2_cfg::FRAC_W))
      p.moves.push_back({double(m.tick), {m.step[0], m.step[1]}, m.point});
    return p;
  };
  const std::vector<CoreColumn> cores = {
      {"fixed_ratio", "", "fixed_ratio", "its model (max(|dx|,|dy|))", fixed_ratio_hw},
      {"dda_line", "preload zero\n", "dda_line", all[2].name + " (2^n)", all[2].run},
      {"dda_line", "preload half\n", "dda_line half", all[3].name + " (2^n)", all[3].run},
      {"ppc_line", "", "ppc_line", all[1].name + " (|dx|+|dy|)", all[1].run},
  };
  TextTable hw({"line", "paper", "exact f", "dividers 1 MHz", "fixed_ratio", "dda_line",
                "dda_line half", "ppc_line"});
  Json hw_json = Json::array();
  std::vector<double> core_worst(cores.size(), 0);
  std::vector<bool> core_ok(cores.size(), true);
  for (size_t li = 0; li < pd::kRatioLines.size(); ++li) {
    const auto& l = pd::kRatioLines[li];
    const LatticePoint a{l[0], l[1]}, b{l[2], l[3]};
    const auto cell = [](double e, double t) { return fmt("%.4f", e) + " / " + fmt("%.1f", t); };
    const StepPath exact = models::fixed_ratio_line(a, b);
    const auto plan = models::fixed_ratio_divider_plan(a, b, v, clk);
    const StepPath divided = models::fixed_ratio_divider_line(a, b, v, clk);
    const double div_ticks = double(plan.completion_clocks) / plan.tick_clocks;
    std::vector<std::string> row = {"L" + std::to_string(li + 1),
                                    "< 1 / " + fmt("%.0f", exact.ticks),
                                    cell(exact.line_error().max_error, exact.ticks),
                                    cell(divided.line_error().max_error, div_ticks)};
    Json o = Json::object();
    o["line"] = int(li + 1);
    o["exact_frequency"] = {{"max_error", exact.line_error().max_error}, {"ticks", exact.ticks}};
    o["dividers_1mhz"] = {{"max_error", divided.line_error().max_error}, {"ticks", div_ticks}};
    for (size_t ci = 0; ci < cores.size(); ++ci) {
      const CoreColumn& col = cores[ci];
      const CoreLine c = core_line(col.core, col.setup, l);
      const StepPath model = col.model(a, b);
      const bool same =
          c.ok && std::abs(c.error - model.line_error().max_error) < 1e-9 && c.ticks == model.ticks;
      core_ok[ci] = core_ok[ci] && same;
      core_worst[ci] = std::max(core_worst[ci], c.error);
      row.push_back(cell(c.error, c.ticks) + (same ? "" : " NO"));
      o[col.title] = {{"max_error", c.error}, {"ticks", c.ticks}, {"equals_model", same}};
    }
    hw.add_row(row);
    hw_json.push_back(std::move(o));
  }
  for (size_t ci = 0; ci < cores.size(); ++ci)
    rows.add("hardware " + cores[ci].title + " on the 8 lines: clean lockstep, error and ticks " +
                 "of " + cores[ci].model_name,
             "equal", core_ok[ci] ? "equal, worst " + fmt("%.4f", core_worst[ci]) : "differ",
             core_ok[ci]);

  out.ok = rows.ok();
  out.text =
      rows.text() +
      "\nThe eight lines (error = normal distance of visited lattice points, steps):\n" +
      lines.render() +
      "\nFixed ratio with integer clock dividers at 1 MHz, v = 5000 (half period "
      "H = round(f_clk / (2 v |d|)); bound [(|dx|+|dy|)/2 + t1 |dy/(2Hx) - dx/(2Hy)|] / L):\n" +
      div.render() +
      "\nThe eight lines on the hardware cores (HLS core and RTL in lockstep, feed 1/2, "
      "1-clock timing; ticks from the clocks between two done_o pulses), beside the models: "
      "max error (steps) / completion (ticks):\n" +
      hw.render();
  out.json["rows"] = rows.json();
  out.json["lines"] = std::move(line_json);
  out.json["worst_up_to_40"] = std::move(bounds);
  out.json["divider_1mhz"] = std::move(div_json);
  out.json["hardware"] = std::move(hw_json);
  return out;
}

}  // namespace

HWINTERP_PAPER("ratio", "004 fixed-ratio velocity synthesis vs PPC, DDA, minimum deviation", 40,
               reproduce_ratio);

}  // namespace hwinterp::cli

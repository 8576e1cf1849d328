// hwinterp regress: the project's main job. For every variant of a core, in
// both lockstep modes: the eight test lines of 004_dc68f1177cad466f.txt with
// plain and half preload, and a seeded random stream. Prints a summary table,
// writes the JSON report, exits 1 if anything failed.
#include <chrono>
#include <iostream>
#include <memory>

#include "cosim_report.h"
#include "dda_line_cosim.h"
#include "subcommand.h"
#include "text_table.h"

namespace hwinterp::cli {

namespace {

struct Run {
  std::string variant, mode;
  std::unique_ptr<tb::DdaLineBench> bench;
  double seconds = 0;
};

std::vector<tb::DdaLineCase> regression_cases(const tb::DdaLineLimits& limits, uint64_t commands,
                                              uint64_t seed) {
  tb::DdaLineSettings plain = tb::default_settings(limits), half = plain;
  half.half_preload = true;
  std::vector<tb::DdaLineCase> cases = tb::paper_lines_004(limits, plain);
  for (auto c : tb::paper_lines_004(limits, half)) {
    c.name += "_half";
    cases.push_back(std::move(c));
  }
  if (commands) cases.push_back(tb::random_case(limits, commands, seed));
  for (const auto& c : cases) tb::validate_case(c, limits);
  return cases;
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int run_regress(int argc, char** argv, int first) {
  Args args("regress",
            "The main regression: for every variant of the core and both lockstep modes, the\n"
            "eight test lines of 004_dc68f1177cad466f.txt (plain and half preload) and a\n"
            "seeded random command stream. Summary table on stdout, JSON with --json.");
  args.option("core", "NAME", "the core (dda_line)", "dda_line")
      .option("random", "N", "commands in the random stream per variant (0: none)", "300")
      .option("seed", "S", "seed of the random stream", "1")
      .option("modes", "LIST", "comma-separated lockstep modes", "direct,systemc")
      .option("progress", "N", "progress line every N clock edges per run (0: none)", "2000000");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;
  const std::string core = args.choice("core", {"dda_line"});
  const uint64_t commands = static_cast<uint64_t>(args.integer("random", 0, 10000000));
  const uint64_t seed = args.seed("seed");
  const uint64_t progress = static_cast<uint64_t>(args.integer("progress", 0, INT64_MAX));
  bool direct = false, systemc = false;
  {
    std::string list = args.str("modes") + ",", m;
    for (char c : list) {
      if (c != ',') {
        m += c;
        continue;
      }
      if (m == "direct")
        direct = true;
      else if (m == "systemc")
        systemc = true;
      else
        throw UsageError("--modes: unknown mode '" + m + "' (direct, systemc)");
      m.clear();
    }
  }

  std::cout << "hwinterp regress: " << core << ", random stream of " << commands
            << " commands, seed " << seed << "\n"
            << std::flush;
  std::vector<Run> runs;
  for (const std::string& variant : tb::dda_line_variants()) {
    const tb::DdaLineLimits limits = tb::dda_line_limits(variant);
    for (const char* mode : {"direct", "systemc"}) {
      if ((mode == std::string("direct") && !direct) ||
          (mode == std::string("systemc") && !systemc))
        continue;
      tb::BenchOptions o;
      o.mode = mode;
      o.seed = seed;
      o.progress_every = progress;
      runs.push_back({variant, mode,
                      std::make_unique<tb::DdaLineBench>(
                          limits, regression_cases(limits, commands, seed), o)});
    }
  }
  // Direct runs one after the other; SystemC runs side by side in the one
  // elaboration a process may have.
  std::vector<std::pair<std::string, tb::DdaLineBench*>> sc_benches;
  for (auto& r : runs) {
    if (r.mode != "direct") {
      sc_benches.emplace_back(r.variant, r.bench.get());
      continue;
    }
    std::cout << "  running " << r.variant << " direct ...\n" << std::flush;
    const double t0 = now();
    tb::run_dda_line_direct(r.variant, *r.bench);
    r.seconds = now() - t0;
  }
  if (!sc_benches.empty()) {
    std::cout << "  running " << sc_benches.size() << " variant(s) in one SystemC elaboration ...\n"
              << std::flush;
    const double t0 = now();
    tb::run_dda_line_systemc(sc_benches);
    for (auto& r : runs)
      if (r.mode == "systemc") r.seconds = now() - t0;  // shared: they ran side by side
  }

  std::vector<tb::CaseResult> all;
  Json report = Json::object();
  report.set("core", core);
  report.set("seed", seed);
  report.set("random_commands", commands);
  Json jruns = Json::array();
  TextTable totals({"variant", "mode", "cases", "cycles", "seconds", "cycles/s", "result"});
  bool ok = true;
  for (const auto& r : runs) {
    const auto& res = r.bench->results();
    const bool pass = tb::all_passed(res);
    ok = ok && pass;
    all.insert(all.end(), res.begin(), res.end());
    Json j = tb::aggregate_json(res);
    j.set("seconds", r.seconds);
    const double rate = r.seconds > 0 ? static_cast<double>(r.bench->cycles()) / r.seconds : 0;
    j.set("cycles_per_second", rate);
    jruns.push(std::move(j));
    totals.add_row({r.variant, r.mode, std::to_string(res.size()),
                    std::to_string(r.bench->cycles()), fmt("%.2f", r.seconds), fmt("%.3g", rate),
                    pass ? "pass" : "FAIL"});
  }
  report.set("runs", std::move(jruns));
  report.set("passed", ok);
  std::cout << "\n" << tb::case_table(all) << "\n" << totals.render() << tb::failure_details(all);
  std::cout << "(SystemC runs share one elaboration: their seconds are the elaboration's)\n";
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  maybe_write_json(args, report);
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("regress", "the main regression of a core: paper lines + random, both modes",
                    20, run_regress);

}  // namespace hwinterp::cli

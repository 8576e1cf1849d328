// hwinterp regress: the project's main job. For every core and variant
// (cmake/cores.cmake), in both lockstep modes: the core's regression cases
// (the papers' figures, a seeded random stream, a random stream with aborts
// and feed holds). Prints a table per case and per run, writes the JSON
// report, exits 1 if anything failed.
#include <chrono>
#include <iostream>
#include <memory>

#include "tb/cli/subcommand.h"
#include "tb/cli/text_table.h"
#include "tb/lockstep/registry.h"
#include "tb/report/cosim_report.h"

namespace hwinterp::cli {

namespace {

struct Run {
  std::string core, variant, mode;
  std::unique_ptr<tb::BenchRun> bench;
  double seconds = 0;
};

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::string item;
  for (const char c : text + ",") {
    if (c != ',') {
      item += c;
    } else if (!item.empty()) {
      out.push_back(item);
      item.clear();
    }
  }
  return out;
}

int run_regress(int argc, char** argv, int first) {
  Args args("regress",
            "The main regression: for every core and variant (or those given) and both\n"
            "lockstep modes, the core's regression cases: the papers' figures, a seeded\n"
            "random stream, and a random stream with aborts and feed holds. Summary\n"
            "tables on stdout, JSON with --json.\nCores: " +
                tb::core_list());
  args.option("cores", "LIST", "comma-separated cores (default: all)")
      .option("random", "N", "commands in each random stream (0: none)", "300")
      .option("seed", "S", "seed of the random streams", "1")
      .option("modes", "LIST", "comma-separated lockstep modes", "direct,systemc")
      .option("progress", "N", "progress line every N clock edges per run (0: none)", "2000000");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;
  const uint64_t commands = static_cast<uint64_t>(args.integer("random", 0, 10000000));
  const uint64_t seed = args.seed("seed");
  const uint64_t progress = static_cast<uint64_t>(args.integer("progress", 0, INT64_MAX));
  std::vector<const tb::CoreEntry*> cores;
  if (args.given("cores")) {
    for (const auto& name : split_list(args.str("cores"))) cores.push_back(&tb::find_core(name));
    if (cores.empty()) throw UsageError("--cores: '" + args.str("cores") + "' names no core");
  } else {
    for (const auto& c : tb::all_cores()) cores.push_back(&c);
  }
  bool direct = false, systemc = false;
  for (const auto& m : split_list(args.str("modes"))) {
    if (m == "direct")
      direct = true;
    else if (m == "systemc")
      systemc = true;
    else
      throw UsageError("--modes: unknown mode '" + m + "' (direct, systemc)");
  }
  if (!direct && !systemc) throw UsageError("--modes: '" + args.str("modes") + "' names no mode");

  std::cout << "hwinterp regress: " << cores.size() << " core(s), random streams of " << commands
            << " commands, seed " << seed << "\n"
            << std::flush;
  std::vector<Run> runs;
  for (const tb::CoreEntry* core : cores) {
    for (const tb::VariantEntry& v : core->variants) {
      for (const char* mode : {"direct", "systemc"}) {
        if ((mode == std::string("direct") && !direct) ||
            (mode == std::string("systemc") && !systemc))
          continue;
        tb::BenchOptions o;
        o.mode = mode;
        o.seed = seed;
        o.progress_every = progress;
        runs.push_back({core->name, v.limits.variant, mode, v.regression(commands, seed, o)});
      }
    }
  }
  // Direct runs one after the other; SystemC runs side by side in the one
  // elaboration a process may have.
  std::vector<tb::BenchRun*> sc_runs;
  for (auto& r : runs) {
    if (r.mode != "direct") {
      sc_runs.push_back(r.bench.get());
      continue;
    }
    std::cout << "  running " << r.variant << " direct ...\n" << std::flush;
    const double t0 = now();
    r.bench->run_direct();
    r.seconds = now() - t0;
  }
  if (!sc_runs.empty()) {
    std::cout << "  running " << sc_runs.size() << " variant(s) in one SystemC elaboration ...\n"
              << std::flush;
    const double t0 = now();
    tb::run_systemc(sc_runs);
    for (auto& r : runs)
      if (r.mode == "systemc") r.seconds = now() - t0;  // shared: they ran side by side
  }

  std::vector<tb::CaseResult> all;
  Json report;
  report["seed"] = seed;
  report["random_commands"] = commands;
  Json jcores = Json::object();
  Json jruns = Json::array();
  TextTable totals({"core", "variant", "mode", "cases", "cycles", "seconds", "cycles/s", "result"});
  bool ok = true;
  for (const auto& r : runs) {
    const auto& res = r.bench->results();
    const bool pass = tb::all_passed(res);
    ok = ok && pass;
    all.insert(all.end(), res.begin(), res.end());
    Json j = tb::aggregate_json(res);
    j["seconds"] = r.seconds;
    const double rate = r.seconds > 0 ? static_cast<double>(r.bench->cycles()) / r.seconds : 0;
    j["cycles_per_second"] = rate;
    jruns.push_back(j);
    Json& jc = jcores[r.core];
    if (jc.is_null()) jc = {{"passed", true}, {"runs", 0}, {"cases", 0}, {"cycles", 0}};
    jc["passed"] = jc["passed"].get<bool>() && pass;
    jc["runs"] = jc["runs"].get<uint64_t>() + 1;
    jc["cases"] = jc["cases"].get<uint64_t>() + res.size();
    jc["cycles"] = jc["cycles"].get<uint64_t>() + r.bench->cycles();
    totals.add_row({r.core, r.variant, r.mode, std::to_string(res.size()),
                    std::to_string(r.bench->cycles()), fmt("%.2f", r.seconds), fmt("%.3g", rate),
                    pass ? "pass" : "FAIL"});
  }
  report["cores"] = std::move(jcores);
  report["runs"] = std::move(jruns);
  report["passed"] = ok;
  std::cout << "\n" << tb::case_table(all) << "\n" << totals.render() << tb::failure_details(all);
  std::cout << "(SystemC runs share one elaboration: their seconds are the elaboration's)\n";
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  maybe_write_json(args, report);
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("regress", "the main regression: every core and variant, both modes", 20,
                    run_regress);

}  // namespace hwinterp::cli

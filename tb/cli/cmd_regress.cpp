// hwinterp regress: the project's main job. For every core and variant
// (cmake/cores.cmake), in both lockstep modes: the core's regression cases
// (the papers' figures, a seeded random stream, a random stream with aborts
// and feed holds). Prints a table per case and per run, writes the JSON (and
// JUnit) report, exits 1 if anything failed.
//
// --shard K/N runs a deterministic slice: the cases of all runs numbered in
// order (core, variant, mode, case), those whose number is K-1 modulo N.
// `hwinterp merge` joins the shards' reports into the unsharded run's report.
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>

#include "tb/cli/subcommand.h"
#include "tb/lockstep/registry.h"
#include "tb/report/cosim_report.h"
#include "tb/report/regress_report.h"

namespace hwinterp::cli {

namespace {

struct Run {
  std::string core, variant, mode;
  uint64_t first_case;  // the number of the run's first case, all runs numbered in order
  std::unique_ptr<tb::BenchRun> bench;
  double seconds = 0;
};

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The list's items, empty ones left out.
std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  for (std::string& item : split_commas(text))
    if (!item.empty()) out.push_back(std::move(item));
  return out;
}

// "K/N" with 1 <= K <= N.
std::pair<uint64_t, uint64_t> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw UsageError("--shard: '" + text + "' is not K/N (e.g. 2/4)");
  const int64_t k = parse_integer(text.substr(0, slash), "--shard " + text + ": K");
  const int64_t n = parse_integer(text.substr(slash + 1), "--shard " + text + ": N");
  if (n < 1 || k < 1 || k > n) throw UsageError("--shard: '" + text + "' needs 1 <= K <= N");
  return {static_cast<uint64_t>(k), static_cast<uint64_t>(n)};
}

int run_regress(int argc, char** argv, int first) {
  Args args("regress",
            "The main regression: for every core and variant (or those given) and both\n"
            "lockstep modes, the core's regression cases: the papers' figures, a seeded\n"
            "random stream, and a random stream with aborts and feed holds. Summary\n"
            "tables on stdout, JSON with --json, JUnit with --junit.\nCores: " +
                tb::core_list());
  args.option("cores", "LIST", "comma-separated cores (default: all)")
      .option("random", "N", "commands in each random stream (0: none)", "300")
      .option("seed", "S", "seed of the random streams", "1")
      .option("modes", "LIST", "comma-separated lockstep modes", "direct,systemc")
      .option("shard", "K/N", "run the K-th of N deterministic slices (hwinterp merge joins them)")
      .option("junit", "FILE", "write a JUnit report (a testcase per case)")
      .option("progress", "N", "progress line every N clock edges per run (0: none)", "2000000");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;
  const uint64_t commands = static_cast<uint64_t>(args.integer("random", 0, 10000000));
  const uint64_t seed = args.seed("seed");
  const uint64_t progress = static_cast<uint64_t>(args.integer("progress", 0, INT64_MAX));
  const auto [shard_k, shard_n] =
      args.given("shard") ? parse_shard(args.str("shard")) : std::pair<uint64_t, uint64_t>{1, 1};
  stage_outputs(args, {"junit"});
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
            << " commands, seed " << seed;
  if (shard_n > 1) std::cout << ", shard " << shard_k << " of " << shard_n;
  std::cout << "\n" << std::flush;
  std::vector<Run> runs;
  uint64_t number = 0;  // cases numbered across all runs, in order
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
        const uint64_t base = number;
        number += v.regression_size(commands);
        auto keep = [base, k = shard_k, n = shard_n](uint64_t i) {
          return (base + i) % n == k - 1;
        };
        if (auto run = v.regression(commands, seed, o, keep))
          runs.push_back({core->name, v.spec.variant, mode, base, std::move(run)});
      }
    }
  }
  // Direct runs one after the other; SystemC runs side by side in the one
  // elaboration a process may have.
  std::vector<tb::BenchRun*> sc_runs;
  size_t direct_done = 0;
  const size_t direct_runs = static_cast<size_t>(
      std::count_if(runs.begin(), runs.end(), [](const Run& r) { return r.mode == "direct"; }));
  for (auto& r : runs) {
    if (r.mode != "direct") {
      sc_runs.push_back(r.bench.get());
      continue;
    }
    std::cout << "  running " << r.variant << " direct (run " << ++direct_done << " of "
              << direct_runs << ") ...\n"
              << std::flush;
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
  std::vector<tb::RegressRun> report_runs;
  for (const auto& r : runs) {
    const auto& res = r.bench->results();
    all.insert(all.end(), res.begin(), res.end());
    tb::RegressRun rr{r.core, r.variant, r.mode, r.first_case, r.seconds, {}};
    for (const auto& c : res) rr.cases.push_back(c.to_json());
    report_runs.push_back(std::move(rr));
  }
  const Json report = tb::regress_report(report_runs, seed, commands,
                                         {std::to_string(shard_k) + "/" + std::to_string(shard_n)});
  const bool ok = report["passed"].get<bool>();
  std::cout << "\n"
            << tb::case_table(all) << "\n"
            << tb::runs_table(report) << tb::failure_details(all);
  std::cout << "(SystemC runs share one elaboration: their seconds are the elaboration's)\n";
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  maybe_write_json(args, report);
  if (args.given("junit")) write_text_file(output_path("junit"), tb::junit_xml(report), "--junit");
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("regress", "the main regression: every core and variant, both modes", 20,
                    run_regress);

}  // namespace hwinterp::cli

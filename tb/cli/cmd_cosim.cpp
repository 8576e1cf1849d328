// hwinterp cosim: one lockstep co-simulation of any core (HLS vs RTL, both vs
// the reference model), from the core's own stimulus options, a job file or
// a seeded random stream, in the SystemC or the direct mode. The cores and
// their variants come from the registry (cmake/cores.cmake); this file knows
// none of them.
#include <cstring>
#include <iostream>
#include <memory>
#include <random>

#include "tb/cli/subcommand.h"
#include "tb/lockstep/registry.h"
#include "tb/report/cosim_report.h"
#include "tb/report/output_path.h"
#include "tb/stimulus/from_args.h"

namespace hwinterp::cli {

namespace {

std::string shell_quote(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789-_./=,:@") == std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The command that replays this run exactly, with a trace of the last cycles.
std::string replay_command(int argc, char** argv, int first, const Args& args, uint64_t seed) {
  std::string cmd = "hwinterp cosim";
  for (int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json" || a == "--vcd" || a == "--fst" || a == "--trace-window") {
      ++i;  // replaced below
      continue;
    }
    if (a.rfind("--json=", 0) == 0 || a.rfind("--vcd=", 0) == 0 || a.rfind("--fst=", 0) == 0 ||
        a.rfind("--trace-window=", 0) == 0)
      continue;
    cmd += " " + shell_quote(a);
  }
  if (args.given("random") && !args.given("seed")) cmd += " --seed " + std::to_string(seed);
  return cmd + " --vcd mismatch.vcd --trace-window 200";
}

// "KIND@CYCLE" for the --inject test hook.
tb::FaultPlan parse_injection(const Args& args) {
  tb::FaultPlan plan;
  if (!args.given("inject")) return plan;
  const std::string v = args.str("inject");
  const auto at = v.find('@');
  const std::string kind = v.substr(0, at);
  if (at == std::string::npos || (kind != "mismatch" && kind != "glitch"))
    throw UsageError("--inject: '" + v + "' is not mismatch@CYCLE or glitch@CYCLE");
  const int64_t cycle = parse_integer(v.substr(at + 1), "--inject");
  if (cycle < 1) throw UsageError("--inject: cycle " + v.substr(at + 1) + " must be >= 1");
  (kind == "mismatch" ? plan.flip_hls_step_at : plan.glitch_step_at) = static_cast<uint64_t>(cycle);
  return plan;
}

// The --core value before the options are declared: the core's own options
// depend on it. Empty when absent.
std::string core_argument(int argc, char** argv, int first) {
  for (int i = first; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--core") && i + 1 < argc) return argv[i + 1];
    if (!std::strncmp(argv[i], "--core=", 7)) return argv[i] + 7;
  }
  return "";
}

int run_cosim(int argc, char** argv, int first) {
  Args args("cosim",
            "Lockstep co-simulation of a core: HLS and RTL compared on every clock, both\n"
            "checked against the reference model, step/dir timing monitored on every axis.\n"
            "Stimulus: exactly one of --job, --random or the core's own (see --core NAME --help).\n"
            "Cores and variants (cmake/cores.cmake): " +
                tb::core_list());
  tb::declare_cosim_options(args);
  const std::string core_name = core_argument(argc, argv, first);
  const tb::CoreEntry* core = nullptr;
  if (!core_name.empty()) {
    core = &tb::find_core(core_name);
    core->declare_options(args);
  }
  bool help = false;
  for (int i = first; i < argc; ++i) help = help || !std::strcmp(argv[i], "--help");
  if (!core && !help) throw UsageError("--core is required (cores: " + tb::core_list() + ")");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;

  const tb::VariantEntry& variant = core->select(args);
  const std::string mode = args.choice("mode", {"systemc", "direct"});
  int sources = args.given("job") + args.given("random");
  std::string source_names = "--job, --random";
  for (const auto& s : core->sources) {
    sources += args.given(s);
    source_names += ", --" + s;
  }
  if (sources != 1)
    throw UsageError("give exactly one of " + source_names + " (" + std::to_string(sources) +
                     " given)");
  for (const char* o : {"seed", "with-aborts", "with-holds"})
    if (args.given(o) && !args.given("random"))
      throw UsageError(std::string("--") + o + " goes with --random");

  tb::BenchOptions options;
  options.mode = mode;
  if (args.given("random"))
    options.seed = args.given("seed") ? args.seed("seed") : std::random_device{}();
  options.faults = parse_injection(args);
  trace_from_args(args, options);
  options.progress_every = static_cast<uint64_t>(args.integer("progress", 0, INT64_MAX));
  if (args.given("abort-at"))
    options.abort_at = static_cast<uint64_t>(args.integer("abort-at", 1, INT64_MAX));

  // Every output can be written and is neither the job file nor another
  // output, or nothing runs; each is put in place when the run completes.
  stage_outputs(args, {"vcd", "fst", "path-csv", "step-times", "dump-frames"}, {"job"});
  if (!options.trace_path.empty())
    options.trace_path = output_path(args.given("vcd") ? "vcd" : "fst");
  if (args.given("dump-frames")) {
    options.frames_path = output_path("dump-frames");
    const std::string tb_path = args.str("dump-frames") + ".sv";
    try {
      options.frames_testbench_path = outputs().stage("--dump-frames's testbench", tb_path);
    } catch (const std::exception& e) {
      throw UsageError(std::string("--dump-frames: ") + e.what());
    }
  }
  if (args.given("path-csv")) options.path_csv = output_path("path-csv");
  if (args.given("step-times")) options.step_times_path = output_path("step-times");
  // Validates the stimulus and opens every output file before the run.
  const std::unique_ptr<tb::BenchRun> run = variant.from_args(args, options);
  std::cout << "hwinterp cosim: " << core->name << " (" << variant.spec.variant << "), mode "
            << mode;
  if (args.given("random")) std::cout << ", seed " << options.seed;
  std::cout << ", " << run->case_count() << (run->case_count() == 1 ? " case\n" : " cases\n")
            << std::flush;
  if (mode == "direct")
    run->run_direct();
  else
    tb::run_systemc({run.get()});
  run->close();

  const auto& results = run->results();
  const bool ok = tb::all_passed(results);
  std::cout << tb::case_table(results) << tb::failure_details(results);
  Json report = tb::aggregate_json(results);
  if (!ok) {
    const std::string replay = replay_command(argc, argv, first, args, options.seed);
    std::cout << "replay: " << replay << "\n";
    report["replay"] = replay;
  }
  if (args.given("abort-at") && report["abort"].is_null())
    std::cout << "note: --abort-at " << args.str("abort-at") << " is past the run's "
              << run->cycles() << " clocks: no abort happened\n";
  if (!options.trace_path.empty())
    std::cout << "trace: " << args.str(args.given("vcd") ? "vcd" : "fst") << "\n";
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  maybe_write_json(args, report);
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("cosim", "lockstep co-simulation of a core (HLS vs RTL vs model)", 10,
                    run_cosim);

}  // namespace hwinterp::cli

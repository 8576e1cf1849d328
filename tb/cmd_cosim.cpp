// hwinterp cosim: one lockstep co-simulation of a core (HLS vs RTL, both vs
// the reference model), from a line, a job file, the paper's test lines or a
// seeded random stream, in the SystemC or the direct mode.
#include <iostream>
#include <memory>
#include <random>
#include <sstream>

#include "cosim_report.h"
#include "dda_line_cosim.h"
#include "subcommand.h"

namespace hwinterp::cli {

namespace {

using tb::DdaLineCase;
using tb::DdaLineLimits;
using tb::DdaLineSettings;

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

DdaLineSettings settings_from_flags(const Args& args, const DdaLineLimits& limits) {
  DdaLineSettings s = tb::default_settings(limits);
  if (args.given("feed")) {
    const std::string f = args.str("feed");
    if (f == "full") {
      s.feed = limits.full_feed();
    } else if (f.find('.') != std::string::npos) {
      const double frac = args.real("feed", 1e-12, 1.0);
      s.feed = static_cast<uint64_t>(std::llround(frac * static_cast<double>(limits.full_feed())));
    } else {
      s.feed = static_cast<uint64_t>(
          args.integer("feed", 1, static_cast<int64_t>(2 * limits.full_feed() - 1)));
    }
  }
  s.half_preload = args.given("half-preload");
  const int64_t tmax = (int64_t{1} << limits.tim_w) - 1;
  if (args.given("step-len"))
    s.timing.step_len = static_cast<uint32_t>(args.integer("step-len", 0, tmax));
  if (args.given("step-space"))
    s.timing.step_space = static_cast<uint32_t>(args.integer("step-space", 0, tmax));
  if (args.given("dir-setup"))
    s.timing.dir_setup = static_cast<uint32_t>(args.integer("dir-setup", 0, tmax));
  if (args.given("dir-hold"))
    s.timing.dir_hold = static_cast<uint32_t>(args.integer("dir-hold", 0, tmax));
  return s;
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

int run_cosim(int argc, char** argv, int first) {
  Args args("cosim",
            "Lockstep co-simulation of a core: HLS and RTL compared on every clock, both\n"
            "checked against the reference model, step/dir timing monitored on every axis.\n"
            "Stimulus: exactly one of --line, --job, --paper-lines, --random.");
  args.option("core", "NAME", "the core to simulate (dda_line)")
      .option("axes", "N", "variant by axis count (2 or 4)", "2")
      .option("line", "X0,Y0,..,X1,Y1,..",
              "one line: start then end coordinates (2k numbers, k <= axes)")
      .option("job", "FILE", "a job file (cases, lines, moves, settings; see README)")
      .flag("paper-lines", "the eight test lines of 004_dc68f1177cad466f.txt, one case each")
      .option("random", "N", "a seeded random stream of N commands")
      .option("seed", "S", "seed of --random (printed; a fresh one when omitted)")
      .option("mode", "MODE", "systemc (SC_MODULE + verilator --sc) or direct (tick() + --cc)",
              "systemc")
      .option("feed", "full|WORD|F", "feed: full, a feed word, or a clock fraction like 0.25")
      .flag("half-preload", "start the accumulators at one half (lower path error)")
      .option("step-len", "N", "step pulse length, clocks (default from the variant)")
      .option("step-space", "N", "minimum low time between steps, clocks")
      .option("dir-setup", "N", "dir setup before a step, clocks")
      .option("dir-hold", "N", "dir hold after a step, clocks")
      .option("vcd", "FILE", "write a VCD trace (inputs, HLS and RTL outputs)")
      .option("fst", "FILE", "write an FST trace (via vcd2fst)")
      .option("trace-window", "N", "trace only the last N cycles (e.g. before a mismatch)")
      .option("path-csv", "FILE",
              "write the lattice path (start, command targets, every move) as CSV for "
              "scripts/plot_dda_paths.py")
      .option("dump-frames", "FILE",
              "write the input frames, one hex line a clock, for replay in a Verilog simulator "
              "(tb/verilog/dda_line_replay_tb.sv)")
      .option("inject", "KIND@CYCLE",
              "test hook: mismatch@C flips the HLS step_o[0] before the comparison, "
              "glitch@C the observed step_o[0] after it");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;

  const std::string core = args.choice("core", {"dda_line"});
  const std::string variant =
      tb::dda_line_variant_for_axes(static_cast<int>(args.integer("axes", 1, tb::kMaxAxes)));
  const DdaLineLimits limits = tb::dda_line_limits(variant);
  const std::string mode = args.choice("mode", {"systemc", "direct"});
  const int sources =
      args.given("line") + args.given("job") + args.given("paper-lines") + args.given("random");
  if (sources != 1)
    throw UsageError("give exactly one of --line, --job, --paper-lines, --random (" +
                     std::to_string(sources) + " given)");
  if (args.given("seed") && !args.given("random"))
    throw UsageError("--seed " + args.str("seed") + " goes with --random");
  if (args.given("vcd") && args.given("fst")) throw UsageError("give one of --vcd and --fst");
  if (args.given("trace-window") && !args.given("vcd") && !args.given("fst"))
    throw UsageError("--trace-window " + args.str("trace-window") + " needs --vcd or --fst");

  const DdaLineSettings settings = settings_from_flags(args, limits);
  uint64_t seed = 0;
  std::vector<DdaLineCase> cases;
  if (args.given("line")) {
    const std::vector<int64_t> v = args.integer_list("line");
    if (v.size() < 2 || v.size() % 2)
      throw UsageError("--line: '" + args.str("line") +
                       "' needs start and end coordinates (2k numbers)");
    const size_t k = v.size() / 2;
    cases.push_back(tb::line_case(limits, "line", {v.begin(), v.begin() + k},
                                  {v.begin() + k, v.end()}, settings));
  } else if (args.given("job")) {
    cases = tb::parse_job(args.str("job"), limits, settings);
  } else if (args.given("paper-lines")) {
    cases = tb::paper_lines_004(limits, settings);
  } else {
    const int64_t n = args.integer("random", 1, 100000000);
    seed = args.given("seed") ? args.seed("seed") : std::random_device{}();
    cases.push_back(tb::random_case(limits, static_cast<uint64_t>(n), seed));
  }
  for (const auto& c : cases) tb::validate_case(c, limits);

  tb::BenchOptions options;
  options.mode = mode;
  options.seed = seed;
  options.faults = parse_injection(args);
  options.trace_path = args.given("vcd")   ? args.str("vcd")
                       : args.given("fst") ? args.str("fst")
                                           : "";
  if (args.given("dump-frames")) options.frames_path = args.str("dump-frames");
  if (args.given("path-csv")) options.path_csv = args.str("path-csv");
  if (args.given("trace-window"))
    options.trace_window = static_cast<uint64_t>(args.integer("trace-window", 1, 100000000));

  std::cout << "hwinterp cosim: " << core << " (" << variant << "), mode " << mode;
  if (args.given("random")) std::cout << ", seed " << seed;
  std::cout << ", " << cases.size() << (cases.size() == 1 ? " case\n" : " cases\n") << std::flush;

  // Output files are opened before the run, so a bad path costs no simulation.
  std::unique_ptr<tb::DdaLineBench> bench_owner;
  try {
    bench_owner = std::make_unique<tb::DdaLineBench>(limits, std::move(cases), options);
  } catch (const std::runtime_error& e) {
    throw UsageError(e.what());
  }
  tb::DdaLineBench& bench = *bench_owner;
  if (mode == "direct")
    tb::run_dda_line_direct(variant, bench);
  else
    tb::run_dda_line_systemc({{variant, &bench}});
  bench.close_trace();

  const auto& results = bench.results();
  const bool ok = tb::all_passed(results);
  std::cout << tb::case_table(results) << tb::failure_details(results);
  Json report = tb::aggregate_json(results);
  if (!ok) {
    const std::string replay = replay_command(argc, argv, first, args, seed);
    std::cout << "replay: " << replay << "\n";
    report.set("replay", replay);
  }
  if (!options.trace_path.empty()) std::cout << "trace: " << options.trace_path << "\n";
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  maybe_write_json(args, report);
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("cosim", "lockstep co-simulation of a core (HLS vs RTL vs model)", 10,
                    run_cosim);

}  // namespace hwinterp::cli

// hwinterp gcode: a part program through motion_top in lockstep
// (tb/gcode/part_program.h runs it: the compiler, the lockstep bench, the
// contour error and the end points). This file holds the argument handling:
// the options, their checks, the output files and the plot.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "models/feed_profile_model.h"
#include "tb/base/spawn.h"
#include "tb/base/text_table.h"
#include "tb/cli/subcommand.h"
#include "tb/gcode/part_program.h"
#include "tb/report/cosim_report.h"
#include "tb/report/output_path.h"

namespace hwinterp::cli {

namespace {

// Runs a plot script with the project's Python, an argument vector and no
// shell (any file name is an argument, never a command); on success names
// the PNG, else says the command that failed and discards the output
// `option` (an existing PNG is left as it was).
bool plot(const std::string& script, const std::vector<std::string>& arguments, const char* option,
          const std::string& png) {
  std::vector<std::string> argv{HWINTERP_PYTHON, script};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  std::string why;
  const int rc = spawn_and_wait(argv, /*quiet=*/true, &why);
  if (rc != 0) {
    std::cout << "plot: failed (" << quoted_command(argv) << ": "
              << (rc < 0 ? why : "exit " + std::to_string(rc)) << ")\n";
    outputs().discard(std::string("--") + option);
    return false;
  }
  std::cout << "plot: " << png << "\n";
  return true;
}

// The feed hold and the 0 % spans of the override stop the machine for
// their length, clock by clock: each, and their sum, within `max_clocks` at
// the machine's clock, and every time they name within the clock counter,
// or a UsageError naming the value (a hold of years would simulate for
// years; one of 1e300 s would overflow the count).
void check_pauses(const gcode::PartProgramSetup& setup, double max_clocks) {
  if (!(max_clocks >= 1 && max_clocks <= 1.8e19))
    throw UsageError("--max-clocks: " + fmt("%g", max_clocks) + " is outside 1..1.8e19");
  const double hz = static_cast<double>(setup.machine.clock_hz);
  const auto clocks = [&](double s) {
    return fmt("%.3g", s * hz) + " clocks at " + fmt("%g", hz) + " Hz";
  };
  const auto beyond = [&](const std::string& what, double s) {
    if (!(s * hz <= max_clocks))
      throw UsageError(what + " " + fmt("%g", s) + " s is " + clocks(s) + ", beyond --max-clocks " +
                       fmt("%g", max_clocks) + " (give a larger --max-clocks to simulate it)");
  };
  double paused = 0;
  if (setup.hold_at_s >= 0) {
    beyond("--feed-hold AT:", setup.hold_at_s);
    beyond("--feed-hold FOR:", setup.hold_for_s);
    paused += setup.hold_for_s;
  }
  const auto& o = setup.feed_override;
  for (size_t i = 0; i < o.size(); ++i) {
    beyond("--feed-override AT:", o[i].at_s);
    if (models::override_word(o[i].percent) == 0 && i + 1 < o.size())
      paused += o[i + 1].at_s - o[i].at_s;
  }
  beyond("the feed hold and the 0 % override spans stop the machine for", paused);
}

int run_gcode(int argc, char** argv, int first) {
  Args args(
      "gcode",
      "A part program through motion_top in lockstep (HLS vs RTL on every clock, both\n"
      "against the reference model), with the contour error of every visited lattice\n"
      "point against the programmed path.\n"
      "Usage: hwinterp gcode FILE.ngc [options]   or   hwinterp gcode --canon FILE [options]\n"
      "FILE.ngc: an RS274/NGC subset (G0-G3 with IJK or R, G17-G19, G20/G21, G90/G91,\n"
      "G90.1/G91.1, F; words that do not change the path are counted). Anything else\n"
      "exits 2 naming file, line and word: run the program through LinuxCNC's\n"
      "interpreter (rs274 -g FILE out.canon) and use --canon.");
  args.option("canon", "FILE", "read LinuxCNC's canonical commands (rs274 -g output) from FILE")
      .option("machine", "FILE",
              "machine description, JSON (tb/gcode/machine.h; default 1000 steps/mm, 50 MHz)")
      .option("variant", "NAME", "motion_top variant (default: the first with the machine's axes)")
      .option("mode", "systemc|direct", "lockstep mode", "systemc")
      .option("bus", "axi4lite|wishbone",
              "then run the program again through motion_soc's register interface (a bus "
              "master writing each command into its FIFO; with a profile, each command's "
              "planned move too, into a motion_soc built with the feed profile) and require "
              "the lockstep run's lattice points and end points (docs/soc.md)")
      .option("bus-waits", "N",
              "with --bus: random wait states, 0..N clocks, on the master's "
              "valid and ready signals",
              "0")
      .option("step-types", "T[,T...]",
              "with --bus: motion_soc's step output type (STEP_TYPE, rtl/step_encode.sv), "
              "stepdir, updown or quad, one for every axis or one per axis; the bus run "
              "decodes each axis's pins by its type and checks its timing",
              "stepdir")
      .option("feed", "full|programmed",
              "full: every move at full feed (the lattice points are the same; machining time "
              "computed from the feed words); programmed: simulate the programmed feeds",
              "full")
      .option("profile", "scurve|trapezoid|off",
              "the feed profile in front of motion_top (rtl/feed_profile.sv), overriding the "
              "machine file's `profile`: moves follow its jerk-limited speed within the "
              "machine's max_accel and max_jerk")
      .option("profile-window", "N", "commands the profile's planner looks ahead", "16")
      .option("soc-writes", "FILE",
              "write the bus writes that stream the program's commands into motion_soc's "
              "command FIFO, as JSON (tb/gcode/soc_writes.h: with a profile each command's "
              "planned move too; the widths, clock, step timing and the per-move grouping), for "
              "a test bench of your own or the host package (hwinterp-host run, docs/host.md)")
      .flag("plan-only",
            "with --soc-writes: compile (and with a profile plan) the program, write the file "
            "and stop: no lockstep run, no other output")
      .option("feed-hold", "AT:FOR",
              "with a profile: feed hold from AT seconds of the run for FOR seconds, a "
              "controlled stop along the path within the limits, then the planned profile "
              "resumes; the report gives the distance and time to rest")
      .option("feed-override", "AT:PCT[,AT:PCT...]",
              "with a profile: the feed override, PCT (0..200 %, resolution 1/128) from AT "
              "seconds of the run on; every change jerk-limited, above 100 % capped at the "
              "machine's limits (hls/feed_profile.h)")
      .option("moves-csv", "FILE", "one row per motion move: programmed end, lattice end reached")
      .option("step-times", "FILE",
              "every step pulse on the wire as CSV: clock,axis,dir (the clock of its rising "
              "edge, the axis letter, +1 or -1)")
      .option("plot", "FILE.png", "the path, coloured by contour error (matplotlib)")
      .option("plot-kinematics", "FILE.png",
              "speed, acceleration and jerk over time for the path and each axis, with the "
              "machine's limits (matplotlib)")
      .option("vcd", "FILE", "VCD trace of the run")
      .option("fst", "FILE", "FST trace of the run")
      .option("trace-window", "N", "keep only the last N clocks in the trace")
      .option("progress", "N", "progress line every N clocks (0: none)", "5000000")
      .option("max-clocks", "N",
              "the ceiling on a run's clocks: a feed hold or a 0 % override longer, or a "
              "profiled program slower even at its time-optimal time, exits 2 before anything "
              "runs",
              "1e11");

  // The program: the first argument, unless --canon names it.
  gcode::PartProgramSetup setup;
  int from = first;
  if (from < argc && argv[from][0] != '-') setup.program = argv[from++];
  if (parse_or_help(args, argc, argv, from)) return kExitOk;
  if (setup.program.empty() == !args.given("canon"))
    throw UsageError(setup.program.empty()
                         ? "give a program: hwinterp gcode FILE.ngc, or --canon FILE"
                         : "give one program: FILE.ngc or --canon FILE, not both");
  setup.canon = args.given("canon");
  if (setup.canon) setup.program = args.str("canon");
  setup.mode = args.choice("mode", {"systemc", "direct"});
  if (args.given("bus")) setup.bus = args.choice("bus", {"axi4lite", "wishbone"});
  setup.bus_waits = static_cast<uint32_t>(args.integer("bus-waits", 0, 64));
  if (args.given("bus-waits") && setup.bus.empty())
    throw UsageError("--bus-waits: give --bus axi4lite or --bus wishbone with it");
  if (args.given("step-types")) {
    if (setup.bus.empty())
      throw UsageError("--step-types: give --bus axi4lite or --bus wishbone with it");
    for (const std::string& t : cli::split_commas(args.str("step-types"))) {
      tb::StepType st;
      if (!tb::parse_step_type(t, st))
        throw UsageError("--step-types: '" + t + "' is not a step type (stepdir, updown, quad)");
      setup.step_types.push_back(st);
    }
  }
  setup.feed_mode = args.choice("feed", {"full", "programmed"}) == "full"
                        ? gcode::FeedMode::kFull
                        : gcode::FeedMode::kProgrammed;
  if (args.given("machine")) setup.machine = gcode::load_machine(args.str("machine"));
  if (args.given("profile"))
    setup.machine.profile = gcode::parse_profile(args.str("profile"), "--profile");
  setup.profile_window = static_cast<size_t>(args.integer("profile-window", 1, 4096));
  if (args.given("feed-hold")) {
    const std::string v = args.str("feed-hold");
    const size_t colon = v.find(':');
    if (colon == std::string::npos)
      throw UsageError("--feed-hold: '" + v + "' is not AT:FOR (seconds, e.g. 2.5:0.5)");
    setup.hold_at_s = cli::parse_real(v.substr(0, colon), "--feed-hold AT");
    setup.hold_for_s = cli::parse_real(v.substr(colon + 1), "--feed-hold FOR");
    if (!(setup.hold_at_s >= 0) || !(setup.hold_for_s > 0))
      throw UsageError("--feed-hold: '" + v + "' needs AT >= 0 and FOR > 0 seconds");
    if (setup.machine.profile == gcode::ProfileKind::kOff)
      throw UsageError("--feed-hold: the hold is the feed profile's; the profile is off");
  }
  if (args.given("feed-override")) {
    try {
      setup.feed_override = tb::parse_feed_override(args.str("feed-override"));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--feed-override: ") + e.what());
    }
    if (setup.machine.profile == gcode::ProfileKind::kOff)
      throw UsageError("--feed-override: the override is the feed profile's; the profile is off");
  }
  setup.max_clocks = args.real("max-clocks");
  check_pauses(setup, setup.max_clocks);
  if (!setup.bus.empty() && setup.machine.profile != gcode::ProfileKind::kOff &&
      (args.given("feed-hold") || args.given("feed-override")))
    throw UsageError(std::string("--bus ") + setup.bus +
                     ": the bus run takes the profile's planned moves only; give --feed-hold and "
                     "--feed-override without --bus");
  if (args.given("variant")) setup.variant = args.str("variant");
  const tb::VariantSpec variant = gcode::part_program_variant(setup);  // a bad --variant stops here
  if (setup.step_types.size() > 1 && setup.step_types.size() != static_cast<size_t>(variant.axes))
    throw UsageError("--step-types: " + std::to_string(setup.step_types.size()) +
                     " types for the " + std::to_string(variant.axes) + " axes of " +
                     variant.variant + " (give one for every axis, or one per axis)");

  if (args.given("plan-only")) {
    if (!args.given("soc-writes")) throw UsageError("--plan-only: give --soc-writes FILE with it");
    for (const char* o : {"bus", "json", "moves-csv", "step-times", "plot", "plot-kinematics",
                          "vcd", "fst", "feed-hold", "feed-override"})
      if (args.given(o))
        throw UsageError(std::string("--plan-only: --") + o +
                         " needs the lockstep run; --plan-only writes --soc-writes only");
    stage_outputs(args, {"soc-writes"}, {"machine"}, {setup.program}, "the program");
    setup.soc_writes_path = output_path("soc-writes");
    gcode::plan_soc_writes(setup);
    std::cout << "hwinterp gcode: " << setup.program << ": wrote " << setup.soc_writes_path << " ("
              << variant.variant << ")\n";
    return kExitOk;
  }

  // Every output can be written and is neither an input nor another output,
  // or nothing runs; each is written beside its file and put in place when
  // the run completes (tb/report/output_path.h).
  trace_from_args(args, setup.bench);
  setup.bench.progress_every = static_cast<uint64_t>(args.integer("progress", 0, INT64_MAX));
  stage_outputs(args,
                {"moves-csv", "step-times", "plot", "plot-kinematics", "vcd", "fst", "soc-writes"},
                {"machine"}, {setup.program}, "the program");
  if (!setup.bench.trace_path.empty())
    setup.bench.trace_path = output_path(args.given("vcd") ? "vcd" : "fst");
  if (args.given("step-times")) setup.bench.step_times_path = output_path("step-times");
  if (args.given("soc-writes")) setup.soc_writes_path = output_path("soc-writes");
  std::unique_ptr<std::ofstream> moves_csv, points_csv;
  if (args.given("moves-csv"))
    moves_csv = std::make_unique<std::ofstream>(output_path("moves-csv"));
  // The plots' data: scratch files beside the PNG, removed at the end.
  const std::string points_path =
      args.given("plot") ? outputs().scratch(args.str("plot") + ".points.csv") : "";
  if (!points_path.empty()) points_csv = std::make_unique<std::ofstream>(points_path);
  setup.moves_csv = moves_csv.get();
  setup.points_csv = points_csv.get();
  std::unique_ptr<std::ofstream> kinematics_csv;
  const std::string kin_png = args.given("plot-kinematics") ? args.str("plot-kinematics") : "";
  const std::string kin_csv = kin_png.empty() ? "" : outputs().scratch(kin_png + ".csv");
  const std::string kin_json = kin_png.empty() ? "" : outputs().scratch(kin_png + ".json");
  if (!kin_png.empty()) kinematics_csv = std::make_unique<std::ofstream>(kin_csv);
  setup.kinematics_csv = kinematics_csv.get();

  const gcode::PartProgramRun run = gcode::run_part_program(setup);
  bool ok = run.passed;
  std::cout << tb::case_table(run.results) << tb::failure_details(run.results)
            << gcode::summary_table(setup, run);
  if (run.bus.ran && !run.bus.passed)
    std::cout << "FAIL: the " << run.bus.bus
              << " run did not meet the lockstep run (lattice points, end points, lost or "
                 "refused commands, bus errors: see the bus rows)\n";
  if (!run.end_mismatches.empty())
    std::cout << "FAIL: " << run.end_mismatches.size()
              << " moves ended off their rounded programmed end (first: move "
              << run.end_mismatches.front() << ")\n";
  Json report = gcode::report_json(setup, run);

  if (moves_csv) {
    moves_csv->close();
    if (!*moves_csv) throw UsageError("--moves-csv: error writing '" + args.str("moves-csv") + "'");
  }
  if (points_csv) {
    points_csv->close();
    if (!*points_csv) throw UsageError("--plot: error writing '" + points_path + "'");
    ok = plot(HWINTERP_SCRIPTS_DIR "/plot_gcode.py",
              {"--out=" + output_path("plot"), "--title=" + setup.program, "--", points_path},
              "plot", args.str("plot")) &&
         ok;
  }
  if (kinematics_csv) {
    kinematics_csv->close();
    if (!*kinematics_csv) throw UsageError("--plot-kinematics: error writing '" + kin_csv + "'");
    std::ofstream(kin_json) << gcode::kinematics_units_json(setup, run).dump(1) << "\n";
    ok = plot(HWINTERP_SCRIPTS_DIR "/plot_kinematics.py",
              {"--out=" + output_path("plot-kinematics"), "--title=" + setup.program, "--", kin_csv,
               kin_json},
              "plot-kinematics", kin_png) &&
         ok;
  }
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  report["passed"] = ok;
  maybe_write_json(args, report);
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("gcode", "a part program (G-code or rs274 canon) through motion_top", 15,
                    run_gcode);

}  // namespace hwinterp::cli

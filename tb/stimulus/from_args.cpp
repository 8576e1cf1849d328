#include "tb/stimulus/from_args.h"

namespace hwinterp::tb {

size_t select_variant(const std::string& core, const std::vector<VariantSpec>& variants,
                      const cli::Args& args) {
  VariantChoice choice;
  if (args.given("variant")) choice.name = args.str("variant");
  if (args.given("axes")) choice.axes = static_cast<int>(args.integer("axes", 1, kMaxAxes));
  return choose_variant(core, variants, choice);
}

std::optional<CaseProfile> profile_from_args(const cli::Args& args) {
  const std::string kind = args.given("profile") ? args.str("profile") : "off";
  if (kind != "scurve" && kind != "trapezoid" && kind != "off")
    throw cli::UsageError("--profile: '" + kind + "' is not scurve, trapezoid or off");
  if (kind == "off") {
    for (const char* o : {"profile-level", "profile-ticks"})
      if (args.given(o))
        throw cli::UsageError(std::string("--") + o + " needs --profile scurve or trapezoid");
    return std::nullopt;
  }
  if (kind == "trapezoid" && args.given("profile-ticks"))
    throw cli::UsageError("--profile-ticks: a trapezoid reaches a level in 1 tick");
  CaseProfile p;
  // A level needs at least one speed quantum of the block's 48 bits.
  p.level = args.given("profile-level") ? args.real("profile-level", 1e-9, 1) : 1.0 / 64;
  if (p.level >= 1)
    throw cli::UsageError("--profile-level: " + args.str("profile-level") +
                          " must be below 1 operation/clock");
  p.len = kind == "trapezoid"
              ? 1
              : static_cast<unsigned>(
                    args.given("profile-ticks") ? args.integer("profile-ticks", 1, 1024) : 8);
  return p;
}

void declare_cosim_options(cli::Args& args) {
  args.option("core", "NAME", "the core to simulate (see above)")
      .option("variant", "NAME", "the variant (default: the first, or the first with --axes)")
      .option("axes", "N", "the first variant with N axes")
      .option("job", "FILE", "a job file (cases, commands, settings, aborts; see README)")
      .option("random", "N", "a seeded random stream of N commands")
      .option("seed", "S", "seed of --random (printed; a fresh one when omitted)")
      .flag("with-aborts", "--random: abort_i pulses at random depths into the stream")
      .flag("with-holds", "--random: feed holds (feed 0 for a while) in the stream")
      .option("mode", "MODE", "systemc (SC_MODULE + verilator --sc) or direct (tick() + --cc)",
              "systemc")
      .option("feed", "full|WORD|F", "feed: full, a feed word, or a clock fraction like 0.25")
      .option("step-len", "N", "step pulse length, clocks (default from the variant)")
      .option("step-space", "N", "minimum low time between steps, clocks")
      .option("dir-setup", "N", "dir setup before a step, clocks")
      .option("dir-hold", "N", "dir hold after a step, clocks")
      .option("abort-at", "CYCLE", "raise abort_i for one clock at this clock edge of the run")
      .option("progress", "N",
              "a progress line on stderr every N clock edges (the case, its commands, the "
              "clocks a second; 0: none)",
              "5000000")
      .option("vcd", "FILE", "write a VCD trace (inputs, HLS and RTL outputs)")
      .option("fst", "FILE", "write an FST trace (via vcd2fst)")
      .option("trace-window", "N", "trace only the last N cycles (e.g. before a mismatch)")
      .option("path-csv", "FILE",
              "write the lattice path (start, command targets, every move) as CSV for "
              "scripts/plot_paths.py")
      .option("step-times", "FILE",
              "write every step pulse on the wire as CSV: clock,axis,dir (the clock of its "
              "rising edge, the axis letter, +1 or -1)")
      .option("dump-frames", "FILE",
              "write the input frames, one hex line a clock, and FILE.sv, a Verilog "
              "testbench that replays them into the RTL")
      .option("profile", "scurve|trapezoid|off",
              "feed_i from a jerk-limited feed profile (docs/profile.md): each command a "
              "rest-to-rest move at its feed word, capped so the step/dir timing never "
              "stalls the engine (default off)")
      .option("profile-level", "F",
              "--profile: one level's speed, operations/clock (the speed steps by at most a "
              "level a tick of 1024 clocks: the acceleration; default 0.015625)")
      .option("profile-ticks", "L",
              "--profile scurve: ticks over which a level is reached (the jerk: a level / L "
              "a tick^2; 1..1024, default 8)")
      .option("inject", "KIND@CYCLE",
              "test hook: mismatch@C flips the HLS step_o[0] before the comparison, "
              "glitch@C the observed step_o[0] after it");
}

}  // namespace hwinterp::tb

// hwinterp board-sim: a board's gateware (all but pads, PHY and PLL),
// Verilated, serving its host link on this machine until stopped
// (tb/board/board_sim.h): Etherbone boards on a UDP port of 127.0.0.1, UART
// boards on a pseudo terminal. Prints the URI the host package takes
// (hwinterp-host ... URI) as its first line.
#include <fstream>
#include <iostream>

#include "tb/board/registry.h"
#include "tb/cli/subcommand.h"

namespace hwinterp::cli {

namespace {

std::string board_names() {
  std::string s;
  for (const auto& b : board::boards())
    if (b.sys_hz == b.board_hz) s += (s.empty() ? "" : ", ") + b.name;
  return s;
}

// The clocks this build simulates board `name` at.
std::string clocks_of(const std::string& name) {
  std::string s;
  for (const auto& b : board::boards())
    if (b.name == name) s += (s.empty() ? "" : ", ") + std::to_string(b.sys_hz);
  return s;
}

int run_board_sim(int argc, char** argv, int first) {
  Args args("board-sim",
            "Simulates a board's gateware (everything but pads, PHY and PLL) and serves its host\n"
            "link on this machine: Etherbone boards on UDP 127.0.0.1, UART boards on a pseudo\n"
            "terminal. Prints the URI to give hwinterp-host, then runs until SIGINT/SIGTERM,\n"
            "--max-clocks or --max-seconds, checking the step pins as the lockstep does.\n"
            "usage: hwinterp board-sim --board NAME [options]");
  args.option("board", "NAME", "the board (" + board_names() + ")")
      .option("clock-hz", "HZ",
              "the simulated clock: the board's own (default) or another this build holds "
              "(scripts/board_sim.sh --clock-hz builds one)")
      .option("port", "N", "Etherbone boards: the UDP port on 127.0.0.1 (0: a free one)", "0")
      .option("faults", "SPEC",
              "faults injected both ways: drop=P,corrupt=P,dup=P,reorder=P (per UDP frame; per "
              "byte on a UART, without reorder)")
      .option("faults-to-board", "SPEC", "faults of the host-to-board direction only")
      .option("faults-to-host", "SPEC", "faults of the board-to-host direction only")
      .option("fault-seed", "S", "the faults' seed", "1")
      .flag("realtime", "never run ahead of the wall clock (board time = wall time at most)")
      .option("max-clocks", "N", "stop after N clocks (0: no limit)", "0")
      .option("max-seconds", "S", "stop after S seconds of wall time (0: no limit)", "0")
      .option("uri-file", "FILE", "also write the URI there once serving")
      .option("steps-csv", "FILE", "every step pulse: clock,axis,dir (as gcode --step-times)")
      .option("commands-csv", "FILE", "every completed command: its clock and where each axis was")
      .option("progress", "S", "seconds between progress lines on stderr (0: none)", "10")
      .flag("list", "list the simulated builds: board, clock (Hz), link, UART rate");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;
  if (args.given("list")) {
    for (const auto& b : board::boards())
      std::cout << b.name << ' ' << b.sys_hz << ' ' << (b.ethernet ? "etherbone" : "uart") << ' '
                << b.baud << (b.sys_hz == b.board_hz ? " (the board's own clock)" : "") << '\n';
    return kExitOk;
  }
  if (!args.given("board")) throw UsageError("--board is required (" + board_names() + ")");
  const std::string name = args.str("board");
  if (clocks_of(name).empty())
    throw UsageError("--board: unknown board '" + name + "' (" + board_names() + ")");
  const uint64_t hz = args.given("clock-hz") ? static_cast<uint64_t>(args.integer("clock-hz", 1)) : 0;
  const board::BoardInfo* b = board::find_board(name, hz);
  if (!b)
    throw UsageError("--clock-hz " + args.str("clock-hz") + ": this build simulates " + name +
                     " at " + clocks_of(name) + " Hz (scripts/board_sim.sh " + name +
                     " --clock-hz " + args.str("clock-hz") + " builds it)");
  check_outputs_writable(args, {"uri-file", "steps-csv", "commands-csv"});

  board::BoardSimOptions o;
  o.port = static_cast<uint16_t>(args.integer("port", 0, 65535));
  if (args.given("port") && !b->ethernet)
    throw UsageError("--port: board " + b->name + " has a UART link, served on a pseudo terminal");
  board::FaultSpec both;
  if (args.given("faults")) both = board::parse_faults(args.str("faults"));
  o.faults_to_board =
      args.given("faults-to-board") ? board::parse_faults(args.str("faults-to-board")) : both;
  o.faults_to_host =
      args.given("faults-to-host") ? board::parse_faults(args.str("faults-to-host")) : both;
  if (!b->ethernet && (o.faults_to_board.reorder > 0 || o.faults_to_host.reorder > 0))
    throw UsageError("--faults: reorder applies to the Ethernet link; board " + b->name +
                     " has a UART");
  o.fault_seed = args.seed("fault-seed");
  o.realtime = args.given("realtime");
  o.max_clocks = static_cast<uint64_t>(args.integer("max-clocks", 0));
  o.max_seconds = args.real("max-seconds", 0);
  o.progress = static_cast<int>(args.integer("progress", 0, 86400));
  if (args.given("uri-file")) o.uri_file = args.str("uri-file");
  if (args.given("steps-csv")) o.steps_csv = args.str("steps-csv");
  if (args.given("commands-csv")) o.commands_csv = args.str("commands-csv");

  board::install_stop_handlers();
  const Json report = b->run(o, [&](const std::string& uri) {
    std::cout << uri << std::endl;
    if (!o.uri_file.empty()) write_text_file(o.uri_file, uri + "\n", "--uri-file");
  });
  maybe_write_json(args, report);
  const bool passed = report["passed"].get<bool>();
  std::cerr << "board-sim " << b->name << ": " << report["clocks"] << " clocks, "
            << report["commands_completed"] << " commands completed, "
            << report["timing_violations"] << " timing violations: " << (passed ? "PASS" : "FAIL")
            << "\n";
  return passed ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("board-sim", "simulate a board's gateware, serving its host link on loopback",
                    60, run_board_sim);

}  // namespace hwinterp::cli

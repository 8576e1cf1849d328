// `hwinterp`: the project's command line. The dispatcher is sc_main, entered
// through SystemC's sc_elab_and_sim like libsystemc's own main(); only the
// SystemC co-simulation mode elaborates a design.
#include <systemc>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>

#include "tb/cli/subcommand.h"
#include "tb/report/output_path.h"

namespace hwinterp::cli {

std::vector<Subcommand>& subcommands() {
  static std::vector<Subcommand> all;
  return all;
}

bool parse_or_help(Args& args, int argc, char** argv, int first) {
  args.parse(argc, argv, first);
  if (args.help_requested()) {
    std::cout << args.help_text();
    return true;
  }
  // The report is written at the end: a path that cannot take it fails now.
  stage_outputs(args, {"json"});
  return false;
}

void maybe_write_json(const Args& args, const Json& report) {
  if (!args.given("json")) return;
  try {
    write_json_file(output_path("json"), report);
  } catch (const std::exception& e) {
    throw UsageError(std::string("--json: ") + e.what());
  }
}

OutputFiles& outputs() {
  static OutputFiles files;
  return files;
}

void stage_outputs(const Args& args, std::initializer_list<const char*> outs,
                   std::initializer_list<const char*> inputs,
                   const std::vector<std::string>& input_paths, const std::string& input_what) {
  try {
    for (const std::string& p : input_paths) outputs().input(input_what, p);
    for (const char* o : inputs)
      if (args.given(o)) outputs().input(std::string("--") + o, args.str(o));
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  for (const char* o : outs) {
    if (!args.given(o)) continue;
    try {
      outputs().stage(std::string("--") + o, args.str(o));
    } catch (const std::exception& e) {
      throw UsageError(std::string("--") + o + ": " + e.what());
    }
  }
}

std::string output_path(const char* o) { return outputs().temporary(std::string("--") + o); }

void check_outputs_writable(const Args& args, std::initializer_list<const char*> options) {
  for (const char* o : options) {
    if (!args.given(o)) continue;
    try {
      outputs().live(std::string("--") + o, args.str(o));
    } catch (const std::exception& e) {
      throw UsageError(std::string("--") + o + ": " + e.what());
    }
  }
}

void trace_from_args(const Args& args, tb::BenchOptions& options) {
  if (args.given("vcd") && args.given("fst")) throw UsageError("give one of --vcd and --fst");
  if (args.given("trace-window") && !args.given("vcd") && !args.given("fst"))
    throw UsageError("--trace-window " + args.str("trace-window") + " needs --vcd or --fst");
  options.trace_path = args.given("vcd")   ? args.str("vcd")
                       : args.given("fst") ? args.str("fst")
                                           : "";
  if (args.given("trace-window"))
    options.trace_window = static_cast<uint64_t>(args.integer("trace-window", 1, 100000000));
}

void write_text_file(const std::string& path, const std::string& text, const std::string& option) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw UsageError(option + ": error writing '" + path + "'");
}

namespace {

void print_usage(std::ostream& os) {
  auto all = subcommands();
  std::sort(all.begin(), all.end(),
            [](const Subcommand& a, const Subcommand& b) { return a.order < b.order; });
  os << "usage: hwinterp <command> [options]   (hwinterp <command> --help for its options)\n\n"
        "commands:\n";
  for (const auto& s : all) {
    std::string name = "  " + s.name;
    name.resize(14, ' ');
    os << name << s.summary << "\n";
  }
  os << "\nexit codes: 0 success, 1 a check failed, 2 bad input\n";
}

}  // namespace
}  // namespace hwinterp::cli

extern "C" int sc_main(int argc, char** argv) {
  using namespace hwinterp::cli;
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    print_usage(argc < 2 ? std::cerr : std::cout);
    return argc < 2 ? kExitBadInput : kExitOk;
  }
  const std::string name = argv[1];
  for (const auto& s : subcommands()) {
    if (s.name != name) continue;
    try {
      const int rc = s.run(argc, argv, 2);
      // A completed run (passed or failed its checks) puts its outputs in
      // place; a refused one leaves every file as it was.
      if (rc == kExitOk || rc == kExitCheckFailed) outputs().commit();
      return rc;
    } catch (const std::exception& e) {
      std::cerr << "hwinterp " << name << ": error: " << one_line(e.what()) << "\n";
      return kExitBadInput;
    }
  }
  std::cerr << "hwinterp: unknown command '" << one_line(name) << "' (see hwinterp --help)\n";
  return kExitBadInput;
}

// Our own main() (it takes precedence over libsystemc's) so that the SystemC
// banner, printed before sc_main runs, stays out of every report.
int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}

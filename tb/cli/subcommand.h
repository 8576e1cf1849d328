// The `hwinterp` subcommands. Each lives in its own tb/cmd_<name>.cpp and
// registers itself with a static HWINTERP_SUBCOMMAND(...) object, so adding a
// subcommand touches no shared table. Those files are compiled straight into
// the executable (not a static library), which keeps the registrations alive.
#pragma once

#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "tb/base/args.h"
#include "tb/base/concat.h"
#include "tb/base/json.h"
#include "tb/lockstep/bench_options.h"
#include "tb/report/output_path.h"

namespace hwinterp::cli {

// Exit codes of the command-line contract.
inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;  // mismatch, bound exceeded, timing violation
inline constexpr int kExitBadInput = 2;     // with a one-line message naming the value

struct Subcommand {
  std::string name;
  std::string summary;
  int order;  // position in `hwinterp --help`
  // Runs with argv[first] the first option after the subcommand name. Returns
  // the exit code; throws UsageError for bad input.
  std::function<int(int argc, char** argv, int first)> run;
};

std::vector<Subcommand>& subcommands();

struct SubcommandRegistration {
  SubcommandRegistration(Subcommand s) { subcommands().push_back(std::move(s)); }
};

// Parses argv into `args`; returns true when --help was asked (help printed).
// Checks that a --json path can be written before anything runs.
bool parse_or_help(Args& args, int argc, char** argv, int first);

// Writes the --json report when asked. Throws UsageError when the file can't be written.
void maybe_write_json(const Args& args, const Json& report);

// The process's output files (tb/report/output_path.h): the commands stage
// them (the --json report is staged by parse_or_help), the dispatcher commits
// them when the command returns 0 or 1; a command that returns 2 or throws
// leaves every existing file as it was.
OutputFiles& outputs();

// Registers each given option of `inputs` and each of `input_paths` (named
// `input_what`) as the run's inputs, then stages each given option of `outs`
// (tb/report/output_path.h: writable, not an input, not another output; its
// temporary created), before anything runs; else a UsageError naming the
// option. The run writes output_path(o).
void stage_outputs(const Args& args, std::initializer_list<const char*> outs,
                   std::initializer_list<const char*> inputs = {},
                   const std::vector<std::string>& input_paths = {},
                   const std::string& input_what = "the input");

// Where the run writes the staged output option `o` (its temporary file).
std::string output_path(const char* o);

// Every output option of `options` that was given names a path that can be
// written, and not the file of an input or another output (OutputFiles::live);
// else a UsageError naming the option, before anything runs. For outputs
// written while the command runs that others read live (board-sim's URI file
// and logs); every other output is staged.
void check_outputs_writable(const Args& args, std::initializer_list<const char*> options);

// --vcd FILE / --fst FILE (one at most) and --trace-window N (only with one
// of them) into the bench options.
void trace_from_args(const Args& args, tb::BenchOptions& options);

// Writes `text` to `path`; throws UsageError naming `option` and the path when
// it cannot be written (a failed flush included).
void write_text_file(const std::string& path, const std::string& text, const std::string& option);

}  // namespace hwinterp::cli

#define HWINTERP_SUBCOMMAND(...)                                        \
  static const ::hwinterp::cli::SubcommandRegistration HWINTERP_CONCAT( \
      hwinterp_subcommand_, __LINE__)(::hwinterp::cli::Subcommand{__VA_ARGS__})

// Command-line parsing shared by every `hwinterp` subcommand.
//
// Contract (docs/command-line.md): every subcommand takes --help and --json FILE; bad input
// ends the run with exit code 2 and one line naming the offending value. The
// parser throws UsageError for that; the dispatcher prints it and exits 2.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace hwinterp::cli {

std::string one_line(const std::string& text);

// Bad input: the message names the offending option and value. Exit code 2.
// Control bytes in the message (a value holding a newline or a NUL) are
// escaped here, so the message is always one printable line.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& message) : std::runtime_error(one_line(message)) {}
};

class Args {
 public:
  Args(std::string command, std::string summary);

  // Declarations. `metavar` is what --help shows for the value.
  Args& option(const std::string& name, const std::string& metavar, const std::string& help,
               std::optional<std::string> default_value = std::nullopt);
  Args& flag(const std::string& name, const std::string& help);

  // Parses argv[first..argc). Throws UsageError on unknown options, missing
  // values, repeated options or stray positional arguments.
  void parse(int argc, char** argv, int first);

  bool help_requested() const { return help_; }
  std::string help_text() const;

  bool has(const std::string& name) const;    // given on the command line or defaulted
  bool given(const std::string& name) const;  // given on the command line
  std::string str(const std::string& name) const;
  // Typed accessors: a value that does not parse or lies outside [lo, hi]
  // throws UsageError naming the option and the value.
  int64_t integer(const std::string& name, int64_t lo = INT64_MIN, int64_t hi = INT64_MAX) const;
  uint64_t seed(const std::string& name) const;
  double real(const std::string& name, double lo = -1e308, double hi = 1e308) const;
  // Comma-separated integers ("0,0,20,40"); an empty or malformed element ->
  // UsageError naming its position.
  std::vector<int64_t> integer_list(const std::string& name) const;
  std::string choice(const std::string& name, const std::vector<std::string>& allowed) const;

  const std::string& command() const { return command_; }

 private:
  struct Spec {
    std::string metavar;
    std::string help;
    bool is_flag = false;
    std::optional<std::string> default_value;
  };
  std::string command_;
  std::string summary_;
  std::vector<std::string> order_;
  std::map<std::string, Spec> specs_;
  std::map<std::string, std::string> values_;
  bool help_ = false;
};

// Strict number parsing used by Args and by job-file readers: the whole text
// must be the number. `what` names the source in the error ("--line", "job.txt:3").
int64_t parse_integer(const std::string& text, const std::string& what);
double parse_real(const std::string& text, const std::string& what);

// A comma-separated list's items, in order, empty ones included ("a,,b":
// "a", "", "b"; "": one empty item); what an empty item means is the caller's.
std::vector<std::string> split_commas(const std::string& text);

// `text` with control bytes escaped (\n, \xNN): an error message names the
// offending value on exactly one line, whatever the value holds.

}  // namespace hwinterp::cli

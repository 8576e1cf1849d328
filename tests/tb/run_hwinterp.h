// Runs the real `hwinterp` executable for command-line contract tests. CMake
// passes its path as HWINTERP_EXE and builds it before the tests, so a test
// never skips for want of the binary.
#pragma once

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#ifndef HWINTERP_EXE
#error "HWINTERP_EXE must name the hwinterp executable (set in tests/CMakeLists.txt)"
#endif

namespace hwinterp::testing {

struct CliResult {
  int code = -1;    // exit status; -1 when killed by a signal
  std::string out;  // stdout
  std::string err;  // stderr
};

inline std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// The rows of a CSV file (no quoting), header first.
inline std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    size_t from = 0;
    for (size_t comma; (comma = line.find(',', from)) != std::string::npos; from = comma + 1)
      cells.push_back(line.substr(from, comma - from));
    cells.push_back(line.substr(from));
    rows.push_back(cells);
  }
  return rows;
}

// A fresh directory for one test's files.
inline std::string scratch_dir(const std::string& name) {
  const std::string dir = "/tmp/hwinterp_test_" + name + "_" + std::to_string(getpid());
  mkdir(dir.c_str(), 0755);
  return dir;
}

// `hwinterp <args>` with stdout and stderr captured separately.
inline CliResult run_hwinterp(const std::string& args) {
  const std::string base = scratch_dir("cli");
  const std::string out = base + "/stdout", err = base + "/stderr";
  const std::string cmd = std::string(HWINTERP_EXE) + " " + args + " >" + out + " 2>" + err;
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

}  // namespace hwinterp::testing

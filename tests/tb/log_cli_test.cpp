// `hwinterp log` through the real executable: the command-line contract (exit
// 0 on success, 2 with one line naming the value on bad input) and the JSON
// and CSV outputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "run_hwinterp.h"
#include "tb/base/json.h"

namespace {

using hwinterp::testing::CliResult;
using hwinterp::testing::run_hwinterp;
using hwinterp::testing::slurp;

CliResult run(const std::string& args) { return run_hwinterp("log " + args); }

class LogCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = hwinterp::testing::scratch_dir("log_cli"); }
  std::string dir_;
};

TEST_F(LogCli, PaperCaseJsonAndCsv) {
  const std::string json = dir_ + "/log.json", csv = dir_ + "/log.csv";
  const CliResult r = run("--d1 10 --spiral 30 --cone 5 --rake 8 --dl 0.2 --x-end 30 --json " +
                          json + " --csv " + csv);
  ASSERT_EQ(r.code, 0) << r.err;
  const hwinterp::Json j = hwinterp::Json::parse(slurp(json));
  // Paper 001: 152 points, last X 30.2684, MaxErPA = MaxErPAo = 3.9785e-5 at
  // point 1, MaxErPAe = 3.5000e-7 at point 152.
  EXPECT_EQ(j["points"], 152);
  EXPECT_NEAR(j["x_last"].get<double>(), 30.2684, 5e-5);
  EXPECT_NEAR(j["max_error"].get<double>(), 3.9785e-5, 5e-9);
  EXPECT_NEAR(j["max_error_odd"].get<double>(), 3.9785e-5, 5e-9);
  EXPECT_NEAR(j["max_error_even"].get<double>(), 3.5000e-7, 5e-11);
  EXPECT_EQ(j["max_error_index"], 1);
  EXPECT_EQ(j["max_error_even_index"], 152);
  std::ifstream f(csv);
  std::string line;
  int rows = 0;
  std::getline(f, line);
  EXPECT_EQ(line, "index,parity,x,y,z,a,pa,error");
  while (std::getline(f, line)) ++rows;
  EXPECT_EQ(rows, 153);  // the start point and 152 interpolated points
}

TEST_F(LogCli, ExactEven) {
  const std::string json = dir_ + "/exact.json";
  const CliResult r = run("--exact-even --json " + json);
  ASSERT_EQ(r.code, 0) << r.err;
  const hwinterp::Json j = hwinterp::Json::parse(slurp(json));
  EXPECT_EQ(j["even_step"], "exact");
  // The exact even step puts every even point on the curve.
  EXPECT_LT(j["max_error_even"].get<double>(), 1e-9);
}

// Bad input: exit 2, exactly one line on stderr, naming the value.
TEST_F(LogCli, BadInputOneLineNamingTheValue) {
  const std::pair<const char*, const char*> cases[] = {
      {"--d1 -3", "--d1: -3"},
      {"--d1 0", "--d1: 0"},
      {"--dl 0", "--dl: 0"},
      {"--dl -0.1", "--dl: -0.1"},
      {"--x-end 0", "--x-end: 0"},
      {"--spiral 90", "--spiral: 90"},
      {"--cone 0", "--cone: 0"},
      {"--rake -5", "--rake: -5"},
      {"--cone abc", "abc"},
      {"--dl 1e-7", "dl 1e-07"},
      {"--dl 31", "dl 31"},
      {"--bogus 1", "--bogus"},
      {"--csv /nonexistent-dir/x.csv", "/nonexistent-dir/x.csv"},
  };
  for (const auto& [args, named] : cases) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

// The reproduction pages of papers 001, 003 and 004 match (exit 0).
TEST_F(LogCli, ReproducePagesMatch) {
  for (const char* paper : {"log", "chord", "ratio"}) {
    const CliResult r = run_hwinterp(std::string("reproduce --paper ") + paper);
    EXPECT_EQ(r.code, 0) << paper << ": " << r.err;
  }
}

}  // namespace

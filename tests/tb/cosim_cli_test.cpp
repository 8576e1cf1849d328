// `hwinterp cosim` and `hwinterp regress` through the real executable: the
// command-line contract of DESIGN.md (JSON keys, exit codes 0/1/2, one-line
// errors naming the value, traces, the replay command).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "run_hwinterp.h"

namespace {

using hwinterp::testing::CliResult;
using hwinterp::testing::run_hwinterp;
using hwinterp::testing::scratch_dir;
using hwinterp::testing::slurp;

TEST(CosimCli, LineInBothModesWritesTheContractJson) {
  const std::string dir = scratch_dir("cosim_json");
  for (const char* mode : {"direct", "systemc"}) {
    const std::string json = dir + "/" + mode + ".json";
    const CliResult r = run_hwinterp(std::string("cosim --core dda_line --line 0,0,20,40 --mode ") +
                                     mode + " --json " + json);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    const std::string j = slurp(json);
    for (const char* key :
         {"\"core\": \"dda_line\"", "\"seed\"", "\"cycles\"", "\"commands\": 1",
          "\"steps\": [20, 40]", "\"end_position\": [20, 40]",
          "\"expected_end_position\": [20, 40]", "\"max_path_error_steps\"", "\"mismatches\": 0",
          "\"timing_violations\": 0", "\"first_mismatch\": null"})
      EXPECT_NE(j.find(key), std::string::npos) << key << " missing in\n" << j;
    EXPECT_NE(j.find(std::string("\"mode\": \"") + mode + "\""), std::string::npos) << j;
  }
}

TEST(CosimCli, RandomRunPrintsItsSeed) {
  const CliResult r = run_hwinterp("cosim --core dda_line --axes 4 --random 5 --mode direct");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find(", seed "), std::string::npos) << r.out;
}

TEST(CosimCli, MismatchExitsOneWithReplayCommandAndTrace) {
  const std::string dir = scratch_dir("cosim_mismatch");
  const CliResult r = run_hwinterp(
      "cosim --core dda_line --random 20 --seed 9 --mode direct "
      "--inject mismatch@77 --json " +
      dir + "/m.json --vcd " + dir + "/m.vcd --trace-window 30");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const std::string j = slurp(dir + "/m.json");
  EXPECT_NE(j.find("\"cycle\": 77"), std::string::npos) << j;
  EXPECT_NE(j.find("\"signal\": \"step_o[0]\""), std::string::npos) << j;
  EXPECT_NE(r.out.find("replay: hwinterp cosim --core dda_line --random 20 --seed 9 --mode direct "
                       "--inject mismatch@77 --vcd mismatch.vcd --trace-window 200"),
            std::string::npos)
      << r.out;
  // The window holds the last 30 cycles: time stamps 48..77 (10 ns a cycle).
  const std::string vcd = slurp(dir + "/m.vcd");
  EXPECT_NE(vcd.find("$var wire 1"), std::string::npos);
  EXPECT_NE(vcd.find("\n#480\n"), std::string::npos);
  EXPECT_NE(vcd.find("\n#770\n"), std::string::npos);
  EXPECT_EQ(vcd.find("\n#470\n"), std::string::npos);
}

TEST(CosimCli, FstTraceIsWritten) {
  const std::string fst = scratch_dir("cosim_fst") + "/t.fst";
  const CliResult r =
      run_hwinterp("cosim --core dda_line --line 0,0,5,3 --mode systemc --fst " + fst);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  std::ifstream f(fst, std::ios::binary);
  f.seekg(0, std::ios::end);
  EXPECT_GT(f.tellg(), 100);
}

// --path-csv: the case start, each command's target and one row per move,
// consistent with the steps the report counts.
TEST(CosimCli, PathCsvHasStartTargetAndEveryMove) {
  const std::string csv = scratch_dir("cosim_path") + "/p.csv";
  const CliResult r = run_hwinterp(
      "cosim --core dda_line --line 10,10,40,20 --mode direct "
      "--path-csv " +
      csv);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  std::ifstream f(csv);
  std::string line;
  std::getline(f, line);
  EXPECT_EQ(line, "case,cycle,kind,p0,p1");
  int starts = 0, targets = 0, moves = 0;
  std::string last;
  while (std::getline(f, line)) {
    starts += line.find(",start,") != std::string::npos;
    targets += line.find(",target,40,20") != std::string::npos;
    moves += line.find(",move,") != std::string::npos;
    last = line;
  }
  EXPECT_EQ(starts, 1);
  EXPECT_EQ(targets, 1);
  EXPECT_GE(moves, 30);  // 30 x-steps, 10 y-steps, some together
  EXPECT_LE(moves, 40);
  EXPECT_NE(last.find(",move,40,20"), std::string::npos) << last;
}

TEST(CosimCli, TimingViolationExitsOne) {
  const CliResult r = run_hwinterp(
      "cosim --core dda_line --line 0,0,8,0 --mode direct "
      "--step-len 4 --step-space 4 --inject glitch@20");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("timing: cycle"), std::string::npos) << r.out;
}

// Bad input: exit 2, one line on stderr naming the offending value, and no
// simulation started (nothing on stdout after the parse).
TEST(CosimCli, BadInputOneLineNamingTheValue) {
  const std::pair<const char*, const char*> cases[] = {
      {"--core dda_line --line 0,0,3000000000,0", "3000000000"},
      {"--core dda_line --line 0,0,1x,2", "'1x'"},
      {"--core dda_line --line 0,0,1", "'0,0,1'"},
      {"--core ppc_nope --line 0,0,1,1", "'ppc_nope'"},
      {"--core dda_line --axes 3 --line 0,0,1,1", "3 axes"},
      {"--core dda_line --line 0,0,1,1 --mode fast", "'fast'"},
      {"--core dda_line --random 0", "--random: 0"},
      {"--core dda_line --random 5 --seed -1", "'-1'"},
      {"--core dda_line --line 0,0,1,1 --random 3", "2 given"},
      {"--core dda_line --line 0,0,1,1 --feed 0", "--feed: 0"},
      {"--core dda_line --line 0,0,1,1 --dir-hold 65536", "65536"},
      {"--core dda_line --job /no/such.job", "/no/such.job"},
      {"--core dda_line --line 0,0,1,1 --inject flip@3", "'flip@3'"},
      {"--core dda_line --line 0,0,1,1 --vcd /no/dir/t.vcd", "/no/dir/t.vcd"},
      {"--line 0,0,1,1", "--core"},
  };
  for (const auto& [args, named] : cases) {
    const CliResult r = run_hwinterp(std::string("cosim ") + args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

TEST(CosimCli, HelpListsTheContract) {
  const CliResult r = run_hwinterp("cosim --help");
  EXPECT_EQ(r.code, 0);
  for (const char* o :
       {"--core", "--line", "--job", "--random", "--seed", "--mode", "--json", "--vcd", "--fst"})
    EXPECT_NE(r.out.find(o), std::string::npos) << o;
}

TEST(RegressCli, SmallRegressionPassesAndReports) {
  const std::string json = scratch_dir("regress") + "/r.json";
  const CliResult r = run_hwinterp("regress --cores dda_line --random 10 --seed 4 --json " + json);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("PASS"), std::string::npos);
  const std::string j = slurp(json);
  EXPECT_NE(j.find("\"passed\": true"), std::string::npos);
  // Every dda_line variant in both modes: 4 runs, each with the 16 paper-line cases
  // (plain and half preload) and the random stream.
  auto count = [&](const std::string& needle) {
    size_t n = 0;
    for (size_t at = j.find(needle); at != std::string::npos; at = j.find(needle, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("\"cycles_per_second\""), 4u) << j;
  EXPECT_EQ(count("\"case\": \"004_line1\""), 4u);
  EXPECT_EQ(count("\"case\": \"004_line8_half\""), 4u);
  EXPECT_EQ(count("\"case\": \"random\""), 4u);
  EXPECT_EQ(count("\"passed\": false"), 0u);
}

}  // namespace

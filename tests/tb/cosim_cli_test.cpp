// `hwinterp cosim` and `hwinterp regress` through the real executable: the
// command-line contract (docs/command-line.md: JSON keys, exit codes 0/1/2, one-line
// errors naming the value, traces, aborts, the replay command).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "run_hwinterp.h"
#include "tb/base/json.h"
#include "tb/lockstep/registry.h"

namespace {

using hwinterp::Json;
using hwinterp::testing::CliResult;
using hwinterp::testing::read_csv;
using hwinterp::testing::run_hwinterp;
using hwinterp::testing::scratch_dir;
using hwinterp::testing::slurp;

Json read_json(const std::string& path) { return Json::parse(slurp(path)); }

TEST(CosimCli, LineInBothModesWritesTheContractJson) {
  const std::string dir = scratch_dir("cosim_json");
  for (const char* mode : {"direct", "systemc"}) {
    const std::string json = dir + "/" + mode + ".json";
    const CliResult r = run_hwinterp(std::string("cosim --core dda_line --line 0,0,20,40 --mode ") +
                                     mode + " --json " + json);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    const Json j = read_json(json);
    EXPECT_EQ(j["core"], "dda_line");
    EXPECT_EQ(j["variant"], "dda_line_n2");
    EXPECT_EQ(j["mode"], mode);
    EXPECT_TRUE(j.contains("seed"));
    EXPECT_GT(j["cycles"].get<int>(), 40);
    EXPECT_EQ(j["commands"], 1);
    EXPECT_EQ(j["steps"], Json({20, 40}));
    EXPECT_EQ(j["end_position"], Json({20, 40}));
    EXPECT_EQ(j["expected_end_position"], Json({20, 40}));
    EXPECT_LT(j["max_path_error_steps"].get<double>(), 1.0);
    EXPECT_EQ(j["mismatches"], 0);
    EXPECT_EQ(j["timing_violations"], 0);
    EXPECT_TRUE(j["first_mismatch"].is_null());
    EXPECT_TRUE(j["abort"].is_null());
    ASSERT_EQ(j["cases"].size(), 1u);
    EXPECT_EQ(j["cases"][0]["passed"], true);
  }
}

TEST(CosimCli, RandomRunPrintsItsSeed) {
  const CliResult r = run_hwinterp("cosim --core dda_line --axes 4 --random 5 --mode direct");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("(dda_line_n4), mode direct, seed "), std::string::npos) << r.out;
}

// --abort-at: the JSON's abort object, on the path, within the bound.
TEST(CosimCli, AbortAtReportsWhereTheMachineIs) {
  const std::string json = scratch_dir("cosim_abort") + "/a.json";
  const CliResult r = run_hwinterp(
      "cosim --core dda_line --line 0,0,200,100 --mode direct --step-len 3 --abort-at 150 "
      "--json " +
      json);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const Json j = read_json(json);
  ASSERT_FALSE(j["abort"].is_null()) << j.dump();
  EXPECT_EQ(j["abort"]["cycle"], 150);
  EXPECT_TRUE(j["abort"]["on_reference_path"].get<bool>());
  EXPECT_LE(j["abort"]["idle_after_clocks"].get<int>(), 2);
  EXPECT_EQ(j["abort"]["position"], j["end_position"]);
  EXPECT_LT(j["end_position"][0].get<int>(), 200);
  EXPECT_GT(j["end_position"][0].get<int>(), 0);
}

// The mismatch report names the inputs of its edge by port, from the core's
// payload field list: the command on the pins at the edge that takes it (the
// third: two reset clocks first), signed deltas as numbers.
TEST(CosimCli, MismatchReportsTheInputsOfItsEdge) {
  const std::string dir = scratch_dir("cosim_mismatch_inputs");
  const CliResult r = run_hwinterp(
      "cosim --core dda_line --line 0,0,-5,3 --half-preload --mode direct "
      "--inject mismatch@3 --json " +
      dir + "/m.json");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const Json in = read_json(dir + "/m.json")["first_mismatch"]["inputs"];
  EXPECT_EQ(in["rst_ni"], 1);
  EXPECT_EQ(in["cmd_valid_i"], 1);
  EXPECT_EQ(in["cmd_delta_i"], Json::array({-5, 3}));
  EXPECT_EQ(in["half_preload_i"], 1);
  EXPECT_EQ(in["feed_i"], 65536);
  EXPECT_EQ(in["abort_i"], 0);
  // The next edge: the command taken, the payload cleared.
  const CliResult next = run_hwinterp(
      "cosim --core dda_line --line 0,0,-5,3 --mode direct --inject mismatch@4 --json " + dir +
      "/n.json");
  EXPECT_EQ(next.code, 1);
  const Json in4 = read_json(dir + "/n.json")["first_mismatch"]["inputs"];
  EXPECT_EQ(in4["cmd_valid_i"], 0);
  EXPECT_EQ(in4["cmd_delta_i"], Json::array({0, 0}));
}

TEST(CosimCli, MismatchExitsOneWithReplayCommandAndTrace) {
  const std::string dir = scratch_dir("cosim_mismatch");
  const CliResult r = run_hwinterp(
      "cosim --core dda_line --random 20 --seed 9 --mode direct "
      "--inject mismatch@77 --json " +
      dir + "/m.json --vcd " + dir + "/m.vcd --trace-window 30");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const Json j = read_json(dir + "/m.json");
  EXPECT_EQ(j["first_mismatch"]["cycle"], 77);
  EXPECT_EQ(j["first_mismatch"]["signal"], "step_o[0]");
  const std::string replay =
      "hwinterp cosim --core dda_line --random 20 --seed 9 --mode direct "
      "--inject mismatch@77 --vcd mismatch.vcd --trace-window 200";
  EXPECT_EQ(j["replay"], replay);
  EXPECT_NE(r.out.find("replay: " + replay), std::string::npos) << r.out;
  // The window holds the last 30 cycles: time stamps 48..77 (10 ns a cycle).
  const std::string vcd = slurp(dir + "/m.vcd");
  EXPECT_NE(vcd.find("$var wire 32 "), std::string::npos);  // cmd_delta_i_0
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

// --path-csv: the case start, each command's ideal path and target, and one
// row per move with its deviation and bound, consistent with the report.
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
  EXPECT_EQ(line, "case,cycle,kind,p0,p1,error,bound");
  int starts = 0, ideal = 0, targets = 0, moves = 0;
  std::string last;
  while (std::getline(f, line)) {
    starts += line.find(",start,10,10,,") != std::string::npos;
    ideal += line.find(",ideal,") != std::string::npos;
    targets += line.find(",target,40,20,,") != std::string::npos;
    moves += line.find(",move,") != std::string::npos;
    last = line;
  }
  EXPECT_EQ(starts, 1);
  EXPECT_EQ(ideal, 2);  // a line: its two ends
  EXPECT_EQ(targets, 1);
  EXPECT_GE(moves, 30);  // 30 x-steps, 10 y-steps, some together
  EXPECT_LE(moves, 40);
  EXPECT_NE(last.find(",move,40,20,0,"), std::string::npos) << last;  // on the line: 0
}

// --step-times: a row per pulse on the wire, in clock order, with its axis
// and direction; the step/dir timing settings space the pulses of an axis.
TEST(CosimCli, StepTimesHaveEveryPulseWithItsAxisAndDirection) {
  const std::string csv = scratch_dir("cosim_step_times") + "/t.csv";
  const CliResult r = run_hwinterp(
      "cosim --core dda_line --line 10,10,-20,17 --mode direct --step-len 3 --step-space 4 "
      "--step-times " +
      csv);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto rows = read_csv(csv);
  ASSERT_GT(rows.size(), 1u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"clock", "axis", "dir"}));
  int x = 0, y = 0;
  long long prev = 0, prev_x = -100;
  for (size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 3u);
    const long long clock = std::stoll(rows[i][0]);
    const int dir = std::stoi(rows[i][2]);
    EXPECT_GE(clock, prev) << i;
    prev = clock;
    if (rows[i][1] == "X") {
      x += dir;
      EXPECT_GE(clock - prev_x, 3 + 4) << i;  // high 3 clocks, low at least 4
      prev_x = clock;
    } else {
      EXPECT_EQ(rows[i][1], "Y") << i;
      y += dir;
    }
  }
  EXPECT_EQ(x, -30);
  EXPECT_EQ(y, 7);
  EXPECT_EQ(rows.size(), 1u + 37u);
}

// --dump-frames writes the frames and a replay testbench for the variant;
// Icarus Verilog runs it on the RTL and reproduces the co-simulation's
// cycles, steps, end position and done pulses.
TEST(CosimCli, DumpedFramesReplayInIcarus) {
  const std::string dir = scratch_dir("cosim_frames");
  const CliResult r = run_hwinterp(
      "cosim --core dda_line --variant dda_line_edge --random 12 "
      "--seed 4 --mode direct --dump-frames " +
      dir + "/f.hex --json " + dir + "/f.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const std::string rtl = std::string(HWINTERP_SOURCE_DIR) + "/rtl/";
  std::string files;
  std::ifstream list(rtl + "dda_line.f");
  for (std::string name; std::getline(list, name);) files += " " + rtl + name;
  const std::string cmd = "cd " + dir + " && iverilog -g2012 -s replay_tb -o replay f.hex.sv" +
                          files + " && vvp -n replay +frames=f.hex > replay.log";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const Json j = read_json(dir + "/f.json");
  const std::string log = slurp(dir + "/replay.log");
  EXPECT_NE(log.find("cycles " + std::to_string(j["cycles"].get<int>())), std::string::npos) << log;
  EXPECT_NE(log.find("done_pulses " + std::to_string(j["commands"].get<int>())), std::string::npos)
      << log;
  for (int i = 0; i < 3; ++i)
    EXPECT_NE(log.find("axis " + std::to_string(i) + " steps " +
                       std::to_string(j["steps"][i].get<int>()) + " pos " +
                       std::to_string(j["end_position"][i].get<int>())),
              std::string::npos)
        << log;
}

TEST(CosimCli, TimingViolationExitsOne) {
  const CliResult r = run_hwinterp(
      "cosim --core dda_line --line 0,0,8,0 --mode direct "
      "--step-len 4 --step-space 4 --inject glitch@20");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("timing: cycle"), std::string::npos) << r.out;
}

// Bad input: exit 2, one line on stderr naming the offending value, and no
// simulation started.
TEST(CosimCli, BadInputOneLineNamingTheValue) {
  const std::pair<const char*, const char*> cases[] = {
      {"--core dda_line --line 0,0,3000000000,0", "3000000000"},
      {"--core dda_line --line 0,0,1x,2", "'1x'"},
      {"--core dda_line --line 0,0,1", "'0,0,1'"},
      {"--core ppc_nope --line 0,0,1,1", "'ppc_nope'"},
      {"--core dda_line --axes 5 --line 0,0,1,1", "5 axes"},
      {"--core dda_line --variant dda_line_n9 --line 0,0,1,1", "'dda_line_n9'"},
      {"--core dda_line --line 0,0,1,1 --mode fast", "'fast'"},
      {"--core dda_line --random 0", "--random: 0"},
      {"--core dda_line --random 5 --seed -1", "'-1'"},
      {"--core dda_line --line 0,0,1,1 --random 3", "2 given"},
      {"--core dda_line --line 0,0,1,1 --feed 0", "--feed: 0"},
      {"--core dda_line --line 0,0,1,1 --feed 0.000001", "0.000001"},
      {"--core dda_line --line 0,0,1,1 --dir-hold 65536", "65536"},
      {"--core dda_line --job /no/such.job", "/no/such.job"},
      {"--core dda_line --line 0,0,1,1 --inject flip@3", "'flip@3'"},
      {"--core dda_line --line 0,0,1,1 --abort-at 0", "--abort-at: 0"},
      {"--core dda_line --line 0,0,1,1 --vcd /no/dir/t.vcd", "/no/dir/t.vcd"},
      {"--line 0,0,1,1", "--core"},
  };
  for (const auto& [args, named] : cases) {
    const CliResult r = run_hwinterp(std::string("cosim ") + args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_EQ(r.out, "") << args;
  }
}

// --help lists the shared options and every core and variant; with --core
// it adds the core's own options.
TEST(CosimCli, HelpListsTheContractCoresAndVariants) {
  const CliResult r = run_hwinterp("cosim --help");
  EXPECT_EQ(r.code, 0);
  for (const char* o : {"--core", "--variant", "--job", "--random", "--seed", "--mode", "--json",
                        "--vcd", "--fst", "--abort-at", "dda_line (dda_line_n2, dda_line_n4"})
    EXPECT_NE(r.out.find(o), std::string::npos) << o;
  EXPECT_EQ(r.out.find("--half-preload"), std::string::npos);
  const CliResult d = run_hwinterp("cosim --core dda_line --help");
  for (const char* o : {"--line", "--paper-lines", "--half-preload"})
    EXPECT_NE(d.out.find(o), std::string::npos) << o;
}

TEST(RegressCli, SmallRegressionPassesAndReportsEveryCore) {
  const std::string json = scratch_dir("regress") + "/r.json";
  const CliResult r = run_hwinterp("regress --random 10 --seed 4 --json " + json);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("PASS"), std::string::npos);
  const Json j = read_json(json);
  EXPECT_EQ(j["passed"], true);
  size_t variants = 0;
  for (const auto& [core, summary] : j["cores"].items()) {
    EXPECT_EQ(summary["passed"], true) << core;
    variants += summary["runs"].get<size_t>() / 2;  // both modes
  }
  EXPECT_EQ(j["cores"].size(), hwinterp::tb::all_cores().size());
  EXPECT_GE(variants, 7u);
  ASSERT_EQ(j["runs"].size(), 2 * variants);
  for (const auto& run : j["runs"]) {
    EXPECT_EQ(run["passed"], true);
    bool random = false;
    for (const auto& c : run["cases"]) {
      EXPECT_EQ(c["passed"], true) << c["variant"] << " " << c["case"];
      EXPECT_GE(c["seconds"].get<double>(), 0.0);
      random = random || c["case"] == "random_abort_hold";
    }
    EXPECT_TRUE(random) << run["variant"];
    // Seconds are reported, never compared here: timings belong to the
    // benchmarks (docs/performance.md), not to a unit test on a shared machine.
    EXPECT_GE(run["seconds"].get<double>(), 0.0) << run["variant"] << " " << run["mode"];
  }
}

// regress --shard K/N: the union of the N slices is the unsharded run, case
// for case; merging them gives its report (timings aside) and its JUnit.
// merge refuses a shard given twice and reports a missing one.
Json without_timings(const Json& j) {
  if (j.is_object()) {
    Json out = Json::object();
    for (const auto& [k, v] : j.items())
      if (k != "seconds" && k != "cycles_per_second" && k != "shards") out[k] = without_timings(v);
    return out;
  }
  if (j.is_array()) {
    Json out = Json::array();
    for (const auto& v : j) out.push_back(without_timings(v));
    return out;
  }
  return j;
}

TEST(RegressCli, ShardsMergeToTheUnshardedRun) {
  const std::string dir = scratch_dir("shards");
  const std::string base = "regress --random 8 --seed 6 --modes direct ";
  ASSERT_EQ(run_hwinterp(base + "--json " + dir + "/full.json").code, 0);
  for (const int n : {2, 3}) {
    std::string shards;
    size_t cases = 0;
    for (int k = 1; k <= n; ++k) {
      const std::string out = dir + "/s" + std::to_string(k) + "of" + std::to_string(n) + ".json";
      const CliResult r = run_hwinterp(base + "--shard " + std::to_string(k) + "/" +
                                       std::to_string(n) + " --json " + out);
      ASSERT_EQ(r.code, 0) << r.out << r.err;
      const Json shard = read_json(out);
      for (const auto& run : shard["runs"]) cases += run["cases"].size();
      shards += " " + out;
    }
    const CliResult m = run_hwinterp("merge" + shards + " --json " + dir + "/merged.json --junit " +
                                     dir + "/merged.xml");
    ASSERT_EQ(m.code, 0) << m.out << m.err;
    const Json full = read_json(dir + "/full.json"), merged = read_json(dir + "/merged.json");
    size_t full_cases = 0;
    for (const auto& run : full["runs"]) full_cases += run["cases"].size();
    EXPECT_EQ(cases, full_cases) << n << " shards: every case exactly once";
    EXPECT_EQ(without_timings(merged), without_timings(full)) << n << " shards";
    const std::string xml = slurp(dir + "/merged.xml");
    EXPECT_EQ(static_cast<size_t>(std::count(xml.begin(), xml.end(), '\n')) > full_cases, true);
    EXPECT_NE(xml.find("<testcase classname=\"dda_line_n2.direct\" name=\"004_line1\""),
              std::string::npos);
  }
  const CliResult twice =
      run_hwinterp("merge " + dir + "/s1of2.json " + dir + "/s1of2.json --json " + dir + "/x.json");
  EXPECT_EQ(twice.code, 2);
  EXPECT_NE(twice.err.find("shard 1/2 given twice"), std::string::npos) << twice.err;
  const CliResult missing = run_hwinterp("merge " + dir + "/s1of3.json " + dir + "/s3of3.json");
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.out.find("missing shard 2/3"), std::string::npos) << missing.out;
}

}  // namespace

// The command line against what users type (issue "Nothing destroyed,
// nothing injected, nothing run forever"). Output files: an output
// that is an input or another output is refused by device and inode before
// anything runs; a refused run leaves every existing file as it was and no
// temporary behind; an output that cannot be created is refused before the
// run; a completed run puts every output in place. And `merge` names the
// file and the field of a malformed report instead of crashing. A feed hold
// or a 0 % override beyond the clock ceiling is refused before it runs. A
// machine value is named by its key.
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "run_hwinterp.h"

namespace hwinterp::testing {
namespace {

const char kProgram[] = "G21 G90\nG1 X1 Y0.5 F600\nM2\n";

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The names in `dir` that a run left behind as temporaries.
std::vector<std::string> temporaries(const std::string& dir) {
  std::vector<std::string> left;
  if (DIR* d = opendir(dir.c_str())) {
    while (const dirent* e = readdir(d))
      if (std::string(e->d_name).rfind(".hwinterp-", 0) == 0) left.push_back(e->d_name);
    closedir(d);
  }
  return left;
}

TEST(CliOutputs, AnOutputThatIsAnInputOrAnotherOutputIsRefused) {
  const std::string d = scratch_dir("outputs_same");
  const std::string ngc = d + "/v.ngc", machine = d + "/m.json";
  write(ngc, kProgram);
  write(machine, "{\"clock_hz\": 1000000}\n");
  const std::string run = "gcode " + ngc + " --mode direct --progress 0 ";
  struct Case {
    std::string args, named;
  };
  const std::vector<Case> cases = {
      {"--moves-csv " + ngc, "the program"},
      {"--machine " + machine + " --json " + machine, "--machine"},
      {"--moves-csv " + d + "/s.csv --step-times " + d + "/./s.csv", "--moves-csv"},
      {"--json " + d + "/f --moves-csv " + d + "/f", "--json"},
      {"--plot " + d + "/k.png --plot-kinematics " + d + "/k.png", "--plot"},
  };
  for (const Case& c : cases) {
    const CliResult r = run_hwinterp(run + c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(r.out.find("PASS"), std::string::npos) << c.args << ": it ran";
  }
  EXPECT_EQ(slurp(ngc), kProgram);
  EXPECT_EQ(slurp(machine), "{\"clock_hz\": 1000000}\n");
  // The same file by another name (a hard link): compared by inode.
  ASSERT_EQ(link(ngc.c_str(), (d + "/alias.csv").c_str()), 0);
  const CliResult r = run_hwinterp(run + "--moves-csv " + d + "/alias.csv");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_EQ(slurp(ngc), kProgram);
  EXPECT_TRUE(temporaries(d).empty());
}

TEST(CliOutputs, ARefusedRunLeavesEveryExistingFileAsItWas) {
  const std::string d = scratch_dir("outputs_refused");
  write(d + "/far.ngc", "G21 G90\nG1 X100000000 F100\nM2\n");
  write(d + "/keep.csv", "keep\n");
  write(d + "/keep.json", "{}\n");
  const CliResult r =
      run_hwinterp("gcode " + d + "/far.ngc --mode direct --progress 0 --moves-csv " + d +
                   "/keep.csv --json " + d + "/keep.json --plot " + d + "/keep.png");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_EQ(slurp(d + "/keep.csv"), "keep\n");
  EXPECT_EQ(slurp(d + "/keep.json"), "{}\n");
  struct stat st {};
  EXPECT_NE(stat((d + "/keep.png").c_str(), &st), 0) << "a refused run wrote the plot";
  EXPECT_NE(stat((d + "/keep.png.points.csv").c_str(), &st), 0) << "the plot's data was left";
  EXPECT_TRUE(temporaries(d).empty());
}

TEST(CliOutputs, AnOutputThatCannotBeCreatedIsRefusedBeforeTheRun) {
  const std::string d = scratch_dir("outputs_proc");
  write(d + "/v.ngc", kProgram);
  for (const char* o : {"--moves-csv", "--json"}) {
    const CliResult r = run_hwinterp("gcode " + d + "/v.ngc --mode direct --progress 0 " + o +
                                     " /proc/hwinterp_x.out");
    EXPECT_EQ(r.code, 2) << o << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(o), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("PASS"), std::string::npos) << o << ": the run went ahead";
  }
}

TEST(CliOutputs, ACompletedRunPutsEveryOutputInPlace) {
  const std::string d = scratch_dir("outputs_done");
  write(d + "/v.ngc", kProgram);
  write(d + "/moves.csv", "old\n");
  const CliResult r =
      run_hwinterp("gcode " + d + "/v.ngc --mode direct --progress 0 --moves-csv " + d +
                   "/moves.csv --step-times " + d + "/steps.csv --json " + d + "/r.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_EQ(slurp(d + "/moves.csv").rfind("move,", 0), 0u) << slurp(d + "/moves.csv");
  EXPECT_EQ(slurp(d + "/steps.csv").rfind("clock,axis,dir", 0), 0u);
  EXPECT_NE(slurp(d + "/r.json").find("\"passed\": true"), std::string::npos);
  // A new file gets the mode an ordinary write gives it.
  const mode_t mask = umask(0);
  umask(mask);
  struct stat st {};
  ASSERT_EQ(stat((d + "/r.json").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
  EXPECT_TRUE(temporaries(d).empty());
}

// A device, a pipe or a name under /dev is written in place: nothing is
// renamed onto /dev/null or onto the /dev/stdout link.
TEST(CliOutputs, ADeviceIsWrittenInPlace) {
  const std::string d = scratch_dir("outputs_device");
  write(d + "/v.ngc", kProgram);
  struct stat before {
  }, after{};
  ASSERT_EQ(lstat("/dev/stdout", &before), 0);
  const CliResult r = run_hwinterp("gcode " + d + "/v.ngc --mode direct --progress 0 --json " +
                                   "/dev/stdout --moves-csv /dev/null");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  ASSERT_EQ(stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode)) << "/dev/null was replaced";
  ASSERT_EQ(lstat("/dev/stdout", &after), 0);
  EXPECT_EQ(after.st_ino, before.st_ino) << "/dev/stdout was replaced";
  EXPECT_EQ(after.st_mode, before.st_mode) << "/dev/stdout was replaced";
  EXPECT_TRUE(temporaries("/dev").empty());
}

TEST(CliOutputs, MergeNamesTheFileAndTheFieldOfAMalformedReport) {
  const std::string d = scratch_dir("outputs_merge");
  const std::string head = "{\"seed\":1,\"random_commands\":3,";
  struct Case {
    std::string report, field;
  };
  const std::vector<Case> cases = {
      {head + "\"shards\":[\"1/1\"],\"runs\":[{}]}", "runs[0].core"},
      {head + "\"shards\":[3],\"runs\":[]}", "shards[0]"},
      {head + "\"shards\":[\"1\"],\"runs\":[]}", "shards[0]"},
      {"{\"seed\":\"1\",\"random_commands\":3,\"shards\":[\"1/1\"],\"runs\":[]}", "seed"},
      {head +
           "\"shards\":[\"1/1\"],\"runs\":[{\"core\":\"c\",\"variant\":\"v\",\"mode\":\"direct\","
           "\"first_case\":0,\"seconds\":1,\"cases\":[{\"case\":\"x\"}]}]}",
       "runs[0].cases[0]"},
  };
  for (const Case& c : cases) {
    write(d + "/bad.json", c.report);
    const CliResult r = run_hwinterp("merge " + d + "/bad.json");
    EXPECT_EQ(r.code, 2) << c.report << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.field), std::string::npos) << r.err;
  }
}

TEST(CliBounds, PausesBeyondTheClockCeilingExitTwoBeforeTheyRun) {
  const std::string d = scratch_dir("bounds_pauses");
  write(d + "/v.ngc", kProgram);
  const std::string run = "gcode " + d + "/v.ngc --mode direct --progress 0 --machine " +
                          std::string(HWINTERP_SOURCE_DIR) +
                          "/tests/data/gcode/machine_profile.json ";
  struct Case {
    std::string args, named;
  };
  const std::vector<Case> cases = {
      {"--feed-hold 0.01:1e9", "--feed-hold FOR"},
      {"--feed-hold 0.01:1e300", "--feed-hold FOR"},
      {"--feed-hold 1e300:1", "--feed-hold AT"},
      {"--feed-override 0.01:0,1e9:100", "--feed-override AT"},
      {"--feed-hold 0.01:150000 --feed-override 0.02:0,150000:100", "0 % override"},
      {"--feed-hold 0.01:1 --max-clocks 1000", "--max-clocks 1000"},
      {"--max-clocks 0", "--max-clocks"},
  };
  for (const Case& c : cases) {
    const CliResult r = run_hwinterp(run + c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(r.out.find("PASS"), std::string::npos) << c.args << ": it ran";
  }
  // Within the ceiling it runs.
  const CliResult ok = run_hwinterp(run + "--feed-hold 0.01:0.5");
  EXPECT_EQ(ok.code, 0) << ok.out << ok.err;
}

// The committed profile machine with clock_hz and each limit swept over
// decades: every point passes (exit 0, PASS) or is refused before it runs
// (exit 2, one line naming a key or an option), never a failed check (exit
// 1): a value the hardware cannot represent is bad input, not a hardware
// fault. --max-clocks keeps the slow points short (they are refused by the
// time-optimal bound).
TEST(CliBounds, MachineSweepPassesOrIsRefusedNeverFails) {
  const std::string d = scratch_dir("bounds_sweep");
  write(d + "/p.ngc", "G21 G90\nG1 X0.2 Y0.1 F600\nG2 X0.4 Y0.1 I0.1 J0\nM2\n");
  const std::string profile =
      slurp(std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/machine_profile.json");
  int passed = 0, refused = 0;
  for (const char* hz : {"100000", "500000", "5000000"})
    for (const char* key : {"max_velocity", "max_accel", "max_jerk"})
      for (const char* factor : {"1e-9", "1e-4", "1e-1", "1e2", "1e6"}) {
        // The machine with clock_hz and every axis's `key` scaled.
        std::string text = profile;
        const std::string clock = "\"clock_hz\": 500000";
        const size_t c = text.find(clock);
        ASSERT_NE(c, std::string::npos);
        text.replace(c, clock.size(), std::string("\"clock_hz\": ") + hz);
        const size_t k = text.find(std::string("\"") + key + "\": {");
        ASSERT_NE(k, std::string::npos) << key;
        const size_t open = text.find('{', k), close = text.find('}', k);
        // Each whole number gets the factor's exponent: "X": 1000 -> "X": 1000e-4.
        const std::string limits = text.substr(open, close - open);
        const std::string exponent = std::string(factor).substr(1);
        std::string out;
        for (size_t i = 0; i < limits.size(); ++i) {
          out += limits[i];
          const bool digit = std::isdigit(static_cast<unsigned char>(limits[i]));
          if (digit &&
              (i + 1 == limits.size() || !std::isdigit(static_cast<unsigned char>(limits[i + 1]))))
            out += exponent;
        }
        text.replace(open, close - open, out);
        write(d + "/m.json", text);
        const CliResult r = run_hwinterp("gcode " + d + "/p.ngc --mode direct --progress 0 " +
                                         "--max-clocks 2e6 --machine " + d + "/m.json");
        const std::string point = std::string("clock_hz ") + hz + ", " + key + " x " + factor;
        EXPECT_TRUE(r.code == 0 || r.code == 2) << point << ": exit " << r.code << "\n"
                                                << r.out << r.err;
        if (r.code == 0) {
          EXPECT_NE(r.out.find("PASS"), std::string::npos) << point;
          ++passed;
        }
        if (r.code == 2) {
          EXPECT_EQ(r.out.find("PASS"), std::string::npos) << point << ": refused after a run";
          ++refused;
        }
      }
  // Both kinds are in the sweep: it measures something.
  EXPECT_GT(passed, 10);
  EXPECT_GT(refused, 10);
}

// A machine file's value the profile cannot hold is named by its key, in
// the file's units; a number beyond a double by its key, line and column.
TEST(CliMessages, MachineValuesAreNamedByTheirKey) {
  const std::string d = scratch_dir("messages_machine");
  write(d + "/v.ngc", kProgram);
  const std::string profile =
      slurp(std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/machine_profile.json");
  struct Case {
    std::string from, to, named;
  };
  const std::vector<Case> cases = {
      {"\"max_accel\": {\"X\": 1000", "\"max_accel\": {\"X\": 1e-9", "max_accel.X = 1e-09"},
      {"\"max_jerk\": {\"X\": 50000", "\"max_jerk\": {\"X\": 1e-7", "max_jerk.X = 1e-07"},
      {"\"max_jerk\": {\"X\": 50000", "\"max_jerk\": {\"X\": 1e999", "max_jerk.X (line 9"},
  };
  for (const Case& c : cases) {
    std::string text = profile;
    const size_t at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    text.replace(at, c.from.size(), c.to);
    write(d + "/m.json", text);
    const CliResult r =
        run_hwinterp("gcode " + d + "/v.ngc --mode direct --progress 0 --machine " + d + "/m.json");
    EXPECT_EQ(r.code, 2) << c.to << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << c.to << ": " << r.err;
  }
}

// A long run says how far it is: the progress line gives the percent of the
// clocks estimated before the run and the time left, and the estimate is
// close to the real count (without the profile each command at its feed
// word or the step/dir stage's rate; with it the plan's levels).
TEST(CliProgress, GcodeGivesThePercentOfItsEstimateAndTheTimeLeft) {
  const std::string d = scratch_dir("progress");
  const std::string data = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";
  struct Case {
    std::string args;
    double tolerance;  // of the estimate, relative
  };
  const std::vector<Case> cases = {
      {"words.ngc --machine " + data + "machine_default.json", 0.01},
      {"words.ngc --feed programmed --machine " + data + "machine_profile.json", 0.05},
  };
  for (const Case& c : cases) {
    const CliResult r = run_hwinterp(
        "gcode " + data + c.args + " --mode direct --progress 100000 " + "--json " + d + "/r.json");
    ASSERT_EQ(r.code, 0) << c.args << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(" % of ~"), std::string::npos) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(" left)"), std::string::npos) << c.args << ": " << r.err;
    const auto j = nlohmann::json::parse(slurp(d + "/r.json"));
    const double estimated = j.at("estimated_clocks").get<double>();
    const double simulated = j.at("simulated_clocks").get<double>();
    EXPECT_LT(std::fabs(estimated - simulated), c.tolerance * simulated)
        << c.args << ": estimated " << estimated << ", simulated " << simulated;
  }
}

// The bus run of `gcode --bus` gives its percent of the lockstep run's clocks
// (the same commands), and `cosim` the percent of its cases' commands.
TEST(CliProgress, BusRunsAndCosimGiveTheirPercent) {
  const std::string data = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";
  const CliResult bus =
      run_hwinterp("gcode " + data + "words.ngc --machine " + data +
                   "machine_default.json --mode direct --bus wishbone " + "--progress 100000");
  ASSERT_EQ(bus.code, 0) << bus.out << bus.err;
  const size_t line = bus.err.find("[motion_soc bus]");
  ASSERT_NE(line, std::string::npos) << bus.err;
  EXPECT_NE(bus.err.find(" % of ~", line), std::string::npos) << bus.err;
  const CliResult cosim =
      run_hwinterp("cosim --core dda_line --mode direct --random 200 --seed 3 --progress 20000");
  ASSERT_EQ(cosim.code, 0) << cosim.out << cosim.err;
  EXPECT_NE(cosim.err.find(" % of the commands, ~"), std::string::npos) << cosim.err;
}

// board-sim, bounded by --max-clocks, says how far towards it the run is.
TEST(CliProgress, BoardSimGivesItsShareOfItsBound) {
  const CliResult r = run_hwinterp(
      "board-sim --board colorlight_5a_75b --clock-hz 1000000 --no-profile --max-clocks 6000000 "
      "--progress 1");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.err.find(" % of its bound, ~"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hwinterp::testing

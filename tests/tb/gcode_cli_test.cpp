// `hwinterp gcode`: the committed part programs (tests/data/gcode/) through
// motion_top in lockstep, from the G-code and from rs274's canonical
// commands; the two reach the same lattice end points move for move; the
// report's figures; bad input exits 2 naming what is wrong and runs nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "run_hwinterp.h"

namespace hwinterp::testing {
namespace {

const std::string kData = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";

// The columns named `names` of every data row.
std::vector<std::vector<std::string>> columns(const std::vector<std::vector<std::string>>& rows,
                                              const std::vector<std::string>& names) {
  std::vector<std::vector<std::string>> out;
  if (rows.empty()) return out;
  std::vector<size_t> idx;
  for (const auto& n : names) {
    size_t k = 0;
    while (k < rows[0].size() && rows[0][k] != n) ++k;
    EXPECT_LT(k, rows[0].size()) << "no column " << n;
    idx.push_back(k);
  }
  for (size_t r = 1; r < rows.size(); ++r) {
    std::vector<std::string> v;
    for (size_t k : idx) v.push_back(k < rows[r].size() ? rows[r][k] : "");
    out.push_back(v);
  }
  return out;
}

class GcodeProgram : public ::testing::TestWithParam<std::string> {};

// Every committed program runs clean in direct mode, from the G-code and
// from its canon file, to the same lattice end point move for move.
TEST_P(GcodeProgram, RunsCleanFromNgcAndCanonToTheSameEnds) {
  const std::string dir = scratch_dir("gcode_" + GetParam());
  const std::string ngc = kData + GetParam() + ".ngc", canon = kData + GetParam() + ".canon";
  const CliResult a = run_hwinterp("gcode " + ngc + " --mode direct --progress 0 --json " + dir +
                                   "/ngc.json --moves-csv " + dir + "/ngc.csv");
  ASSERT_EQ(a.code, 0) << a.out << a.err;
  EXPECT_NE(a.out.find("PASS"), std::string::npos) << a.out;
  const CliResult b =
      run_hwinterp("gcode --canon " + canon + " --mode direct --progress 0 --json " + dir +
                   "/canon.json --moves-csv " + dir + "/canon.csv");
  ASSERT_EQ(b.code, 0) << b.out << b.err;

  const auto j = nlohmann::json::parse(slurp(dir + "/ngc.json"));
  EXPECT_TRUE(j.at("passed").get<bool>());
  EXPECT_EQ(j.at("end_mismatches").get<int>(), 0);
  EXPECT_GT(j.at("moves").get<int>(), 0);
  EXPECT_GT(j.at("visited_points").get<int>(), 0);
  // Every visited point within 2 steps of its move's programmed path: the
  // engines' bounds (< 1 step from the lattice path) plus the compiler's arc
  // tolerance (1 step, tb/gcode/motion_compiler.h). Measured: 1.86 at most.
  EXPECT_LT(j.at("max_contour_error_steps").get<double>(), 2.0) << a.out;
  EXPECT_GT(j.at("programmed_time_s").get<double>(), 0.0);

  const std::vector<std::string> ends = {"x_steps", "y_steps", "z_steps"};
  const auto from_ngc = columns(read_csv(dir + "/ngc.csv"), ends);
  const auto from_canon = columns(read_csv(dir + "/canon.csv"), ends);
  ASSERT_FALSE(from_ngc.empty());
  // rs274 prints every motion move, so the rows pair up one for one.
  ASSERT_EQ(from_ngc.size(), from_canon.size());
  for (size_t k = 0; k < from_ngc.size(); ++k)
    EXPECT_EQ(from_ngc[k], from_canon[k]) << GetParam() << " move " << k + 1;
}

INSTANTIATE_TEST_SUITE_P(Committed, GcodeProgram,
                         ::testing::Values("arcs", "corners", "engraving", "helix", "incremental",
                                           "inch", "modal", "words"));

// SystemC mode runs the same program to the same result as direct mode.
TEST(GcodeCli, SystemcModeMatchesDirect) {
  const std::string dir = scratch_dir("gcode_sc");
  const std::string ngc = kData + "incremental.ngc";
  const CliResult d =
      run_hwinterp("gcode " + ngc + " --mode direct --progress 0 --json " + dir + "/d.json");
  const CliResult s =
      run_hwinterp("gcode " + ngc + " --mode systemc --progress 0 --json " + dir + "/s.json");
  ASSERT_EQ(d.code, 0) << d.out << d.err;
  ASSERT_EQ(s.code, 0) << s.out << s.err;
  const auto jd = nlohmann::json::parse(slurp(dir + "/d.json"));
  const auto js = nlohmann::json::parse(slurp(dir + "/s.json"));
  for (const char* k : {"simulated_clocks", "visited_points", "max_contour_error_mm", "commands"})
    EXPECT_EQ(jd.at(k), js.at(k)) << k;
}

// --feed programmed simulates the feed words: the simulated time is the
// machining time the feed words give (a run of clocks, within a few).
TEST(GcodeCli, ProgrammedFeedSimulatesTheFeedWords) {
  const std::string dir = scratch_dir("gcode_feed");
  const std::string ngc = kData + "modal.ngc";
  // A 500 kHz clock keeps the run short (23 s of machining, 12 M clocks).
  std::ofstream(dir + "/slow.json") << R"({"clock_hz": 500000})";
  const CliResult r =
      run_hwinterp("gcode " + ngc + " --mode direct --progress 0 --feed programmed " +
                   "--machine " + dir + "/slow.json --json " + dir + "/p.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(dir + "/p.json"));
  const double sim = j.at("simulated_time_s").get<double>();
  const double words = j.at("feed_word_time_s").get<double>();
  const double programmed = j.at("programmed_time_s").get<double>();
  EXPECT_NEAR(sim, words, 1e-4 * words + 1e-5);
  // 24-bit feed words keep the programmed feeds within 0.1 %.
  EXPECT_NEAR(words, programmed, 1e-3 * programmed) << r.out;
}

// --plot writes the PNG (matplotlib) and removes its points file.
TEST(GcodeCli, PlotWritesAPng) {
  const std::string dir = scratch_dir("gcode_plot");
  const CliResult r =
      run_hwinterp("gcode " + kData + "incremental.ngc --mode direct --progress 0 " + "--plot " +
                   dir + "/path.png");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const std::string png = slurp(dir + "/path.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_TRUE(slurp(dir + "/path.png.points.csv").empty());
}

// A file name is an argument to the plot scripts, never a command: programs
// and PNGs named with quotes, semicolons, spaces, $(...) and a newline plot
// as any other, and nothing they spell runs (issue 38: `it's;touch
// PWNED;'.ngc` with --plot ran `touch PWNED` through a shell).
TEST(GcodeCli, PlotFileNamesAreNeverRunAsCommands) {
  const std::string dir = scratch_dir("gcode_plot_names");
  const auto sh = [](const std::string& s) {  // quoted for run_hwinterp's shell
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  const std::string program = slurp(kData + "incremental.ngc");
  const std::vector<std::string> names = {"it's;touch PWNED1;'", "bob's part", "$(touch PWNED2)",
                                          "`touch PWNED3`",      "new\nline",  "-dash"};
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string ngc = dir + "/" + names[i] + ".ngc";
    std::ofstream(ngc) << program;
    const std::string png = dir + "/" + names[i] + ";touch PWNED" + std::to_string(i) + ".png";
    const std::string kin = dir + "/k" + names[i] + ".png";
    const CliResult r = run_hwinterp("gcode " + sh(ngc) + " --mode direct --progress 0 --plot " +
                                     sh(png) + " --plot-kinematics " + sh(kin));
    ASSERT_EQ(r.code, 0) << names[i] << ": " << r.out << r.err;
    EXPECT_EQ(slurp(png).substr(1, 3), "PNG") << names[i] << ": " << r.out;
    EXPECT_EQ(slurp(kin).substr(1, 3), "PNG") << names[i] << ": " << r.out;
  }
  for (int k = 0; k < 6; ++k)
    for (const std::string& where : {std::string("."), dir}) {
      const std::string f = where + "/PWNED" + std::to_string(k);
      EXPECT_NE(access(f.c_str(), F_OK), 0) << f << " exists: a file name ran as a command";
    }
}

// --plot-kinematics: speed, acceleration and jerk over time, from the
// estimator's windows, with the machine's limits; its data files go.
TEST(GcodeCli, PlotKinematicsWritesAPng) {
  const std::string dir = scratch_dir("gcode_plot_kinematics");
  std::ofstream(dir + "/mill.json") << R"({"clock_hz": 1000000, "max_velocity": {"X": 500}})";
  const CliResult r =
      run_hwinterp("gcode " + kData + "incremental.ngc --mode direct --progress 0 " + "--machine " +
                   dir + "/mill.json --plot-kinematics " + dir + "/kin.png");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const std::string png = slurp(dir + "/kin.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_TRUE(slurp(dir + "/kin.png.csv").empty());
  EXPECT_TRUE(slurp(dir + "/kin.png.json").empty());
}

// --step-times: the pulses of every axis add up to the lattice point the
// program ends on, one row per step the report counts.
TEST(GcodeCli, StepTimesAddUpToTheEndPoint) {
  const std::string dir = scratch_dir("gcode_step_times");
  std::ofstream(dir + "/mill.json")
      << R"({"clock_hz": 1000000, "max_velocity": {"X": 100}, "max_jerk": {"Z": 5e4}})";
  const CliResult r = run_hwinterp("gcode " + kData + "modal.ngc --mode direct --step-times " +
                                   dir + "/t.csv --moves-csv " + dir + "/m.csv --json " + dir +
                                   "/r.json --machine " + dir + "/mill.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto rows = read_csv(dir + "/t.csv");
  ASSERT_GT(rows.size(), 1u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"clock", "axis", "dir"}));
  std::map<std::string, long long> sum, count;
  for (size_t i = 1; i < rows.size(); ++i) {
    sum[rows[i][1]] += std::stoll(rows[i][2]);
    ++count[rows[i][1]];
  }
  const auto moves = read_csv(dir + "/m.csv");
  const auto end = columns(moves, {"x_steps", "y_steps", "z_steps", "a_steps"}).back();
  EXPECT_EQ(sum["X"], std::stoll(end[0]));
  EXPECT_EQ(sum["Y"], std::stoll(end[1]));
  EXPECT_EQ(sum["Z"], std::stoll(end[2]));
  EXPECT_EQ(sum["A"], std::stoll(end[3]));
  const auto report = nlohmann::json::parse(slurp(dir + "/r.json"));
  const auto steps = report["steps"].get<std::vector<long long>>();
  ASSERT_EQ(steps.size(), 4u);
  EXPECT_EQ(count["X"], steps[0]);
  EXPECT_EQ(count["Y"], steps[1]);
  EXPECT_EQ(count["Z"], steps[2]);
  EXPECT_EQ(count["A"], steps[3]);

  // The kinematics the stream asks for, beside the machine's limits: at full
  // feed (no profile) far beyond them, but never past one step a clock
  // (at 1 MHz, for 10 ms windows over the program's ~0.5 s).
  const auto& k = report["kinematics"];
  EXPECT_EQ(k["window_s"].get<double>(), 0.01);
  const auto& x = k["axes"]["X"];
  EXPECT_EQ(x["speed"]["limit"].get<double>(), 100);
  EXPECT_TRUE(x["accel"]["limit"].is_null());
  EXPECT_EQ(k["axes"]["Z"]["jerk"]["limit"].get<double>(), 5e4);
  EXPECT_GT(x["speed"]["max"].get<double>(), 100);
  EXPECT_LE(x["speed"]["max"].get<double>(), 1e6 / 1000 + x["speed"]["tolerance"].get<double>());
  EXPECT_GT(x["accel"]["max"].get<double>(), 0);
  EXPECT_GT(k["path"]["speed"]["max"].get<double>(), 0);
  EXPECT_NE(r.out.find("peak speed, accel, jerk: X"), std::string::npos) << r.out;
}

// Bad input: exit 2 with the file, line and word, and nothing runs.
TEST(GcodeCli, BadInputExitsTwoNamingIt) {
  const std::string dir = scratch_dir("gcode_bad");
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + "/" + name) << text;
    return dir + "/" + name;
  };
  const std::string comp = write("comp.ngc", "G21 G90\nG1 X1 F100\nG41 D1\nG1 X2\nM2\n");
  CliResult r = run_hwinterp("gcode " + comp + " --mode direct");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("comp.ngc:3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("G41"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--canon"), std::string::npos) << r.err;

  const std::string junk = write("junk.ngc", "G1 X1 F100\nthis is not gcode\n");
  r = run_hwinterp("gcode " + junk + " --mode direct");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("junk.ngc:2"), std::string::npos) << r.err;

  r = run_hwinterp("gcode " + dir + "/missing.ngc");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("missing.ngc"), std::string::npos) << r.err;

  r = run_hwinterp("gcode " + kData + "arcs.ngc --variant dda_line_n2");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("dda_line_n2"), std::string::npos) << r.err;

  r = run_hwinterp("gcode " + kData + "arcs.ngc --moves-csv /nonexistent/dir/m.csv");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/nonexistent/dir/m.csv"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("PASS"), std::string::npos) << "ran despite bad output path";

  r = run_hwinterp("gcode " + kData + "arcs.ngc --feed fast");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("fast"), std::string::npos) << r.err;

  r = run_hwinterp("gcode " + kData + "arcs.ngc --canon " + kData + "arcs.canon");
  EXPECT_EQ(r.code, 2);

  r = run_hwinterp("gcode " + kData + "arcs.ngc --profile smooth");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--profile: 'smooth'"), std::string::npos) << r.err;

  // A profile needs every axis's max_accel (and max_jerk for an S-curve).
  const std::string nojerk = write("nojerk.json", R"({"max_accel": {"X": 1000, "Y": 1000,
      "Z": 1000, "A": 1000}, "profile": "scurve"})");
  r = run_hwinterp("gcode " + kData + "arcs.ngc --machine " + nojerk);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("needs max_jerk for axis X"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("clocks"), std::string::npos) << "simulated: " << r.out;
  r = run_hwinterp("gcode " + kData + "arcs.ngc --machine " + nojerk + " --profile wavy");
  EXPECT_EQ(r.code, 2);
}

// A path the machine cannot reach exits 2 before any clock is simulated:
// beyond the position counters (it used to run for minutes), or out of the
// machine file's travel, with the line and the axis.
TEST(GcodeCli, APathOutOfReachExitsTwoBeforeItRuns) {
  const std::string dir = scratch_dir("gcode_reach");
  const std::string far = dir + "/far.ngc";
  std::ofstream(far) << "G21 G90\nG0 X1\nG1 X100000000 F1000\nM2\n";
  CliResult r = run_hwinterp("gcode " + far + " --mode direct");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("far.ngc:3: X reaches 1e+08 mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("POS_W"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("clocks"), std::string::npos) << "simulated: " << r.out;

  const std::string machine = dir + "/mill.json";
  std::ofstream(machine) << R"({"travel": {"Y": [-2, 40]}})";
  r = run_hwinterp("gcode " + kData + "arcs.ngc --mode direct --machine " + machine);
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("arcs.ngc:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Y reaches"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("travel [-2, 40]"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hwinterp::testing

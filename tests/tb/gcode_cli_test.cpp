// `hwinterp gcode`: the committed part programs (tests/data/gcode/) through
// motion_top in lockstep, from the G-code and from rs274's canonical
// commands; the two reach the same lattice end points move for move; the
// report's figures; bad input exits 2 naming what is wrong and runs nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "run_hwinterp.h"

namespace hwinterp::testing {
namespace {

const std::string kData = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";

// The rows of a --moves-csv file: header first.
std::vector<std::vector<std::string>> read_csv(const std::string& path) {
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
                         ::testing::Values("arcs", "engraving", "incremental", "inch", "modal",
                                           "words"));

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
}

}  // namespace
}  // namespace hwinterp::testing

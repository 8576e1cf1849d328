// `hwinterp gcode --profile`: the committed part programs at their programmed
// feeds with the jerk-limited feed profile (tests/tb/gcode_profile_check.h).
// CI runs the short programs in direct mode, one in SystemC mode and one with
// the trapezoid; tests/long/gcode_profile_long_test.cpp runs every program in
// both modes (ctest -L long).
#include "gcode_profile_check.h"

#include <fstream>

namespace hwinterp::testing {
namespace {

class GcodeProfile : public ::testing::TestWithParam<ProfileCase> {};

TEST_P(GcodeProfile, KeepsTheLimitsAndTheLatticePoints) { check_profiled_program(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Committed, GcodeProfile,
                         ::testing::Values(ProfileCase{"corners", "direct", "scurve"},
                                           ProfileCase{"helix", "direct", "scurve"},
                                           ProfileCase{"incremental", "direct", "scurve"},
                                           ProfileCase{"modal", "direct", "scurve"},
                                           ProfileCase{"words", "direct", "scurve"},
                                           ProfileCase{"corners", "systemc", "scurve"},
                                           ProfileCase{"corners", "direct", "trapezoid"}),
                         profile_case_name);

// The check is not idle: without the profile the same program breaks the
// limits the profiled run keeps.
TEST(GcodeProfileOff, TheSameProgramBreaksTheLimits) {
  const std::string data = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";
  const std::string dir = scratch_dir("gcode_profile_off");
  const CliResult off = run_hwinterp(
      "gcode " + data + "corners.ngc --feed programmed --mode direct --progress 0 " + "--machine " +
      data + "machine_profile.json --profile off --json " + dir + "/off.json");
  ASSERT_EQ(off.code, 0) << off.out << off.err;
  const auto j = nlohmann::json::parse(slurp(dir + "/off.json"));
  EXPECT_EQ(j["profile"]["kind"], "off");
  const auto& x = j["kinematics"]["axes"]["X"];
  EXPECT_GT(x["accel"]["max"].get<double>(), x["accel"]["limit"].get<double>());
  EXPECT_GT(x["jerk"]["max"].get<double>(), x["jerk"]["limit"].get<double>());
}

// Feed hold: a controlled stop along the path within every limit, at rest
// for the hold, then the planned profile resumes; the run visits the same
// lattice points as without the profile (the check above), and it takes the
// hold's time longer than the run without a hold.
TEST(GcodeProfileHold, StopsWithinTheLimitsAndResumes) {
  nlohmann::json held, plain;
  check_profiled_program({"corners", "direct", "scurve", "--feed-hold 2:0.5"}, &held);
  check_profiled_program({"corners", "direct", "scurve", ""}, &plain);
  ASSERT_TRUE(held["profile"].contains("hold")) << held["profile"];
  const auto& h = held["profile"]["hold"];
  EXPECT_TRUE(h["stopped"].get<bool>());
  EXPECT_GT(h["speed_ops_per_s"].get<double>(), 0);
  EXPECT_GT(h["stop_ops"].get<double>(), 0);
  EXPECT_GT(h["stop_s"].get<double>(), 0);
  // Simulated seconds (clocks / clock_hz), not wall time: at rest within the hold.
  EXPECT_LT(h["stop_s"].get<double>(), h["for_s"].get<double>());
  EXPECT_GT(held["profile"]["time_s"].get<double>(),
            plain["profile"]["time_s"].get<double>() + 0.4);
}

// M0 and M1 are exact stops: a line split by an M0 takes longer than the same
// line split without one, which the profile crosses at speed.
TEST(GcodeProfileStops, AnM0IsAnExactStop) {
  const std::string dir = scratch_dir("gcode_profile_m0");
  const std::string machine =
      std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/machine_profile.json";
  const auto run = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + "/" + name + ".ngc") << text;
    const CliResult r =
        run_hwinterp("gcode " + dir + "/" + name + ".ngc --mode direct --feed programmed " +
                     "--progress 0 --machine " + machine + " --json " + dir + "/" + name + ".json");
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    return nlohmann::json::parse(slurp(dir + "/" + name + ".json"));
  };
  const auto stop = run("m0", "G21 G90\nG1 X10 F3000\nM0\nG1 X20\nM2\n");
  const auto on = run("through", "G21 G90\nG1 X10 F3000\nG1 X20\nM2\n");
  EXPECT_TRUE(stop["passed"].get<bool>());
  EXPECT_TRUE(on["passed"].get<bool>());
  EXPECT_GT(stop["profile"]["time_s"].get<double>(), on["profile"]["time_s"].get<double>() + 0.1);
}

// Bad --feed-hold values exit 2 naming them, and a hold needs a profile.
TEST(GcodeProfileHold, BadValuesExitTwo) {
  const std::string data = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";
  const std::string base =
      "gcode " + data + "words.ngc --mode direct --machine " + data + "machine_profile.json ";
  CliResult r = run_hwinterp(base + "--feed-hold 2");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'2' is not AT:FOR"), std::string::npos) << r.err;
  r = run_hwinterp(base + "--feed-hold 1:-3");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'1:-3'"), std::string::npos) << r.err;
  r = run_hwinterp(base + "--feed-hold x:1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'x'"), std::string::npos) << r.err;
  r = run_hwinterp(base + "--feed-hold 1:1 --profile off");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("the profile is off"), std::string::npos) << r.err;
}

// Feed override: 150 %, then 50 %, then 200 % of the programmed feed (each
// capped by the machine's limits): the run passes (the profile's faces agree
// on every clock), every axis keeps its limits, the step stream visits the
// same lattice points as without the profile, and the report records the
// schedule.
TEST(GcodeProfileOverride, ScalesTheFeedWithinTheLimitsAndKeepsTheLatticePoints) {
  nlohmann::json j;
  check_profiled_program({"corners", "direct", "scurve", "--feed-override 0.5:150,1.5:50,2.5:200"},
                         &j);
  ASSERT_TRUE(j["profile"].contains("feed_override")) << j["profile"];
  const auto& steps = j["profile"]["feed_override"];
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[0]["at_s"].get<double>(), 0.5);
  EXPECT_EQ(steps[0]["word"].get<unsigned>(), 192u);
  EXPECT_EQ(steps[1]["word"].get<unsigned>(), 64u);
  EXPECT_EQ(steps[2]["percent"].get<double>(), 200);
}

// The override scales the programmed feed and the machine caps the result:
// a 40 mm line along X at F1500 (25 mm/s) runs at 50 mm/s at 200 %; at F4800
// (80 mm/s) it runs at 40 mm/s at 50 %, and at 200 % no faster than at 100 %:
// the step/dir stage caps such a line at 61.1 mm/s (DDA operations are a
// power of two, 0.61 steps of X an operation; 2 + 2 clock pulses at 500 kHz).
TEST(GcodeProfileOverride, ScalesTheProgrammedFeedUpToTheMachinesCap) {
  const std::string dir = scratch_dir("gcode_profile_override");
  const std::string machine =
      std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/machine_profile.json";
  const auto x_speed = [&](const std::string& feed, const std::string& pct) {
    const std::string name = dir + "/f" + feed + "_" + pct;
    std::ofstream(name + ".ngc") << "G21 G90\nG1 X40 F" + feed + "\nM2\n";
    const CliResult r = run_hwinterp("gcode " + name + ".ngc --mode direct --feed programmed " +
                                     "--progress 0 --machine " + machine +
                                     " --feed-override 0:" + pct + " --json " + name + ".json");
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    const auto k = nlohmann::json::parse(slurp(name + ".json"));
    EXPECT_TRUE(k["passed"].get<bool>()) << r.out;
    return k["kinematics"]["axes"]["X"]["speed"]["max"].get<double>();
  };
  EXPECT_NEAR(x_speed("1500", "100"), 25, 0.5);
  EXPECT_NEAR(x_speed("1500", "200"), 50, 0.5);
  EXPECT_NEAR(x_speed("4800", "50"), 40, 0.5);
  const double full = x_speed("4800", "100");
  EXPECT_NEAR(full, 61.1, 0.5);
  EXPECT_EQ(x_speed("4800", "200"), full);
}

// Bad --feed-override values exit 2 naming them, and the override needs a profile.
TEST(GcodeProfileOverride, BadValuesExitTwo) {
  const std::string data = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";
  const std::string base =
      "gcode " + data + "words.ngc --mode direct --machine " + data + "machine_profile.json ";
  CliResult r = run_hwinterp(base + "--feed-override 150");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'150' is not AT:PCT"), std::string::npos) << r.err;
  r = run_hwinterp(base + "--feed-override 1:250");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'1:250' is outside 0..200"), std::string::npos) << r.err;
  r = run_hwinterp(base + "--feed-override 1:50,x:100");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'x'"), std::string::npos) << r.err;
  r = run_hwinterp(base + "--feed-override 2:50,1:100");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'1:100' comes before"), std::string::npos) << r.err;
  r = run_hwinterp(base + "--feed-override 1:100,2:0");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'2:0' stops the feed for good"), std::string::npos) << r.err;
  r = run_hwinterp(base + "--feed-override 1:50 --profile off");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("the profile is off"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hwinterp::testing

// `hwinterp profile` through the real executable: bad input exits 2 with one
// line naming the value; a stream's JSON ends every move, keeps the limits
// and writes the per-tick speed.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "run_hwinterp.h"
#include "tb/base/json.h"

namespace {

using hwinterp::testing::CliResult;
using hwinterp::testing::run_hwinterp;
using hwinterp::testing::slurp;

const std::string kLimits = "--max-velocity 20000 --max-accel 5e5 --max-jerk 3e7 ";

CliResult run(const std::string& args) { return run_hwinterp("profile " + args); }

TEST(ProfileCli, BadValuesExitTwoNamingThem) {
  struct Case {
    std::string args, names;
  };
  const std::string dir = hwinterp::testing::scratch_dir("profile_cli");
  { std::ofstream(dir + "/bad.csv") << "ops,target_speed,end_speed\n100,,\n0.5,,\n"; }
  for (const Case& c :
       {Case{kLimits + "--ops 0", "--ops: 0"},
        Case{"--max-velocity 20000 --max-accel -5 --max-jerk 3e7 --ops 10", "--max-accel: -5"},
        Case{kLimits + "--ops 10 --end-speed 30000", "--end-speed"},
        Case{kLimits + "--ops 10 --moves x.csv", "one of --ops"},
        Case{kLimits + "--moves " + dir + "/bad.csv", "bad.csv:3"},
        Case{"--max-velocity 20000 --max-accel 5e5 --max-jerk 1e-9 --ops 10", "jerk 1e-09"},
        Case{kLimits + "--ops 10 --feed-override 1:250", "'1:250' is outside 0..200"},
        Case{kLimits + "--ops 10 --feed-override 0:50,1:0", "'1:0' stops the feed"}}) {
    const CliResult r = run(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << "\n" << r.err;
  }
}

TEST(ProfileCli, AStreamEndsEveryMoveWithinTheLimits) {
  const std::string dir = hwinterp::testing::scratch_dir("profile_cli");
  const std::string moves = dir + "/moves.csv", json = dir + "/p.json", csv = dir + "/t.csv";
  { std::ofstream(moves) << "ops,target_speed,end_speed\n3000,15000,5000\n2000,,2000\n500,,0\n"; }
  const CliResult r = run(kLimits + "--moves " + moves + " --json " + json + " --csv " + csv);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = hwinterp::Json::parse(slurp(json));
  ASSERT_EQ(j["move_end_clocks"].size(), 3u);
  EXPECT_EQ(j["ops"].get<uint64_t>(), 5500u);
  // Each move ends after the one before, at no more than its end speed (the
  // last, to rest: within one level of 0).
  EXPECT_LT(j["move_end_clocks"][0].get<uint64_t>(), j["move_end_clocks"][1].get<uint64_t>());
  EXPECT_LT(j["move_end_clocks"][1].get<uint64_t>(), j["move_end_clocks"][2].get<uint64_t>());
  EXPECT_LE(j["move_end_speeds"][0].get<double>(), 5000.0);
  EXPECT_LE(j["move_end_speeds"][1].get<double>(), 2000.0);
  EXPECT_LE(j["move_end_speeds"][2].get<double>(), j["registers"]["level_speed"].get<double>());
  EXPECT_LE(j["peak"]["speed"].get<double>(), 20000.0 * (1 + 1e-9));
  EXPECT_LE(j["peak"]["accel"].get<double>(), 5e5 * (1 + 1e-9));
  EXPECT_LE(j["peak"]["jerk"].get<double>(), 3e7 * (1 + 1e-9));
  EXPECT_GT(slurp(csv).size(), 100u);
}

// The feed override: at 50 % from the start the move's peak speed is half the
// limit's level (ceil), it takes longer, the limits hold, and the JSON lists
// the schedule; 200 % stays at the velocity limit.
TEST(ProfileCli, TheFeedOverrideScalesTheSpeedWithinTheLimits) {
  const std::string dir = hwinterp::testing::scratch_dir("profile_cli");
  const auto at = [&](const std::string& ovr) {
    const std::string json = dir + "/o" + std::to_string(ovr.size()) + ".json";
    const CliResult r = run(kLimits + "--ops 20000 " + ovr + " --json " + json);
    EXPECT_EQ(r.code, 0) << r.err;
    return hwinterp::Json::parse(slurp(json));
  };
  const auto full = at(""), half = at("--feed-override 0:50"), twice = at("--feed-override 0:200");
  const double level = full["registers"]["level_speed"].get<double>();
  const double top = full["registers"]["max_level"].get<double>();
  EXPECT_NEAR(half["peak"]["speed"].get<double>(), std::ceil(top / 2) * level, level);
  EXPECT_GT(half["seconds_at_rest"].get<double>(), 1.5 * full["seconds_at_rest"].get<double>());
  EXPECT_EQ(twice["peak"]["speed"].get<double>(), full["peak"]["speed"].get<double>());
  EXPECT_EQ(half["ops"].get<uint64_t>(), 20000u);
  for (const auto* j : {&half, &twice}) {
    EXPECT_LE((*j)["peak"]["accel"].get<double>(), 5e5 * (1 + 1e-9));
    EXPECT_LE((*j)["peak"]["jerk"].get<double>(), 3e7 * (1 + 1e-9));
  }
  ASSERT_EQ(half["feed_override"].size(), 1u);
  EXPECT_EQ(half["feed_override"][0]["word"].get<unsigned>(), 64u);
  EXPECT_EQ(full["feed_override"].size(), 0u);
}

}  // namespace

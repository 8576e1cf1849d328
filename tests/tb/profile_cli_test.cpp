// `hwinterp profile` through the real executable: bad input exits 2 with one
// line naming the value; a stream's JSON ends every move, keeps the limits
// and writes the per-tick speed.
#include <gtest/gtest.h>

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
        Case{"--max-velocity 20000 --max-accel 5e5 --max-jerk 1e-9 --ops 10", "jerk 1e-09"}}) {
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

}  // namespace

// One committed part program with the jerk-limited feed profile
// (machine_profile.json: profile scurve, 500 kHz) at its programmed feeds:
// the run passes (the profile's two faces agree on every clock, HLS = RTL for
// motion_top, every limit kept by the run's own estimator), the report's
// kinematics are within the limits on every axis and the path, the step
// stream visits the very lattice points of the run without a profile in the
// same order, and it takes no less time than that run (the profile never goes
// faster than the programmed feed). Shared by tb_tests (the CI set) and
// long_tests (every program, both lockstep modes).
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

#include "run_hwinterp.h"

namespace hwinterp::testing {

struct ProfileCase {
  std::string program;  // tests/data/gcode/<program>.ngc
  std::string mode;     // systemc | direct
  std::string profile;  // scurve | trapezoid
  std::string extra;    // more options for the profiled run (e.g. --feed-hold AT:FOR)
};

// Names the case in test listings (ctest prints GetParam()).
inline void PrintTo(const ProfileCase& c, std::ostream* os) {
  *os << c.program << " " << c.mode << " " << c.profile << (c.extra.empty() ? "" : " ") << c.extra;
}

inline std::string profile_case_name(const ::testing::TestParamInfo<ProfileCase>& info) {
  return info.param.program + "_" + info.param.mode + "_" + info.param.profile;
}

// The step stream's clocks, grouped: one group per clock with the pulses
// (axis, dir) that rose on it, in order. Two runs visit the same lattice
// points in the same order exactly when their groups are equal.
inline std::vector<std::string> step_groups(const std::string& csv) {
  const auto rows = read_csv(csv);
  std::vector<std::string> groups;
  std::string clock;
  for (size_t i = 1; i < rows.size(); ++i) {
    if (rows[i][0] != clock || groups.empty()) groups.emplace_back();
    clock = rows[i][0];
    groups.back() += rows[i][1] + rows[i][2] + " ";
  }
  return groups;
}

// A program run with the profile and without: `base` (the command with the
// program and its machine) plus `on_args` (the profiled run's options), then
// `base` in direct mode with the profile off, each writing its step stream
// and JSON report into `dir` (on.csv, on.json, off.csv, off.json). Both must
// exit 0 (call with ASSERT_NO_FATAL_FAILURE).
struct OnOffRuns {
  CliResult on, off;
  nlohmann::json j_on, j_off;
};
inline void run_on_off(const std::string& base, const std::string& on_args, const std::string& dir,
                       OnOffRuns& r) {
  r.on =
      run_hwinterp(base + on_args + " --step-times " + dir + "/on.csv --json " + dir + "/on.json");
  ASSERT_EQ(r.on.code, 0) << r.on.out << r.on.err;
  r.off = run_hwinterp(base + "--mode direct --profile off --step-times " + dir +
                       "/off.csv --json " + dir + "/off.json");
  ASSERT_EQ(r.off.code, 0) << r.off.out << r.off.err;
  r.j_on = nlohmann::json::parse(slurp(dir + "/on.json"));
  r.j_off = nlohmann::json::parse(slurp(dir + "/off.json"));
}

// `report`, when given, gets the profiled run's JSON report.
inline void check_profiled_program(const ProfileCase& c, nlohmann::json* report = nullptr) {
  const std::string data = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";
  const std::string dir =
      scratch_dir("gcode_profile_" + c.program + "_" + c.mode + "_" + c.profile);
  const std::string base = "gcode " + data + c.program + ".ngc --feed programmed --progress 0 " +
                           "--machine " + data + "machine_profile.json ";
  OnOffRuns r;
  ASSERT_NO_FATAL_FAILURE(
      run_on_off(base, "--mode " + c.mode + " --profile " + c.profile + " " + c.extra, dir, r));
  const CliResult& on = r.on;
  const nlohmann::json &j_on = r.j_on, &j_off = r.j_off;
  if (report) *report = j_on;
  EXPECT_TRUE(j_on["passed"].get<bool>()) << on.out;
  EXPECT_EQ(j_on["profile"]["kind"], c.profile);
  EXPECT_EQ(j_on["profile"]["moves"].get<uint64_t>(), j_on["commands"].get<uint64_t>());
  EXPECT_TRUE(j_on["profile"]["failures"].empty()) << j_on["profile"]["failures"];
  EXPECT_EQ(j_on["end_mismatches"].get<int>(), 0);
  // Within the limits on every axis and the path; a trapezoid has no jerk limit.
  for (const auto& [name, row] : j_on["kinematics"]["axes"].items())
    for (const char* q : {"speed", "accel", "jerk"}) {
      if (c.profile == "trapezoid" && std::string(q) == "jerk") continue;
      if (row[q]["limit"].is_null()) continue;
      EXPECT_LE(row[q]["max"].get<double>(),
                row[q]["limit"].get<double>() + row[q]["tolerance"].get<double>())
          << name << " " << q;
    }
  const auto g_on = step_groups(dir + "/on.csv"), g_off = step_groups(dir + "/off.csv");
  ASSERT_FALSE(g_on.empty());
  EXPECT_EQ(g_on.size(), g_off.size());
  EXPECT_TRUE(g_on == g_off) << "the step streams visit different lattice points";
  // (A feed override above 100 % may go faster than the programmed feed.)
  if (c.extra.find("--feed-override") == std::string::npos)
    EXPECT_GE(j_on["simulated_clocks"].get<double>(), j_off["simulated_clocks"].get<double>());
}

}  // namespace hwinterp::testing

// `hwinterp gcode --bus ... --profile scurve`: a part program through
// motion_soc built with the feed profile (rtl/motion_soc.sv, PROFILE = 1), the
// planned moves written with each command, the HLS face beside the Verilated
// top on every clock. The bus run must visit the lattice points of the
// lockstep run with the profile (the same step events in the same order,
// every command ending after the same one), keep the machine's limits, and
// visit the points of the run without the profile. Shared by tb_tests (CI:
// tests/tb/soc_profile_test.cpp) and long_tests
// (tests/long/soc_profile_long_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <ostream>
#include <string>

#include "gcode_profile_check.h"
#include "run_hwinterp.h"

namespace hwinterp::testing {

struct SocProfileCase {
  std::string name;     // the test's name
  std::string program;  // the program's path, or
  std::string text;     // the program itself (then written to the test's scratch directory)
  std::string bus;      // axi4lite | wishbone
  std::string mode;     // the lockstep run's: systemc | direct
};

inline void PrintTo(const SocProfileCase& c, std::ostream* os) {
  *os << c.name << " " << c.bus << " " << c.mode;
}

inline std::string soc_profile_case_name(const ::testing::TestParamInfo<SocProfileCase>& info) {
  return info.param.name + "_" + info.param.bus + "_" + info.param.mode;
}

// tests/data/gcode/<name>.ngc
inline SocProfileCase committed_soc_case(const std::string& name, const std::string& bus,
                                         const std::string& mode) {
  return {name, std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/" + name + ".ngc", "", bus,
          mode};
}

inline void check_soc_profiled_program(const SocProfileCase& c) {
  const std::string machine =
      std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/machine_profile.json";
  const std::string dir = scratch_dir("soc_profile_" + c.name + "_" + c.bus + "_" + c.mode);
  std::string program = c.program;
  if (!c.text.empty()) {
    program = dir + "/" + c.name + ".ngc";
    std::ofstream(program) << c.text;
  }
  const std::string base =
      "gcode " + program + " --feed programmed --progress 0 --machine " + machine + " ";
  OnOffRuns r;
  ASSERT_NO_FATAL_FAILURE(
      run_on_off(base, "--mode " + c.mode + " --profile scurve --bus " + c.bus, dir, r));
  const CliResult& on = r.on;
  const nlohmann::json& j = r.j_on;
  EXPECT_TRUE(j["passed"].get<bool>()) << on.out;
  EXPECT_TRUE(j["profile"]["failures"].empty()) << j["profile"]["failures"];
  const auto& b = j["bus"];
  EXPECT_TRUE(b["passed"].get<bool>()) << on.out;
  EXPECT_TRUE(b["profile"].get<bool>());
  EXPECT_TRUE(b["limit_failures"].empty()) << b["limit_failures"];
  EXPECT_EQ(b["hls_mismatch_clock"].get<uint64_t>(), 0u) << on.out;
  EXPECT_EQ(b["first_point_mismatch"].get<int64_t>(), -1);
  EXPECT_EQ(b["first_end_mismatch"].get<int64_t>(), -1);
  EXPECT_GT(b["points"].get<uint64_t>(), 0u);
  EXPECT_EQ(b["points"], b["lockstep_points"]);
  EXPECT_EQ(b["completed"], b["lockstep_completed"]);
  EXPECT_EQ(b["completed"], j["commands"]);
  EXPECT_EQ(b["end"], b["lockstep_end"]);
  EXPECT_EQ(b["end_mismatches"].get<int>(), 0);
  // The run without the profile: the same step events (clocks with rising
  // steps), the same lattice points in the same order, so the same end point.
  const auto g_on = step_groups(dir + "/on.csv"), g_off = step_groups(dir + "/off.csv");
  ASSERT_FALSE(g_on.empty());
  EXPECT_EQ(b["points"].get<uint64_t>(), g_off.size());
  EXPECT_TRUE(g_on == g_off) << "the step streams visit different lattice points";
}

}  // namespace hwinterp::testing

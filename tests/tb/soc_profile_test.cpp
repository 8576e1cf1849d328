// `hwinterp gcode --bus ... --profile scurve` in CI (tests/tb/soc_profile_check.h):
// corners.ngc through AXI4-Lite after the direct lockstep run, and a short
// program of arcs in the three planes through Wishbone after the SystemC
// lockstep run (about 35 s and 15 s). tests/long/soc_profile_long_test.cpp
// runs the longer committed programs (ctest -L long -R SocProfileLong).
#include "soc_profile_check.h"

namespace hwinterp::testing {
namespace {

class SocProfile : public ::testing::TestWithParam<SocProfileCase> {};

TEST_P(SocProfile, MeetsTheLockstepRunWithinTheLimits) { check_soc_profiled_program(GetParam()); }

// Arcs in XY both ways (at two feeds) and in ZX, joined by lines: 7 commands.
const SocProfileCase kShortArcs{"short_arcs", "",
                                "G21 G90 G17\nG1 X4 F3000\nG2 X8 Y0 I2 J0\nG3 X12 Y0 I2 J0\n"
                                "G2 X12 Y4 I0 J2 F1500\nG1 X6 Y6\nG18 G2 X4 Z2 I-2 K0\n"
                                "G17 G1 X0 Y0 Z0\nM2\n",
                                "wishbone", "systemc"};

INSTANTIATE_TEST_SUITE_P(Committed, SocProfile,
                         ::testing::Values(committed_soc_case("corners", "axi4lite", "direct"),
                                           kShortArcs),
                         soc_profile_case_name);

// --bus with the profile takes its planned moves only: --feed-hold and
// --feed-override with it exit 2 naming the clash.
TEST(SocProfileCli, HoldAndOverrideNeedTheLockstepRunAlone) {
  const std::string data = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";
  const std::string base = "gcode " + data + "words.ngc --mode direct --bus axi4lite --machine " +
                           data + "machine_profile.json ";
  CliResult r = run_hwinterp(base + "--feed-hold 1:1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("without --bus"), std::string::npos) << r.err;
  r = run_hwinterp(base + "--feed-override 1:50");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("without --bus"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hwinterp::testing

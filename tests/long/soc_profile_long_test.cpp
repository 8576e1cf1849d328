// `hwinterp gcode --bus ... --profile scurve` on the longer committed programs
// (tests/tb/soc_profile_check.h), both buses, both lockstep modes: ctest -L long
// -R SocProfileLong (about 1-8 min each). CI runs the short ones
// (tests/tb/soc_profile_test.cpp).
#include "../tb/soc_profile_check.h"

namespace hwinterp::testing {
namespace {

class SocProfileLong : public ::testing::TestWithParam<SocProfileCase> {};

TEST_P(SocProfileLong, MeetsTheLockstepRunWithinTheLimits) {
  check_soc_profiled_program(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Committed, SocProfileLong,
                         ::testing::Values(committed_soc_case("corners", "wishbone", "systemc"),
                                           committed_soc_case("helix", "axi4lite", "direct"),
                                           committed_soc_case("incremental", "wishbone", "direct"),
                                           committed_soc_case("arcs", "axi4lite", "systemc")),
                         soc_profile_case_name);

}  // namespace
}  // namespace hwinterp::testing

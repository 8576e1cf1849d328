// Every committed part program at its programmed feeds with the jerk-limited
// feed profile, in both lockstep modes (tests/tb/gcode_profile_check.h):
// ctest -L long -R GcodeProfileAll. CI runs the short ones
// (tests/tb/gcode_profile_test.cpp).
#include "../tb/gcode_profile_check.h"

namespace hwinterp::testing {
namespace {

class GcodeProfileAll : public ::testing::TestWithParam<ProfileCase> {};

TEST_P(GcodeProfileAll, KeepsTheLimitsAndTheLatticePoints) { check_profiled_program(GetParam()); }

std::vector<ProfileCase> every_program() {
  std::vector<ProfileCase> out;
  for (const char* mode : {"direct", "systemc"})
    for (const char* p :
         {"arcs", "corners", "engraving", "helix", "incremental", "inch", "modal", "words"})
      out.push_back({p, mode, "scurve"});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Committed, GcodeProfileAll, ::testing::ValuesIn(every_program()),
                         profile_case_name);

}  // namespace
}  // namespace hwinterp::testing

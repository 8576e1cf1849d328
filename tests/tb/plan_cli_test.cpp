// `hwinterp plan` as a user runs it: the built executable, its exit codes,
// its one-line complaints about bad input, and its JSON report.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "run_hwinterp.h"
#include "tb/base/json.h"

namespace {

using hwinterp::testing::CliResult;
using hwinterp::testing::run_hwinterp;
using hwinterp::testing::scratch_dir;
using hwinterp::testing::slurp;

CliResult plan(const std::string& args) { return run_hwinterp("plan " + args); }

TEST(PlanCli, TranslatingCam1MatchesThePaper) {
  const std::string json = scratch_dir("plan_json") + "/plan.json";
  const CliResult r = plan("--law ms --tol 0.0005 --stroke 100 --lift 40 --json " + json);
  EXPECT_EQ(r.code, 0) << r.err;
  const hwinterp::Json j = hwinterp::Json::parse(slurp(json));
  EXPECT_EQ(j["segments"], 124);
  // Achieved error e <= E, and the independent verifier agrees within 1e-9.
  EXPECT_LE(j["error"].get<double>(), 0.0005);
  EXPECT_NEAR(j["error"].get<double>(), 0.0004888, 1e-6);
  EXPECT_NEAR(j["verified_max_error"].get<double>(), j["error"].get<double>(), 1e-9);
  ASSERT_EQ(j["intervals"].size(), 2u);  // Cam 1: concave half, convex half
  EXPECT_EQ(j["intervals"][0]["segments"].get<int>() + j["intervals"][1]["segments"].get<int>(),
            124);
  EXPECT_GT(j["seconds"].get<double>(), 0);
}

TEST(PlanCli, RotatingCam2WritesSegmentsAndErrors) {
  const std::string dir = scratch_dir("plan_csv");
  const CliResult r =
      plan("--law ms --tol 0.0005 --rotating --r0 40 --lift 30 --theta-d 100 --csv " + dir +
           "/segments.csv --error-csv " + dir + "/errors.csv");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("149"), std::string::npos) << r.out;
  const std::string c = slurp(dir + "/segments.csv");
  EXPECT_EQ(std::count(c.begin(), c.end(), '\n'), 150);  // header + 149 segments
  EXPECT_EQ(slurp(dir + "/errors.csv").rfind("segment,theta_deg,position_mm,", 0), 0u);
}

// Nishioka's chords exceed the tolerance in the normal sense: exit 1.
TEST(PlanCli, NishiokaFailsTheNormalErrorCheck) {
  const CliResult r = plan("--law ms --tol 0.0005 --stroke 100 --lift 40 --method nishioka");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("180"), std::string::npos) << r.out;
}

// Bad input: exit 2 and exactly one line naming the offending value.
TEST(PlanCli, BadInputNamesTheValue) {
  const std::pair<const char*, const char*> cases[] = {
      {"--law ms --tol -0.1 --stroke 100 --lift 40", "-0.1"},
      {"--law ms --tol 0 --stroke 100 --lift 40", "--tol"},
      {"--law ms --tol abc --stroke 100 --lift 40", "abc"},
      {"--law ms --tol 1e-12 --stroke 100 --lift 40", "1e-12"},
      {"--law ms --tol 10 --stroke 100 --lift 40", "too coarse"},
      {"--law ms --tol 0.001 --stroke 0 --lift 40", "--stroke"},
      {"--law ms --tol 0.001 --stroke 100 --lift 0", "--lift"},
      {"--law ms --tol 0.001 --stroke 100", "--lift"},
      {"--law ms --tol 0.001 --rotating --r0 40 --lift 30 --theta-d 0", "--theta-d"},
      {"--law ms --tol 0.001 --rotating --r0 40 --lift 30 --theta-d 400", "400"},
      {"--law ms --tol 0.001 --rotating --r0 -1 --lift 30 --theta-d 90", "--r0"},
      {"--law ms --tol 0.001 --rotating --r0 40 --lift 30 --theta-d 90 --stroke 9", "--stroke"},
      {"--law ms --tol 0.001 --r0 40 --lift 30 --stroke 100", "--r0"},
      {"--law parabolic --tol 0.001 --stroke 100 --lift 40", "parabolic"},
      {"--tol 0.001 --stroke 100 --lift 40", "--law"},
      {"--law ms --tol 0.001 --stroke 100 --lift 40 --method best", "best"},
      {"--law harmonic --tol 0.0005 --rotating --r0 1 --lift 50 --theta-d 30", "too coarse"},
      {"--law ms --tol 0.001 --stroke 100 --lift 40 --csv /nonexistent/x.csv", "--csv"},
  };
  for (const auto& [args, named] : cases) {
    const CliResult r = plan(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  }
}

}  // namespace

// The step output monitors (tb/monitor/step_output_monitor.h) on hand-made
// waveforms of each type: decoded into the steps they stand for, one clock
// after the step stage's rise, and each type's rule one clock short fails
// with the right numbers.
#include "tb/monitor/step_output_monitor.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace hwinterp::tb {
namespace {

struct Played {
  std::vector<TimingViolation> kept;
  uint64_t count = 0;
  std::string steps;  // per clock: '.' none, '+' a positive step, '-' a negative
};

// One axis of `type`: out_a and out_b as strings ('1'/'0'), a char a clock
// from clock 1 (after a reset at clock 0).
Played play(StepType type, const std::string& a, const std::string& b, StepdirTiming t) {
  StepOutputMonitors m({type});
  m.reset(0);
  Played p;
  for (size_t c = 0; c < a.size(); ++c) {
    uint32_t dir = 0;
    const uint32_t s = m.observe(c + 1, a[c] == '1', b[c] == '1', t, dir, p.kept, p.count);
    p.steps += s ? ((dir & 1) ? '-' : '+') : '.';
  }
  return p;
}

const StepdirTiming kT{2, 2, 2, 1};  // len, space, setup, hold

TEST(StepOutputMonitor, StepDirStepsOneClockAfterTheRise) {
  // dir turns 1 clock (hold) after the fall, the rise 2 (setup) after it.
  const Played p = play(StepType::kStepDir, "011000110000", "000011111111", kT);
  EXPECT_EQ(p.count, 0u);
  EXPECT_EQ(p.steps, "..+....-....");
}

TEST(StepOutputMonitor, UpDownDecodesEachLineAsADirection) {
  // up 2 clocks, 2 low, up; then down after hold + setup = 3 low clocks.
  const Played p = play(StepType::kUpDown, "0110011000000", "0000000000110", kT);
  EXPECT_EQ(p.count, 0u) << p.kept.front().rule;
  EXPECT_EQ(p.steps, "..+...+....-.");
}

TEST(StepOutputMonitor, QuadratureDecodesGrayStepsBothWays) {
  // 00 10 11 01 00 (forward, 4 clocks each), then back 01 00.
  const std::string a = "0000111111110000000000000000";
  const std::string b = "0000000011111111000011110000";
  const Played p = play(StepType::kQuadrature, a, b, StepdirTiming{2, 2, 1, 1});
  EXPECT_EQ(p.count, 0u) << p.kept.front().rule;
  EXPECT_EQ(p.steps, "....+...+...+...+...-...+...");
}

TEST(StepOutputMonitor, EachTypesRuleOneClockShortFails) {
  struct Case {
    StepType type;
    const char *a, *b, *rule;
    uint64_t measured, required;
  };
  const Case cases[] = {
      {StepType::kStepDir, "0100", "0000", "step_len", 1, 2},
      {StepType::kUpDown, "0100", "0000", "step_len", 1, 2},
      {StepType::kUpDown, "0110100", "0000000", "step_space", 1, 2},
      {StepType::kUpDown, "0110000", "0110000", "updown_both", 1, 0},
      {StepType::kUpDown, "011000000", "000001100", "updown_turn", 2, 3},
      {StepType::kQuadrature, "0010000", "0010000", "quad_state", 2, 1},
      {StepType::kQuadrature, "0011111", "0000111", "quad_dwell", 2, 4},
  };
  for (const Case& c : cases) {
    const Played p = play(c.type, c.a, c.b, kT);
    ASSERT_GE(p.count, 1u) << c.rule;
    EXPECT_EQ(p.kept.front().rule, c.rule);
    EXPECT_EQ(p.kept.front().measured, c.measured) << c.rule;
    EXPECT_EQ(p.kept.front().required, c.required) << c.rule;
  }
}

TEST(StepOutputMonitor, ParsesTheTypeNames) {
  StepType t;
  ASSERT_TRUE(parse_step_type("quad", t));
  EXPECT_EQ(t, StepType::kQuadrature);
  ASSERT_TRUE(parse_step_type("updown", t));
  EXPECT_EQ(t, StepType::kUpDown);
  EXPECT_FALSE(parse_step_type("pwm", t));
  EXPECT_STREQ(step_type_name(StepType::kStepDir), "stepdir");
}

}  // namespace
}  // namespace hwinterp::tb

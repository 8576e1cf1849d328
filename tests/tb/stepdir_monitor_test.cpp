// The step/dir timing monitor on hand-made waveforms: each rule met exactly
// at its limit passes, one cycle short fails with the right numbers.
#include "tb/monitor/stepdir_monitor.h"

#include <gtest/gtest.h>

#include <string>

namespace hwinterp::tb {
namespace {

struct Findings {
  std::vector<TimingViolation> kept;
  uint64_t count = 0;
};

// Plays step/dir waveforms written as strings ('1'/'0'), one char a cycle,
// starting at cycle 1.
Findings play(const std::string& step, const std::string& dir, StepdirTiming t) {
  StepdirMonitor m(0);
  Findings f;
  for (size_t c = 0; c < step.size(); ++c)
    m.observe(c + 1, step[c] == '1', dir[c] == '1', t, f.kept, f.count);
  return f;
}

const StepdirTiming kT{3, 2, 2, 2};  // len, space, setup, hold

TEST(StepdirMonitor, PulsesAtTheLimitsPass) {
  // high 3, low 2, high 3: exactly the limits.
  EXPECT_EQ(play("0111001110", "0000000000", kT).count, 0u);
  // dir changes 2 cycles after a fall (hold) and 2 before a rise (setup).
  // fall at 5, dir at 7, rise at 9.
  EXPECT_EQ(play("01110000111000", "00000011111111", kT).count, 0u);
}

TEST(StepdirMonitor, EachRuleOneCycleShortFails) {
  struct Case {
    const char *step, *dir, *rule;
    uint64_t measured, required;
  } cases[] = {
      {"011000", "000000", "step_len", 2, 3},
      {"01110111", "00000000", "step_space", 1, 2},
      {"0111000011100", "0000000111111", "dir_setup", 1, 2},  // dir at 8, rise at 9
      {"011100000", "000001111", "dir_hold", 1, 2},           // fall at 5, dir at 6
      {"011100000", "001111111", "dir_hold", 0, 2},           // dir changed while high
  };
  for (const auto& c : cases) {
    const Findings f = play(c.step, c.dir, kT);
    ASSERT_EQ(f.count, 1u) << c.rule;
    EXPECT_EQ(f.kept[0].rule, c.rule);
    EXPECT_EQ(f.kept[0].measured, c.measured) << c.rule;
    EXPECT_EQ(f.kept[0].required, c.required) << c.rule;
  }
}

TEST(StepdirMonitor, ZeroSettingsActAsOne) {
  // A one-cycle pulse and a one-cycle gap meet len = space = 0 (= 1).
  EXPECT_EQ(play("0101010", "0000000", StepdirTiming{0, 0, 0, 0}).count, 0u);
  // Dir changing on the rising edge itself breaks setup even at 0.
  EXPECT_EQ(play("00010", "00011", StepdirTiming{0, 0, 0, 0}).kept.at(0).rule, "dir_setup");
}

// A reset counts as the end of a pulse and a change of dir: the first pulse
// after it keeps dir_setup (and step_space) from the reset cycle.
TEST(StepdirMonitor, FirstPulseAfterResetKeepsSetupFromTheReset) {
  const StepdirTiming t{1, 1, 5, 1};
  for (const uint64_t rise : {14u, 15u}) {  // reset at 10: 4 clocks is short, 5 enough
    StepdirMonitor m(0);
    Findings f;
    m.reset(10);
    for (uint64_t c = 11; c <= 16; ++c) m.observe(c, c == rise, false, t, f.kept, f.count);
    if (rise == 14) {
      ASSERT_EQ(f.count, 1u);
      EXPECT_EQ(f.kept[0].rule, "dir_setup");
      EXPECT_EQ(f.kept[0].measured, 4u);
      EXPECT_EQ(f.kept[0].required, 5u);
    } else {
      EXPECT_EQ(f.count, 0u);
    }
  }
}

// The set of every axis's monitors, fed the step/dir words: a violation is
// found on the axis it happens on, and the first clock after a reset gives
// the settings even when no pin changes on it (the set skips only clocks
// with no edge that are not the first after a reset).
TEST(StepdirMonitors, ChecksEveryAxisAndTakesTheSettingsAfterReset) {
  StepdirMonitors ms(3);
  Findings f;
  ms.reset(10);
  // Clock 11: no edge, setup 5 (the reset's setup phase keeps it); later
  // clocks setup 1. Axis 2 rises at 14 (4 clocks after the reset: short),
  // axis 0 at 15 (enough), each for one clock.
  for (uint64_t c = 11; c <= 17; ++c) {
    const StepdirTiming t{1, 1, c == 11 ? 5u : 1u, 1};
    const uint32_t step = (c == 14 ? 4u : 0u) | (c == 15 ? 1u : 0u);
    ms.observe(c, step, 0, t, f.kept, f.count);
  }
  ASSERT_EQ(f.count, 1u);
  EXPECT_EQ(f.kept[0].axis, 2);
  EXPECT_EQ(f.kept[0].rule, "dir_setup");
  EXPECT_EQ(f.kept[0].measured, 4u);
  EXPECT_EQ(f.kept[0].required, 5u);
  EXPECT_EQ(ms.high_len(), 0u);
  ms.observe(18, 2, 0, StepdirTiming{7, 1, 1, 1}, f.kept, f.count);  // axis 1 rises
  EXPECT_EQ(ms.high_len(), 7u);
}

}  // namespace
}  // namespace hwinterp::tb

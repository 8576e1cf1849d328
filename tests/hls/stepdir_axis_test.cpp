// hls::StepdirAxis alone: pulses are exactly step_len long, and with a step
// always waiting the stage is exactly as fast as the timing allows: gaps of
// step_space, a reversal taking dir_hold then dir_setup. Never slower, so the
// engine stalls only as long as it must.
#include "hls/stepdir_axis.h"

#include <gtest/gtest.h>

#include <vector>

namespace hwinterp::hls {
namespace {

struct Trace {
  std::vector<bool> step, dir;
};

// Runs `cycles` clocks; the axis wants direction `want(c)` and fires whenever ready.
template <typename Want>
Trace run(StepdirSettings<16> s, int cycles, Want want) {
  StepdirTiming<16> timing;
  StepdirAxis<16> a;
  timing.reset();
  a.reset();
  Trace t;
  for (int c = 0; c < cycles; ++c) {
    const bool w = want(c);
    const StepdirPrepared<16> p = timing.prepare(s);
    timing.clock();
    a.tick(p, true, w, a.ready(w));
    t.step.push_back(a.step());
    t.dir.push_back(a.dir());
  }
  return t;
}

TEST(StepdirAxis, BackToBackPulsesAreExactlyLenAndSpace) {
  for (unsigned len : {1u, 2u, 5u}) {
    for (unsigned space : {1u, 3u}) {
      const Trace t = run({len, space, 1, 1}, 60, [](int) { return false; });
      // After the first rise the waveform repeats with period len + space.
      size_t first = 0;
      while (!t.step[first]) ++first;
      for (size_t c = first; c < t.step.size(); ++c)
        EXPECT_EQ(t.step[c], (c - first) % (len + space) < len) << len << "/" << space << " @" << c;
    }
  }
}

TEST(StepdirAxis, ReversalTakesHoldThenSetup) {
  const unsigned len = 2, space = 1, setup = 4, hold = 3;
  // Want negative from cycle 10 on.
  const Trace t = run({len, space, setup, hold}, 40, [](int c) { return c >= 10; });
  int last_fall = -1, dir_change = -1, next_rise = -1;
  for (int c = 1; c < 40; ++c) {
    if (t.step[c - 1] && !t.step[c] && c <= 12) last_fall = c;
    if (t.dir[c] && !t.dir[c - 1]) dir_change = c;
    if (dir_change >= 0 && !t.step[c - 1] && t.step[c] && next_rise < 0) next_rise = c;
  }
  ASSERT_GE(last_fall, 0);
  ASSERT_GE(dir_change, 0);
  ASSERT_GE(next_rise, 0);
  EXPECT_GE(dir_change - last_fall, static_cast<int>(hold));
  EXPECT_LE(dir_change - last_fall, static_cast<int>(hold) + len + space);  // may wait for a pulse
  EXPECT_EQ(next_rise - dir_change, static_cast<int>(setup));  // exactly the setup, no more
}

TEST(StepdirAxis, ZeroSettingsActAsOne) {
  const Trace t = run({0, 0, 0, 0}, 10, [](int) { return false; });
  // One clock high, one low: the fastest a step pin can toggle.
  for (size_t c = 1; c < t.step.size(); ++c) EXPECT_NE(t.step[c], t.step[c - 1]) << c;
}

}  // namespace
}  // namespace hwinterp::hls

// rtl/feed_profile.sv against hls/feed_profile.h on every clock: the feed
// word, the level, the speed, busy and ready agree bit for bit over seeded
// random streams (random limits, moves, end levels, gaps between commands,
// feed holds, and configuration pins that change at random: both faces take
// them only at rest). The RTL's RAM starts random (--x-initial unique).
#include <gtest/gtest.h>

#include <random>

#include "Vfeed_profile_cc.h"
#include "hls/feed_profile.h"
#include "models/feed_profile_model.h"
#include "verilated.h"

namespace hwinterp::hls {
namespace {

using Profile = FeedProfile<16, 48, 8, 10, 16, 28>;

// Both faces of the block, out of reset (the RTL's RAM random from `seed`).
struct Faces {
  VerilatedContext context;
  Vfeed_profile_cc rtl;
  Profile hls;
  explicit Faces(uint64_t seed)
      : rtl((context.randReset(2), context.randSeed(static_cast<int>(seed)), &context)) {
    hls.reset();
    // Reset over a rising edge (the asynchronous reset wins at the edge).
    rtl.rst_ni = 0;
    for (int e : {0, 1, 0}) {
      rtl.clk_i = e;
      rtl.eval();
    }
    rtl.rst_ni = 1;
    rtl.eval();
  }
  ~Faces() { rtl.final(); }

  // One clock: both faces' outputs (registers) compared before the edge,
  // then the same pins into both. `taken`: the offered move was taken.
  ::testing::AssertionResult clock(const Profile::Command& cmd, bool valid, bool hold, uint64_t q,
                                   unsigned len, unsigned ovr, bool& taken) {
    rtl.q_i = q;
    rtl.len_i = len;
    rtl.cmd_valid_i = valid;
    rtl.cmd_ops_i = cmd.ops.to_uint();
    rtl.cmd_target_i = cmd.target.to_uint();
    rtl.cmd_end_i = cmd.end.to_uint();
    rtl.cmd_max_i = cmd.max.to_uint();
    rtl.hold_i = hold;
    rtl.ovr_i = ovr;
    if (rtl.feed_o != hls.feed() || rtl.level_o != hls.state().c || rtl.speed_o != hls.state().v ||
        rtl.busy_o != hls.busy() || rtl.cmd_ready_o != hls.cmd_ready())
      return ::testing::AssertionFailure()
             << "RTL feed " << rtl.feed_o << " level " << rtl.level_o << " speed " << rtl.speed_o
             << " busy " << int(rtl.busy_o) << " ready " << int(rtl.cmd_ready_o) << ", HLS feed "
             << hls.feed() << " level " << hls.state().c << " speed " << hls.state().v << " busy "
             << hls.busy() << " ready " << hls.cmd_ready();
    taken = valid && hls.cmd_ready();
    rtl.clk_i = 1;
    rtl.eval();
    hls.clock(valid, cmd, hold, q, len, ovr);
    rtl.clk_i = 0;
    rtl.eval();
    return ::testing::AssertionSuccess();
  }
};

TEST(FeedProfileRtl, MatchesTheHlsFaceOnEveryClock) {
  struct RestoreThreadContext {
    ~RestoreThreadContext() { Verilated::threadContextp(Verilated::defaultContextp()); }
  } restore;
  std::mt19937_64 rng(21);
  uint64_t clocks = 0, moves_done = 0;
  for (int k = 0; k < 12; ++k) {
    Faces f(static_cast<uint64_t>(k) + 1);
    Profile& hls = f.hls;
    models::ProfileBuild b;
    b.tick_w = 8;
    b.clock_hz = 1e6;
    std::uniform_real_distribution<double> vel(5e3, 5e4), acc(1e5, 1e6), jerk(1e7, 1e8);
    const models::ProfileRegisters regs =
        models::profile_registers({vel(rng), acc(rng), jerk(rng)}, b);
    // A second configuration, offered on the pins at random times.
    const models::ProfileRegisters regs2 =
        models::profile_registers({vel(rng), acc(rng), jerk(rng)}, b);
    std::uniform_int_distribution<uint32_t> ops(1, 3000), pct(0, 99);
    Profile::Command cmd;
    bool valid = false, hold = false, second = false;
    int sent = 0;
    const int moves = 6;
    for (uint64_t clk = 0; clk < 20'000'000; ++clk) {
      if (!valid && sent < moves && pct(rng) < 5) {
        cmd.ops = ops(rng);
        cmd.target = std::uniform_int_distribution<uint32_t>(1, regs.max_level)(rng);
        cmd.end = sent == moves - 1
                      ? 0
                      : std::uniform_int_distribution<uint32_t>(0, cmd.target.to_uint())(rng);
        valid = true;
      }
      if (clk % 4096 == 0) hold = pct(rng) < 10;
      if (clk % 1000 == 0 && pct(rng) < 20) second = !second;
      const models::ProfileRegisters& r = second ? regs2 : regs;
      bool take = false;
      ASSERT_TRUE(f.clock(cmd, valid, hold, r.q, r.len, Profile::kOvrOne, take))
          << "case " << k << " clock " << clk;
      if (take) {
        valid = false;
        ++sent;
      }
      ++clocks;
      if (sent == moves && !valid && !hls.busy()) {
        moves_done += moves;
        break;
      }
    }
    EXPECT_EQ(sent, moves) << "case " << k;
  }
  std::printf("%llu clocks, %llu moves compared\n", static_cast<unsigned long long>(clocks),
              static_cast<unsigned long long>(moves_done));
}

// The same with the feed override: ovr_i changes at random clocks (every
// tick for a while, then every few thousand clocks, among them 0 %, 200 % and
// words above 256) and each move has a random cap word (cmd_max_i).
TEST(FeedProfileRtl, MatchesTheHlsFaceOnEveryClockUnderTheOverride) {
  struct RestoreThreadContext {
    ~RestoreThreadContext() { Verilated::threadContextp(Verilated::defaultContextp()); }
  } restore;
  std::mt19937_64 rng(25);
  uint64_t clocks = 0, moves_done = 0, changes = 0;
  for (int k = 0; k < 8; ++k) {
    Faces f(static_cast<uint64_t>(k) + 101);
    Profile& hls = f.hls;
    models::ProfileBuild b;
    b.tick_w = 8;
    b.clock_hz = 1e6;
    std::uniform_real_distribution<double> vel(5e3, 5e4), acc(1e5, 1e6), jerk(1e7, 1e8);
    const models::ProfileRegisters regs =
        models::profile_registers({vel(rng), acc(rng), jerk(rng)}, b);
    std::uniform_int_distribution<uint32_t> ops(1, 3000), pct(0, 99), word(0, 511);
    Profile::Command cmd;
    bool valid = false, hold = false;
    unsigned ovr = Profile::kOvrOne;
    int sent = 0;
    const int moves = 6;
    for (uint64_t clk = 0; clk < 20'000'000; ++clk) {
      if (!valid && sent < moves && pct(rng) < 5) {
        cmd.ops = ops(rng);
        cmd.target = std::uniform_int_distribution<uint32_t>(1, regs.max_level)(rng);
        cmd.max =
            pct(rng) < 50 ? 0 : std::uniform_int_distribution<uint32_t>(0, regs.max_level)(rng);
        cmd.end = sent == moves - 1
                      ? 0
                      : std::uniform_int_distribution<uint32_t>(0, cmd.target.to_uint())(rng);
        valid = true;
      }
      if (clk % 4096 == 0) hold = pct(rng) < 5;
      // Every tick (256 clocks) for the first 200 ticks, then now and then;
      // a zero override is lifted after a while so that the stream finishes.
      const bool every_tick = clk < 51200 && clk % 256 == 0;
      if (every_tick || (clk % 997 == 0 && pct(rng) < 30)) {
        ovr = pct(rng) < 15 ? 0 : (pct(rng) < 15 ? 256 : word(rng));
        ++changes;
      }
      if (clk > 2'000'000 && ovr < 64) ovr = 64;
      bool take = false;
      ASSERT_TRUE(f.clock(cmd, valid, hold, regs.q, regs.len, ovr, take))
          << "case " << k << " clock " << clk;
      if (take) {
        valid = false;
        ++sent;
      }
      ++clocks;
      if (sent == moves && !valid && !hls.busy()) {
        moves_done += moves;
        break;
      }
    }
    EXPECT_EQ(sent, moves) << "case " << k;
    EXPECT_FALSE(hls.busy()) << "case " << k;
  }
  std::printf("%llu clocks, %llu moves, %llu override changes compared\n",
              static_cast<unsigned long long>(clocks), static_cast<unsigned long long>(moves_done),
              static_cast<unsigned long long>(changes));
}

}  // namespace
}  // namespace hwinterp::hls

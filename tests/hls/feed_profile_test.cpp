// hls::FeedProfile on its own: every tick the speed change stays within q*L
// (the acceleration limit) and the change of that within q (the jerk limit),
// exactly, in the block's own integers; the speed never passes the target; a
// rest-to-rest stream travels at least the ops given and stops within a few
// levels of rest at the last one; and a move takes at least the time-optimal
// S-curve's time at the limits the registers give, and not much more when
// it is long. The random moves and limits are seeded.
#include "hls/feed_profile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "models/feed_profile_model.h"

namespace hwinterp::hls {
namespace {

using Profile = FeedProfile<16, 48, 8, 10, 16, 28>;
constexpr int kTick = 256;

struct Trace {
  std::vector<int64_t> v;     // the speed at each tick boundary
  std::vector<uint64_t> ops;  // engine operations done by each tick
  uint64_t clocks = 0;        // clocks until the last op of the stream
  uint64_t total_ops = 0;     // ops the feed words add up to at rest
  uint64_t v_at_last_op = 0;  // the speed when the last op was taken
  uint64_t rest_clocks = 0;   // clocks until the speed is 0 again after the last op
};

// Runs `moves` through the block with an engine that takes an op on every
// carry of a 16-bit phase (feed_accum without stalls) until `need` ops.
// hold_i is high on clocks [hold_from, hold_to).
Trace run(const std::vector<Profile::Command>& moves, uint64_t q, unsigned len, uint64_t need,
          uint64_t hold_from = 0, uint64_t hold_to = 0, uint64_t max_clocks = 200'000'000) {
  Profile p;
  p.reset();
  Trace r;
  size_t sent = 0;
  uint64_t phase = 0, ops = 0;
  for (uint64_t clk = 0; clk < max_clocks; ++clk) {
    const bool valid = sent < moves.size();
    const bool take = valid && p.cmd_ready();
    if (clk % kTick == 0) {
      r.v.push_back(static_cast<int64_t>(p.state().v));
      r.ops.push_back(ops);
    }
    // The engine: a feed word >= 2^16 is full feed.
    const uint64_t f = p.feed();
    phase += std::min<uint64_t>(f, 1u << 16);
    while (phase >= (1u << 16)) {
      phase -= 1u << 16;
      if (ops < need) {
        ++ops;
        if (ops == need) {
          r.clocks = clk + 1;
          r.v_at_last_op = p.state().v;
        }
      }
    }
    if (ops == need && r.rest_clocks == 0 && p.state().v == 0) r.rest_clocks = clk;
    const bool hold = clk >= hold_from && clk < hold_to;
    p.clock(valid, valid ? moves[sent] : Profile::Command{}, hold, q, len);
    if (take) ++sent;
    if (sent == moves.size() && !p.busy() && clk > 2 * kTick) {
      r.total_ops = ops;
      break;
    }
  }
  return r;
}

struct Limits {
  models::ProfileRegisters regs;
  models::PathLimits path;
};

Limits random_limits(std::mt19937_64& rng, double clock_hz) {
  std::uniform_real_distribution<double> vel(5e3, 5e4), acc(1e5, 1e6), jerk(1e7, 1e8);
  Limits l;
  l.path = {vel(rng), acc(rng), jerk(rng)};
  models::ProfileBuild b;
  b.clock_hz = clock_hz;
  l.regs = models::profile_registers(l.path, b);
  return l;
}

// Every tick: |dv| <= q*L, |d2v| <= q, v <= q*L*top.
void expect_within_limits(const Trace& r, uint64_t q, unsigned len, uint32_t top, int k) {
  const int64_t a_max = static_cast<int64_t>(q * len), j_max = static_cast<int64_t>(q);
  const int64_t v_max = a_max * top;
  for (size_t i = 0; i < r.v.size(); ++i) {
    ASSERT_LE(r.v[i], v_max) << "case " << k << " tick " << i;
    if (i >= 1) ASSERT_LE(std::abs(r.v[i] - r.v[i - 1]), a_max) << "case " << k << " tick " << i;
    if (i >= 2)
      ASSERT_LE(std::abs(r.v[i] - 2 * r.v[i - 1] + r.v[i - 2]), j_max)
          << "case " << k << " tick " << i;
  }
}

TEST(FeedProfile, AccelerationAndJerkStayWithinTheRegistersEveryTick) {
  std::mt19937_64 rng(11);
  for (int k = 0; k < 20; ++k) {
    const Limits l = random_limits(rng, 1e6);
    std::uniform_int_distribution<uint32_t> ops(1, 20000);
    std::vector<Profile::Command> moves;
    uint64_t need = 0;
    for (int m = 0; m < 4; ++m) {
      Profile::Command c;
      c.ops = ops(rng);
      c.target = l.regs.max_level;
      c.end = m == 3 ? 0 : std::uniform_int_distribution<uint32_t>(0, l.regs.max_level / 4)(rng);
      need += c.ops.to_uint64();
      moves.push_back(c);
    }
    const Trace r = run(moves, l.regs.q, l.regs.len, need);
    ASSERT_GT(r.clocks, 0u) << "case " << k << ": the stream never finished";
    expect_within_limits(r, l.regs.q, l.regs.len, l.regs.max_level, k);
    EXPECT_GE(r.total_ops, need) << "case " << k;
  }
}

TEST(FeedProfile, RestToRestMovesTakeWithinOnePercentOfTheOptimalTime) {
  std::mt19937_64 rng(5);
  std::vector<double> gaps;
  for (int k = 0; k < 40; ++k) {
    const Limits l = random_limits(rng, 1e6);
    const uint32_t n = std::uniform_int_distribution<uint32_t>(1000, 100000)(rng);
    Profile::Command c;
    c.ops = n;
    c.target = l.regs.max_level;
    c.end = 0;
    const Trace r = run({c}, l.regs.q, l.regs.len, n);
    ASSERT_GT(r.clocks, 0u);
    // The limits the registers really give.
    const models::PathLimits real{l.regs.level_speed * l.regs.max_level, l.regs.accel, l.regs.jerk};
    const double opt = models::optimal_move_time(n, real);
    const double ours = r.rest_clocks / 1e6;
    gaps.push_back(ours / opt - 1);
    // Never faster than the optimum (one tick of slack: the speed is a
    // staircase of ticks, not a continuous curve).
    EXPECT_GE(ours, opt - kTick / 1e6) << "case " << k << " n " << n;
    // The speed at the last op: the profile was within a few levels of rest.
    EXPECT_LE(r.v_at_last_op, 4 * l.regs.q * l.regs.len) << "case " << k;
  }
  std::sort(gaps.begin(), gaps.end());
  // The aim of issue 25: within 1 % of the optimum on moves over 1000 steps.
  EXPECT_LE(gaps.back(), 0.01);
  std::printf("gap to the optimum: min %.4f median %.4f max %.4f\n", gaps.front(),
              gaps[gaps.size() / 2], gaps.back());
}

TEST(FeedProfile, FeedHoldStopsWithinTheLimitsAndResumeFinishesTheMove) {
  std::mt19937_64 rng(3);
  for (int k = 0; k < 10; ++k) {
    const Limits l = random_limits(rng, 1e6);
    Profile::Command c;
    c.ops = 50000;
    c.target = l.regs.max_level;
    c.end = 0;
    const Trace free_run = run({c}, l.regs.q, l.regs.len, 50000);
    // Hold from a third of the free run's time for a long while, then resume.
    const uint64_t from = free_run.rest_clocks / 3, to = from + 2'000'000;
    const Trace r = run({c}, l.regs.q, l.regs.len, 50000, from, to);
    expect_within_limits(r, l.regs.q, l.regs.len, l.regs.max_level, k);
    // At rest before the hold ends: the speed reached 0 and no op was taken.
    const size_t tick_to = to / kTick;
    ASSERT_LT(tick_to, r.v.size());
    EXPECT_EQ(r.v[tick_to - 1], 0) << "case " << k;
    EXPECT_EQ(r.ops[tick_to - 1], r.ops[tick_to - 100]) << "case " << k;
    EXPECT_LT(r.ops[tick_to - 1], 50000u) << "case " << k;
    EXPECT_GT(r.clocks, 0u) << "case " << k << ": the move did not finish after the resume";
    EXPECT_GE(r.total_ops, 50000u) << "case " << k;
  }
}

}  // namespace
}  // namespace hwinterp::hls

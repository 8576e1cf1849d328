// The double-precision side of the feed profile (hls/feed_profile.h): the
// block's registers from a machine's limits, the limits the registers really
// give, and the time-optimal jerk-limited rest-to-rest move the profile is
// measured against (the closed form of the 7-phase S-curve, which Ruckig
// computes too: tests/profile/ compares all three).
#pragma once

#include <cstdint>
#include <string>

namespace hwinterp::models {

// Limits along the path, in engine operations (steps) and seconds.
struct PathLimits {
  double velocity = 0;  // ops/s
  double accel = 0;     // ops/s^2
  double jerk = 0;      // ops/s^3
};

// The block's build: its widths (hls/feed_profile.h, rtl/feed_profile.sv).
struct ProfileBuild {
  int spd_w = 48;  // speed fraction bits
  int tick_w = 8;  // a tick is 2^tick_w clocks
  int len_w = 10;  // the moving sum is at most 2^len_w ticks
  int lvl_w = 16;  // speed level bits
  double clock_hz = 50e6;
};

// The registers, and what they give in physical units.
struct ProfileRegisters {
  uint64_t q = 0;          // speed quantum, ops/clock * 2^spd_w
  unsigned len = 1;        // ticks of the moving sum (L)
  double level_speed = 0;  // ops/s of one level (q * L)
  double accel = 0;        // ops/s^2 the registers allow (<= the limit)
  double jerk = 0;         // ops/s^3 the registers allow (<= the limit)
  uint32_t max_level = 0;  // the highest level within the velocity limit and one op a clock
};

// Registers within `limits`: L = ceil(A/J) ticks (at most 2^len_w), q the
// largest quantum with q*L <= A a tick and q <= J a tick^2, both rounded
// down. Throws std::invalid_argument naming the value when a limit is not
// positive or the quantum rounds to 0 (the build's speed bits are too few).
ProfileRegisters profile_registers(const PathLimits& limits, const ProfileBuild& build);

// The level of a speed (ops/s), rounded down, capped at max_level.
uint32_t profile_level(const ProfileRegisters& regs, double speed);

// The distance, in level-ticks (one tick at level 1; a tick at level c
// travels c), the block charges a move entered at level `e` whose end level
// is `next_end` (hls/feed_profile.h's cost): a tick at e with the hold the
// reversal rule may force (L ticks), the brake from e to next_end, and
// next_end held L - 1 ticks before the move's distance runs out. A planner
// keeps it within the move's length so that the move ends at its end level.
double profile_entry_cost(double e, double next_end, unsigned len);

// The feed override's word for `percent` (0..200): round(percent * 128 / 100),
// the block's ovr_i (hls/feed_profile.h: factor word / 128, 1/128 = 0.78 %
// resolution). Throws std::invalid_argument naming the value outside 0..200.
unsigned override_word(double percent);

// The clocks the block takes over a move of `ops` operations entered at level
// `entry`, cruising at level `cruise` and ending at level `end`, as its
// rules give them: the level moves a step a tick and the speed is its moving
// sum over L ticks, so a change of d levels lasts d + L ticks at the mean of
// its two speeds; the cruise level is lowered until the changes in and out fit
// the move. An estimate (the progress lines', the clock ceilings'): the block's
// reversal holds and the ticks' phase are left out.
double profile_move_clocks(const ProfileRegisters& regs, const ProfileBuild& build, uint32_t entry,
                           uint64_t ops, uint32_t cruise, uint32_t end);

// The shortest time (s) of a rest-to-rest move of `distance` ops within the
// limits (the 7-phase S-curve, or fewer phases when a limit is not reached).
double optimal_move_time(double distance, const PathLimits& limits);

}  // namespace hwinterp::models

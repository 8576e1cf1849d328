// The motion compiler's side of the feed profile (issue 25): for each
// motion_top command, the feed profile's move (hls/feed_profile.h): its engine
// operations, its cruise level and its end level, planned over a window of
// commands ahead (look-ahead).
//
// Limits. The profile's acceleration and jerk are one pair for the whole
// program (its registers change only at rest): 0.8 of the smallest limit, in
// steps, of the axes the program moves (an axis moves at most one step an
// engine operation, so no axis goes faster than the path in operations; an
// axis the program never moves sees nothing); the 0.2 left is for the
// centripetal terms on arcs. Per command, the cruise speed (operations/s) is
// the programmed one (its feed word) capped by every axis's velocity limit
// projected on the command (axis speed = path speed * steps of the axis per
// operation), and on arcs by v^2/r <= 0.2 A, v^3/r^2 <= 0.1 J and
// 3 v A / r <= 0.1 J (the centripetal acceleration and the jerk of turning).
//
// Corners (the corner model the kinematics check states too): at a junction
// the speed in operations/s is continuous, and each axis's speed jumps by
// v * |s1_i - s2_i| (s: the axis's steps per operation before and after,
// which differ with the direction and with a line's length: its operations
// are a power of two). The junction speed keeps every jump within one tick
// of the axis's acceleration (A_i * tick): what the profile itself changes
// the speed by in a tick. So corners are exact stops unless the moves join
// tangentially (arc pieces, split lines, tangent arcs and lines).
// A program stop (M0, M1) between two moves is an exact stop too, and the
// program ends at rest (M2, M30).
//
// The feed override (hls/feed_profile.h) scales the programmed speed (the
// level `target`), and the block caps the result at `max`: the caps above
// without the programmed feed (the axes' velocity limits, the step/dir stage,
// the arc terms, one operation a clock), so no override passes a limit, and
// at 100 % the cruise level is min(target, max), as before the override. The
// end levels are planned from that level and are not raised.
//
// Look-ahead. A command is planned once `window` commands after it are known
// (or the program ended: the last ends at rest): backward over the window,
// each end level is lowered until the next command can brake from it to its
// own end level within its length, by the block's own cost (hold L ticks,
// brake, settle: hls/feed_profile.h). Forward, the block accelerates as far
// as it can on its own.
#pragma once

#include <cstdint>
#include <deque>
#include <string>

#include "models/feed_profile_model.h"
#include "models/motion_top_model.h"
#include "tb/gcode/machine.h"

namespace hwinterp::gcode {

struct ProfileCommand {
  uint64_t ops = 0;         // engine operations of the command
  uint32_t target = 0;      // cruise level: the programmed speed's
  uint32_t end = 0;         // level at its last operation
  uint32_t max = 0;         // the cap of the cruise level (the machine's)
  double target_speed = 0;  // operations/s before rounding to a level (for reports)
};

// The axes a command moves, as bits: a line's axes with steps, an arc's plane
// axes and its slaved axes with steps.
uint32_t motion_moved_axes(const models::MotionCommand& c, int axes);

class ProfilePlanner {
 public:
  // Throws cli::UsageError naming the key when an axis of `machine` lacks a
  // limit the profile needs (max_accel; max_jerk for an S-curve). `moved`:
  // bit i set when the program moves axis i (motion_moved_axes); the
  // program's acceleration and jerk come from those axes' limits only.
  ProfilePlanner(const Machine& machine, int axes, const models::ProfileBuild& build, size_t window,
                 int feed_w, uint32_t moved);
  const models::ProfileRegisters& registers() const { return regs_; }
  double accel() const { return accel_; }  // the profile's acceleration, operations/s^2
  double jerk() const { return jerk_; }    // and jerk, operations/s^3

  // The next command, in program order; stop_before: the machine is at rest
  // before it (M0, M1: an exact stop at the junction).
  void push(const models::MotionCommand& c, bool stop_before = false);
  // Throws cli::UsageError naming the key when the machine's limits for `c`
  // cannot be kept by the profile (a max_velocity below one level); push
  // checks each command, a caller may check a whole program before it runs.
  void check(const models::MotionCommand& c) const;
  // The cruise speed `c` is planned at (operations/s, at 100 % override):
  // its programmed feed within the caps of its axes and, on an arc, of its
  // centripetal acceleration and jerk.
  double planned_speed(const models::MotionCommand& c) const;
  // Its feed word's speed (operations/s; the clock's for a word of 0).
  double programmed_speed(const models::MotionCommand& c) const;
  void finish();                  // the program ended
  bool pop(ProfileCommand& out);  // the next planned command, if any is final

 private:
  struct Entry {
    ProfileCommand p;
    std::array<double, models::kMotionMaxAxes> s_start{}, s_end{};  // steps per operation
    double max_end = 0;  // the junction's bound into the next command (levels)
  };
  // The speed cap (operations/s) of `c` from its axes' max_velocity and the
  // step/dir stage, and the axis whose max_velocity sets it (-1: the stage
  // or nothing does) with its steps per operation.
  struct AxisCap {
    double v;
    int axis;
    double steps_per_op;
  };
  AxisCap axis_cap(const models::MotionCommand& c) const;
  void check_cap(const AxisCap& cap) const;  // check()'s refusal, on a cap already taken
  // `cap` and, on an arc, the centripetal caps: the speed at 100 % override or more.
  double speed_cap(const models::MotionCommand& c, const AxisCap& cap) const;
  uint32_t brake_level(uint64_t ops, uint32_t next_end) const;
  void plan_back();

  Machine machine_;
  int axes_;
  models::ProfileBuild build_;
  models::ProfileRegisters regs_;
  double accel_ = 0, jerk_ = 0, tick_s_ = 0;
  size_t window_;
  int feed_w_;
  std::deque<Entry> q_;
  bool finished_ = false;
};

}  // namespace hwinterp::gcode

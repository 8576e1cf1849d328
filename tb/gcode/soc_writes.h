// `hwinterp gcode --soc-writes FILE`: a part program as the bus writes that
// stream its commands into motion_soc's command FIFO (the host's own
// staging, tb/bus/soc_host.h's CommandStager), for a test bench of one's own
// to replay (tests/cocotb/test_motion_soc.py's gcode_program does) and for
// the host package (sw/host, `hwinterp-host run`), which streams it to a
// board.
//
// The file (JSON):
//   "program", "canon", "variant", "feed_mode" ("full" or "programmed");
//   "axes", "feed_w": the variant's; "widths": every width it was compiled
//     for (axes, acc_w, coord_w, ops_w, pos_w, tim_w, feed_w: ID_WIDTHS and
//     ID_WIDTHS2 of a board that runs it);
//   "clock_hz": the machine's clock (ID_CLOCK); "timing": the machine's
//     step timing in clocks (step_len, step_space, dir_setup, dir_hold);
//   "fifo_level_room_lsb": the room field of FIFO_LEVEL (push only with room);
//   "profile": {"kind": "off"}, or with a feed profile its kind, the
//     registers q (PROF_Q) and len (PROF_LEN), the build's widths spd_w,
//     tick_w, len_w, lvl_w (ID_PROFILE), level_speed, max_level, accel,
//     jerk and the planner's window;
//   "commands": one list per command of [register, value] pairs in order,
//     the register named as the SystemRDL description names it, upper case
//     (CMD_DELTA0, ..., CMD_PUSH): the staging registers whose value changes
//     from the command before (the first command: from the reset values, 0),
//     with the profile each command's CMD_MV_* words and CMD_FEED 0, then
//     CMD_PUSH;
//   "moves": one object per G-code move in order: "move" (1-based), "line",
//     "kind" (traverse, feed, arc), "end_mm" (the programmed end: x, y, z mm,
//     a deg), "end_steps" (its lattice point per axis from the origin: the
//     sum of the displacements of every command up to its last), "first_command"
//     (0-based index into "commands") and "commands" (how many; 0: the move
//     leaves the lattice point where it is), "chords", "programmed_s",
//     "feed_words_s" (the moves CSV's columns);
//   "totals": the `hwinterp gcode --json` keys of the compile (moves,
//     traverses, feeds, arcs, commands, line_commands, arc_commands,
//     chord_arcs, chords, split_arcs, programmed_time_s, feed_word_time_s);
//   "end": the lattice point the commands lead to, per axis, from the origin.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "models/feed_profile_model.h"
#include "tb/gcode/motion_compiler.h"
#include "tb/gcode/move.h"
#include "tb/lockstep/profile_feed.h"

namespace hwinterp::gcode {

// What the file is written for.
struct SocWritesSetup {
  std::string program;
  bool canon = false;
  std::string variant;
  MotionWidths widths;
  int pos_w = 0, tim_w = 0;  // the variant's POS_W and TIM_W
  FeedMode mode = FeedMode::kFull;
  // With a feed profile (machine.profile not off): its registers, build and
  // window, and each command's planned move in order (next_move: false
  // after the last).
  bool profiled = false;
  models::ProfileRegisters prof_regs;
  models::ProfileBuild prof_build;
  size_t prof_window = 0;
  double prof_accel = 0, prof_jerk = 0;  // the planner's, operations/s^2 and /s^3
  std::function<bool(tb::ProfileWords&)> next_move;
};

// Compiles `source` (as the run does) and writes the file. Throws
// std::runtime_error naming `path` when it cannot be written.
void write_soc_writes(MoveSource& source, const Machine& machine, const SocWritesSetup& setup,
                      const std::string& path);

}  // namespace hwinterp::gcode

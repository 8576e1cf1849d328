// `hwinterp gcode --soc-writes FILE`: a part program as the bus writes that
// stream its commands into motion_soc's command FIFO (the host's own
// staging, tb/bus/soc_host.h's CommandStager), for a test bench of one's own
// to replay: tests/cocotb/test_motion_soc.py's gcode_program does.
//
// The file (JSON): "variant", "axes", "feed_w", "fifo_level_room_lsb" (the
// room field of FIFO_LEVEL: push only with room), "commands": one list per
// command of [register, value] pairs in order, the register named as the
// SystemRDL description names it, upper case (CMD_DELTA0, ..., CMD_PUSH);
// "end": the lattice point the commands lead to, per axis, from the origin.
#pragma once

#include <string>

#include "tb/gcode/motion_compiler.h"
#include "tb/gcode/move.h"

namespace hwinterp::gcode {

// Compiles `source` (as the run does) and writes the file. Throws
// std::runtime_error naming `path` when it cannot be written.
void write_soc_writes(MoveSource& source, const Machine& machine, const MotionWidths& widths,
                      FeedMode mode, const std::string& program, const std::string& variant,
                      const std::string& path);

}  // namespace hwinterp::gcode

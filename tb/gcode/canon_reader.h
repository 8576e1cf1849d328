// Reads LinuxCNC's canonical-command output (`rs274 -g prog.ngc out.canon`),
// one command a line, as rs274 2.9 prints it:
//
//     12 N..... ARC_FEED(20.0000, 2.0000, 12.5000, 2.0000, -1, 3.0000, 0.0000, 0.0000, 0.0000)
//     20 N12345 STRAIGHT_FEED(2.0000, 6.0000, 3.0000, 0.0000, 0.0000, 0.0000)
//     21 N999999STRAIGHT_FEED(3.0000, 6.0000, 3.0000, 0.0000, 0.0000, 0.0000)
//
// that is: the canon line number (Move::line), 'N' and the source line's N
// digits padded to six columns ("....." when it has none, nothing when its
// N has no digits), the command and its arguments.
//
// Read: STRAIGHT_TRAVERSE and STRAIGHT_FEED (X Y Z A B C, or X Y Z A B C U V W
// with U V W zero), ARC_FEED (first_end, second_end, first_axis, second_axis,
// rotation, axis_end, A, B, C [, U, V, W zero]: ends and centre in the
// plane's canon order, tb/gcode/move.h), SET_FEED_RATE (>= 0),
// USE_LENGTH_UNITS (CANON_UNITS_MM, CANON_UNITS_INCHES: lengths and feeds
// after it are converted to mm; a feed keeps the units it was given in, as
// LinuxCNC's canon layer does), SELECT_PLANE (CANON_PLANE_XY, _YZ, _XZ).
// Start: mm, XY plane, feed 0.
// Counted by name and ignored (ReaderStats::ignored_commands): every other
// command, except those that would move the tool or shift the path, which
// are refused: STRAIGHT_PROBE, RIGID_TAP, NURBS_*/SPLINE_* feeds, a feed mode
// other than units per minute (SET_FEED_MODE(_, 1)), and SET_G5X_OFFSET,
// SET_G92_OFFSET, SET_XY_ROTATION with a non-zero value (moves are read in
// program coordinates).
// rs274 writes "executing" to stderr before it starts: when both streams
// went to one file it is a line of its own, or stuck after the last
// command's ')'; both are counted as "executing" and ignored.
// Anything else throws cli::UsageError "FILE:LINE: ..." naming the text: a
// line not of this form, an unknown argument, a number that is not a plain
// decimal (no nan, no inf) or beyond +-1e9, a wrong argument count.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "tb/gcode/line_source.h"
#include "tb/gcode/move.h"

namespace hwinterp::gcode {

class CanonReader : public MoveSource {
 public:
  // `name` names the file in error messages. `in` must outlive the reader.
  CanonReader(std::istream& in, std::string name);

  bool next(Move& m) override;
  const ReaderStats& stats() const override { return stats_; }

  static constexpr size_t kMaxLineChars = 4096;

 private:
  bool run_line(const std::string& line, Move& m);
  double number(const std::string& text, const std::string& what) const;
  void position(const std::vector<std::string>& args, size_t first, size_t count,
                const std::string& cmd, Move& m) const;

  LineSource src_;
  ReaderStats stats_;
  bool inch_ = false;
  Plane plane_ = Plane::kXY;
  double feed_mm_ = 0;
  bool stop_pending_ = false;  // a PROGRAM_STOP or OPTIONAL_PROGRAM_STOP since the last move
  std::string shown_;          // the line, for messages
};

}  // namespace hwinterp::gcode

// An RS274/NGC subset reader with LinuxCNC 2.9's semantics (its `rs274`
// interpreter is the oracle: tests/data/gcode/*.canon).
//
// Accepted, changing the path:
//   G0 G1 G2 G3 (modal; a line with axis words only repeats the motion mode,
//   in arc mode also a line with I/J/K words only), X Y Z A B C, I J K (the
//   plane's two; G90.1 absolute needs both, G91.1 incremental defaults them to
//   0), R (> 0 the shorter arc, < 0 the longer), P with G2/G3 (turns, an
//   integer >= 1 within 0.001), G17 G18 G19, G20 G21 (25.4 exactly), G90 G91,
//   G90.1 G91.1, F (mm/min or in/min, >= 0), G80 (ends the motion mode).
// Accepted and counted (ReaderStats::words), not changing the path:
//   N (first on the line), S (>= 0), T (an integer >= 0), M0 M1 M2 M30 M3 M4
//   M5 M6 M7 M8 M9, G4 with P (dwell), G40, G49, G54-G59 (moves stay in
//   program coordinates: no offsets are known or applied, as rs274 prints
//   them), G61 G61.1 G64 (P, Q), G94, comments "(...)" and ";...", '%' lines,
//   blank lines; upper and lower case, spaces anywhere outside comments.
// State at the start, as rs274's: every axis at 0, G21 G90 G17 G91.1 G94, no
// motion mode (axis words need a G0-G3 first), feed 0.
// Per line, LinuxCNC's order of execution: F (in the units in force before
// this line's G20/G21), S, T, M6, M3-M5, M7-M9, G4, plane, units, G40 G49
// G5x G6x, distance modes, motion, then M0 M1 M2 M30.
// Like LinuxCNC:
//   - at most one word of a modal group per line (two motion words are
//     refused; a G80 beside G0-G3 is ignored), every word must have a use on
//     its line;
//   - G94 sets the feed to 0 (an F on its line comes after it); G1, G2, G3
//     need a feed > 0;
//   - arcs follow tb/gcode/arc_rules.h; R0 is refused (rs274 takes it when
//     the chord is within 0.00127 mm, and prints a NaN centre);
//   - M2, M30 or a closing '%' end the program (what follows is counted, not
//     read); a program that just stops is refused; a '%' opens a program
//     only on its first non-blank line; a line has at most 252 characters.
// Everything else throws cli::UsageError "FILE:LINE: ...": a word outside
// the subset (parameters, expressions, O-words, G41/G42, G43, G92, G28, G30,
// G33, G38, G73-G89 cycles, G93, G95, G5, G7/G8, G10, G53, U V W, ...) with
// the hint to run LinuxCNC's interpreter and use --canon, and every
// unreadable line with its text. Nothing is skipped.
#pragma once

#include <array>
#include <istream>
#include <string>

#include "tb/gcode/line_source.h"
#include "tb/gcode/move.h"

namespace hwinterp::gcode {

class NgcReader : public MoveSource {
 public:
  // `name` names the program in error messages. `in` must outlive the reader.
  NgcReader(std::istream& in, std::string name);

  bool next(Move& m) override;
  const ReaderStats& stats() const override { return stats_; }

  static constexpr size_t kMaxLineChars = 252;

 private:
  struct Block;
  bool run_line(const std::string& line, Move& m);
  bool execute(const Block& b, Move& m);
  void arc(const Block& b, bool clockwise, const std::array<double, 6>& end, Move& m);
  void finish(Move& m) const;
  void skip_rest();

  LineSource src_;
  ReaderStats stats_;
  // Program state, in program units (mm or inch; A B C in degrees), as
  // LinuxCNC keeps it.
  std::array<double, 6> pos_{};
  bool inch_ = false;
  bool absolute_ = true;       // G90
  bool arc_absolute_ = false;  // G90.1
  Plane plane_ = Plane::kXY;
  int motion_ = -1;       // G code x 10 of the motion mode (0, 10, 20, 30), -1 none
  double feed_mm_ = 0;    // mm/min
  bool started_ = false;  // a non-blank line was read
  bool percent_ = false;  // the program opened with '%'
  bool ended_ = false;
  bool stop_pending_ = false;  // an M0 or M1 since the last move
};

}  // namespace hwinterp::gcode

// The one move type both part-program readers produce, and the streaming
// interface they share.
//
// Contract: a reader turns a part program (RS274/NGC, tb/gcode/ngc_reader.h,
// or LinuxCNC's canonical commands, tb/gcode/canon_reader.h) into Moves, one
// at a time, in program order, in absolute program coordinates and always in
// mm (A B C in degrees). It reads its std::istream line by line and never
// holds the program: memory does not grow with the program's length. Bad
// input ends the stream with cli::UsageError ("FILE:LINE: ..."), never with
// a silently skipped line.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>

#include "models/common.h"

namespace hwinterp::gcode {

constexpr double kMmPerInch = 25.4;  // exact, by definition

enum class MoveKind { kTraverse, kFeed, kArc };  // G0 / G1 / G2,G3
enum class Plane { kXY, kYZ, kXZ };              // G17 / G19 / G18 (LinuxCNC's CANON_PLANE_*)

// Axis indices into Move::end.
enum Axis { kX = 0, kY = 1, kZ = 2, kA = 3, kB = 4, kC = 5 };
constexpr int kAxes = 6;
constexpr const char* kAxisNames = models::kAxisLetters;

// One motion command.
struct Move {
  MoveKind kind = MoveKind::kTraverse;
  std::array<double, 6> end{};  // X Y Z (mm) A B C (deg): absolute programmed end, always in mm
  Plane plane = Plane::kXY;     // arcs: the plane in force (other moves: the plane in force too)
  // Arcs: centre, absolute mm, in LinuxCNC's canon order for the plane:
  //   XY: (X, Y); YZ: (Y, Z); XZ: (Z, X). Zero for other moves.
  std::array<double, 2> center{};
  // Arcs: LinuxCNC's rotation: +1 CCW, -1 CW; |rotation| = 1 + extra full
  // turns (P word). Zero for other moves.
  int rotation = 0;
  double feed = 0;  // mm/min in force (0 if none); traverses keep the last F too but it is unused
  // A program stop (M0, M1; canon PROGRAM_STOP, OPTIONAL_PROGRAM_STOP) came
  // between the move before and this one: the machine is at rest before it
  // (the feed profile plans an exact stop there).
  bool stop_before = false;
  uint64_t line =
      0;  // 1-based source line number (ngc: the file's line; canon: the canon line number)
};

// The plane's axes in canon order: first and second (the arc's plane, as in
// Move::center) and the third (the helix axis).
struct PlaneAxes {
  int first, second, third;
};
constexpr PlaneAxes plane_axes(Plane p) {
  return p == Plane::kXY   ? PlaneAxes{kX, kY, kZ}
         : p == Plane::kYZ ? PlaneAxes{kY, kZ, kX}
                           : PlaneAxes{kZ, kX, kY};
}

const char* to_string(MoveKind k);  // "traverse", "feed", "arc"
const char* to_string(Plane p);     // "XY", "YZ", "XZ"

// What a reader saw besides the moves.
struct ReaderStats {
  uint64_t traverses = 0;
  uint64_t feeds = 0;
  uint64_t arcs = 0;
  uint64_t lines = 0;  // source lines read
  // Lines after the program's end (M2, M30 or the closing '%'), which
  // LinuxCNC does not read either: counted, not interpreted.
  uint64_t lines_after_end = 0;
  // ngc: every accepted word that does not change the path, by name ("S",
  // "T", "F", "N", "M3", "G64", "G90.1", "P", "comment", "%", ...), with the
  // number of times it appeared.
  std::map<std::string, uint64_t> words;
  // canon: every ignored canonical command, by name, with its count.
  std::map<std::string, uint64_t> ignored_commands;

  uint64_t moves() const { return traverses + feeds + arcs; }
  void count(const Move& m);
};

// A stream of moves. next() is called once per move, not per clock.
class MoveSource {
 public:
  virtual ~MoveSource() = default;
  // The next move into `m`; false at the end of the program. Throws
  // cli::UsageError ("FILE:LINE: ...") on bad input.
  virtual bool next(Move& m) = 0;
  virtual const ReaderStats& stats() const = 0;
};

}  // namespace hwinterp::gcode

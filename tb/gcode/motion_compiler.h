// The motion compiler: G-code Moves (tb/gcode/move.h, from either reader)
// to motion_top's commands (models/motion_top_model.h), one at a time, with
// a report per move. Streaming: it pulls one Move at a time from its
// MoveSource and keeps O(1) state; a move's commands (chords, pieces) are
// made one at a time as they are asked for.
//
// Lattice. Every lattice point is rounded from absolute programmed
// coordinates, never accumulated: a point p (mm; A B C in degrees) is
// llround(p_i * steps_per_unit_i) on each axis the machine has (0 on the
// others). The start of a move is the current lattice point, which is always
// the rounded programmed end of the previous move (the program starts at 0).
//
// Lines (G0, G1): one dda_line command with delta = the rounded end - the
// current lattice point. A line command (a line, a piece, a chord) whose
// delta is 0 on every axis is left out: such a move becomes no command.
// When a delta does not fit ACC_W (|delta| <= 2^(ACC_W-1) - 1 is what fits),
// the line is split into k = ceil((D + 1) / (2^(ACC_W-1) - 2)) equal pieces
// (D the largest axis travel in steps, unrounded), each ending at the
// lattice point rounded from the programmed point i/k along the line:
// every piece's delta is then at most D/k + 1 and fits.
//
// Arcs (G2, G3): the programmed sweep theta (LinuxCNC's: the angle from the
// start to the end about the centre in the arc's direction in (0, 2 pi], a
// full circle when they coincide, plus 2 pi per extra turn of P) runs as
// k = 1 engine arc, or, when theta > 3 pi / 2 and it is not a one-turn full
// circle, k = ceil(theta / (3 pi / 2)) pieces of equal sweep (so that no
// piece's end is near its start, where rule M's lap rule could read the
// rounded end as the other side of the start). The programmed path is
// LinuxCNC's: the radius goes linearly from the start's to the end's over the
// sweep, the helix axis and every other axis linearly too; piece i ends at
// the lattice point rounded from the path's point at i/k (the last one at
// the programmed end). Each piece is one ppc_arc command: centre = the
// rounded programmed centre - the start, end = the piece's end - the start
// (engine x, y = the plane's canon axes: XY, ZX, YZ), ccw = G3, ops =
// models::motion_arc_ops, delta = the piece's steps on the other axes.
// Arc tolerance: two more cuts keep the engine's arcs on the programmed path
// (CompilerOptions::arc_tolerance_steps, default 1 step; infinity turns
// them off; pieces of equal sweep, one engine arc each):
//   - Spirals. Rule M runs the circle through the piece's start and closes
//     with a line to its end, up to |re - rs| off LinuxCNC's spiral: k is at
//     least |r2 - r1| (in steps of the finer plane axis) / tolerance.
//   - Slaved progress. The engine steps a slaved axis by the arc's
//     operations, i.e. by the PPC path's L1 length (one axis step per
//     operation), while LinuxCNC moves it linearly with the angle: over a
//     quadrant the two differ by up to 2.1 % of the axis's travel (near 20
//     and 70 degrees), e.g. 21 steps of Z on a quarter helix falling 1000
//     steps. k grows until, for every piece, its largest slaved travel in
//     steps times the largest gap between the L1 and the angular progress of
//     the programmed path over it (sampled at 64 points) is within the
//     tolerance (the gap shrinks with the sweep: the error falls with k^2).
// A piece runs as chord lines instead (never refusing a valid program) when:
//   - the plane's two axes have different steps per unit,
//   - a coordinate (centre or end, relative to the start) exceeds COORD_W
//     (|v| <= 2^(COORD_W-1) - 1 fits) or the PPC model's 2^29,
//   - ops exceeds OPS_W (ops <= 2^OPS_W - 1 fits),
//   - a slaved delta exceeds ops (more than one step per operation) or ACC_W,
//   - the rounded command is degenerate for rule M (start within one step of
//     the centre, or end on the centre), or
//   - rule M would turn a sweep other than the programmed one: its sweep is
//     the lattice angle from start to end (models::PpcArcIdeal::theta), one
//     lap more when it counts a full lap first with the end angularly ahead,
//     one lap less when it counts none with the end angularly behind
//     (models::PpcArcStream::laps); it must be within pi/4 of the piece's
//     programmed sweep (rounding moves a sweep by ~1 step / radius).
// Chords: the piece is cut into n chords of equal parameter, each ending at
// the lattice point rounded from the path's point there, with
// n >= sweep / alpha, alpha = 2 acos(1 - 0.4 / R) (computed as
// 4 asin(sqrt(0.2 / R)); n >= 1, and 1 when R <= 0.4), R = the larger radius
// in mm times the larger steps per unit of the plane's axes: the exact
// chord's sagitta, R (1 - cos(alpha/2)), is then at most 0.4 step (below
// 0.5; the other axes are linear in the parameter on both the chord and the
// helix, so only the plane contributes). n also keeps every chord's delta
// within ACC_W.
//
// Feed words. Full mode: every command feed = 2^FEED_W. Programmed mode:
// the command's programmed time T = its share of the move's path / rate,
// with LinuxCNC's rate: the feed F (mm/min) over the XYZ length, or, for a
// move with no XYZ motion, F as deg/min over the ABC length; traverses use
// the machine's rapid rate (rapid_mm_per_min, also as deg/min for a rotary
// traverse). A line piece's share is 1/k of the move; an arc piece's or a
// chord's is the XYZ length of its parameter interval of the helix. Then
// clocks = T * clock_hz, and feed = ceil(ops * 2^FEED_W / clocks), clamped to
// [1, 2^FEED_W], ops = the command's engine operations (line 2^n, arc ops).
// A feed move at feed rate 0 (a canon file can say so) is a UsageError.
//
// Machining time, exact from the feed words, ignoring stalls from the
// step/dir timing and the clocks a command takes to load: the core's feed
// accumulator adds the word f to a FEED_W-bit phase p every clock and does
// one operation per carry; the phase is kept from command to command. A
// command of K operations takes ceil((K 2^FEED_W - p) / f) clocks to its
// K-th operation and leaves p' = p + clocks f - K 2^FEED_W; at f = 2^FEED_W
// it takes K clocks and keeps p. The report gives, per move and in total,
// the programmed time and both modes' times (full words: clocks = ops;
// programmed words, with their own phase), in clocks and in seconds
// (clocks / clock_hz).
//
// Errors (cli::UsageError "FILE:LINE: ..."): a move that changes an axis
// the machine does not have (or an arc in a plane with such an axis), an
// end whose steps do not fit 62 bits, a feed move at feed rate 0. A machine
// axis beyond the core's AXES, or widths out of range, are UsageErrors when
// the compiler is built.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "models/motion_top_model.h"
#include "tb/gcode/machine.h"
#include "tb/gcode/move.h"

namespace hwinterp::gcode {

// The core's widths (motion_top's parameters).
struct MotionWidths {
  int axes = 4;      // AXES: machine axes X Y Z A ... in that order, 3..6
  int acc_w = 32;    // ACC_W: signed line delta (and slaved delta) width, 4..62
  int coord_w = 24;  // COORD_W: signed arc coordinate width, 3..60
  int ops_w = 31;    // OPS_W: arc operation count width, 1..ACC_W - 1
  int feed_w = 16;   // FEED_W: feed word fraction bits, 1..31
};

enum class FeedMode { kFull, kProgrammed };

// Choices of the compiler's own (see "Arc tolerance" above).
struct CompilerOptions {
  double arc_tolerance_steps = 1.0;  // > 0; infinity: arcs are not cut for it
};

// One move's report, complete when its last command has been made.
struct MoveReport {
  uint64_t index = 0;  // 1-based move number
  MoveKind kind = MoveKind::kTraverse;
  uint64_t line = 0;                   // source line (ngc: file line; canon: canon line number)
  std::array<double, 4> end{};         // programmed end: x_mm, y_mm, z_mm, a_deg
  std::array<int64_t, 6> end_steps{};  // its lattice point, X Y Z A B C
  uint64_t commands = 0;               // commands it became (0: no motion on the lattice)
  uint64_t arc_commands = 0;           // of which ppc_arc commands
  uint64_t pieces = 1;                 // k: line pieces (ACC_W) or arc pieces (sweep, arc
                                       //   tolerance); 1 if not split
  uint64_t chords = 0;                 // chord lines (arcs the arc engine could not take)
  const char* chord_reason = "";       // why (the first piece's reason), "" if none
  double length_mm = 0;                // XYZ length (mm), or ABC length (deg) with no XYZ motion
  double programmed_s = 0;             // length / rate
  uint64_t operations = 0;             // engine operations of its commands
  uint64_t clocks_full = 0;            // = operations: full feed, one operation a clock
  uint64_t clocks_programmed = 0;      // with the programmed feed words (phase carried)
  double full_s = 0, programmed_words_s = 0;  // the clocks / clock_hz
  uint32_t feed_min = 0, feed_max = 0;        // feed words of its commands (this mode)
};

// Sums over the program so far.
struct CompileTotals {
  uint64_t moves = 0, commands = 0, line_commands = 0, arc_commands = 0;
  uint64_t split_lines = 0, line_pieces = 0;  // lines split for ACC_W, their pieces
  uint64_t split_arcs = 0, arc_pieces = 0;    // arcs split into pieces, their pieces
  uint64_t chord_arcs = 0, chords = 0;        // arcs (moves) with chords, the chord lines
  uint64_t operations = 0, clocks_full = 0, clocks_programmed = 0;
  double length_mm = 0, programmed_s = 0, full_s = 0, programmed_words_s = 0;
};

// About the command next() returned last.
struct CommandInfo {
  uint64_t move_index = 0;         // the move it belongs to (MoveReport::index)
  uint64_t line = 0;               // its source line
  uint64_t number = 0;             // 1-based within its move
  bool chord = false;              // a chord of an arc
  std::array<int64_t, 6> start{};  // lattice point it starts from
  uint64_t operations = 0;
  uint64_t clocks_full = 0, clocks_programmed = 0;
};

// A FEED_W-bit feed accumulator's clocks: see the top.
class FeedClock {
 public:
  explicit FeedClock(int feed_w) : feed_w_(feed_w) {}
  // Clocks to the K-th operation of a command with feed word `word`
  // (>= 2^FEED_W: full); advances the phase.
  uint64_t run(uint64_t operations, uint64_t word);
  uint64_t phase() const { return phase_; }

 private:
  int feed_w_;
  uint64_t phase_ = 0;
};

// The feed word for `operations` engine operations in `clocks` clocks:
// ceil(operations 2^FEED_W / clocks) in [1, 2^FEED_W] (2^FEED_W when
// clocks <= 0).
uint32_t feed_word(uint64_t operations, double clocks, int feed_w);

class MotionCompiler {
 public:
  using ReportSink = std::function<void(const MoveReport&)>;

  // `name` names the program in error messages; `source` must outlive the
  // compiler. `sink` (optional) gets each move's report once all its
  // commands have been returned: during the next() call that goes past the
  // move (the one that returns the next move's first command, or false at
  // the end of the program).
  MotionCompiler(MoveSource& source, const Machine& machine, const MotionWidths& widths,
                 FeedMode mode, std::string name, ReportSink sink = {},
                 const CompilerOptions& options = {});
  ~MotionCompiler();
  MotionCompiler(const MotionCompiler&) = delete;
  MotionCompiler& operator=(const MotionCompiler&) = delete;

  // The next command; false at the end of the program. Throws
  // cli::UsageError on bad input (the readers' and the compiler's own).
  bool next(models::MotionCommand& command);
  const CommandInfo& info() const { return info_; }
  const CompileTotals& totals() const { return totals_; }
  // The lattice point the commands so far lead to.
  const std::array<int64_t, 6>& position() const { return at_; }
  // The move the last command belongs to, and where its programmed path
  // starts (the previous move's programmed end; 0 before the first).
  const Move& move() const { return move_; }
  const std::array<double, 6>& move_start() const { return move_start_; }
  const Machine& machine() const { return machine_; }
  const MotionWidths& widths() const { return widths_; }

 private:
  struct Plan;
  void plan_move();
  bool make_command(models::MotionCommand& c);
  void finish_move();
  [[noreturn]] void fail(const std::string& what) const;

  MoveSource& source_;
  Machine machine_;
  MotionWidths widths_;
  FeedMode mode_;
  CompilerOptions options_;
  std::string name_;
  ReportSink sink_;
  Move move_;
  std::array<double, 6> move_start_{};
  std::array<double, 6> prev_end_{};
  std::array<int64_t, 6> at_{};
  FeedClock full_clock_, programmed_clock_;
  std::unique_ptr<Plan> plan_;  // the move being compiled
  MoveReport report_;
  CommandInfo info_;
  CompileTotals totals_;
  uint64_t moves_ = 0;
};

}  // namespace hwinterp::gcode

// The common output of the 2-axis fine interpolators compared in paper
// 004_dc68f1177cad466f.txt (fixed ratio, PPC, DDA, minimum deviation,
// Bresenham): the sequence of moves on the step lattice, when they happen, and
// how much work the method did. A move steps one or both axes at the same
// instant; the lattice point after it is what the path-error metric of
// models/lattice_path.h measures.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "models/dda_line_model.h"
#include "models/lattice_path.h"

namespace hwinterp::models {

struct StepMove {
  double time = 0;            // when the move happens, in the path's ticks
  std::array<int, 2> step{};  // -1, 0, +1 per axis
  LatticePoint point;         // lattice point after the move
};

struct StepPath {
  LatticePoint start, end;  // the commanded line (or arc) end points
  std::vector<StepMove> moves;
  double ticks = 0;         // completion time (docs/papers.md, paper 004: the tick of each method)
  uint64_t operations = 0;  // interpolation computations the method needs

  // Pulses sent per axis (sum of |step|).
  std::array<uint64_t, 2> pulses() const;
  // Start followed by the point after every move.
  std::vector<LatticePoint> visited() const;
  const LatticePoint& last_point() const { return moves.empty() ? start : moves.back().point; }
  bool ends_on_end() const { return last_point() == end; }
  // Normal distance of the visited points from the ideal line start -> end.
  PathError line_error() const;
};

// Every move is stored (about 70 bytes each): a path of more steps than this
// is refused rather than exhausting memory.
inline constexpr uint64_t kMaxStepMoves = uint64_t{1} << 24;

// Validates a 2-axis lattice line (coordinates within 2^28, at most
// kMaxStepMoves steps); throws std::invalid_argument otherwise.
void check_line_2d(const LatticePoint& start, const LatticePoint& end, const char* who);
// Throws std::invalid_argument when `moves` exceeds kMaxStepMoves.
void check_move_count(uint64_t moves, const char* who);

// The DDA reference (models/dda_line_model.h) in this form, for the 004
// comparison: one tick per DDA iteration, 2^n ticks, one addition per
// iteration and axis counted as one operation per iteration.
StepPath dda_step_path(const LatticePoint& start, const LatticePoint& end, Preload preload);

}  // namespace hwinterp::models

// The program's reach, checked before anything runs: every move's
// programmed path against the machine's travel (tb/gcode/machine.h), and
// every lattice point it leads to against the core's position counters
// (POS_W bits, signed: |p| <= 2^(POS_W-1) - 1 steps). A program that leaves
// either exits 2 naming the file, the line, the axis and the coordinate,
// instead of simulating for minutes towards a point the machine cannot reach
// (a G1 X100000000 at 1000 steps/mm is 10^11 steps).
//
// The reach of a move, per axis, is the interval its programmed path sweeps:
//   - lines (G0, G1): the interval between its start and end (a line is
//     straight in every axis);
//   - arcs (G2, G3, tb/gcode/helix.h): the start, the end, and the spiral's
//     point at every angle the sweep crosses where its direction from the
//     centre is an axis direction (0, 90, 180, 270 degrees): the circle's
//     extremes; for a spiral (start and end radius differ) the extreme lies
//     within |r2 - r1| * (90 degrees / sweep) of that point, which a travel
//     check at the programmed coordinate resolution does not need; the
//     helix axis and A B C are linear in the angle.
// Positions in steps are the reach rounded to the lattice (llround(p *
// steps_per_unit), as the compiler rounds), widened by 1 step on the arc's
// plane axes (the arc engine stays within a step of its circle).
//
// Streaming as the readers are: one move at a time, O(1) memory.
#pragma once

#include <array>
#include <string>

#include "tb/gcode/machine.h"
#include "tb/gcode/move.h"

namespace hwinterp::gcode {

// The interval each axis sweeps on a move from `start` (absolute, mm/deg).
struct Reach {
  std::array<double, kAxes> lo{}, hi{};
};
Reach move_reach(const std::array<double, kAxes>& start, const Move& move);

// Reads `source` to its end and throws cli::UsageError ("NAME:LINE: ...")
// at the first move whose reach leaves the machine's travel or the signed
// `pos_w`-bit position counters (`core` names them in the message). Returns
// the number of moves checked.
uint64_t check_reach(MoveSource& source, const Machine& machine, int pos_w, const std::string& core,
                     const std::string& name);

}  // namespace hwinterp::gcode

#include "models/step_path.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace hwinterp::models {

std::array<uint64_t, 2> StepPath::pulses() const {
  std::array<uint64_t, 2> n{0, 0};
  for (const auto& m : moves)
    for (size_t i = 0; i < 2; ++i) n[i] += static_cast<uint64_t>(std::abs(m.step[i]));
  return n;
}

std::vector<LatticePoint> StepPath::visited() const {
  std::vector<LatticePoint> v;
  v.reserve(moves.size() + 1);
  v.push_back(start);
  for (const auto& m : moves) v.push_back(m.point);
  return v;
}

PathError StepPath::line_error() const { return max_line_error(visited(), start, end); }

void check_line_2d(const LatticePoint& start, const LatticePoint& end, const char* who) {
  if (start.size() != 2 || end.size() != 2)
    throw std::invalid_argument(std::string(who) + ": start and end must have 2 axes");
  // Keeps every product of coordinates (deviation functions, time
  // comparisons) far inside 64 bits.
  constexpr int64_t kLimit = int64_t{1} << 28;
  int64_t travel = 0;
  for (size_t i = 0; i < 2; ++i) {
    const int64_t d = end[i] - start[i];
    if (std::abs(start[i]) > kLimit || std::abs(end[i]) > kLimit || std::abs(d) > kLimit)
      throw std::invalid_argument(std::string(who) + ": coordinate beyond 2^28 steps on axis " +
                                  std::to_string(i));
    travel += std::abs(d);
  }
  check_move_count(static_cast<uint64_t>(travel), who);
}

void check_move_count(uint64_t moves, const char* who) {
  if (moves > kMaxStepMoves)
    throw std::invalid_argument(std::string(who) + ": " + std::to_string(moves) +
                                " steps exceed the reference model's limit of " +
                                std::to_string(kMaxStepMoves) + " stored moves");
}

StepPath dda_step_path(const LatticePoint& start, const LatticePoint& end, Preload preload) {
  check_line_2d(start, end, "dda_step_path");
  const std::vector<int64_t> delta{end[0] - start[0], end[1] - start[1]};
  StepPath path;
  path.start = start;
  path.end = end;
  for (const DdaMove& m : dda_line_moves(start, delta, preload))
    path.moves.push_back(
        StepMove{static_cast<double>(m.iteration), {m.step[0], m.step[1]}, m.point});
  path.ticks = static_cast<double>(dda_iterations(delta));
  path.operations = dda_iterations(delta);
  return path;
}

}  // namespace hwinterp::models

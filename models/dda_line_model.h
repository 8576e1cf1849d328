// Reference model of the `dda_line` core: the mathematics the HLS and RTL
// faces are checked against. Independent of their bit-level tricks (shifted
// increments, carry outs): it states the DDA directly.
//
// A command moves by `delta` (signed steps per axis). Let M = max_i |delta_i|
// and n the bit length of M (the smallest n with M < 2^n). The DDA runs 2^n
// iterations; after k of them axis i has taken
//     floor(k |delta_i| / 2^n + p)   steps,  p = 0 (plain) or 1/2 (half preload),
// in the direction of sign(delta_i). Exactly |delta_i| steps after 2^n
// iterations, so the end point is exact. Every axis that steps in iteration k
// steps at the same time (one "move").
//
// Path-error bounds (normal distance from the ideal line, in steps) for a core
// with N axes, from the per-axis lag e_i = steps_i(k) - k delta_i / 2^n:
//   plain: e_i in (-1, 0]      ->  error < sqrt(N - 1)   (< 1 for N = 2)
//   half : e_i in (-1/2, 1/2]  ->  error <= sqrt(N) / 2  (0.7071 for N = 2)
#pragma once

#include <cstdint>
#include <vector>

#include "models/error_bound.h"
#include "models/lattice_path.h"

namespace hwinterp::models {

enum class Preload { kZero, kHalf };

// Bit length of max |delta_i| (0 for an all-zero delta).
int dda_exponent(const std::vector<int64_t>& delta);

// Iterations the DDA runs for `delta`: 2^dda_exponent(delta).
uint64_t dda_iterations(const std::vector<int64_t>& delta);

// Steps axis `i` has taken after `k` iterations (magnitude; direction = sign of delta).
uint64_t dda_steps_after(int64_t delta_i, int exponent, uint64_t k, Preload preload);

// One DDA iteration that issued at least one step: per-axis step (-1, 0, +1)
// and the lattice point reached.
struct DdaMove {
  uint64_t iteration;  // 1-based iteration index k in [1, 2^n]
  std::vector<int> step;
  LatticePoint point;
};

// The moves of one command, one at a time: what the testbench scoreboard
// compares the cores' step/dir outputs against without storing a whole line.
class DdaMoveStream {
 public:
  DdaMoveStream(LatticePoint start, std::vector<int64_t> delta, Preload preload);
  // The next move; false when the command has no more.
  bool next(DdaMove& move);
  const std::vector<int64_t>& delta() const { return delta_; }
  Preload preload() const { return preload_; }

 private:
  std::vector<int64_t> delta_;
  Preload preload_;
  int exponent_;
  uint64_t iterations_;
  uint64_t k_ = 0;
  std::vector<uint64_t> taken_;
  LatticePoint at_;
};

// All moves of one command from `start`, in order.
std::vector<DdaMove> dda_line_moves(const LatticePoint& start, const std::vector<int64_t>& delta,
                                    Preload preload);

// The documented bound on the normal path error for a core with `axes` axes.
ErrorBound dda_error_bound(int axes, Preload preload);

}  // namespace hwinterp::models

// Reference model of the `fixed_ratio` core (rtl/fixed_ratio.sv,
// hls/fixed_ratio.h): the fixed-ratio (velocity-synthesis) generator of paper
// 004_dc68f1177cad466f.txt at the core's own widths, bit-exact with the
// hardware's integer arithmetic (rate words, phases, pulse counters). The
// exact-frequency and integer-divider generators of the paper's analysis are
// models/fixed_ratio.h.
//
// A command moves by `delta` (signed steps per axis, N axes). With
// M = max_i |delta_i| and F = FRAC_W:
//   rate word   R_i = ceil(|delta_i| 2^F / M)          (R_i = 2^F: the major axis)
//   after k engine ticks axis i has stepped
//               s_i(k) = min(|delta_i|, floor((2^(F-1) + k R_i) / 2^F))
//   (a phase accumulator started at one half: the paper's mid-period edge,
//   Eqs. 9/10, position = round(v_i t)), in the direction of sign(delta_i);
//   the axes that step on one tick make one move. The command completes
//   when every axis has sent its |delta_i| pulses; a zero-length command
//   takes one tick with no step.
//
// Exact counts in M ticks. Write R_i / 2^F = r_i + e_i, r_i = |delta_i| / M,
// 0 <= e_i < 2^-F (rounding up). Then k R_i / 2^F + 1/2 = k r_i + k e_i + 1/2
// and at k = M: floor(|delta_i| + M e_i + 1/2) >= |delta_i| for any F (no
// axis can lag: every counter is at 0 by tick M), and = |delta_i| when
// M e_i < 1/2, which holds for every M <= 2^(ACC_W-1) the widths accept when
// F >= ACC_W (M e_i < M 2^-F <= 1/2). s_i is nondecreasing, so no axis
// overshoots before tick M and none lags after it: the min() never binds
// (the pulse counters never act), the major axis (r = 1, e = 0) steps on
// every tick, and the command completes in exactly max(M, 1) ticks
// (fixed_ratio_ticks).
//
// Equal to the exact-frequency generator. With exact rates the model gives
// s_i(k) = floor(k r_i + 1/2) = round(|delta_i| k / M): the paper's generator
// (models::fixed_ratio_line) sampled at the tick instants, i.e. its moves
// merged over each tick interval ((k-1)/M, k/M] of the line's time. Rounding
// up leaves every s_i(k) unchanged when k e_i < 1/(2M) for k <= M (the
// fractional part of k r_i + 1/2 is a multiple of 1/(2M), at most
// 1 - 1/(2M)), i.e. whenever 2 M^2 <= 2^F: every line up to M = 2^((F-1)/2)
// steps (131 072 at F = 35, 90 at F = 14). Rounding to nearest would not do:
// where k r_i + 1/2 is an integer (a step due exactly on a tick, e.g.
// (6, 5) at tick 3) a rate rounded down moves the step one tick later (96 of
// the 2-axis lines up to 40 steps per axis differ at any F).
//
// Error bound (normal distance of a visited point from the ideal line, in
// steps). The point after tick k is k d/M + lag, k d / M on the line, with
// lag_i = s_i(k) - k r_i = (s_i - k r_i - k e_i) + k e_i in
// (-1/2, 1/2 + M e_i] for a minor axis (0 < |delta_i| < M), and 0 for the
// major and zero axes. The distance is the lag's component normal to the
// line, |lag|^2 - (lag . u)^2 with u = |d| / L: convex in the lag, so its
// maximum over that box is at a vertex (lag_i = -1/2 or 1/2 + M e_i);
// fixed_ratio_hw_bound() evaluates every vertex. Closed forms:
//   2 axes: error <= (M / L) (1/2 + M e)
//                 <= (|dx| + |dy|) / (2 L) + M^2 2^-F / L   (the paper's term
//                    plus the rounding term; M/L <= 1, so <= 1/2 + M 2^-F)
//   N axes: error <= sqrt(N - 1) (1/2 + M 2^-F)
//                 <= sqrt(N - 1) (1/2 + 2^(ACC_W-1-F))       (fixed_ratio_hw_worst_bound)
// At F = ACC_W + 3 the rounding term is <= 1/16 and the bound stays below 1
// step for every line the widths accept up to 4 axes (0.5625 for 2 axes,
// 0.795 for 3, 0.974 for 4).
#pragma once

#include <cstdint>
#include <vector>

#include "models/error_bound.h"
#include "models/lattice_path.h"

namespace hwinterp::models {

// M = max |delta_i| (0 for an all-zero delta).
uint64_t fixed_ratio_major(const std::vector<int64_t>& delta);

// The rate word of an axis: ceil(mag 2^frac_w / major); 0 when major is 0.
// Throws std::invalid_argument when mag > major or frac_w is outside [1, 62].
uint64_t fixed_ratio_rate(uint64_t mag, uint64_t major, int frac_w);

// Engine ticks of a command: max(M, 1).
uint64_t fixed_ratio_ticks(const std::vector<int64_t>& delta);

// Steps an axis with rate word `rate` has taken after `k` ticks, before the
// pulse counter's limit: floor((2^(frac_w-1) + k rate) / 2^frac_w).
uint64_t fixed_ratio_phase_steps(uint64_t rate, int frac_w, uint64_t k);

// Steps an axis takes after `k` ticks with exact rates: floor(k |d| / M + 1/2).
uint64_t fixed_ratio_exact_steps(uint64_t mag, uint64_t major, uint64_t k);

// One engine tick that issued at least one step: per-axis step (-1, 0, +1)
// and the lattice point reached.
struct FixedRatioMove {
  uint64_t tick;  // 1-based tick index k
  std::vector<int> step;
  LatticePoint point;
};

// The moves of one command, one at a time, from the hardware's integer
// arithmetic (phase accumulators, rate words, pulse counters).
class FixedRatioMoveStream {
 public:
  // Throws std::invalid_argument for a start/delta axis mismatch, a frac_w
  // outside [1, 62], or a delta beyond +-2^62.
  FixedRatioMoveStream(LatticePoint start, std::vector<int64_t> delta, int frac_w);
  // The next move; false when the command has no more.
  bool next(FixedRatioMove& move);
  const std::vector<int64_t>& delta() const { return delta_; }
  const std::vector<uint64_t>& rates() const { return rate_; }
  uint64_t major() const { return major_; }
  // Ticks run so far; after the last move, the command's ticks.
  uint64_t ticks() const { return k_; }
  bool finished() const;

 private:
  std::vector<int64_t> delta_;
  int frac_w_;
  uint64_t major_;
  std::vector<uint64_t> rate_, phase_, left_;
  uint64_t k_ = 0;
  bool zero_done_ = false;
  LatticePoint at_;
};

// All moves of one command from `start`, in order.
std::vector<FixedRatioMove> fixed_ratio_hw_moves(const LatticePoint& start,
                                                 const std::vector<int64_t>& delta, int frac_w);

// The per-command bound on the normal path error (the maximum over the lag
// box's vertices, with the command's own rounding errors e_i); attained or
// not, it is checked as <= (strict = false).
ErrorBound fixed_ratio_hw_bound(const std::vector<int64_t>& delta, int frac_w);

// The bound for every command a core with `axes` axes, ACC_W-bit deltas and
// FRAC_W fraction bits accepts: sqrt(axes - 1) (1/2 + 2^(acc_w - 1 - frac_w)).
double fixed_ratio_hw_worst_bound(int axes, int acc_w, int frac_w);

}  // namespace hwinterp::models

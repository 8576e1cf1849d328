#include "models/dda_line_model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace hwinterp::models {

namespace {
uint64_t magnitude(int64_t v) {
  return v < 0 ? uint64_t{0} - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
}
}  // namespace

int dda_exponent(const std::vector<int64_t>& delta) {
  uint64_t m = 0;
  for (const int64_t d : delta) m = std::max(m, magnitude(d));
  int n = 0;
  while (n < 64 && (m >> n) != 0) ++n;
  return n;
}

uint64_t dda_iterations(const std::vector<int64_t>& delta) {
  const int n = dda_exponent(delta);
  if (n > 62) throw std::out_of_range("dda_iterations: delta too large for the model");
  return uint64_t{1} << n;
}

uint64_t dda_steps_after(int64_t delta_i, int exponent, uint64_t k, Preload preload) {
  // floor((k |d| + p 2^n) / 2^n) in 128-bit integers: exact for every width.
  const unsigned __int128 num = static_cast<unsigned __int128>(k) * magnitude(delta_i) +
                                (preload == Preload::kHalf && exponent > 0
                                     ? (static_cast<unsigned __int128>(1) << (exponent - 1))
                                     : 0);
  return static_cast<uint64_t>(num >> exponent);
}

std::vector<DdaMove> dda_line_moves(const LatticePoint& start, const std::vector<int64_t>& delta,
                                    Preload preload) {
  if (start.size() != delta.size())
    throw std::invalid_argument("dda_line_moves: start and delta have different axis counts");
  const int n = dda_exponent(delta);
  const uint64_t iterations = dda_iterations(delta);
  std::vector<DdaMove> moves;
  std::vector<uint64_t> taken(delta.size(), 0);
  LatticePoint at = start;
  for (uint64_t k = 1; k <= iterations; ++k) {
    DdaMove m{k, std::vector<int>(delta.size(), 0), {}};
    bool any = false;
    for (size_t i = 0; i < delta.size(); ++i) {
      const uint64_t s = dda_steps_after(delta[i], n, k, preload);
      if (s != taken[i]) {  // at most one step per axis and iteration: |d_i| < 2^n
        taken[i] = s;
        m.step[i] = delta[i] < 0 ? -1 : 1;
        at[i] += m.step[i];
        any = true;
      }
    }
    if (any) {
      m.point = at;
      moves.push_back(std::move(m));
    }
  }
  return moves;
}

ErrorBound dda_error_bound(int axes, Preload preload) {
  if (axes < 1) throw std::invalid_argument("dda_error_bound: axes must be >= 1");
  if (preload == Preload::kHalf) return {std::sqrt(static_cast<double>(axes)) / 2, false};
  return {std::sqrt(static_cast<double>(axes - 1)), true};
}

bool within_bound(double error, ErrorBound bound) {
  return bound.strict ? error < bound.value + 1e-12 : error <= bound.value + 1e-12;
}

}  // namespace hwinterp::models

#include "models/dda_line_model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "models/common.h"

namespace hwinterp::models {

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

DdaMoveStream::DdaMoveStream(LatticePoint start, std::vector<int64_t> delta, Preload preload)
    : delta_(std::move(delta)),
      preload_(preload),
      exponent_(dda_exponent(delta_)),
      iterations_(dda_iterations(delta_)),
      taken_(delta_.size(), 0),
      at_(std::move(start)) {
  if (at_.size() != delta_.size())
    throw std::invalid_argument("DdaMoveStream: start and delta have different axis counts");
}

bool DdaMoveStream::next(DdaMove& move) {
  while (k_ < iterations_) {
    ++k_;
    bool any = false;
    move.step.assign(delta_.size(), 0);
    for (size_t i = 0; i < delta_.size(); ++i) {
      const uint64_t s = dda_steps_after(delta_[i], exponent_, k_, preload_);
      if (s != taken_[i]) {  // at most one step per axis and iteration: |d_i| < 2^n
        taken_[i] = s;
        move.step[i] = delta_[i] < 0 ? -1 : 1;
        at_[i] += move.step[i];
        any = true;
      }
    }
    if (any) {
      move.iteration = k_;
      move.point = at_;
      return true;
    }
  }
  return false;
}

std::vector<DdaMove> dda_line_moves(const LatticePoint& start, const std::vector<int64_t>& delta,
                                    Preload preload) {
  DdaMoveStream stream(start, delta, preload);
  std::vector<DdaMove> moves;
  DdaMove m;
  while (stream.next(m)) moves.push_back(m);
  return moves;
}

ErrorBound dda_error_bound(int axes, Preload preload) {
  if (axes < 1) throw std::invalid_argument("dda_error_bound: axes must be >= 1");
  if (preload == Preload::kHalf) return {std::sqrt(static_cast<double>(axes)) / 2, false};
  return {std::sqrt(static_cast<double>(axes - 1)), true};
}

}  // namespace hwinterp::models

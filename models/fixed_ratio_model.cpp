#include "models/fixed_ratio_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "models/common.h"

namespace hwinterp::models {

namespace {

using u128 = unsigned __int128;

void check_frac_w(int frac_w, const char* who) {
  if (frac_w < 1 || frac_w > 62)
    throw std::invalid_argument(std::string(who) + ": frac_w " + std::to_string(frac_w) +
                                " is outside [1, 62]");
}

}  // namespace

uint64_t fixed_ratio_major(const std::vector<int64_t>& delta) {
  uint64_t m = 0;
  for (const int64_t d : delta) m = std::max(m, magnitude(d));
  return m;
}

uint64_t fixed_ratio_rate(uint64_t mag, uint64_t major, int frac_w) {
  check_frac_w(frac_w, "fixed_ratio_rate");
  if (mag > major)
    throw std::invalid_argument("fixed_ratio_rate: |delta| " + std::to_string(mag) +
                                " exceeds the major delta " + std::to_string(major));
  if (major == 0) return 0;
  if (major > (uint64_t{1} << 62))
    throw std::invalid_argument("fixed_ratio_rate: delta beyond 2^62");
  // What the restoring divider and the round-up at the load compute.
  const u128 num = (static_cast<u128>(mag) << frac_w) + (major - 1);
  return static_cast<uint64_t>(num / major);
}

uint64_t fixed_ratio_ticks(const std::vector<int64_t>& delta) {
  return std::max<uint64_t>(fixed_ratio_major(delta), 1);
}

uint64_t fixed_ratio_phase_steps(uint64_t rate, int frac_w, uint64_t k) {
  check_frac_w(frac_w, "fixed_ratio_phase_steps");
  const u128 v = (static_cast<u128>(1) << (frac_w - 1)) + static_cast<u128>(k) * rate;
  return static_cast<uint64_t>(v >> frac_w);
}

uint64_t fixed_ratio_exact_steps(uint64_t mag, uint64_t major, uint64_t k) {
  if (major == 0) return 0;
  // floor((2 k |d| + M) / (2 M)) in 128-bit integers.
  const u128 num = 2 * static_cast<u128>(k) * mag + major;
  return static_cast<uint64_t>(num / (2 * static_cast<u128>(major)));
}

FixedRatioMoveStream::FixedRatioMoveStream(LatticePoint start, std::vector<int64_t> delta,
                                           int frac_w)
    : delta_(std::move(delta)),
      frac_w_(frac_w),
      major_(fixed_ratio_major(delta_)),
      at_(std::move(start)) {
  check_frac_w(frac_w, "FixedRatioMoveStream");
  if (at_.size() != delta_.size())
    throw std::invalid_argument("FixedRatioMoveStream: start and delta have different axis counts");
  for (const int64_t d : delta_) {
    rate_.push_back(fixed_ratio_rate(magnitude(d), major_, frac_w_));
    phase_.push_back(uint64_t{1} << (frac_w_ - 1));  // one half
    left_.push_back(magnitude(d));
  }
}

bool FixedRatioMoveStream::finished() const {
  if (major_ == 0) return zero_done_;
  return std::all_of(left_.begin(), left_.end(), [](uint64_t n) { return n == 0; });
}

bool FixedRatioMoveStream::next(FixedRatioMove& move) {
  if (major_ == 0) {  // one tick, no step
    if (!zero_done_) {
      zero_done_ = true;
      k_ = 1;
    }
    return false;
  }
  const uint64_t mask = (uint64_t{1} << frac_w_) - 1;
  while (!finished()) {
    ++k_;
    bool any = false;
    move.step.assign(delta_.size(), 0);
    for (size_t i = 0; i < delta_.size(); ++i) {
      // phase + rate < 2^(frac_w + 1) <= 2^63: no overflow.
      const uint64_t sum = phase_[i] + rate_[i];
      phase_[i] = sum & mask;
      if ((sum >> frac_w_) != 0 && left_[i] != 0) {  // carry, and the counter lets it out
        --left_[i];
        move.step[i] = delta_[i] < 0 ? -1 : 1;
        at_[i] += move.step[i];
        any = true;
      }
    }
    if (any) {
      move.tick = k_;
      move.point = at_;
      return true;
    }
  }
  return false;
}

std::vector<FixedRatioMove> fixed_ratio_hw_moves(const LatticePoint& start,
                                                 const std::vector<int64_t>& delta, int frac_w) {
  FixedRatioMoveStream stream(start, delta, frac_w);
  std::vector<FixedRatioMove> moves;
  FixedRatioMove m;
  while (stream.next(m)) moves.push_back(m);
  return moves;
}

ErrorBound fixed_ratio_hw_bound(const std::vector<int64_t>& delta, int frac_w) {
  check_frac_w(frac_w, "fixed_ratio_hw_bound");
  const uint64_t major = fixed_ratio_major(delta);
  long double len2 = 0;
  for (const int64_t d : delta) len2 += static_cast<long double>(d) * static_cast<long double>(d);
  // The lag box of the minor axes: [-1/2, 1/2 + M e_i], in magnitude
  // coordinates (each axis mirrored to positive), with u_i = |d_i| / L.
  std::vector<long double> lo, hi, u;
  for (const int64_t d : delta) {
    const uint64_t mag = magnitude(d);
    if (mag == 0 || mag == major) continue;  // no lag: always on its exact count
    const uint64_t rate = fixed_ratio_rate(mag, major, frac_w);
    // M e_i = (R_i M - |d_i| 2^F) / 2^F, the numerator exact in 128 bits (< M).
    const u128 over = static_cast<u128>(rate) * major - (static_cast<u128>(mag) << frac_w);
    const long double me = std::ldexp(static_cast<long double>(over), -frac_w);
    lo.push_back(-0.5L);
    hi.push_back(0.5L + me);
    u.push_back(static_cast<long double>(mag) / std::sqrt(len2));
  }
  if (lo.empty()) return {0, false};
  const size_t n = lo.size();
  long double best = 0;
  if (n > 20) {  // too many vertices: the sphere around the box
    for (size_t i = 0; i < n; ++i) best += std::max(lo[i] * lo[i], hi[i] * hi[i]);
  } else {
    for (uint64_t mask = 0; mask < (uint64_t{1} << n); ++mask) {
      long double norm2 = 0, along = 0;
      for (size_t i = 0; i < n; ++i) {
        const long double v = (mask >> i) & 1 ? hi[i] : lo[i];
        norm2 += v * v;
        along += v * u[i];
      }
      best = std::max(best, norm2 - along * along);
    }
  }
  return {static_cast<double>(std::sqrt(std::max(best, 0.0L))), false};
}

double fixed_ratio_hw_worst_bound(int axes, int acc_w, int frac_w) {
  if (axes < 1) throw std::invalid_argument("fixed_ratio_hw_worst_bound: axes must be >= 1");
  check_frac_w(frac_w, "fixed_ratio_hw_worst_bound");
  return std::sqrt(static_cast<double>(axes - 1)) * (0.5 + std::ldexp(1.0, acc_w - 1 - frac_w));
}

}  // namespace hwinterp::models

// Bit-exact model of the log_stepper core's coarse engine (rtl/log_stepper.sv,
// hls/log_stepper.h): the odd-even third-order log-curve points of
// models/log_curve.h computed in unsigned fixed point, and the lattice
// positions the core streams to its fine stage. The double-precision model
// (models/log_curve.h) is what this one states its error against.
//
// Format: every word is an unsigned fixed-point number with INT_W integer and
// FRAC_W fraction bits (W = INT_W + FRAC_W <= 62). The operations, exactly as
// the hardware does them:
//   mul(x, y)   = floor(x y / 2^F)                      (truncating product)
//   sqrt(x)     = floor(sqrt(x 2^F))                    (x >= 1.0)
//   recip(x)    = floor(2^2F / x)                       (x >= 1.0)
//   rsb(x, s)   = 3.0 - (x << s)                        (never below 0, see below)
//   pos(x, k)   = floor((x k + 2^(2F-17)) / 2^(2F-16))  (lattice position,
//                                                        rounded to nearest)
// The curve is normalised by a: with d' = dA10 / a = b dl / sqrt(q^2 + (ab)^2),
// Eq. 14's and Eq. 15's denominators are both a^3 D and a^2 D with
// D = 3 - 2 d' s2 (3 - 4 d'), so one reciprocal serves both even-step ratios:
//   q = 1 + b X0, u = 1 / sqrt(q^2 + ab^2), dX10 = dl (q u), dA10 = dl (ab u),
//   s2 = (ab u)^2, d' = (b dl) u, e = d' s2,
//   D = 3 - 2 e (3 - 4d'), N15 = 3 - 2 d' (3 - 4d'), N14 = 3 - 2 (d' e)(3 - 8d'),
//   dX21 = (N14 / D) dX10, dA21 = (N15 / D) dA10.
// X and A are running sums of their increments (only X feeds back, as in the
// paper); Y and Z are not computed: their lattice positions are X's times
// their own scale (tan C and tan C sin r folded into k1 and k2).
//
// Command words (the host computes them): b, ab, dl and x_end in the format,
// and per axis k_i = steps per unit / 2^16 (X, Y, Z per mm of X, A per rad).
// Accepted commands (log_stepper_check): every word fits, d' < 3/8 at X = 0
// (so 3 - 8d' > 0 and every rsb stays positive: D >= 15/8), the curve stays
// inside the format (q^2 + ab^2 < 2^INT_W) and every segment's delta fits the
// fine stage's SEG_W-bit signed deltas.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "models/log_curve.h"

namespace hwinterp::models {

struct LogFixedFormat {
  int int_w = 10;   // integer bits
  int frac_w = 30;  // fraction bits F
  int width() const { return int_w + frac_w; }
  uint64_t one() const { return uint64_t{1} << frac_w; }
  uint64_t max_word() const { return (uint64_t{1} << width()) - 1; }
};

// The scale of the k words: k = steps per unit / 2^kLogPosShift.
inline constexpr int kLogPosShift = 16;

struct LogFixedCommand {
  uint64_t b = 0, ab = 0, dl = 0, x_end = 0;  // fixed-point words
  std::array<uint64_t, 4> k{};                // X, Y, Z (per mm of X), A (per rad)
};

// Steps per unit of each axis, as the user gives them.
struct LogStepScale {
  double x_per_mm = 1000, y_per_mm = 1000, z_per_mm = 1000;
  double a_per_deg = 1000;
};

// The command words for a curve: fixed-point b, ab, dl and x_end (rounded to
// nearest) and k0 = steps/mm X, k1 = tan C steps/mm Y, k2 = tan C sin r
// steps/mm Z, k3 = steps/deg A * 180/pi, each / 2^16.
LogFixedCommand log_fixed_command(const LogCurveParams& p, const LogStepScale& s,
                                  const LogFixedFormat& f);

// The fixed-point primitives (x, y words of format f).
uint64_t log_mul(uint64_t x, uint64_t y, const LogFixedFormat& f);
uint64_t log_sqrt(uint64_t x, const LogFixedFormat& f);
uint64_t log_recip(uint64_t x, const LogFixedFormat& f);
int64_t log_pos(uint64_t x, uint64_t k, const LogFixedFormat& f);

// One coarse point: the fixed-point X and A words and the four lattice
// positions (relative to the curve's start).
struct LogFixedPoint {
  size_t index = 0;  // 1 = first point (odd), as LogPoint::index
  uint64_t x = 0, a = 0;
  std::array<int64_t, 4> pos{};
};

// The points of one command, one at a time (a small copyable value). The
// run makes whole odd+even cycles until an even point has X >= x_end, the
// paper's stop rule (models/log_curve.h).
class LogFixedStream {
 public:
  LogFixedStream(const LogFixedCommand& c, const LogFixedFormat& f) : c_(c), f_(f) {}
  bool next(LogFixedPoint& p);
  // d' at X = 0, the largest it gets, as a word; the command is refused from 3/8 on.
  static uint64_t d_prime_at_start(const LogFixedCommand& c, const LogFixedFormat& f);

 private:
  void cycle();
  LogFixedCommand c_;
  LogFixedFormat f_;
  uint64_t x_ = 0, a_ = 0;
  uint64_t dx21_ = 0, da21_ = 0;  // the even step, computed with the odd one
  size_t index_ = 0;
  bool done_ = false;
};

// Why a command cannot run on a core of format f with SEG_W-bit segments and
// positions below 2^(pos_w-1), or "" when it can. Runs the stream (cheap: up
// to kLogMaxPoints points).
std::string log_fixed_check(const LogFixedCommand& c, const LogFixedFormat& f, int seg_w,
                            int pos_w);

// Lattice position of a double-model point (models/log_curve.h), rounded to
// nearest, with the scale the command words were made from.
std::array<int64_t, 4> log_lattice(const LogPoint& p, const LogCurveParams& params,
                                   const LogStepScale& s);

}  // namespace hwinterp::models

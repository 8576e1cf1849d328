#include "models/log_stepper_model.h"

#include <algorithm>
#include <cmath>

#include "models/common.h"

namespace hwinterp::models {

namespace {

using u128 = unsigned __int128;

uint64_t word(double v, const LogFixedFormat& f) {
  return static_cast<uint64_t>(std::llround(std::ldexp(v, f.frac_w)));
}

// 3.0 - (x << s); the accepted commands keep it positive (header).
uint64_t rsb(uint64_t x, int s, const LogFixedFormat& f) { return 3 * f.one() - (x << s); }

}  // namespace

LogFixedCommand log_fixed_command(const LogCurveParams& p, const LogStepScale& s,
                                  const LogFixedFormat& f) {
  const double a = log_a(p), b = log_b(p);
  const double tc = std::tan(p.cone_deg * kPi / 180), sr = std::sin(p.rake_deg * kPi / 180);
  const double scale = std::ldexp(1.0, -kLogPosShift);
  LogFixedCommand c;
  c.b = word(b, f);
  c.ab = word(a * b, f);
  c.dl = word(p.dl_mm, f);
  c.x_end = word(p.x_end_mm, f);
  c.k = {word(s.x_per_mm * scale, f), word(tc * s.y_per_mm * scale, f),
         word(tc * sr * s.z_per_mm * scale, f), word(s.a_per_deg * 180 / kPi * scale, f)};
  return c;
}

uint64_t log_mul(uint64_t x, uint64_t y, const LogFixedFormat& f) {
  return static_cast<uint64_t>((u128{x} * y) >> f.frac_w) & f.max_word();
}

uint64_t log_sqrt(uint64_t x, const LogFixedFormat& f) {
  // floor(sqrt(n)) of n = x 2^F, by the digit recurrence the hardware runs.
  const u128 n = u128{x} << f.frac_w;
  const int digits = (f.width() + f.frac_w + 1) / 2;
  u128 rem = 0, root = 0;
  for (int i = digits - 1; i >= 0; --i) {
    rem = (rem << 2) | ((n >> (2 * i)) & 3);
    const u128 trial = (root << 2) | 1;
    if (rem >= trial) {
      rem -= trial;
      root = (root << 1) | 1;
    } else {
      root <<= 1;
    }
  }
  return static_cast<uint64_t>(root);
}

uint64_t log_recip(uint64_t x, const LogFixedFormat& f) {
  return static_cast<uint64_t>((u128{1} << (2 * f.frac_w)) / x);
}

int64_t log_pos(uint64_t x, uint64_t k, const LogFixedFormat& f) {
  const int sh = 2 * f.frac_w - kLogPosShift;
  return static_cast<int64_t>((u128{x} * k + (u128{1} << (sh - 1))) >> sh);
}

uint64_t LogFixedStream::d_prime_at_start(const LogFixedCommand& c, const LogFixedFormat& f) {
  const uint64_t root = log_sqrt(f.one() + log_mul(c.ab, c.ab, f), f);
  return log_mul(log_mul(c.b, c.dl, f), log_recip(root, f), f);
}

void LogFixedStream::cycle() {
  const LogFixedFormat& f = f_;
  const uint64_t q = log_mul(c_.b, x_, f) + f.one();
  const uint64_t u = log_recip(log_sqrt(log_mul(q, q, f) + log_mul(c_.ab, c_.ab, f), f), f);
  const uint64_t dx10 = log_mul(c_.dl, log_mul(q, u, f), f);
  const uint64_t abu = log_mul(c_.ab, u, f);
  const uint64_t da10 = log_mul(c_.dl, abu, f);
  const uint64_t s2 = log_mul(abu, abu, f);
  const uint64_t dp = log_mul(log_mul(c_.b, c_.dl, f), u, f);
  const uint64_t e = log_mul(dp, s2, f);
  const uint64_t f34 = rsb(dp, 2, f);  // 3 - 4d'
  const uint64_t d = rsb(log_mul(e, f34, f), 1, f);
  const uint64_t n15 = rsb(log_mul(dp, f34, f), 1, f);
  const uint64_t n14 = rsb(log_mul(log_mul(dp, e, f), rsb(dp, 3, f), f), 1, f);
  const uint64_t inv = log_recip(d, f);
  dx21_ = log_mul(log_mul(n14, inv, f), dx10, f);
  da21_ = log_mul(log_mul(n15, inv, f), da10, f);
  x_ += dx10;
  a_ += da10;
}

bool LogFixedStream::next(LogFixedPoint& p) {
  if (done_) return false;
  ++index_;
  if (index_ % 2 == 1) {
    cycle();
  } else {
    x_ += dx21_;
    a_ += da21_;
    done_ = x_ >= c_.x_end;
  }
  p.index = index_;
  p.x = x_;
  p.a = a_;
  for (size_t i = 0; i < 3; ++i) p.pos[i] = log_pos(x_, c_.k[i], f_);
  p.pos[3] = log_pos(a_, c_.k[3], f_);
  return true;
}

std::string log_fixed_check(const LogFixedCommand& c, const LogFixedFormat& f, int seg_w,
                            int pos_w) {
  const auto hex = [](uint64_t v) { return std::to_string(v); };
  const char* names[] = {"b", "ab", "dl", "x_end", "k0", "k1", "k2", "k3"};
  const uint64_t words[] = {c.b, c.ab, c.dl, c.x_end, c.k[0], c.k[1], c.k[2], c.k[3]};
  for (size_t i = 0; i < 8; ++i)
    if (words[i] > f.max_word())
      return std::string(names[i]) + " word " + hex(words[i]) + " does not fit " +
             std::to_string(f.width()) + " bits";
  if (c.dl == 0) return "dl rounds to 0 in " + std::to_string(f.frac_w) + " fraction bits";
  if (c.x_end == 0) return "x_end rounds to 0";
  const double one = static_cast<double>(f.one());
  // d' is largest at X = 0 (it falls as q grows).
  const uint64_t dp = LogFixedStream::d_prime_at_start(c, f);
  if (8 * dp >= 3 * f.one())
    return "d' = b dl / sqrt(1 + (ab)^2) = " + std::to_string(static_cast<double>(dp) / one) +
           " at X = 0 is not below 3/8: the even step's terms 3 - 8d' would turn negative "
           "(shorten dl or widen the cone)";
  // q^2 + ab^2 at the largest X the run reaches (x_end plus one cycle).
  const double b = static_cast<double>(c.b) / one, ab = static_cast<double>(c.ab) / one;
  const double reach = static_cast<double>(c.x_end + 3 * c.dl) / one;
  const double q = 1 + b * reach;
  if (q * q + ab * ab >= std::ldexp(1.0, f.int_w - 1))
    return "q^2 + (ab)^2 = " + std::to_string(q * q + ab * ab) +
           " at X = " + std::to_string(reach) + " leaves the " + std::to_string(f.int_w) +
           "-bit integer part (shorten x_end or narrow the cone)";
  const int64_t seg_max = (int64_t{1} << (seg_w - 1)) - 1;
  const int64_t pos_lim = (int64_t{1} << (pos_w - 1)) - 1;
  LogFixedStream s(c, f);
  LogFixedPoint p, prev;
  size_t count = 0;
  while (s.next(p)) {
    if (++count > kLogMaxPoints)
      return "the curve has more than " + std::to_string(kLogMaxPoints) + " points";
    if (p.x > f.max_word() / 2 || p.a > f.max_word() / 2)
      return "point " + std::to_string(p.index) + " reaches X or A of " +
             std::to_string(static_cast<double>(std::max(p.x, p.a)) / one) + ", past the " +
             std::to_string(f.int_w) + "-bit integer part";
    for (size_t i = 0; i < 4; ++i) {
      if (p.pos[i] - prev.pos[i] > seg_max)
        return "point " + std::to_string(p.index) + " moves axis " + std::to_string(i) + " by " +
               std::to_string(p.pos[i] - prev.pos[i]) + " steps, more than the " +
               std::to_string(seg_w) + "-bit segment deltas hold (" + std::to_string(seg_max) +
               "): shorten dl or lower the steps per unit";
      if (p.pos[i] > pos_lim)
        return "axis " + std::to_string(i) + " reaches " + std::to_string(p.pos[i]) +
               " steps, past the " + std::to_string(pos_w) + "-bit position counter";
    }
    prev = p;
  }
  return "";
}

std::array<int64_t, 4> log_lattice(const LogPoint& p, const LogCurveParams&,
                                   const LogStepScale& s) {
  return {std::llround(p.x * s.x_per_mm), std::llround(p.y * s.y_per_mm),
          std::llround(p.z * s.z_per_mm), std::llround(p.a * 180 / kPi * s.a_per_deg)};
}

}  // namespace hwinterp::models

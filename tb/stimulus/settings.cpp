#include "tb/stimulus/settings.h"

#include <algorithm>
#include <cmath>

#include "tb/base/args.h"

namespace hwinterp::tb {

using cli::UsageError;

StepdirTiming random_timing(Rng& rng, const VariantSpec& spec) {
  auto one = [&] {
    const int64_t v = rng.chance(1, 8) ? rng.range(5, 16) : rng.range(0, 4);
    return static_cast<uint32_t>(std::min<uint64_t>(static_cast<uint64_t>(v), spec.tim_max()));
  };
  StepdirTiming t;
  t.step_len = one();
  t.step_space = one();
  t.dir_setup = one();
  t.dir_hold = one();
  return t;
}

uint64_t random_feed(Rng& rng, const VariantSpec& spec) {
  const int64_t full = static_cast<int64_t>(spec.full_feed());
  const uint64_t pick = rng.below(10);
  if (pick < 4) return static_cast<uint64_t>(full);  // full feed
  if (pick < 5)
    return static_cast<uint64_t>(full + rng.range(1, full - 1));  // above full: still full
  if (pick < 8) return static_cast<uint64_t>(rng.range(full / 4, full - 1));
  return static_cast<uint64_t>(rng.range(full / 16, full / 4 - 1));  // slow
}

uint64_t parse_feed(const std::string& text, const VariantSpec& spec, const std::string& where) {
  if (text == "full") return spec.full_feed();
  if (text.find('.') != std::string::npos) {  // a fraction of the clock rate
    const double f = cli::parse_real(text, where);
    if (!(f > 0 && f <= 1))
      throw UsageError(where + ": feed fraction " + text + " is outside (0, 1]");
    const auto word =
        static_cast<uint64_t>(std::llround(f * static_cast<double>(spec.full_feed())));
    if (word == 0)
      throw UsageError(where + ": feed fraction " + text + " is below one feed step (1/" +
                       std::to_string(spec.full_feed()) + " of the clock) and rounds to 0");
    return word;
  }
  const int64_t v = cli::parse_integer(text, where);
  if (v < 0) throw UsageError(where + ": feed word " + text + " is negative");
  return static_cast<uint64_t>(v);
}

void validate_feed_and_timing(uint64_t feed, const StepdirTiming& t, const VariantSpec& spec,
                              const std::string& where) {
  // feed_i is FEED_W + 1 bits wide; anything at or above 2^FEED_W is full feed.
  if (feed >= 2 * spec.full_feed())
    throw UsageError(where + ": feed word " + std::to_string(feed) + " does not fit feed_i (" +
                     std::to_string(spec.feed_w + 1) + " bits)");
  const std::pair<const char*, uint32_t> s[] = {{"step_len", t.step_len},
                                                {"step_space", t.step_space},
                                                {"dir_setup", t.dir_setup},
                                                {"dir_hold", t.dir_hold}};
  for (const auto& [name, v] : s)
    if (v > spec.tim_max())
      throw UsageError(where + ": " + name + " " + std::to_string(v) + " does not fit " +
                       std::to_string(spec.tim_w) + " bits");
}

std::string point_text(const models::LatticePoint& p) {
  std::string s = "(";
  for (size_t i = 0; i < p.size(); ++i) s += (i ? "," : "") + std::to_string(p[i]);
  return s + ")";
}

}  // namespace hwinterp::tb

namespace hwinterp::tb {

void check_coordinate(int64_t v, const std::string& what) {
  if (v > kCoordinateLimit || v < -kCoordinateLimit)
    throw cli::UsageError(what + ": coordinate " + std::to_string(v) +
                          " is outside +-2^61 (the lattice the testbench works on)");
}

models::LatticePoint pad_point(const VariantSpec& spec, const std::vector<int64_t>& v,
                               const std::string& what) {
  for (const int64_t x : v) check_coordinate(x, what);
  if (v.empty() || static_cast<int>(v.size()) > spec.axes)
    throw cli::UsageError(what + ": " + std::to_string(v.size()) + " coordinates given, " +
                          spec.variant + " has " + std::to_string(spec.axes) + " axes");
  models::LatticePoint p(static_cast<size_t>(spec.axes), 0);
  std::copy(v.begin(), v.end(), p.begin());
  return p;
}

}  // namespace hwinterp::tb

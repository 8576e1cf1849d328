// The shared run-time settings (feed word and step/dir timing) of stimulus:
// random draws, parsing and validation against a variant's widths. Used by
// every core's stimulus; the core's own setup is its adapter's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "models/lattice_path.h"

#include "tb/base/variant_spec.h"
#include "tb/stimulus/rng.h"

namespace hwinterp::tb {

// Mostly short settings (fast runs, many stalls), sometimes long ones (up
// to 16 clocks, or what TIM_W holds).
StepdirTiming random_timing(Rng& rng, const VariantSpec& spec);

// Full feed 40 %, above full (still full) 10 %, 1/4..1 30 %, slow 20 %.
uint64_t random_feed(Rng& rng, const VariantSpec& spec);

// A feed given as `full`, a clock fraction with a '.' (0 < F <= 1) or a feed
// word (0 = hold). Throws cli::UsageError naming `where` and the text.
uint64_t parse_feed(const std::string& text, const VariantSpec& spec, const std::string& where);

// The feed word fits feed_i (FEED_W + 1 bits) and every timing setting fits
// TIM_W bits; throws cli::UsageError naming `where`, the setting and value.
void validate_feed_and_timing(uint64_t feed, const StepdirTiming& timing, const VariantSpec& spec,
                              const std::string& where);

// "(a,b,c)" for messages.
std::string point_text(const models::LatticePoint& p);

}  // namespace hwinterp::tb

namespace hwinterp::tb {

// Every lattice coordinate, given or reached, stays within +-2^61, so that the
// difference or sum of two of them never overflows 64 bits (an end minus a
// start, a position plus a delta).
inline constexpr int64_t kCoordinateLimit = int64_t{1} << 61;
// Throws cli::UsageError naming `what` and `v` when |v| > kCoordinateLimit.
void check_coordinate(int64_t v, const std::string& what);

// Leading-axis coordinates padded with zeros to the variant's axis count;
// throws cli::UsageError (`what`: where they came from) when there are none
// or more than the axes, or one is past kCoordinateLimit.
models::LatticePoint pad_point(const VariantSpec& spec, const std::vector<int64_t>& v,
                               const std::string& what);

}  // namespace hwinterp::tb

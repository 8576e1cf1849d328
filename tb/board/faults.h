// Faults a simulated board's link injects, seeded: what a test asks for to
// show that the link loses nothing and doubles nothing (docs/link.md).
//
//   --faults drop=P,corrupt=P,dup=P,reorder=P   probabilities in [0, 1]
//
// Ethernet: per UDP frame, in each direction: dropped; one bit of the UDP
// payload flipped after the FCS was computed (the frame arrives with a bad
// FCS, as a bit error on the cable makes it); sent twice; held back and sent
// after the next frame (or after a while if none comes). ARP is left alone.
// UART: per byte, in each direction: dropped, one bit flipped, sent twice
// (reorder does not apply to a serial line).
#pragma once

#include <cstdint>
#include <random>
#include <string>

#include "tb/base/json.h"

namespace hwinterp::board {

struct FaultSpec {
  double drop = 0, corrupt = 0, dup = 0, reorder = 0;
  bool any() const { return drop > 0 || corrupt > 0 || dup > 0 || reorder > 0; }
};

// Parses "drop=0.05,corrupt=0.02"; throws cli::UsageError naming the item.
FaultSpec parse_faults(const std::string& text);

// The faults one direction of a link injected.
struct FaultCounts {
  uint64_t units = 0;  // frames or bytes that passed through
  uint64_t dropped = 0, corrupted = 0, duplicated = 0, reordered = 0;
  Json to_json() const;
};

// What to do with one frame or byte.
struct FaultAction {
  bool drop = false, corrupt = false, dup = false, reorder = false;
};

class FaultInjector {
 public:
  FaultInjector(const FaultSpec& spec, uint64_t seed) : spec_(spec), rng_(seed) {}
  // Draws the faults of the next unit (at most one of drop, corrupt,
  // reorder; dup besides any but drop) and counts them.
  FaultAction next(FaultCounts& counts);
  // A random index below n (which bit or byte to corrupt).
  uint64_t below(uint64_t n) { return n ? rng_() % n : 0; }
  const FaultSpec& spec() const { return spec_; }

 private:
  bool draw(double p) { return p > 0 && std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  FaultSpec spec_;
  std::mt19937_64 rng_;
};

}  // namespace hwinterp::board

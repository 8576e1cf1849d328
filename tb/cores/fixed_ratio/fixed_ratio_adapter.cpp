#include "tb/cores/fixed_ratio/fixed_ratio_adapter.h"

#include <algorithm>
#include <cstdlib>

#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb::cores::fixed_ratio {

Adapter::Reference::Reference(const models::LatticePoint& start, const Command& c, const Setup&,
                              const VariantSpec& l)
    : IdealLine(start, c),
      stream_(start, delta_vector(c, start.size()), l.param("FRAC_W")),
      bound_(models::fixed_ratio_hw_bound(stream_.delta(), l.param("FRAC_W"))) {}

bool Adapter::Reference::next(Move& m) {
  if (!stream_.next(move_)) return false;
  m.index = move_.tick;
  for (size_t i = 0; i < move_.step.size(); ++i) m.step[i] = static_cast<int8_t>(move_.step[i]);
  return true;
}

uint64_t Adapter::work(const Command& c, const VariantSpec&) {
  return models::fixed_ratio_ticks(delta_vector(c, kMaxAxes));
}

// Positions stay inside a window well within POS_W and deltas inside ACC_W.
// The near-diagonal long lines are where a rate word's rounding would show
// first (every minor axis a step or less behind the major one for 10^5 to
// 10^6 ticks). On the 32-bit variants they are rare (1 command in 150, and
// never reversed: each tick costs a pulse and a space on every axis, about 7
// clocks at the random settings), so a 300-command stream runs a few 10^6
// clocks (one or two seconds in the direct mode).
Adapter::Command Adapter::random_command(Rng& rng, const VariantSpec& l,
                                         const models::LatticePoint& at, const Command& previous) {
  const size_t axes = static_cast<size_t>(l.axes);
  const int64_t pos_room =
      l.pos_w >= 20 ? int64_t{1} << (l.pos_w - 2) : (int64_t{1} << (l.pos_w - 1)) - 1;
  const int64_t max_delta = (int64_t{1} << (l.param("ACC_W") - 1)) - 1;
  const bool narrow = max_delta <= pos_room / 2;  // the whole delta width fits the window
  auto sign = [&] { return rng.chance(1, 2) ? int64_t{1} : int64_t{-1}; };
  auto near_diagonal = [&](int64_t len) {
    Command c;
    const size_t major = rng.below(axes);
    for (size_t i = 0; i < axes; ++i)
      c.delta[i] = (i == major ? len : len - rng.range(0, 4)) * sign();
    return c;
  };
  Command c;
  const uint64_t kind = rng.below(300);
  if (kind < 15) {
    // zero length: one tick, no step
  } else if (kind < 51) {  // axis-parallel
    c.delta[rng.below(axes)] = random_delta_magnitude(rng) * sign();
  } else if (kind < 90 && (narrow || models::fixed_ratio_ticks(delta_vector(previous, axes)) <
                                         100000)) {  // reversal of the previous command
    for (size_t i = 0; i < axes; ++i) c.delta[i] = -previous.delta[i];
  } else if (narrow && kind >= 90 && kind < 105) {  // near-diagonal, up to the delta width
    c = near_diagonal(rng.range(max_delta / 2, max_delta));
  } else if (narrow && kind >= 105 && kind < 117) {  // the extremes of the delta width
    for (size_t i = 0; i < axes; ++i) c.delta[i] = rng.range(-max_delta - 1, max_delta);
    c.delta[rng.below(axes)] = rng.chance(1, 2) ? max_delta : -max_delta - 1;
  } else if (!narrow && kind >= 90 && kind < 92) {
    // near-diagonal, 10^5 to 10^6 steps, half of them below 3 10^5
    c = near_diagonal(
        std::min<int64_t>(rng.range(100000, rng.chance(1, 2) ? 1000000 : 300000), max_delta));
  } else if (!narrow && kind >= 92 && kind < 102) {  // long, up to 10^4 steps
    for (size_t i = 0; i < axes; ++i) c.delta[i] = rng.range(0, 10000) * sign();
  } else {  // any octant
    for (size_t i = 0; i < axes; ++i) c.delta[i] = random_delta_magnitude(rng) * sign();
  }
  for (size_t i = 0; i < axes; ++i) {
    // Turn back rather than leave the position window (-(-2^(ACC_W-1)) does
    // not fit: clamp after turning).
    if (std::llabs(at[i] + c.delta[i]) > pos_room) c.delta[i] = -c.delta[i];
    c.delta[i] = std::clamp<int64_t>(c.delta[i], -max_delta - 1, max_delta);
    if (std::llabs(at[i] + c.delta[i]) > pos_room) c.delta[i] = 0;
  }
  return c;
}

std::vector<Case<Adapter>> Adapter::regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed) {
  std::vector<Case<Adapter>> cases = paper_lines_004(l, default_settings<Adapter>(l));
  append_random_streams(cases, l, commands, seed);
  return cases;
}

void Adapter::declare_options(cli::Args& args) {
  args.option("line", "X0,Y0,..,X1,Y1,..",
              "one line: start then end coordinates (2k numbers, k <= axes)")
      .flag("paper-lines", "the eight test lines of 004_dc68f1177cad466f.txt, one case each");
}

std::vector<Case<Adapter>> Adapter::cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings) {
  if (args.given("paper-lines")) return paper_lines_004(l, settings);
  return {delta_line_from_option(args, l, settings)};
}

}  // namespace hwinterp::tb::cores::fixed_ratio

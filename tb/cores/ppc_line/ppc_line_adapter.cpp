#include "tb/cores/ppc_line/ppc_line_adapter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "models/paper_data_001_003_004.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb::cores::ppc_line {

using cli::UsageError;

namespace {

int64_t random_magnitude(Rng& rng, int64_t cap) {
  switch (rng.below(10)) {
    case 0:
    case 1:
      return rng.range(0, 3);
    case 2:
    case 3:
    case 4:
      return rng.range(0, 40);
    case 5:
    case 6:
      return rng.range(0, 300);
    case 7:
      return rng.range(0, 3000);
    case 8:
      return rng.range(0, 100);
    default:
      return rng.chance(1, 2) ? cap : rng.range(cap / 2, cap);  // long: up to the widths
  }
}

}  // namespace

Adapter::Reference::Reference(const models::LatticePoint& start, const Command& c, const Setup&,
                              const VariantSpec&)
    : IdealLine(start, c),
      stream_(start, end_),
      bound_{models::ppc_line_error_bound(start_, end_), false} {}

bool Adapter::Reference::next(Move& m) {
  if (!stream_.next(move_)) return false;
  m.index = static_cast<uint64_t>(move_.time);
  for (size_t i = 0; i < 2; ++i) m.step[i] = static_cast<int8_t>(move_.step[i]);
  return true;
}

uint64_t Adapter::work(const Command& c, const VariantSpec&) {
  return std::max<uint64_t>(
      static_cast<uint64_t>(std::llabs(c.delta[0])) + static_cast<uint64_t>(std::llabs(c.delta[1])),
      1);
}

// Positions stay inside a window well within POS_W; long lines reach the
// delta width where the window allows it (the narrow variants), else a few
// thousand steps (a full 32-bit line would run for hours).
Adapter::Command Adapter::random_command(Rng& rng, const VariantSpec& l,
                                         const models::LatticePoint& at, const Command& previous) {
  const int64_t pos_room = l.pos_w >= 20 ? 100000 : (int64_t{1} << (l.pos_w - 1)) - 1;
  const int64_t max_delta = (int64_t{1} << (l.param("ACC_W") - 1)) - 1;
  const int64_t cap = std::min<int64_t>(max_delta, 5000);
  Command c;
  const uint64_t kind = rng.below(20);
  auto sign = [&] { return rng.chance(1, 2) ? int64_t{1} : int64_t{-1}; };
  if (kind == 0) {
    // zero length: one operation, no step
  } else if (kind <= 2) {  // vertical
    c.delta[1] = random_magnitude(rng, cap) * sign();
  } else if (kind <= 4) {  // horizontal
    c.delta[0] = random_magnitude(rng, cap) * sign();
  } else if (kind == 5) {  // diagonal
    c.delta[0] = random_magnitude(rng, cap) * sign();
    c.delta[1] = std::llabs(c.delta[0]) * sign();
  } else if (kind <= 7) {  // reversal of the previous command
    c.delta = previous.delta;
    for (auto& d : c.delta) d = -d;
  } else if (kind == 8 && max_delta <= pos_room / 2) {  // the extremes of the delta width
    c.delta[0] = rng.chance(1, 2) ? max_delta : -max_delta - 1;
    c.delta[1] = rng.range(-max_delta - 1, max_delta);
    if (rng.chance(1, 2)) std::swap(c.delta[0], c.delta[1]);
  } else {  // any octant
    c.delta[0] = random_magnitude(rng, cap) * sign();
    c.delta[1] = random_magnitude(rng, cap) * sign();
  }
  for (size_t i = 0; i < 2; ++i) {
    // Turn back rather than leave the position window (-(-2^(ACC_W-1)) does
    // not fit: clamp after turning).
    if (std::llabs(at[i] + c.delta[i]) > pos_room) c.delta[i] = -c.delta[i];
    c.delta[i] = std::clamp<int64_t>(c.delta[i], -max_delta - 1, max_delta);
    if (std::llabs(at[i] + c.delta[i]) > pos_room) c.delta[i] = 0;
  }
  return c;
}

std::vector<Case<Adapter>> Adapter::paper_lines(const VariantSpec& l,
                                                const RunSettings<Adapter>& settings) {
  std::vector<Case<Adapter>> cases = paper_lines_004(l, settings);
  cases.push_back(delta_line_case(l, "003_line", {0, 0}, {4, 3}, settings));
  return cases;
}

std::vector<Case<Adapter>> Adapter::regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed) {
  std::vector<Case<Adapter>> cases = paper_lines(l, default_settings<Adapter>(l));
  append_random_streams(cases, l, commands, seed);
  return cases;
}

void Adapter::declare_options(cli::Args& args) {
  args.option("line", "X0,Y0,X1,Y1", "one line: start then end coordinates")
      .flag("paper-lines",
            "the eight test lines of 004_dc68f1177cad466f.txt and 003's (0,0)->(4,3), one case "
            "each");
}

std::vector<Case<Adapter>> Adapter::cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings) {
  if (args.given("paper-lines")) return paper_lines(l, settings);
  return {delta_line_from_option(args, l, settings)};
}

}  // namespace hwinterp::tb::cores::ppc_line

#include "tb/cores/dda_line/dda_line_adapter.h"

#include <algorithm>
#include <cstdlib>

#include "tb/stimulus/delta_commands.h"

namespace hwinterp::tb::cores::dda_line {

using cli::UsageError;

Adapter::Reference::Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
                              const VariantSpec& l)
    : IdealLine(start, c),
      stream_(start, delta_vector(c, start.size()),
              s.half_preload ? models::Preload::kHalf : models::Preload::kZero),
      bound_(models::dda_error_bound(l.axes, stream_.preload())) {}

bool Adapter::Reference::next(Move& m) {
  if (!stream_.next(move_)) return false;
  m.index = move_.iteration;
  for (size_t i = 0; i < move_.step.size(); ++i) m.step[i] = static_cast<int8_t>(move_.step[i]);
  return true;
}

uint64_t Adapter::work(const Command& c, const VariantSpec&) {
  return models::dda_iterations(delta_vector(c, kMaxAxes));
}

// All octants, zero deltas, single-axis moves and reversals of the previous
// command; positions stay well inside POS_W and deltas inside ACC_W.
Adapter::Command Adapter::random_command(Rng& rng, const VariantSpec& l,
                                         const models::LatticePoint& at, const Command& previous) {
  const size_t axes = static_cast<size_t>(l.axes);
  const int64_t pos_room = l.pos_w >= 20 ? 100000 : (int64_t{1} << (l.pos_w - 2));
  const int64_t max_delta = (int64_t{1} << (l.param("ACC_W") - 1)) - 1;
  const int64_t delta_cap = std::min<int64_t>(max_delta, pos_room / 2);
  Command c;
  const uint64_t kind = rng.below(20);
  if (kind == 0) {
    // all zero: one iteration, no steps
  } else if (kind <= 3) {  // single-axis move
    c.delta[rng.below(axes)] = random_delta_magnitude(rng) * (rng.chance(1, 2) ? 1 : -1);
  } else if (kind <= 6) {  // reversal of the previous command
    for (size_t i = 0; i < axes; ++i) c.delta[i] = -previous.delta[i];
  } else {  // any octant
    for (size_t i = 0; i < axes; ++i)
      c.delta[i] = random_delta_magnitude(rng) * (rng.chance(1, 2) ? 1 : -1);
  }
  for (size_t i = 0; i < axes; ++i) {
    c.delta[i] = std::clamp<int64_t>(c.delta[i], -delta_cap, delta_cap);
    // Turn back rather than leave the position window.
    if (std::llabs(at[i] + c.delta[i]) > pos_room) c.delta[i] = -c.delta[i];
  }
  return c;
}

bool Adapter::job_directive(JobLine<Adapter>& line) {
  if (delta_job_directive(line)) return true;
  if (line.words[0] == "preload") {
    const auto& w = line.words;
    if (w.size() != 2 || (w[1] != "half" && w[1] != "zero"))
      throw UsageError(line.where + ": preload must be 'half' or 'zero', not '" +
                       (w.size() > 1 ? w[1] : std::string()) + "'");
    line.settings().setup.half_preload = w[1] == "half";
    return true;
  }
  return false;
}

std::vector<Case<Adapter>> Adapter::regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed) {
  RunSettings<Adapter> plain = default_settings<Adapter>(l), half = plain;
  half.setup.half_preload = true;
  std::vector<Case<Adapter>> cases = paper_lines_004(l, plain);
  for (auto c : paper_lines_004(l, half)) {
    c.name += "_half";
    cases.push_back(std::move(c));
  }
  append_random_streams(cases, l, commands, seed);
  return cases;
}

void Adapter::declare_options(cli::Args& args) {
  args.option("line", "X0,Y0,..,X1,Y1,..",
              "one line: start then end coordinates (2k numbers, k <= axes)")
      .flag("paper-lines", "the eight test lines of 004_dc68f1177cad466f.txt, one case each")
      .flag("half-preload", "start the accumulators at one half (lower path error)");
}

std::vector<Case<Adapter>> Adapter::cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings) {
  if (args.given("paper-lines")) return paper_lines_004(l, settings);
  return {delta_line_from_option(args, l, settings)};
}

}  // namespace hwinterp::tb::cores::dda_line

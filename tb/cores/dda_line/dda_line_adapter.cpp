#include "tb/cores/dda_line/dda_line_adapter.h"

#include <algorithm>
#include <cstdlib>

#include "models/paper_data_001_003_004.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb::cores::dda_line {

using cli::UsageError;

namespace {

std::vector<int64_t> delta_vector(const Adapter::Command& c, size_t axes) {
  return {c.delta.begin(), c.delta.begin() + static_cast<std::ptrdiff_t>(axes)};
}

int64_t random_magnitude(Rng& rng) {
  switch (rng.below(8)) {
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
    default:
      return rng.chance(1, 4) ? rng.range(300, 3000) : rng.range(0, 100);
  }
}

}  // namespace

Adapter::Reference::Reference(const models::LatticePoint& start, const Command& c, const Setup& s,
                              const CoreLimits& l)
    : stream_(start, delta_vector(c, start.size()),
              s.half_preload ? models::Preload::kHalf : models::Preload::kZero),
      start_(start),
      end_(start),
      bound_(models::dda_error_bound(l.axes, stream_.preload())) {
  apply(c, end_);
}

bool Adapter::Reference::next(Move& m) {
  if (!stream_.next(move_)) return false;
  m.index = move_.iteration;
  for (size_t i = 0; i < move_.step.size(); ++i) m.step[i] = static_cast<int8_t>(move_.step[i]);
  return true;
}

double Adapter::Reference::error(const models::LatticePoint& p) const {
  return models::point_line_distance(p, start_, end_);
}

uint64_t Adapter::work(const Command& c) {
  return models::dda_iterations(delta_vector(c, kMaxAxes));
}

void Adapter::validate(const Command& c, const models::LatticePoint& at, const CoreLimits& l,
                       const std::string& where) {
  (void)at;
  const int acc_w = l.param("ACC_W");
  const int64_t max = (int64_t{1} << (acc_w - 1)) - 1, min = -max - 1;
  for (int i = 0; i < l.axes; ++i) {
    const int64_t d = c.delta[static_cast<size_t>(i)];
    if (d > max || d < min)
      throw UsageError(where + ": delta " + std::to_string(d) + " on axis " + std::to_string(i) +
                       " is wider than the " + std::to_string(acc_w) + "-bit datapath of " +
                       l.variant + " (limit " + std::to_string(min) + ".." + std::to_string(max) +
                       ")");
  }
}

// All octants, zero deltas, single-axis moves and reversals of the previous
// command; positions stay well inside POS_W and deltas inside ACC_W.
Adapter::Command Adapter::random_command(Rng& rng, const CoreLimits& l,
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
    c.delta[rng.below(axes)] = random_magnitude(rng) * (rng.chance(1, 2) ? 1 : -1);
  } else if (kind <= 6) {  // reversal of the previous command
    for (size_t i = 0; i < axes; ++i) c.delta[i] = -previous.delta[i];
  } else {  // any octant
    for (size_t i = 0; i < axes; ++i)
      c.delta[i] = random_magnitude(rng) * (rng.chance(1, 2) ? 1 : -1);
  }
  for (size_t i = 0; i < axes; ++i) {
    c.delta[i] = std::clamp<int64_t>(c.delta[i], -delta_cap, delta_cap);
    // Turn back rather than leave the position window.
    if (std::llabs(at[i] + c.delta[i]) > pos_room) c.delta[i] = -c.delta[i];
  }
  return c;
}

bool Adapter::job_directive(JobLine<Adapter>& line) {
  const std::string& key = line.words[0];
  if (key == "line" || key == "move") {
    const models::LatticePoint v = line.point(1);
    Command c;
    for (size_t i = 0; i < v.size(); ++i) c.delta[i] = key == "line" ? v[i] - line.at()[i] : v[i];
    line.command(c);
    return true;
  }
  if (key == "preload") {
    const auto& w = line.words;
    if (w.size() != 2 || (w[1] != "half" && w[1] != "zero"))
      throw UsageError(line.where + ": preload must be 'half' or 'zero', not '" +
                       (w.size() > 1 ? w[1] : std::string()) + "'");
    line.settings().setup.half_preload = w[1] == "half";
    return true;
  }
  return false;
}

Case<Adapter> Adapter::line_case(const CoreLimits& l, const std::string& name,
                                 const std::vector<int64_t>& start, const std::vector<int64_t>& end,
                                 const RunSettings<Adapter>& settings) {
  if (start.size() != end.size())
    throw UsageError("line '" + name + "': start and end have different axis counts");
  Case<Adapter> c;
  c.name = name;
  c.start = pad_point(l, start, "line '" + name + "'");
  const models::LatticePoint e = pad_point(l, end, "line '" + name + "'");
  Command cmd;
  for (size_t i = 0; i < e.size(); ++i) cmd.delta[i] = e[i] - c.start[i];
  c.settings = settings;
  c.items.push_back(command_item<Adapter>(cmd));
  return c;
}

std::vector<Case<Adapter>> Adapter::paper_lines(const CoreLimits& l,
                                                const RunSettings<Adapter>& settings) {
  std::vector<Case<Adapter>> cases;
  int n = 0;
  for (const auto& p : models::paper::kRatioLines)
    cases.push_back(
        line_case(l, "004_line" + std::to_string(++n), {p[0], p[1]}, {p[2], p[3]}, settings));
  return cases;
}

std::vector<Case<Adapter>> Adapter::regression_cases(const CoreLimits& l, uint64_t commands,
                                                     uint64_t seed) {
  RunSettings<Adapter> plain = default_settings<Adapter>(l), half = plain;
  half.setup.half_preload = true;
  std::vector<Case<Adapter>> cases = paper_lines(l, plain);
  for (auto c : paper_lines(l, half)) {
    c.name += "_half";
    cases.push_back(std::move(c));
  }
  if (commands) {
    cases.push_back(random_case<Adapter>(l, commands, seed));
    Case<Adapter> extra = random_case<Adapter>(l, commands, seed, {true, true});
    extra.name = "random_abort_hold";
    cases.push_back(std::move(extra));
  }
  return cases;
}

void Adapter::declare_options(cli::Args& args) {
  args.option("line", "X0,Y0,..,X1,Y1,..",
              "one line: start then end coordinates (2k numbers, k <= axes)")
      .flag("paper-lines", "the eight test lines of 004_dc68f1177cad466f.txt, one case each")
      .flag("half-preload", "start the accumulators at one half (lower path error)");
}

std::vector<Case<Adapter>> Adapter::cases_from_options(const cli::Args& args, const CoreLimits& l,
                                                       const RunSettings<Adapter>& settings) {
  if (args.given("paper-lines")) return paper_lines(l, settings);
  const std::vector<int64_t> v = args.integer_list("line");
  if (v.size() < 2 || v.size() % 2)
    throw UsageError("--line: '" + args.str("line") +
                     "' needs start and end coordinates (2k numbers)");
  const size_t k = v.size() / 2;
  return {line_case(l, "line", {v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k)},
                    {v.begin() + static_cast<std::ptrdiff_t>(k), v.end()}, settings)};
}

}  // namespace hwinterp::tb::cores::dda_line

#include "tb/cores/ppc_arc/ppc_arc_adapter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "models/common.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb::cores::ppc_arc {

using cli::UsageError;

namespace {
using models::kPi;

models::PpcArcStream relative_stream(const Adapter::Command& c) {
  return models::PpcArcStream({c.center[0], c.center[1]}, {0, 0}, {c.end[0], c.end[1]}, c.ccw);
}

double norm(int64_t x, int64_t y) {
  return std::hypot(static_cast<double>(x), static_cast<double>(y));
}

int64_t coord_max(const VariantSpec& l) { return (int64_t{1} << (l.param("COORD_W") - 1)) - 1; }

// A uniformly drawn real in [0, 1).
double unit(Rng& rng) { return static_cast<double>(rng.next() >> 11) * 0x1.0p-53; }

// A random lattice point on the circle x^2 + y^2 = r2 (r2 has one: it is |s|^2).
models::LatticePoint lattice_point_on(Rng& rng, int64_t r2) {
  std::vector<models::LatticePoint> on;
  const auto r = static_cast<int64_t>(std::floor(std::sqrt(static_cast<double>(r2))));
  for (int64_t x = -r; x <= r; ++x) {
    const int64_t y2 = r2 - x * x;
    const auto y = static_cast<int64_t>(std::llround(std::sqrt(static_cast<double>(y2))));
    if (y * y != y2) continue;
    on.push_back({x, y});
    if (y != 0) on.push_back({x, -y});
  }
  return on[rng.below(on.size())];
}

}  // namespace

Adapter::Reference::Reference(const models::LatticePoint& start, const Command& c, const Setup&,
                              const VariantSpec&)
    : start_(start),
      stream_(relative_stream(c)),
      ideal_({c.center[0], c.center[1]}, {0, 0}, {c.end[0], c.end[1]}, c.ccw) {}

bool Adapter::Reference::next(Move& m) {
  if (!stream_.next(move_)) return false;
  m.index = static_cast<uint64_t>(move_.time);
  for (size_t i = 0; i < 2; ++i) m.step[i] = static_cast<int8_t>(move_.step[i]);
  return true;
}

double Adapter::Reference::error(const models::LatticePoint& p) const {
  rel_[0] = p[0] - start_[0];
  rel_[1] = p[1] - start_[1];
  return ideal_.error(rel_);
}

uint64_t Adapter::work(const Command& c, const VariantSpec&) {
  return relative_stream(c).operation_bound();
}

uint64_t Adapter::operations(const Command& c, const VariantSpec&) {
  models::PpcArcStream s = relative_stream(c);
  models::StepMove m;
  while (s.next(m)) {
  }
  return s.operations();
}

void Adapter::validate(const Command& c, const models::LatticePoint& from, const VariantSpec& l,
                       const std::string& where) {
  l.check_fits("cmd_center_i", c.center[0], "centre offset I (centre x - start x)", where);
  l.check_fits("cmd_center_i", c.center[1], "centre offset J (centre y - start y)", where);
  l.check_fits("cmd_end_i", c.end[0], "end offset (end x - start x)", where);
  l.check_fits("cmd_end_i", c.end[1], "end offset (end y - start y)", where);
  // The whole circle, as the position counters see it (from the case start).
  const double rs = norm(c.center[0], c.center[1]);
  const double re = norm(c.end[0] - c.center[0], c.end[1] - c.center[1]);
  const auto reach = static_cast<int64_t>(std::ceil(std::max(rs, re))) + 2;
  for (size_t i = 0; i < 2; ++i) {
    const int64_t cen = from[i] + c.center[i];
    for (const int64_t edge : {cen - reach, cen + reach})
      if (edge > l.pos_max() || edge < l.pos_min())
        throw UsageError(where + ": the arc's circle (centre " + std::to_string(cen) + " +- " +
                         std::to_string(reach) + " on axis " + std::to_string(i) +
                         ", from the case start) reaches position " + std::to_string(edge) +
                         ", past the " + std::to_string(l.pos_w) + "-bit position counter");
  }
}

Adapter::Command Adapter::random_command(Rng& rng, const VariantSpec& l,
                                         const models::LatticePoint& at, const Command&) {
  const int64_t cmax = coord_max(l);
  // Where the path may wander (the start of every command stays inside).
  const int64_t room = l.pos_w >= 20 ? 100000 : l.pos_max();
  for (int attempt = 0; attempt < 64; ++attempt) {
    Command c;
    c.ccw = rng.chance(1, 2);
    const uint64_t kind = rng.below(20);
    bool large = false;
    if (kind == 0) {
      // Degenerate: the start within one step of the centre, a line to the end.
      const int64_t d[5][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      const auto& k = d[rng.below(5)];
      c.center = {k[0], k[1]};
      c.end = {rng.range(-30, 30), rng.range(-30, 30)};
    } else {
      double r;
      if (kind <= 8) {
        r = 1.5 + unit(rng) * 12;  // small
      } else if (kind <= 15) {
        r = 12 + unit(rng) * 200;  // medium
      } else {
        r = 200 + unit(rng) * static_cast<double>(cmax - 200);  // large, up to the width
        large = true;
      }
      r = std::min(r, static_cast<double>(cmax));
      const double a0 = unit(rng) * 2 * kPi;
      c.center = {std::llround(-r * std::cos(a0)), std::llround(-r * std::sin(a0))};
      const int64_t sx = -c.center[0], sy = -c.center[1];  // s = start - centre
      const int64_t r2 = sx * sx + sy * sy;
      const double rs = std::sqrt(static_cast<double>(r2));
      models::LatticePoint e;  // relative to the centre
      const uint64_t end_kind = rng.below(20);
      if (end_kind < 2) {
        e = {sx, sy};  // full circle
      } else if (end_kind < 7 && rs < 300) {
        e = lattice_point_on(rng, r2);  // on the circle (the arc phase ends on it)
      } else {
        // Rounded from a real point on the circle, sometimes a few steps off.
        const double sweep =
            large ? (8 + unit(rng) * 1500) / rs : unit(rng) * 2 * kPi;  // large: short arcs
        const double a1 =
            std::atan2(static_cast<double>(sy), static_cast<double>(sx)) + (c.ccw ? sweep : -sweep);
        const double off = rng.chance(1, 3) ? static_cast<double>(rng.range(-3, 3)) : 0.0;
        e = {std::llround((rs + off) * std::cos(a1)), std::llround((rs + off) * std::sin(a1))};
      }
      c.end = {e[0] - sx, e[1] - sy};
    }
    // Fits the widths and the position window, and a large radius runs no lap.
    if (std::max(std::llabs(c.end[0]), std::llabs(c.end[1])) > cmax) continue;
    if (std::llabs(at[0] + c.end[0]) > room || std::llabs(at[1] + c.end[1]) > room) continue;
    const double reach = std::max(norm(c.center[0], c.center[1]),
                                  norm(c.end[0] - c.center[0], c.end[1] - c.center[1])) +
                         3;
    bool inside = true;
    for (size_t i = 0; i < 2; ++i)
      inside = inside && std::abs(static_cast<double>(at[i] + c.center[i])) + reach <
                             static_cast<double>(l.pos_max());
    if (!inside) continue;
    if (large && relative_stream(c).laps() > 1) continue;
    return c;
  }
  // Nothing fitted (the path is near the edge of the window): a line back
  // towards the origin, as a degenerate arc.
  Command c;
  const int64_t step = std::min<int64_t>(cmax, 50);
  c.end = {std::clamp<int64_t>(-at[0], -step, step), std::clamp<int64_t>(-at[1], -step, step)};
  return c;
}

bool Adapter::job_directive(JobLine<Adapter>& line) {
  if (line.words[0] != "arc") return false;
  const auto& w = line.words;
  if (w.size() != 6)
    throw UsageError(line.where + ": 'arc' takes CX CY X1 Y1 cw|ccw (" +
                     std::to_string(w.size() - 1) + " values given)");
  const std::vector<int64_t> v = line.integers(1, 4);
  if (w[5] != "cw" && w[5] != "ccw")
    throw UsageError(line.where + ": arc direction must be 'cw' or 'ccw', not '" + w[5] + "'");
  const models::LatticePoint& at = line.at();
  Command c;
  c.center = {v[0] - at[0], v[1] - at[1]};
  c.end = {v[2] - at[0], v[3] - at[1]};
  c.ccw = w[5] == "ccw";
  line.command(c);
  return true;
}

Case<Adapter> Adapter::arc_case(const VariantSpec& l, const std::string& name,
                                const models::LatticePoint& center,
                                const models::LatticePoint& start, const models::LatticePoint& end,
                                bool ccw, const RunSettings<Adapter>& settings) {
  Case<Adapter> c;
  c.name = name;
  c.start = pad_point(l, start, "arc '" + name + "'");
  Command cmd;
  cmd.center = {center[0] - start[0], center[1] - start[1]};
  cmd.end = {end[0] - start[0], end[1] - start[1]};
  cmd.ccw = ccw;
  c.settings = settings;
  c.items.push_back(command_item<Adapter>(cmd));
  return c;
}

std::vector<Case<Adapter>> Adapter::paper_arcs(const VariantSpec& l,
                                               const RunSettings<Adapter>& settings) {
  return {arc_case(l, "003_arc", {0, 0}, {4, 0}, {0, 4}, true, settings)};
}

std::vector<Case<Adapter>> Adapter::regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed) {
  const RunSettings<Adapter> plain = default_settings<Adapter>(l);
  std::vector<Case<Adapter>> cases = paper_arcs(l, plain);
  cases.push_back(arc_case(l, "full_circle_cw", {0, 0}, {5, 0}, {5, 0}, false, plain));
  cases.push_back(arc_case(l, "off_circle_end", {0, 0}, {4, 0}, {-1, 5}, true, plain));
  append_random_streams(cases, l, commands, seed);
  return cases;
}

void Adapter::declare_options(cli::Args& args) {
  args.option("arc", "CX,CY,X0,Y0,X1,Y1,cw|ccw",
              "one arc: centre, start and end (absolute lattice coordinates) and direction; "
              "the case starts at X0,Y0")
      .flag("paper-arcs", "the arc (4,0)->(0,4) CCW around (0,0) of 003_b291717b57510359.txt");
}

std::vector<Case<Adapter>> Adapter::cases_from_options(const cli::Args& args, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings) {
  if (args.given("paper-arcs")) return paper_arcs(l, settings);
  const std::string text = args.str("arc");
  std::vector<std::string> f;
  std::string item;
  for (const char ch : text + ",") {
    if (ch == ',') {
      f.push_back(item);
      item.clear();
    } else {
      item += ch;
    }
  }
  if (f.size() != 7)
    throw UsageError("--arc: '" + text + "' needs CX,CY,X0,Y0,X1,Y1,cw|ccw (7 fields, " +
                     std::to_string(f.size()) + " given)");
  std::vector<int64_t> v;
  for (size_t i = 0; i < 6; ++i) {
    v.push_back(cli::parse_integer(f[i], "--arc"));
    check_coordinate(v.back(), "--arc");
  }
  if (f[6] != "cw" && f[6] != "ccw")
    throw UsageError("--arc: direction must be 'cw' or 'ccw', not '" + f[6] + "'");
  return {arc_case(l, "arc", {v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, f[6] == "ccw", settings)};
}

}  // namespace hwinterp::tb::cores::ppc_arc

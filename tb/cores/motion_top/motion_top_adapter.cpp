#include "tb/cores/motion_top/motion_top_adapter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <sstream>

#include "models/common.h"
#include "tb/cores/delta_payload.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb::cores::motion_top {

using cli::UsageError;
using models::MotionCommand;
using models::MotionKind;

namespace {
using models::kPi;

int64_t signed_max(int w) { return (int64_t{1} << (w - 1)) - 1; }

double unit(Rng& rng) { return static_cast<double>(rng.next() >> 11) * 0x1.0p-53; }

uint64_t full_feed(const VariantSpec& l) { return l.full_feed(); }

// The plane's axes as machine axes, and whether `i` is one of them.
bool in_plane(const MotionCommand& c, int i) {
  const auto p = models::motion_plane_axes(c.plane);
  return i == p[0] || i == p[1];
}

}  // namespace

Adapter::Reference::Reference(const models::LatticePoint& start, const Command& c, const Setup&,
                              const VariantSpec& l)
    : start_(start), cmd_(c), stream_(start, c, l.axes), ideal_(start, c, l.axes) {
  move_.point = start;
}

bool Adapter::Reference::next(Move& m) {
  if (!stream_.next(move_)) return false;
  op_ = move_.op;
  m.index = move_.op;
  for (size_t i = 0; i < start_.size(); ++i) m.step[i] = move_.step[i];
  return true;
}

std::vector<std::vector<double>> Adapter::Reference::ideal() const {
  const auto d = models::motion_displacement(cmd_);
  std::vector<std::vector<double>> out;
  if (cmd_.kind == MotionKind::kLine) {
    std::vector<double> a(start_.begin(), start_.end()), b = a;
    for (size_t i = 0; i < b.size(); ++i) b[i] += static_cast<double>(d[i]);
    return {a, b};
  }
  // The arc (its spiral from the start radius to the end radius) and the
  // slaved axes, linearly, in 64 pieces.
  const auto p = models::motion_plane_axes(cmd_.plane);
  const double cx = static_cast<double>(cmd_.center[0]), cy = static_cast<double>(cmd_.center[1]);
  const double sx = -cx, sy = -cy, ex = cmd_.end[0] - cx, ey = cmd_.end[1] - cy;
  const double rs = std::hypot(sx, sy), re = std::hypot(ex, ey);
  const double a0 = std::atan2(sy, sx);
  double sweep = std::atan2(ey, ex) - a0;
  if (cmd_.ccw) {
    while (sweep <= 1e-12) sweep += 2 * kPi;
  } else {
    while (sweep >= -1e-12) sweep -= 2 * kPi;
  }
  for (int k = 0; k <= 64; ++k) {
    const double t = k / 64.0, a = a0 + sweep * t, r = rs + (re - rs) * t;
    std::vector<double> q(start_.begin(), start_.end());
    for (size_t i = 0; i < q.size(); ++i) q[i] += static_cast<double>(d[i]) * t;
    q[static_cast<size_t>(p[0])] =
        static_cast<double>(start_[static_cast<size_t>(p[0])]) + cx + r * std::cos(a);
    q[static_cast<size_t>(p[1])] =
        static_cast<double>(start_[static_cast<size_t>(p[1])]) + cy + r * std::sin(a);
    out.push_back(std::move(q));
  }
  return out;
}

void Adapter::apply(const Command& c, models::LatticePoint& at) {
  const auto d = models::motion_displacement(c);
  for (size_t i = 0; i < at.size(); ++i) at[i] += d[i];
}

uint64_t Adapter::work(const Command& c, const VariantSpec& l) {
  const uint64_t feed = std::max<uint64_t>(c.feed, 1);
  const uint64_t per_op = (full_feed(l) + feed - 1) / feed;
  return models::motion_operations(c) * std::max<uint64_t>(per_op, 1) + 4;
}

void Adapter::validate(const Command& c, const models::LatticePoint& from, const VariantSpec& l,
                       const std::string& where) {
  // 0: the move follows feed_i's word (a feed profile drives it).
  if (c.feed > full_feed(l))
    throw UsageError(where + ": feed word " + std::to_string(c.feed) + " is outside 0.." +
                     std::to_string(full_feed(l)) + " (" + l.variant + ")");
  for (int i = 0; i < models::kMotionMaxAxes; ++i) {
    const int64_t d = c.delta[static_cast<size_t>(i)];
    if (i >= l.axes && d != 0)
      throw UsageError(where + ": axis " + std::to_string(i) + " moves, but " + l.variant +
                       " has " + std::to_string(l.axes) + " axes");
    if (i < l.axes) l.check_fits("cmd_delta_i", d, "delta", where, " on axis " + std::to_string(i));
  }
  if (c.kind == MotionKind::kLine) return;
  if (c.plane < 0 || c.plane > 2)
    throw UsageError(where + ": arc plane " + std::to_string(c.plane) +
                     " is not 0 (XY), 1 (ZX) or 2 (YZ)");
  for (const int64_t v : {c.center[0], c.center[1]})
    l.check_fits("cmd_center_i", v, "arc centre offset", where);
  for (const int64_t v : {c.end[0], c.end[1]})
    l.check_fits("cmd_end_i", v, "arc end offset", where);
  for (int i = 0; i < l.axes; ++i)
    if (in_plane(c, i) && c.delta[static_cast<size_t>(i)] != 0)
      throw UsageError(where + ": axis " + std::to_string(i) +
                       " is in the arc's plane; its delta must be 0 (the arc's end moves it)");
  const uint64_t ops = models::motion_arc_ops(c.center, c.end, c.ccw);
  if (c.ops != ops)
    throw UsageError(where + ": arc operations " + std::to_string(c.ops) + " but the arc takes " +
                     std::to_string(ops));
  l.check_fits("cmd_ops_i", static_cast<int64_t>(ops), "arc operations", where);
  for (int i = 0; i < l.axes; ++i) {
    const uint64_t mag = static_cast<uint64_t>(std::llabs(c.delta[static_cast<size_t>(i)]));
    if (mag > ops)
      throw UsageError(where + ": slaved axis " + std::to_string(i) + " moves " +
                       std::to_string(mag) + " steps over the arc's " + std::to_string(ops) +
                       " operations (at most one step an operation)");
  }
  // The whole circle, as the position counters see it.
  const auto p = models::motion_plane_axes(c.plane);
  const double rs = std::hypot(static_cast<double>(c.center[0]), static_cast<double>(c.center[1]));
  const double re = std::hypot(static_cast<double>(c.end[0] - c.center[0]),
                               static_cast<double>(c.end[1] - c.center[1]));
  const auto reach = static_cast<int64_t>(std::ceil(std::max(rs, re))) + 2;
  for (int k = 0; k < 2; ++k) {
    const int64_t cen =
        from[static_cast<size_t>(p[static_cast<size_t>(k)])] + c.center[static_cast<size_t>(k)];
    for (const int64_t edge : {cen - reach, cen + reach})
      if (edge > l.pos_max() || edge < l.pos_min())
        throw UsageError(where + ": the arc's circle reaches position " + std::to_string(edge) +
                         " on axis " + std::to_string(p[static_cast<size_t>(k)]) + ", past the " +
                         std::to_string(l.pos_w) + "-bit position counter");
  }
}

Adapter::Command Adapter::random_command(Rng& rng, const VariantSpec& l,
                                         const models::LatticePoint& at, const Command& previous) {
  const int64_t cmax = signed_max(l.param("COORD_W"));
  const int64_t dmax = signed_max(l.param("ACC_W"));
  const uint64_t ops_lim = (uint64_t{1} << l.param("OPS_W")) - 1;
  // Where the path may wander (the start of every command stays inside).
  const int64_t room = std::min<int64_t>(l.pos_max() / 2, 100000);
  const uint64_t full = full_feed(l);
  auto feed = [&]() -> uint32_t {
    return static_cast<uint32_t>(rng.chance(3, 4) ? full : rng.range(full / 4, full));
  };
  auto sign = [&] { return rng.chance(1, 2) ? int64_t{1} : int64_t{-1}; };
  for (int attempt = 0; attempt < 64; ++attempt) {
    Command c;
    c.feed = feed();
    if (rng.chance(1, 2)) {
      c.kind = MotionKind::kLine;
      const uint64_t kind = rng.below(10);
      if (kind == 0 && previous.kind == MotionKind::kLine) {
        for (int i = 0; i < l.axes; ++i)
          c.delta[static_cast<size_t>(i)] = -previous.delta[static_cast<size_t>(i)];
      } else if (kind == 1) {
        // zero length
      } else {
        for (int i = 0; i < l.axes; ++i)
          c.delta[static_cast<size_t>(i)] =
              rng.chance(1, 4) ? 0 : std::min<int64_t>(random_delta_magnitude(rng), dmax) * sign();
      }
    } else {
      c.kind = MotionKind::kArc;
      c.plane = static_cast<int>(rng.below(3));
      c.ccw = rng.chance(1, 2);
      // Radius log-uniform over 1.5 .. 3000 steps (within the widths).
      const double r = std::min(1.5 * std::pow(2000.0, unit(rng)), static_cast<double>(cmax) / 2);
      const double a0 = unit(rng) * 2 * kPi;
      c.center = {std::llround(-r * std::cos(a0)), std::llround(-r * std::sin(a0))};
      const double sx = static_cast<double>(-c.center[0]), sy = static_cast<double>(-c.center[1]);
      const double rs = std::hypot(sx, sy);
      if (rng.chance(1, 12)) {
        c.end = {0, 0};  // a full circle
      } else {
        const double sweep = unit(rng) * 2 * kPi;
        const double a1 = std::atan2(sy, sx) + (c.ccw ? sweep : -sweep);
        const double off = rng.chance(1, 4) ? static_cast<double>(rng.range(-2, 2)) : 0.0;
        c.end = {std::llround((rs + off) * std::cos(a1)) - static_cast<int64_t>(std::llround(sx)),
                 std::llround((rs + off) * std::sin(a1)) - static_cast<int64_t>(std::llround(sy))};
      }
      c.ops = models::motion_arc_ops(c.center, c.end, c.ccw);
      if (c.ops > ops_lim) continue;
      // Slaved axes: none, or up to the operations (at most one step each).
      const auto p = models::motion_plane_axes(c.plane);
      for (int i = 0; i < l.axes; ++i) {
        if (i == p[0] || i == p[1] || rng.chance(1, 3)) continue;
        const int64_t most =
            static_cast<int64_t>(std::min<uint64_t>(c.ops, static_cast<uint64_t>(dmax)));
        // Sometimes the extreme: a step on every operation (|delta| = N).
        const int64_t mag = rng.chance(1, 6)   ? most
                            : rng.chance(1, 3) ? rng.range(0, most)
                                               : rng.range(0, std::max<int64_t>(most / 8, 1));
        c.delta[static_cast<size_t>(i)] = mag * sign();
      }
    }
    // Stays inside the window, and inside the widths (validate's rules).
    models::LatticePoint next = at;
    apply(c, next);
    bool inside = true;
    for (const int64_t v : next) inside = inside && std::llabs(v) <= room;
    if (!inside) continue;
    try {
      validate(c, at, l, "random");
    } catch (const UsageError&) {
      continue;
    }
    return c;
  }
  // Nothing fitted (near the edge of the window): a line towards the origin.
  Command c;
  c.feed = static_cast<uint32_t>(full);
  for (size_t i = 0; i < at.size(); ++i) c.delta[i] = std::clamp<int64_t>(-at[i], -50, 50);
  return c;
}

bool Adapter::job_directive(JobLine<Adapter>& line) {
  const auto& w = line.words;
  const std::string& key = w[0];
  if (key == "movefeed") {
    if (w.size() != 2) throw UsageError(line.where + ": 'movefeed' takes one value");
    line.settings().setup.move_feed = parse_feed(w[1], line.spec, line.where);
    if (line.settings().setup.move_feed == 0)
      throw UsageError(line.where + ": movefeed 0 would never move; give a feed > 0");
    return true;
  }
  if (key != "line" && key != "move" && key != "arc") return false;
  Command c;
  const uint64_t mf = line.current_settings().setup.move_feed;
  c.feed = static_cast<uint32_t>(mf ? mf : full_feed(line.spec));
  const models::LatticePoint& at = line.at();
  if (key != "arc") {
    const models::LatticePoint v = line.point(1);
    for (size_t i = 0; i < v.size(); ++i) c.delta[i] = key == "line" ? v[i] - at[i] : v[i];
    line.command(c);
    return true;
  }
  // arc PLANE CX CY X1 Y1 cw|ccw [END...]
  if (w.size() < 7)
    throw UsageError(line.where +
                     ": 'arc' takes xy|zx|yz CX CY X1 Y1 cw|ccw [END of the other axes...]");
  const std::string& plane = w[1];
  if (plane != "xy" && plane != "zx" && plane != "yz")
    throw UsageError(line.where + ": arc plane must be xy, zx or yz, not '" + plane + "'");
  c.kind = MotionKind::kArc;
  c.plane = plane == "xy" ? 0 : plane == "zx" ? 1 : 2;
  const std::vector<int64_t> v = line.integers(2, 4);
  if (w[6] != "cw" && w[6] != "ccw")
    throw UsageError(line.where + ": arc direction must be 'cw' or 'ccw', not '" + w[6] + "'");
  c.ccw = w[6] == "ccw";
  const auto p = models::motion_plane_axes(c.plane);
  const size_t px = static_cast<size_t>(p[0]), py = static_cast<size_t>(p[1]);
  c.center = {v[0] - at[px], v[1] - at[py]};
  c.end = {v[2] - at[px], v[3] - at[py]};
  const std::vector<int64_t> ends = line.integers(7);
  size_t k = 0;
  for (int i = 0; i < line.spec.axes; ++i) {
    if (static_cast<size_t>(i) == px || static_cast<size_t>(i) == py) continue;
    if (k < ends.size()) c.delta[static_cast<size_t>(i)] = ends[k++] - at[static_cast<size_t>(i)];
  }
  if (k < ends.size())
    throw UsageError(line.where + ": 'arc' has " + std::to_string(ends.size()) +
                     " end values for the other axes; there are " +
                     std::to_string(line.spec.axes - 2));
  c.ops = models::motion_arc_ops(c.center, c.end, c.ccw);
  line.command(c);
  return true;
}

std::vector<Case<Adapter>> Adapter::regression_cases(const VariantSpec& l, uint64_t commands,
                                                     uint64_t seed) {
  const RunSettings<Adapter> plain = default_settings<Adapter>(l);
  std::vector<Case<Adapter>> cases = cases_from_options(cli::Args("", ""), l, plain);
  append_random_streams(cases, l, commands, seed);
  return cases;
}

void Adapter::declare_options(cli::Args& args) {
  args.flag("demo",
            "a rounded rectangle (lines and quarter arcs in XY), a two-turn helix, and arcs in "
            "ZX and YZ");
}

std::vector<Case<Adapter>> Adapter::cases_from_options(const cli::Args&, const VariantSpec& l,
                                                       const RunSettings<Adapter>& settings) {
  // Scaled to the variant: a radius of a quarter of the arc coordinates' reach, at most 400.
  const int64_t r = std::min<int64_t>(400, signed_max(l.param("COORD_W")) / 4);
  const int64_t side = 2 * r;
  const std::string z = l.axes > 3 ? " 0" : "";
  std::string job =
      "case rounded_rectangle\n"
      "move " +
      std::to_string(side) +
      " 0 0\n"
      "arc xy " +
      std::to_string(side) + " " + std::to_string(r) + " " + std::to_string(side + r) + " " +
      std::to_string(r) + " ccw 0" + z +
      "\n"
      "move 0 " +
      std::to_string(side) +
      " 0\n"
      "arc xy " +
      std::to_string(side) + " " + std::to_string(side + r) + " " + std::to_string(side) + " " +
      std::to_string(side + 2 * r) + " ccw 0" + z +
      "\n"
      "move -" +
      std::to_string(side) +
      " 0 0\n"
      "arc xy 0 " +
      std::to_string(side + r) + " -" + std::to_string(r) + " " + std::to_string(side + r) +
      " ccw 0" + z +
      "\n"
      "move 0 -" +
      std::to_string(side) +
      " 0\n"
      "arc xy 0 " +
      std::to_string(r) + " 0 0 ccw 0" + z +
      "\n"
      "case helix\n"
      "start " +
      std::to_string(r) +
      " 0 0\n"
      "arc xy 0 0 " +
      std::to_string(r) + " 0 ccw " + std::to_string(r) + z +
      "\n"
      "arc xy 0 0 " +
      std::to_string(r) + " 0 ccw " + std::to_string(2 * r) + z +
      "\n"
      "case arcs_zx_yz\n"
      "arc zx " +
      std::to_string(r) + " 0 " + std::to_string(r) + " " + std::to_string(r) + " cw " +
      std::to_string(r / 2) + z +
      "\n"
      "arc yz 0 " +
      std::to_string(r) + " " + std::to_string(r) + " " + std::to_string(r) + " ccw " +
      std::to_string(r / 3) + z + "\n";
  std::istringstream in(job);
  return parse_job<Adapter>(in, "motion_top --demo", l, settings);
}

}  // namespace hwinterp::tb::cores::motion_top

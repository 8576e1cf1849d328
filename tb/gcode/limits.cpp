#include "tb/gcode/limits.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "tb/base/args.h"
#include "tb/base/text_table.h"
#include "tb/gcode/helix.h"

namespace hwinterp::gcode {

namespace {

constexpr double kQuarter = 1.5707963267948966192313216916398;

void widen(Reach& r, const std::array<double, kAxes>& p) {
  for (size_t i = 0; i < p.size(); ++i) {
    r.lo[i] = std::min(r.lo[i], p[i]);
    r.hi[i] = std::max(r.hi[i], p[i]);
  }
}

std::string unit(int axis) { return axis < kA ? "mm" : "deg"; }

}  // namespace

Reach move_reach(const std::array<double, kAxes>& start, const Move& move) {
  Reach r{start, start};
  widen(r, move.end);
  if (move.kind != MoveKind::kArc) return r;
  const Helix h(start, move);
  const auto f = static_cast<size_t>(h.first()), g = static_cast<size_t>(h.second());
  const double a0 = std::atan2(start[g] - h.c2(), start[f] - h.c1());
  const double d = h.ccw() ? 1.0 : -1.0;
  const double a1 = a0 + d * h.theta();
  const double lo = std::min(a0, a1), hi = std::max(a0, a1);
  for (double k = std::ceil(lo / kQuarter); k * kQuarter <= hi; k += 1) {
    const double t = std::abs(k * kQuarter - a0) / h.theta();
    if (t > 0 && t < 1) widen(r, h.point(t));
  }
  return r;
}

uint64_t check_reach(MoveSource& source, const Machine& machine, int pos_w, const std::string& core,
                     const std::string& name) {
  const double counter = std::ldexp(1.0, pos_w - 1) - 1;  // |p| <= 2^(POS_W-1) - 1
  std::array<double, kAxes> at{};
  uint64_t moves = 0;
  for (Move m; source.next(m); at = m.end, ++moves) {
    const Reach r = move_reach(at, m);
    const std::string where = name + ":" + std::to_string(m.line) + ": ";
    for (int i = 0; i < kAxes; ++i) {
      if (!machine.has_axis[i]) continue;
      const auto a = static_cast<size_t>(i);
      const std::string axis(1, kAxisNames[i]);
      const Travel& t = machine.travel[a];
      for (const double v : {r.lo[a], r.hi[a]})
        if (v < t.min || v > t.max)
          throw cli::UsageError(where + axis + " reaches " + fmt("%.6g", v) + " " + unit(i) +
                                ", outside the machine's travel [" + fmt("%.6g", t.min) + ", " +
                                fmt("%.6g", t.max) + "]");
      const bool plane = m.kind == MoveKind::kArc &&
                         (i == plane_axes(m.plane).first || i == plane_axes(m.plane).second);
      const double spu = static_cast<double>(machine.steps_per_unit[a]);
      for (const double v : {r.lo[a], r.hi[a]}) {
        const double steps = std::abs(std::round(v * spu)) + (plane ? 1 : 0);
        if (steps > counter)
          throw cli::UsageError(where + axis + " reaches " + fmt("%.6g", v) + " " + unit(i) +
                                " = " + fmt("%.6g", std::round(v * spu)) + " steps, beyond " +
                                core + "'s position counters (POS_W " + std::to_string(pos_w) +
                                ": |steps| <= " + fmt("%.0f", counter) + ")");
      }
    }
  }
  return moves;
}

}  // namespace hwinterp::gcode

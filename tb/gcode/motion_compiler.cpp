#include "tb/gcode/motion_compiler.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "models/common.h"
#include "tb/base/args.h"
#include "tb/gcode/helix.h"

namespace hwinterp::gcode {

namespace {
using models::kPi;
using models::kTwoPi;
using models::magnitude;

constexpr double kMaxPieceSweep = 1.5 * kPi;     // arc pieces: no end near its start
constexpr double kSweepTolerance = kPi / 4;      // rule M's sweep against the programmed one
constexpr double kSagitta = 0.4;                 // steps: a chord's ideal error, below 0.5
constexpr int64_t kPpcLimit = int64_t{1} << 29;  // PPC model: |v| < 2^30 for v and e - c
constexpr double kLatticeLimit = 4611686018427387904.0;  // 2^62

int64_t signed_max(int bits) { return (int64_t{1} << (bits - 1)) - 1; }

std::string number(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// Engine operations of a line: 2^n, n the bit length of max |delta|.
uint64_t line_operations(const models::MotionCommand& c) {
  uint64_t m = 0;
  for (const int64_t d : c.delta) m = std::max(m, magnitude(d));
  int n = 0;
  while (n < 64 && (m >> n) != 0) ++n;
  return uint64_t{1} << n;
}

// The largest gap between the L1 progress of the helix's plane path and its
// angular (parameter) progress over [t0, t1], as a fraction of the piece:
// 64 samples.
double progress_gap(const Helix& h, double t0, double t1) {
  constexpr int n = 64;
  std::array<double, n + 1> l1{};
  const auto f = static_cast<size_t>(h.first()), g = static_cast<size_t>(h.second());
  std::array<double, 6> prev = h.point(t0);
  for (int i = 1; i <= n; ++i) {
    const std::array<double, 6> p = h.point(t0 + (t1 - t0) * i / n);
    l1[static_cast<size_t>(i)] =
        l1[static_cast<size_t>(i - 1)] + std::abs(p[f] - prev[f]) + std::abs(p[g] - prev[g]);
    prev = p;
  }
  const double total = l1[n];
  if (!(total > 0)) return 0;
  double gap = 0;
  for (int i = 1; i < n; ++i)
    gap = std::max(gap, std::abs(l1[static_cast<size_t>(i)] / total - static_cast<double>(i) / n));
  return gap;
}

constexpr uint64_t kMaxArcPieces = uint64_t{1} << 16;

}  // namespace

// --- feed words and clocks ------------------------------------------------------------

uint64_t FeedClock::run(uint64_t operations, uint64_t word) {
  const uint64_t one = uint64_t{1} << feed_w_;
  if (word >= one) return operations;  // full feed: one operation a clock, the phase holds
  if (word == 0) word = 1;             // (a feed word is never 0 here; 0 would hold)
  const unsigned __int128 need = (static_cast<unsigned __int128>(operations) << feed_w_) - phase_;
  const unsigned __int128 clocks = (need + word - 1) / word;
  phase_ = static_cast<uint64_t>(phase_ + clocks * word -
                                 (static_cast<unsigned __int128>(operations) << feed_w_));
  return static_cast<uint64_t>(clocks);
}

uint32_t feed_word(uint64_t operations, double clocks, int feed_w) {
  const uint64_t one = uint64_t{1} << feed_w;
  if (!(clocks > 0)) return static_cast<uint32_t>(one);
  const long double w = std::ceil(static_cast<long double>(operations) *
                                  static_cast<long double>(one) / static_cast<long double>(clocks));
  if (w >= static_cast<long double>(one)) return static_cast<uint32_t>(one);
  if (w < 1) return 1;
  return static_cast<uint32_t>(w);
}

// --- the plan of one move -----------------------------------------------------------------

struct MotionCompiler::Plan {
  enum Kind { kLine, kArc } kind = kLine;
  std::array<double, 6> s{}, e{};  // programmed start and end
  uint64_t pieces = 1, piece = 0;  // k, and the pieces begun
  double seconds = 0;              // the move's programmed time
  // arcs
  std::optional<Helix> helix;
  int plane = 0;
  double length = 0;                // XYZ length of the helix
  std::array<int64_t, 2> center{};  // rounded centre (plane axes, canon order)
  bool equal_steps = true;
  double radius_steps = 0;  // max(r1, r2) * the larger steps per unit of the plane
  // chords of the current piece
  uint64_t chords = 0, chord = 0;
  double ta = 0, tb = 0, t_prev = 0;

  // The programmed path's point at parameter t in [0, 1] (exactly e at 1).
  std::array<double, 6> point(double t) const {
    if (helix) return helix->point(t);
    if (t >= 1) return e;
    std::array<double, 6> p{};
    for (size_t i = 0; i < 6; ++i) p[i] = s[i] + (e[i] - s[i]) * t;
    return p;
  }
  // The programmed time between parameters t0 and t1 of an arc.
  double arc_seconds(double t0, double t1) const {
    return length > 0 ? seconds * helix->length(t0, t1) / length : 0;
  }
};

// --- the compiler ---------------------------------------------------------------------------

MotionCompiler::MotionCompiler(MoveSource& source, const Machine& machine,
                               const MotionWidths& widths, FeedMode mode, std::string name,
                               ReportSink sink, const CompilerOptions& options)
    : source_(source),
      machine_(machine),
      widths_(widths),
      mode_(mode),
      options_(options),
      name_(std::move(name)),
      sink_(std::move(sink)),
      full_clock_(widths.feed_w),
      programmed_clock_(widths.feed_w) {
  auto range = [](const char* what, int v, int lo, int hi) {
    if (v < lo || v > hi)
      throw cli::UsageError(std::string("motion_top widths: ") + what + " = " + std::to_string(v) +
                            " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  };
  range("AXES", widths.axes, 3, models::kMotionMaxAxes);
  // rtl/motion_top.sv's ranges, which it checks at elaboration.
  range("ACC_W", widths.acc_w, 4, 62);
  range("COORD_W", widths.coord_w, 3, 60);
  range("OPS_W", widths.ops_w, 1, widths.acc_w - 1);
  range("FEED_W", widths.feed_w, 1, 31);
  if (!(options.arc_tolerance_steps > 0))
    throw cli::UsageError("arc tolerance " + number(options.arc_tolerance_steps) +
                          " steps: must be > 0");
  for (int a = widths.axes; a < kAxes; ++a)
    if (machine.has_axis[static_cast<size_t>(a)])
      throw cli::UsageError(std::string("the machine's ") + kAxisNames[a] +
                            " axis is beyond the core's " + std::to_string(widths.axes) +
                            " axes (" + std::string(kAxisNames).substr(0, widths.axes) + ")");
}

MotionCompiler::~MotionCompiler() = default;

void MotionCompiler::fail(const std::string& what) const {
  throw cli::UsageError(name_ + ":" + std::to_string(move_.line) + ": " + what);
}

bool MotionCompiler::next(models::MotionCommand& command) {
  for (;;) {
    if (plan_) {
      if (make_command(command)) return true;
      finish_move();
    }
    if (!source_.next(move_)) return false;
    plan_move();
  }
}

void MotionCompiler::plan_move() {
  const Move& m = move_;
  move_start_ = prev_end_;
  auto p = std::make_unique<Plan>();
  p->s = move_start_;
  p->e = m.end;
  ++moves_;
  report_ = MoveReport{};
  report_.index = moves_;
  report_.kind = m.kind;
  report_.line = m.line;
  for (size_t i = 0; i < 4; ++i) report_.end[i] = m.end[i];

  // Axes the machine lacks must not move.
  for (int a = 0; a < kAxes; ++a) {
    const auto i = static_cast<size_t>(a);
    if (!machine_.has_axis[i] && m.end[i] != p->s[i])
      fail(std::string("the move takes ") + kAxisNames[a] + " from " + number(p->s[i]) + " to " +
           number(m.end[i]) + " but the machine has no " + kAxisNames[a] + " axis (axes " +
           machine_.axes() + ")");
  }
  for (int a = 0; a < kAxes; ++a) {
    const auto i = static_cast<size_t>(a);
    const double v = m.end[i] * static_cast<double>(machine_.steps_per_unit[i]);
    if (machine_.has_axis[i] && !(std::abs(v) < kLatticeLimit))
      fail(std::string(kAxisNames).substr(i, 1) + " = " + number(m.end[i]) + " is " + number(v) +
           " steps, beyond 2^62");
    report_.end_steps[i] = machine_.has_axis[i] ? std::llround(v) : 0;
  }

  // Length and rate (LinuxCNC: XYZ length, or ABC for a rotary-only move).
  double xyz = 0, abc = 0;
  for (int a = 0; a < 3; ++a)
    xyz += std::pow(m.end[static_cast<size_t>(a)] - p->s[static_cast<size_t>(a)], 2);
  for (int a = 3; a < 6; ++a)
    abc += std::pow(m.end[static_cast<size_t>(a)] - p->s[static_cast<size_t>(a)], 2);
  xyz = std::sqrt(xyz);
  abc = std::sqrt(abc);

  if (m.kind == MoveKind::kArc) {
    p->kind = Plan::kArc;
    p->plane = m.plane == Plane::kXY ? 0 : m.plane == Plane::kXZ ? 1 : 2;
    const PlaneAxes pa = plane_axes(m.plane);
    for (const int a : {pa.first, pa.second})
      if (!machine_.has_axis[static_cast<size_t>(a)])
        fail(std::string("an arc in the ") + to_string(m.plane) + " plane moves " + kAxisNames[a] +
             " but the machine has no " + kAxisNames[a] + " axis (axes " + machine_.axes() + ")");
    const Helix& h = p->helix.emplace(p->s, m);
    const auto f = static_cast<size_t>(pa.first), g = static_cast<size_t>(pa.second);
    p->length = h.length(0, 1);
    const bool full_circle =
        std::abs(m.rotation) == 1 && m.end[f] == p->s[f] && m.end[g] == p->s[g];
    p->pieces = h.theta() > kMaxPieceSweep && !full_circle
                    ? static_cast<uint64_t>(std::ceil(h.theta() / kMaxPieceSweep))
                    : 1;
    // Arc tolerance: spirals, then the slaved axes' progress.
    const int64_t sf = machine_.steps_per_unit[f], sg = machine_.steps_per_unit[g];
    const double tol = options_.arc_tolerance_steps;
    if (std::isfinite(tol)) {
      const double dr = std::abs(h.r2() - h.r1()) * static_cast<double>(std::max(sf, sg));
      if (dr > tol)
        p->pieces = std::max(p->pieces,
                             std::min(kMaxArcPieces, static_cast<uint64_t>(std::ceil(dr / tol))));
      double slaved = 0;  // the largest slaved travel, steps
      for (size_t a = 0; a < static_cast<size_t>(widths_.axes); ++a)
        if (a != f && a != g && machine_.has_axis[a])
          slaved = std::max(slaved, std::abs(m.end[a] - p->s[a]) *
                                        static_cast<double>(machine_.steps_per_unit[a]));
      for (int round = 0; slaved > 0 && round < 16 && p->pieces < kMaxArcPieces; ++round) {
        const auto k = static_cast<double>(p->pieces);
        double worst = 0;
        for (uint64_t i = 0; i < p->pieces; ++i)
          worst = std::max(worst, slaved / k *
                                      progress_gap(h, static_cast<double>(i) / k,
                                                   static_cast<double>(i + 1) / k));
        if (worst <= tol) break;
        p->pieces =
            std::min(kMaxArcPieces,
                     std::max(p->pieces + 1,
                              static_cast<uint64_t>(std::ceil(k * std::sqrt(worst / tol) * 1.05))));
      }
    }
    p->equal_steps = sf == sg;
    p->radius_steps = std::max(h.r1(), h.r2()) * static_cast<double>(std::max(sf, sg));
    p->center = {std::llround(h.c1() * static_cast<double>(sf)),
                 std::llround(h.c2() * static_cast<double>(sg))};
    report_.length_mm = p->length;
  } else {
    p->kind = Plan::kLine;
    report_.length_mm = xyz > 0 ? xyz : abc;
    // Pieces for ACC_W: D the largest axis travel in steps.
    double travel = 0;
    for (int a = 0; a < kAxes; ++a) {
      const auto i = static_cast<size_t>(a);
      if (machine_.has_axis[i])
        travel = std::max(
            travel, std::abs(m.end[i] - p->s[i]) * static_cast<double>(machine_.steps_per_unit[i]));
    }
    const auto room = static_cast<double>(signed_max(widths_.acc_w) - 1);
    p->pieces = travel + 1 > room ? static_cast<uint64_t>(std::ceil((travel + 1) / room)) : 1;
  }
  report_.pieces = p->pieces;

  if (report_.length_mm > 0) {
    double rate = m.kind == MoveKind::kTraverse ? machine_.rapid_mm_per_min : m.feed;
    if (!(rate > 0))
      fail(std::string("a ") + to_string(m.kind) + " move at feed rate " + number(m.feed) +
           " (no F in force)");
    p->seconds = report_.length_mm / rate * 60.0;
  }
  report_.programmed_s = p->seconds;
  prev_end_ = m.end;
  plan_ = std::move(p);
}

bool MotionCompiler::make_command(models::MotionCommand& c) {
  Plan& p = *plan_;
  auto lattice = [&](const std::array<double, 6>& pt) {
    std::array<int64_t, 6> l{};
    for (size_t i = 0; i < 6; ++i)
      if (machine_.has_axis[i])
        l[i] = std::llround(pt[i] * static_cast<double>(machine_.steps_per_unit[i]));
    return l;
  };
  const int axes = widths_.axes;
  const int64_t acc_max = signed_max(widths_.acc_w);
  double seconds = 0;
  bool chord = false;
  for (;;) {
    c = models::MotionCommand{};
    std::array<int64_t, 6> target{};
    if (p.kind == Plan::kLine) {
      if (p.piece >= p.pieces) return false;
      ++p.piece;
      target = p.piece == p.pieces
                   ? report_.end_steps
                   : lattice(p.point(static_cast<double>(p.piece) / static_cast<double>(p.pieces)));
      seconds = p.seconds / static_cast<double>(p.pieces);
    } else if (p.chord < p.chords) {
      ++p.chord;
      const double t = p.chord == p.chords ? p.tb
                                           : p.ta + (p.tb - p.ta) * static_cast<double>(p.chord) /
                                                        static_cast<double>(p.chords);
      target = t >= 1 ? report_.end_steps : lattice(p.point(t));
      seconds = p.arc_seconds(p.t_prev, t);
      p.t_prev = t;
      chord = true;
    } else {
      if (p.piece >= p.pieces) return false;
      ++p.piece;
      p.ta = static_cast<double>(p.piece - 1) / static_cast<double>(p.pieces);
      p.tb =
          p.piece == p.pieces ? 1.0 : static_cast<double>(p.piece) / static_cast<double>(p.pieces);
      target = p.piece == p.pieces ? report_.end_steps : lattice(p.point(p.tb));
      // Try the arc engine.
      const char* why = nullptr;
      const Helix& h = *p.helix;
      const auto f = static_cast<size_t>(h.first()), g = static_cast<size_t>(h.second());
      c.kind = models::MotionKind::kArc;
      c.plane = p.plane;
      c.ccw = h.ccw();
      c.center = {p.center[0] - at_[f], p.center[1] - at_[g]};
      c.end = {target[f] - at_[f], target[g] - at_[g]};
      for (int j = 0; j < axes; ++j) {
        const auto i = static_cast<size_t>(j);
        if (i != f && i != g) c.delta[i] = target[i] - at_[i];
      }
      const int64_t coord_max = std::min(signed_max(widths_.coord_w), kPpcLimit - 1);
      auto fits = [&](int64_t v) { return v <= coord_max && v >= -coord_max; };
      if (!p.equal_steps) {
        why = "the plane's axes have different steps per unit";
      } else if (!fits(c.center[0]) || !fits(c.center[1]) || !fits(c.end[0]) || !fits(c.end[1])) {
        why = "a coordinate exceeds COORD_W";
      } else {
        for (const int64_t d : c.delta)
          if (d > acc_max || d < -acc_max) why = "a slaved delta exceeds ACC_W";
      }
      if (!why) {
        const models::PpcArcStream rule({c.center[0], c.center[1]}, {0, 0}, {c.end[0], c.end[1]},
                                        c.ccw);
        const models::PpcArcIdeal ideal({c.center[0], c.center[1]}, {0, 0}, {c.end[0], c.end[1]},
                                        c.ccw);
        double swept = ideal.theta();
        if (rule.laps() == 0 && swept > kPi) swept -= kTwoPi;  // rule M goes back
        if (rule.laps() == 4 && swept < kPi) swept += kTwoPi;  // rule M laps first
        const double want = h.theta() * (p.tb - p.ta);
        if (rule.degenerate())
          why = "the rounded arc is degenerate for rule M";
        else if (std::abs(swept - want) > kSweepTolerance)
          why = "rule M would sweep another angle on the lattice";
      }
      if (!why) {
        c.ops = models::motion_arc_ops(c.center, c.end, c.ccw);
        if (widths_.ops_w < 64 && c.ops > (uint64_t{1} << widths_.ops_w) - 1) {
          why = "ops exceeds OPS_W";
        } else {
          for (const int64_t d : c.delta)
            if (magnitude(d) > c.ops) why = "a slaved axis needs more than one step per operation";
        }
      }
      if (why) {
        // Chords over this piece instead.
        if (report_.chord_reason[0] == '\0') report_.chord_reason = why;
        const double sweep = h.theta() * (p.tb - p.ta);
        double n = 1;
        if (p.radius_steps > kSagitta)
          n = std::max(
              n, std::ceil(sweep / (4 * std::asin(std::sqrt(kSagitta / 2 / p.radius_steps)))));
        double travel = p.radius_steps * sweep;
        for (int a = 0; a < kAxes; ++a) {
          const auto i = static_cast<size_t>(a);
          if (machine_.has_axis[i] && i != f && i != g)
            travel = std::max(travel, std::abs(p.e[i] - p.s[i]) * (p.tb - p.ta) *
                                          static_cast<double>(machine_.steps_per_unit[i]));
        }
        n = std::max(n, std::ceil(travel / static_cast<double>(acc_max - 2)));
        p.chords = static_cast<uint64_t>(n);
        p.chord = 0;
        p.t_prev = p.ta;
        continue;
      }
      seconds = p.arc_seconds(p.ta, p.tb);
    }
    if (c.kind == models::MotionKind::kLine) {
      bool any = false;
      for (int j = 0; j < axes; ++j) {
        const auto i = static_cast<size_t>(j);
        c.delta[i] = target[i] - at_[i];
        any = any || c.delta[i] != 0;
      }
      if (!any) continue;  // nothing to do on the lattice
    }
    // Feed word and clocks.
    const uint64_t ops = c.kind == models::MotionKind::kArc ? c.ops : line_operations(c);
    const uint32_t programmed =
        feed_word(ops, seconds * static_cast<double>(machine_.clock_hz), widths_.feed_w);
    const auto full = static_cast<uint32_t>(uint64_t{1} << widths_.feed_w);
    c.feed = mode_ == FeedMode::kFull ? full : programmed;
    info_ = CommandInfo{};
    info_.move_index = report_.index;
    info_.line = move_.line;
    info_.number = report_.commands + 1;
    info_.chord = chord;
    info_.start = at_;
    info_.operations = ops;
    info_.clocks_full = full_clock_.run(ops, full);
    info_.clocks_programmed = programmed_clock_.run(ops, programmed);
    at_ = target;
    ++report_.commands;
    if (c.kind == models::MotionKind::kArc) ++report_.arc_commands;
    if (chord) ++report_.chords;
    report_.operations += ops;
    report_.clocks_full += info_.clocks_full;
    report_.clocks_programmed += info_.clocks_programmed;
    report_.feed_min = report_.commands == 1 ? c.feed : std::min(report_.feed_min, c.feed);
    report_.feed_max = std::max(report_.feed_max, c.feed);
    return true;
  }
}

void MotionCompiler::finish_move() {
  const auto hz = static_cast<double>(machine_.clock_hz);
  report_.full_s = static_cast<double>(report_.clocks_full) / hz;
  report_.programmed_words_s = static_cast<double>(report_.clocks_programmed) / hz;
  CompileTotals& t = totals_;
  ++t.moves;
  t.commands += report_.commands;
  t.arc_commands += report_.arc_commands;
  t.line_commands += report_.commands - report_.arc_commands;
  if (report_.pieces > 1 && plan_->kind == Plan::kLine) {
    ++t.split_lines;
    t.line_pieces += report_.pieces;
  }
  if (report_.pieces > 1 && plan_->kind == Plan::kArc) {
    ++t.split_arcs;
    t.arc_pieces += report_.pieces;
  }
  if (report_.chords > 0) {
    ++t.chord_arcs;
    t.chords += report_.chords;
  }
  t.operations += report_.operations;
  t.clocks_full += report_.clocks_full;
  t.clocks_programmed += report_.clocks_programmed;
  t.length_mm += report_.length_mm;
  t.programmed_s += report_.programmed_s;
  t.full_s = static_cast<double>(t.clocks_full) / hz;
  t.programmed_words_s = static_cast<double>(t.clocks_programmed) / hz;
  plan_.reset();
  if (sink_) sink_(report_);
}

}  // namespace hwinterp::gcode

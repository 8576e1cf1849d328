#include "tb/gcode/part_program.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

// The Verilated root headers (for motion_top's done_o) trip -Wunused-parameter
// in Verilator 5.006's own verilated_types.h.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "hwinterp_soc.h"
#pragma GCC diagnostic pop
#include "models/feed_profile_model.h"
#include "tb/base/text_table.h"
#include "tb/bus/soc_run.h"
#include "tb/cores/motion_top/motion_top_adapter.h"
#include "tb/gcode/contour.h"
#include "tb/gcode/limits.h"
#include "tb/gcode/profile_plan.h"
#include "tb/gcode/soc_writes.h"
#include "tb/lockstep/bench_run.h"
#include "tb/lockstep/feed_profile_run.h"
#include "tb/lockstep/profile_feed.h"
#include "tb/monitor/kinematics.h"
#include "tb/report/cosim_report.h"
#include "tb/report/progress.h"

namespace hwinterp::gcode {

namespace {

using MotionAdapter = tb::cores::motion_top::Adapter;

constexpr const char* kAxisName[] = {"x", "y", "z", "a", "b", "c"};

// Units per step of each axis on the path: mm on X Y Z, 0 on the rotary axes
// (the feed, as LinuxCNC's, applies to XYZ).
std::vector<double> path_units(const Machine& m, int axes) {
  std::vector<double> u(static_cast<size_t>(axes), 0.0);
  for (int i = 0; i < axes && i < kA; ++i)
    u[static_cast<size_t>(i)] = 1.0 / static_cast<double>(m.steps_per_unit[i]);
  return u;
}

uint64_t kinematics_window(const Machine& m, double seconds) {
  return std::max<uint64_t>(
      1, static_cast<uint64_t>(std::llround(seconds * static_cast<double>(m.clock_hz))));
}

// One command on its way to the core, and the move it belongs to.
struct Pending {
  uint64_t command = 0;  // 0-based, as the scoreboard counts
  uint64_t move = 0;     // MoveReport::index
  uint64_t line = 0;     // the move's source line
  std::shared_ptr<const ContourPath> path;
};

// Streams the compiler's commands into the bench, and follows the moves the
// core makes: contour error per visited point, the lattice point each
// G-code move ends on, the moves CSV.
class Program final : public tb::ItemSource<MotionAdapter>, public tb::MoveObserver {
 public:
  Program(std::unique_ptr<MoveSource> source, const Machine& machine, const MotionWidths& widths,
          FeedMode mode, const std::string& name, std::ostream* moves_csv, std::ostream* points_csv,
          std::ostream* kinematics_csv, double kinematics_window_s, bool profiled)
      : profiled_(profiled),
        source_(std::move(source)),
        machine_(machine),
        compiler_(*source_, machine, widths, mode, name,
                  [this](const MoveReport& r) { reports_.push_back(r); }),
        axes_(widths.axes),
        moves_csv_(moves_csv),
        points_csv_(points_csv),
        last_reached_(static_cast<size_t>(widths.axes), 0),
        kinematics_(widths.axes, path_units(machine, widths.axes),
                    kinematics_window(machine, kinematics_window_s)) {
    if (moves_csv_) {
      *moves_csv_ << "move,line,kind,x_mm,y_mm,z_mm,a_deg";
      for (int i = 0; i < axes_; ++i) *moves_csv_ << ',' << kAxisName[i] << "_steps";
      *moves_csv_ << ",commands,chords,programmed_s,feed_words_s,max_contour_mm\n";
    }
    if (points_csv_) *points_csv_ << "move,x_mm,y_mm,z_mm,error_mm\n";
    std::vector<std::string> letters;
    for (int i = 0; i < axes_; ++i) letters.emplace_back(1, kAxisNames[i]);
    kinematics_.write_series(kinematics_csv, letters);
  }

  // tb::ItemSource: the next command of the program.
  bool next(tb::Item<MotionAdapter>& it) override {
    models::MotionCommand c;
    if (!next(c)) return false;
    if (profiled_) c.feed = 0;  // the move follows feed_i: the profile's word
    it = tb::command_item<MotionAdapter>(c);
    return true;
  }
  // The next command of the program (the bus run's source).
  bool next(models::MotionCommand& c) {
    if (!compiler_.next(c)) {
      flush_rows();
      return false;
    }
    const CommandInfo& info = compiler_.info();
    if (!path_ || path_move_ != info.move_index) {
      path_ = std::make_shared<ContourPath>(machine_, compiler_.move_start(), compiler_.move());
      path_move_ = info.move_index;
    }
    pending_.push_back({commands_++, info.move_index, info.line, path_});
    flush_rows();
    return true;
  }

  // tb::MoveObserver: a move of command `command`.
  void move(const models::LatticePoint& at, uint64_t command) override {
    const Pending* p = find(command);
    if (!p) return;
    const ContourError e = p->path->error(lattice6(at));
    move_max_[p->move] = std::max(move_max_[p->move], e.mm);
    if (e.mm > max_.mm) {
      max_.mm = e.mm;
      max_.steps = e.steps;
      max_.move = p->move;
      max_.line = p->line;
    }
    if (points_csv_) {
      *points_csv_ << p->move;
      for (int i = 0; i < 3; ++i)
        *points_csv_ << ','
                     << (i < axes_ ? static_cast<double>(at[static_cast<size_t>(i)]) /
                                         static_cast<double>(machine_.steps_per_unit[i])
                                   : 0.0);
      *points_csv_ << ',' << e.mm << '\n';
    }
    ++points_;
  }

  // tb::MoveObserver: the pulses on the wire.
  void pulses(uint64_t clock, uint32_t rising, uint32_t dir) override {
    kinematics_.pulses(clock, rising, dir);
  }

  // tb::MoveObserver: command `command` completed at `at`.
  void done(uint64_t command, const models::LatticePoint& at) override {
    while (!pending_.empty() && pending_.front().command < command) pending_.pop_front();
    if (!pending_.empty() && pending_.front().command == command) {
      reached_[pending_.front().move] = at;
      last_reached_ = at;
      pending_.pop_front();
    }
    flush_rows();
  }

  const MotionCompiler& compiler() const { return compiler_; }
  const ReaderStats& reader_stats() const { return source_->stats(); }
  const ContourMax& max() const { return max_; }
  uint64_t points() const { return points_; }
  tb::KinematicsMonitor& kinematics() { return kinematics_; }

  // The rows of every reported move whose last command the core completed.
  void flush_rows() {
    while (!reports_.empty()) {
      const MoveReport& r = reports_.front();
      std::optional<models::LatticePoint> at;  // where the move ended, once known
      if (r.commands == 0) {
        at = last_reached_;
      } else if (auto f = reached_.find(r.index); f != reached_.end() && !still_pending(r.index)) {
        at = f->second;
      }
      if (!at) return;
      if (moves_csv_) {
        *moves_csv_ << r.index << ',' << r.line << ',' << to_string(r.kind);
        for (int i = 0; i < 4; ++i) *moves_csv_ << ',' << r.end[static_cast<size_t>(i)];
        for (int i = 0; i < axes_; ++i)
          *moves_csv_ << ',' << (at->empty() ? 0 : (*at)[static_cast<size_t>(i)]);
        *moves_csv_ << ',' << r.commands << ',' << r.chords << ',' << r.programmed_s << ','
                    << r.programmed_words_s << ',' << move_max_[r.index] << '\n';
      }
      if (!at->empty()) {
        for (int i = 0; i < axes_; ++i)
          if ((*at)[static_cast<size_t>(i)] != r.end_steps[static_cast<size_t>(i)])
            end_mismatches_.push_back(r.index);
      }
      reached_.erase(r.index);
      move_max_.erase(r.index);
      reports_.pop_front();
    }
  }
  const std::vector<uint64_t>& end_mismatches() const { return end_mismatches_; }
  bool all_rows_written() const { return reports_.empty(); }

 private:
  static std::array<int64_t, 6> lattice6(const models::LatticePoint& at) {
    std::array<int64_t, 6> a{};
    for (size_t i = 0; i < at.size() && i < a.size(); ++i) a[i] = at[i];
    return a;
  }
  const Pending* find(uint64_t command) const {
    for (const Pending& p : pending_)
      if (p.command == command) return &p;
    return nullptr;
  }
  bool still_pending(uint64_t move) const {
    return std::any_of(pending_.begin(), pending_.end(),
                       [&](const Pending& p) { return p.move == move; });
  }

  bool profiled_;
  std::unique_ptr<MoveSource> source_;
  Machine machine_;
  MotionCompiler compiler_;
  int axes_;
  std::ostream* moves_csv_;
  std::ostream* points_csv_;
  std::deque<Pending> pending_;                       // commands made and not yet completed
  std::deque<MoveReport> reports_;                    // moves compiled, rows not yet written
  std::map<uint64_t, models::LatticePoint> reached_;  // move -> where its last command ended
  std::map<uint64_t, double> move_max_;               // move -> its worst contour error
  models::LatticePoint last_reached_;  // where the last completed command ended (the origin first)
  std::shared_ptr<const ContourPath> path_;
  uint64_t path_move_ = 0;
  uint64_t commands_ = 0, points_ = 0;
  ContourMax max_;
  std::vector<uint64_t> end_mismatches_;
  tb::KinematicsMonitor kinematics_;
};

// This process's peak resident memory in KiB (VmHWM: since exec, so not the
// parent's), 0 where /proc does not say.
uint64_t peak_rss_kib() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::strtoull(line.c_str() + 6, nullptr, 10);
  return 0;
}

int machine_axes(const Machine& m) {
  int axes = 0;
  for (int i = 0; i < 6; ++i)
    if (m.has_axis[i]) axes = i + 1;
  return axes;
}

// The motion_top variants and the one the setup picks.
struct Chosen {
  std::vector<tb::TypedVariant<MotionAdapter>> all;
  size_t index = 0;
  const tb::TypedVariant<MotionAdapter>& variant() const { return all[index]; }
};

Chosen choose(const PartProgramSetup& setup) {
  Chosen c;
  c.all = tb::typed_variants<MotionAdapter>();
  std::vector<tb::VariantSpec> specs;
  for (const auto& v : c.all) specs.push_back(v.spec);
  const int axes = machine_axes(setup.machine);
  c.index = tb::choose_variant(MotionAdapter::kName, specs, {setup.variant, axes, true});
  const tb::VariantSpec& l = c.variant().spec;
  if (l.axes < axes)
    throw cli::UsageError("--variant: " + l.variant + " has " + std::to_string(l.axes) +
                          " axes, the machine " + std::to_string(axes));
  return c;
}

std::unique_ptr<MoveSource> open_source(const PartProgramSetup& setup) {
  return setup.canon ? open_canon(setup.program) : open_ngc(setup.program);
}

// The monitor's peaks in units per s^k, beside the machine's limits.
Kinematics kinematics_of(const tb::KinematicsMonitor& k, const Machine& m) {
  const double hz = static_cast<double>(m.clock_hz);
  const double w = static_cast<double>(k.window_clocks());
  const tb::KinematicsMonitor::Peaks tol = k.tolerance();
  // `unit` per clock^k -> per s^k; the tolerance in steps per clock^k times `tol_unit`
  auto peak = [&](const tb::KinematicsMonitor::Peak& p, double tol_steps, double unit,
                  double tol_unit, int order, double limit) {
    const double scale = std::pow(hz, order);
    return KinematicPeak{p.value * unit * scale, static_cast<double>(p.clock + 1) / hz,
                         tol_steps * tol_unit * scale, limit};
  };
  auto row = [&](std::string name, std::string unit, int axis, double unit_per_step,
                 double tol_unit, const tb::KinematicsMonitor::Peaks& p, const AxisLimits& l) {
    return KinematicRow{std::move(name),
                        std::move(unit),
                        axis,
                        unit_per_step,
                        peak(p.speed, tol.speed.value, unit_per_step, tol_unit, 1, l.velocity),
                        peak(p.accel, tol.accel.value, unit_per_step, tol_unit, 2, l.accel),
                        peak(p.jerk, tol.jerk.value, unit_per_step, tol_unit, 3, l.jerk)};
  };
  Kinematics out;
  out.window_s = w / hz;
  out.windows = k.windows();
  // The path's peaks are in mm already; its tolerance adds the per-axis
  // errors (steps' lengths in mm) as a vector.
  double path_unit = 0;
  for (int i = 0; i < kA; ++i)
    if (m.has_axis[i]) path_unit += std::pow(1.0 / static_cast<double>(m.steps_per_unit[i]), 2);
  out.rows.push_back(row("path", "mm", -1, 1, std::sqrt(path_unit), k.path(), AxisLimits{}));
  for (int i = 0; i < kAxes; ++i) {
    if (!m.has_axis[i]) continue;
    const double unit = 1.0 / static_cast<double>(m.steps_per_unit[i]);
    out.rows.push_back(row(std::string(1, kAxisNames[i]), i < kA ? "mm" : "deg", i, unit, unit,
                           k.axis(i), m.limits[static_cast<size_t>(i)]));
  }
  return out;
}

// The machine's limits, within the estimator's tolerance, on every axis and
// the path: one failure line per quantity above its limit (a trapezoid
// limits the acceleration only: its jerk is not checked).
std::vector<std::string> limit_failures(const Kinematics& k, ProfileKind kind,
                                        const std::string& prefix) {
  std::vector<std::string> out;
  for (const KinematicRow& row : k.rows) {
    const std::pair<const char*, const KinematicPeak*> peaks[] = {
        {"speed", &row.speed}, {"acceleration", &row.accel}, {"jerk", &row.jerk}};
    for (const auto& [what, p] : peaks)
      if (std::isfinite(p->limit) && p->max > p->limit + p->tolerance &&
          !(kind == ProfileKind::kTrapezoid && p == &row.jerk))
        out.push_back(prefix + row.name + " " + what + " " + fmt("%.6g", p->max) +
                      " above its limit " + fmt("%.6g", p->limit) + " + " +
                      fmt("%.3g", p->tolerance) + " at " + fmt("%.4f", p->at_s) + " s");
  }
  return out;
}

// The feed profile's moves of a program, one per command in order: a
// planner on its own pass over the program (its registers from the limits
// of the axes the program moves), a window of commands ahead.
// The least clocks the step/dir stage lets `mc` take: its busiest axis's
// steps at one step each step_len + step_space clocks. An arc's operations
// step its plane axes, one step each; the busier axis takes about 0.707 of
// them (over a circle, the mean of max(|cos|, |sin|) against that of
// |cos| + |sin|).
double step_bound_clocks(const models::MotionCommand& mc, const StepTiming& t) {
  double steps = 0;
  for (const int64_t d : mc.delta) steps = std::max(steps, std::fabs(static_cast<double>(d)));
  if (mc.kind == models::MotionKind::kArc)
    steps = std::max(steps, 0.707 * static_cast<double>(models::motion_operations(mc)));
  return steps * static_cast<double>(t.step_len + t.step_space);
}

// The clocks a run without the profile takes, estimated before it runs:
// each command at its feed word (operations a clock: feed / 2^FEED_W; 0: the
// pin's full feed) or at the step/dir stage's rate, whichever is slower.
// A run beyond --max-clocks is refused before it runs, naming its slowest
// command's line.
double estimate_direct_clocks(const PartProgramSetup& setup, const MotionWidths& widths,
                              int feed_w) {
  auto src = open_source(setup);
  MotionCompiler pass(*src, setup.machine, widths, setup.feed_mode, setup.program);
  const double full = std::ldexp(1.0, feed_w);
  double clocks = 0, slowest = 0;
  uint64_t slowest_line = 0;
  models::MotionCommand mc;
  while (pass.next(mc)) {
    const double feed = mc.feed == 0 ? full : std::min(full, static_cast<double>(mc.feed));
    const double c = std::max(static_cast<double>(models::motion_operations(mc)) * full / feed,
                              step_bound_clocks(mc, setup.machine.timing));
    clocks += c;
    if (c > slowest) slowest = c, slowest_line = pass.info().line;
  }
  if (clocks > setup.max_clocks) {
    const double hz = static_cast<double>(setup.machine.clock_hz);
    throw cli::UsageError(setup.program + ":" + std::to_string(slowest_line) +
                          ": the program takes about " + fmt("%.3g", clocks) + " clocks (" +
                          fmt("%.3g", clocks / hz) + " s at clock_hz " + fmt("%g", hz) +
                          "), beyond --max-clocks " + fmt("%g", setup.max_clocks) +
                          "; its slowest move, on this line, " + fmt("%.3g", slowest) +
                          " clocks at its feed (give a larger --max-clocks to simulate it)");
  }
  return clocks;
}

// A run estimated to take more than two minutes says so before it starts,
// at the lockstep's rate on motion_top in direct mode on the project's
// machine (1.8 M clocks/s: docs/data/gcode_bench.json); the progress line
// then gives the rate measured.
void announce_long_run(double clocks, uint64_t progress_every) {
  constexpr double kClocksPerSecond = 1.8e6;
  if (progress_every == 0 || clocks < 120 * kClocksPerSecond) return;
  std::fprintf(stderr,
               "hwinterp gcode: about %s clocks to simulate, ~%s at 1.8 M clocks/s; progress "
               "every %s clocks (--progress N, 0: none)\n",
               tb::short_count(clocks).c_str(),
               tb::short_duration(clocks / kClocksPerSecond).c_str(),
               tb::short_count(static_cast<double>(progress_every)).c_str());
}

class PlannedMoves {
 public:
  PlannedMoves(const PartProgramSetup& setup, const tb::VariantSpec& l,
               const MotionWidths& widths) {
    // The program's commands, compiled once more for a look over the whole.
    const auto each_command = [&](const auto& fn) {
      auto src = open_source(setup);
      MotionCompiler pass(*src, setup.machine, widths, setup.feed_mode, setup.program);
      models::MotionCommand mc;
      while (pass.next(mc)) fn(mc, pass);
    };
    uint32_t moved = 0;  // the axes the program moves: their limits set the profile's
    double ops = 0;      // the whole path's engine operations
    each_command([&](const models::MotionCommand& mc, const MotionCompiler&) {
      moved |= motion_moved_axes(mc, l.axes);
      ops += static_cast<double>(models::motion_operations(mc));
    });
    const double hz = static_cast<double>(setup.machine.clock_hz);
    const models::ProfileBuild build = tb::feed_profile_build(hz);
    // The profile changes its speed once a tick (2^TICK_W clocks): the
    // machine's limits hold within the kinematics window only when a tick is
    // at most half of it (at a slower clock the speed steps read as jerk
    // beyond the limit: measured, docs/command-line.md).
    const double min_hz = 2 * std::ldexp(1.0, build.tick_w) / setup.kinematics_window_s;
    if (hz < min_hz)
      throw cli::UsageError(
          "--machine: clock_hz " + fmt("%g", hz) +
          " is too slow for the feed profile: its tick of " + std::to_string(1u << build.tick_w) +
          " clocks lasts " + fmt("%.3g", std::ldexp(1.0, build.tick_w) / hz * 1e3) +
          " ms, more than half the " + fmt("%g", setup.kinematics_window_s * 1e3) +
          " ms within which its limits hold: clock_hz at least " + fmt("%g", min_hz));
    planner_ = std::make_unique<ProfilePlanner>(setup.machine, l.axes, build, setup.profile_window,
                                                l.feed_w, moved);
    // One speed level of the profile, as a jump within the kinematics
    // window W, reads as acceleration dv / W and jerk dv / W^2: an axis
    // limit below what one level reads as cannot be kept at this clock.
    const double dv = planner_->registers().level_speed;  // operations/s, >= steps/s of an axis
    const double w = setup.kinematics_window_s;
    for (int i = 0; i < l.axes; ++i) {
      if (!(moved >> i & 1)) continue;
      const AxisLimits& lim = setup.machine.limits[static_cast<size_t>(i)];
      const double spu = static_cast<double>(setup.machine.steps_per_unit[static_cast<size_t>(i)]);
      const std::string axis(1, kAxisNames[i]);
      const auto refuse = [&](const char* key, double value, double reads, const char* unit) {
        throw cli::UsageError(
            std::string("--machine: ") + key + "." + axis + " = " + fmt("%g", value) +
            " is below what one speed level of the feed profile reads as at clock_hz " +
            fmt("%g", hz) + ": " + fmt("%.3g", reads) + " " + unit + " (a level of " +
            fmt("%.3g", dv / spu) + " units/s within the " + fmt("%g", w * 1e3) +
            " ms kinematics window); raise it, or raise clock_hz");
      };
      if (std::isfinite(lim.accel) && dv / w > lim.accel * spu)
        refuse("max_accel", lim.accel, dv / w / spu, "units/s^2");
      if (setup.machine.profile == ProfileKind::kScurve && std::isfinite(lim.jerk) &&
          dv / (w * w) > lim.jerk * spu)
        refuse("max_jerk", lim.jerk, dv / (w * w) / spu, "units/s^3");
    }
    // Every command's limits the profile can keep, before anything runs; and
    // the run's clocks estimated from the plan itself (a planner of its own:
    // each command's entry, cruise and end levels, models::profile_move_clocks).
    ProfilePlanner plan(setup.machine, l.axes, build, setup.profile_window, l.feed_w, moved);
    uint32_t entry = 0;
    const auto take = [&] {
      for (ProfileCommand pc; plan.pop(pc); entry = pc.end)
        estimate_ += models::profile_move_clocks(plan.registers(), build, entry, pc.ops,
                                                 std::min(pc.target, pc.max), pc.end);
    };
    const double level = planner_->registers().level_speed;
    each_command([&](const models::MotionCommand& mc, const MotionCompiler& pass) {
      planner_->check(mc);
      // A programmed feed below one level would run at the level: faster.
      const double programmed = planner_->programmed_speed(mc);
      if (programmed < level)
        throw cli::UsageError(
            setup.program + ":" + std::to_string(pass.info().line) + ": F" +
            fmt("%g", pass.move().feed) + " is below the slowest speed of the feed profile at " +
            "clock_hz " + fmt("%g", hz) + " (one level): F" +
            fmt("%.3g", pass.move().feed * level / programmed) + " at least on this move");
      plan.push(mc, pass.info().number == 1 && pass.move().stop_before);
      take();
    });
    plan.finish();
    take();
    // No run is faster than the whole path as one time-optimal move at the
    // profile's acceleration and jerk and one operation a clock: refuse a
    // program that would take more than the ceiling even so.
    const double fastest =
        models::optimal_move_time(ops, {hz, planner_->accel(), planner_->jerk()}) * hz;
    if (fastest > setup.max_clocks)
      throw cli::UsageError(
          "--machine: the program's " + fmt("%.6g", ops) + " operations take at least " +
          fmt("%.3g", fastest) + " clocks (" + fmt("%.3g", fastest / hz) +
          " s) at the feed profile's acceleration " + fmt("%.3g", planner_->accel()) +
          " and jerk " + fmt("%.3g", planner_->jerk()) +
          " operations/s^2, /s^3 (0.8 of the smallest max_accel, max_jerk of the axes it "
          "moves, in steps), beyond --max-clocks " +
          fmt("%g", setup.max_clocks) + " (give a larger --max-clocks to simulate it)");
    source_ = open_source(setup);
    compiler_ = std::make_unique<MotionCompiler>(*source_, setup.machine, widths, setup.feed_mode,
                                                 setup.program);
  }
  const ProfilePlanner& planner() const { return *planner_; }
  double estimated_clocks() const { return estimate_; }
  // The next command's move (false: the program ended).
  bool next(tb::ProfileWords& w) {
    ProfileCommand pc;
    while (!planner_->pop(pc)) {
      if (finished_) return false;
      models::MotionCommand mc;
      if (compiler_->next(mc)) {
        planner_->push(mc, compiler_->info().number == 1 && compiler_->move().stop_before);
      } else {
        planner_->finish();
        finished_ = true;
      }
    }
    w = {pc.ops, pc.target, pc.end, pc.max};
    return true;
  }

 private:
  std::unique_ptr<ProfilePlanner> planner_;
  std::unique_ptr<MoveSource> source_;
  std::unique_ptr<MotionCompiler> compiler_;
  bool finished_ = false;
  double estimate_ = 0;
};

// The bus host's source with the profile: the program's commands (feed word
// 0: motion_top follows the profile) and each command's move.
struct ProfiledSource {
  Program& prog;
  PlannedMoves& moves;
  bool next(models::MotionCommand& c) {
    if (!prog.next(c)) return false;
    c.feed = 0;
    return true;
  }
  bool next_move(tb::ProfileWords& w) { return moves.next(w); }
};

// The lockstep run's step events for the bus run to meet, passed on to the
// program's own observer.
class Recorder final : public tb::MoveObserver {
 public:
  Recorder(tb::MoveObserver& inner, tb::bus::LatticeRecord& record)
      : inner_(inner), record_(record) {}
  void move(const models::LatticePoint& at, uint64_t command) override { inner_.move(at, command); }
  void done(uint64_t command, const models::LatticePoint& at) override {
    record_.done();
    inner_.done(command, at);
  }
  void pulses(uint64_t clock, uint32_t rising, uint32_t dir) override {
    record_.pulses(rising, dir);
    inner_.pulses(clock, rising, dir);
  }

 private:
  tb::MoveObserver& inner_;
  tb::bus::LatticeRecord& record_;
};

// The bus run's sink: the check against the lockstep run's record, and a
// second Program's contour error and end points.
struct BusSink {
  Program& prog;
  tb::bus::LatticeCheck& check;
  void pulses(uint64_t clock, uint32_t rising, uint32_t dir) {
    check.pulses(rising, dir);
    prog.pulses(clock, rising, dir);
  }
  void move(const models::LatticePoint& at, uint64_t command) { prog.move(at, command); }
  void done(uint64_t command, const models::LatticePoint& at) {
    check.done(command);
    prog.done(command, at);
  }
};

template <class Cfg, class Src>
tb::bus::SocRunResult run_soc_of(const std::string& bus, Src& src, BusSink& sink,
                                 const tb::bus::SocSetup& s, const tb::bus::WaitStates& w,
                                 const tb::bus::SocRunLimits& limits) {
  using Soc = SocOf<Cfg>;
  if (s.profile) {  // the tops with the feed profile (PROFILE=1)
    if constexpr (Soc::kProfile) {
      if (bus == "axi4lite") {
        tb::bus::AxilShadow<Cfg, 1> hls;
        return tb::bus::run_soc<typename Soc::AxilProf, tb::bus::Axi4LiteMaster, Soc>(
            src, s, sink, hls, w, limits);
      }
      tb::bus::WbShadow<Cfg, 1> hls;
      return tb::bus::run_soc<typename Soc::WbProf, tb::bus::WishboneMaster, Soc>(src, s, sink, hls,
                                                                                  w, limits);
    }
    throw cli::UsageError(
        "--bus --profile: no motion_soc build with the feed profile at these "
        "widths (FEED_W must be 24)");
  }
  if (bus == "axi4lite") {
    tb::bus::AxilShadow<Cfg> hls;
    return tb::bus::run_soc<typename Soc::Axil, tb::bus::Axi4LiteMaster, Soc>(src, s, sink, hls, w,
                                                                              limits);
  }
  tb::bus::WbShadow<Cfg> hls;
  return tb::bus::run_soc<typename Soc::Wb, tb::bus::WishboneMaster, Soc>(src, s, sink, hls, w,
                                                                          limits);
}

// The program again, through motion_soc's bus, against the lockstep run.
BusCompare run_bus(const PartProgramSetup& setup, const tb::VariantSpec& l,
                   const MotionWidths& widths, const tb::bus::LatticeRecord& record,
                   const models::LatticePoint& lockstep_end, uint64_t lockstep_clocks) {
  const bool profiled = setup.machine.profile != ProfileKind::kOff;
  auto prog = std::make_shared<Program>(open_source(setup), setup.machine, widths, setup.feed_mode,
                                        setup.program, nullptr, nullptr, nullptr,
                                        setup.kinematics_window_s, profiled);
  tb::bus::LatticeCheck check(record);
  BusSink sink{*prog, check};
  tb::bus::SocSetup s;
  s.axes = l.axes;
  s.feed = static_cast<uint32_t>(l.full_feed());
  const StepTiming& t = setup.machine.timing;
  s.step_len = static_cast<uint32_t>(t.step_len);
  s.step_space = static_cast<uint32_t>(t.step_space);
  s.dir_setup = static_cast<uint32_t>(t.dir_setup);
  s.dir_hold = static_cast<uint32_t>(t.dir_hold);
  std::string types;
  for (int i = 0; i < l.axes; ++i) {
    const tb::StepType st = setup.step_types.empty() ? tb::StepType::kStepDir
                            : setup.step_types.size() == 1
                                ? setup.step_types.front()
                                : setup.step_types[static_cast<size_t>(i)];
    s.step_type[static_cast<size_t>(i)] = static_cast<uint8_t>(st);
    types += std::string(i ? "," : "") + tb::step_type_name(st);
  }
  // With the profile: its registers and each command's move, planned as
  // for the lockstep run.
  std::unique_ptr<PlannedMoves> moves;
  if (profiled) {
    moves = std::make_unique<PlannedMoves>(setup, l, widths);
    s.profile = true;
    s.prof_q = moves->planner().registers().q;
    s.prof_len = moves->planner().registers().len;
  }
  const tb::bus::WaitStates waits{setup.bus_waits, 1};
  // No step for this long after the last completed command: the end (every
  // step/dir timing twice, and some).
  tb::bus::SocRunLimits limits;
  limits.drain = 2 * (s.step_len + s.step_space + s.dir_setup + s.dir_hold) + 64;
  // The bus adds clocks per command (about 3 per write on AXI4-Lite); a run
  // past this has stalled.
  limits.max_clocks = 4 * lockstep_clocks +
                      64 * (record.done_at().size() + 1) * (16 + 4 * uint64_t{setup.bus_waits}) +
                      100000;
  // The lockstep run's clocks are the bus run's estimate: the same commands.
  limits.progress_every = setup.bench.progress_every;
  limits.expected_clocks = static_cast<double>(lockstep_clocks);
  tb::bus::SocRunResult r;
  bool found = false;
#define HWINTERP_RUN_SOC(v)                                              \
  if (!found && l.variant == #v) {                                       \
    if (moves) {                                                         \
      ProfiledSource src{*prog, *moves};                                 \
      r = run_soc_of<v##_cfg>(setup.bus, src, sink, s, waits, limits);   \
    } else {                                                             \
      r = run_soc_of<v##_cfg>(setup.bus, *prog, sink, s, waits, limits); \
    }                                                                    \
    found = true;                                                        \
  }
  HWINTERP_SOC_VARIANTS(HWINTERP_RUN_SOC)
#undef HWINTERP_RUN_SOC
  if (!found) throw cli::UsageError("--bus: no motion_soc build of variant " + l.variant);
  prog->flush_rows();
  prog->kinematics().finish(r.clocks);

  BusCompare b;
  b.ran = true;
  b.bus = setup.bus;
  b.build = std::string(setup.bus == "axi4lite" ? "motion_soc_axil" : "motion_soc_wb") + " at " +
            l.variant + "'s widths, FIFO_DEPTH 16" + (profiled ? ", PROFILE 1" : "");
  if (profiled) {
    b.profiled = true;
    b.limit_failures = limit_failures(kinematics_of(prog->kinematics(), setup.machine),
                                      setup.machine.profile, "bus run: ");
  }
  b.clocks = r.clocks;
  b.writes = r.host.writes;
  b.reads = r.host.reads;
  b.errors = r.host.errors;
  b.pushes = r.host.pushes;
  b.level_reads = r.host.level_reads;
  b.credit_waits = r.host.credit_waits;
  b.irq_wait_clocks = r.host.irq_clocks;
  b.events = r.host.events;
  b.points = check.points();
  b.lockstep_points = record.events().size();
  b.completed = r.completed;
  b.lockstep_completed = record.done_at().size();
  b.first_point_mismatch = check.first_point();
  b.first_end_mismatch = check.first_end();
  b.step_types = types;
  b.timing_violations = r.timing_violations;
  b.timing_violation_count = r.timing_violation_count;
  b.end = r.end;
  b.lockstep_end = lockstep_end;
  b.end_mismatches = prog->end_mismatches();
  b.contour = prog->max();
  b.timed_out = r.timed_out;
  b.hls_mismatch_clock = r.shadow.clock;
  b.hls_mismatch_what = r.shadow.what;
  b.hls_mismatch_hls = r.shadow.hls;
  b.hls_mismatch_rtl = r.shadow.rtl;
  // EVENTS: an overflow or a refused push would be a lost command.
  b.passed = check.same() && !r.timed_out && r.shadow.clock == 0 && r.host.errors == 0 &&
             r.timing_violation_count == 0 && r.host.events_read &&
             (r.host.events & tb::bus::kLost) == 0 && r.completed == r.host.pushes &&
             r.host.pushes == prog->compiler().totals().commands && b.end == b.lockstep_end &&
             b.end_mismatches.empty() && prog->all_rows_written() && b.limit_failures.empty();
  return b;
}

MotionWidths widths_of(const tb::VariantSpec& l) {
  MotionWidths widths;
  widths.axes = l.axes;
  widths.acc_w = l.param("ACC_W");
  widths.coord_w = l.param("COORD_W");
  widths.ops_w = l.param("OPS_W");
  widths.feed_w = l.feed_w;
  return widths;
}

// Bad input found before anything runs: the program's reach (travel and
// position counters, tb/gcode/limits.h) and a profile at the wrong FEED_W.
void check_program(const PartProgramSetup& setup, const tb::VariantSpec& l) {
  {
    auto source = open_source(setup);
    check_reach(*source, setup.machine, l.param("POS_W"), l.variant, setup.program);
  }
  if (setup.machine.profile != ProfileKind::kOff && l.feed_w != tb::kProfileFeedW)
    throw cli::UsageError("--profile: the feed profile's build gives " +
                          std::to_string(tb::kProfileFeedW) + "-bit feed words; " + l.variant +
                          " takes FEED_W " + std::to_string(l.feed_w));
}

// The --soc-writes file (tb/gcode/soc_writes.h): the compile again, and with
// a profile its planned moves from a planner of their own.
void write_program_soc_writes(const PartProgramSetup& setup, const tb::VariantSpec& l,
                              const MotionWidths& widths) {
  SocWritesSetup s;
  s.program = setup.program;
  s.canon = setup.canon;
  s.variant = l.variant;
  s.widths = widths;
  s.pos_w = l.pos_w;
  s.tim_w = l.tim_w;
  s.mode = setup.feed_mode;
  std::unique_ptr<PlannedMoves> moves;
  if (setup.machine.profile != ProfileKind::kOff) {
    moves = std::make_unique<PlannedMoves>(setup, l, widths);
    s.profiled = true;
    s.prof_regs = moves->planner().registers();
    s.prof_build = tb::feed_profile_build(static_cast<double>(setup.machine.clock_hz));
    s.prof_window = setup.profile_window;
    s.prof_accel = moves->planner().accel();
    s.prof_jerk = moves->planner().jerk();
    s.next_move = [&moves](tb::ProfileWords& w) { return moves->next(w); };
  }
  auto src = open_source(setup);
  write_soc_writes(*src, setup.machine, s, setup.soc_writes_path);
}

}  // namespace

tb::VariantSpec part_program_variant(const PartProgramSetup& setup) {
  return choose(setup).variant().spec;
}

void plan_soc_writes(const PartProgramSetup& setup) {
  const tb::VariantSpec l = choose(setup).variant().spec;
  const MotionWidths widths = widths_of(l);
  check_program(setup, l);
  write_program_soc_writes(setup, l, widths);
}

PartProgramRun run_part_program(const PartProgramSetup& setup) {
  const Chosen chosen = choose(setup);
  const tb::VariantSpec& l = chosen.variant().spec;
  const MotionWidths widths = widths_of(l);

  // The program's reach first: travel and position counters (tb/gcode/limits.h).
  check_program(setup, l);
  if (!setup.soc_writes_path.empty()) write_program_soc_writes(setup, l, widths);
  auto source = open_source(setup);
  const bool profiled = setup.machine.profile != ProfileKind::kOff;
  auto prog = std::make_shared<Program>(std::move(source), setup.machine, widths, setup.feed_mode,
                                        setup.program, setup.moves_csv, setup.points_csv,
                                        setup.kinematics_csv, setup.kinematics_window_s, profiled);

  // The feed profile: a planner on its own pass over the program, running a
  // window of commands ahead of the engine, feeding the profile's two faces,
  // whose word drives feed_i.
  std::unique_ptr<PlannedMoves> moves;
  std::unique_ptr<tb::ProfileFeed> profile_feed;
  if (profiled) {
    moves = std::make_unique<PlannedMoves>(setup, l, widths);
    profile_feed = std::make_unique<tb::ProfileFeed>(
        moves->planner().registers().q, moves->planner().registers().len,
        [&](tb::ProfileWords& w) { return moves->next(w); });
  }

  if (profile_feed && !setup.feed_override.empty())
    profile_feed->override_schedule(
        tb::override_steps(setup.feed_override, static_cast<double>(setup.machine.clock_hz)));
  if (profile_feed && setup.hold_at_s >= 0) {
    const double hz = static_cast<double>(setup.machine.clock_hz);
    profile_feed->hold_between(
        static_cast<uint64_t>(std::llround(setup.hold_at_s * hz)),
        static_cast<uint64_t>(std::llround((setup.hold_at_s + setup.hold_for_s) * hz)));
  }

  // One case from the origin, the machine's step/dir timing, feed_i running.
  tb::Case<MotionAdapter> c;
  c.name = setup.program;
  c.start.assign(static_cast<size_t>(l.axes), 0);
  c.settings = tb::default_settings<MotionAdapter>(l);
  c.settings.feed = l.full_feed();
  const StepTiming& t = setup.machine.timing;
  c.settings.timing = {static_cast<uint32_t>(t.step_len), static_cast<uint32_t>(t.step_space),
                       static_cast<uint32_t>(t.dir_setup), static_cast<uint32_t>(t.dir_hold)};
  c.more = prog;

  tb::BenchOptions options = setup.bench;
  options.mode = setup.mode;
  // The run's clocks estimated (the progress line's percent and time left),
  // with the pauses of a feed hold.
  options.expected_clocks =
      moves ? moves->estimated_clocks() : estimate_direct_clocks(setup, widths, l.feed_w);
  if (moves && setup.hold_at_s >= 0)
    options.expected_clocks += setup.hold_for_s * static_cast<double>(setup.machine.clock_hz);
  announce_long_run(options.expected_clocks, options.progress_every);
  options.observer = prog.get();
  options.profile_feed = profile_feed.get();
  tb::bus::LatticeRecord record;
  std::unique_ptr<Recorder> recorder;
  if (!setup.bus.empty()) {
    recorder = std::make_unique<Recorder>(*prog, record);
    options.observer = recorder.get();
  }
  std::vector<tb::Case<MotionAdapter>> cases;
  cases.push_back(std::move(c));
  const std::unique_ptr<tb::BenchRun> run = chosen.variant().make(l, std::move(cases), options);

  std::cout << "hwinterp gcode: " << setup.program << (setup.canon ? " (canon)" : "") << " on "
            << l.variant << ", mode " << setup.mode << ", feed "
            << (setup.feed_mode == FeedMode::kFull ? "full" : "programmed") << "\n"
            << std::flush;
  if (setup.mode == "direct")
    run->run_direct();
  else
    tb::run_systemc({run.get()});
  run->close();
  prog->flush_rows();
  prog->kinematics().finish(run->cycles());

  PartProgramRun r;
  r.variant = l;
  r.results = run->results();
  r.totals = prog->compiler().totals();
  r.reader = prog->reader_stats();
  r.contour = prog->max();
  r.visited_points = prog->points();
  r.end_mismatches = prog->end_mismatches();
  r.estimated_clocks = options.expected_clocks;
  r.kinematics = kinematics_of(prog->kinematics(), setup.machine);
  r.all_rows_written = prog->all_rows_written();
  if (profiled) {
    const ProfilePlanner& planner = moves->planner();
    const models::ProfileRegisters& g = planner.registers();
    r.profile = {true,
                 profile_name(setup.machine.profile),
                 g.q,
                 g.len,
                 g.level_speed,
                 planner.accel(),
                 planner.jerk(),
                 g.max_level,
                 setup.profile_window,
                 profile_feed->moves_taken(),
                 false,
                 {},
                 setup.feed_override};
    if (setup.hold_at_s >= 0) {
      const tb::ProfileFeed::HoldStop& h = profile_feed->hold_stop();
      const double hz = static_cast<double>(setup.machine.clock_hz);
      r.profile.held = true;
      r.profile.hold = {setup.hold_at_s, setup.hold_for_s,
                        h.stopped,       h.speed * hz,
                        h.ops,           static_cast<double>(h.clocks) / hz};
      if (!h.began)  // bad input found by the run: nothing of it is kept
        throw cli::UsageError("--feed-hold AT: " + fmt("%.6g", setup.hold_at_s) +
                              " s is after the program's end at " +
                              fmt("%.6g", static_cast<double>(run->cycles()) / hz) +
                              " s of the run");
      if (!h.stopped)
        r.profile_failures.push_back("the feed hold did not bring the path to rest within its " +
                                     fmt("%.6g", setup.hold_for_s) + " s");
    }
    if (profile_feed->failed()) r.profile_failures.push_back(profile_feed->failure());
    if (profile_feed->stranded() && !r.results.empty() && r.results.front().timed_out)
      r.profile_failures.push_back(
          "the feed profile came to rest with motion_top still busy: the step/dir stage "
          "stalled the engine behind the profile's distance");
    // The machine's limits, within the estimator's tolerance, on every axis and the path.
    for (std::string& f : limit_failures(r.kinematics, setup.machine.profile, ""))
      r.profile_failures.push_back(std::move(f));
  }
  r.passed = tb::all_passed(r.results) && !r.results.empty() && r.results.front().completed &&
             r.end_mismatches.empty() && r.all_rows_written && r.profile_failures.empty();
  if (!setup.bus.empty()) {
    std::cout << "hwinterp gcode: " << setup.program << " through motion_soc's " << setup.bus
              << " interface\n"
              << std::flush;
    r.bus = run_bus(setup, l, widths, record, r.results.front().end_position, run->cycles());
    r.passed = r.passed && r.bus.passed;
  }
  return r;
}

std::string summary_table(const PartProgramSetup& setup, const PartProgramRun& run) {
  const tb::CaseResult& r = run.results.front();
  const CompileTotals& t = run.totals;
  const ReaderStats& rs = run.reader;
  const double clock = static_cast<double>(setup.machine.clock_hz);
  const ContourMax& m = run.contour;
  TextTable s({"", "value"});
  s.add_row({"moves (traverse / feed / arc)",
             std::to_string(t.moves) + " (" + std::to_string(rs.traverses) + " / " +
                 std::to_string(rs.feeds) + " / " + std::to_string(rs.arcs) + ")"});
  s.add_row({"commands (lines / arcs)", std::to_string(t.commands) + " (" +
                                            std::to_string(t.line_commands) + " / " +
                                            std::to_string(t.arc_commands) + ")"});
  s.add_row({"arcs run as chords / split arcs",
             std::to_string(t.chord_arcs) + " / " + std::to_string(t.split_arcs)});
  std::string steps;
  for (int i = 0; i < run.variant.axes; ++i)
    steps += (i ? " " : "") + std::string(kAxisName[i]) + "=" +
             std::to_string(r.steps[static_cast<size_t>(i)]);
  s.add_row({"steps per axis", steps});
  s.add_row({"programmed machining time (F, rapids)", fmt("%.3f", t.programmed_s) + " s"});
  s.add_row({"machining time from the feed words", fmt("%.3f", t.programmed_words_s) + " s"});
  s.add_row({std::string("simulated (") +
                 (setup.feed_mode == FeedMode::kFull ? "full" : "programmed") + " feed, " +
                 fmt("%.3f", clock / 1e6) + " MHz)",
             std::to_string(r.cycles) +
                 " clocks = " + fmt("%.6f", static_cast<double>(r.cycles) / clock) + " s"});
  if (run.profile.on) {
    const ProfileReport& p = run.profile;
    s.add_row({"feed profile (" + p.kind + ")",
               "accel " + fmt("%.4g", p.accel) + " steps/s^2, jerk " +
                   (p.kind == "scurve" ? fmt("%.4g", p.jerk) + " steps/s^3" : "-") + ", L " +
                   std::to_string(p.len) + " ticks, " + std::to_string(p.moves) +
                   " moves, look-ahead " + std::to_string(p.window)});
    s.add_row(
        {"machining time at the profile",
         fmt("%.6f", static_cast<double>(r.cycles) / clock) + " s (" +
             (run.profile_failures.empty() ? std::string("within the limits")
                                           : std::to_string(run.profile_failures.size()) +
                                                 " failures: " + run.profile_failures.front()) +
             ")"});
    if (!p.feed_override.empty()) {
      std::string steps;
      for (const tb::OverridePoint& o : p.feed_override)
        steps += (steps.empty() ? "" : ", ") + fmt("%.6g", o.percent) + " % from " +
                 fmt("%.6g", o.at_s) + " s";
      s.add_row({"feed override", steps});
    }
    if (p.held) {
      const ProfileReport::Hold& h = p.hold;
      s.add_row({"feed hold at " + fmt("%.6g", h.at_s) + " s for " + fmt("%.6g", h.for_s) + " s",
                 h.stopped ? "from " + fmt("%.6g", h.speed_ops_per_s) +
                                 " operations/s to rest in " + fmt("%.6g", h.stop_ops) +
                                 " operations and " + fmt("%.4g", h.stop_s * 1e3) + " ms"
                           : std::string("not at rest")});
    }
  }
  s.add_row({"max contour error", fmt("%.6f", m.mm) + " mm = " + fmt("%.3f", m.steps) +
                                      " steps (move " + std::to_string(m.move) + ", line " +
                                      std::to_string(m.line) + ")"});
  s.add_row({"visited lattice points", std::to_string(run.visited_points)});
  if (run.bus.ran) {
    const BusCompare& b = run.bus;
    auto point = [](const std::vector<int64_t>& p) {
      std::string t;
      for (size_t i = 0; i < p.size(); ++i) t += (i ? " " : "") + std::to_string(p[i]);
      return t;
    };
    s.add_row({"bus: " + b.bus + " (" + b.build + ")",
               std::to_string(b.clocks) + " clocks, " + std::to_string(b.writes) + " writes, " +
                   std::to_string(b.reads) + " reads, " + std::to_string(b.errors) + " errors"});
    s.add_row({"bus: commands pushed / completed (lockstep)",
               std::to_string(b.pushes) + " / " + std::to_string(b.completed) + " (" +
                   std::to_string(b.lockstep_completed) + "), FIFO full at " +
                   std::to_string(b.credit_waits) + " of " + std::to_string(b.level_reads) +
                   " level reads, " + std::to_string(b.irq_wait_clocks) +
                   " clocks asleep on low water"});
    s.add_row({"bus: lattice points (lockstep)",
               std::to_string(b.points) + " (" + std::to_string(b.lockstep_points) + "), " +
                   (b.first_point_mismatch < 0
                        ? std::string("the same sequence")
                        : "first difference at point " + std::to_string(b.first_point_mismatch)) +
                   (b.first_end_mismatch < 0 ? std::string(", every command ends on the same point")
                                             : ", command " + std::to_string(b.first_end_mismatch) +
                                                   " ends elsewhere")});
    const std::string first_violation =
        b.timing_violations.empty()
            ? std::string()
            : ": first " + b.timing_violations.front().rule + " on axis " +
                  std::to_string(b.timing_violations.front().axis) + " at clock " +
                  std::to_string(b.timing_violations.front().cycle) + ", " +
                  std::to_string(b.timing_violations.front().measured) + " < " +
                  std::to_string(b.timing_violations.front().required);
    s.add_row(
        {"bus: step outputs (STEP_TYPE " + b.step_types + ")",
         b.timing_violation_count == 0
             ? std::string("decoded by type, within the step timing on every clock")
             : std::to_string(b.timing_violation_count) + " timing violations" + first_violation});
    s.add_row(
        {"bus: HLS face (hls/motion_soc.h) against the RTL",
         b.hls_mismatch_clock == 0
             ? std::string("the same bus pins, step pins and FIFO, time and watchdog counts") +
                   (b.profiled ? ", the moves' FIFO and the profile's feed word" : "") +
                   " on all " + std::to_string(b.clocks) + " clocks"
             : "differs at clock " + std::to_string(b.hls_mismatch_clock) + ": " +
                   b.hls_mismatch_what + " HLS " + std::to_string(b.hls_mismatch_hls) + " RTL " +
                   std::to_string(b.hls_mismatch_rtl)});
    if (b.profiled)
      s.add_row({"bus: kinematics with the feed profile",
                 b.limit_failures.empty() ? std::string("within the machine's limits")
                                          : std::to_string(b.limit_failures.size()) +
                                                " failures: " + b.limit_failures.front()});
    s.add_row({"bus: end point (lockstep)",
               point(b.end) + " (" + point(b.lockstep_end) + ")" +
                   (b.timed_out ? ", TIMED OUT" : "") +
                   ((b.events & tb::bus::kLost) ? ", EVENTS overflow/refused set" : "")});
  }
  const Kinematics& k = run.kinematics;
  // The estimator needs three whole windows for a jerk (its second difference).
  if (k.windows < 3) {
    s.add_row({"peak speed, accel, jerk", "not estimated: the run is shorter than three " +
                                              fmt("%g", k.window_s * 1e3) + " ms windows (" +
                                              std::to_string(k.windows) + ")"});
    return s.render();
  }
  for (const KinematicRow& row : k.rows) {
    auto cell = [&](const KinematicPeak& p, const char* per) {
      std::string c = fmt("%.4g", p.max) + " " + row.unit + per;
      if (std::isfinite(p.limit)) c += " (limit " + fmt("%.4g", p.limit) + ")";
      return c;
    };
    s.add_row(
        {"peak speed, accel, jerk: " + row.name + " (" + fmt("%g", k.window_s * 1e3) + " ms)",
         cell(row.speed, "/s") + ", " + cell(row.accel, "/s^2") + ", " + cell(row.jerk, "/s^3")});
  }
  return s.render();
}

Json report_json(const PartProgramSetup& setup, const PartProgramRun& run) {
  const tb::CaseResult& r = run.results.front();
  const CompileTotals& t = run.totals;
  const ReaderStats& rs = run.reader;
  const ContourMax& m = run.contour;
  Json report = tb::aggregate_json(run.results);
  report["program"] = setup.program;
  report["canon"] = setup.canon;
  report["variant"] = run.variant.variant;
  report["feed_mode"] = setup.feed_mode == FeedMode::kFull ? "full" : "programmed";
  report["moves"] = t.moves;
  report["traverses"] = rs.traverses;
  report["feeds"] = rs.feeds;
  report["arcs"] = rs.arcs;
  report["commands"] = t.commands;
  report["line_commands"] = t.line_commands;
  report["arc_commands"] = t.arc_commands;
  report["chord_arcs"] = t.chord_arcs;
  report["chords"] = t.chords;
  report["split_arcs"] = t.split_arcs;
  report["programmed_time_s"] = t.programmed_s;
  report["feed_word_time_s"] = t.programmed_words_s;
  report["simulated_clocks"] = r.cycles;
  report["estimated_clocks"] = run.estimated_clocks;
  report["simulated_time_s"] =
      static_cast<double>(r.cycles) / static_cast<double>(setup.machine.clock_hz);
  report["clock_hz"] = setup.machine.clock_hz;
  report["max_contour_error_mm"] = m.mm;
  report["max_contour_error_steps"] = m.steps;
  report["max_contour_error_move"] = m.move;
  report["max_contour_error_line"] = m.line;
  report["visited_points"] = run.visited_points;
  report["end_mismatches"] = run.end_mismatches.size();
  report["peak_rss_kib"] = peak_rss_kib();
  Json kin;
  kin["estimator"] =
      "window means of the step counts and their first and second differences "
      "(tb/monitor/kinematics.h)";
  kin["window_s"] = run.kinematics.window_s;
  kin["windows"] = run.kinematics.windows;
  for (const KinematicRow& row : run.kinematics.rows) {
    Json j;
    j["unit"] = row.unit;
    auto put = [&](const char* name, const KinematicPeak& p) {
      j[name] = {{"max", p.max},
                 {"at_s", p.at_s},
                 {"tolerance", p.tolerance},
                 {"limit", std::isfinite(p.limit) ? Json(p.limit) : Json(nullptr)}};
    };
    put("speed", row.speed);
    put("accel", row.accel);
    put("jerk", row.jerk);
    if (row.axis < 0)
      kin["path"] = j;
    else
      kin["axes"][row.name] = j;
  }
  report["kinematics"] = kin;
  const ProfileReport& pr = run.profile;
  Json prof = Json::object();
  prof["kind"] = pr.on ? pr.kind : "off";
  if (pr.on) {
    prof["q"] = pr.q;
    prof["len"] = pr.len;
    prof["level_speed"] = pr.level_speed;
    prof["max_level"] = pr.max_level;
    prof["accel"] = pr.accel;
    prof["jerk"] = pr.jerk;
    prof["window"] = pr.window;
    prof["moves"] = pr.moves;
    prof["time_s"] = static_cast<double>(r.cycles) / static_cast<double>(setup.machine.clock_hz);
    if (pr.held) prof["hold"] = Json(nlohmann::json(pr.hold));  // its keys in name order
    if (!pr.feed_override.empty()) {
      Json steps = Json::array();
      for (const tb::OverridePoint& o : pr.feed_override)
        steps.push_back(
            {{"at_s", o.at_s}, {"percent", o.percent}, {"word", models::override_word(o.percent)}});
      prof["feed_override"] = std::move(steps);
    }
    prof["failures"] = run.profile_failures;
  }
  report["profile"] = prof;
  if (run.bus.ran) {
    const BusCompare& b = run.bus;
    Json j;
    j["bus"] = b.bus;
    j["build"] = b.build;
    j["clocks"] = b.clocks;
    j["writes"] = b.writes;
    j["reads"] = b.reads;
    j["errors"] = b.errors;
    j["pushes"] = b.pushes;
    j["level_reads"] = b.level_reads;
    j["fifo_full_reads"] = b.credit_waits;
    j["irq_wait_clocks"] = b.irq_wait_clocks;
    j["events"] = b.events;
    j["points"] = b.points;
    j["lockstep_points"] = b.lockstep_points;
    j["completed"] = b.completed;
    j["lockstep_completed"] = b.lockstep_completed;
    j["first_point_mismatch"] = b.first_point_mismatch;
    j["first_end_mismatch"] = b.first_end_mismatch;
    j["end"] = b.end;
    j["lockstep_end"] = b.lockstep_end;
    j["end_mismatches"] = b.end_mismatches.size();
    j["max_contour_error_mm"] = b.contour.mm;
    j["timed_out"] = b.timed_out;
    j["hls_mismatch_clock"] = b.hls_mismatch_clock;
    j["step_types"] = b.step_types;
    j["timing_violations"] = b.timing_violation_count;
    j["profile"] = b.profiled;
    if (b.profiled) j["limit_failures"] = b.limit_failures;
    if (b.hls_mismatch_clock != 0) {
      j["hls_mismatch"] = {{"signal", b.hls_mismatch_what},
                           {"hls", b.hls_mismatch_hls},
                           {"rtl", b.hls_mismatch_rtl}};
    }
    j["passed"] = b.passed;
    report["bus"] = j;
  }
  return report;
}

Json kinematics_units_json(const PartProgramSetup& setup, const PartProgramRun& run) {
  Json j;
  j["clock_hz"] = setup.machine.clock_hz;
  j["window_s"] = run.kinematics.window_s;
  j["axes"] = Json::object();
  for (const KinematicRow& row : run.kinematics.rows) {
    if (row.axis < 0) continue;
    Json a;
    a["unit_per_step"] = row.unit_per_step;
    a["unit"] = row.unit;
    a["limits"] = Json::object();
    if (std::isfinite(row.speed.limit)) a["limits"]["speed"] = row.speed.limit;
    if (std::isfinite(row.accel.limit)) a["limits"]["accel"] = row.accel.limit;
    if (std::isfinite(row.jerk.limit)) a["limits"]["jerk"] = row.jerk.limit;
    j["axes"][row.name] = a;
  }
  return j;
}

}  // namespace hwinterp::gcode

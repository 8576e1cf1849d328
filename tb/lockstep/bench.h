// The lockstep testbench of any core, independent of how the two DUTs are
// clocked: it drives the stimulus one clock edge at a time, compares the HLS
// core and the RTL after every edge, runs the step/dir timing monitors and
// the scoreboard on the outputs, follows aborts, and collects one CaseResult
// per case. The direct runner (a C++ loop, tb/lockstep/direct.h) and the
// SystemC runner (a negedge process, tb/lockstep/systemc.h) both call it, so
// the two modes see the same stimulus and the same checks. It knows nothing
// of a core's insides: A, the core's adapter, supplies the payload, the
// reference model and the stimulus (tb/cores/<core>/<core>_adapter.h).
//
// Protocol per clock edge: in = next_frame(); both DUTs take `in` at the edge;
// observe(hls_outputs, rtl_outputs). Repeat while !finished().
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tb/base/case_result.h"
#include "tb/base/out_pins.h"
#include "tb/lockstep/bench_options.h"
#include "tb/lockstep/case_profile.h"
#include "tb/lockstep/frame.h"
#include "tb/lockstep/payload_pins.h"
#include "tb/lockstep/profile_feed.h"
#include "tb/monitor/stepdir_monitor.h"
#include "tb/report/frames.h"
#include "tb/report/progress.h"
#include "tb/report/step_times.h"
#include "tb/report/trace.h"
#include "tb/scoreboard/scoreboard.h"
#include "tb/stimulus/stimulus.h"

namespace hwinterp::tb {

// The input ports in frame order: the shared contract around the core's own.
inline std::vector<PortSpec> input_ports(const VariantSpec& l) {
  std::vector<PortSpec> p = {{"rst_ni", 1, 1}, {"cmd_valid_i", 1, 1}};
  for (const auto& own : l.own_ports) p.push_back(own);
  p.push_back({"feed_i", 1, l.feed_w + 1});
  for (const char* t : {"step_len_i", "step_space_i", "dir_setup_i", "dir_hold_i"})
    p.push_back({t, 1, l.tim_w});
  p.push_back({"abort_i", 1, 1});
  return p;
}

// One value per input element of `f`, in input_ports() order; `flatten`
// gives the payload's.
template <class A>
void flat_inputs(const Frame<A>& f, FlattenPayload<A> flatten, uint64_t* out) {
  size_t k = 0;
  out[k++] = f.rst_n;
  out[k++] = f.cmd_valid;
  k += flatten(f.cmd(), f.setup(), out + k);
  out[k++] = f.feed;
  out[k++] = f.timing.step_len;
  out[k++] = f.timing.step_space;
  out[k++] = f.timing.dir_setup;
  out[k++] = f.timing.dir_hold;
  out[k++] = f.abort;
}

inline double bench_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

template <class A>
class Bench {
 public:
  using Kind = typename Item<A>::Kind;

  // Opens every output file (throws std::runtime_error naming it): a bad
  // path costs no simulation. `flatten` is flatten_payload<A, Cfg> of the
  // variant (tb/lockstep/payload_pins.h): the payload's pin values for
  // traces, frame dumps and mismatch reports.
  Bench(VariantSpec spec, std::vector<Case<A>> cases, BenchOptions options,
        FlattenPayload<A> flatten)
      : spec_(std::move(spec)),
        cases_(std::move(cases)),
        options_(std::move(options)),
        flatten_(flatten) {
    if (!options_.trace_path.empty() || !options_.frames_path.empty()) {
      const std::vector<PortSpec> ports = input_ports(spec_);
      if (!options_.trace_path.empty())
        trace_ = std::make_unique<Trace>(options_.trace_path, ports, spec_.axes, spec_.pos_w,
                                         options_.trace_window);
      if (!options_.frames_path.empty())
        frames_ = std::make_unique<FrameWriter>(options_.frames_path,
                                                options_.frames_testbench_path.empty()
                                                    ? options_.frames_path + ".sv"
                                                    : options_.frames_testbench_path,
                                                spec_, ports);
    }
    if (!options_.step_times_path.empty())
      step_times_ = std::make_unique<StepTimesCsv>(options_.step_times_path, spec_.axes);
    if (!options_.path_csv.empty()) {
      path_csv_ = std::make_unique<std::ofstream>(options_.path_csv);
      if (!*path_csv_)
        throw std::runtime_error("cannot write path CSV '" + options_.path_csv + "'");
      *path_csv_ << "case,cycle,kind";
      for (int i = 0; i < spec_.axes; ++i) *path_csv_ << ",p" << i;
      *path_csv_ << ",error,bound\n";
    }
    if (cases_.empty())
      finished_ = true;
    else
      start_case();
  }

  const Frame<A>& next_frame() {
    // The payload stays in the frame while the same command is offered
    // (cmd_loaded_) and is cleared once, when cmd_valid_i falls: the clocks
    // a command waits copy nothing.
    const bool was_valid = frame_.cmd_valid;
    frame_.cmd_valid = false;
    frame_.abort = false;
    frame_.rst_n = phase_ != Phase::kReset;
    if (case_clock_start_ == 0) case_clock_start_ = bench_now();
    if (phase_ == Phase::kRun) {
      if (options_.abort_at && *options_.abort_at == cycle_ + 1)
        frame_.abort = true;  // the item being offered waits a clock
      else
        drive_items();
    }
    if (was_valid && !frame_.cmd_valid) {
      frame_.set_cmd(typename A::Command{});
      cmd_loaded_ = false;
    }
    frame_.feed = profile_ ? profile_->clock() : settings_.feed;
    if (setup_changed_) {
      frame_.set_setup(settings_.setup);
      setup_changed_ = false;
    }
    frame_.timing = settings_.timing;
    return frame_;
  }

  void observe(const OutPins& hls, const OutPins& rtl) {
    ++cycle_;
    if (options_.progress_every && cycle_ % options_.progress_every == 0) print_progress();
    const FaultPlan& f = options_.faults;
    // A planned fault acts on a copy; a clean clock reads the pins in place.
    const OutPins& hls_seen = f.flip_hls_step_at == cycle_ ? flipped(hls) : hls;
    if (trace_ || frames_) {
      flat_inputs<A>(frame_, flatten_, in_values_);
      if (trace_) trace_->record(cycle_, in_values_, hls_seen, rtl);
      if (frames_) frames_->write(in_values_);
    }

    CaseResult& r = results_.back();
    r.cycles = cycle_ - case_start_cycle_;
    if (hls_seen != rtl) {
      record_mismatch(hls_seen, rtl);
      // The first mismatch ends the run: nothing after it can be trusted.
      r.end_position = scoreboard_->position();
      r.expected_end_position = scoreboard_->expected_end();
      r.seconds = bench_now() - case_clock_start_;
      finished_ = true;
      return;
    }
    last_ready_ = rtl.cmd_ready;
    last_busy_ = rtl.busy;
    const OutPins& seen = f.glitch_step_at == cycle_ ? flipped(rtl) : rtl;

    if (!frame_.rst_n) {
      monitors_.reset(cycle_);
    } else {
      monitors_.observe(cycle_, seen.step, seen.dir, frame_.timing, r.timing_violations,
                        r.timing_violation_count);
      const uint64_t done_before = scoreboard_->done_count();
      const bool moved = scoreboard_->observe(cycle_, seen, r);
      if (moved) {
        if (step_times_) step_times_->write(cycle_, scoreboard_->rising(), seen.dir);
        if (case_profile_)
          case_profile_->pulses(cycle_ - case_start_cycle_, scoreboard_->rising(), seen.dir);
        if (path_csv_) path_row("move", scoreboard_->position(), scoreboard_->last_error());
        if (options_.record_path) r.visited.push_back(scoreboard_->position());
        if (options_.observer) {
          options_.observer->pulses(cycle_, scoreboard_->rising(), seen.dir);
          options_.observer->move(scoreboard_->position(), scoreboard_->current_command());
        }
      }
      if (options_.observer && scoreboard_->done_count() > done_before)
        options_.observer->done(done_before, scoreboard_->position());
      if (options_.record_path && seen.done) r.done_cycles.push_back(cycle_ - case_start_cycle_);
      if (frame_.abort) abort_edge(moved, r);
      follow_abort(seen, r);
    }

    switch (phase_) {
      case Phase::kReset:
        if (--phase_left_ == 0) phase_ = Phase::kRun;
        break;
      case Phase::kRun:
        // Idle after the last item: the last command taken shows busy_o on the
        // edge that took it, so !busy here means everything has run.
        if (!items_left_ && !frame_.cmd_valid && !rtl.busy) {
          phase_ = Phase::kTail;
          phase_left_ = kTailCycles;
        }
        break;
      case Phase::kTail:
        if (--phase_left_ == 0) {
          end_case();
          return;
        }
        break;
    }
    // A feed hold of the profile pauses the engine: its clocks are extra.
    const uint64_t held = profile_ ? profile_->hold_clocks() : 0;
    if (r.cycles > budget_ + held || (profile_ && last_busy_ && profile_->stranded())) {
      r.timed_out = true;
      end_case();
    }
  }

  bool finished() const { return finished_; }
  // Results of the cases that ran (a mismatch stops the run).
  const std::vector<CaseResult>& results() const { return results_; }
  uint64_t cycles() const { return cycle_; }
  const VariantSpec& spec() const { return spec_; }
  size_t case_count() const { return cases_.size(); }
  // Closes the trace (FST conversion), the frame file and the path CSV;
  // throws std::runtime_error on failure.
  void close() {
    progress_.finish();
    if (trace_) trace_->close();
    if (frames_) frames_->close();
    if (step_times_) step_times_->close();
    if (path_csv_) {
      path_csv_->close();
      if (!*path_csv_)
        throw std::runtime_error("error writing path CSV '" + options_.path_csv + "'");
    }
  }

 private:
  enum class Phase { kReset, kRun, kTail };
  static constexpr uint64_t kResetCycles = 2;
  static constexpr uint64_t kTailCycles = 2;  // after the core goes idle, so traces show the end

  void start_case() {
    const Case<A>& c = cases_[case_index_];
    CaseResult r;
    r.core = spec_.core;
    r.variant = spec_.variant;
    r.name = c.name;
    r.ordinal = c.ordinal;
    r.mode = options_.mode;
    r.seed = options_.seed;
    r.commands_offered = command_count(c);
    r.steps.assign(static_cast<size_t>(spec_.axes), 0);
    r.start = c.start;
    if (options_.record_path) r.visited.push_back(c.start);
    results_.push_back(std::move(r));

    phase_ = Phase::kReset;
    phase_left_ = kResetCycles;
    case_start_cycle_ = cycle_;
    budget_ = cycle_budget(c, spec_);
    item_ = 0;
    items_left_ = !c.items.empty() || c.more;
    have_streamed_ = false;
    gap_left_ = 0;
    settings_ = c.settings;
    setup_changed_ = true;
    last_ready_ = false;
    last_busy_ = false;
    abort_open_ = false;
    monitors_ = StepdirMonitors(spec_.axes);
    scoreboard_.emplace(spec_, c.start, case_start_cycle_);
    // A case's own profile; a run's (hwinterp gcode) spans its cases.
    case_profile_.reset();
    profile_ = options_.profile_feed;
    if (c.profile && !profile_) {
      case_profile_ = std::make_unique<CaseProfileRun<A>>(c, spec_);
      profile_ = &case_profile_->feed();
      budget_ += case_profile_->budget();
    }
    case_clock_start_ = 0;  // set by the case's first frame
    path_target_ = c.start;
    path_row("start", c.start);
  }

  void end_case() {
    CaseResult& r = results_.back();
    scoreboard_->finish(r);
    if (case_profile_) case_profile_->finish(cycle_ - case_start_cycle_, r);
    if (abort_open_)
      record_capped(r.scoreboard_errors, r.scoreboard_error_count,
                    std::string("abort at cycle ") + std::to_string(r.aborts.back().cycle) +
                        ": busy_o never fell");
    r.completed = true;
    r.seconds = bench_now() - case_clock_start_;
    if (++case_index_ < cases_.size())
      start_case();
    else
      finished_ = true;
  }

  // Walks the case's items for the next edge: settings apply at once, a gap or
  // a drain holds cmd_valid_i low, an abort raises abort_i for one edge, a
  // command is offered until the core takes it (cmd_ready_o, a register, seen
  // after the previous edge, tells whether it will).
  void drive_items() {
    while (const Item<A>* item = current_item()) {
      const Item<A>& it = *item;
      switch (it.kind) {
        case Kind::kSettings:
          settings_ = it.settings;
          setup_changed_ = true;
          next_item();
          continue;
        case Kind::kGap:
          if (gap_left_ == 0) gap_left_ = it.cycles;
          if (--gap_left_ == 0) next_item();
          return;
        case Kind::kDrain:
          if (last_busy_) return;
          next_item();
          continue;
        case Kind::kAbort:
          frame_.abort = true;
          next_item();
          return;
        case Kind::kCommand:
          // After an exact stop of the feed profile, the block comes to rest first.
          if (profile_ && profile_->holds_next_command(results_.back().commands)) return;
          frame_.cmd_valid = true;
          if (!cmd_loaded_) {
            frame_.set_cmd(it.cmd);
            cmd_loaded_ = true;
          }
          if (last_ready_) {
            // busy_o is the new command's from here: an abort still open
            // stays unmeasured (idle_after_clocks -1).
            abort_open_ = false;
            scoreboard_->command_taken(it.cmd, settings_.setup);
            if (case_profile_) case_profile_->command_taken();
            ++results_.back().commands;
            if (path_csv_) ideal_rows(it.cmd);
            A::apply(it.cmd, path_target_);
            path_row("target", path_target_);
            next_item();
            cmd_loaded_ = false;  // the next offer copies its own command in
          } else {
            ++results_.back().offer_wait_cycles;
          }
          return;
      }
    }
  }

  // The case's item at hand: from Case::items, then pulled one at a time
  // from Case::more (null when none is left).
  const Item<A>* current_item() {
    const Case<A>& c = cases_[case_index_];
    if (item_ < c.items.size()) return &c.items[item_];
    if (!c.more || !items_left_) {
      items_left_ = false;
      return nullptr;
    }
    if (!have_streamed_) {
      if (!c.more->next(streamed_)) {
        items_left_ = false;
        return nullptr;
      }
      have_streamed_ = true;
      if (streamed_.kind == Kind::kCommand) {
        budget_ += streamed_command_budget<A>(streamed_.cmd, spec_, settings_);
        ++results_.back().commands_offered;
      } else if (streamed_.kind == Kind::kGap) {
        budget_ += 2 * streamed_.cycles;
      } else {
        budget_ += 32;
      }
    }
    return &streamed_;
  }
  void next_item() {
    if (item_ < cases_[case_index_].items.size()) {
      ++item_;
      if (item_ == cases_[case_index_].items.size() && !cases_[case_index_].more)
        items_left_ = false;
    } else {
      have_streamed_ = false;
    }
  }

  // The abort edge: nothing may start on it; the position must be on the
  // reference path; then busy_o must fall within the core's bound.
  void abort_edge(bool moved, CaseResult& r) {
    const uint64_t case_cycle = cycle_ - case_start_cycle_;
    if (moved)
      record_capped(r.scoreboard_errors, r.scoreboard_error_count,
                    "cycle " + std::to_string(cycle_) + ": a step started on the abort edge");
    AbortRecord a;
    a.cycle = case_cycle;
    a.position = scoreboard_->position();
    a.on_reference_path = scoreboard_->abort();
    // A pulse already high keeps the length it started with.
    a.idle_bound = std::max<uint32_t>(frame_.timing.step_len, 1) - 1;
    a.idle_bound =
        std::max<uint64_t>(a.idle_bound, std::max<uint32_t>(monitors_.high_len(), 1) - 1);
    if (!a.on_reference_path)
      record_capped(r.scoreboard_errors, r.scoreboard_error_count,
                    "abort at cycle " + std::to_string(cycle_) + ": position " +
                        point_text(a.position) + " is not on the reference path");
    r.aborts.push_back(std::move(a));
    abort_open_ = true;
    abort_cycle_ = cycle_;
  }

  void follow_abort(const OutPins& seen, CaseResult& r) {
    if (!abort_open_) return;
    AbortRecord& a = r.aborts.back();
    // A pulse in flight follows the length setting of every clock it is high.
    a.idle_bound =
        std::max<uint64_t>(a.idle_bound, std::max<uint32_t>(frame_.timing.step_len, 1) - 1);
    if (seen.busy) return;
    abort_open_ = false;
    a.idle_after_clocks = static_cast<int64_t>(cycle_ - abort_cycle_);
    if (static_cast<uint64_t>(a.idle_after_clocks) > a.idle_bound)
      record_capped(r.scoreboard_errors, r.scoreboard_error_count,
                    "abort at cycle " + std::to_string(abort_cycle_) + ": busy_o fell " +
                        std::to_string(a.idle_after_clocks) + " clocks later, bound " +
                        std::to_string(a.idle_bound));
  }

  // `p` with step_o[0] flipped (a planned fault), in flip_.
  const OutPins& flipped(const OutPins& p) {
    flip_ = p;
    flip_.step ^= 1;
    return flip_;
  }

  // The two DUTs' outputs differ: name the first differing signal, in port order.
  void record_mismatch(const OutPins& hls, const OutPins& rtl) {
    Mismatch m{cycle_, "", 0, 0};
    auto differs = [&](const std::string& name, uint64_t h, uint64_t r) {
      if (h == r || !m.signal.empty()) return;
      m.signal = name;
      m.hls = h;
      m.rtl = r;
    };
    differs("cmd_ready_o", hls.cmd_ready, rtl.cmd_ready);
    for (int i = 0; i < spec_.axes; ++i)
      differs("step_o[" + std::to_string(i) + "]", (hls.step >> i) & 1, (rtl.step >> i) & 1);
    for (int i = 0; i < spec_.axes; ++i)
      differs("dir_o[" + std::to_string(i) + "]", (hls.dir >> i) & 1, (rtl.dir >> i) & 1);
    for (int i = 0; i < spec_.axes; ++i)
      differs("pos_o[" + std::to_string(i) + "]", hls.pos[static_cast<size_t>(i)],
              rtl.pos[static_cast<size_t>(i)]);
    differs("busy_o", hls.busy, rtl.busy);
    differs("done_o", hls.done, rtl.done);
    // The inputs the two took at that edge, by port.
    uint64_t in[Trace::kMaxInputs] = {};
    flat_inputs<A>(frame_, flatten_, in);
    size_t k = 0;
    for (const PortSpec& p : input_ports(spec_)) {
      Json values = Json::array();
      for (int i = 0; i < p.count; ++i) values.push_back(p.value(in[k++]));
      m.inputs[p.name] = p.count == 1 ? values[0] : values;
    }
    CaseResult& r = results_.back();
    r.mismatches = 1;
    r.first_mismatch = m;
  }

  void print_progress() {
    const CaseResult& r = results_.back();
    std::string what = "case " + std::to_string(case_index_ + 1) + "/" +
                       std::to_string(cases_.size()) + " '" + r.name + "', " +
                       std::to_string(r.commands) + " commands done of " +
                       std::to_string(r.commands_offered) + " taken";
    // Without an estimate of the clocks: the share of the cases' items
    // offered, when every case's items are known ahead (no streamed source).
    double share = -1;
    size_t total = 0, offered = item_;
    bool known = true;
    for (size_t i = 0; i < cases_.size(); ++i) {
      known = known && !cases_[i].more;
      total += cases_[i].items.size();
      if (i < case_index_) offered += cases_[i].items.size();
    }
    if (known && total > 0) share = static_cast<double>(offered) / static_cast<double>(total);
    progress_.print(cycle_, spec_.variant + " " + options_.mode, what, share);
  }

  // A row of the path CSV: kind start, target or move (with the move's
  // deviation from the ideal path and the bound), or ideal (a vertex of a
  // command's ideal path).
  template <class Point>
  void path_row(const char* kind, const Point& p, double error = -1) {
    if (!path_csv_) return;
    *path_csv_ << cases_[case_index_].name << ',' << cycle_ - case_start_cycle_ << ',' << kind;
    for (const auto v : p) *path_csv_ << ',' << v;
    *path_csv_ << ',';
    if (error >= 0)
      *path_csv_ << error << ',' << results_.back().error_bound;
    else
      *path_csv_ << ',';
    *path_csv_ << '\n';
  }
  void ideal_rows(const typename A::Command& cmd) {
    const typename A::Reference ref(path_target_, cmd, settings_.setup, spec_);
    for (const auto& p : ref.ideal()) path_row("ideal", p);
  }

  VariantSpec spec_;
  std::vector<Case<A>> cases_;
  BenchOptions options_;
  FlattenPayload<A> flatten_;
  std::vector<CaseResult> results_;
  std::unique_ptr<Trace> trace_;
  std::unique_ptr<FrameWriter> frames_;
  std::unique_ptr<std::ofstream> path_csv_;
  std::unique_ptr<StepTimesCsv> step_times_;
  models::LatticePoint path_target_;  // where the commands taken so far lead
  uint64_t in_values_[Trace::kMaxInputs] = {};

  uint64_t cycle_ = 0;  // clock edges so far in the run
  bool finished_ = false;

  // Current case.
  size_t case_index_ = 0;
  Phase phase_ = Phase::kReset;
  uint64_t phase_left_ = 0;  // reset / tail edges still to drive
  uint64_t case_start_cycle_ = 0;
  uint64_t budget_ = 0;
  // When the bench was made: the progress line's rate.
  ProgressLine progress_{options_.expected_clocks};
  size_t item_ = 0;
  bool items_left_ = false;     // Case::items or Case::more still has items
  Item<A> streamed_;            // the item pulled from Case::more...
  bool have_streamed_ = false;  // ...and not yet done
  uint64_t gap_left_ = 0;
  RunSettings<A> settings_;
  bool setup_changed_ = false;  // settings_.setup is not yet in frame_
  Frame<A> frame_;
  bool cmd_loaded_ = false;  // frame_.cmd() holds the command item at hand
  bool last_ready_ = false,
       last_busy_ = false;  // cmd_ready_o, busy_o after the last edge: what the driver reacts to
  OutPins flip_;            // a fault's copy of the pins (flipped())
  StepdirMonitors monitors_{0};
  std::optional<Scoreboard<A>> scoreboard_;
  std::unique_ptr<CaseProfileRun<A>> case_profile_;  // the case's feed profile (Case::profile)
  ProfileFeed* profile_ = nullptr;                   // the profile driving feed_i, if any
  bool abort_open_ = false;                          // an abort whose busy_o has not fallen yet
  uint64_t abort_cycle_ = 0;
  double case_clock_start_ = 0;
};

}  // namespace hwinterp::tb

#include "dda_line_bench.h"

#include <chrono>
#include <cstdio>

namespace hwinterp::tb {

namespace {
constexpr uint64_t kResetCycles = 2;
constexpr uint64_t kTailCycles = 2;  // after the core goes idle, so traces show the end

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

DdaLineBench::DdaLineBench(DdaLineLimits limits, std::vector<DdaLineCase> cases,
                           BenchOptions options)
    : limits_(std::move(limits)), cases_(std::move(cases)), options_(std::move(options)) {
  if (!options_.trace_path.empty())
    trace_ = std::make_unique<DdaLineTrace>(options_.trace_path, limits_, options_.trace_window);
  if (!options_.frames_path.empty())
    frames_ = std::make_unique<DdaLineFrameWriter>(options_.frames_path, limits_);
  if (!options_.path_csv.empty()) {
    path_csv_ = std::make_unique<std::ofstream>(options_.path_csv);
    if (!*path_csv_) throw std::runtime_error("cannot write path CSV '" + options_.path_csv + "'");
    *path_csv_ << "case,cycle,kind";
    for (int i = 0; i < limits_.axes; ++i) *path_csv_ << ",p" << i;
    *path_csv_ << "\n";
  }
  if (cases_.empty())
    finished_ = true;
  else
    start_case();
}

DdaLineBench::~DdaLineBench() = default;

void DdaLineBench::close_trace() {
  if (trace_) trace_->close();
  if (frames_) frames_->close();
  if (path_csv_) {
    path_csv_->close();
    if (!*path_csv_) throw std::runtime_error("error writing path CSV '" + options_.path_csv + "'");
  }
}

void DdaLineBench::path_row(const char* kind, const models::LatticePoint& p) {
  if (!path_csv_) return;
  *path_csv_ << cases_[case_index_].name << ',' << cycle_ - case_start_cycle_ << ',' << kind;
  for (const int64_t v : p) *path_csv_ << ',' << v;
  *path_csv_ << '\n';
}

void DdaLineBench::start_case() {
  const DdaLineCase& c = cases_[case_index_];
  CaseResult r;
  r.core = "dda_line";
  r.variant = limits_.variant;
  r.name = c.name;
  r.mode = options_.mode;
  r.seed = options_.seed;
  r.commands_offered = command_count(c);
  r.steps.assign(static_cast<size_t>(limits_.axes), 0);
  r.start = c.start;
  results_.push_back(std::move(r));

  phase_ = Phase::kReset;
  phase_left_ = kResetCycles;
  case_start_cycle_ = cycle_;
  budget_ = cycle_budget(c, limits_);
  item_ = 0;
  gap_left_ = 0;
  settings_ = c.settings;
  last_rtl_ = DdaLinePins{};
  prev_step_ = 0;
  monitors_.clear();
  for (int i = 0; i < limits_.axes; ++i) monitors_.emplace_back(i);
  scoreboard_ =
      std::make_unique<DdaLineScoreboard>(limits_.axes, limits_.pos_w, c.start, case_start_cycle_);
  case_clock_start_ = now_seconds();
  path_target_ = c.start;
  path_row("start", c.start);
}

void DdaLineBench::end_case() {
  CaseResult& r = results_.back();
  scoreboard_->finish(r);
  r.completed = true;
  r.seconds = now_seconds() - case_clock_start_;
  if (++case_index_ < cases_.size())
    start_case();
  else
    finished_ = true;
}

// Walks the case's items for the next edge: settings apply at once, a gap or
// a drain holds cmd_valid_i low, a command is offered until the core takes it
// (cmd_ready_o, a register, seen after the previous edge, tells whether it will).
void DdaLineBench::drive_items() {
  const auto& items = cases_[case_index_].items;
  while (item_ < items.size()) {
    const DdaLineItem& it = items[item_];
    switch (it.kind) {
      case DdaLineItem::Kind::kSettings:
        settings_ = it.settings;
        ++item_;
        continue;
      case DdaLineItem::Kind::kGap:
        if (gap_left_ == 0) gap_left_ = it.cycles;
        if (--gap_left_ == 0) ++item_;
        return;
      case DdaLineItem::Kind::kDrain:
        if (last_rtl_.busy) return;
        ++item_;
        continue;
      case DdaLineItem::Kind::kCommand:
        frame_.cmd_valid = true;
        for (size_t i = 0; i < it.delta.size(); ++i) frame_.cmd_delta[i] = it.delta[i];
        if (last_rtl_.cmd_ready) {
          scoreboard_->command_taken(
              it.delta, settings_.half_preload ? models::Preload::kHalf : models::Preload::kZero);
          ++results_.back().commands;
          ++item_;
          for (size_t i = 0; i < it.delta.size(); ++i) path_target_[i] += it.delta[i];
          path_row("target", path_target_);
        }
        return;
    }
  }
}

const DdaLineFrame& DdaLineBench::next_frame() {
  frame_.cmd_valid = false;
  frame_.cmd_delta.fill(0);
  frame_.rst_n = phase_ != Phase::kReset;
  if (phase_ == Phase::kRun) drive_items();
  frame_.feed = settings_.feed;
  frame_.half_preload = settings_.half_preload;
  frame_.timing = settings_.timing;
  return frame_;
}

bool DdaLineBench::compare(const DdaLinePins& hls, const DdaLinePins& rtl) {
  if (hls == rtl) return true;
  // Name the first differing signal, in port order.
  Mismatch m{cycle_, "", 0, 0};
  auto differs = [&](const std::string& name, uint64_t h, uint64_t r) {
    if (h == r || !m.signal.empty()) return;
    m.signal = name;
    m.hls = h;
    m.rtl = r;
  };
  differs("cmd_ready_o", hls.cmd_ready, rtl.cmd_ready);
  for (int i = 0; i < limits_.axes; ++i)
    differs("step_o[" + std::to_string(i) + "]", (hls.step >> i) & 1, (rtl.step >> i) & 1);
  for (int i = 0; i < limits_.axes; ++i)
    differs("dir_o[" + std::to_string(i) + "]", (hls.dir >> i) & 1, (rtl.dir >> i) & 1);
  for (int i = 0; i < limits_.axes; ++i)
    differs("pos_o[" + std::to_string(i) + "]", hls.pos[static_cast<size_t>(i)],
            rtl.pos[static_cast<size_t>(i)]);
  differs("busy_o", hls.busy, rtl.busy);
  differs("done_o", hls.done, rtl.done);
  CaseResult& r = results_.back();
  r.mismatches = 1;
  r.first_mismatch = m;
  return false;
}

void DdaLineBench::print_progress() const {
  const CaseResult& r = results_.back();
  std::fprintf(stderr, "  [%s %s] cycle %llu: case %zu/%zu '%s', command %llu/%llu\n",
               limits_.variant.c_str(), options_.mode.c_str(),
               static_cast<unsigned long long>(cycle_), case_index_ + 1, cases_.size(),
               r.name.c_str(), static_cast<unsigned long long>(r.commands),
               static_cast<unsigned long long>(r.commands_offered));
}

void DdaLineBench::observe(const DdaLinePins& hls, const DdaLinePins& rtl) {
  ++cycle_;
  if (options_.progress_every && cycle_ % options_.progress_every == 0) print_progress();
  const FaultPlan& f = options_.faults;
  DdaLinePins hls_seen = hls;
  if (f.flip_hls_step_at == cycle_) hls_seen.step ^= 1;
  if (trace_) trace_->record(cycle_, frame_, hls_seen, rtl);
  if (frames_) frames_->write(frame_);

  CaseResult& r = results_.back();
  r.cycles = cycle_ - case_start_cycle_;
  if (!compare(hls_seen, rtl)) {
    // The first mismatch ends the run: nothing after it can be trusted.
    r.end_position = scoreboard_->position();
    r.expected_end_position = scoreboard_->expected_end();
    r.seconds = now_seconds() - case_clock_start_;
    finished_ = true;
    return;
  }
  last_rtl_ = rtl;
  DdaLinePins seen = rtl;
  if (f.glitch_step_at == cycle_) seen.step ^= 1;

  if (frame_.rst_n) {
    for (int i = 0; i < limits_.axes; ++i)
      monitors_[static_cast<size_t>(i)].observe(cycle_, (seen.step >> i) & 1, (seen.dir >> i) & 1,
                                                frame_.timing, r.timing_violations,
                                                r.timing_violation_count);
    scoreboard_->observe(cycle_, seen, r);
    // A rising step edge is a move (the scoreboard has just applied it).
    if (path_csv_ && (seen.step & ~prev_step_)) path_row("move", scoreboard_->position());
    prev_step_ = seen.step;
  }

  switch (phase_) {
    case Phase::kReset:
      if (--phase_left_ == 0) phase_ = Phase::kRun;
      break;
    case Phase::kRun:
      // Idle after the last item: the last command taken shows busy_o on the
      // edge that took it, so !busy here means everything has run.
      if (item_ == cases_[case_index_].items.size() && !frame_.cmd_valid && !rtl.busy) {
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
  if (r.cycles > budget_) {
    r.timed_out = true;
    end_case();
  }
}

}  // namespace hwinterp::tb

#include "tb/board/board_sim.h"

#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "models/common.h"
#include "tb/report/progress.h"

namespace hwinterp::board {

std::atomic<bool>& board_sim_stop() {
  static std::atomic<bool> stop{false};
  return stop;
}

namespace {
void on_signal(int) { board_sim_stop().store(true); }
constexpr const char* kLetters = models::kAxisLetters;
constexpr size_t kKeptViolations = 20;
}  // namespace

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

BoardRun::BoardRun(std::string board, int axes, uint64_t sys_hz, const BoardSimOptions& o)
    : board_(std::move(board)),
      axes_(axes),
      sys_hz_(sys_hz),
      pos_(static_cast<size_t>(axes), 0),
      steps_(static_cast<size_t>(axes), 0) {
  if (!o.steps_csv.empty()) steps_csv_ = std::make_unique<tb::StepTimesCsv>(o.steps_csv, axes);
  if (!o.commands_csv.empty()) {
    commands_csv_ = std::make_unique<std::ofstream>(o.commands_csv);
    if (!*commands_csv_) throw std::runtime_error("cannot write commands '" + o.commands_csv + "'");
    *commands_csv_ << "command,clock";
    for (int i = 0; i < axes; ++i) *commands_csv_ << ',' << kLetters[i] << "_steps";
    *commands_csv_ << '\n';
  }
}

void BoardRun::observe(uint64_t clock, uint32_t a, uint32_t b, const tb::StepdirTiming& t,
                       const std::vector<tb::StepType>& types, bool done, bool bite,
                       bool stopping) {
  if (!monitors_ || types != types_) {
    // A new step type takes effect while the axis's output is low: the
    // monitors start over with the new types.
    types_ = types;
    monitors_ = std::make_unique<tb::StepOutputMonitors>(types_);
  }
  uint32_t dir = 0;
  const uint32_t rising = monitors_->observe(clock, a, b, t, dir, violations_, violation_count_);
  if (violations_.size() > kKeptViolations) violations_.resize(kKeptViolations);
  if (rising) {
    for (int i = 0; i < axes_; ++i)
      if ((rising >> i) & 1) {
        pos_[static_cast<size_t>(i)] += ((dir >> i) & 1) ? -1 : 1;
        ++steps_[static_cast<size_t>(i)];
        ++step_count_;
      }
    if (steps_csv_) steps_csv_->write(clock, rising, dir);
    last_step_clock_ = clock;
    if (!bites_.empty()) {
      Bite& last = bites_.back();
      if (last.rested)
        ++last.steps_after_rest;
      else
        ++last.steps_to_rest;
    }
  }
  // A command's last steps come out of the monitors a clock after motion_top's
  // done (tb/monitor/step_output_monitor.h): its end position is counted
  // with the clock after it, which the CSV's clock is.
  if (done_pending_) {
    ++commands_;
    if (commands_csv_) {
      *commands_csv_ << commands_ << ',' << clock;
      for (int64_t p : pos_) *commands_csv_ << ',' << p;
      *commands_csv_ << '\n';
    }
  }
  done_pending_ = done;
  if (bite) bites_.push_back(Bite{clock, 0, false, 0, 0});
  if (was_stopping_ && !stopping && !bites_.empty() && !bites_.back().rested) {
    bites_.back().rested = true;
    bites_.back().rest_clock = clock;
  }
  was_stopping_ = stopping;
}

void BoardRun::close() {
  if (steps_csv_) steps_csv_->close();
  if (commands_csv_) {
    commands_csv_->close();
    if (!*commands_csv_) throw std::runtime_error("error writing the commands CSV");
  }
}

bool BoardRun::passed(uint64_t bad_link_units) const {
  // Steps after a watchdog's rest are reported, not failed: a host may clear
  // EVENTS.wdog and go on.
  return violation_count_ == 0 && bad_link_units == 0;
}

Json BoardRun::report(const Json& link, double seconds, uint64_t clocks) const {
  Json steps = Json::array(), position = Json::array();
  for (int i = 0; i < axes_; ++i) {
    steps.push_back(steps_[static_cast<size_t>(i)]);
    position.push_back(pos_[static_cast<size_t>(i)]);
  }
  Json violations = Json::array();
  for (const auto& v : violations_)
    violations.push_back({{"clock", v.cycle},
                          {"axis", std::string(1, kLetters[v.axis])},
                          {"rule", v.rule},
                          {"measured", v.measured},
                          {"required", v.required}});
  Json bites = Json::array();
  for (const Bite& b : bites_)
    bites.push_back({{"bite_clock", b.clock},
                     {"rest_clock", b.rested ? Json(b.rest_clock) : Json(nullptr)},
                     {"stop_clocks", b.rested ? Json(b.rest_clock - b.clock) : Json(nullptr)},
                     {"steps_to_rest", b.steps_to_rest},
                     {"steps_after_rest", b.steps_after_rest}});
  return Json{{"board", board_},
              {"sys_hz", sys_hz_},
              {"clocks", clocks},
              {"seconds", seconds},
              {"clocks_per_second", seconds > 0 ? static_cast<double>(clocks) / seconds : 0.0},
              {"link", link},
              {"steps", steps},
              {"position", position},
              {"commands_completed", commands_},
              {"last_step_clock", last_step_clock_},
              {"timing_violations", violation_count_},
              {"first_timing_violations", violations},
              {"watchdog_bites", bites}};
}

void board_sim_progress(const std::string& board, uint64_t clock, uint64_t sys_hz, double wall,
                        double share) {
  const std::string bound = tb::share_text(share, wall, "its bound");
  std::fprintf(stderr,
               "board-sim %s: %.3f s of board time (%llu clocks) in %.1f s%s, %.2f M clocks/s\n",
               board.c_str(), static_cast<double>(clock) / static_cast<double>(sys_hz),
               static_cast<unsigned long long>(clock), wall, bound.c_str(),
               wall > 0 ? static_cast<double>(clock) / wall / 1e6 : 0.0);
}

}  // namespace hwinterp::board

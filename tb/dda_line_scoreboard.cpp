#include "dda_line_scoreboard.h"

#include <sstream>

namespace hwinterp::tb {

namespace {
std::string vec(const std::vector<int>& v) {
  std::string s = "(";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
  return s + ")";
}
std::string vec(const models::LatticePoint& v) {
  std::string s = "(";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
  return s + ")";
}
}  // namespace

DdaLineScoreboard::DdaLineScoreboard(int axes, int pos_w, models::LatticePoint start,
                                     uint64_t case_start_cycle)
    : axes_(axes),
      pos_w_(pos_w),
      case_start_cycle_(case_start_cycle),
      start_(start),
      at_(start),
      expected_end_(std::move(start)) {}

void DdaLineScoreboard::command_taken(const std::vector<int64_t>& delta, models::Preload preload) {
  Command c{delta, preload, expected_end_, expected_end_};
  for (int i = 0; i < axes_; ++i) c.end[i] += delta[i];
  expected_end_ = c.end;
  taken_.push_back(std::move(c));
}

void DdaLineScoreboard::error(CaseResult& r, const std::string& what) {
  record_capped(r.scoreboard_errors, r.scoreboard_error_count, what);
}

bool DdaLineScoreboard::next_expected_move(models::DdaMove& m) {
  for (;;) {
    if (!stream_) {
      if (current_ >= taken_.size()) return false;
      const Command& c = taken_[current_];
      stream_.emplace(c.start, c.delta, c.preload);
    }
    if (stream_->next(m)) return true;
    stream_.reset();
    ++current_;
  }
}

bool DdaLineScoreboard::has_moves_left(size_t command) const {
  if (command < current_) return false;
  models::DdaMove m;
  if (command == current_ && stream_) {
    models::DdaMoveStream probe = *stream_;
    return probe.next(m);
  }
  const Command& c = taken_[command];
  models::DdaMoveStream probe(c.start, c.delta, c.preload);
  return probe.next(m);
}

void DdaLineScoreboard::check_path_error(uint64_t cycle, CaseResult& r) {
  const Command& c = taken_[current_];
  const double e = models::point_line_distance(at_, c.start, c.end);
  const models::ErrorBound bound = models::dda_error_bound(axes_, c.preload);
  if (e > r.max_path_error_steps) r.max_path_error_steps = e;
  if (bound.value > r.error_bound) {
    r.error_bound = bound.value;
    r.error_bound_strict = bound.strict;
  }
  if (!models::within_bound(e, bound)) {
    std::ostringstream os;
    os << "cycle " << cycle << ": point " << vec(at_) << " of command #" << current_ + 1 << " is "
       << e << " steps from its line, bound " << (bound.strict ? "< " : "<= ") << bound.value;
    error(r, os.str());
  }
}

void DdaLineScoreboard::observe(uint64_t cycle, const DdaLinePins& pins, CaseResult& r) {
  const uint32_t rising = pins.step & ~prev_step_;
  prev_step_ = pins.step;
  if (rising) {
    if (r.first_step_cycle == 0) r.first_step_cycle = cycle - case_start_cycle_;
    std::vector<int> step(static_cast<size_t>(axes_), 0);
    for (int i = 0; i < axes_; ++i) {
      if (!((rising >> i) & 1)) continue;
      step[static_cast<size_t>(i)] = ((pins.dir >> i) & 1) ? -1 : 1;
      at_[static_cast<size_t>(i)] += step[static_cast<size_t>(i)];
      ++r.steps[static_cast<size_t>(i)];
    }
    if (!diverged_) {
      models::DdaMove m;
      if (!next_expected_move(m)) {
        error(r, "cycle " + std::to_string(cycle) + ": move " + vec(step) +
                     " but every command taken has already finished its moves");
        diverged_ = true;
      } else if (m.step != step) {
        error(r, "cycle " + std::to_string(cycle) + ": command #" + std::to_string(current_ + 1) +
                     " iteration " + std::to_string(m.iteration) + ": expected move " +
                     vec(m.step) + ", the core stepped " + vec(step));
        diverged_ = true;
      } else {
        check_path_error(cycle, r);
      }
    }
  }
  // done_o comes with the last iteration's steps: by then every move of that
  // command (and of the zero-move commands before it) has been seen.
  if (pins.done) {
    if (done_count_ >= taken_.size()) {
      error(r, "cycle " + std::to_string(cycle) + ": done_o pulse with no command running");
    } else if (!diverged_) {
      for (size_t k = current_; k <= done_count_; ++k)
        if (has_moves_left(k)) {
          error(r, "cycle " + std::to_string(cycle) + ": done_o for command #" +
                       std::to_string(done_count_ + 1) + " before all its steps");
          diverged_ = true;
          break;
        }
      if (!diverged_) {
        current_ = static_cast<size_t>(done_count_) + 1;
        stream_.reset();
      }
    }
    ++done_count_;
  }
  // pos_o holds the position relative to reset, POS_W bits.
  const uint64_t mask = pos_w_ >= 64 ? ~uint64_t{0} : (uint64_t{1} << pos_w_) - 1;
  for (int i = 0; i < axes_; ++i) {
    const size_t a = static_cast<size_t>(i);
    const uint64_t want = static_cast<uint64_t>(at_[a] - start_[a]) & mask;
    if (pins.pos[a] != want && !pos_reported_) {
      pos_reported_ = true;
      error(r, "cycle " + std::to_string(cycle) + ": pos_o[" + std::to_string(i) +
                   "] = " + std::to_string(pins.pos[a]) +
                   " but the steps on step_o/dir_o add up to " + std::to_string(want));
      break;
    }
  }
}

void DdaLineScoreboard::finish(CaseResult& r) {
  r.end_position = at_;
  r.expected_end_position = expected_end_;
  if (done_count_ != taken_.size())
    error(r, std::to_string(taken_.size()) + " commands taken but " + std::to_string(done_count_) +
                 " done_o pulses");
  if (at_ != expected_end_) error(r, "ended at " + vec(at_) + ", expected " + vec(expected_end_));
}

}  // namespace hwinterp::tb

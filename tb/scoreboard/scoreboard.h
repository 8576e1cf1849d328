// The step-stream scoreboard every core shares: integrates the step/dir
// outputs into lattice moves (the axes whose step_o rises on one clock) and
// checks them, move by move, against the core's reference model; checks pos_o
// against the integrated position on every clock, one done_o pulse per
// completed command after its last step, the exact end point, and the
// deviation of every visited point from the ideal path against the bound the
// core states. After an abort the position must be a point of the reference
// path (a prefix of the model's moves) and the commands not done are dropped.
//
// A is the core's adapter. Its reference model, one per command taken:
//   A::Reference(const LatticePoint& start, const A::Command&, const A::Setup&,
//                const VariantSpec&)
//   bool next(Move&)                      the next move; false when none is left
//   double error(const LatticePoint&)     deviation of a visited point from the ideal path
//   models::ErrorBound bound()            the bound the error is checked against
//   std::vector<std::vector<double>> ideal()   the ideal path as a polyline (plots)
// (a copyable value: the scoreboard probes copies). Optionally, a model
// checks figures of its own at points it chooses (tb/report/cosim_result.h,
// CoreCheck), e.g. log_stepper's coarse points against the double model:
//   void check(const LatticePoint& at, CaseResult&, std::vector<std::string>& failures)
//       after each move of its command the scoreboard has matched (`at` is
//       where the step/dir outputs have taken the axes);
//   void finish(const LatticePoint& at, CaseResult&, std::vector<std::string>& failures)
//       on its command's done_o (every move seen).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "models/error_bound.h"
#include "tb/base/case_result.h"
#include "tb/base/out_pins.h"
#include "tb/scoreboard/move.h"
#include "tb/stimulus/settings.h"

namespace hwinterp::tb {

template <class R, class = void>
struct HasCoreChecks : std::false_type {};
template <class R>
struct HasCoreChecks<R,
                     std::void_t<decltype(std::declval<R&>().check(
                         std::declval<const models::LatticePoint&>(), std::declval<CaseResult&>(),
                         std::declval<std::vector<std::string>&>()))>> : std::true_type {};

template <class A>
class Scoreboard {
 public:
  using Reference = typename A::Reference;

  // `case_start_cycle`: run cycle before the case's first edge (cycles in
  // reports are counted from the case start).
  Scoreboard(const VariantSpec& spec, models::LatticePoint start, uint64_t case_start_cycle)
      : limits_(spec),
        axes_(spec.axes),
        case_start_cycle_(case_start_cycle),
        start_(start),
        at_(start),
        expected_end_(std::move(start)),
        pos_mask_(spec.pos_w >= 64 ? ~uint64_t{0} : (uint64_t{1} << spec.pos_w) - 1) {}

  // A command the core took, in order, with the setup it was taken with.
  void command_taken(const typename A::Command& cmd, const typename A::Setup& setup) {
    Command c{cmd, setup, expected_end_, expected_end_};
    A::apply(cmd, c.end);
    expected_end_ = c.end;
    taken_.push_back(std::move(c));
  }

  // Commands taken so far, and those completed (done_o) so far.
  uint64_t taken_count() const { return first_ + taken_.size(); }
  uint64_t done_count() const { return done_count_; }
  // The (0-based) command whose moves the core is making.
  uint64_t current_command() const { return current_; }

  // Outputs after one clock edge (not during reset). Returns true when a
  // move (a rising step edge on some axis) was applied. Most clocks have
  // neither a move nor done_o: they only compare pos_o, inline.
  bool observe(uint64_t cycle, const OutPins& pins, CaseResult& r) {
    const uint32_t rising = pins.step & ~prev_step_;
    prev_step_ = pins.step;
    rising_ = rising;
    if (rising || pins.done) observe_event(cycle, pins, rising, r);
    uint64_t pos_diff = 0;
    for (int i = 0; i < axes_; ++i)
      pos_diff |= pins.pos[static_cast<size_t>(i)] ^ want_pos_[static_cast<size_t>(i)];
    if (pos_diff != 0 && !pos_reported_) report_pos(cycle, pins, r);
    return rising != 0;
  }

  // The abort edge has been observed: every command taken and not done is
  // dropped, later commands start where the axes are. Returns whether that
  // position is on the reference path (every move so far was the model's).
  bool abort() {
    const bool on_path = !diverged_;
    if (taken_count() > done_count_) taken_.resize(static_cast<size_t>(done_count_ - first_));
    current_ = static_cast<size_t>(taken_count());
    stream_.reset();
    expected_end_ = at_;
    diverged_ = false;  // the findings so far are reported; compare afresh
    return on_path;
  }

  // End of the case: everything taken must have completed and arrived.
  void finish(CaseResult& r) {
    r.end_position = at_;
    r.expected_end_position = expected_end_;
    if (done_count_ != taken_count())
      error(r, std::to_string(taken_count()) + " commands taken but " +
                   std::to_string(done_count_) + " done_o pulses");
    if (at_ != expected_end_)
      error(r, "ended at " + point_text(at_) + ", expected " + point_text(expected_end_));
  }

  // The axes whose step pulse rose on the last observed clock (bit i: axis i).
  uint32_t rising() const { return rising_; }
  // Where the step/dir outputs have taken the axes so far, and where the
  // commands taken so far lead (for a report cut short by a mismatch).
  const models::LatticePoint& position() const { return at_; }
  const models::LatticePoint& expected_end() const { return expected_end_; }
  // Deviation of the last move's point from its command's ideal path.
  double last_error() const { return last_error_; }

 private:
  // The moves of the axes in `rising`, then done_o.
  void observe_event(uint64_t cycle, const OutPins& pins, uint32_t rising, CaseResult& r) {
    if (rising) {
      if (r.first_step_cycle == 0) r.first_step_cycle = cycle - case_start_cycle_;
      Move seen;
      for (int i = 0; i < axes_; ++i) {
        const size_t a = static_cast<size_t>(i);
        if (!((rising >> i) & 1)) continue;
        seen.step[a] = ((pins.dir >> i) & 1) ? -1 : 1;
        at_[a] += seen.step[a];
        want_pos_[a] = static_cast<uint64_t>(at_[a] - start_[a]) & pos_mask_;
        ++r.steps[a];
      }
      if (!diverged_) {
        Move want;
        if (!next_expected_move(want)) {
          error(r, "cycle " + std::to_string(cycle) + ": move " + move_text(seen) +
                       " but every command taken has already finished its moves");
          diverged_ = true;
        } else if (!want.same_steps(seen, axes_)) {
          error(r, "cycle " + std::to_string(cycle) + ": command #" + std::to_string(current_ + 1) +
                       " operation " + std::to_string(want.index) + ": expected move " +
                       move_text(want) + ", the core stepped " + move_text(seen));
          diverged_ = true;
        } else {
          check_path_error(cycle, r);
          if constexpr (HasCoreChecks<Reference>::value) {
            stream_->check(at_, r, failures_);
            report_failures(cycle, r);
          }
        }
      }
    }
    // done_o comes with the last operation's steps: by then every move of that
    // command (and of the zero-move commands before it) has been seen.
    if (pins.done) {
      if (done_count_ >= taken_count()) {
        error(r, "cycle " + std::to_string(cycle) + ": done_o pulse with no command running");
      } else if (!diverged_) {
        for (size_t k = current_; k <= done_count_; ++k)
          if (has_moves_left(k)) {
            error(r, "cycle " + std::to_string(cycle) + ": done_o for command #" +
                         std::to_string(done_count_ + 1) + " before all its steps");
            diverged_ = true;
            break;
          }
        if constexpr (HasCoreChecks<Reference>::value) {
          if (!diverged_ && stream_ && current_ == done_count_) {
            stream_->finish(at_, r, failures_);
            report_failures(cycle, r);
          }
        }
        if (!diverged_) {
          current_ = static_cast<size_t>(done_count_) + 1;
          stream_.reset();
        }
      }
      ++done_count_;
      forget_done();
    }
  }

  // pos_o must hold the position relative to reset, POS_W bits (want_pos_,
  // kept with at_); it does not: one report per case, for the first axis off.
  void report_pos(uint64_t cycle, const OutPins& pins, CaseResult& r) {
    for (int i = 0; i < axes_; ++i) {
      const size_t a = static_cast<size_t>(i);
      if (pins.pos[a] == want_pos_[a]) continue;
      pos_reported_ = true;
      error(r, "cycle " + std::to_string(cycle) + ": pos_o[" + std::to_string(i) +
                   "] = " + std::to_string(pins.pos[a]) +
                   " but the steps on step_o/dir_o add up to " + std::to_string(want_pos_[a]));
      return;
    }
  }

  struct Command {
    typename A::Command cmd;
    typename A::Setup setup;
    models::LatticePoint start, end;
  };

  static void error(CaseResult& r, const std::string& what) {
    record_capped(r.scoreboard_errors, r.scoreboard_error_count, what);
  }

  void report_failures(uint64_t cycle, CaseResult& r) {
    for (const auto& f : failures_) error(r, "cycle " + std::to_string(cycle) + ": " + f);
    failures_.clear();
  }

  std::string move_text(const Move& m) const {
    std::string s = "(";
    for (int i = 0; i < axes_; ++i)
      s += (i ? "," : "") + std::to_string(m.step[static_cast<size_t>(i)]);
    return s + ")";
  }

  Reference reference(const Command& c) const {
    return Reference(c.start, c.cmd, c.setup, limits_);
  }

  // Commands both completed and consumed are not needed any more: memory
  // stays bounded however long the stream.
  void forget_done() {
    while (!taken_.empty() && first_ < current_ && first_ < done_count_) {
      taken_.pop_front();
      ++first_;
    }
  }
  const Command& taken(size_t command) const { return taken_[command - first_]; }

  // The next move across the commands taken, in order.
  bool next_expected_move(Move& m) {
    for (;;) {
      if (!stream_) {
        if (current_ >= taken_count()) return false;
        stream_.emplace(reference(taken(current_)));
      }
      if (stream_->next(m)) return true;
      stream_.reset();
      ++current_;
    }
  }

  bool has_moves_left(size_t command) const {
    if (command < current_) return false;
    Move m;
    if (command == current_ && stream_) {
      Reference probe = *stream_;
      return probe.next(m);
    }
    Reference probe = reference(taken(command));
    return probe.next(m);
  }

  void check_path_error(uint64_t cycle, CaseResult& r) {
    const double e = stream_->error(at_);
    last_error_ = e;
    const models::ErrorBound bound = stream_->bound();
    if (e > r.max_path_error_steps) r.max_path_error_steps = e;
    // The weakest bound checked: an equal non-strict one too (a case starts
    // at "< 0", which an exact core's bound of 0, "<= 0", must replace).
    if (bound.value > r.error_bound || (bound.value == r.error_bound && !bound.strict)) {
      r.error_bound = bound.value;
      r.error_bound_strict = bound.strict;
    }
    if (!models::within_bound(e, bound))
      error(r, "cycle " + std::to_string(cycle) + ": point " + point_text(at_) + " of command #" +
                   std::to_string(current_ + 1) + " is " + std::to_string(e) +
                   " steps from its ideal path, bound " + (bound.strict ? "< " : "<= ") +
                   std::to_string(bound.value));
  }

  VariantSpec limits_;
  int axes_;
  uint64_t case_start_cycle_;
  models::LatticePoint start_, at_, expected_end_;
  std::deque<Command> taken_;  // from command first_ on: those not yet done or not yet consumed
  size_t first_ = 0;
  size_t current_ = 0;               // command whose moves are being consumed
  std::optional<Reference> stream_;  // moves of taken_[current_]
  uint64_t done_count_ = 0;
  uint32_t prev_step_ = 0;
  uint32_t rising_ = 0;
  double last_error_ = 0;
  std::vector<std::string> failures_;  // of the reference's own checks, reported at once
  bool diverged_ = false;      // after a wrong move the rest of the sequence is not compared
  bool pos_reported_ = false;  // one pos_o report per case, not one per cycle
  uint64_t pos_mask_;          // POS_W bits
  std::array<uint64_t, kMaxAxes> want_pos_{};  // what pos_o must read: at_ - start_, POS_W bits
};

}  // namespace hwinterp::tb

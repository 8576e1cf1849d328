// A long run's progress on stderr: the clocks done and the rate, and with an
// estimate of the run's clocks the percent and the time left. On a terminal
// the line updates in place; in a log (stderr not a terminal) each report
// is a line of its own.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace hwinterp::tb {

class ProgressLine {
 public:
  // `expected_clocks`: the run's estimated clocks (0: no estimate).
  explicit ProgressLine(double expected_clocks = 0);
  // Reports `clock` clocks done; `who` leads the line (the run's name),
  // `what` ends it (the case, the command). Without an estimate of the clocks,
  // `share` (0..1; negative: unknown) is the part of the run's commands
  // offered, for a percent and the time left.
  void print(uint64_t clock, const std::string& who, const std::string& what, double share = -1);
  // Ends a line left open on a terminal (no-op otherwise).
  void finish();
  double expected_clocks() const { return expected_; }

 private:
  double expected_;
  bool tty_;
  bool open_ = false;
  std::chrono::steady_clock::time_point started_;
};

// "12.3 M", "456 k", "789": a count for a progress line.
std::string short_count(double n);
// "45 s", "12 min", "3.4 h": a duration for a progress line.
std::string short_duration(double seconds);
// " (37 % of OF, ~12 s left)" for a run `share` (0..1] of the way through
// after `seconds`; "" for a share outside it.
std::string share_text(double share, double seconds, const std::string& of);

}  // namespace hwinterp::tb

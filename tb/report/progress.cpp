#include "tb/report/progress.h"

#include <unistd.h>

#include <cstdio>

namespace hwinterp::tb {

std::string short_count(double n) {
  char buf[32];
  if (n >= 1e9)
    std::snprintf(buf, sizeof buf, "%.3g G", n / 1e9);
  else if (n >= 1e6)
    std::snprintf(buf, sizeof buf, "%.3g M", n / 1e6);
  else if (n >= 1e4)
    std::snprintf(buf, sizeof buf, "%.3g k", n / 1e3);
  else
    std::snprintf(buf, sizeof buf, "%.0f", n);
  return buf;
}

std::string short_duration(double seconds) {
  char buf[32];
  if (seconds < 90)
    std::snprintf(buf, sizeof buf, "%.0f s", seconds);
  else if (seconds < 5400)
    std::snprintf(buf, sizeof buf, "%.0f min", seconds / 60);
  else
    std::snprintf(buf, sizeof buf, "%.1f h", seconds / 3600);
  return buf;
}

std::string share_text(double share, double seconds, const std::string& of) {
  if (!(share > 0 && share <= 1)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, " (%.0f %% of ", 100 * share);
  std::string text = buf + of;
  if (share < 1) text += ", ~" + short_duration(seconds * (1 - share) / share) + " left";
  return text + ")";
}

ProgressLine::ProgressLine(double expected_clocks)
    : expected_(expected_clocks > 0 ? expected_clocks : 0),
      tty_(isatty(STDERR_FILENO) == 1),
      started_(std::chrono::steady_clock::now()) {}

void ProgressLine::print(uint64_t clock, const std::string& who, const std::string& what,
                         double share) {
  const double s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const double done = static_cast<double>(clock);
  const double rate = s > 0 ? done / s : 0;
  std::string line = "  [" + who + "] " + short_count(done) + " clocks";
  if (expected_ > 0) {
    char buf[96];
    if (done <= expected_) {
      std::snprintf(buf, sizeof buf, " (%.0f %% of ~%s", 100 * done / expected_,
                    short_count(expected_).c_str());
      line += buf;
      if (rate > 0) line += ", ~" + short_duration((expected_ - done) / rate) + " left";
      line += ")";
    } else {
      line += " (beyond the estimate of ~" + short_count(expected_) + ")";
    }
  } else {
    line += share_text(share, s, "the commands");
  }
  line += ", " + short_count(rate) + " clocks/s, " + short_duration(s);
  if (!what.empty()) line += ", " + what;
  if (tty_) {
    std::fprintf(stderr, "\r%s\x1b[K", line.c_str());
    open_ = true;
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (open_) std::fputc('\n', stderr);
  open_ = false;
}

}  // namespace hwinterp::tb

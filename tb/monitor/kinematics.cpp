#include "tb/monitor/kinematics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hwinterp::tb {

namespace {

double norm(const std::vector<double>& v) {
  double s = 0;
  for (const double x : v) s += x * x;
  return std::sqrt(s);
}

void raise(KinematicsMonitor::Peak& p, double value, uint64_t clock) {
  if (value > p.value) p = {value, clock};
}

}  // namespace

KinematicsMonitor::KinematicsMonitor(int axes, std::vector<double> unit, uint64_t window_clocks)
    : axes_(axes),
      unit_(std::move(unit)),
      window_(window_clocks),
      window_end_(window_clocks),
      count_(static_cast<size_t>(axes), 0),
      axis_(static_cast<size_t>(axes)),
      scratch_(1),
      path_v_(static_cast<size_t>(axes), 0) {
  if (axes < 1 || window_clocks < 1 || unit_.size() != static_cast<size_t>(axes))
    throw std::invalid_argument("KinematicsMonitor: axes >= 1, window >= 1, a unit per axis");
  has_path_ = std::any_of(unit_.begin(), unit_.end(), [](double u) { return u != 0; });
}

void KinematicsMonitor::close_windows(uint64_t clock) {
  while (clock >= window_end_) {
    close_window();
    window_end_ += window_;
  }
}

void KinematicsMonitor::finish(uint64_t clock) {
  // A window ends at clock window_end_ - 1: it is complete once that clock ran.
  if (clock + 1 >= window_end_) close_windows(clock + 1);
}

void KinematicsMonitor::write_series(std::ostream* csv, const std::vector<std::string>& names) {
  series_ = csv;
  if (!series_) return;
  *series_ << "clock";
  if (has_path_) *series_ << ",path_speed,path_accel,path_jerk";
  for (const std::string& n : names)
    *series_ << ',' << n << "_speed," << n << "_accel," << n << "_jerk";
  *series_ << '\n';
}

void KinematicsMonitor::push(Track& t, const std::vector<double>& v, uint64_t clock,
                             double window) {
  t.v2.swap(t.v1);
  t.v1.swap(t.v0);
  t.v0 = v;
  t.seen = std::min(t.seen + 1, 3);
  const double speed = norm(t.v0);
  raise(t.peaks.speed, speed, clock);
  if (series_) *series_ << ',' << speed << ',';
  if (t.seen < 2) {
    if (series_) *series_ << ',';
    return;
  }
  std::vector<double> d(v.size());
  for (size_t i = 0; i < v.size(); ++i) d[i] = (t.v0[i] - t.v1[i]) / window;
  const double accel = norm(d);
  raise(t.peaks.accel, accel, clock);
  if (series_) *series_ << accel << ',';
  if (t.seen < 3) return;
  for (size_t i = 0; i < v.size(); ++i)
    d[i] = (t.v0[i] - 2 * t.v1[i] + t.v2[i]) / (window * window);
  const double jerk = norm(d);
  raise(t.peaks.jerk, jerk, clock);
  if (series_) *series_ << jerk;
}

void KinematicsMonitor::close_window() {
  const double w = static_cast<double>(window_);
  const uint64_t clock = window_end_ - 1;
  for (int i = 0; i < axes_; ++i) {
    const auto a = static_cast<size_t>(i);
    path_v_[a] = static_cast<double>(count_[a]) / w * unit_[a];
  }
  if (series_) *series_ << clock;
  if (has_path_) push(path_, path_v_, clock, w);
  for (int i = 0; i < axes_; ++i) {
    const auto a = static_cast<size_t>(i);
    scratch_[0] = static_cast<double>(count_[a]) / w;
    push(axis_[a], scratch_, clock, w);
    count_[a] = 0;
  }
  if (series_) *series_ << '\n';
  ++windows_;
}

KinematicsMonitor::Peaks KinematicsMonitor::tolerance() const {
  const double w = static_cast<double>(window_);
  Peaks t;
  t.speed.value = 2 / w;
  t.accel.value = 4 / (w * w);
  t.jerk.value = 8 / (w * w * w);
  return t;
}

}  // namespace hwinterp::tb

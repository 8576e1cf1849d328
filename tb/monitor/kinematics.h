// What the step stream asks of the machine: per axis and along the path,
// the highest speed, acceleration and jerk the pulses on the wire imply.
// Independent of any core: it sees only when each step pulse rose, on which
// axis, in which direction.
//
// The estimator. The run's clocks are cut into windows of W clocks, aligned
// on clock 0 (window j = clocks [jW, (j+1)W)). n_j is an axis's signed step
// count in window j (+1 or -1 per pulse). Then, in steps per clock^k,
//     v_j = n_j / W,   a_j = (v_{j+1} - v_j) / W,   jerk_j = (a_{j+1} - a_j) / W,
// the mean speed of each window and its first and second differences; a
// trailing window the run did not finish is left out. Along the path the
// same differences of the vector (n_j,i * unit_i) over the path's axes (unit_i
// the axis's units per step; the rotary axes have unit 0) are measured by
// their Euclidean length.
//
// Tolerance. If an axis's step count never differs from the position of a
// motion that obeys the limits by e steps or more (e = 1 for a stream that
// truncates an exact position; the cores keep within 1 step of theirs), each
// n_j is within 2e of that motion's travel over the window, so v_j exceeds
// the motion's highest speed by less than 2e / W, a_j its highest
// acceleration by less than 4e / W^2, jerk_j its highest jerk by less than
// 8e / W^3 (a mean over a window never exceeds the maximum: differences of
// window means are means of the derivative). tolerance() gives these for
// e = 1. A longer window gives a smaller tolerance and blurs short phases.
//
// Streaming: O(axes) memory, constant work per pulse and per window.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace hwinterp::tb {

class KinematicsMonitor {
 public:
  // The highest magnitude seen and the clock of the window it ends with.
  struct Peak {
    double value = 0;
    uint64_t clock = 0;
  };
  struct Peaks {
    Peak speed, accel, jerk;
  };

  // `axes` axes; `unit` per axis (units per step; 0: not part of the path);
  // windows of `window_clocks` >= 1 clocks.
  KinematicsMonitor(int axes, std::vector<double> unit, uint64_t window_clocks);

  // Pulses that rose on `clock` (bit i: axis i; dir bit set: -1), clocks in
  // non-decreasing order.
  void pulses(uint64_t clock, uint32_t rising, uint32_t dir) {
    if (clock >= window_end_) close_windows(clock);
    for (int i = 0; i < axes_; ++i)
      if ((rising >> i) & 1) count_[static_cast<size_t>(i)] += ((dir >> i) & 1) ? -1 : 1;
  }
  // The run ended on `clock`: closes the windows that ended by then.
  void finish(uint64_t clock);

  // Per axis, in steps per clock^k; along the path, in units per clock^k.
  const Peaks& axis(int i) const { return axis_[static_cast<size_t>(i)].peaks; }
  const Peaks& path() const { return path_.peaks; }
  // The estimator's tolerance for e = 1, in steps per clock^k (see the top).
  Peaks tolerance() const;
  uint64_t window_clocks() const { return window_; }
  // Every window as a CSV row (a plot's data), or none (null): the header
  // `clock,path_speed,path_accel,path_jerk,<axis>_speed,...` with `names` the
  // axes' column prefixes; each row the clock the window ends on and the
  // values in units (path) or steps (axes) per clock^k, empty where a
  // difference needs windows not yet seen.
  void write_series(std::ostream* csv, const std::vector<std::string>& names);
  uint64_t windows() const { return windows_; }

 private:
  // The last window means of one signal (speed of an axis, or the path's
  // velocity vector) and the peaks seen.
  struct Track {
    std::vector<double> v0, v1, v2;  // the last three window velocities, newest first
    int seen = 0;                    // how many of them are valid (up to 3)
    Peaks peaks;
  };
  void close_windows(uint64_t clock);
  void close_window();
  void push(Track& t, const std::vector<double>& v, uint64_t clock, double window);

  int axes_;
  std::vector<double> unit_;
  uint64_t window_;
  uint64_t window_end_;
  uint64_t windows_ = 0;
  std::vector<int64_t> count_;
  std::vector<Track> axis_;
  Track path_;
  bool has_path_ = false;
  std::vector<double> scratch_, path_v_;
  std::ostream* series_ = nullptr;
};

}  // namespace hwinterp::tb

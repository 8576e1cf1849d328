// The dda_line testbench, independent of how the two DUTs are clocked: it
// drives the stimulus one clock edge at a time, compares the HLS core and the
// RTL after every edge, runs the step/dir timing monitors and the scoreboard
// on the outputs, and collects one CaseResult per case. The direct runner (a
// C++ loop) and the SystemC runner (a negedge process) both call it, so the
// two modes see the same stimulus and the same checks.
//
// Protocol per clock edge: in = next_frame(); both DUTs take `in` at the edge;
// observe(hls_outputs, rtl_outputs). Repeat while !finished().
#pragma once

#include <cstdint>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cosim_result.h"
#include "dda_line_frames.h"
#include "dda_line_pins.h"
#include "dda_line_scoreboard.h"
#include "dda_line_stimulus.h"
#include "dda_line_trace.h"
#include "stepdir_monitor.h"

namespace hwinterp::tb {

// Test hooks that prove the checks can fail. Cycles count clock edges from
// the start of the run (1-based).
struct FaultPlan {
  // Invert step_o[0] of the HLS outputs before the lockstep comparison.
  std::optional<uint64_t> flip_hls_step_at;
  // Invert step_o[0] of the RTL outputs after the comparison, as the
  // monitors and the scoreboard see them (a glitch on the pin).
  std::optional<uint64_t> glitch_step_at;
};

struct BenchOptions {
  std::string mode;  // "direct" or "systemc": reported only
  uint64_t seed = 0;
  FaultPlan faults;
  std::string trace_path;     // empty: no trace
  uint64_t trace_window = 0;  // 0: whole run
  // Progress line on stderr every this many clock edges (0: none).
  uint64_t progress_every = 0;
  // Input frames for replay in other simulators (tb/dda_line_frames.h); empty: none.
  std::string frames_path;
  // The lattice path as CSV (case,cycle,kind,axis values...): kind `start`
  // (case start), `target` (end point of a command taken), `move` (position
  // after the core stepped); scripts/plot_dda_paths.py draws it. Empty: none.
  std::string path_csv;
};

class DdaLineBench {
 public:
  DdaLineBench(DdaLineLimits limits, std::vector<DdaLineCase> cases, BenchOptions options);
  ~DdaLineBench();

  const DdaLineFrame& next_frame();
  void observe(const DdaLinePins& hls, const DdaLinePins& rtl);
  bool finished() const { return finished_; }

  // Results of the cases that ran (a mismatch stops the run).
  const std::vector<CaseResult>& results() const { return results_; }
  uint64_t cycles() const { return cycle_; }
  // Closes the trace (FST conversion) and the frame file; throws
  // std::runtime_error on failure.
  void close_trace();

 private:
  enum class Phase { kReset, kRun, kTail };
  void start_case();
  void end_case();
  void drive_items();
  void print_progress() const;
  DdaLinePins compared_hls(const DdaLinePins& hls) const;
  bool compare(const DdaLinePins& hls, const DdaLinePins& rtl);

  DdaLineLimits limits_;
  std::vector<DdaLineCase> cases_;
  BenchOptions options_;
  std::vector<CaseResult> results_;
  std::unique_ptr<DdaLineTrace> trace_;
  std::unique_ptr<DdaLineFrameWriter> frames_;
  std::unique_ptr<std::ofstream> path_csv_;
  models::LatticePoint path_target_;  // where the commands taken so far lead
  uint32_t prev_step_ = 0;            // step_o seen after the previous edge
  void path_row(const char* kind, const models::LatticePoint& p);

  uint64_t cycle_ = 0;  // clock edges so far in the run
  bool finished_ = false;

  // Current case.
  size_t case_index_ = 0;
  Phase phase_ = Phase::kReset;
  uint64_t phase_left_ = 0;  // reset / tail edges still to drive
  uint64_t case_start_cycle_ = 0;
  uint64_t budget_ = 0;
  size_t item_ = 0;
  uint64_t gap_left_ = 0;
  DdaLineSettings settings_;
  DdaLineFrame frame_;
  DdaLinePins last_rtl_;  // outputs after the last edge: what the driver reacts to
  std::vector<StepdirMonitor> monitors_;
  std::unique_ptr<DdaLineScoreboard> scoreboard_;
  double case_clock_start_ = 0;
};

}  // namespace hwinterp::tb

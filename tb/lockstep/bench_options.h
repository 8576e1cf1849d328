// How a lockstep run is set up, for every core: the test hooks that prove
// the checks can fail, traces, frame dumps, path export, progress, abort.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "models/lattice_path.h"

namespace hwinterp::tb {

class ProfileFeed;  // tb/lockstep/profile_feed.h

// Test hooks that prove the checks can fail. Cycles count clock edges from
// the start of the run (1-based).
struct FaultPlan {
  // Invert step_o[0] of the HLS outputs before the lockstep comparison.
  std::optional<uint64_t> flip_hls_step_at;
  // Invert step_o[0] of the RTL outputs after the comparison, as the
  // monitors and the scoreboard see them (a glitch on the pin).
  std::optional<uint64_t> glitch_step_at;
};

// What a run reports move by move to whoever watches it.
class MoveObserver {
 public:
  virtual ~MoveObserver() = default;
  // The axes stepped to `at` in a move of command `command` (0-based, in the
  // case's order of commands taken).
  virtual void move(const models::LatticePoint& at, uint64_t command) = 0;
  // Command `command` completed (done_o) with the axes at `at`.
  virtual void done(uint64_t command, const models::LatticePoint& at) = 0;
  // The step pulses that rose on clock edge `clock` of the run (bit i: axis
  // i; dir bit i set: the pulse moved axis i by -1), on the clocks of move().
  virtual void pulses(uint64_t clock, uint32_t rising, uint32_t dir) {
    (void)clock, (void)rising, (void)dir;
  }
};

struct BenchOptions {
  std::string mode;  // "direct" or "systemc": reported only
  uint64_t seed = 0;
  FaultPlan faults;
  std::string trace_path;     // VCD or .fst; empty: no trace
  uint64_t trace_window = 0;  // 0: whole run
  // Progress line on stderr every this many clock edges (0: none).
  uint64_t progress_every = 0;
  // The run's estimated clocks, for the progress line's percent and time
  // left (0: no estimate).
  double expected_clocks = 0;
  // Input frames for replay in other simulators (tb/report/frames.h); empty: none.
  std::string frames_path;
  // Their replay testbench; empty: frames_path + ".sv".
  std::string frames_testbench_path;
  // The lattice path as CSV (case,cycle,kind,axis values...): kind `start`
  // (case start), `target` (end point of a command taken), `move` (position
  // after the core stepped); scripts/plot_paths.py draws it. Empty: none.
  std::string path_csv;
  // Every step pulse on the wire as CSV (clock,axis,dir: tb/report/step_times.h);
  // empty: none.
  std::string step_times_path;
  // Keep every visited lattice point in CaseResult::visited and the cycle of
  // every done_o pulse in CaseResult::done_cycles.
  bool record_path = false;
  // Raise abort_i (with cmd_valid_i low) on this clock edge of the run.
  std::optional<uint64_t> abort_at;
  // Told of every move and every completed command (hwinterp gcode's contour
  // and end points); null: none. Called per move, not per clock.
  MoveObserver* observer = nullptr;
  // Drives feed_i every clock with a feed profile's word (both of its faces
  // in lockstep; tb/lockstep/profile_feed.h) instead of the case's constant
  // feed; null: none. (motion_top moves with feed word 0 follow it.)
  ProfileFeed* profile_feed = nullptr;
};

}  // namespace hwinterp::tb

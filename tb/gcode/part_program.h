// A part program through motion_top in lockstep: `hwinterp gcode`'s run.
// The program (an RS274/NGC subset, tb/gcode/ngc_reader.h, or LinuxCNC's
// `rs274 -g` canonical commands, tb/gcode/canon_reader.h) is compiled move by
// move into motion_top commands (tb/gcode/motion_compiler.h: lattice points
// rounded from absolute coordinates, arcs on the arc engine, feed words) and
// streamed into the lockstep bench: the HLS core against the RTL on every
// clock, both against the reference model (every move, every end point,
// every visited point within its bound), the step/dir timing on every axis.
// On top, every visited lattice point is measured against the programmed
// path of its move (tb/gcode/contour.h): the contour error; and every move
// must end on its rounded programmed end. Memory does not grow with the
// program: moves, commands and checks stream.
//
// This part needs the lockstep harness, so it is built into the testbench
// library, not into the plain hwinterp_gcode library (readers, machine file,
// compiler: no SystemC, no Verilator) that the fuzzers use.
#pragma once

#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "tb/base/case_result.h"
#include "tb/base/json.h"
#include "tb/base/variant_spec.h"
#include "tb/gcode/machine.h"
#include "tb/gcode/motion_compiler.h"
#include "tb/gcode/program_file.h"
#include "tb/lockstep/bench_options.h"
#include "tb/lockstep/profile_feed.h"
#include "tb/monitor/step_output_monitor.h"

namespace hwinterp::gcode {

// What to run.
struct PartProgramSetup {
  std::string program;  // the file
  bool canon = false;   // LinuxCNC canonical commands, not RS274/NGC
  Machine machine;
  std::string variant;  // a motion_top variant; empty: the first with the machine's axes
  FeedMode feed_mode = FeedMode::kFull;
  std::string mode = "systemc";        // lockstep mode: systemc or direct
  tb::BenchOptions bench;              // traces, progress (mode and observer are set by the run)
  std::ostream* moves_csv = nullptr;   // one row per motion move; null: none
  std::ostream* points_csv = nullptr;  // one row per visited point (the plot's); null: none
  std::ostream* kinematics_csv = nullptr;  // one row per estimator window; null: none
  double kinematics_window_s = 0.01;  // the kinematics estimator's window (tb/monitor/kinematics.h)
  size_t profile_window = 16;  // commands the profile planner looks ahead (machine.profile on)
  // Feed hold (machine.profile on): the profile's hold input high from
  // hold_at_s for hold_for_s seconds of the run; hold_at_s < 0: none.
  double hold_at_s = -1, hold_for_s = 0;
  // The ceiling on a run's clocks (gcode --max-clocks): a profiled program
  // whose time-optimal time at the profile's limits is beyond it is refused
  // before it runs.
  double max_clocks = 1e11;
  // The feed override (--feed-override AT:PCT,...), the profile's ovr_i:
  // percent from AT seconds of the run on; empty: 100 % throughout.
  std::vector<tb::OverridePoint> feed_override;
  // The bus writes that stream the program's commands into motion_soc
  // (tb/gcode/soc_writes.h); empty: none.
  std::string soc_writes_path;
  // After the lockstep run, the same program through motion_soc's register
  // interface (tb/bus/): "axi4lite" or "wishbone"; empty: not.
  std::string bus;
  uint32_t bus_waits = 0;  // the bus master's random wait states, 0..N clocks each
  // The bus run's STEP_TYPE: one type for every axis, or one per axis of the
  // variant (the machine's axes first); empty: step/dir.
  std::vector<tb::StepType> step_types;
};

// The feed profile of a run (machine.profile not off): its registers, the
// limits it keeps along the path, and the moves it took.
struct ProfileReport {
  bool on = false;
  std::string kind;
  uint64_t q = 0;
  unsigned len = 1;
  double level_speed = 0, accel = 0, jerk = 0;  // operations (steps)/s, /s^2, /s^3
  uint32_t max_level = 0;
  size_t window = 0;
  uint64_t moves = 0;  // the profile's moves taken (one per command)
  // The feed hold's stop (--feed-hold): the path speed when it began, and
  // the distance and time to rest (tb/lockstep/profile_feed.h).
  struct Hold {
    double at_s = 0, for_s = 0;
    bool stopped = false;
    double speed_ops_per_s = 0, stop_ops = 0, stop_s = 0;
  };
  bool held = false;  // a hold was asked for: `hold` is set
  Hold hold;
  std::vector<tb::OverridePoint> feed_override;  // --feed-override's steps (empty: 100 %)
};
// The JSON report's `profile.hold`: the fields once.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ProfileReport::Hold, at_s, for_s, stopped, speed_ops_per_s,
                                   stop_ops, stop_s)

// One quantity's highest magnitude seen on the wire, beside its limit, in
// units (mm or deg) per s^k.
struct KinematicPeak {
  double max = 0;        // the estimator's highest value
  double at_s = 0;       // the end of the window it was seen in, s from the run's start
  double tolerance = 0;  // the estimator's tolerance (tb/monitor/kinematics.h), same units
  double limit = std::numeric_limits<double>::infinity();  // the machine's; infinity: none
};
struct KinematicRow {
  std::string name;          // "path" or the axis letter
  std::string unit;          // "mm" or "deg"
  int axis = -1;             // X..C as 0..5; -1: the path
  double unit_per_step = 1;  // an axis's mm (deg) per step; the path: 1 (in mm already)
  KinematicPeak speed, accel, jerk;
};
// What the step stream asked of the machine: the path (X Y Z) and each axis.
struct Kinematics {
  double window_s = 0;
  uint64_t windows = 0;
  std::vector<KinematicRow> rows;  // the path first, then the axes in order
};

// The worst contour error, and where.
struct ContourMax {
  double mm = 0, steps = 0;
  uint64_t move = 0, line = 0;
};

// The bus run (PartProgramSetup::bus) against the lockstep run.
struct BusCompare {
  bool ran = false;
  std::string bus;      // axi4lite or wishbone
  std::string build;    // the Verilated top and its widths
  uint64_t clocks = 0;  // clock edges after reset
  uint64_t writes = 0, reads = 0, errors = 0;
  uint64_t pushes = 0, level_reads = 0, credit_waits = 0;
  uint64_t irq_wait_clocks = 0;                    // the host asleep on the low-water interrupt
  uint32_t events = 0;                             // EVENTS at the end
  uint64_t points = 0, lockstep_points = 0;        // visited lattice points
  uint64_t completed = 0, lockstep_completed = 0;  // commands completed (done_o)
  int64_t first_point_mismatch = -1;               // the first point that differs; -1: none
  int64_t first_end_mismatch = -1;  // the first command that ended elsewhere; -1: none
  std::string step_types;           // STEP_TYPE per axis, e.g. "quad,updown,stepdir"
  // The step outputs of those types against the timing set (every clock):
  // the first few violations and their count.
  std::vector<tb::TimingViolation> timing_violations;
  uint64_t timing_violation_count = 0;
  std::vector<int64_t> end, lockstep_end;  // the axes at the end
  std::vector<uint64_t> end_mismatches;    // moves off their rounded programmed end (bus run)
  ContourMax contour;                      // the bus run's own
  bool timed_out = false;
  // The HLS face (hls/motion_soc.h) against the Verilated top, every clock
  // (tb/bus/hls_shadow.h): the first difference; clock 0: none.
  uint64_t hls_mismatch_clock = 0;
  std::string hls_mismatch_what;
  uint64_t hls_mismatch_hls = 0, hls_mismatch_rtl = 0;
  // With the feed profile (a PROFILE=1 top): the bus run's step stream
  // against the machine's limits, as the lockstep run's.
  bool profiled = false;
  std::vector<std::string> limit_failures;
  bool passed = false;
};

// What the run gave.
struct PartProgramRun {
  tb::VariantSpec variant;
  std::vector<tb::CaseResult> results;  // the one case
  CompileTotals totals;
  ReaderStats reader;
  ContourMax contour;
  uint64_t visited_points = 0;
  std::vector<uint64_t> end_mismatches;  // moves that ended off their rounded programmed end
  double estimated_clocks = 0;  // the clocks estimated before the run (the progress line's)
  Kinematics kinematics;
  bool all_rows_written = false;  // every move reached the moves CSV
  ProfileReport profile;
  // With a profile: the profile's faces disagreed, or the step stream broke a
  // machine limit beyond the estimator's tolerance (each names which).
  std::vector<std::string> profile_failures;
  BusCompare bus;  // when PartProgramSetup::bus is set
  // lockstep, model, timing, end points, the profile (and the bus run): everything held
  bool passed = false;
};

// The variant it will run on (named, or the first with the machine's axes);
// throws cli::UsageError listing the variants.
tb::VariantSpec part_program_variant(const PartProgramSetup& setup);

// Compiles the program (and with a profile plans its moves) into
// setup.soc_writes_path (tb/gcode/soc_writes.h) and runs nothing: `hwinterp
// gcode --soc-writes FILE --plan-only`. Bad input throws cli::UsageError as
// run_part_program does.
void plan_soc_writes(const PartProgramSetup& setup);

// Compiles and runs the program; bad input (the program, the variant, a
// path that leaves the machine's travel or the core's position counters:
// tb/gcode/limits.h) throws cli::UsageError before anything is simulated.
PartProgramRun run_part_program(const PartProgramSetup& setup);

// The run's summary table (moves, commands, steps, times, contour error) and
// its report keys (the `hwinterp gcode --json` contract, without the
// command's own keys).
std::string summary_table(const PartProgramSetup& setup, const PartProgramRun& run);
Json report_json(const PartProgramSetup& setup, const PartProgramRun& run);
// What scripts/plot_kinematics.py needs beside the series: clock_hz, the
// window, and per axis its units per step, unit name and limits.
Json kinematics_units_json(const PartProgramSetup& setup, const PartProgramRun& run);

}  // namespace hwinterp::gcode

// What one co-simulated case produced: the lockstep comparison, the timing
// monitors, the scoreboard and any aborts, in the shape of the `hwinterp
// cosim --json` contract (docs/verification.md). Shared by every core's testbench.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/lattice_path.h"
#include "tb/base/json.h"

namespace hwinterp::tb {

// The first cycle on which the HLS core and the RTL disagreed.
struct Mismatch {
  uint64_t cycle;
  std::string signal;  // e.g. "pos_o[1]"
  uint64_t hls;
  uint64_t rtl;
  // The inputs both took at that edge, by port name (signed payload fields
  // as numbers; a port of several elements as a list).
  Json inputs = Json::object();
};

Json to_json(const Mismatch& m);

// A step/dir timing rule broken on one axis.
struct TimingViolation {
  uint64_t cycle;
  int axis;
  std::string rule;   // step_len, step_space, dir_setup, dir_hold
  uint64_t measured;  // cycles
  uint64_t required;
};

// One abort_i pulse and what followed it.
struct AbortRecord {
  uint64_t cycle = 0;             // case cycle of the abort edge
  models::LatticePoint position;  // where the axes are (the pulses on the wire)
  // Clocks from the abort edge until busy_o fell; -1 (JSON null): not
  // measured, a new command was taken first.
  int64_t idle_after_clocks = -1;
  uint64_t idle_bound = 0;         // the core's promise: max(L, 1) - 1, L the pulse's step_len
  bool on_reference_path = false;  // position is a point of the model's path
};

Json to_json(const AbortRecord& a);

// A figure a core's reference model checks beyond the path error, at points
// the model chooses (e.g. log_stepper's coarse points against the
// double-precision model): how many were checked, the largest value seen and
// its limit. JSON: `<count_name>` and `max_<name>` in the case object, and the
// whole record in `core_checks`.
struct CoreCheck {
  std::string name;        // e.g. "point_error_steps"
  std::string count_name;  // e.g. "points"
  double limit = -1;       // checked as value <= limit; < 0: reported only
  uint64_t count = 0;
  double max = 0;
  Json to_json() const;
};

struct CaseResult {
  std::string core, variant, name, mode;
  uint64_t ordinal = 0;  // the case's position in its run's full list (Case::ordinal)
  uint64_t seed = 0;
  uint64_t cycles = 0;    // clock edges simulated in this case, reset included
  uint64_t commands = 0;  // commands taken by the core
  uint64_t commands_offered = 0;
  uint64_t offer_wait_cycles = 0;  // clocks a command was offered and not taken (backpressure)
  uint64_t first_step_cycle = 0;   // case cycle of the first step_o rise (0: none)
  std::vector<uint64_t> steps;     // per axis, counted at step_o rising edges
  models::LatticePoint start, end_position, expected_end_position;
  double max_path_error_steps = 0;
  double error_bound = 0;  // the documented bound the error is checked against
  bool error_bound_strict = true;
  uint64_t mismatches = 0;  // 0 or 1: the first mismatch ends the run
  std::optional<Mismatch> first_mismatch;
  uint64_t timing_violation_count = 0;
  std::vector<TimingViolation> timing_violations;  // the first few, for the report
  uint64_t scoreboard_error_count = 0;
  std::vector<std::string> scoreboard_errors;  // the first few
  std::vector<AbortRecord> aborts;
  std::vector<CoreCheck> core_checks;  // the core's own figures (Reference::check)
  std::vector<models::LatticePoint>
      checkpoints;                            // where they were checked (BenchOptions::record_path)
  std::vector<models::LatticePoint> visited;  // start and every move (BenchOptions::record_path)
  std::vector<uint64_t> done_cycles;  // case cycle of each done_o (BenchOptions::record_path)
  bool timed_out = false;
  bool completed = false;  // ran to its end (not cut short by a mismatch elsewhere)
  double seconds = 0;      // from the case's first clock edge to its last

  bool passed() const {
    return completed && mismatches == 0 && timing_violation_count == 0 &&
           scoreboard_error_count == 0 && !timed_out;
  }
  Json to_json() const;
  // The check `name`, added (with its count name and limit) on first use.
  // (Inline: the adapters use it, and the fuzzers link them without the reports.)
  CoreCheck& core_check(const std::string& check, const std::string& count_name, double limit) {
    for (auto& c : core_checks)
      if (c.name == check) return c;
    core_checks.push_back({check, count_name, limit});
    return core_checks.back();
  }
};

// Keeps the first few of a list of findings and counts all of them.
template <typename T>
void record_capped(std::vector<T>& kept, uint64_t& count, T item, size_t cap = 16) {
  ++count;
  if (kept.size() < cap) kept.push_back(std::move(item));
}

}  // namespace hwinterp::tb

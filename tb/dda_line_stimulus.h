// Stimulus for the dda_line testbench: cases made of commands, run-time
// setting changes, idle gaps and drains; from a --line, a job file, the
// eight test lines of 004_dc68f1177cad466f.txt, or a seeded random stream.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "models/lattice_path.h"
#include "stepdir_monitor.h"

namespace hwinterp::tb {

// The widths of one dda_line variant (from its generated configuration) and
// its timing defaults: what stimulus is validated against.
struct DdaLineLimits {
  std::string variant;
  int axes, acc_w, pos_w, tim_w, feed_w;
  StepdirTiming default_timing;

  int64_t max_delta() const { return (int64_t{1} << (acc_w - 1)) - 1; }
  int64_t min_delta() const { return -(int64_t{1} << (acc_w - 1)); }
  uint64_t full_feed() const { return uint64_t{1} << feed_w; }
};

// Run-time inputs besides the command stream.
struct DdaLineSettings {
  uint64_t feed = 0;  // feed word: iterations per clock = feed / 2^FEED_W; >= 2^FEED_W is full
  bool half_preload = false;
  StepdirTiming timing;
};

struct DdaLineItem {
  enum class Kind { kCommand, kSettings, kGap, kDrain };
  Kind kind = Kind::kCommand;
  std::vector<int64_t> delta;  // kCommand: signed steps per axis
  DdaLineSettings settings;    // kSettings: applied from the next clock edge on
  uint64_t cycles = 0;         // kGap: clocks with cmd_valid_i low
  int source_line = 0;         // job-file line, for messages
};

struct DdaLineCase {
  std::string name;
  models::LatticePoint start;  // absolute position the core's counters start from
  DdaLineSettings settings;    // in force from reset
  std::vector<DdaLineItem> items;
};

// Full feed, plain preload, the variant's default timing.
DdaLineSettings default_settings(const DdaLineLimits& limits);

// One case: a line from `start` to `end` (given for some leading axes; the
// rest are 0).
DdaLineCase line_case(const DdaLineLimits& limits, const std::string& name,
                      const std::vector<int64_t>& start, const std::vector<int64_t>& end,
                      const DdaLineSettings& settings);

// The eight test lines of 004_dc68f1177cad466f.txt, one case each (axes past
// the second stay at 0).
std::vector<DdaLineCase> paper_lines_004(const DdaLineLimits& limits,
                                         const DdaLineSettings& settings);

// A seeded random stream of `commands` commands in one case: all octants,
// zero deltas, single-axis moves, reversals, back-to-back commands and idle
// gaps, random timing settings, feed words and preloads changed while the
// core runs. The same seed gives the same case everywhere.
DdaLineCase random_case(const DdaLineLimits& limits, uint64_t commands, uint64_t seed);

// Parses a job file (format in docs of parse_job in the .cpp and README).
// Throws cli::UsageError naming file:line and the bad value.
std::vector<DdaLineCase> parse_job(const std::string& path, const DdaLineLimits& limits,
                                   const DdaLineSettings& defaults);

// Checks a case against the variant's widths: deltas fit ACC_W (signed),
// every position reached fits POS_W (signed), settings fit TIM_W / FEED_W,
// feed is not 0 (the run would never end). Throws cli::UsageError naming the
// case and the value; nothing is simulated that would overflow.
void validate_case(const DdaLineCase& c, const DdaLineLimits& limits);

// Upper bound on the clock edges the case needs on a correct core, with
// margin; running past it means the core hung.
uint64_t cycle_budget(const DdaLineCase& c, const DdaLineLimits& limits);

// Commands in a case.
uint64_t command_count(const DdaLineCase& c);

}  // namespace hwinterp::tb

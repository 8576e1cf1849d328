// Scoreboard of the dda_line testbench: integrates the step/dir outputs into
// lattice moves and checks them, move by move, against the reference model
// (models/dda_line_model.h); checks pos_o against the integrated position,
// one done_o pulse per command after its last step, the exact end point, and
// the path error of every visited point against the documented bound.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "cosim_result.h"
#include "dda_line_pins.h"
#include "models/dda_line_model.h"

namespace hwinterp::tb {

class DdaLineScoreboard {
 public:
  // `case_start_cycle`: run cycle before the case's first edge (cycles in
  // reports are counted from the case start).
  DdaLineScoreboard(int axes, int pos_w, models::LatticePoint start, uint64_t case_start_cycle);

  // A command the core took, in order, with the preload it was taken with.
  void command_taken(const std::vector<int64_t>& delta, models::Preload preload);

  // Outputs after one clock edge (not during reset).
  void observe(uint64_t cycle, const DdaLinePins& pins, CaseResult& result);

  // End of the case: everything taken must have completed and arrived.
  void finish(CaseResult& result);

  // Where the step/dir outputs have taken the axes so far, and where the
  // commands taken so far lead (for a report cut short by a mismatch).
  const models::LatticePoint& position() const { return at_; }
  const models::LatticePoint& expected_end() const { return expected_end_; }

 private:
  struct Command {
    std::vector<int64_t> delta;
    models::Preload preload;
    models::LatticePoint start, end;
  };
  void error(CaseResult& r, const std::string& what);
  bool next_expected_move(models::DdaMove& m);  // across commands, in order
  bool has_moves_left(size_t command) const;
  void check_path_error(uint64_t cycle, CaseResult& r);

  int axes_;
  int pos_w_;
  uint64_t case_start_cycle_;
  models::LatticePoint start_, at_, expected_end_;
  std::vector<Command> taken_;
  size_t current_ = 0;                           // command whose moves are being consumed
  std::optional<models::DdaMoveStream> stream_;  // moves of taken_[current_]
  uint64_t done_count_ = 0;
  uint32_t prev_step_ = 0;
  bool diverged_ = false;      // after a wrong move the rest of the sequence is not compared
  bool pos_reported_ = false;  // one pos_o report per case, not one per cycle
};

}  // namespace hwinterp::tb

// The simulated boards the build holds: one per hwinterp_board of
// cmake/cores.cmake (rtl/CMakeLists.txt Verilates each board's gateware,
// boards/hwinterp_litex/sim.py, and lists them in hwinterp_boards.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tb/base/json.h"
#include "tb/board/board_sim.h"

namespace hwinterp::board {

// One simulated build of a board: the board's gateware at a clock (its own,
// or another: hwinterp_board_sim in cmake/cores.cmake).
struct BoardInfo {
  std::string name;  // the board
  bool ethernet;     // Etherbone over UDP; else a UART
  uint64_t sys_hz, baud;  // this build's clock and UART rate
  uint64_t board_hz;      // the board's own clock
  int axes;
  // Runs the board until stopped; `serving` is called with its URI first.
  std::function<Json(const BoardSimOptions&, const std::function<void(const std::string&)>&)> run;
};

const std::vector<BoardInfo>& boards();
// The build of board `name` at `hz` (0: the board's own clock); nullptr if
// the build holds none.
const BoardInfo* find_board(const std::string& name, uint64_t hz = 0);

}  // namespace hwinterp::board

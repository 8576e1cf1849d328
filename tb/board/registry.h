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

struct BoardInfo {
  std::string name;
  bool ethernet;  // Etherbone over UDP; else a UART
  uint64_t sys_hz, baud;
  int axes;
  // Runs the board until stopped; `serving` is called with its URI first.
  std::function<Json(const BoardSimOptions&, const std::function<void(const std::string&)>&)> run;
};

const std::vector<BoardInfo>& boards();
// nullptr for an unknown name.
const BoardInfo* find_board(const std::string& name);

}  // namespace hwinterp::board

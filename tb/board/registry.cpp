#include "tb/board/registry.h"

#include "hwinterp_boards.h"

namespace hwinterp::board {

namespace {

template <class Cfg>
BoardInfo info() {
  return BoardInfo{
      Cfg::kBoard,
      Cfg::kEthernet,
      Cfg::kSysHz,
      Cfg::kBaud,
      Cfg::kBoardHz,
      Cfg::kAxes,
      [](const BoardSimOptions& o, const std::function<void(const std::string&)>& serving) {
        BoardSim<Cfg> sim(o);
        serving(sim.uri());
        return sim.run();
      }};
}

}  // namespace

const std::vector<BoardInfo>& boards() {
#define HWINTERP_BOARD_INFO(board) info<board##_board_cfg>(),
  static const std::vector<BoardInfo> all{HWINTERP_BOARD_SIMS(HWINTERP_BOARD_INFO)};
#undef HWINTERP_BOARD_INFO
  return all;
}

const BoardInfo* find_board(const std::string& name, uint64_t hz) {
  for (const BoardInfo& b : boards())
    if (b.name == name && b.sys_hz == (hz ? hz : b.board_hz)) return &b;
  return nullptr;
}

}  // namespace hwinterp::board

#include "tb/gcode/soc_writes.h"

#include <cctype>
#include <stdexcept>

#include "tb/base/json.h"
#include "tb/bus/soc_host.h"

namespace hwinterp::gcode {
namespace {

// The register at byte address `addr`, named as the description names it.
std::string register_name(uint32_t addr) {
  for (const auto& r : tb::bus::regs::kRegs)
    if (r.addr == addr && r.count == 1) {
      std::string n = r.name;
      for (char& ch : n) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      return n;
    }
  throw std::logic_error("soc writes: no register at address " + std::to_string(addr));
}

}  // namespace

void write_soc_writes(MoveSource& source, const Machine& machine, const MotionWidths& widths,
                      FeedMode mode, const std::string& program, const std::string& variant,
                      const std::string& path) {
  MotionCompiler compiler(source, machine, widths, mode, program);
  tb::bus::CommandStager stager(widths.axes);
  Json commands = Json::array();
  models::MotionCommand c;
  while (compiler.next(c)) {
    Json writes = Json::array();
    stager.stage(c, [&](uint32_t addr, uint32_t v) { writes.push_back({register_name(addr), v}); });
    commands.push_back(std::move(writes));
  }
  Json end = Json::array();
  for (int i = 0; i < widths.axes; ++i) end.push_back(compiler.position()[static_cast<size_t>(i)]);
  Json j;
  j["program"] = program;
  j["variant"] = variant;
  j["axes"] = widths.axes;
  j["feed_w"] = widths.feed_w;
  j["fifo_level_room_lsb"] = tb::bus::kRoomLsb;
  j["commands"] = std::move(commands);
  j["end"] = std::move(end);
  write_json_file(path, j);
}

}  // namespace hwinterp::gcode

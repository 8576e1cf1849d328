#include "tb/gcode/soc_writes.h"

#include <cctype>
#include <deque>
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

void write_soc_writes(MoveSource& source, const Machine& machine, const SocWritesSetup& setup,
                      const std::string& path) {
  const MotionWidths& widths = setup.widths;
  std::deque<MoveReport> reports;
  MotionCompiler compiler(source, machine, widths, setup.mode, setup.program,
                          [&](const MoveReport& r) { reports.push_back(r); });
  tb::bus::CommandStager stager(widths.axes);
  Json commands = Json::array();
  Json moves = Json::array();
  uint64_t first = 0;  // the next move's first command
  const auto flush_moves = [&] {
    for (; !reports.empty(); reports.pop_front()) {
      const MoveReport& r = reports.front();
      Json m;
      m["move"] = r.index;
      m["line"] = r.line;
      m["kind"] = to_string(r.kind);
      m["end_mm"] = r.end;
      Json steps = Json::array();
      for (int i = 0; i < widths.axes; ++i) steps.push_back(r.end_steps[static_cast<size_t>(i)]);
      m["end_steps"] = std::move(steps);
      m["first_command"] = first;
      m["commands"] = r.commands;
      m["chords"] = r.chords;
      m["programmed_s"] = r.programmed_s;
      m["feed_words_s"] = r.programmed_words_s;
      moves.push_back(std::move(m));
      first += r.commands;
    }
  };
  models::MotionCommand c;
  while (compiler.next(c)) {
    Json writes = Json::array();
    const auto put = [&](uint32_t addr, uint32_t v) { writes.push_back({register_name(addr), v}); };
    if (setup.profiled) {
      // The move follows the profile's feed word (CMD_FEED 0) and carries its
      // planned words, as the bus run's host stages them.
      c.feed = 0;
      tb::ProfileWords w;
      if (!setup.next_move(w))
        throw std::logic_error("soc writes: the profile planner has no move for command " +
                               std::to_string(commands.size()));
      stager.stage(c, &w, put);
    } else {
      stager.stage(c, put);
    }
    commands.push_back(std::move(writes));
  }
  flush_moves();
  if (first != commands.size())
    throw std::logic_error("soc writes: the moves hold " + std::to_string(first) +
                           " commands, the program " + std::to_string(commands.size()));

  Json end = Json::array();
  for (int i = 0; i < widths.axes; ++i) end.push_back(compiler.position()[static_cast<size_t>(i)]);
  const CompileTotals& t = compiler.totals();
  const ReaderStats& rs = source.stats();
  Json j;
  j["program"] = setup.program;
  j["canon"] = setup.canon;
  j["variant"] = setup.variant;
  j["feed_mode"] = setup.mode == FeedMode::kFull ? "full" : "programmed";
  j["axes"] = widths.axes;
  j["feed_w"] = widths.feed_w;
  j["widths"] = {{"axes", widths.axes},    {"acc_w", widths.acc_w}, {"coord_w", widths.coord_w},
                 {"ops_w", widths.ops_w},  {"pos_w", setup.pos_w},  {"tim_w", setup.tim_w},
                 {"feed_w", widths.feed_w}};
  j["clock_hz"] = machine.clock_hz;
  const StepTiming& st = machine.timing;
  j["timing"] = {{"step_len", st.step_len},
                 {"step_space", st.step_space},
                 {"dir_setup", st.dir_setup},
                 {"dir_hold", st.dir_hold}};
  j["fifo_level_room_lsb"] = tb::bus::kRoomLsb;
  Json prof;
  prof["kind"] = setup.profiled ? profile_name(machine.profile) : "off";
  if (setup.profiled) {
    const models::ProfileRegisters& g = setup.prof_regs;
    const models::ProfileBuild& b = setup.prof_build;
    prof["q"] = g.q;
    prof["len"] = g.len;
    prof["spd_w"] = b.spd_w;
    prof["tick_w"] = b.tick_w;
    prof["len_w"] = b.len_w;
    prof["lvl_w"] = b.lvl_w;
    prof["level_speed"] = g.level_speed;
    prof["max_level"] = g.max_level;
    prof["accel"] = setup.prof_accel;
    prof["jerk"] = setup.prof_jerk;
    prof["window"] = setup.prof_window;
  }
  j["profile"] = std::move(prof);
  j["commands"] = std::move(commands);
  j["moves"] = std::move(moves);
  j["totals"] = {{"moves", t.moves},
                 {"traverses", rs.traverses},
                 {"feeds", rs.feeds},
                 {"arcs", rs.arcs},
                 {"commands", t.commands},
                 {"line_commands", t.line_commands},
                 {"arc_commands", t.arc_commands},
                 {"chord_arcs", t.chord_arcs},
                 {"chords", t.chords},
                 {"split_arcs", t.split_arcs},
                 {"programmed_time_s", t.programmed_s},
                 {"feed_word_time_s", t.programmed_words_s}};
  j["end"] = std::move(end);
  write_json_file(path, j);
}

}  // namespace hwinterp::gcode

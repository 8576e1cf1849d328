// `hwinterp gcode --soc-writes FILE` (tb/gcode/soc_writes.h), the file the
// host package streams to a board: each command's staging writes (only the
// registers that change) and CMD_PUSH; each move's commands, programmed end
// and lattice end, which is the sum of its commands' displacements and the
// point the lockstep run reaches; the widths, clock and step timing; with
// the profile its registers and each command's CMD_MV_* words, CMD_FEED 0.
// --plan-only writes the same file without the lockstep run.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "run_hwinterp.h"

namespace hwinterp::testing {
namespace {

using nlohmann::json;

const std::string kData = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";

int64_t s32(uint64_t v) { return static_cast<int32_t>(static_cast<uint32_t>(v)); }

// Every command's full staging values, replayed from the reset values (0).
std::vector<std::map<std::string, uint64_t>> replay(const json& commands) {
  std::vector<std::map<std::string, uint64_t>> out;
  std::map<std::string, uint64_t> staged;
  for (const json& c : commands) {
    EXPECT_FALSE(c.empty());
    EXPECT_EQ(c.back()[0].get<std::string>(), "CMD_PUSH");
    for (size_t i = 0; i + 1 < c.size(); ++i) {
      const std::string reg = c[i][0].get<std::string>();
      const uint64_t v = c[i][1].get<uint64_t>();
      EXPECT_NE(staged[reg], v) << "a write that changes nothing: " << reg;
      staged[reg] = v;
    }
    out.push_back(staged);
  }
  return out;
}

// A command's lattice displacement: a line's deltas; an arc's end on its
// plane's axes (XY: X Y; ZX: Z X; YZ: Y Z), the deltas elsewhere.
std::vector<int64_t> displacement(std::map<std::string, uint64_t>& c, int axes) {
  std::vector<int64_t> d;
  for (int i = 0; i < axes; ++i) d.push_back(s32(c["CMD_DELTA" + std::to_string(i)]));
  const uint64_t flags = c["CMD_FLAGS"];
  if (flags & 1) {
    static const int kPlane[3][2] = {{0, 1}, {2, 0}, {1, 2}};
    const int p = static_cast<int>((flags >> 1) & 3);
    d[static_cast<size_t>(kPlane[p][0])] = s32(c["CMD_END0"]);
    d[static_cast<size_t>(kPlane[p][1])] = s32(c["CMD_END1"]);
  }
  return d;
}

TEST(SocWrites, MovesEndWhereTheirCommandsAndTheLockstepRunLead) {
  const std::string dir = scratch_dir("soc_writes_arcs");
  const CliResult run =
      run_hwinterp("gcode " + kData + "arcs.ngc --mode direct --progress 0 --soc-writes " + dir +
                   "/run.json --moves-csv " + dir + "/moves.csv --json " + dir + "/report.json");
  ASSERT_EQ(run.code, 0) << run.out << run.err;
  const CliResult plan =
      run_hwinterp("gcode " + kData + "arcs.ngc --soc-writes " + dir + "/plan.json --plan-only");
  ASSERT_EQ(plan.code, 0) << plan.out << plan.err;
  EXPECT_EQ(slurp(dir + "/plan.json"), slurp(dir + "/run.json"));  // no run needed for the file

  const json f = json::parse(slurp(dir + "/plan.json"));
  const json report = json::parse(slurp(dir + "/report.json"));
  const int axes = f.at("axes").get<int>();
  EXPECT_EQ(f.at("widths").at("axes").get<int>(), axes);
  // motion_top_n4 (the default machine's 4 axes): cmake/cores.cmake's widths
  EXPECT_EQ(f.at("variant").get<std::string>(), report.at("variant").get<std::string>());
  EXPECT_EQ(f.at("widths"), json({{"axes", 4},
                                  {"acc_w", 32},
                                  {"coord_w", 24},
                                  {"ops_w", 28},
                                  {"pos_w", 32},
                                  {"tim_w", 16},
                                  {"feed_w", 24}}));
  EXPECT_EQ(f.at("clock_hz"), report.at("clock_hz"));
  EXPECT_EQ(f.at("timing").at("step_len").get<int>(), 2);
  EXPECT_EQ(f.at("profile").at("kind").get<std::string>(), "off");
  for (const char* k :
       {"moves", "traverses", "feeds", "arcs", "commands", "line_commands", "arc_commands",
        "chord_arcs", "chords", "split_arcs", "programmed_time_s", "feed_word_time_s"})
    EXPECT_EQ(f.at("totals").at(k), report.at(k)) << k;

  auto cmds = replay(f.at("commands"));
  ASSERT_EQ(cmds.size(), report.at("commands").get<size_t>());
  const auto rows = read_csv(dir + "/moves.csv");
  const json& moves = f.at("moves");
  ASSERT_EQ(moves.size() + 1, rows.size());
  std::vector<int64_t> at(static_cast<size_t>(axes), 0);
  size_t next = 0, arcs = 0;
  for (size_t m = 0; m < moves.size(); ++m) {
    const json& mv = moves[m];
    ASSERT_EQ(mv.at("first_command").get<size_t>(), next);
    const size_t n = mv.at("commands").get<size_t>();
    for (size_t k = next; k < next + n; ++k) {
      arcs += cmds[k]["CMD_FLAGS"] & 1;
      const auto d = displacement(cmds[k], axes);
      for (size_t i = 0; i < at.size(); ++i) at[i] += d[i];
    }
    next += n;
    const std::vector<std::string>& row = rows[m + 1];
    EXPECT_EQ(row[0], std::to_string(mv.at("move").get<uint64_t>()));
    EXPECT_EQ(row[1], std::to_string(mv.at("line").get<uint64_t>()));
    EXPECT_EQ(row[2], mv.at("kind").get<std::string>());
    for (int i = 0; i < axes; ++i) {
      // the file's lattice end, the sum of the deltas, the point the core reached
      EXPECT_EQ(mv.at("end_steps")[static_cast<size_t>(i)].get<int64_t>(),
                at[static_cast<size_t>(i)])
          << "move " << m + 1 << " axis " << i;
      EXPECT_EQ(row[7 + static_cast<size_t>(i)], std::to_string(at[static_cast<size_t>(i)]))
          << "move " << m + 1 << " axis " << i;
    }
    EXPECT_EQ(row[7 + static_cast<size_t>(axes)], std::to_string(n));
    for (int i = 0; i < 4; ++i)
      EXPECT_DOUBLE_EQ(std::stod(row[3 + static_cast<size_t>(i)]),
                       mv.at("end_mm")[static_cast<size_t>(i)].get<double>())
          << "move " << m + 1;
  }
  EXPECT_EQ(next, cmds.size());
  EXPECT_EQ(arcs, report.at("arc_commands").get<size_t>());
  EXPECT_EQ(f.at("end").get<std::vector<int64_t>>(), at);
  EXPECT_EQ(report.at("end_position").get<std::vector<int64_t>>(), at);
}

TEST(SocWrites, TheProfileCarriesItsRegistersAndEachCommandsMove) {
  const std::string dir = scratch_dir("soc_writes_profile");
  const std::string machine = kData + "machine_profile.json";
  const CliResult plan =
      run_hwinterp("gcode " + kData + "corners.ngc --machine " + machine +
                   " --profile scurve --soc-writes " + dir + "/p.json --plan-only");
  ASSERT_EQ(plan.code, 0) << plan.out << plan.err;
  const json f = json::parse(slurp(dir + "/p.json"));
  const json& p = f.at("profile");
  EXPECT_EQ(p.at("kind").get<std::string>(), "scurve");
  EXPECT_GT(p.at("q").get<uint64_t>(), 0u);
  EXPECT_GE(p.at("len").get<unsigned>(), 1u);
  // tb/lockstep/harness_profile.h's build
  EXPECT_EQ(p.at("spd_w").get<int>(), 48);
  EXPECT_EQ(p.at("tick_w").get<int>(), 10);
  EXPECT_EQ(p.at("len_w").get<int>(), 10);
  EXPECT_EQ(p.at("lvl_w").get<int>(), 16);
  EXPECT_EQ(f.at("clock_hz").get<uint64_t>(), 500000u);
  auto cmds = replay(f.at("commands"));
  ASSERT_FALSE(cmds.empty());
  const uint32_t max_level = p.at("max_level").get<uint32_t>();
  for (size_t k = 0; k < cmds.size(); ++k) {
    auto& c = cmds[k];
    EXPECT_EQ(c["CMD_FEED"], 0u) << "command " << k << ": the profile drives the feed";
    EXPECT_GE(c["CMD_MV_OPS"], 1u) << "command " << k;
    if (c["CMD_FLAGS"] & 1) EXPECT_EQ(c["CMD_MV_OPS"], c["CMD_OPS"]) << "command " << k;
    EXPECT_LE(c["CMD_MV_TARGET"], max_level) << "command " << k;
  }
  EXPECT_EQ(cmds.back()["CMD_MV_END"], 0u);  // the program ends at rest

  // The same registers as the lockstep run with the profile reports (a short program).
  const CliResult run = run_hwinterp("gcode " + kData + "modal.ngc --machine " + machine +
                                     " --profile scurve --mode direct --progress 0 --soc-writes " +
                                     dir + "/m.json --json " + dir + "/m_report.json");
  ASSERT_EQ(run.code, 0) << run.out << run.err;
  const json m = json::parse(slurp(dir + "/m.json"));
  const json r = json::parse(slurp(dir + "/m_report.json"));
  EXPECT_EQ(m.at("profile").at("q"), r.at("profile").at("q"));
  EXPECT_EQ(m.at("profile").at("len"), r.at("profile").at("len"));
  EXPECT_EQ(m.at("profile").at("max_level"), r.at("profile").at("max_level"));
}

TEST(SocWrites, PlanOnlyBadUseExitsTwo) {
  const std::string dir = scratch_dir("soc_writes_bad");
  const CliResult a = run_hwinterp("gcode " + kData + "modal.ngc --plan-only");
  EXPECT_EQ(a.code, 2);
  EXPECT_NE(a.err.find("--plan-only: give --soc-writes FILE"), std::string::npos) << a.err;
  const CliResult b = run_hwinterp("gcode " + kData + "modal.ngc --plan-only --soc-writes " + dir +
                                   "/x.json --json " + dir + "/r.json");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("--plan-only: --json needs the lockstep run"), std::string::npos) << b.err;
  // the profile at a variant whose FEED_W is not the profile's is refused, nothing written
  const std::string m3 = dir + "/m3.json";
  {
    std::ofstream(m3) << R"({"axes": ["X", "Y", "Z"], "clock_hz": 500000, "profile": "scurve",
      "max_velocity": {"X": 100, "Y": 100, "Z": 50}, "max_accel": {"X": 1000, "Y": 1000, "Z": 500},
      "max_jerk": {"X": 50000, "Y": 50000, "Z": 25000}})";
  }
  const CliResult c =
      run_hwinterp("gcode " + kData + "modal.ngc --variant motion_top_edge " + "--machine " + m3 +
                   " --soc-writes " + dir + "/e.json --plan-only");
  EXPECT_EQ(c.code, 2) << c.out << c.err;
  EXPECT_NE(c.err.find("FEED_W 7"), std::string::npos) << c.err;
  EXPECT_FALSE(std::ifstream(dir + "/e.json").good());
}

}  // namespace
}  // namespace hwinterp::testing

// motion_soc through its bus in the lockstep harness (tb/bus/): committed
// part programs through each bus reach the lattice points and end points of
// the lockstep run, with the HLS face identical on every clock (`hwinterp
// gcode --bus`); a bad --bus value exits 2; and
// randomized bus traffic (legal and illegal, back to back and with wait
// states, pushes to a full FIFO) never loses a committed command and never
// corrupts a register: every accepted command ends where the sum of the
// accepted deltas says, a refused one is flagged in EVENTS.overflow.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <fstream>
#include <random>
#include <string>
#include <vector>

// The Verilated root headers (for motion_top's done_o) trip -Wunused-parameter
// in Verilator 5.006's own verilated_types.h.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "hwinterp_soc.h"
#pragma GCC diagnostic pop
#include "run_hwinterp.h"
#include "tb/bus/soc_run.h"

namespace hwinterp::testing {
namespace {

namespace bus = tb::bus;
namespace regs = hls::motion_soc_regs;

const std::string kData = std::string(HWINTERP_SOURCE_DIR) + "/tests/data/gcode/";

class SocBusGcode : public ::testing::TestWithParam<std::string> {};

// The bus run's JSON holds everything the lockstep run reached.
void expect_bus_met_lockstep(const nlohmann::json& j, const std::string& bus, bool fills) {
  const auto& b = j.at("bus");
  EXPECT_TRUE(b.at("passed").get<bool>());
  EXPECT_EQ(b.at("bus").get<std::string>(), bus);
  EXPECT_GT(b.at("points").get<uint64_t>(), 1000u);
  EXPECT_EQ(b.at("points"), b.at("lockstep_points"));
  EXPECT_EQ(b.at("first_point_mismatch").get<int64_t>(), -1);
  EXPECT_EQ(b.at("first_end_mismatch").get<int64_t>(), -1);
  EXPECT_EQ(b.at("completed"), b.at("lockstep_completed"));
  EXPECT_EQ(b.at("pushes"), j.at("commands"));
  EXPECT_EQ(b.at("end"), b.at("lockstep_end"));
  EXPECT_EQ(b.at("errors").get<int>(), 0);
  EXPECT_EQ(b.at("events").get<uint32_t>() & bus::kLost, 0u);  // no overflow, no refused push
  EXPECT_EQ(b.at("hls_mismatch_clock").get<uint64_t>(), 0u);   // the HLS face, every clock
  // The FIFO filled (the host slept on the low-water interrupt): back-pressure.
  if (fills) {
    EXPECT_GT(b.at("fifo_full_reads").get<uint64_t>(), 0u);
    EXPECT_GT(b.at("irq_wait_clocks").get<uint64_t>(), 0u);
  }
}

// incremental.ngc (G91 lines and arcs, a rotary axis) through the bus at
// motion_top_n4's widths, with wait states.
TEST_P(SocBusGcode, ProgramReachesTheLockstepLatticePoints) {
  const std::string dir = scratch_dir("soc_bus_" + GetParam());
  const CliResult r =
      run_hwinterp("gcode " + kData + "incremental.ngc --mode direct --progress 0 --bus " +
                   GetParam() + " --bus-waits 2 --json " + dir + "/run.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  expect_bus_met_lockstep(nlohmann::json::parse(slurp(dir + "/run.json")), GetParam(), true);
}

// The lockstep run in SystemC mode, then the bus run: the same lattice
// points (modal.ngc on the default machine).
TEST_P(SocBusGcode, SystemcLockstepModeReachesTheSameLatticePoints) {
  const std::string dir = scratch_dir("soc_bus_sc_" + GetParam());
  const CliResult r =
      run_hwinterp("gcode " + kData + "modal.ngc --mode systemc --progress 0 --bus " + GetParam() +
                   " --json " + dir + "/run.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(dir + "/run.json"));
  EXPECT_EQ(j.at("mode").get<std::string>(), "systemc");
  expect_bus_met_lockstep(j, GetParam(), false);
}

// modal.ngc on a 3-axis machine at motion_top_edge's narrow widths (its 14
// commands fit the FIFO).
TEST_P(SocBusGcode, EdgeWidthsReachTheLockstepLatticePoints) {
  const std::string dir = scratch_dir("soc_bus_edge_" + GetParam());
  std::ofstream(dir + "/m3.json")
      << R"({"axes": ["X", "Y", "Z"], "steps_per_unit": {"X": 100, "Y": 100, "Z": 100}})";
  const CliResult r = run_hwinterp("gcode " + kData + "modal.ngc --machine " + dir +
                                   "/m3.json --variant motion_top_edge --mode direct --progress "
                                   "0 --bus " +
                                   GetParam() + " --json " + dir + "/run.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(dir + "/run.json"));
  EXPECT_EQ(j.at("variant").get<std::string>(), "motion_top_edge");
  expect_bus_met_lockstep(j, GetParam(), false);  // 14 commands: the FIFO holds 16
}

// Every step output type (STEP_TYPE, rtl/step_encode.sv) on the axes of
// motion_top_n4: the bus run decodes each axis's out_a/out_b by its type
// (tb/monitor/step_output_monitor.h), meets the lockstep run's lattice
// points and keeps each type's timing on every clock.
TEST_P(SocBusGcode, StepTypesDecodeToTheLockstepLatticePoints) {
  const std::string dir = scratch_dir("soc_bus_types_" + GetParam());
  const CliResult r =
      run_hwinterp("gcode " + kData + "modal.ngc --mode direct --progress 0 --bus " + GetParam() +
                   " --step-types quad,updown,stepdir,quad --json " + dir + "/run.json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(dir + "/run.json"));
  expect_bus_met_lockstep(j, GetParam(), false);
  EXPECT_EQ(j.at("bus").at("step_types").get<std::string>(), "quad,updown,stepdir,quad");
  EXPECT_EQ(j.at("bus").at("timing_violations").get<uint64_t>(), 0u);
  EXPECT_NE(r.out.find("STEP_TYPE quad,updown,stepdir,quad"), std::string::npos) << r.out;
}

INSTANTIATE_TEST_SUITE_P(Buses, SocBusGcode, ::testing::Values("axi4lite", "wishbone"));

TEST(SocBusCli, BadBusOptionsExit2NamingThem) {
  const CliResult r =
      run_hwinterp("gcode " + kData + "arcs.ngc --mode direct --progress 0 --bus pci");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'pci'"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("lockstep"), std::string::npos) << "ran something: " << r.out;
  const CliResult w = run_hwinterp("gcode " + kData + "arcs.ngc --progress 0 --bus-waits 2");
  EXPECT_EQ(w.code, 2);
  EXPECT_NE(w.err.find("--bus-waits"), std::string::npos) << w.err;
  const CliResult n =
      run_hwinterp("gcode " + kData + "arcs.ngc --progress 0 --bus wishbone --bus-waits 65");
  EXPECT_EQ(n.code, 2);
  EXPECT_NE(n.err.find("65"), std::string::npos) << n.err;
  const CliResult t =
      run_hwinterp("gcode " + kData + "arcs.ngc --progress 0 --bus axi4lite --step-types quad,pwm");
  EXPECT_EQ(t.code, 2);
  EXPECT_NE(t.err.find("'pwm'"), std::string::npos) << t.err;
  const CliResult nb = run_hwinterp("gcode " + kData + "arcs.ngc --progress 0 --step-types quad");
  EXPECT_EQ(nb.code, 2);
  EXPECT_NE(nb.err.find("--step-types"), std::string::npos) << nb.err;
  const CliResult c = run_hwinterp("gcode " + kData +
                                   "arcs.ngc --progress 0 --bus wishbone --step-types quad,updown");
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("2 types"), std::string::npos) << c.err;
  EXPECT_EQ(c.out.find("lockstep"), std::string::npos) << "ran something: " << c.out;
}

// The check itself: a different step, a different grouping, a command ending
// elsewhere and a shorter run are all reported.
TEST(SocBusLattice, CheckFindsEveryKindOfDifference) {
  bus::LatticeRecord rec;
  rec.pulses(1, 0);
  rec.pulses(3, 2);
  rec.done();
  rec.pulses(4, 4);
  rec.done();
  {
    bus::LatticeCheck c(rec);
    c.pulses(1, 0);
    c.pulses(3, 2 | 4);  // dir of a non-stepping axis does not count
    c.done(0);
    c.pulses(4, 4);
    c.done(1);
    EXPECT_TRUE(c.same());
  }
  {
    bus::LatticeCheck c(rec);
    c.pulses(1, 0);
    c.pulses(1, 0);  // axis 1 stepped apart: another point
    c.pulses(2, 2);
    EXPECT_EQ(c.first_point(), 1);
  }
  {
    bus::LatticeCheck c(rec);
    c.pulses(1, 0);
    c.done(0);  // ended one point early
    c.pulses(3, 2);
    c.pulses(4, 4);
    c.done(1);
    EXPECT_EQ(c.first_point(), -1);
    EXPECT_EQ(c.first_end(), 0);
  }
  {
    bus::LatticeCheck c(rec);
    c.pulses(1, 0);
    EXPECT_EQ(c.first_point(), 1);  // shorter
    EXPECT_FALSE(c.same());
  }
}

constexpr uint32_t kOverflow = bus::field_bit("events", "overflow");

// The bits of the word at `addr` that software writes and reads back (from
// the generated description).
uint32_t rw_mask(uint32_t addr) {
  uint32_t m = 0;
  for (const regs::FieldDesc& f : regs::kFields) {
    const regs::RegDesc& r = regs::kRegs[f.reg];
    if (f.sw != regs::Sw::kRw || f.hw_writes || addr < r.addr || addr >= r.addr + 4 * r.words)
      continue;
    const int lsb = f.lsb - 32 * static_cast<int>((addr - r.addr) / 4);
    if (lsb < 0 || lsb >= 32) continue;
    m |= (f.width >= 32 ? 0xFFFFFFFFu : ((1u << f.width) - 1)) << lsb;
  }
  return m;
}

// Randomized traffic on one build, one bus.
template <class Model, template <class> class Master, class Probe>
void random_traffic(uint64_t seed, int axes, int commands, uint32_t max_wait) {
  VerilatedContext ctx;
  Model m(&ctx);
  Master<Model> master(bus::WaitStates{max_wait, seed});
  std::mt19937_64 rng(seed);
  auto uni = [&](int64_t lo, int64_t hi) {
    return std::uniform_int_distribution<int64_t>(lo, hi)(rng);
  };
  master.drive(m);
  bus::reset_soc(m, [](Model&) {});
  bus::NoShadow no_shadow;  // the bus alone: no HLS face here

  struct Op {
    bus::BusTxn t;
    int expect_err;  // 1: error, 0: no error, -1: either
    int kind;        // 0 plain, 1 credit push, 2 push without credit, 3 FIFO_LEVEL, 4 EVENTS
                     // after a push without credit, 5 read back of a register just written
    uint32_t expect_data;
  };
  std::deque<Op> ops;
  auto wr = [&](uint32_t a, uint32_t d, int err = 0, int kind = 0) {
    ops.push_back({bus::BusTxn{true, a, d, 0xF}, err, kind, 0});
  };
  auto rd = [&](uint32_t a, int err = 0, int kind = 0, uint32_t expect = 0) {
    ops.push_back({bus::BusTxn{false, a, 0, 0xF}, err, kind, expect});
  };
  wr(regs::kStepLen, 2);
  wr(regs::kStepSpace, 2);
  wr(regs::kDirSetup, 3);
  wr(regs::kDirHold, 3);
  wr(regs::kCmdFeed, 0xFFFFFFFFu);  // saturates: full feed

  std::vector<int64_t> staged(static_cast<size_t>(axes), 0), expect_pos(staged), pos(staged);
  std::deque<std::vector<int64_t>> expect_ends;  // accepted commands not yet done
  uint32_t room = 0;                             // FIFO_LEVEL.room as last read, less pushes
  int pushed = 0, accepted = 0, refused = 0, errors_seen = 0, illegal = 0, done = 0;
  uint64_t clocks = 0;
  uint32_t prev_step = 0;
  const uint32_t mask = (1u << axes) - 1;
  bool in_flight = false, held = false;
  int holds = 0, transactions = 0;
  Op cur{};

  while (clocks < 2000000) {
    if (!in_flight) {
      if (ops.empty()) {
        if (pushed == commands) {
          if (held) {  // let the last commands run
            wr(regs::kFeed, 0xFFFFFFFFu);
            held = false;
          } else if (expect_ends.empty()) {
            break;
          }
        } else {
          // What to do next.
          const int64_t k = uni(0, 99);
          if (k < 30) {  // stage and push a command
            for (int i = 0; i < axes; ++i) {
              staged[static_cast<size_t>(i)] = uni(-12, 12);
              wr(regs::kCmdDelta0 + 4u * static_cast<uint32_t>(i),
                 static_cast<uint32_t>(staged[static_cast<size_t>(i)]));
            }
            wr(regs::kCmdFlags, 0);
            if (room == 0) rd(regs::kFifoLevel, 0, 3);
            wr(regs::kCmdPush, 1, 0, 1);
          } else if (k < 40) {  // an unmapped word
            static const uint32_t kHoles[] = {0x1c, 0x38,  0x3c,  0x58,  0x7c,  0xe8,
                                              0xec, 0x150, 0x1fc, 0x250, 0x3f8, 0x3fc};
            const uint32_t a = kHoles[uni(0, 11)];
            uni(0, 1) ? wr(a, static_cast<uint32_t>(uni(0, 0xFFFFFFFF)), 1) : rd(a, 1);
            ++illegal;
          } else if (k < 50) {  // a write of a read-only register, a read of a write-only one
            static const uint32_t kRo[] = {regs::kIdMagic, regs::kStatus, regs::kFifoLevel,
                                           regs::kTimeLo, regs::kSnapPos0};
            static const uint32_t kWo[] = {regs::kCtrl, regs::kCmdDelta0, regs::kCmdPush,
                                           regs::kWdogKick, regs::kCmdFlags};
            uni(0, 1) ? wr(kRo[uni(0, 4)], 0xFFFFFFFFu, 1) : rd(kWo[uni(0, 4)], 1);
            ++illegal;
          } else if (k < 65) {  // a harmless register written and read back
            static const uint32_t kRw[] = {regs::kFifoLow, regs::kIrqEn, regs::kSnapAt,
                                           regs::kSnapAt + 4};
            const int i = static_cast<int>(uni(0, 3));
            const uint32_t v = static_cast<uint32_t>(uni(0, 0xFFFFFFFF));
            wr(kRw[i], v);
            rd(kRw[i], 0, 5, v & rw_mask(kRw[i]));
          } else if (k < 80) {  // reads
            rd(regs::kIdMagic, 0, 5, 0x484D5331u);
            rd(regs::kStatus);
          } else if (k < 84) {  // feed hold (FEED 0) or full feed: the FIFO fills on a hold
            held = !held;
            wr(regs::kFeed, held ? 0u : 0xFFFFFFFFu);
            ++holds;
          } else if (k < 92 && room == 0 && pushed > 0) {
            // A push without credit (the FIFO was full when last asked):
            // taken if it drained since, else refused with EVENTS.overflow.
            wr(regs::kCmdPush, 1, 0, 2);
            rd(regs::kEvents, 0, 4);
          } else {
            rd(regs::kFifoLevel, 0, 3);
          }
        }
      }
      if (!ops.empty()) {
        cur = ops.front();
        ops.pop_front();
        if (cur.kind == 1 && room == 0) {
          ops.push_front(cur);
          if (held) {  // a full FIFO on a feed hold: release it
            cur = Op{bus::BusTxn{true, regs::kFeed, 0xFFFFFFFFu, 0xF}, 0, 0, 0};
            held = false;
          } else {  // no credit yet: ask again
            cur = Op{bus::BusTxn{false, regs::kFifoLevel, 0, 0xF}, 0, 3, 0};
          }
        }
        if (cur.kind == 1) {
          --room;
          ++pushed;
          ++accepted;
          for (int i = 0; i < axes; ++i)
            expect_pos[static_cast<size_t>(i)] += staged[static_cast<size_t>(i)];
          expect_ends.push_back(expect_pos);
        }
        master.issue(cur.t);
        in_flight = true;
        ++transactions;
      }
    }
    bus::soc_clock<Probe>(m, master, no_shadow, ++clocks);
    bus::BusRsp rsp;
    if (master.take(rsp)) {
      in_flight = false;
      if (cur.expect_err >= 0)
        ASSERT_EQ(rsp.err, cur.expect_err == 1)
            << std::hex << "addr 0x" << cur.t.addr << (cur.t.write ? " write" : " read");
      if (rsp.err) ++errors_seen;
      if (cur.kind == 3) room = rsp.data >> 16;
      if (cur.kind == 5) ASSERT_EQ(rsp.data, cur.expect_data) << std::hex << cur.t.addr;
      if (cur.kind == 4) {
        ++pushed;
        if (rsp.data & kOverflow) {  // refused, flagged; clear it
          ++refused;
          ops.push_front({bus::BusTxn{true, regs::kEvents, kOverflow, 0xF}, 0, 0, 0});
        } else {
          ++accepted;
          for (int i = 0; i < axes; ++i)
            expect_pos[static_cast<size_t>(i)] += staged[static_cast<size_t>(i)];
          expect_ends.push_back(expect_pos);
        }
        room = 0;
      }
    }
    const uint32_t step = m.out_a_o & mask, dir = m.out_b_o & mask, rising = step & ~prev_step;
    prev_step = step;
    for (int i = 0; i < axes; ++i)
      if (rising >> i & 1) pos[static_cast<size_t>(i)] += (dir >> i & 1) ? -1 : 1;
    if (Probe::done(m)) {
      ASSERT_FALSE(expect_ends.empty()) << "a command completed that was never accepted";
      // A push's EVENTS read may still be on its way: an unaccepted command
      // that completed is caught above only once the read says refused.
      ASSERT_EQ(pos, expect_ends.front()) << "command " << done;
      expect_ends.pop_front();
      ++done;
    }
  }
  EXPECT_LT(clocks, 2000000u) << "stalled";
  EXPECT_EQ(done, accepted);
  EXPECT_EQ(pushed, commands);
  EXPECT_EQ(pushed, accepted + refused);
  EXPECT_EQ(pos, expect_pos);
  EXPECT_GT(refused, 0) << "no push to a full FIFO was refused: the test did not reach it";
  EXPECT_GT(illegal, 50);
  EXPECT_GT(holds, 5);
  EXPECT_EQ(errors_seen, illegal);
  std::printf(
      "seed %llu: %llu clocks, %d transactions (%d illegal), %d feed holds, %d pushes: "
      "%d taken, %d refused (FIFO full)\n",
      static_cast<unsigned long long>(seed), static_cast<unsigned long long>(clocks), transactions,
      illegal, holds, pushed, accepted, refused);
}

TEST(SocBusRandom, AxiTrafficLosesNoCommand) {
  using Soc = SocOf<motion_top_n3_cfg>;
  for (uint64_t seed : {1, 2, 3})
    random_traffic<Soc::Axil, bus::Axi4LiteMaster, Soc>(seed, 3, 150, seed == 1 ? 0 : 3);
}
TEST(SocBusRandom, WishboneTrafficLosesNoCommand) {
  using Soc = SocOf<motion_top_n3_cfg>;
  for (uint64_t seed : {1, 2, 3})
    random_traffic<Soc::Wb, bus::WishboneMaster, Soc>(seed, 3, 150, seed == 1 ? 0 : 3);
}
TEST(SocBusRandom, EdgeWidthsLoseNoCommand) {
  using Soc = SocOf<motion_top_edge_cfg>;
  random_traffic<Soc::Axil, bus::Axi4LiteMaster, Soc>(7, 3, 150, 2);
  random_traffic<Soc::Wb, bus::WishboneMaster, Soc>(8, 3, 150, 2);
}

// The HLS face (hls/motion_soc.h, hls/motion_soc_bus.h) against the
// Verilated top on every clock (tb/bus/hls_shadow.h) under random traffic to
// every register: commands (lines and half circles, timed or not), feed
// holds, step timing and step types, the watchdog, aborts, snapshots, the
// probe latch (random probe_i), estop_i, event clears, unmapped words, random
// byte strobes, with wait states. The two must agree on every bus response
// and every output pin for the whole run.
template <class Cfg, class Model, template <class> class Master, class Shadow>
void random_lockstep(uint64_t seed, uint64_t clocks) {
  using Probe = SocOf<Cfg>;
  VerilatedContext ctx;
  Model m(&ctx);
  Master<Model> master(bus::WaitStates{static_cast<uint32_t>(seed % 3), seed});
  Shadow shadow;
  std::mt19937_64 rng(seed);
  auto uni = [&](int64_t lo, int64_t hi) {
    return std::uniform_int_distribution<int64_t>(lo, hi)(rng);
  };
  master.drive(m);
  bus::reset_soc(m, [&](Model& mm) { shadow.before_edge(mm); });
  const uint32_t full_feed = 1u << Cfg::FEED_W;
  std::array<int64_t, 2> center{}, end{};
  bool ccw = false;
  uint64_t arc_ops = 0;  // the last half circle's operation count
  uint64_t estop_left = 0;
  int writes = 0, reads = 0, pushes = 0, dones = 0, steps = 0;
  uint32_t prev_step = 0;
  for (uint64_t c = 1; c <= clocks; ++c) {
    if (master.idle() && uni(0, 9) < 8) {
      bus::BusTxn t;
      t.strb = uni(0, 9) == 0 ? static_cast<uint8_t>(uni(0, 15)) : 0xF;
      const int64_t k = uni(0, 99);
      auto w = [&](uint32_t a, int64_t d) {
        t.write = true;
        t.addr = a;
        t.data = static_cast<uint32_t>(d);
      };
      if (k < 12) {  // a command's staging
        const int64_t f = uni(0, 5);
        if (f < 3) {
          w(regs::kCmdDelta0 + 4u * static_cast<uint32_t>(uni(0, Cfg::AXES - 1)), uni(-30, 30));
        } else if (f == 3) {  // a half circle: the end diametric to the start
          center = {uni(-15, 15), uni(-15, 15)};
          end = {2 * center[0], 2 * center[1]};
          ccw = uni(0, 1);
          w(regs::kCmdCenter0, center[0]);
          arc_ops = models::motion_arc_ops(center, end, ccw);
        } else {
          w(regs::kCmdFeed, uni(0, 3) ? full_feed : uni(0, full_feed));
        }
      } else if (k < 20) {  // the rest of the arc, the flags, the push
        const int64_t f = uni(0, 5);
        if (f == 0) w(regs::kCmdCenter1, center[1]);
        if (f == 1) w(regs::kCmdEnd0, end[0]);
        if (f == 2) w(regs::kCmdEnd1, end[1]);
        if (f == 3) w(regs::kCmdOps, static_cast<int64_t>(arc_ops));
        if (f >= 4) {
          const bool arc = uni(0, 2) == 0, timed = uni(0, 4) == 0;
          w(regs::kCmdFlags,
            (arc ? bus::kArcBit : 0) | (static_cast<uint32_t>(uni(0, 2)) << bus::kPlaneLsb) |
                (ccw ? bus::kCcwBit : 0) | (timed ? bus::field_bit("cmd_flags", "timed") : 0));
        }
      } else if (k < 30) {
        w(regs::kCmdPush, 1);
        ++pushes;
      } else if (k < 32) {
        w(regs::kCmdAt, static_cast<int64_t>(c) + uni(-50, 400));
      } else if (k < 35) {
        w(regs::kFeed, uni(0, 3) ? full_feed : uni(0, full_feed));
      } else if (k < 38) {
        static const uint32_t kTiming[] = {regs::kStepLen, regs::kStepSpace, regs::kDirSetup,
                                           regs::kDirHold};
        w(kTiming[uni(0, 3)], uni(0, 6));
      } else if (k < 40) {
        w(regs::kStepType, uni(0, 0xFFF));
      } else if (k < 42) {
        w(regs::kWdogPeriod, uni(0, 2) ? 0 : uni(1, 400));
      } else if (k < 45) {
        w(regs::kWdogKick, 1);
      } else if (k < 46) {
        w(regs::kCtrl, 1);  // abort
      } else if (k < 50) {
        w(regs::kEvents, uni(0, 0x1FF));
      } else if (k < 52) {
        w(regs::kSnapAt, static_cast<int64_t>(c) + uni(-20, 300));
      } else if (k < 54) {
        w(regs::kSnapCtrl, 1);
      } else if (k < 56) {
        w(regs::kProbeCfg, uni(0, 6) | (uni(0, 1) << 16) | ((uni(0, 5) == 0) << 17));
      } else if (k < 58) {
        w(regs::kLatchCtrl, 1);
      } else if (k < 60) {
        w(uni(0, 1) ? regs::kIrqEn : regs::kFifoLow, uni(0, 0x1FF));
      } else if (k < 63) {  // any word, mapped or not, written with anything
        w(static_cast<uint32_t>(uni(0, 255)) * 4, uni(0, 0xFFFFFFFF));
      } else {  // a read of any word (mostly the map)
        t.write = false;
        t.addr = static_cast<uint32_t>(uni(0, 3) ? uni(0, 0x23C / 4) : uni(0, 255)) * 4;
      }
      t.write ? ++writes : ++reads;
      master.issue(t);
    }
    if (uni(0, 199) == 0) m.probe_i = !m.probe_i;
    if (estop_left == 0 && uni(0, 19999) == 0) estop_left = static_cast<uint64_t>(uni(1, 20));
    m.estop_i = estop_left > 0;
    if (estop_left) --estop_left;
    const bool done = bus::soc_clock<Probe>(m, master, shadow, c);
    const auto& mm = shadow.mismatch();
    ASSERT_FALSE(shadow.failed()) << "seed " << seed << ": clock " << mm.clock << " " << mm.what
                                  << " HLS " << mm.hls << " RTL " << mm.rtl;
    bus::BusRsp rsp;
    master.take(rsp);
    dones += done;
    const uint32_t step = m.out_a_o;
    steps += __builtin_popcount(step & ~prev_step);
    prev_step = step;
  }
  std::printf(
      "seed %llu: %llu clocks, %d writes (%d pushes), %d reads, %d commands done, %d "
      "out_a rises: HLS = RTL on every clock\n",
      static_cast<unsigned long long>(seed), static_cast<unsigned long long>(clocks), writes,
      pushes, reads, dones, steps);
  EXPECT_GT(dones, 3);
  EXPECT_GT(steps, 200);
}

TEST(SocBusHls, RandomTrafficMatchesTheRtlOnEveryClock) {
  using N3 = SocOf<motion_top_n3_cfg>;
  using Edge = SocOf<motion_top_edge_cfg>;
  random_lockstep<motion_top_n3_cfg, N3::Axil, bus::Axi4LiteMaster,
                  bus::AxilShadow<motion_top_n3_cfg>>(11, 60000);
  random_lockstep<motion_top_n3_cfg, N3::Wb, bus::WishboneMaster, bus::WbShadow<motion_top_n3_cfg>>(
      12, 60000);
  random_lockstep<motion_top_edge_cfg, Edge::Axil, bus::Axi4LiteMaster,
                  bus::AxilShadow<motion_top_edge_cfg>>(13, 60000);
  random_lockstep<motion_top_edge_cfg, Edge::Wb, bus::WishboneMaster,
                  bus::WbShadow<motion_top_edge_cfg>>(14, 60000);
}

// regblock's AXI4-Lite interface in the HLS face with more than one
// transaction in flight: AW, W and AR raised independently at random (each
// held to its handshake, as AXI4-Lite requires), bready and rready random on
// every clock, so reads and writes overlap and queue in the response buffer.
TEST(SocBusHls, AxiChannelsOverlapAndMatchTheRtl) {
  using Cfg = motion_top_n3_cfg;
  using Model = SocOf<Cfg>::Axil;
  VerilatedContext ctx;
  Model m(&ctx);
  bus::AxilShadow<Cfg> shadow;
  std::mt19937_64 rng(21);
  auto uni = [&](int64_t lo, int64_t hi) {
    return std::uniform_int_distribution<int64_t>(lo, hi)(rng);
  };
  auto addr = [&]() {  // mostly the map, sometimes anywhere
    return static_cast<uint32_t>(uni(0, 3) ? uni(0, 0x23C / 4) : uni(0, 255)) * 4;
  };
  m.s_axil_awvalid_i = m.s_axil_wvalid_i = m.s_axil_arvalid_i = 0;
  m.s_axil_bready_i = m.s_axil_rready_i = 0;
  m.s_axil_awprot_i = m.s_axil_arprot_i = 0;
  bus::reset_soc(m, [&](Model& mm) { shadow.before_edge(mm); });
  int aw = 0, wd = 0, ar = 0, b = 0, r = 0, two_in_flight = 0;
  int outstanding = 0;
  for (uint64_t c = 1; c <= 40000; ++c) {
    if (!m.s_axil_awvalid_i && uni(0, 2) == 0) {
      m.s_axil_awvalid_i = 1;
      m.s_axil_awaddr_i = addr();
    }
    if (!m.s_axil_wvalid_i && uni(0, 2) == 0) {
      m.s_axil_wvalid_i = 1;
      m.s_axil_wdata_i = static_cast<uint32_t>(uni(0, 3) ? uni(-40, 40) : uni(0, 0xFFFFFFFF));
      m.s_axil_wstrb_i = uni(0, 4) ? 0xF : static_cast<uint8_t>(uni(0, 15));
    }
    if (!m.s_axil_arvalid_i && uni(0, 2) == 0) {
      m.s_axil_arvalid_i = 1;
      m.s_axil_araddr_i = addr();
    }
    m.s_axil_bready_i = uni(0, 2) != 0;
    m.s_axil_rready_i = uni(0, 2) != 0;
    m.clk_i = 0;
    m.eval();
    const bool aw_fire = m.s_axil_awvalid_i && m.s_axil_awready_o;
    const bool w_fire = m.s_axil_wvalid_i && m.s_axil_wready_o;
    const bool ar_fire = m.s_axil_arvalid_i && m.s_axil_arready_o;
    const bool b_fire = m.s_axil_bvalid_o && m.s_axil_bready_i;
    const bool r_fire = m.s_axil_rvalid_o && m.s_axil_rready_i;
    shadow.before_edge(m);
    m.clk_i = 1;
    m.eval();
    shadow.after_edge(m, SocOf<Cfg>::done(m), c);
    const auto& mm = shadow.mismatch();
    ASSERT_FALSE(shadow.failed()) << "clock " << mm.clock << " " << mm.what << " HLS " << mm.hls
                                  << " RTL " << mm.rtl;
    if (aw_fire) m.s_axil_awvalid_i = 0, ++aw;
    if (w_fire) m.s_axil_wvalid_i = 0, ++wd;
    if (ar_fire) m.s_axil_arvalid_i = 0, ++ar, ++outstanding;
    if (aw_fire) ++outstanding;
    if (b_fire) ++b, --outstanding;
    if (r_fire) ++r, --outstanding;
    if (outstanding >= 2) ++two_in_flight;
  }
  std::printf(
      "AXI4-Lite channels at random: %d AW, %d W, %d AR, %d B, %d R; %d clocks with two "
      "or more accepted and unanswered: HLS = RTL on every clock\n",
      aw, wd, ar, b, r, two_in_flight);
  EXPECT_GT(b, 1000);
  EXPECT_GT(r, 1000);
  EXPECT_GT(two_in_flight, 1000);
}

}  // namespace
}  // namespace hwinterp::testing

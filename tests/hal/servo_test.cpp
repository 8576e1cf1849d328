// The LinuxCNC driver's servo without a board (sw/hal/hwinterp_servo.h):
// the lattice, the period's line and its feed word, the Etherbone records it
// writes, the boundaries and the packet window. tests/board/test_hal_servo.py
// runs the same code against the simulated board.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <vector>

#include "servo_fixture.h"

namespace {

using namespace hal_test;

hwi_board_id_t board_id() {
  hwi_board_id_t id{};
  id.magic = MOTION_SOC_REGS__ID_MAGIC__MAGIC_reset;
  id.major = MOTION_SOC_REGS__ID_VERSION__MAJOR_reset;
  id.axes = 4;
  id.fifo_depth = 64;
  id.feed_w = 24;
  id.clock_hz = 1000000;
  return id;
}

hwi_config_t config(uint32_t axes = 3) {
  hwi_config_t c{};
  c.axes = axes;
  c.period_ns = 1000000;         // 1000 clocks
  c.boundary_lead_ns = 5000000;  // 5 periods
  c.step_len_ns = 2000;
  c.step_space_ns = 2000;
  c.dir_setup_ns = 3000;
  c.dir_hold_ns = 3000;
  c.watchdog_period_ns = 20000000;
  c.retry_periods = 4;
  c.dead_periods = 32;
  return c;
}

// One axis at 0, SEQ 0, board time 0 at host time 0.
void start_one_axis(hwi_servo_t* s) {
  const hwi_config_t c = config(1);
  const hwi_board_id_t id = board_id();
  const int64_t start[1] = {0};
  hwi_servo_start(s, &c, &id, 3, 0, start, 0, 0);
}

TEST(HalServo, LatticeRoundsToTheNearestStepAndRefusesWhatIsNotANumber) {
  EXPECT_EQ(hwi_lattice(1.0, 200.0), 200);
  EXPECT_EQ(hwi_lattice(0.0024, 200.0), 0);  // 0.48 step
  EXPECT_EQ(hwi_lattice(0.0026, 200.0), 1);  // 0.52 step
  EXPECT_EQ(hwi_lattice(-0.0026, 200.0), -1);
  EXPECT_EQ(hwi_lattice(std::nan(""), 200.0), 0);
  EXPECT_EQ(hwi_lattice(std::numeric_limits<double>::infinity(), 1.0), 0);
}

TEST(HalServo, ALineRunsTwoToTheBitLengthOfItsLargestDelta) {
  const int64_t zero[3] = {0, 0, 0}, one[3] = {0, -1, 0}, d[3] = {5, -31, 2}, e[3] = {32, 0, 0};
  EXPECT_EQ(hwi_line_exponent(zero, 3), 0);
  EXPECT_EQ(hwi_line_exponent(one, 3), 1);
  EXPECT_EQ(hwi_line_exponent(d, 3), 5);
  EXPECT_EQ(hwi_line_exponent(e, 3), 6);
}

// The feed word makes 2^n operations end within the budget, as fast as the
// budget needs and no faster, and never beyond the step stage's rate.
TEST(HalServo, FeedWordEndsTheLineWithinItsBudgetAtTheStepStagesRate) {
  const uint32_t fw = 24;
  const uint64_t one = uint64_t{1} << fw;
  for (int n = 0; n <= 10; ++n)
    for (int64_t budget : {50, 237, 937, 1000, 4000}) {
      int too_fast = 0;
      const uint32_t feed = hwi_line_feed(n, budget, fw, 4, &too_fast);
      const uint64_t ops = uint64_t{1} << n;
      const double clocks = static_cast<double>(ops) * static_cast<double>(one) / feed;
      if (ops * 4 <= static_cast<uint64_t>(budget)) {
        EXPECT_FALSE(too_fast) << n << " " << budget;
        EXPECT_LE(clocks, static_cast<double>(budget)) << n << " " << budget;
        // One less would not fit: the slowest word that fits.
        EXPECT_GT(static_cast<double>(ops) * static_cast<double>(one) / (feed - 1), budget);
      } else {
        EXPECT_TRUE(too_fast) << n << " " << budget;
        EXPECT_EQ(feed, one / 4);  // one operation every step_len + step_space clocks
      }
    }
}

// The latency and the retries from the round trip measured at load.
TEST(HalServo, LinkTimingFollowsTheRoundTripMeasured) {
  const uint64_t ms = 1000000;
  hwi_link_timing_t t = hwi_link_timing(ms / 4, ms, 0, 0);  // a LAN: 0.25 ms
  EXPECT_EQ(t.lead_ns, 5 * ms);                             // at least five periods
  EXPECT_EQ(t.retry_periods, 4u);
  EXPECT_EQ(t.dead_periods, 100u);
  t = hwi_link_timing(8 * ms, ms, 0, 0);  // a slow link: 8 ms
  EXPECT_EQ(t.lead_ns, 26 * ms);          // three round trips and two periods
  EXPECT_EQ(t.retry_periods, 17u);        // two round trips, and one
  EXPECT_EQ(t.dead_periods, 425u);
  t = hwi_link_timing(8 * ms, ms, 20 * ms, 0);  // given: kept
  EXPECT_EQ(t.lead_ns, 20 * ms);
  EXPECT_EQ(t.retry_periods, 17u);
  // A UART at 1 Mbaud: 0.3 ms round trips of small reads, 1.5 ms a period's
  // exchange on the wire.
  t = hwi_link_timing(300000, ms, 0, 1500000);
  EXPECT_EQ(t.lead_ns, 8900000u);  // 3 x 0.3 + 2 x 1 + 4 x 1.5 ms
  EXPECT_EQ(t.retry_periods, 4u);  // (0.6 + 3) / 1 + 1
}

TEST(HalServo, IdRefusesAProfileBuildAndTooManyJoints) {
  hwi_config_t c = config();
  hwi_board_id_t id = board_id();
  EXPECT_EQ(hwi_id_problem(&id, &c), nullptr);
  id.profile = 1;
  EXPECT_NE(hwi_id_problem(&id, &c), nullptr);
  id = board_id();
  c.axes = 5;
  EXPECT_NE(hwi_id_problem(&id, &c), nullptr);
  id.magic = 0;
  c.axes = 3;
  EXPECT_NE(hwi_id_problem(&id, &c), nullptr);
}

TEST(HalServo, ReplyDecodingRefusesMalformedPackets) {
  uint32_t tag = 0, w[4];
  std::vector<uint8_t> r = reply(0x12345600, {7, 8});
  EXPECT_EQ(hwi_eb_reply(r.data(), r.size(), &tag, w, 4), 2);
  EXPECT_EQ(tag, 0x12345600u);
  EXPECT_EQ(w[1], 8u);
  EXPECT_EQ(hwi_eb_reply(r.data(), r.size() - 1, &tag, w, 4), -1);  // short
  EXPECT_EQ(hwi_eb_reply(r.data(), r.size(), &tag, w, 1), -1);      // more words than asked
  r[0] = 0;
  EXPECT_EQ(hwi_eb_reply(r.data(), r.size(), &tag, w, 4), -1);  // magic
}

// The first packet carries the settings; each period with motion pushes one
// timed line from the last point to this one, its boundary the period's
// host time on the board plus the latency, one period after the last.
TEST(HalServo, EachPeriodIsOneTimedLineAtItsBoundary) {
  hwi_servo_t s;
  const hwi_config_t c = config();
  const hwi_board_id_t id = board_id();
  const int64_t start[3] = {10, -5, 0};
  hwi_servo_start(&s, &c, &id, 3, 100, start, /*board_time=*/50000, /*host_ns=*/0);
  Sent out;
  GuardedBoard board;
  board.expect = 100;
  const int64_t p1[3] = {14, -5, 1}, p2[3] = {14, -5, 1}, p3[3] = {20, -9, 1};
  const int64_t* path[3] = {p1, p2, p3};
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(hwi_servo_period(&s, (k + 1) * 1000000, path[k], Sent::send, &out), 1);
    // The board keeps time: its TIME when it reads is the host's, 200 clocks on.
    board.regs[motion(offsetof(motion_soc_regs_t, time_lo))] = 50000 + (k + 1) * 1000 + 200;
    const std::vector<uint8_t> r = board.answer(out.packets.back());
    ASSERT_EQ(hwi_servo_reply(&s, r.data(), r.size(), (k + 1) * 1000000 + 200000), 1);
  }
  ASSERT_EQ(board.taken.size(), 3u);
  // Settings: FEED (a full word), the step timing in clocks, EVENTS cleared, the watchdog.
  std::map<uint32_t, uint32_t> first(board.taken[0].writes.begin(), board.taken[0].writes.end());
  EXPECT_EQ(first[motion(offsetof(motion_soc_regs_t, feed))], 1u << 24);
  EXPECT_EQ(first[motion(offsetof(motion_soc_regs_t, step_len))], 2u);
  EXPECT_EQ(first[motion(offsetof(motion_soc_regs_t, dir_setup))], 3u);
  EXPECT_EQ(first[motion(offsetof(motion_soc_regs_t, events))], 0xFFFFFFFFu);
  EXPECT_EQ(first[motion(offsetof(motion_soc_regs_t, wdog_period))], 20000u);
  // The pushes: periods 1 and 3 (period 2 does not move).
  std::vector<std::map<uint32_t, uint32_t>> pushes;
  std::map<uint32_t, uint32_t> staged;
  for (const Decoded& d : board.taken)
    for (auto [a, v] : d.writes) {
      staged[a] = v;
      if (a == motion(offsetof(motion_soc_regs_t, cmd_push))) pushes.push_back(staged);
    }
  ASSERT_EQ(pushes.size(), 2u);
  auto delta = [&](const std::map<uint32_t, uint32_t>& m, int a) {
    return static_cast<int32_t>(m.at(motion(offsetof(motion_soc_regs_t, cmd_delta0) + 4 * a)));
  };
  auto at = [&](const std::map<uint32_t, uint32_t>& m) {
    const uint32_t lo = motion(offsetof(motion_soc_regs_t, cmd_at));
    return uint64_t{m.at(lo + 4)} << 32 | m.at(lo);
  };
  EXPECT_EQ(delta(pushes[0], 0), 4);
  EXPECT_EQ(delta(pushes[0], 2), 1);
  EXPECT_EQ(delta(pushes[1], 0), 6);
  EXPECT_EQ(delta(pushes[1], 1), -4);
  EXPECT_EQ(pushes[0].at(motion(offsetof(motion_soc_regs_t, cmd_flags))),
            1u << MOTION_SOC_REGS__CMD_FLAGS__TIMED_bp);
  // Period 1 at host 1 ms: board 50000 + 1000 clocks + 5000 of latency.
  EXPECT_EQ(at(pushes[0]), 56000u);
  // Two periods later, two periods on, within the slew of 15 clocks a period.
  EXPECT_NEAR(static_cast<double>(at(pushes[1])), 58000.0, 2 * 15);
  EXPECT_EQ(s.stats.commands, 2u);
  EXPECT_EQ(s.stats.commands_taken, 2u);
}

// The window: a packet lost makes the guard refuse the next ones; the
// servo sends them all again, in order, and every command is pushed once.
TEST(HalServo, ALostPacketIsSentAgainWithTheOnesAfterIt) {
  hwi_servo_t s;
  start_one_axis(&s);
  Sent out;
  GuardedBoard board;
  int64_t host = 0;
  for (int k = 1; k <= 20; ++k) {
    host += 1000000;
    const int64_t p[1] = {k};
    const size_t before = out.packets.size();
    ASSERT_GE(hwi_servo_period(&s, host, p, Sent::send, &out), 1) << k;
    for (size_t i = before; i < out.packets.size(); ++i) {
      if (k == 3 && i == before) continue;  // the period-3 packet is lost
      const std::vector<uint8_t> r = board.answer(out.packets[i]);
      hwi_servo_reply(&s, r.data(), r.size(), host + 100000);
    }
  }
  // The board pushed 20 lines of +1, each once, in order.
  int pushes = 0;
  for (const Decoded& d : board.taken)
    for (auto [a, v] : d.writes)
      if (a == motion(offsetof(motion_soc_regs_t, cmd_push))) ++pushes;
  EXPECT_EQ(pushes, 20);
  EXPECT_GT(s.stats.retransmits, 0u);
  EXPECT_EQ(s.stats.commands_taken, 20u);
  EXPECT_EQ(s.state, HWI_RUN);
}

// A link slower than the retry measured at load (replies nine periods
// late, the retry 4, the latency 20 periods): the first packets are sent
// again, then the retry follows the round trips measured (smoothed, plus
// four deviations; at most half the latency) and no copy is sent; every
// command is pushed once.
TEST(HalServo, TheRetryFollowsTheRoundTripsAsTheyCome) {
  hwi_servo_t s;
  hwi_config_t c = config(1);
  c.boundary_lead_ns = 20 * c.period_ns;
  c.dead_periods = 100;
  const hwi_board_id_t id = board_id();
  const int64_t origin[1] = {0};
  hwi_servo_start(&s, &c, &id, 3, 0, origin, 0, 0);
  Sent out;
  GuardedBoard board;
  std::vector<std::pair<int, size_t>> due;  // period, packet
  uint64_t retransmits_at_100 = 0;
  for (int k = 1; k <= 300; ++k) {
    for (auto it = due.begin(); it != due.end();) {
      if (it->first != k) {
        ++it;
        continue;
      }
      const std::vector<uint8_t> r = board.answer(out.packets[it->second]);
      hwi_servo_reply(&s, r.data(), r.size(), k * 1000000LL);
      it = due.erase(it);
    }
    const int64_t p[1] = {k};
    const size_t before = out.packets.size();
    ASSERT_GE(hwi_servo_period(&s, k * 1000000LL, p, Sent::send, &out), 0) << k;
    for (size_t i = before; i < out.packets.size(); ++i) due.push_back({k + 9, i});
    if (k == 100) retransmits_at_100 = s.stats.retransmits;
  }
  EXPECT_GT(s.stats.retransmits, 0u);  // before the first round trip was known
  EXPECT_LE(s.stats.retransmits, 8u);
  EXPECT_EQ(s.stats.retransmits, retransmits_at_100);  // none after
  EXPECT_EQ(s.stats.retry_periods, 10u);               // half the latency
  EXPECT_GE(s.stats.commands_taken, 290u);
  int pushes = 0;
  for (const Decoded& d : board.taken)
    for (auto [a, v] : d.writes)
      if (a == motion(offsetof(motion_soc_regs_t, cmd_push))) ++pushes;
  EXPECT_EQ(pushes, static_cast<int>(s.stats.commands_taken));
  EXPECT_EQ(s.state, HWI_RUN);
}

// A reply that comes late, after a later one moved EXPECT on (a packet
// refused, its reply delayed past the retry that got its predecessor
// through), is old news: dropped, the link stays up.
TEST(HalServo, AReplyBehindTheGuardsExpectIsDroppedNotTheLink) {
  hwi_servo_t s;
  start_one_axis(&s);
  Sent out;
  GuardedBoard board;
  const int64_t p1[1] = {1}, p2[1] = {2};
  ASSERT_EQ(hwi_servo_period(&s, 1000000, p1, Sent::send, &out), 1);  // SEQ 0: lost
  ASSERT_EQ(hwi_servo_period(&s, 2000000, p2, Sent::send, &out), 1);  // SEQ 1
  const std::vector<uint8_t> refused = board.answer(out.packets[1]);  // EXPECT 0: held back
  int k = 3;
  while (s.stats.retransmits == 0 && k < 20) {  // the timeout sends SEQ 0 again
    const int64_t p[1] = {2};
    hwi_servo_period(&s, k++ * 1000000LL, p, Sent::send, &out);
  }
  ASSERT_EQ(s.stats.retransmits, 1u);
  size_t again = 2;  // SEQ 0 sent again
  while (decode(out.packets[again].data(), out.packets[again].size()).seq != 0) ++again;
  const std::vector<uint8_t> r0 = board.answer(out.packets[again]);  // taken: EXPECT 1
  ASSERT_EQ(hwi_servo_reply(&s, r0.data(), r0.size(), k * 1000000LL), 1);
  ASSERT_EQ(s.expect, 1u);
  const uint32_t waiting = s.in_flight;  // SEQ 1 and the later ones
  ASSERT_GE(waiting, 1u);
  EXPECT_EQ(hwi_servo_reply(&s, refused.data(), refused.size(), k * 1000000LL), 0);
  EXPECT_EQ(s.state, HWI_RUN);
  EXPECT_EQ(s.in_flight, waiting);
}

// No reply at all: the link is down after dead_periods, and no more
// commands are made.
TEST(HalServo, TheLinkIsDownAfterDeadPeriodsWithoutAReply) {
  hwi_servo_t s;
  start_one_axis(&s);
  Sent out;
  int k = 1;
  for (; k < 100 && s.state == HWI_RUN; ++k) {
    const int64_t p[1] = {k};
    hwi_servo_period(&s, k * 1000000, p, Sent::send, &out);
  }
  EXPECT_EQ(s.state, HWI_DOWN);
  EXPECT_LE(k, static_cast<int>(s.cfg.dead_periods) + 2);
  const int64_t p[1] = {1000};
  EXPECT_EQ(hwi_servo_period(&s, k * 1000000, p, Sent::send, &out), -1);
}

// A snapshot armed at a boundary and read back equal to the point held
// there is a check without error; one step off is an error of one step.
TEST(HalServo, TheSnapshotChecksTheFollowingErrorAtItsBoundary) {
  for (int64_t off : {0, 1}) {
    hwi_servo_t s;
    start_one_axis(&s);
    Sent out;
    GuardedBoard board;
    const uint32_t snap_at = motion(offsetof(motion_soc_regs_t, snap_at));
    int64_t host = 0;
    for (int k = 1; k <= 12 && s.stats.boundary_checks == 0; ++k) {
      host += 1000000;
      const int64_t p[1] = {10 * k};
      const size_t before = out.packets.size();
      hwi_servo_period(&s, host, p, Sent::send, &out);
      for (size_t i = before; i < out.packets.size(); ++i) {
        // The board: TIME is the host's time; a snapshot armed fires at
        // once with the position the servo expects there (plus `off`).
        board.regs[motion(offsetof(motion_soc_regs_t, time_lo))] =
            static_cast<uint32_t>(host / 1000);
        const Decoded d = decode(out.packets[i].data(), out.packets[i].size());
        for (auto [a, v] : d.writes)
          if (a == snap_at) {
            board.regs[motion(offsetof(motion_soc_regs_t, events))] =
                1u << MOTION_SOC_REGS__EVENTS__SNAP_bp;
            board.regs[motion(offsetof(motion_soc_regs_t, snap_time))] = v;
            const int64_t held = s.snap_boundary.hold[0] + off;
            board.regs[motion(offsetof(motion_soc_regs_t, snap_pos0))] =
                static_cast<uint32_t>(held);
            board.regs[motion(offsetof(motion_soc_regs_t, snap_pos0)) + 4] =
                static_cast<uint32_t>(static_cast<uint64_t>(held) >> 32);
          }
        const std::vector<uint8_t> r = board.answer(out.packets[i]);
        // The reads ran after the arm: the board of this test fires at once.
        hwi_servo_reply(&s, r.data(), r.size(), host + 100000);
      }
    }
    EXPECT_EQ(s.stats.boundary_checks, 1u) << off;
    EXPECT_EQ(s.stats.boundary_errors, off ? 1u : 0u);
    EXPECT_EQ(s.stats.max_ferror, off);
  }
}

}  // namespace

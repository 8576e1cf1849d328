// The LinuxCNC driver's UART link without a board (sw/hal/hwinterp_link.h):
// the SLIP + CRC-32 framing of docs/link.md, the serial device opened from
// a URI (a pseudo terminal here), and what a UART asks of the servo: one
// packet unanswered, the commands of the periods its exchange takes
// together in the next packet, retries that wait for the wire.
// tests/board/test_hal_servo.py runs the same code against the simulated
// Tang Nano's UART bridge.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

extern "C" {
#include "../../sw/board_regs.h"
#include "hwinterp_link.h"
}
#include "servo_fixture.h"

namespace {

using namespace hal_test;

// A packet of `n` bytes holding both of SLIP's special bytes.
Bytes packet(size_t n) {
  Bytes p(n);
  for (size_t i = 0; i < n; ++i) p[i] = static_cast<uint8_t>(i * 37 + 1);
  p[3] = 0xC0;
  p[7] = 0xDB;
  p[n - 1] = 0xC0;
  return p;
}

Bytes frame(const Bytes& p) {
  Bytes f(2 * p.size() + 10);
  f.resize(hwi_slip_frame(f.data(), f.size(), p.data(), p.size()));
  return f;
}

// The packets a byte stream closes, in order.
std::vector<Bytes> deframe(hwi_deframer_t* d, const Bytes& wire) {
  std::vector<Bytes> out;
  for (uint8_t b : wire) {
    const size_t n = hwi_deframe(d, b);
    if (n) out.emplace_back(d->buf, d->buf + n);
  }
  return out;
}

TEST(HalLink, Crc32IsIeee8023) {
  const char* check = "123456789";
  EXPECT_EQ(hwi_crc32(reinterpret_cast<const uint8_t*>(check), 9), 0xCBF43926u);
  EXPECT_EQ(hwi_crc32(nullptr, 0), 0u);
}

// END, the escaped packet and CRC (least significant byte first), END; the
// deframer gives the packet back at the closing END only.
TEST(HalLink, AFrameEscapesAndComesBackWhole) {
  const Bytes p = packet(40);
  const Bytes f = frame(p);
  ASSERT_GE(f.size(), p.size() + 6 + 2);  // two escapes at least
  EXPECT_EQ(f.front(), 0xC0);
  EXPECT_EQ(f.back(), 0xC0);
  for (size_t i = 1; i + 1 < f.size(); ++i) EXPECT_NE(f[i], 0xC0) << i;
  // The CRC, unescaped, closes the body.
  Bytes body;
  for (size_t i = 1; i + 1 < f.size(); ++i)
    body.push_back(f[i] == 0xDB ? (f[++i] == 0xDC ? 0xC0 : 0xDB) : f[i]);
  ASSERT_EQ(body.size(), p.size() + 4);
  EXPECT_TRUE(std::equal(p.begin(), p.end(), body.begin()));
  const uint32_t crc = hwi_crc32(p.data(), p.size());
  for (int k = 0; k < 4; ++k) EXPECT_EQ(body[p.size() + k], static_cast<uint8_t>(crc >> 8 * k));

  hwi_deframer_t d{};
  Bytes wire = f;
  wire.insert(wire.end(), f.begin(), f.end());  // two frames back to back
  const std::vector<Bytes> got = deframe(&d, wire);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0], p);
  EXPECT_EQ(got[1], p);
  EXPECT_EQ(d.frames, 2u);
  EXPECT_EQ(d.bad_crc + d.bad_escape + d.too_short + d.too_long_frames, 0u);
}

// Each kind of bad frame is dropped and counted; the good frame after it
// still comes through; an empty frame is nothing.
TEST(HalLink, BadFramesAreDroppedAndCounted) {
  const Bytes p = packet(20), good = frame(p);
  Bytes corrupt = good;
  corrupt[12] ^= 0x10;  // a plain byte of the packet
  const Bytes bad_escape = {0xC0, 0x01, 0xDB, 0x00, 0x02, 0xC0};
  Bytes short_frame = frame(Bytes(11, 0x55));  // 11 bytes: less than a record header
  Bytes long_frame = {0xC0};
  long_frame.insert(long_frame.end(), HWI_MAX_FRAME + 1, 0x11);
  long_frame.push_back(0xC0);
  const Bytes empty = {0xC0, 0xC0, 0xC0};
  struct Case {
    const char* what;
    Bytes wire;
    uint64_t hwi_deframer_t::*count;
  } cases[] = {{"crc", corrupt, &hwi_deframer_t::bad_crc},
               {"escape", bad_escape, &hwi_deframer_t::bad_escape},
               {"short", short_frame, &hwi_deframer_t::too_short},
               {"long", long_frame, &hwi_deframer_t::too_long_frames}};
  for (const Case& c : cases) {
    hwi_deframer_t d{};
    Bytes wire = c.wire;
    wire.insert(wire.end(), empty.begin(), empty.end());
    wire.insert(wire.end(), good.begin(), good.end());
    const std::vector<Bytes> got = deframe(&d, wire);
    EXPECT_EQ(d.*c.count, 1u) << c.what;
    ASSERT_EQ(got.size(), 1u) << c.what;
    EXPECT_EQ(got[0], p) << c.what;
    EXPECT_EQ(d.frames, 1u) << c.what;
    EXPECT_EQ(d.bad_crc + d.bad_escape + d.too_short + d.too_long_frames, 1u) << c.what;
  }
}

// A pseudo terminal as the board's serial port: what the link sends is
// the frame; what the board sends (after noise) comes back as the packet.
TEST(HalLink, ASerialLinkFramesWhatItSendsAndReceives) {
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(grantpt(master), 0);
  ASSERT_EQ(unlockpt(master), 0);
  const std::string dev = ptsname(master);
  hwi_link_t l;
  char err[256];
  ASSERT_EQ(hwi_link_open(&l, ("serial:" + dev + "@250000").c_str(), err, sizeof err), 0) << err;
  EXPECT_EQ(l.serial, 1);
  EXPECT_EQ(l.baud, 250000u);
  EXPECT_EQ(std::string(l.name), "serial:" + dev + "@250000");

  const Bytes p = packet(30);
  ASSERT_EQ(hwi_link_send(&l, p.data(), p.size()), 0);
  Bytes seen(256);
  pollfd q{master, POLLIN, 0};
  ASSERT_EQ(poll(&q, 1, 1000), 1);
  seen.resize(static_cast<size_t>(read(master, seen.data(), seen.size())));
  EXPECT_EQ(seen, frame(p));

  Bytes answer = {0x00, 0xFF, 0xC0};  // noise, then an END
  const Bytes r = packet(24), fr = frame(r);
  answer.insert(answer.end(), fr.begin(), fr.end());
  ASSERT_EQ(write(master, answer.data(), answer.size()), static_cast<ssize_t>(answer.size()));
  Bytes got(HWI_MAX_PACKET);
  const int n = hwi_link_recv(&l, got.data(), got.size(), 1000000);
  ASSERT_EQ(n, static_cast<int>(r.size()));
  got.resize(static_cast<size_t>(n));
  EXPECT_EQ(got, r);
  EXPECT_EQ(l.deframer.too_short, 1u);                            // the noise before the END
  EXPECT_EQ(hwi_link_recv(&l, got.data(), got.size(), 1000), 0);  // nothing more
  // A byte at 250 kbaud is 40 us: 100 bytes and a frame's 6 are 4.24 ms.
  EXPECT_EQ(hwi_link_wire_ns(&l, 100), 4240000u);
  hwi_config_t cfg{};
  hwi_link_configure(&l, &cfg);
  EXPECT_EQ(cfg.window, 1u);
  EXPECT_DOUBLE_EQ(cfg.byte_ns, 40000.0);
  EXPECT_EQ(cfg.max_commands, static_cast<uint32_t>(HWI_UART_COMMANDS));
  hwi_link_close(&l);
  close(master);
}

// Bad URIs name themselves and what is wrong.
TEST(HalLink, BadUrisAreRefusedByName) {
  struct Case {
    const char* uri;
    const char* says;
  } cases[] = {{"tcp:1.2.3.4", "no scheme"},
               {"udp:", "no host"},
               {"udp:1.2.3.4:70000", "port '70000'"},
               {"udp:board.local:1234", "'board.local' is not an IPv4 address"},
               {"serial:", "no device"},
               {"serial:/dev/null@fast", "baud rate 'fast'"},
               {"serial:/dev/null", "not a serial device"},
               {"serial:/nonexistent/tty@115200", "No such file"}};
  for (const Case& c : cases) {
    hwi_link_t l;
    char err[256] = "";
    EXPECT_EQ(hwi_link_open(&l, c.uri, err, sizeof err), -1) << c.uri;
    EXPECT_NE(std::strstr(err, c.uri), nullptr) << err;
    EXPECT_NE(std::strstr(err, c.says), nullptr) << err;
  }
  hwi_link_t l;
  char err[256];
  ASSERT_EQ(hwi_link_open(&l, "udp:127.0.0.1", err, sizeof err), 0) << err;
  EXPECT_EQ(std::string(l.name), "udp:127.0.0.1:1234");  // the default port
  EXPECT_EQ(hwi_link_wire_ns(&l, 100), 0u);
  hwi_config_t cfg{};
  hwi_link_configure(&l, &cfg);
  EXPECT_EQ(cfg.window, 0u);
  EXPECT_EQ(cfg.max_commands, 0u);
  hwi_link_close(&l);
}

// --- the servo on a UART ---------------------------------------------------------

hwi_config_t uart_config(uint32_t axes) {
  hwi_config_t c{};
  c.axes = axes;
  c.period_ns = 1000000;
  c.boundary_lead_ns = 10000000;
  c.step_len_ns = c.step_space_ns = 2000;
  c.dir_setup_ns = c.dir_hold_ns = 3000;
  c.watchdog_period_ns = 20000000;
  c.retry_periods = 4;
  c.dead_periods = 100;
  c.window = 1;
  c.byte_ns = 10000;  // 1 Mbaud
  return c;
}

void start(hwi_servo_t* s, const hwi_config_t& c) {
  hwi_board_id_t id{};
  id.magic = MOTION_SOC_REGS__ID_MAGIC__MAGIC_reset;
  id.major = MOTION_SOC_REGS__ID_VERSION__MAJOR_reset;
  id.axes = 4;
  id.fifo_depth = 64;
  id.feed_w = 24;
  id.clock_hz = 1000000;
  const int64_t origin[HWI_MAX_AXES] = {0};
  hwi_servo_start(s, &c, &id, 5, 0, origin, 0, 0);
}

// One packet unanswered: a period whose packet is not answered yet keeps
// its command, and the next packet carries every command waiting; each is
// pushed once, in order. The packets and replies are the sizes
// hwi_period_packet_bytes and hwi_period_reply_bytes say (the wire's
// budget is computed from them).
TEST(HalLink, OnAUartOnePacketIsUnansweredAndTheNextCarriesTheCommandsWaiting) {
  hwi_servo_t s;
  start(&s, uart_config(4));
  Sent out;
  GuardedBoard board;
  board.fires = true;
  // The board answers each packet two periods after it was sent.
  std::vector<std::pair<int, size_t>> due;  // period, packet
  int64_t want = 0;
  size_t replies_plain = 0, replies_snap = 0;
  const int periods = 60;
  for (int k = 1; k <= periods; ++k) {
    const int64_t host = k * 1000000LL;
    for (auto it = due.begin(); it != due.end();)
      if (it->first == k) {
        board.regs[motion(offsetof(motion_soc_regs_t, time_lo))] =
            static_cast<uint32_t>(host / 1000);
        const Bytes r = board.answer(out.packets[it->second]);
        if (r.size() == hwi_period_reply_bytes(0)) ++replies_plain;
        if (r.size() == hwi_period_reply_bytes(4)) ++replies_snap;
        ASSERT_EQ(hwi_servo_reply(&s, r.data(), r.size(), host), 1) << k;
        it = due.erase(it);
      } else {
        ++it;
      }
    const int64_t p[4] = {3 * k, -k, k / 2, 7};
    const size_t before = out.packets.size();
    ASSERT_GE(hwi_servo_period(&s, host, p, Sent::send, &out), 0) << k;
    ASSERT_LE(out.packets.size(), before + 1) << k;
    if (out.packets.size() > before) due.push_back({k + 2, before});
    EXPECT_LE(s.in_flight, 1u);
    want = 3 * k;
  }
  EXPECT_EQ(s.stats.retransmits, 0u);
  EXPECT_GT(s.stats.missed_slots, 10u);
  // Every command pushed once, in order: the X deltas add up to the end.
  int pushes = 0;
  int64_t x = 0;
  size_t two = 0, checked = 0;
  for (const Decoded& d : board.taken) {
    pushes += d.pushes();
    for (auto [a, v] : d.writes)
      if (a == motion(offsetof(motion_soc_regs_t, cmd_delta0))) x += static_cast<int32_t>(v);
    if (d.seq == 0 || d.arms()) continue;  // the settings, a snapshot armed
    ++checked;
    const Bytes& raw = out.packets[d.seq];
    EXPECT_EQ(raw.size(), hwi_period_packet_bytes(4, static_cast<uint32_t>(d.pushes())) +
                              (d.reads.size() - 5) * 4)
        << d.seq;
    two += d.pushes() == 2;
  }
  EXPECT_EQ(pushes, static_cast<int>(s.stats.commands_taken));
  EXPECT_GE(pushes, periods - 4);
  EXPECT_EQ(x, want - 3 * (periods - pushes));  // the commands not taken yet are the last ones
  EXPECT_GT(two, 5u);
  EXPECT_GT(checked, 10u);
  EXPECT_GT(replies_plain, 5u);
  EXPECT_GT(replies_snap, 0u);
  EXPECT_GT(s.stats.boundary_checks + s.stats.boundary_misses, 0u);  // the snapshot read back
}

// A backlog on the UART goes in packets of at most max_commands commands,
// in order, each once.
TEST(HalLink, ABacklogGoesInPacketsOfAtMostMaxCommands) {
  hwi_config_t c = uart_config(2);
  c.max_commands = 3;
  c.retry_periods = 50;  // no retry in this test
  c.dead_periods = 200;
  c.boundary_lead_ns = 100 * c.period_ns;
  hwi_servo_t s;
  start(&s, c);
  Sent out;
  GuardedBoard board;
  int k = 1;
  for (; k <= 10; ++k) {  // the first packet's reply is held back: 9 commands wait
    const int64_t p[2] = {k, 0};
    hwi_servo_period(&s, k * 1000000LL, p, Sent::send, &out);
  }
  ASSERT_EQ(out.packets.size(), 1u);
  for (; k <= 20; ++k) {  // then every packet is answered in the next period
    const Bytes r = board.answer(out.packets.back());
    ASSERT_EQ(hwi_servo_reply(&s, r.data(), r.size(), k * 1000000LL), 1) << k;
    const int64_t p[2] = {k, 0};
    ASSERT_EQ(hwi_servo_period(&s, k * 1000000LL, p, Sent::send, &out), 1) << k;
  }
  std::vector<int> per_packet;
  int64_t x = 0;
  for (const Decoded& d : board.taken) {
    per_packet.push_back(d.pushes());
    for (auto [a, v] : d.writes)
      if (a == motion(offsetof(motion_soc_regs_t, cmd_delta0))) x += static_cast<int32_t>(v);
  }
  // 1; then 3 a packet while the backlog of 10 drains (a period's command
  // joining it each time), then 1 a period. The last packet (period 20) is
  // not answered yet.
  EXPECT_EQ(per_packet, (std::vector<int>{1, 3, 3, 3, 3, 2, 1, 1, 1, 1}));
  EXPECT_EQ(x, 19);  // every command once: the X lattice went 0 .. 19 in steps of 1
}

// A packet not answered is sent again after retry_periods and its and its
// reply's bytes on the wire: at 1 Mbaud the first packet (its settings
// too) and reply take more than a period.
TEST(HalLink, ARetryWaitsForThePacketsTimeOnTheWire) {
  for (double byte_ns : {0.0, 10000.0}) {
    hwi_config_t c = uart_config(3);
    c.byte_ns = byte_ns;
    hwi_servo_t s;
    start(&s, c);
    Sent out;
    int first_retry = 0;
    for (int k = 1; k <= 20 && !first_retry; ++k) {
      const int64_t p[3] = {k, 0, 0};
      hwi_servo_period(&s, k * 1000000LL, p, Sent::send, &out);
      if (s.stats.retransmits) first_retry = k;
    }
    const Decoded d = decode(out.packets[0]);
    const double wire = static_cast<double>(out.packets[0].size() + 16 + 4 * d.reads.size() + 12) *
                        byte_ns / 1e6;  // ms
    ASSERT_EQ(out.packets.size(), 2u);  // the first, and its copy
    EXPECT_EQ(out.packets[1].size(), out.packets[0].size());
    // Sent in period 1; again at age retry + the wire's periods.
    EXPECT_EQ(first_retry, 1 + 4 + static_cast<int>(std::ceil(wire))) << byte_ns;
    if (byte_ns > 0) {
      EXPECT_GT(wire, 1.0);
    }
  }
}

}  // namespace

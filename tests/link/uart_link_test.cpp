// rtl/link/uart_etherbone.sv chained to rtl/link/link_guard.sv and a
// Wishbone memory model (bridge master -> guard -> memory), driven by a C++
// host over the UART line bit by bit (8N1 at the configured 16 clocks a
// bit, and 3 % fast and slow): Etherbone packets in SLIP frames with their
// CRC-32 (tests/link/link_sim.h), the replies received from tx_o, decoded
// and checked (CRC, format, the words read). Seeded, the seed printed.
//   - probes, plain writes and reads, bus errors (a read answers
//     0xFFFFFFFF), the largest frame the buffer holds;
//   - guarded packets (SEQ and a stream through the guard): taken once;
//     the same packet sent again is refused by the guard (no write runs
//     twice) while its reads still answer (EXPECT = n + 1);
//   - faults on the line: a bit flipped, a character dropped or repeated,
//     an END lost (two frames run together), garbage between frames, a
//     truncated frame, an oversize frame, a framing error, a bad escape, a
//     packet of the wrong format or length with a right CRC: each runs
//     nothing (no write, no reply, frames_run unchanged, frames_bad up) and
//     the next good frame runs normally.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <random>

#include "Vlink_guard.h"
#include "Vuart_etherbone.h"
#include "link_sim.h"
#include "verilated.h"

namespace hwinterp::link_test {
namespace {

constexpr int kDiv = HWINTERP_LINK_CLK_HZ / HWINTERP_LINK_BAUD;  // clocks a bit
static_assert(HWINTERP_LINK_CLK_HZ % HWINTERP_LINK_BAUD == 0, "the test's bit time is whole");
constexpr uint32_t kWinByte = HWINTERP_LINK_WIN_BASE * 4u;  // the guard's window, byte address
constexpr uint32_t kExpectAt = kWinByte, kStaleAt = kWinByte + 0x404;
constexpr size_t kBuf = HWINTERP_LINK_BUF_BYTES;

class Chain {
 public:
  explicit Chain(uint64_t seed, double period = kDiv)
      : mem(seed, static_cast<int>(seed % 3)), drv(period), rcv(kDiv) {
    ctx_.randSeed(static_cast<int>(seed & 0x7FFFFFFF));
    br_ = std::make_unique<Vuart_etherbone>(&ctx_);
    g_ = std::make_unique<Vlink_guard>(&ctx_);
    br_->rst_ni = g_->rst_ni = 0;
    br_->rx_i = 1;
    for (int e : {0, 1, 0}) {
      br_->clk_i = g_->clk_i = e;
      br_->eval();
      g_->eval();
    }
    br_->rst_ni = g_->rst_ni = 1;
    br_->eval();
    g_->eval();
    // Word addresses whose low byte is 0xEE answer err.
    mem.err_at = [](uint32_t adr) { return (adr & 0xFF) == 0xEE; };
  }
  ~Chain() {
    br_->final();
    g_->final();
  }

  void clock() {
    Vuart_etherbone& b = *br_;
    Vlink_guard& g = *g_;
    b.rx_i = drv.step();
    b.eval();
    // The bridge's request (registers) into the guard, the memory's answer back.
    g.s_cyc_i = b.m_cyc_o;
    g.s_stb_i = b.m_stb_o;
    g.s_we_i = b.m_we_o;
    g.s_adr_i = b.m_adr_o;
    g.s_dat_i = b.m_dat_o;
    g.s_sel_i = b.m_sel_o;
    g.eval();
    WbMemory::Answer a = mem.comb(g.m_cyc_o, g.m_stb_o, g.m_we_o, g.m_adr_o, g.m_dat_o, g.m_sel_o);
    g.m_ack_i = a.ack;
    g.m_err_i = a.err;
    g.m_dat_i = a.dat;
    g.eval();
    b.m_ack_i = g.s_ack_o;
    b.m_err_i = g.s_err_o;
    b.m_dat_i = g.s_dat_o;
    // The bridge's Wishbone rules: stb with cyc, a request held until answered.
    bool req = b.m_cyc_o && b.m_stb_o, answer = g.s_ack_o || g.s_err_o;
    if (b.m_stb_o != b.m_cyc_o) ++master_faults;
    if (pending_ && !(req && b.m_we_o == p_we_ && b.m_adr_o == p_adr_ && b.m_dat_o == p_dat_ &&
                      b.m_sel_o == p_sel_))
      ++master_faults;
    if (req && !b.busy_o) ++master_faults;
    pending_ = req && !answer;
    p_we_ = b.m_we_o;
    p_adr_ = b.m_adr_o;
    p_dat_ = b.m_dat_o;
    p_sel_ = b.m_sel_o;
    b.clk_i = g.clk_i = 1;
    b.eval();
    g.eval();
    mem.edge();
    b.clk_i = g.clk_i = 0;
    b.eval();
    g.eval();
    rcv.step(b.tx_o);
    while (fed_ < rcv.bytes.size()) dec.put(rcv.bytes[fed_++]);
    quiet_ = b.tx_o ? quiet_ + 1 : 0;
    sent_ = drv.idle() ? sent_ + 1 : 0;
    ++clocks;
  }

  // Sends `bytes`, then runs until they have been sent for 2 character times
  // (the bridge has seen the last one), the bridge is idle and its line has
  // been quiet for 12 character times.
  void send(const std::vector<uint8_t>& bytes) {
    drv.send(bytes);
    settle();
  }
  void settle() {
    sent_ = 0;
    for (uint64_t n = 0; !(sent_ > 2 * 10 * kDiv && !br_->busy_o && quiet_ > 12 * 10 * kDiv); ++n) {
      if (n > 50'000'000) {
        ADD_FAILURE() << "the bridge did not settle";
        return;
      }
      clock();
    }
  }

  unsigned frames_run() const { return br_->frames_run_o; }
  unsigned frames_bad() const { return br_->frames_bad_o; }
  unsigned bus_errors() const { return br_->bus_errors_o; }

  WbMemory mem;
  UartDriver drv;
  UartReceiver rcv;
  SlipDecoder dec;
  uint64_t clocks = 0;
  int master_faults = 0;

 private:
  VerilatedContext ctx_;
  std::unique_ptr<Vuart_etherbone> br_;
  std::unique_ptr<Vlink_guard> g_;
  size_t fed_ = 0;
  uint64_t quiet_ = 0, sent_ = 0;
  bool pending_ = false, p_we_ = false;
  uint32_t p_adr_ = 0, p_dat_ = 0;
  uint8_t p_sel_ = 0;
};

// A reply frame: CRC right, the record's header as docs/link.md states it;
// returns the words read.
std::vector<uint32_t> parse_reply(const std::vector<uint8_t>& f, const Record& asked) {
  std::vector<uint32_t> words;
  EXPECT_GE(f.size(), 20u);
  if (f.size() < 20) return words;
  std::vector<uint8_t> p(f.begin(), f.end() - 4);
  uint32_t c = uint32_t(f[f.size() - 4]) | uint32_t(f[f.size() - 3]) << 8 |
               uint32_t(f[f.size() - 2]) << 16 | uint32_t(f[f.size() - 1]) << 24;
  EXPECT_EQ(c, crc32(p)) << "reply CRC";
  std::vector<uint8_t> head = {
      0x4E, 0x6F, 0x10, 0x44, 0, 0, 0, 0, 0, asked.be, static_cast<uint8_t>(asked.reads.size()), 0};
  EXPECT_TRUE(std::equal(head.begin(), head.end(), p.begin())) << "reply header";
  EXPECT_EQ(p.size(), 16 + 4 * asked.reads.size());
  EXPECT_EQ(get32(p, 12), asked.rbase) << "the reply goes to the base return address asked";
  for (size_t at = 16; at + 4 <= p.size(); at += 4) words.push_back(get32(p, at));
  return words;
}

// The host side: guarded packets, the memory as the test expects it, the
// counters as they must be.
struct Host {
  std::mt19937_64 rng;
  Chain chain;
  std::vector<WbMemory::Write> expected;  // writes the memory must have logged
  uint32_t seq = 0;                       // the guard's EXPECT
  uint32_t stale = 0;
  unsigned run = 0, bad = 0, berr = 0;  // frames_run, frames_bad, bus_errors as they must be
  uint32_t tag = 0;

  explicit Host(uint64_t seed) : rng(seed), chain(seed) {}
  unsigned pick(unsigned lo, unsigned hi) {
    return std::uniform_int_distribution<unsigned>(lo, hi)(rng);
  }
  uint32_t word() { return static_cast<uint32_t>(rng()); }

  // A guarded packet with sequence number n: SEQ, 1-3 chunks of 1-6 words to
  // word addresses 0x10000.., then reads of EXPECT, STALE and a written word.
  struct Guarded {
    Record rec;
    std::vector<WbMemory::Write> writes;  // what it writes if taken
  };
  Guarded guarded(uint32_t n) {
    Guarded g;
    g.rec.wbase = kWinByte;
    g.rec.writes.push_back(n);
    unsigned chunks = pick(1, 3);
    for (unsigned c = 0; c < chunks; ++c) {
      unsigned count = pick(1, 6);
      uint32_t base = 0x10000 + pick(0, 0x3FF);
      if ((base & 0xFF) + count > 0xED && (base & 0xFF) <= 0xEE) base -= 0x20;  // no error words
      g.rec.writes.push_back(count << 24 | base);
      for (unsigned i = 0; i < count; ++i) {
        uint32_t d = word();
        g.rec.writes.push_back(d);
        g.writes.push_back({base + i, d, 0xF});
      }
    }
    g.rec.rbase = 0xA0000000u | ++tag;
    g.rec.reads = {kExpectAt, kStaleAt, g.writes.back().adr * 4};
    return g;
  }

  // Sends a frame expected to run and reply; checks the reply's words.
  std::vector<uint32_t> exchange(const std::vector<uint8_t>& frame, const Record& rec) {
    size_t before = chain.dec.frames.size();
    chain.send(frame);
    ++run;
    EXPECT_EQ(chain.dec.frames.size(), before + 1) << "one reply";
    if (chain.dec.frames.size() != before + 1) return {};
    return parse_reply(chain.dec.frames.back(), rec);
  }

  // A guarded packet the guard must take (seq is its EXPECT).
  void take(const Guarded& g, const std::vector<uint8_t>& frame) {
    std::vector<uint32_t> w = exchange(frame, g.rec);
    for (const auto& x : g.writes) expected.push_back(x);
    ++seq;
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[0], seq) << "EXPECT after a taken packet";
    EXPECT_EQ(w[1], stale);
    EXPECT_EQ(w[2], g.writes.back().dat);
    check();
  }
  // The same packet again: refused, its reads answer.
  void refuse(const Guarded& g, const std::vector<uint8_t>& frame) {
    std::vector<uint32_t> w = exchange(frame, g.rec);
    ++stale;
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[0], seq) << "EXPECT after a refused copy";
    EXPECT_EQ(w[1], stale);
    check();
  }
  // A frame that must run nothing.
  void lost(const std::vector<uint8_t>& chars, const char* what) {
    size_t replies = chain.dec.frames.size();
    unsigned bad0 = chain.frames_bad();
    chain.send(chars);
    EXPECT_EQ(chain.dec.frames.size(), replies) << what << ": no reply";
    EXPECT_EQ(chain.frames_run(), run) << what << ": nothing runs";
    EXPECT_GE(static_cast<uint16_t>(chain.frames_bad() - bad0), 1) << what << ": counted as bad";
    bad = chain.frames_bad();
    check();
  }
  void check() {
    EXPECT_TRUE(chain.mem.writes == expected) << "memory writes: " << chain.mem.writes.size()
                                              << " logged, " << expected.size() << " expected";
    EXPECT_EQ(chain.frames_run(), run);
    EXPECT_EQ(chain.frames_bad(), bad);
    EXPECT_EQ(chain.bus_errors(), berr);
    EXPECT_EQ(chain.master_faults, 0);
    EXPECT_EQ(chain.mem.faults, 0u);
    EXPECT_EQ(chain.rcv.framing_errors, 0);
    EXPECT_EQ(chain.rcv.timing_errors, 0);
    EXPECT_EQ(chain.dec.bad, 0);
  }
};

TEST(UartLink, ProbePlainAccessesBusErrorsAndTheLargestFrame) {
  Host h(11);
  // Probe: the same packet back, pf clear, pr set.
  Record none;
  std::vector<uint8_t> probe = etherbone(none, 0x01);
  probe.insert(probe.end(), {1, 2, 3, 4, 0xC0, 0xDB, 7, 8});  // payload with END and ESC in it
  h.chain.send(slip_frame(probe));
  ++h.run;
  ASSERT_EQ(h.chain.dec.frames.size(), 1u);
  std::vector<uint8_t> back = h.chain.dec.frames[0];
  ASSERT_EQ(back.size(), probe.size() + 4);
  std::vector<uint8_t> want = probe;
  want[2] = 0x12;
  EXPECT_TRUE(std::equal(want.begin(), want.end(), back.begin())) << "probe reply";
  EXPECT_EQ(get32(std::vector<uint8_t>(back.end() - 4, back.end()), 0),
            __builtin_bswap32(crc32(want)));
  h.check();
  // Writes then reads outside the guard, sel 0x3, one write and one read to
  // an error address.
  Record r;
  r.be = 0x03;
  r.wbase = 0x4000;  // word 0x1000
  r.writes = {0x11111111, 0x22222222, 0x33333333};
  r.rbase = 0x12345678;
  r.reads = {0x4000, 0x4004, 0x4008, 0x400C, 0xEE * 4};
  for (int i = 0; i < 3; ++i) h.expected.push_back({0x1000u + i, r.writes[i], 0x3});
  std::vector<uint32_t> w = h.exchange(slip_frame(etherbone(r)), r);
  ++h.berr;
  ASSERT_EQ(w.size(), 5u);
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(w[i], (WbMemory::init(0x1000 + i) & 0xFFFF0000u) | (r.writes[i] & 0xFFFF));
  EXPECT_EQ(w[3], WbMemory::init(0x1003));
  EXPECT_EQ(w[4], 0xFFFFFFFFu) << "a read the bus answers with err";
  h.check();
  Record e;
  e.wbase = 0x1EE * 4;  // an error word, then a good one: both tried
  e.writes = {5, 6};
  h.expected.push_back({0x1EF, 6, 0xF});
  h.chain.send(slip_frame(etherbone(e)));
  ++h.run;
  ++h.berr;
  h.check();
  // The largest frame the buffer holds (packet + CRC = BUF_BYTES), and one
  // word more (dropped).
  Record big;
  big.wbase = 0x80EF * 4;  // 251 words from 0x80EF: none ends in 0xEE
  for (size_t i = 0; 16 + 4 * (i + 1) + 4 <= kBuf; ++i) big.writes.push_back(h.word() | 1);
  std::vector<uint8_t> fb = etherbone(big);
  ASSERT_EQ(fb.size() + 4, kBuf);
  Record bigger = big;
  bigger.writes.push_back(7);
  h.lost(slip_frame(etherbone(bigger)), "oversize frame");
  h.chain.send(slip_frame(fb));
  ++h.run;
  for (size_t i = 0; i < big.writes.size(); ++i)
    h.expected.push_back({0x80EFu + static_cast<uint32_t>(i), big.writes[i], 0xF});
  h.check();
  std::printf("UartLink probe/plain: %llu clocks\n",
              static_cast<unsigned long long>(h.chain.clocks));
}

// Faults on the line, one after another, each followed by the packet it
// spoiled, sent whole (taken, as it never ran), and a retransmitted copy
// (refused).
TEST(UartLink, FaultsRunNothingAndTheNextGoodFrameRuns) {
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::printf("UartLink faults: seed %llu\n", static_cast<unsigned long long>(seed));
    Host h(seed * 1000 + 3);
    for (int round = 0; round < 14; ++round) {
      Host::Guarded g = h.guarded(h.seq);
      std::vector<uint8_t> frame = slip_frame(etherbone(g.rec));
      std::vector<uint8_t> bad = frame;
      // Characters 1 .. size-2 are the frame's body (0 and the last are ENDs).
      size_t at = h.pick(1, static_cast<unsigned>(frame.size() - 2));
      switch (round % 12) {
        case 0:  // a bit flipped
          bad[at] ^= static_cast<uint8_t>(1u << h.pick(0, 7));
          h.lost(bad, "bit flip");
          break;
        case 1:  // a character lost
          bad.erase(bad.begin() + static_cast<long>(at));
          h.lost(bad, "dropped character");
          break;
        case 2:  // a character repeated
          bad.insert(bad.begin() + static_cast<long>(at), bad[at]);
          h.lost(bad, "repeated character");
          break;
        case 3: {  // the END lost: the frame runs into the next one (sent without its leading END)
          bad.pop_back();
          Host::Guarded g2 = h.guarded(h.seq);
          std::vector<uint8_t> next = slip_frame(etherbone(g2.rec), false);
          bad.insert(bad.end(), next.begin(), next.end());
          h.lost(bad, "lost END");
          break;
        }
        case 4: {  // garbage between frames (ENDs in it make several bad frames)
          std::vector<uint8_t> junk = {0x55};
          for (unsigned i = h.pick(1, 40); i > 0; --i)
            junk.push_back(h.pick(0, 3) == 0 ? kEnd : static_cast<uint8_t>(h.word()));
          junk.push_back(kEnd);
          h.lost(junk, "garbage");
          break;
        }
        case 5:  // truncated
          bad.resize(at);
          bad.push_back(kEnd);
          h.lost(bad, "truncated frame");
          break;
        case 6: {  // a framing error on one character, the right byte otherwise (the line
                   // idle for a character after it, so the next ones are received right)
          h.chain.drv.send(
              std::vector<uint8_t>(frame.begin(), frame.begin() + static_cast<long>(at)));
          h.chain.drv.send(frame[at], true);
          h.chain.drv.pause(10 * kDiv);
          h.lost(std::vector<uint8_t>(frame.begin() + static_cast<long>(at) + 1, frame.end()),
                 "framing error");
          break;
        }
        case 7: {  // ESC before an ordinary byte: RFC 1055 would take the byte as it is (and
                   // the CRC would pass); the link's rule drops the frame
          while (bad[at] == kEnd || bad[at] == kEsc || bad[at] == kEscEnd || bad[at] == kEscEsc ||
                 (at > 0 && bad[at - 1] == kEsc))
            at = h.pick(1, static_cast<unsigned>(frame.size() - 2));
          bad.insert(bad.begin() + static_cast<long>(at), kEsc);
          h.lost(bad, "bad escape");
          break;
        }
        case 8: {  // right CRC, wrong format: magic, version, sizes
          std::vector<uint8_t> p = etherbone(g.rec);
          p[h.pick(0, 3)] ^= 0x20;
          h.lost(slip_frame(p), "wrong header");
          break;
        }
        case 9: {  // right CRC, a length the record does not say
          std::vector<uint8_t> p = etherbone(g.rec);
          if (h.pick(0, 1))
            p.push_back(0);
          else
            p.resize(p.size() - 4);
          h.lost(slip_frame(p), "wrong length");
          break;
        }
        case 10: {  // oversize
          Record r = g.rec;
          while (etherbone(r).size() + 4 <= kBuf) r.writes.push_back(0);
          h.lost(slip_frame(etherbone(r)), "oversize frame");
          break;
        }
        default:  // no fault
          break;
      }
      if (::testing::Test::HasFailure()) return;
      h.take(g, frame);
      h.refuse(g, frame);
      if (::testing::Test::HasFailure()) return;
    }
    std::printf("UartLink faults: seed %llu: %llu clocks, %u frames run, %u dropped\n",
                static_cast<unsigned long long>(seed),
                static_cast<unsigned long long>(h.chain.clocks), h.run, h.bad);
  }
}

// The host's bit time 3 % off the bridge's, both ways.
TEST(UartLink, BaudRateOffsetOfThreePercent) {
  for (double f : {0.97, 1.03}) {
    SCOPED_TRACE("bit time x " + std::to_string(f));
    Host h(77);
    h.chain.drv = UartDriver(kDiv * f);
    for (int i = 0; i < 6; ++i) {
      Host::Guarded g = h.guarded(h.seq);
      h.take(g, slip_frame(etherbone(g.rec)));
    }
  }
}

}  // namespace
}  // namespace hwinterp::link_test

namespace hwinterp::link_test {
namespace {

// A frame that arrives while the bridge runs another or sends its reply (a
// host that retransmits too early) is dropped whole and counted; the frame
// running is not disturbed (its buffer is not written: its reply reads
// addresses from it); the same frame sent again later runs.
TEST(UartLink, FrameWhileBusyIsDropped) {
  Host h(5);
  // A reads 40 words that are all END bytes: its reply (every byte escaped,
  // two characters) is slow, so the frame B that follows overtakes the
  // reply's reading of A's buffer: a bridge that stored B would send
  // addresses of B's bytes.
  Host::Guarded a = h.guarded(h.seq);
  for (uint32_t i = 0; i < 40; ++i) {
    h.chain.mem.poke(0x12000 + i, 0xC0C0C0C0u);
    a.rec.reads.push_back((0x12000 + i) * 4);
  }
  Host::Guarded b = h.guarded(h.seq + 1);
  b.rec.writes.push_back(40u << 24 | 0x11000);
  for (uint32_t i = 0; i < 40; ++i) {
    uint32_t d = h.word();
    b.rec.writes.push_back(d);
    b.writes.push_back({0x11000 + i, d, 0xF});
  }
  b.rec.reads[2] = b.writes.back().adr * 4;
  std::vector<uint8_t> fa = slip_frame(etherbone(a.rec)), fb = slip_frame(etherbone(b.rec));
  h.chain.drv.send(fa);
  h.chain.send(fb);  // B's characters arrive while A's reply goes out
  ++h.run;
  ++h.bad;
  ++h.seq;
  for (const auto& x : a.writes) h.expected.push_back(x);
  ASSERT_EQ(h.chain.dec.frames.size(), 1u) << "A's reply only";
  std::vector<uint32_t> w = parse_reply(h.chain.dec.frames[0], a.rec);
  ASSERT_EQ(w.size(), 43u);
  EXPECT_EQ(w[0], h.seq);
  EXPECT_EQ(w[2], a.writes.back().dat);
  for (uint32_t i = 0; i < 40; ++i) EXPECT_EQ(w[3 + i], 0xC0C0C0C0u) << "read " << i;
  h.check();
  h.take(b, fb);
}

}  // namespace
}  // namespace hwinterp::link_test

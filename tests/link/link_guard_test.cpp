// rtl/link/link_guard.sv (the sequence guard, docs/link.md) between a C++
// Wishbone manager and a memory model with random wait states and error
// addresses: seeded random guarded packets (stream chunks, SEQ taken,
// duplicated, late or random), accesses outside the window, forbidden
// window accesses and bus errors, from a manager that holds cyc over a
// record (LiteEth's Etherbone) and one that drops it between accesses. The
// memory's log of writes must be exactly the writes of the taken packets'
// data words (in order, once each, with their sel) and of the accesses
// outside the window; every window read must return the reference model's
// value; the guard must keep the Wishbone rules and pass every access
// outside the window through unchanged, in the same clock.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include "Vlink_guard.h"
#include "link_sim.h"
#include "verilated.h"

namespace hwinterp::link_test {
namespace {

constexpr uint32_t kWin = HWINTERP_LINK_WIN_BASE;  // the window's word address
static_assert(kWin % 512 == 0, "the guard's window is aligned to 512 words");
constexpr unsigned kExpect = 0, kAccepted = 256, kStale = 257, kDropped = 258, kErrors = 259;

// The guard with a manager on its upstream port and WbMemory downstream.
class GuardBench {
 public:
  struct Result {
    bool ack = false, err = false;
    uint32_t dat = 0;
    int clocks = 0;  // from the request's first clock to its answer, inclusive
  };

  GuardBench(uint64_t seed, int max_wait) : mem(seed, max_wait) {
    ctx_.randSeed(static_cast<int>(seed & 0x7FFFFFFF));
    dut_ = std::make_unique<Vlink_guard>(&ctx_);
    dut_->rst_ni = 0;
    dut_->clk_i = 0;
    dut_->eval();
    dut_->clk_i = 1;
    dut_->eval();
    dut_->clk_i = 0;
    dut_->rst_ni = 1;
    dut_->eval();
  }
  ~GuardBench() { dut_->final(); }

  // `gap` idle clocks (cyc high if `hold`), then the request until answered.
  Result access(bool we, uint32_t adr, uint32_t dat, uint8_t sel, bool hold, int gap) {
    for (int i = 0; i < gap; ++i) clock(hold, false, we, adr, dat, sel, nullptr);
    Result r;
    for (r.clocks = 1; r.clocks < 64; ++r.clocks) {
      if (clock(true, true, we, adr, dat, sel, &r)) return r;
    }
    ADD_FAILURE() << "no answer to the access at " << std::hex << adr;
    return r;
  }
  void idle(int n) {
    for (int i = 0; i < n; ++i) clock(false, false, false, 0, 0, 0, nullptr);
  }

  WbMemory mem;
  int rule_faults = 0;  // Wishbone rules or transparency broken (each clock counts)

 private:
  // One clock with these upstream pins; true if the access was answered.
  bool clock(bool cyc, bool stb, bool we, uint32_t adr, uint32_t dat, uint8_t sel, Result* r) {
    Vlink_guard& g = *dut_;
    g.s_cyc_i = cyc;
    g.s_stb_i = stb;
    g.s_we_i = we;
    g.s_adr_i = adr;
    g.s_dat_i = dat;
    g.s_sel_i = sel;
    g.eval();
    WbMemory::Answer a = mem.comb(g.m_cyc_o, g.m_stb_o, g.m_we_o, g.m_adr_o, g.m_dat_o, g.m_sel_o);
    g.m_ack_i = a.ack;
    g.m_err_i = a.err;
    g.m_dat_i = a.dat;
    g.eval();
    bool answered = g.s_ack_o || g.s_err_o;
    if ((g.s_ack_o && g.s_err_o) || (answered && !(cyc && stb)) || (g.m_stb_o && !g.m_cyc_o))
      ++rule_faults;
    bool in_win = adr >= kWin && adr < kWin + 512;
    if (!in_win &&
        (g.m_cyc_o != cyc || g.m_stb_o != (cyc && stb) || g.m_we_o != we || g.m_adr_o != adr ||
         g.m_dat_o != dat || g.m_sel_o != sel || g.s_ack_o != (cyc && stb && a.ack) ||
         g.s_err_o != (cyc && stb && a.err) || (a.ack && g.s_dat_o != a.dat)))
      ++rule_faults;
    if (r) {
      r->ack = g.s_ack_o;
      r->err = g.s_err_o;
      r->dat = g.s_dat_o;
    }
    g.clk_i = 1;
    g.eval();
    mem.edge();
    g.clk_i = 0;
    g.eval();
    return answered;
  }

  VerilatedContext ctx_;
  std::unique_ptr<Vlink_guard> dut_;
};

// The bench, the reference model, and what the memory must have logged.
struct GuardRun {
  std::mt19937_64 rng;
  GuardBench bench;
  GuardModel model;
  std::vector<WbMemory::Write> expected;
  std::map<uint32_t, uint32_t> shadow;  // the memory's words as the expected writes leave them
  bool hold = false;                    // the manager holds cyc between accesses
  int taken = 0, refused = 0;

  explicit GuardRun(uint64_t seed) : rng(seed), bench(seed * 7 + 1, static_cast<int>(seed % 3)) {
    // Word addresses whose low byte is 0xEE answer err.
    bench.mem.err_at = [](uint32_t adr) { return (adr & 0xFF) == 0xEE; };
  }
  unsigned pick(unsigned lo, unsigned hi) {
    return std::uniform_int_distribution<unsigned>(lo, hi)(rng);
  }
  int gap() { return pick(0, 3) == 0 ? static_cast<int>(pick(1, 3)) : 0; }
  void expect_write(uint32_t adr, uint32_t dat, uint8_t sel) {
    expected.push_back({adr, dat, sel});
    auto it = shadow.find(adr);
    uint32_t v = it == shadow.end() ? WbMemory::init(adr) : it->second;
    for (int b = 0; b < 4; ++b)
      if (sel >> b & 1) v = (v & ~(0xFFu << 8 * b)) | (dat & 0xFFu << 8 * b);
    shadow[adr] = v;
  }
  uint32_t shadow_read(uint32_t adr) const {
    auto it = shadow.find(adr);
    return it == shadow.end() ? WbMemory::init(adr) : it->second;
  }

  // A window access, checked against the model.
  void window(bool we, unsigned off, uint32_t dat, uint8_t sel) {
    GuardModel::Kind k = model.kind(we, off);
    GuardBench::Result r = bench.access(we, kWin + off, dat, sel, hold, gap());
    uint32_t target = 0;
    bool bus_err = false;
    if (k == GuardModel::Kind::Forward) {
      // target of the word: the model's before it moves on
      uint32_t t = model.addr;
      bus_err = bench.mem.err_at(t);
      EXPECT_EQ(r.err, bus_err) << "forwarded word to " << std::hex << t;
      EXPECT_EQ(r.ack, !bus_err);
      if (!bus_err) expect_write(t, dat, sel);
    } else if (k == GuardModel::Kind::Err) {
      EXPECT_TRUE(r.err && !r.ack) << (we ? "write" : "read") << " of word " << off;
    } else {
      EXPECT_TRUE(r.ack && !r.err) << (we ? "write" : "read") << " of word " << off;
      EXPECT_EQ(r.clocks, 1) << "the guard answers its own words in the request's clock";
      if (!we) {
        EXPECT_EQ(r.dat, model.read(off)) << "read of word " << off;
      }
    }
    if (we && k != GuardModel::Kind::Err) model.write(off, dat, bus_err, &target);
  }
  // An access outside the window.
  void outside() {
    uint32_t adr;
    do adr = pick(0, (1u << 30) - 1) & (pick(0, 1) ? 0x1FFFFu : 0x3FFFFFFFu);
    while (adr >= kWin && adr < kWin + 512);
    bool we = pick(0, 1);
    uint32_t dat = static_cast<uint32_t>(rng());
    uint8_t sel = static_cast<uint8_t>(pick(1, 15));
    GuardBench::Result r = bench.access(we, adr, dat, sel, hold, gap());
    bool err = bench.mem.err_at(adr);
    EXPECT_EQ(r.err, err);
    EXPECT_EQ(r.ack, !err);
    if (!err && we) expect_write(adr, dat, sel);
    if (!err && !we) {
      EXPECT_EQ(r.dat, shadow_read(adr)) << "read outside at " << std::hex << adr;
    }
  }
  // A forbidden window access (answers err, changes nothing).
  void forbidden() {
    switch (pick(0, 2)) {
      case 0:
        window(false, pick(1, 255), 0, 0xF);
        break;  // read STREAM
      case 1:
        window(true, pick(256, 259), static_cast<uint32_t>(rng()), 0xF);
        break;  // write a counter
      default:
        window(pick(0, 1), pick(260, 511), static_cast<uint32_t>(rng()), 0xF);
        break;
    }
  }

  // A guarded packet: SEQ, then chunks, as one Etherbone record writes them
  // (consecutive words, or any words of 1..255: the guard takes them in
  // arrival order), with stray accesses between its words.
  void packet() {
    uint32_t seq;
    switch (pick(0, 3)) {
      case 0:
      case 1:
        seq = model.expect;
        break;  // the next one
      case 2:
        seq = model.expect - 1 - pick(0, 2);
        break;  // a duplicate or late copy
      default:
        seq = static_cast<uint32_t>(rng());
        break;  // anything
    }
    bool consecutive = pick(0, 3) != 0;
    hold = pick(0, 1);
    (seq == model.expect ? taken : refused)++;
    window(true, 0, seq, 0xF);
    unsigned words = 0, off = 1;
    auto stream = [&](uint32_t w, uint8_t sel) {
      if (pick(0, 15) == 0) forbidden();
      if (pick(0, 15) == 0) outside();
      window(true, consecutive ? off : pick(1, 255), w, sel);
      ++off;
      ++words;
    };
    unsigned chunks = pick(1, 5);
    for (unsigned c = 0; c < chunks; ++c) {
      unsigned count = pick(0, 7) == 0 ? 0 : pick(1, 12);
      if (words + 1 + count > 255) break;
      uint32_t base = pick(0, 7) == 0 ? 0xFFFFFF - pick(0, 3) : 0x10000 + pick(0, 0x7FF);
      stream(count << 24 | base, 0xF);
      unsigned n = count;
      if (pick(0, 9) == 0 && n > 1) n = pick(0, n - 1);  // cut short by the next SEQ
      for (unsigned i = 0; i < n; ++i)
        stream(static_cast<uint32_t>(rng()), static_cast<uint8_t>(pick(1, 15)));
      if (n < count) break;
    }
    hold = false;
    // The reply's reads: EXPECT and the counters.
    for (unsigned o : {kExpect, kAccepted, kStale, kDropped, kErrors}) window(false, o, 0, 0xF);
  }
};

TEST(LinkGuard, RandomPacketsRunOnceInOrderOrNotAtAll) {
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::printf("LinkGuard random packets: seed %llu\n", static_cast<unsigned long long>(seed));
    GuardRun run(seed);
    for (int p = 0; p < 400; ++p) {
      if (run.pick(0, 2) == 0) run.outside();
      run.packet();
      if (::testing::Test::HasFailure()) break;
    }
    std::printf("  %d taken, %d refused, %zu writes, %u dropped, %u bus errors\n", run.taken,
                run.refused, run.expected.size(), run.model.dropped, run.model.errors);
    EXPECT_EQ(run.bench.mem.writes.size(), run.expected.size());
    EXPECT_TRUE(run.bench.mem.writes == run.expected) << "the memory's writes differ";
    EXPECT_EQ(run.bench.mem.faults, 0u);
    EXPECT_EQ(run.bench.rule_faults, 0);
    EXPECT_EQ(run.model.expect, static_cast<uint32_t>(run.taken));
    EXPECT_GT(run.taken, 100);
    EXPECT_GT(run.refused, 100);
    EXPECT_GT(run.model.errors, 0u) << "no forwarded write met a bus error";
    EXPECT_GT(run.model.dropped, 0u);
  }
}

// Directed: the counters and the stream's rules, step by step.
TEST(LinkGuard, StreamRulesAndCounters) {
  GuardRun run(99);
  run.bench.mem.err_at = [](uint32_t adr) { return adr == 0x2222; };
  auto w = [&](unsigned off, uint32_t v, uint8_t sel = 0xF) { run.window(true, off, v, sel); };
  auto rd = [&](unsigned off) { return run.bench.access(false, kWin + off, 0, 0xF, false, 0); };
  // Closed after reset: data words dropped.
  w(1, 2u << 24 | 0x1000);
  w(2, 11);
  w(3, 12);
  EXPECT_EQ(rd(kDropped).dat, 2u);
  EXPECT_EQ(rd(kExpect).dat, 0u);
  // SEQ 0 opens: a chunk of 3 (the second with sel 0x3), a count-0 header
  // (ignored), a chunk of 1 to the error address.
  w(0, 0);
  w(1, 3u << 24 | 0x1000);
  w(2, 0xA0);
  w(3, 0xA1, 0x3);
  w(4, 0xA2);
  w(5, 0u << 24 | 0x5555);
  w(6, 1u << 24 | 0x2222);
  w(7, 0xBAD);
  EXPECT_EQ(rd(kErrors).dat, 1u);
  // A SEQ cuts a chunk short; a stale SEQ closes, a chunk then is dropped.
  w(0, 1);
  w(1, 2u << 24 | 0x3000);
  w(2, 0xC0);
  w(0, 1);  // stale: a duplicate of the last
  w(1, 1u << 24 | 0x3001);
  w(2, 0xC1);
  // Back in step: taken again.
  w(0, 2);
  w(1, 1u << 24 | 0x3001);
  w(2, 0xC2);
  EXPECT_EQ(rd(kExpect).dat, 3u);
  EXPECT_EQ(rd(kAccepted).dat, 3u);
  EXPECT_EQ(rd(kStale).dat, 1u);
  EXPECT_EQ(rd(kDropped).dat, 3u);
  EXPECT_EQ(rd(kErrors).dat, 1u);
  std::vector<WbMemory::Write> want = {{0x1000, 0xA0, 0xF},
                                       {0x1001, 0xA1, 0x3},
                                       {0x1002, 0xA2, 0xF},
                                       {0x3000, 0xC0, 0xF},
                                       {0x3001, 0xC2, 0xF}};
  EXPECT_TRUE(run.bench.mem.writes == want);
  EXPECT_TRUE(run.bench.mem.writes == run.expected);
  // Forbidden accesses answer err and change nothing, even mid-chunk.
  w(0, 3);
  w(1, 2u << 24 | 0x4000);
  EXPECT_TRUE(rd(1).err);
  EXPECT_TRUE(run.bench.access(true, kWin + kStale, 5, 0xF, false, 0).err);
  EXPECT_TRUE(rd(300).err);
  EXPECT_TRUE(run.bench.access(true, kWin + 511, 5, 0xF, false, 0).err);
  w(2, 0xD0);
  w(3, 0xD1);
  EXPECT_EQ(run.bench.mem.writes.back(), (WbMemory::Write{0x4001, 0xD1, 0xF}));
  EXPECT_EQ(rd(kStale).dat, 1u);
  EXPECT_EQ(rd(kExpect).dat, 4u);
  EXPECT_EQ(run.bench.rule_faults, 0);
}

// rtl/regs/link_guard.rdl (what the host package and the docs take the
// window from) against the RTL: every register at the offset the guard
// decodes, with the access the description gives it.
TEST(LinkGuard, WindowIsWhatTheRdlDescribes) {
  std::ifstream f(HWINTERP_LINK_GUARD_RDL);
  ASSERT_TRUE(f) << HWINTERP_LINK_GUARD_RDL;
  std::stringstream ss;
  ss << f.rdbuf();
  std::string rdl = ss.str();
  std::map<std::string, unsigned> at;  // instance -> byte offset
  std::regex inst(R"(\}\s*(\w+)\s*@\s*0x([0-9A-Fa-f]+)\s*;)");
  for (auto it = std::sregex_iterator(rdl.begin(), rdl.end(), inst); it != std::sregex_iterator();
       ++it)
    at[(*it)[1]] = static_cast<unsigned>(std::stoul((*it)[2], nullptr, 16));
  std::smatch m;
  ASSERT_TRUE(std::regex_search(rdl, m, std::regex(R"(mementries\s*=\s*(\d+))")));
  unsigned stream_words = static_cast<unsigned>(std::stoul(m[1]));
  ASSERT_EQ(at.size(), 6u);
  EXPECT_EQ(at["seq"], kExpect * 4);
  EXPECT_EQ(at["stream"], 4u);
  EXPECT_EQ(stream_words, 255u);
  EXPECT_EQ(at["accepted"], kAccepted * 4);
  EXPECT_EQ(at["stale"], kStale * 4);
  EXPECT_EQ(at["dropped"], kDropped * 4);
  EXPECT_EQ(at["errors"], kErrors * 4);
  // The RTL at those offsets: SEQ read/write, STREAM write-only over all its
  // words, the counters read-only, everything else in the window err.
  GuardBench b(3, 0);
  auto acc = [&](bool we, unsigned byte_off) {
    return b.access(we, kWin + byte_off / 4, 0x01000000, 0xF, false, 0);
  };
  EXPECT_TRUE(acc(false, at["seq"]).ack);
  EXPECT_TRUE(acc(true, at["seq"]).ack);
  for (unsigned w = 0; w < stream_words; ++w) {
    EXPECT_TRUE(acc(true, at["stream"] + 4 * w).ack) << "STREAM word " << w;
    EXPECT_TRUE(acc(false, at["stream"] + 4 * w).err) << "STREAM word " << w;
  }
  for (const char* r : {"accepted", "stale", "dropped", "errors"}) {
    EXPECT_TRUE(acc(false, at[r]).ack) << r;
    EXPECT_TRUE(acc(true, at[r]).err) << r;
  }
  for (unsigned off = at["errors"] + 4; off < 512 * 4; off += 4) {
    EXPECT_TRUE(acc(false, off).err && acc(true, off).err) << "byte offset " << off;
  }
}

}  // namespace
}  // namespace hwinterp::link_test

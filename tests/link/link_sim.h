// Test helpers for the host link's gateware (rtl/link/, docs/link.md):
// a Wishbone B4 classic memory model with wait states, error addresses and a
// log of the writes it took; a reference model of the sequence guard; the
// CRC-32, SLIP and Etherbone encodings a host uses; a UART line driver and
// receiver at a given number of clocks a bit.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace hwinterp::link_test {

// --- Wishbone memory --------------------------------------------------------

// A Wishbone B4 classic subordinate over a sparse 2^30-word memory. Each
// request (cyc & stb) is answered after 0..max_wait clocks (drawn per
// request), with err if err_at(adr) holds, else ack; an acked write takes
// effect (per byte select) at the edge and goes into `writes`. A word never
// written reads init(adr). Protocol faults of the manager (a request that
// changes or goes away before its answer, stb without cyc) are counted.
class WbMemory {
 public:
  struct Write {
    uint32_t adr;
    uint32_t dat;
    uint8_t sel;
    bool operator==(const Write& o) const { return adr == o.adr && dat == o.dat && sel == o.sel; }
  };
  struct Answer {
    bool ack = false, err = false;
    uint32_t dat = 0;
  };

  WbMemory(uint64_t seed, int max_wait) : rng_(seed), max_wait_(max_wait) {}

  static uint32_t init(uint32_t adr) { return adr * 2654435761u ^ 0x5A5A0000u; }
  uint32_t peek(uint32_t adr) const {
    auto it = mem_.find(adr);
    return it == mem_.end() ? init(adr) : it->second;
  }
  void poke(uint32_t adr, uint32_t v) { mem_[adr] = v; }
  size_t words_written() const { return mem_.size(); }

  // The answer in this clock to the manager's pins (before the edge).
  Answer comb(bool cyc, bool stb, bool we, uint32_t adr, uint32_t dat, uint8_t sel) {
    Answer a;
    commit_ = false;
    if (stb && !cyc) ++faults;
    if (!(cyc && stb)) {
      if (wait_ >= 0) ++faults;  // the request went away before its answer
      wait_ = -1;
      return a;
    }
    if (wait_ < 0) {
      wait_ = std::uniform_int_distribution<int>(0, max_wait_)(rng_);
      req_ = {adr, dat, sel};
      req_we_ = we;
    } else if (!(req_ == Write{adr, dat, sel}) || req_we_ != we) {
      ++faults;  // the request changed while it waited
    }
    if (wait_ > 0) return a;
    if (err_at && err_at(adr)) {
      a.err = true;
    } else {
      a.ack = true;
      a.dat = peek(adr);
      commit_ = we;
    }
    answered_ = true;
    return a;
  }
  // The edge that ends the clock comb() answered.
  void edge() {
    if (commit_) {
      uint32_t v = peek(req_.adr);
      for (int b = 0; b < 4; ++b)
        if (req_.sel >> b & 1) v = (v & ~(0xFFu << 8 * b)) | (req_.dat & 0xFFu << 8 * b);
      mem_[req_.adr] = v;
      writes.push_back(req_);
    }
    commit_ = false;
    if (answered_) {
      wait_ = -1;
      answered_ = false;
    } else if (wait_ > 0) {
      --wait_;
    }
  }

  std::function<bool(uint32_t)> err_at;  // word addresses that answer err
  std::vector<Write> writes;             // every acked write, in order
  uint64_t faults = 0;                   // manager protocol faults seen

 private:
  std::mt19937_64 rng_;
  int max_wait_;
  int wait_ = -1;  // clocks before the current request's answer (-1: none)
  Write req_{};
  bool req_we_ = false;
  bool commit_ = false, answered_ = false;
  std::map<uint32_t, uint32_t> mem_;
};

// --- The sequence guard, as docs/link.md states it --------------------------

struct GuardModel {
  uint32_t expect = 0, stale = 0, dropped = 0, errors = 0;
  bool open = false;
  unsigned left = 0;
  uint32_t addr = 0;

  enum class Kind { Err, Own, Forward };
  // What a window access at word offset `off` does (before its effect).
  Kind kind(bool we, unsigned off) const {
    if (off == 0) return Kind::Own;
    if (off <= 255) return !we ? Kind::Err : (left != 0 && open ? Kind::Forward : Kind::Own);
    if (off <= 259) return we ? Kind::Err : Kind::Own;
    return Kind::Err;
  }
  uint32_t read(unsigned off) const {
    switch (off) {
      case 257:
        return stale;
      case 258:
        return dropped;
      case 259:
        return errors;
      default:
        return expect;  // 0 and 256 (ACCEPTED = EXPECT)
    }
  }
  // The effect of an answered window write; `bus_err`: a forwarded write's
  // bus answer was err. Returns the downstream write's word address if the
  // word was forwarded.
  bool write(unsigned off, uint32_t dat, bool bus_err, uint32_t* target) {
    if (off == 0) {
      open = dat == expect;
      if (open)
        ++expect;
      else
        ++stale;
      left = 0;
      return false;
    }
    if (off > 255) return false;
    if (left == 0) {
      left = dat >> 24;
      addr = dat & 0xFFFFFF;
      return false;
    }
    bool fwd = open;
    if (fwd) {
      *target = addr;
      if (bus_err) ++errors;
    } else {
      ++dropped;
    }
    --left;
    addr = (addr + 1) & 0xFFFFFF;
    return fwd;
  }
};

// --- CRC-32, SLIP, Etherbone ------------------------------------------------

inline uint32_t crc32(const std::vector<uint8_t>& b) {
  uint32_t c = 0xFFFFFFFFu;
  for (uint8_t x : b) {
    c ^= x;
    for (int i = 0; i < 8; ++i) c = (c >> 1) ^ (c & 1 ? 0xEDB88320u : 0);
  }
  return ~c;
}

constexpr uint8_t kEnd = 0xC0, kEsc = 0xDB, kEscEnd = 0xDC, kEscEsc = 0xDD;

// The frame a host sends for a packet: END (flush), the packet and its CRC-32
// (least significant byte first), SLIP-escaped, END.
inline std::vector<uint8_t> slip_frame(const std::vector<uint8_t>& packet, bool lead_end = true) {
  std::vector<uint8_t> body = packet;
  uint32_t c = crc32(packet);
  for (int i = 0; i < 4; ++i) body.push_back(static_cast<uint8_t>(c >> 8 * i));
  std::vector<uint8_t> out;
  if (lead_end) out.push_back(kEnd);
  for (uint8_t x : body) {
    if (x == kEnd) {
      out.push_back(kEsc);
      out.push_back(kEscEnd);
    } else if (x == kEsc) {
      out.push_back(kEsc);
      out.push_back(kEscEsc);
    } else {
      out.push_back(x);
    }
  }
  out.push_back(kEnd);
  return out;
}

inline void put32(std::vector<uint8_t>& b, uint32_t v) {
  for (int i = 3; i >= 0; --i) b.push_back(static_cast<uint8_t>(v >> 8 * i));
}
inline uint32_t get32(const std::vector<uint8_t>& b, size_t at) {
  return uint32_t(b[at]) << 24 | uint32_t(b[at + 1]) << 16 | uint32_t(b[at + 2]) << 8 | b[at + 3];
}

// An Etherbone packet of LiteEth's subset (docs/link.md): the header and one
// record writing `writes` from byte address `wbase` and reading the byte
// addresses `reads`, the reply to go to `rbase`.
struct Record {
  uint8_t be = 0x0F;
  uint32_t wbase = 0;
  std::vector<uint32_t> writes;
  uint32_t rbase = 0;
  std::vector<uint32_t> reads;
};
inline std::vector<uint8_t> etherbone(const Record& r, uint8_t flags = 0) {
  std::vector<uint8_t> b = {0x4E, 0x6F, static_cast<uint8_t>(0x10 | flags), 0x44, 0, 0, 0, 0};
  b.push_back(0);
  b.push_back(r.be);
  b.push_back(static_cast<uint8_t>(r.writes.size()));
  b.push_back(static_cast<uint8_t>(r.reads.size()));
  if (!r.writes.empty()) {
    put32(b, r.wbase);
    for (uint32_t w : r.writes) put32(b, w);
  }
  if (!r.reads.empty()) {
    put32(b, r.rbase);
    for (uint32_t a : r.reads) put32(b, a);
  }
  return b;
}

// SLIP frames out of received bytes: each frame's bytes (unescaped), ENDs
// removed, empty frames skipped; `bad` counts frames with a bad escape.
struct SlipDecoder {
  std::vector<std::vector<uint8_t>> frames;
  std::vector<uint8_t> cur;
  bool esc = false;
  int bad = 0;
  void put(uint8_t x) {
    if (x == kEnd) {
      if (!cur.empty()) frames.push_back(cur);
      cur.clear();
      esc = false;
    } else if (esc) {
      esc = false;
      if (x == kEscEnd)
        cur.push_back(kEnd);
      else if (x == kEscEsc)
        cur.push_back(kEsc);
      else
        ++bad;
    } else if (x == kEsc) {
      esc = true;
    } else {
      cur.push_back(x);
    }
  }
};

// --- UART -------------------------------------------------------------------

// Drives a line, 8N1, at `period` clocks a bit (a fraction allowed: a bit
// starts on the first clock at or after its time), from a queue of
// characters and pauses; a character may be sent with a low stop bit (a
// framing error).
class UartDriver {
 public:
  explicit UartDriver(double period) : period_(period) {}
  void send(uint8_t b, bool bad_stop = false) { queue_.push_back({b, bad_stop, 0}); }
  void pause(int clocks) { queue_.push_back({0, false, clocks}); }  // the line idle (high)
  void send(const std::vector<uint8_t>& bytes) {
    for (uint8_t b : bytes) send(b);
  }
  bool idle() const { return queue_.empty() && !active_; }
  // The line level for the next clock.
  bool step() {
    if (!active_) {
      if (queue_.empty()) return true;
      cur_ = queue_.front();
      queue_.erase(queue_.begin());
      active_ = true;
      t_ = 0;
    }
    if (cur_.pause > 0) {
      active_ = ++t_ < cur_.pause;
      return true;
    }
    int bit = static_cast<int>(t_ / period_);
    bool level;
    if (bit == 0)
      level = false;
    else if (bit <= 8)
      level = cur_.byte >> (bit - 1) & 1;
    else
      level = !cur_.bad_stop;
    t_ += 1;
    if (t_ >= 10 * period_ - 1e-9) active_ = false;
    return level;
  }

 private:
  struct Char {
    uint8_t byte;
    bool bad_stop;
    int pause;  // > 0: not a character, the line idle this many clocks
  };
  double period_;
  std::vector<Char> queue_;
  Char cur_{};
  bool active_ = false;
  double t_ = 0;
};

// Receives a line, 8N1, `period` clocks a bit: the start bit's falling edge,
// then each bit sampled at its middle. Counts stop bits that are low
// (framing_errors) and edges inside a character that are not a whole number
// of bits after its start edge (timing_errors).
class UartReceiver {
 public:
  explicit UartReceiver(int period) : period_(period) {}
  void step(bool line) {
    if (!active_) {
      if (prev_ && !line) {
        active_ = true;
        t_ = 0;
        shift_ = 0;
      }
    } else {
      ++t_;
      if (line != prev_ && t_ % period_ != 0) ++timing_errors;  // an edge off the bit grid
      if (t_ % period_ == period_ / 2) {
        int bit = t_ / period_;
        if (bit == 0 && line) active_ = false;  // a glitch
        if (bit >= 1 && bit <= 8) shift_ |= static_cast<unsigned>(line) << (bit - 1);
        if (bit == 9) {
          if (!line) ++framing_errors;
          bytes.push_back(static_cast<uint8_t>(shift_));
          active_ = false;
        }
      }
    }
    prev_ = line;
  }
  std::vector<uint8_t> bytes;
  int framing_errors = 0, timing_errors = 0;

 private:
  int period_;
  bool active_ = false, prev_ = true;
  int t_ = 0;
  unsigned shift_ = 0;
};

}  // namespace hwinterp::link_test

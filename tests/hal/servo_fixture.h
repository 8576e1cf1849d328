// What tests/hal/ share to drive the LinuxCNC driver's servo without a
// board: its guarded packets read back, a board that runs them in SEQ order
// as the guard does and answers their reads, and a sink for what it sends.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

extern "C" {
#include "../../sw/board_regs.h"
#include "hwinterp_servo.h"
}

namespace hal_test {

using Bytes = std::vector<uint8_t>;

inline uint32_t be32(const uint8_t* p) {
  return uint32_t{p[0]} << 24 | uint32_t{p[1]} << 16 | uint32_t{p[2]} << 8 | p[3];
}

// A motion_soc register's address on the board (offsetof into its block).
inline uint32_t motion(size_t off) {
  return static_cast<uint32_t>(offsetof(hwinterp_board_t, motion) + off);
}

// A guarded packet read back: its SEQ, the bus writes its stream makes (in
// order), its reads and its tag.
struct Decoded {
  uint32_t seq = 0, tag = 0;
  std::vector<std::pair<uint32_t, uint32_t>> writes;  // byte address, value
  std::vector<uint32_t> reads;
  int pushes() const {
    int n = 0;
    for (auto [a, v] : writes) n += a == motion(offsetof(motion_soc_regs_t, cmd_push));
    return n;
  }
  bool arms() const {
    for (auto [a, v] : writes)
      if (a == motion(offsetof(motion_soc_regs_t, snap_at))) return true;
    return false;
  }
};

inline Decoded decode(const uint8_t* p, size_t len) {
  Decoded d;
  EXPECT_GE(len, 12u);
  EXPECT_EQ(be32(p) >> 16, 0x4E6Fu);
  EXPECT_EQ(p[3], 0x44);
  const uint32_t nw = p[10], nr = p[11];
  EXPECT_EQ(len, 12 + (nw ? 4 + 4 * nw : 0) + (nr ? 4 + 4 * nr : 0));
  const uint8_t* q = p + 12;
  EXPECT_EQ(be32(q), offsetof(hwinterp_board_t, link.seq));  // the guard's window
  q += 4;
  std::vector<uint32_t> stream;
  for (uint32_t i = 0; i < nw; ++i, q += 4) stream.push_back(be32(q));
  d.seq = stream.at(0);
  for (size_t i = 1; i < stream.size();) {  // chunks: {count, word address}, data
    const uint32_t count = stream[i] >> 24, word = stream[i] & 0xFFFFFF;
    for (uint32_t k = 0; k < count; ++k) d.writes.push_back({4 * (word + k), stream.at(i + 1 + k)});
    i += 1 + count;
  }
  d.tag = be32(q);
  q += 4;
  for (uint32_t i = 0; i < nr; ++i, q += 4) d.reads.push_back(be32(q));
  return d;
}

inline Decoded decode(const Bytes& b) { return decode(b.data(), b.size()); }

// The board's answer to a packet: EXPECT after it, then every read's value.
inline Bytes reply(uint32_t tag, const std::vector<uint32_t>& words) {
  Bytes r = {0x4E, 0x6F, 0x10, 0x44, 0, 0, 0, 0, 0, 0x0F, static_cast<uint8_t>(words.size()), 0};
  auto put = [&](uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) r.push_back(static_cast<uint8_t>(v >> s));
  };
  put(tag);
  for (uint32_t w : words) put(w);
  return r;
}

// A board for the servo's packets: runs their writes in SEQ order as the
// guard does (a packet whose SEQ is not EXPECT is refused) and answers the
// reads from its registers; with `fires`, a snapshot armed is taken at once
// (EVENTS.snap set).
struct GuardedBoard {
  uint32_t expect = 0;
  bool fires = false;
  std::map<uint32_t, uint32_t> regs;
  std::vector<Decoded> taken;
  Bytes answer(const Bytes& pkt) {
    Decoded d = decode(pkt);
    if (d.seq == expect) {
      ++expect;
      for (auto [a, v] : d.writes) regs[a] = v;
      if (fires && d.arms())
        regs[motion(offsetof(motion_soc_regs_t, events))] = 1u << MOTION_SOC_REGS__EVENTS__SNAP_bp;
      taken.push_back(d);
    }
    std::vector<uint32_t> words;
    for (uint32_t a : d.reads)
      words.push_back(a == offsetof(hwinterp_board_t, link.seq) ? expect : regs[a]);
    return reply(d.tag, words);
  }
};

// What the servo sends, packet by packet (its hwi_send_fn).
struct Sent {
  std::vector<Bytes> packets;
  static int send(void* ctx, const uint8_t* data, size_t len) {
    static_cast<Sent*>(ctx)->packets.emplace_back(data, data + len);
    return 0;
  }
};

}  // namespace hal_test

// The C++ register model generated from rtl/regs/motion_soc.rdl
// (hls/gen/motion_soc_regs.h, scripts/regs/cpp_model.py) against the
// description: the same properties the cocotb tests check on the generated
// SystemVerilog (tests/cocotb/test_motion_soc.py), one request a clock.
#include "hls/gen/motion_soc_regs.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <iterator>
#include <map>
#include <random>
#include <set>

namespace {

namespace regs = hwinterp::hls::motion_soc_regs;

struct Harness {
  regs::Block block;
  regs::HwifIn in;
  regs::HwifOut out;
  regs::Response rsp;

  Harness() { block.reset(); }

  // One clock with the request, then the edge.
  void clock(const regs::Request& rq) {
    block.eval(rq, in, rsp, out);
    block.commit();
  }
  uint32_t read(uint32_t addr, bool* err) {
    regs::Request rq;
    rq.req = true;
    rq.addr = addr;
    clock(rq);
    EXPECT_TRUE(rsp.rd_ack);
    *err = rsp.rd_err;
    return rsp.rd_data;
  }
  bool write(uint32_t addr, uint32_t data, uint32_t biten = 0xFFFFFFFFu) {
    regs::Request rq;
    rq.req = rq.is_wr = true;
    rq.addr = addr;
    rq.wr_data = data;
    rq.wr_biten = biten;
    clock(rq);
    EXPECT_TRUE(rsp.wr_ack);
    return rsp.wr_err;
  }
  void idle() { clock(regs::Request()); }
};

// The reset value of word w of register r over its software-readable fields
// that the hardware does not drive (those read hwif_in, 0 here).
uint32_t reset_word(int r, uint32_t w) {
  uint64_t v = 0;
  for (const auto& f : regs::kFields) {
    if (f.reg != r || f.sw == regs::Sw::kW || (f.hw_writes && !f.woclr)) continue;
    const uint64_t mask = f.width == 64 ? ~0ull : ((1ull << f.width) - 1) << f.lsb;
    v |= (f.reset << f.lsb) & mask;
  }
  return static_cast<uint32_t>(v >> (32 * w));
}

TEST(SocRegsModel, ResetValuesAndAccessRights) {
  Harness h;
  int words = 0;
  for (int r = 0; r < static_cast<int>(std::size(regs::kRegs)); r++) {
    const auto& d = regs::kRegs[r];
    for (uint32_t e = 0; e < d.count; e++) {
      for (uint32_t w = 0; w < d.words; w++) {
        const uint32_t addr = d.addr + e * d.stride + 4 * w;
        bool err = false;
        const uint32_t data = h.read(addr, &err);
        EXPECT_EQ(err, d.sw == regs::Sw::kW) << d.name << " word " << w;
        if (d.sw != regs::Sw::kW) {
          EXPECT_EQ(data, reset_word(r, w)) << d.name << " word " << w;
        }
        words++;
      }
    }
  }
  EXPECT_EQ(words, 90);  // the map's 32-bit words
  // Writes: a read-only register answers an error and keeps its value.
  bool err = false;
  EXPECT_TRUE(h.write(regs::kIdMagic, 0));
  EXPECT_EQ(h.read(regs::kIdMagic, &err), 0x484D5331u);
  EXPECT_TRUE(h.write(regs::kStatus, 0xFFFFFFFFu));
  EXPECT_FALSE(h.write(regs::kCmdPush, 1));
  EXPECT_FALSE(h.write(regs::kFifoLow, 0x1234));
  EXPECT_EQ(h.read(regs::kFifoLow, &err), 0x1234u);
  EXPECT_FALSE(err);
  // Byte enables: only byte 0.
  EXPECT_FALSE(h.write(regs::kFifoLow, 0xFFFFFF56u, 0xFFu));
  EXPECT_EQ(h.read(regs::kFifoLow, &err), 0x1256u);
}

TEST(SocRegsModel, UnmappedAddressesAnswerErrors) {
  std::set<uint32_t> used;
  for (const auto& d : regs::kRegs)
    for (uint32_t e = 0; e < d.count; e++)
      for (uint32_t w = 0; w < d.words; w++) used.insert(d.addr + e * d.stride + 4 * w);
  Harness h;
  int n = 0;
  for (uint32_t a = 0; a < 0x400; a += 4) {
    if (used.count(a)) continue;
    bool err = false;
    h.read(a, &err);
    EXPECT_TRUE(err) << std::hex << a;
    EXPECT_TRUE(h.write(a, 0xDEADBEEFu)) << std::hex << a;
    n++;
  }
  EXPECT_EQ(n, 166);  // as the cocotb test counts on the generated blocks
}

TEST(SocRegsModel, StickyEventsClearOnWriteOneAndHardwareWins) {
  Harness h;
  bool err = false;
  h.in.events.overflow.next = 1;
  h.idle();
  h.in.events.overflow.next = 0;
  h.idle();
  EXPECT_EQ(h.read(regs::kEvents, &err) & 1u, 1u);
  EXPECT_FALSE(h.write(regs::kEvents, 0x2));  // another bit: overflow stays
  EXPECT_EQ(h.read(regs::kEvents, &err) & 1u, 1u);
  h.in.events.overflow.next = 1;  // set and cleared in one clock: set wins
  EXPECT_FALSE(h.write(regs::kEvents, 0x1));
  h.in.events.overflow.next = 0;
  EXPECT_EQ(h.read(regs::kEvents, &err) & 1u, 1u);
  EXPECT_FALSE(h.write(regs::kEvents, 0x1));
  EXPECT_EQ(h.read(regs::kEvents, &err) & 1u, 0u);
}

TEST(SocRegsModel, StrobesAndPulses) {
  Harness h;
  bool err = false;
  // CMD_PUSH: swmod in the clock of a write with byte 0 enabled.
  EXPECT_FALSE(h.write(regs::kCmdPush, 1));
  EXPECT_TRUE(h.out.cmd_push.push.swmod);
  EXPECT_FALSE(h.write(regs::kCmdPush, 1, 0xFF00u));
  EXPECT_FALSE(h.out.cmd_push.push.swmod);
  // CTRL.abort_motion: one clock high after the write.
  EXPECT_FALSE(h.write(regs::kCtrl, 1));
  h.idle();
  EXPECT_EQ(h.out.ctrl.abort_motion.value, 1u);
  h.idle();
  EXPECT_EQ(h.out.ctrl.abort_motion.value, 0u);
  // TIME_LO: swacc on a read; the hardware's value read back.
  h.in.time_lo.count.next = 0x12345678u;
  EXPECT_EQ(h.read(regs::kTimeLo, &err), 0x12345678u);
  EXPECT_TRUE(h.out.time_lo.count.swacc);
  h.idle();
  EXPECT_FALSE(h.out.time_lo.count.swacc);
  // A 64-bit hardware value: two words.
  h.in.snap_pos0.pos.next = 0xFFFFFFFFFFFFFFFEull;
  EXPECT_EQ(h.read(regs::kSnapPos0, &err), 0xFFFFFFFEu);
  EXPECT_EQ(h.read(regs::kSnapPos0 + 4, &err), 0xFFFFFFFFu);
}

// Random legal and illegal requests, with idle clocks between some: every
// response is what the map says (error exactly on unmapped addresses and
// wrong-direction accesses), and every plain read-write field holds what was
// last written to it through its byte enables.
TEST(SocRegsModel, RandomTrafficKeepsEveryRegister) {
  std::set<uint32_t> readable, writable;
  std::map<uint32_t, uint32_t> rw_mask;  // word address -> bits of plain rw fields
  for (int r = 0; r < static_cast<int>(std::size(regs::kRegs)); r++) {
    const auto& d = regs::kRegs[r];
    for (uint32_t w = 0; w < d.words; w++) {
      const uint32_t addr = d.addr + 4 * w;
      if (d.sw != regs::Sw::kW) readable.insert(addr);
      if (d.sw != regs::Sw::kR) writable.insert(addr);
      for (const auto& f : regs::kFields) {
        if (f.reg != r || f.sw != regs::Sw::kRw || f.hw_writes || f.woclr || f.singlepulse)
          continue;
        for (int b = f.lsb; b < f.lsb + f.width; b++)
          if (b / 32 == static_cast<int>(w)) rw_mask[addr] |= 1u << (b % 32);
      }
    }
  }
  Harness h;
  std::map<uint32_t, uint32_t> model;  // the rw bits' values
  for (const auto& [addr, mask] : rw_mask) {
    bool err = false;
    model[addr] = h.read(addr, &err) & mask;
  }
  std::mt19937 rng(1);
  int reads = 0, writes = 0, errors = 0;
  for (int i = 0; i < 20000; i++) {
    if (rng() % 4 == 0) h.idle();
    const uint32_t addr = (rng() % 0x100) * 4;
    if (rng() % 2) {
      bool err = false;
      const uint32_t data = h.read(addr, &err);
      ASSERT_EQ(err, readable.count(addr) == 0) << std::hex << addr;
      if (rw_mask.count(addr)) {
        ASSERT_EQ(data & rw_mask[addr], model[addr]) << std::hex << addr;
      }
      reads++;
      errors += err;
    } else {
      // Only the plain rw words take random data (actions and events have
      // side effects this test does not model); others get a write whose
      // response is checked.
      if (writable.count(addr) && !rw_mask.count(addr) && addr != regs::kFifoLow) continue;
      const uint32_t data = static_cast<uint32_t>(rng());
      uint32_t biten = 0;
      for (int b = 0; b < 4; b++)
        if (rng() % 2) biten |= 0xFFu << (8 * b);
      const bool err = h.write(addr, data, biten);
      ASSERT_EQ(err, writable.count(addr) == 0) << std::hex << addr;
      if (rw_mask.count(addr))
        model[addr] = ((model[addr] & ~biten) | (data & biten)) & rw_mask[addr];
      writes++;
      errors += err;
    }
  }
  EXPECT_GT(errors, 1000);
  EXPECT_GT(writes, 3000);
  EXPECT_GT(reads, 5000);
}

}  // namespace

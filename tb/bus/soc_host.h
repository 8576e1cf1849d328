// The host's side of motion_soc (rtl/motion_soc.sv): the bus transactions
// that set it up and stream motion_top commands into its command FIFO, as a
// CPU driver would (docs/soc.md's bring-up), one transaction at a time for a
// bus master (tb/bus/bus_master.h). Addresses and fields come from the
// register description (hls/gen/motion_soc_regs.h, generated from
// rtl/regs/motion_soc.rdl).
//
// Per command: the staging registers it needs that differ from what is
// staged already (CMD_DELTA*, CMD_CENTER*, CMD_END*, CMD_OPS, CMD_FEED,
// CMD_FLAGS), then CMD_PUSH. Back-pressure: a push only with credit, the
// room FIFO_LEVEL last said, less the pushes since; without credit the host
// reads FIFO_LEVEL again (never a push to a full FIFO), and when that says
// full it sleeps on the low-water interrupt, as a driver would: it clears
// EVENTS.low_water (IRQ_EN has only low_water, FIFO_LOW is SocSetup's mark),
// waits for irq_o, and reads FIFO_LEVEL again. At the end it reads EVENTS:
// an overflow or refused push there, or any error response, is a lost
// command and fails the run.
//
// With the feed profile (SocSetup::profile, a PROFILE = 1 build): PROF_Q and
// PROF_LEN before the first command, and each command's profile move
// (CMD_MV_OPS, CMD_MV_TARGET, CMD_MV_END, CMD_MV_MAX, only what changes)
// staged with it: the source gives the move with next_move(ProfileWords&)
// after each command.
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "hls/gen/motion_soc_regs.h"
#include "models/motion_top_model.h"
#include "tb/bus/bus_master.h"
#include "tb/lockstep/profile_feed.h"

namespace hwinterp::tb::bus {

namespace regs = hls::motion_soc_regs;

// A field's lowest bit, from the generated table (-1: no such field).
constexpr bool same_name(const char* a, const char* b) {
  while (*a && *a == *b) ++a, ++b;
  return *a == *b;
}
constexpr int field_lsb(const char* reg, const char* field) {
  for (const regs::FieldDesc& f : regs::kFields)
    if (same_name(regs::kRegs[f.reg].name, reg) && same_name(f.name, field)) return f.lsb;
  return -1;
}
constexpr uint32_t field_bit(const char* reg, const char* field) {
  return 1u << field_lsb(reg, field);
}
inline constexpr int kRoomLsb = field_lsb("fifo_level", "room");
inline constexpr int kPlaneLsb = field_lsb("cmd_flags", "plane");
inline constexpr uint32_t kArcBit = field_bit("cmd_flags", "arc");
inline constexpr uint32_t kCcwBit = field_bit("cmd_flags", "ccw");
inline constexpr uint32_t kLowWater = field_bit("events", "low_water");
inline constexpr uint32_t kLost = field_bit("events", "overflow") | field_bit("events", "refused");
// STEP_TYPE's field of each axis.
inline constexpr int kStepTypeLsb[6] = {
    field_lsb("step_type", "axis0"), field_lsb("step_type", "axis1"),
    field_lsb("step_type", "axis2"), field_lsb("step_type", "axis3"),
    field_lsb("step_type", "axis4"), field_lsb("step_type", "axis5")};
static_assert(kStepTypeLsb[0] == 0 && kStepTypeLsb[5] > 0 && kRoomLsb > 0 && kPlaneLsb > 0 &&
                  field_lsb("irq_en", "low_water") == field_lsb("events", "low_water"),
              "the register description changed under the host");

// What the host writes before the first command.
struct SocSetup {
  int axes = 3;
  uint32_t feed = 0;  // FEED (feed_i): 2^FEED_W is full feed
  uint32_t step_len = 0, step_space = 0, dir_setup = 0, dir_hold = 0;
  // STEP_TYPE per axis (rtl/step_encode.sv): 0 step/dir, 1 up/down, 2 quadrature.
  std::array<uint8_t, 6> step_type{};
  uint32_t fifo_low = 4;  // FIFO_LOW: the low-water mark the host sleeps on
  bool profile = false;   // stage each command's profile move (a PROFILE = 1 build)
  uint64_t prof_q = 0;    // PROF_Q
  uint32_t prof_len = 1;  // PROF_LEN
};

inline uint32_t step_type_word(const SocSetup& s) {
  uint32_t w = 0;
  for (int i = 0; i < s.axes && i < 6; ++i)
    w |= uint32_t{s.step_type[static_cast<size_t>(i)]} << kStepTypeLsb[i];
  return w;
}

struct HostCounts {
  uint64_t writes = 0, reads = 0, errors = 0;
  uint64_t pushes = 0;        // CMD_PUSH writes (each with credit)
  uint64_t level_reads = 0;   // FIFO_LEVEL reads for credit
  uint64_t credit_waits = 0;  // of those, the ones that found the FIFO full (then: irq wait)
  uint64_t irq_clocks = 0;    // clocks spent waiting for the low-water interrupt
  uint32_t events = 0;        // EVENTS as read at the end
  bool events_read = false;
};

// One command's writes into the staging registers: every field the direct
// lockstep drives (tb/cores/motion_top: to_own), lines included, so the core
// sees the same payload; only the registers whose staged value changes, then
// CMD_PUSH. put(addr, data) takes each write in order. Used by SocHost and
// by `hwinterp gcode --soc-writes` (a replay for other test benches).
class CommandStager {
 public:
  explicit CommandStager(int axes) : axes_(axes) { staged_.fill(0); }  // the reset values

  template <class Put>
  void stage(const models::MotionCommand& c, Put&& put) {
    stage(c, nullptr, put);
  }
  // ... with the command's profile move (mv: null for none).
  template <class Put>
  void stage(const models::MotionCommand& c, const ProfileWords* mv, Put&& put) {
    const auto write = [&](size_t reg, uint32_t addr, uint32_t v) {
      if (staged_[reg] == v) return;
      staged_[reg] = v;
      put(addr, v);
    };
    const bool arc = c.kind == models::MotionKind::kArc;
    for (int i = 0; i < axes_; ++i)
      write(static_cast<size_t>(i), regs::kCmdDelta0 + 4u * static_cast<uint32_t>(i),
            static_cast<uint32_t>(c.delta[static_cast<size_t>(i)]));
    write(6, regs::kCmdCenter0, static_cast<uint32_t>(c.center[0]));
    write(7, regs::kCmdCenter1, static_cast<uint32_t>(c.center[1]));
    write(8, regs::kCmdEnd0, static_cast<uint32_t>(c.end[0]));
    write(9, regs::kCmdEnd1, static_cast<uint32_t>(c.end[1]));
    write(10, regs::kCmdOps, static_cast<uint32_t>(c.ops));
    write(11, regs::kCmdFeed, c.feed);
    // CMD_FLAGS: arc, plane, ccw; timed 0 (at once).
    const uint32_t flags = (arc ? kArcBit : 0u) |
                           (static_cast<uint32_t>(c.plane & 3) << kPlaneLsb) |
                           (c.ccw ? kCcwBit : 0u);
    write(12, regs::kCmdFlags, flags);
    if (mv) {
      write(13, regs::kCmdMvOps, static_cast<uint32_t>(mv->ops));
      write(14, regs::kCmdMvTarget, mv->target);
      write(15, regs::kCmdMvEnd, mv->end);
      write(16, regs::kCmdMvMax, mv->max);
    }
    put(regs::kCmdPush, 1u);
  }

 private:
  int axes_;
  std::array<uint32_t, 17> staged_{};
};

// A source that gives profile moves: next_move(ProfileWords&).
template <class Src, class = void>
struct HasMoves : std::false_type {};
template <class Src>
struct HasMoves<
    Src, std::void_t<decltype(std::declval<Src&>().next_move(std::declval<ProfileWords&>()))>>
    : std::true_type {};

// Src: bool next(models::MotionCommand&) per command (false at the end).
template <class Src>
class SocHost {
 public:
  SocHost(Src& src, const SocSetup& s) : src_(src), setup_(s), stager_(s.axes) {
    put_write(regs::kFeed, s.feed);
    put_write(regs::kStepLen, s.step_len);
    put_write(regs::kStepSpace, s.step_space);
    put_write(regs::kDirSetup, s.dir_setup);
    put_write(regs::kDirHold, s.dir_hold);
    put_write(regs::kStepType, step_type_word(s));
    put_write(regs::kFifoLow, s.fifo_low);
    put_write(regs::kIrqEn, kLowWater);
    if (s.profile) {
      put_write(regs::kProfQ, static_cast<uint32_t>(s.prof_q));
      put_write(regs::kProfQ + 4, static_cast<uint32_t>(s.prof_q >> 32));
      put_write(regs::kProfLen, s.prof_len);
    }
  }

  // The next transaction, if any now (false: nothing until a response, the
  // interrupt, or the end); irq: irq_o now.
  bool next(BusTxn& t, bool irq) {
    if (waiting_) return false;
    if (sleeping_) {
      if (!irq) {
        ++counts_.irq_clocks;
        return false;
      }
      sleeping_ = false;
      t = BusTxn{false, regs::kFifoLevel, 0, 0xF};
      ++counts_.level_reads;
      waiting_ = true;
      return true;
    }
    if (clear_low_) {  // going to sleep: clear the sticky low-water event first
      clear_low_ = false;
      sleeping_ = true;
      t = BusTxn{true, regs::kEvents, kLowWater, 0xF};
      ++counts_.writes;
      return true;
    }
    if (n_ == i_ && !refill()) return false;
    t = q_[i_];
    if (t.write && t.addr == regs::kCmdPush) {
      if (credit_ == 0) {  // ask the FIFO for room first
        t = BusTxn{false, regs::kFifoLevel, 0, 0xF};
        ++counts_.level_reads;
        waiting_ = true;
        return true;
      }
      --credit_;
      ++counts_.pushes;
    } else if (!t.write && t.addr == regs::kEvents) {
      waiting_ = true;
    }
    ++i_;
    t.write ? ++counts_.writes : ++counts_.reads;
    return true;
  }
  // A transaction ended.
  void response(const BusRsp& r) {
    if (r.err) ++counts_.errors;
    if (!r.txn.write && r.txn.addr == regs::kFifoLevel) {
      ++counts_.reads;
      credit_ = r.data >> kRoomLsb;  // FIFO_LEVEL.room
      if (credit_ == 0) {
        ++counts_.credit_waits;
        clear_low_ = true;
      }
      waiting_ = false;
    } else if (!r.txn.write && r.txn.addr == regs::kEvents) {
      counts_.events = r.data;
      counts_.events_read = true;
      waiting_ = false;
    }
  }
  // Every command pushed and EVENTS read.
  bool finished() const { return counts_.events_read; }
  const HostCounts& counts() const { return counts_; }

 private:
  void put_write(uint32_t addr, uint32_t data) { q_[n_++] = BusTxn{true, addr, data, 0xF}; }
  // The next command's writes (or, at the end, the read of EVENTS).
  bool refill() {
    n_ = i_ = 0;
    if (ended_) return false;
    models::MotionCommand c;
    if (!src_.next(c)) {
      ended_ = true;
      q_[n_++] = BusTxn{false, regs::kEvents, 0, 0xF};
      return true;
    }
    const auto put = [this](uint32_t addr, uint32_t v) { put_write(addr, v); };
    if constexpr (HasMoves<Src>::value) {
      if (setup_.profile) {
        ProfileWords w;
        if (!src_.next_move(w)) w = ProfileWords{};  // the planner has a move for each command
        stager_.stage(c, &w, put);
        return true;
      }
    }
    stager_.stage(c, put);
    return true;
  }

  Src& src_;
  SocSetup setup_;
  std::array<BusTxn, 24> q_{};  // this command's transactions
  size_t n_ = 0, i_ = 0;
  CommandStager stager_;
  uint32_t credit_ = 0;
  bool waiting_ = false;                       // a read whose answer decides what comes next
  bool clear_low_ = false, sleeping_ = false;  // the FIFO was full: wait for low water
  bool ended_ = false;
  HostCounts counts_;
};

}  // namespace hwinterp::tb::bus

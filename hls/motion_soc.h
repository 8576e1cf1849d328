// motion_soc's HLS face: hls::MotionTop behind the register block and the
// command FIFO, clock for clock as rtl/motion_soc.sv, and the bus faces of
// rtl/motion_soc_axil.sv and rtl/motion_soc_wb.sv (PeakRDL-regblock's
// AXI4-Lite and Wishbone CPU interfaces). The register block is the C++
// model generated from the same SystemRDL description
// (hls/gen/motion_soc_regs.h, scripts/regs/cpp_model.py): this file names no
// register address or field layout of its own; it reads hwif_out and drives
// hwif_in as motion_soc.sv does.
//
// tick() is one rising clock edge: with the bus pins of the clock it
// computes the CPU-interface request, the register block's outputs, the
// SoC's logic and hwif_in, the register block's response and next state,
// motion_top's tick, and the registers of the FIFO, time, watchdog, probe,
// snapshot and step types. The outputs (out_a, out_b, irq and the bus
// response pins) are then those after the edge, as a Verilated model's after
// its eval at clk_i = 1. The comparison with the Verilated tops, clock by
// clock, is tb/bus/soc_run.h's (hwinterp gcode --bus; docs/soc.md).
#pragma once

#include <cstdint>

#include "hls/gen/motion_soc_regs.h"
#include "hls/motion_top.h"

namespace hwinterp::hls {

// The SoC between the register block's CPU interface and the step outputs.
template <class Cfg, int FIFO_DEPTH = 16, int BUS = 0, uint32_t CLK_HZ = 50000000>
class MotionSoc {
 public:
  static constexpr int AXES = Cfg::AXES;
  static constexpr int ACC_W = Cfg::ACC_W;
  static constexpr int COORD_W = Cfg::COORD_W;
  static constexpr int OPS_W = Cfg::OPS_W;
  static constexpr int POS_W = Cfg::POS_W;
  static constexpr int TIM_W = Cfg::TIM_W;
  static constexpr int FEED_W = Cfg::FEED_W;
  static_assert(FIFO_DEPTH >= 2 && FIFO_DEPTH <= 65535, "FIFO_DEPTH must be 2..65535");
  using Core = MotionTop<Cfg>;
  using Regs = motion_soc_regs::Block;

  struct Pins {
    bool rst_n = false;
    bool probe = false, estop = false;
  };

  MotionSoc() { reset(); }

  void reset() {
    regs_.reset();
    core_.reset();
    core_out_ = core_.outputs();
    time_q_ = 0;
    time_hi_q_ = 0;
    estop_s_q_ = 0;
    wdog_left_q_ = 0;
    wdog_kick_q_ = false;
    wptr_q_ = rptr_q_ = cnt_q_ = 0;
    head_q_ = false;
    step_prev_q_ = seen_q_ = neg_q_ = 0;
    probe_s_q_ = 0;
    probe_f_q_ = false;
    probe_n_q_ = 0;
    latch_armed_q_ = snap_armed_q_ = false;
    snap_time_q_ = latch_time_q_ = 0;
    for (int i = 0; i < AXES; ++i) {
      since_q_[i] = period_q_[i] = 0;
      type_q_[i] = phase_q_[i] = 0;
      snap_pos_q_[i] = latch_pos_q_[i] = 0;
      snap_speed_q_[i] = 0;
    }
  }

  // One rising edge with this clock's request on the register block's CPU
  // interface; `rsp` is the block's response in this clock (before the edge).
  void tick(const Pins& p, const motion_soc_regs::Request& rq, motion_soc_regs::Response& rsp) {
    if (!p.rst_n) {
      reset();
      rsp = motion_soc_regs::Response();
      return;
    }
    motion_soc_regs::HwifOut o;
    // hwif_out does not depend on hwif_in: one evaluation for it, then the
    // one that counts with this clock's hwif_in.
    regs_.eval(rq, in_, rsp, o);
    comb(o);
    regs_.eval(rq, in_, rsp, o);

    // motion_top's inputs of this clock.
    typename Core::Inputs ci;
    ci.rst_n = true;
    ci.cmd_valid = cmd_valid_;
    ci.abort = abort_;
    ci.feed = feed_word_;
    ci.timing.step_len = step_len_;
    ci.timing.step_space = step_space_;
    ci.timing.dir_setup = dir_setup_;
    ci.timing.dir_hold = dir_hold_;
    to_own(rdata_q_, ci.cmd);

    // The edge.
    regs_.commit();
    core_.tick(ci);
    seq(p);
    core_out_ = core_.outputs();
  }

  // The pins after the last edge.
  uint32_t out_a() const { return out_a_; }
  uint32_t out_b() const { return out_b_; }
  bool irq() const { return irq_; }
  bool done() const { return core_out_.done; }
  // Internal state the testbench compares with the RTL's (tb/bus/hls_shadow.h).
  uint32_t fifo_count() const { return cnt_q_; }  // in the RAM, the head not counted
  bool fifo_head() const { return head_q_; }
  uint32_t fifo_level() const { return cnt_q_ + (head_q_ ? 1u : 0u); }
  uint64_t time() const { return time_q_; }
  uint32_t wdog_left() const { return wdog_left_q_; }

 private:
  // A FIFO entry (rtl/motion_soc.sv's ENTRY_W bits, as fields).
  struct Entry {
    bool arc = false, ccw = false, timed = false;
    uint64_t delta[AXES] = {};
    uint32_t plane = 0;
    uint64_t center[2] = {}, end[2] = {};
    uint64_t ops = 0;
    uint32_t feed = 0;
    uint64_t at = 0;
  };

  static constexpr uint64_t mask(int w) { return w >= 64 ? ~0ull : (1ull << w) - 1; }
  static uint64_t sext32(uint64_t v) {
    return static_cast<uint64_t>(static_cast<int64_t>(static_cast<int32_t>(v & 0xFFFFFFFFu)));
  }
  static uint32_t sat32(uint64_t v, int w) {
    const uint64_t lim = w >= 32 ? 0xFFFFFFFFull : (1ull << w) - 1;
    return static_cast<uint32_t>(v > lim ? lim : v);
  }
  static uint32_t feed_sat(uint64_t v) {
    const uint64_t full = 1ull << FEED_W;
    return static_cast<uint32_t>(v > full ? full : v);
  }
  static void to_own(const Entry& e, typename Core::Own& own) {
    own.arc = e.arc;
    for (int i = 0; i < AXES; ++i) own.delta[i] = e.delta[i];
    own.plane = e.plane;
    for (int i = 0; i < 2; ++i) {
      own.center[i] = e.center[i];
      own.end[i] = e.end[i];
    }
    own.ccw = e.ccw;
    own.ops = e.ops;
    own.feed = e.feed;
  }

  // Everything combinational of one clock, from the registers and hwif_out.
  void comb(const motion_soc_regs::HwifOut& o) {
    const uint64_t delta_reg[6] = {o.cmd_delta0.value.value, o.cmd_delta1.value.value,
                                   o.cmd_delta2.value.value, o.cmd_delta3.value.value,
                                   o.cmd_delta4.value.value, o.cmd_delta5.value.value};
    push_entry_ = Entry();
    push_entry_.arc = o.cmd_flags.arc.value & 1;
    for (int i = 0; i < AXES; ++i) push_entry_.delta[i] = sext32(delta_reg[i]) & mask(ACC_W);
    push_entry_.plane = static_cast<uint32_t>(o.cmd_flags.plane.value & 3);
    push_entry_.center[0] = sext32(o.cmd_center0.value.value) & mask(COORD_W);
    push_entry_.center[1] = sext32(o.cmd_center1.value.value) & mask(COORD_W);
    push_entry_.end[0] = sext32(o.cmd_end0.value.value) & mask(COORD_W);
    push_entry_.end[1] = sext32(o.cmd_end1.value.value) & mask(COORD_W);
    push_entry_.ccw = o.cmd_flags.ccw.value & 1;
    push_entry_.ops = o.cmd_ops.value.value & mask(OPS_W);
    push_entry_.feed = feed_sat(o.cmd_feed.value.value) & static_cast<uint32_t>(mask(FEED_W + 1));
    push_entry_.timed = o.cmd_flags.timed.value & 1;
    push_entry_.at = (o.cmd_at.hi.value << 32) | (o.cmd_at.lo.value & 0xFFFFFFFFu);
    feed_word_ = feed_sat(o.feed.value.value) & static_cast<uint32_t>(mask(FEED_W + 1));
    step_len_ = sat32(o.step_len.value.value, TIM_W);
    step_space_ = sat32(o.step_space.value.value, TIM_W);
    dir_setup_ = sat32(o.dir_setup.value.value, TIM_W);
    dir_hold_ = sat32(o.dir_hold.value.value, TIM_W);

    // Time, stop and abort.
    time_hi_d_ = o.time_lo.count.swacc ? static_cast<uint32_t>(time_q_ >> 32) : time_hi_q_;
    const bool estop = (estop_s_q_ >> 1) & 1;
    const bool stopped = o.events.wdog.value || o.events.estop.value;

    // Watchdog.
    const uint64_t period = o.wdog_period.period.value;
    const bool wdog_run = period != 0 && !o.events.wdog.value;
    wdog_kick_d_ = o.wdog_kick.kick.swmod || o.wdog_period.period.swmod;
    const bool bite = wdog_run && !wdog_kick_d_ && !wdog_kick_q_ && wdog_left_q_ <= 1;
    if (!wdog_run || wdog_kick_d_ || wdog_kick_q_)
      wdog_left_d_ = static_cast<uint32_t>(period);
    else if (bite)
      wdog_left_d_ = 0;
    else
      wdog_left_d_ = wdog_left_q_ - 1;

    // Probe filter and latch (before the abort: a latch may stop).
    const bool probe_s = (probe_s_q_ >> 1) & 1;
    probe_f_d_ = probe_f_q_;
    probe_n_d_ = 0;
    if (probe_s != probe_f_q_) {
      if (probe_n_q_ >= o.probe_cfg.filter.value)
        probe_f_d_ = probe_s;
      else
        probe_n_d_ = static_cast<uint16_t>(probe_n_q_ + 1);
    }
    const bool probe_edge =
        o.probe_cfg.falling.value ? (probe_f_q_ && !probe_f_d_) : (!probe_f_q_ && probe_f_d_);
    const bool latch_armed = latch_armed_q_ || o.latch_ctrl.arm.value;
    latch_fire_ = latch_armed && probe_edge;
    const bool latch_stop = latch_fire_ && o.probe_cfg.stop.value;
    latch_armed_d_ = latch_armed && !probe_edge;
    abort_ = o.ctrl.abort_motion.value || bite || estop || latch_stop;

    // The FIFO and its head.
    const bool push = o.cmd_push.push.swmod;
    const uint32_t level = cnt_q_ + (head_q_ ? 1u : 0u);
    const bool full = level == static_cast<uint32_t>(FIFO_DEPTH);
    const bool push_refused = push && (stopped || abort_);
    const bool push_full = push && !push_refused && full;
    push_ok_ = push && !push_refused && !full;
    const bool head_due = !rdata_q_.timed || time_q_ >= rdata_q_.at;
    const bool head_late = rdata_q_.timed && time_q_ > rdata_q_.at;
    cmd_valid_ = head_q_ && head_due && !abort_;
    const bool cmd_take = cmd_valid_ && core_out_.cmd_ready;
    re_ = !abort_ && cnt_q_ != 0 && (!head_q_ || cmd_take);
    cmd_take_ = cmd_take;

    // Speed and step types.
    const uint32_t step = static_cast<uint32_t>(core_out_.step.to_uint());
    const uint32_t dir = static_cast<uint32_t>(core_out_.dir.to_uint());
    rise_ = step & ~step_prev_q_;
    const uint64_t type_reg[6] = {o.step_type.axis0.value, o.step_type.axis1.value,
                                  o.step_type.axis2.value, o.step_type.axis3.value,
                                  o.step_type.axis4.value, o.step_type.axis5.value};
    for (int i = 0; i < AXES; ++i) {
      const uint32_t since = since_q_[i];
      speed_[i] = !((seen_q_ >> i) & 1) ? 0u
                                        : (((neg_q_ >> i) & 1u) << 31) |
                                              (since > period_q_[i] ? since : period_q_[i]);
      type_reg_[i] = static_cast<uint8_t>(type_reg[i] & 3);
    }
    (void)dir;

    // Snapshot.
    const uint64_t snap_at = (o.snap_at.hi.value << 32) | (o.snap_at.lo.value & 0xFFFFFFFFu);
    const bool snap_armed = snap_armed_q_ || o.snap_ctrl.arm.value;
    snap_fire_ = snap_armed && time_q_ >= snap_at;
    snap_armed_d_ = snap_armed && !snap_fire_;

    // hwif_in.
    motion_soc_regs::HwifIn& h = in_;
    h.id_build.axes.next = AXES & 0xF;
    h.id_build.core.next = 1;
    h.id_build.bus.next = BUS & 3;
    h.id_build.step_types.next = 7;
    h.id_build.fifo_depth.next = FIFO_DEPTH & 0xFFFF;
    h.id_widths.acc_w.next = ACC_W & 0xFF;
    h.id_widths.coord_w.next = COORD_W & 0xFF;
    h.id_widths.ops_w.next = OPS_W & 0xFF;
    h.id_widths.pos_w.next = POS_W & 0xFF;
    h.id_widths2.tim_w.next = TIM_W & 0xFF;
    h.id_widths2.feed_w.next = FEED_W & 0xFF;
    h.id_clock.hz.next = CLK_HZ;
    const bool low = (level & 0xFFFF) <= o.fifo_low.mark.value;
    h.status.busy.next = core_out_.busy;
    h.status.fifo_empty.next = level == 0;
    h.status.fifo_full.next = full;
    h.status.low.next = low;
    h.status.probe.next = probe_f_q_;
    h.status.wdog_run.next = wdog_run;
    h.status.stopped.next = stopped;
    h.status.snap_armed.next = snap_armed;
    h.status.latch_armed.next = latch_armed;
    h.status.waiting.next = head_q_ && !head_due;
    h.events.overflow.next = push_full;
    h.events.refused.next = push_refused;
    h.events.late.next = cmd_take && head_late;
    h.events.wdog.next = bite;
    h.events.snap.next = snap_fire_;
    h.events.latch.next = latch_fire_;
    h.events.low_water.next = low;
    h.events.estop.next = estop;
    h.events.done.next = core_out_.done;
    h.fifo_level.fill.next = level & 0xFFFF;
    h.fifo_level.room.next = (static_cast<uint32_t>(FIFO_DEPTH) - level) & 0xFFFF;
    h.time_lo.count.next = time_q_ & 0xFFFFFFFFu;
    h.time_hi.count.next = time_hi_q_;
    h.wdog_left.left.next = wdog_left_q_;
    h.snap_time.count.next = snap_time_q_;
    h.latch_time.count.next = latch_time_q_;
    uint64_t sp[6] = {}, lp[6] = {};
    uint32_t ss[6] = {};
    for (int i = 0; i < AXES; ++i) {
      sp[i] = snap_pos_q_[i];
      lp[i] = latch_pos_q_[i];
      ss[i] = snap_speed_q_[i];
    }
    h.snap_pos0.pos.next = sp[0];
    h.snap_pos1.pos.next = sp[1];
    h.snap_pos2.pos.next = sp[2];
    h.snap_pos3.pos.next = sp[3];
    h.snap_pos4.pos.next = sp[4];
    h.snap_pos5.pos.next = sp[5];
    h.latch_pos0.pos.next = lp[0];
    h.latch_pos1.pos.next = lp[1];
    h.latch_pos2.pos.next = lp[2];
    h.latch_pos3.pos.next = lp[3];
    h.latch_pos4.pos.next = lp[4];
    h.latch_pos5.pos.next = lp[5];
    auto speed = [](auto& f, uint32_t v) {
      f.period.next = v & 0x7FFFFFFFu;
      f.neg.next = v >> 31;
    };
    speed(h.snap_speed0, ss[0]);
    speed(h.snap_speed1, ss[1]);
    speed(h.snap_speed2, ss[2]);
    speed(h.snap_speed3, ss[3]);
    speed(h.snap_speed4, ss[4]);
    speed(h.snap_speed5, ss[5]);
  }

  // The registers at the edge (motion_top ticked already; core_out_ is still
  // the clock's).
  void seq(const Pins& p) {
    const uint32_t step = static_cast<uint32_t>(core_out_.step.to_uint());
    const uint32_t dir = static_cast<uint32_t>(core_out_.dir.to_uint());
    // The FIFO (the RAM reads before it writes, as nonblocking assignments).
    if (re_) rdata_q_ = ram_[rptr_q_];
    if (abort_) {
      rptr_q_ = wptr_q_;
      cnt_q_ = 0;
      head_q_ = false;
    } else {
      if (push_ok_) ram_[wptr_q_] = push_entry_;
      const uint32_t next_w = wptr_q_ == FIFO_DEPTH - 1 ? 0 : wptr_q_ + 1;
      const uint32_t next_r = rptr_q_ == FIFO_DEPTH - 1 ? 0 : rptr_q_ + 1;
      cnt_q_ = cnt_q_ + (push_ok_ ? 1u : 0u) - (re_ ? 1u : 0u);
      head_q_ = re_ || (head_q_ && !cmd_take_);
      if (push_ok_) wptr_q_ = next_w;
      if (re_) rptr_q_ = next_r;
    }
    time_q_ = time_q_ + 1;
    time_hi_q_ = time_hi_d_;
    estop_s_q_ = static_cast<uint8_t>(((estop_s_q_ << 1) | (p.estop ? 1 : 0)) & 3);
    wdog_left_q_ = wdog_left_d_;
    wdog_kick_q_ = wdog_kick_d_;
    for (int i = 0; i < AXES; ++i) {
      const bool r = (rise_ >> i) & 1;
      const uint32_t since = since_q_[i];
      const uint32_t since_inc = since == 0x7FFFFFFFu ? since : since + 1;
      if (r && ((seen_q_ >> i) & 1)) period_q_[i] = since_inc;
      since_q_[i] = r ? 0 : since_inc;
      if (r) {
        neg_q_ = (neg_q_ & ~(1u << i)) | (((dir >> i) & 1u) << i);
        phase_q_[i] =
            static_cast<uint8_t>(((dir >> i) & 1 ? phase_q_[i] - 1 : phase_q_[i] + 1) & 3);
      }
      if (!((step >> i) & 1)) type_q_[i] = type_reg_[i];
      const uint64_t pos = core_out_.pos[i].to_uint64();
      const uint64_t pos64 = (pos >> (POS_W - 1)) & 1 ? pos | ~mask(POS_W) : pos;  // sign-extended
      if (snap_fire_) {
        snap_pos_q_[i] = pos64;
        snap_speed_q_[i] = speed_[i];
      }
      if (latch_fire_) latch_pos_q_[i] = pos64;
    }
    seen_q_ |= rise_;
    step_prev_q_ = step;
    probe_s_q_ = static_cast<uint8_t>(((probe_s_q_ << 1) | (p.probe ? 1 : 0)) & 3);
    probe_f_q_ = probe_f_d_;
    probe_n_q_ = probe_n_d_;
    latch_armed_q_ = latch_armed_d_;
    snap_armed_q_ = snap_armed_d_;
    if (snap_fire_) snap_time_q_ = time_q_ - 1;
    if (latch_fire_) latch_time_q_ = time_q_ - 1;
    // The pins after the edge.
    const uint32_t step_n = static_cast<uint32_t>(core_.outputs().step.to_uint());
    const uint32_t dir_n = static_cast<uint32_t>(core_.outputs().dir.to_uint());
    out_a_ = out_b_ = 0;
    for (int i = 0; i < AXES; ++i) {
      const uint32_t s = (step_n >> i) & 1, d = (dir_n >> i) & 1;
      uint32_t a = s, b = d;
      if (type_q_[i] == 1) {
        a = s & !d;
        b = s & d;
      } else if (type_q_[i] == 2) {
        a = ((phase_q_[i] >> 1) ^ phase_q_[i]) & 1;
        b = (phase_q_[i] >> 1) & 1;
      }
      out_a_ |= a << i;
      out_b_ |= b << i;
    }
    motion_soc_regs::HwifOut o;
    regs_.outputs(o);
    irq_ = (o.events.overflow.value && o.irq_en.overflow.value) ||
           (o.events.refused.value && o.irq_en.refused.value) ||
           (o.events.late.value && o.irq_en.late.value) ||
           (o.events.wdog.value && o.irq_en.wdog.value) ||
           (o.events.snap.value && o.irq_en.snap.value) ||
           (o.events.latch.value && o.irq_en.latch.value) ||
           (o.events.low_water.value && o.irq_en.low_water.value) ||
           (o.events.estop.value && o.irq_en.estop.value) ||
           (o.events.done.value && o.irq_en.done.value);
  }

  Regs regs_;
  motion_soc_regs::HwifIn in_;
  Core core_;
  typename Core::Outputs core_out_;  // motion_top's pins after the last edge
  Entry ram_[FIFO_DEPTH];
  Entry rdata_q_;  // the RAM's read register: the head
  uint32_t wptr_q_, rptr_q_, cnt_q_;
  bool head_q_;
  uint64_t time_q_;
  uint32_t time_hi_q_;
  uint8_t estop_s_q_;
  uint32_t wdog_left_q_;
  bool wdog_kick_q_;
  uint32_t step_prev_q_, seen_q_, neg_q_;
  uint32_t since_q_[AXES], period_q_[AXES];
  uint8_t type_q_[AXES], phase_q_[AXES];
  uint8_t probe_s_q_;
  bool probe_f_q_;
  uint16_t probe_n_q_;
  bool latch_armed_q_, snap_armed_q_;
  uint64_t snap_time_q_, latch_time_q_;
  uint64_t snap_pos_q_[AXES], latch_pos_q_[AXES];
  uint32_t snap_speed_q_[AXES];

  // This clock's combinational values (comb() to seq()).
  Entry push_entry_;
  bool push_ok_ = false, re_ = false, abort_ = false, cmd_valid_ = false, cmd_take_ = false;
  bool latch_fire_ = false, snap_fire_ = false, latch_armed_d_ = false, snap_armed_d_ = false;
  bool wdog_kick_d_ = false, probe_f_d_ = false;
  uint16_t probe_n_d_ = 0;
  uint32_t wdog_left_d_ = 0, time_hi_d_ = 0, rise_ = 0;
  uint32_t feed_word_ = 0, step_len_ = 0, step_space_ = 0, dir_setup_ = 0, dir_hold_ = 0;
  uint32_t speed_[AXES] = {};
  uint8_t type_reg_[AXES] = {};
  uint32_t out_a_ = 0, out_b_ = 0;
  bool irq_ = false;
};

}  // namespace hwinterp::hls

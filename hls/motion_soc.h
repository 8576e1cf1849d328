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
//
// PROFILE = 1: the feed profile (hls/feed_profile.h, at rtl/motion_soc.sv's
// default profile widths: SPD_W 48, TICK_W 10, LEN_W 10, PROF_LVL_W 16,
// MV_OPS_W 28) drives motion_top's feed, the moves come from the FIFO's
// second read pointer, the exact-stop rule and the watchdog's controlled stop
// as rtl/motion_soc.sv states them.
#pragma once

#include <cstdint>

#include "hls/feed_profile.h"
#include "hls/gen/motion_soc_regs.h"
#include "hls/motion_top.h"
#include "hls/step_encode.h"

namespace hwinterp::hls {

// The SoC between the register block's CPU interface and the step outputs.
template <class Cfg, int FIFO_DEPTH = 16, int BUS = 0, uint32_t CLK_HZ = 50000000, int PROFILE = 0>
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
  static_assert(PROFILE == 0 || PROFILE == 1, "PROFILE must be 0 or 1");
  // The feed profile's widths (rtl/motion_soc.sv's defaults).
  static constexpr int SPD_W = 48, TICK_W = 10, LEN_W = 10, PROF_LVL_W = 16, MV_OPS_W = 28;
  using Core = MotionTop<Cfg>;
  using Profile = FeedProfile<FEED_W, SPD_W, TICK_W, LEN_W, PROF_LVL_W, MV_OPS_W>;
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
    mrptr_q_ = mcnt_q_ = 0;
    mhead_q_ = stop_open_q_ = wstop_q_ = prof_clr_q_ = false;
    if constexpr (PROFILE != 0) prof_.reset();
    step_prev_q_ = seen_q_ = neg_q_ = 0;
    probe_s_q_ = 0;
    probe_f_q_ = false;
    probe_n_q_ = 0;
    latch_armed_q_ = snap_armed_q_ = false;
    snap_time_q_ = latch_time_q_ = 0;
    for (int i = 0; i < AXES; ++i) {
      since_q_[i] = period_q_[i] = 0;
      encode_[i].reset();
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
    ci.feed = PROFILE != 0 ? static_cast<uint32_t>(prof_.feed()) : feed_word_;
    ci.timing.step_len = step_len_;
    ci.timing.step_space = step_space_;
    ci.timing.dir_setup = dir_setup_;
    ci.timing.dir_hold = dir_hold_;
    to_own(rdata_q_, ci.cmd);

    // The edge.
    regs_.commit();
    core_.tick(ci);
    if constexpr (PROFILE != 0) {
      // The profile's reset is rst_ni && !prof_clr_q: held on a clock with
      // prof_clr_q, and asserted right after the edge that sets it.
      if (!prof_clr_q_) prof_.clock(mv_valid_, mv_cmd_, prof_hold_, prof_q_, prof_len_, prof_ovr_);
      if (prof_clr_d_) prof_.reset();
    }
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
  uint32_t move_count() const { return mcnt_q_; }  // the moves' RAM count (PROFILE)
  bool move_head() const { return mhead_q_; }
  uint64_t profile_feed() const { return PROFILE != 0 ? prof_.feed() : 0; }
  const Profile& profile() const { return prof_; }

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
  // A move entry (the profile's FIFO).
  struct Move {
    uint64_t ops = 0;
    uint32_t target = 0, end = 0, max = 0;
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
    push_move_.ops = o.cmd_mv_ops.value.value & mask(MV_OPS_W);
    push_move_.target = static_cast<uint32_t>(o.cmd_mv_target.value.value & mask(PROF_LVL_W));
    push_move_.end = static_cast<uint32_t>(o.cmd_mv_end.value.value & mask(PROF_LVL_W));
    push_move_.max = static_cast<uint32_t>(o.cmd_mv_max.value.value & mask(PROF_LVL_W));
    // The profile's registers: q modulo 2^SPD_W, L saturated at 2^LEN_W.
    prof_q_ = ((o.prof_q.hi.value << 32) | (o.prof_q.lo.value & 0xFFFFFFFFu)) & mask(SPD_W);
    const uint64_t len = o.prof_len.value.value;
    prof_len_ = static_cast<unsigned>(len > (1u << LEN_W) ? (1u << LEN_W) : len);
    prof_ovr_ = static_cast<unsigned>(o.prof_ctrl.ovr.value & 511u);
    prof_hold_ = o.prof_ctrl.hold.value || wstop_q_;
    // The profile's outputs of this clock (reset values while cleared).
    const uint64_t p_feed = PROFILE != 0 ? prof_.feed() : 0;
    const uint64_t p_speed = PROFILE != 0 ? prof_.state().v : 0;
    const uint32_t p_level = PROFILE != 0 ? prof_.state().c : 0;
    const bool p_busy = PROFILE != 0 && prof_.busy();
    const bool p_ready = PROFILE != 0 && prof_.cmd_ready();
    feed_word_ = feed_sat(o.feed.value.value) & static_cast<uint32_t>(mask(FEED_W + 1));
    step_len_ = sat32(o.step_len.value.value, TIM_W);
    step_space_ = sat32(o.step_space.value.value, TIM_W);
    dir_setup_ = sat32(o.dir_setup.value.value, TIM_W);
    dir_hold_ = sat32(o.dir_hold.value.value, TIM_W);

    // Time, stop and abort.
    time_hi_d_ = o.time_lo.count.swacc ? static_cast<uint32_t>(time_q_ >> 32) : time_hi_q_;
    const bool estop = (estop_s_q_ >> 1) & 1;
    const bool stopped = o.events.wdog.value || o.events.estop.value || wstop_q_;

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
    // Without the profile the bite aborts; with it, the controlled stop's end.
    const uint32_t step_now = static_cast<uint32_t>(core_out_.step.to_uint());
    const bool prof_rest = p_speed == 0 && p_feed == 0 && step_now == 0;
    const bool wstop_done = PROFILE != 0 && wstop_q_ && prof_rest;
    abort_ =
        o.ctrl.abort_motion.value || (PROFILE == 0 && bite) || wstop_done || estop || latch_stop;
    wstop_d_ = PROFILE != 0 && !abort_ && (bite || wstop_q_);
    prof_clr_d_ = PROFILE != 0 && abort_;

    // The FIFO and its head.
    const bool push = o.cmd_push.push.swmod;
    const uint32_t level_c = cnt_q_ + (head_q_ ? 1u : 0u);
    const uint32_t level_m = mcnt_q_ + (mhead_q_ ? 1u : 0u);
    const uint32_t level = level_m > level_c ? level_m : level_c;
    const bool full = level == static_cast<uint32_t>(FIFO_DEPTH);
    const bool push_refused =
        push && (stopped || abort_ || (PROFILE != 0 && o.cmd_flags.timed.value));
    const bool push_full = push && !push_refused && full;
    push_ok_ = push && !push_refused && !full;
    const bool head_due = !rdata_q_.timed || time_q_ >= rdata_q_.at;
    const bool head_late = rdata_q_.timed && time_q_ > rdata_q_.at;
    // The exact-stop rule, and the moves' side of the FIFO.
    const bool stop_wait = stop_open_q_ && p_busy;
    const bool cmd_hold = stop_wait && level_c <= level_m;
    cmd_valid_ = head_q_ && head_due && !abort_ && !cmd_hold;
    const bool cmd_take = cmd_valid_ && core_out_.cmd_ready;
    re_ = !abort_ && cnt_q_ != 0 && (!head_q_ || cmd_take);
    cmd_take_ = cmd_take;
    mv_valid_ = mhead_q_ && !abort_ && !stop_wait && !prof_clr_q_;
    mv_take_ = mv_valid_ && p_ready;
    mre_ = !abort_ && mcnt_q_ != 0 && (!mhead_q_ || mv_take_);
    stop_open_d_ = !abort_ && (mv_take_ ? mrdata_q_.end == 0 : stop_wait);
    mv_cmd_.ops = mrdata_q_.ops;
    mv_cmd_.target = mrdata_q_.target;
    mv_cmd_.end = mrdata_q_.end;
    mv_cmd_.max = mrdata_q_.max;

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
    h.id_build.profile.next = PROFILE != 0;
    if constexpr (PROFILE != 0) {
      h.id_profile.spd_w.next = SPD_W;
      h.id_profile.tick_w.next = TICK_W;
      h.id_profile.len_w.next = LEN_W;
      h.id_profile.lvl_w.next = PROF_LVL_W;
    }
    h.prof_level.c.next = p_level;
    h.prof_speed.speed.next = p_speed;
    h.status.prof_busy.next = p_busy;
    h.status.wdog_stopping.next = wstop_q_;
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
    if constexpr (PROFILE != 0) {
      if (mre_) mrdata_q_ = mram_[mrptr_q_];
    }
    if (abort_) {
      rptr_q_ = wptr_q_;
      cnt_q_ = 0;
      head_q_ = false;
      mrptr_q_ = wptr_q_;
      mcnt_q_ = 0;
      mhead_q_ = false;
    } else {
      if constexpr (PROFILE != 0) {
        if (push_ok_) mram_[wptr_q_] = push_move_;
        mcnt_q_ = mcnt_q_ + (push_ok_ ? 1u : 0u) - (mre_ ? 1u : 0u);
        mhead_q_ = mre_ || (mhead_q_ && !mv_take_);
        if (mre_) mrptr_q_ = mrptr_q_ == FIFO_DEPTH - 1 ? 0 : mrptr_q_ + 1;
      }
      if (push_ok_) ram_[wptr_q_] = push_entry_;
      const uint32_t next_w = wptr_q_ == FIFO_DEPTH - 1 ? 0 : wptr_q_ + 1;
      const uint32_t next_r = rptr_q_ == FIFO_DEPTH - 1 ? 0 : rptr_q_ + 1;
      cnt_q_ = cnt_q_ + (push_ok_ ? 1u : 0u) - (re_ ? 1u : 0u);
      head_q_ = re_ || (head_q_ && !cmd_take_);
      if (push_ok_) wptr_q_ = next_w;
      if (re_) rptr_q_ = next_r;
    }
    stop_open_q_ = stop_open_d_;
    wstop_q_ = wstop_d_;
    prof_clr_q_ = prof_clr_d_;
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
      if (r) neg_q_ = (neg_q_ & ~(1u << i)) | (((dir >> i) & 1u) << i);
      encode_[i].clock(type_reg_[i], (step >> i) & 1, (dir >> i) & 1);
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
      const bool s = (step_n >> i) & 1, d = (dir_n >> i) & 1;
      out_a_ |= uint32_t{encode_[i].a(s, d)} << i;
      out_b_ |= uint32_t{encode_[i].b(s, d)} << i;
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
  // The moves' side (PROFILE): its RAM, read register, pointer, count, head.
  Move mram_[PROFILE != 0 ? FIFO_DEPTH : 1];
  Move mrdata_q_;
  uint32_t mrptr_q_, mcnt_q_;
  bool mhead_q_, stop_open_q_, wstop_q_, prof_clr_q_;
  Profile prof_;
  uint64_t time_q_;
  uint32_t time_hi_q_;
  uint8_t estop_s_q_;
  uint32_t wdog_left_q_;
  bool wdog_kick_q_;
  uint32_t step_prev_q_, seen_q_, neg_q_;
  uint32_t since_q_[AXES], period_q_[AXES];
  StepEncode encode_[AXES];  // the step output types (rtl/step_encode.sv)
  uint8_t probe_s_q_;
  bool probe_f_q_;
  uint16_t probe_n_q_;
  bool latch_armed_q_, snap_armed_q_;
  uint64_t snap_time_q_, latch_time_q_;
  uint64_t snap_pos_q_[AXES], latch_pos_q_[AXES];
  uint32_t snap_speed_q_[AXES];

  // This clock's combinational values (comb() to seq()).
  Entry push_entry_;
  Move push_move_;
  typename Profile::Command mv_cmd_;
  bool mv_valid_ = false, mv_take_ = false, mre_ = false, stop_open_d_ = false;
  bool wstop_d_ = false, prof_clr_d_ = false, prof_hold_ = false;
  uint64_t prof_q_ = 0;
  unsigned prof_len_ = 1, prof_ovr_ = 128;
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

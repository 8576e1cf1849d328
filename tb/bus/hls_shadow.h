// motion_soc's HLS face (hls/motion_soc.h, hls/motion_soc_bus.h) in
// lockstep with a Verilated motion_soc top (tb/bus/soc_run.h): it takes the
// very pins the bus master drives into the Verilated model on every clock,
// and is compared with it on every clock:
//   - AXI4-Lite: after the edge, every subordinate output (awready, wready,
//     bvalid, bresp, arready, rvalid, rresp, and rdata while rvalid);
//   - Wishbone: in the clock of the request, ack, err, and dat_o on a read's
//     ack;
//   - both: after the edge, out_a_o and out_b_o of every axis, irq_o, and
//     motion_top's done_o; and inside motion_soc (read through
//     tb/bus/motion_soc_probe.vlt) the FIFO's count and head, TIME and the
//     watchdog's count; with the feed profile (PROFILE = 1) also the moves'
//     count and head and the profile's feed word.
// The first difference ends the run; it is reported with its clock.
#pragma once

#include <cstdint>

#include "hls/motion_soc.h"
#include "hls/motion_soc_bus.h"

namespace hwinterp::tb::bus {

struct ShadowMismatch {
  uint64_t clock = 0;  // clock edge after reset (0: none)
  const char* what = "";
  uint64_t hls = 0, rtl = 0;
};

// No HLS face: the bus run alone.
struct NoShadow {
  template <class M>
  void before_edge(const M&) {}
  template <class M>
  void after_edge(const M&, bool, uint64_t) {}
  bool failed() const { return false; }
  const ShadowMismatch& mismatch() const { return mm_; }
  ShadowMismatch mm_;
};

template <class Self>
class ShadowBase {
 public:
  bool failed() const { return mm_.clock != 0; }
  const ShadowMismatch& mismatch() const { return mm_; }

 protected:
  bool differ(uint64_t clock, const char* what, uint64_t hls, uint64_t rtl) {
    if (hls == rtl || failed()) return hls != rtl;
    mm_ = {clock, what, hls, rtl};
    return true;
  }
  // The RTL's internal values as motion_soc's registers hold them.
  struct Inside {
    uint64_t cnt, head, time, wdog_left, mcnt, mhead, prof_feed;
  };
  template <class Soc, class M>
  void compare_pins(const Soc& soc, const M& m, bool done, const Inside& in, uint64_t clock,
                    uint32_t mask) {
    differ(clock, "out_a_o", soc.out_a() & mask, m.out_a_o & mask) ||
        differ(clock, "out_b_o", soc.out_b() & mask, m.out_b_o & mask) ||
        differ(clock, "irq_o", soc.irq(), m.irq_o) || differ(clock, "done", soc.done(), done) ||
        differ(clock, "u_soc.cnt_q", soc.fifo_count(), in.cnt) ||
        differ(clock, "u_soc.head_q", soc.fifo_head(), in.head) ||
        differ(clock, "u_soc.time_q", soc.time(), in.time) ||
        differ(clock, "u_soc.wdog_left_q", soc.wdog_left(), in.wdog_left) ||
        differ(clock, "u_soc.mcnt_q", soc.move_count(), in.mcnt) ||
        differ(clock, "u_soc.mhead_q", soc.move_head(), in.mhead) ||
        differ(clock, "u_soc.prof_feed", soc.profile_feed(), in.prof_feed);
  }
  ShadowMismatch mm_;
};

// PROFILE: the tops with the feed profile (SocOf<Cfg>::AxilProf, WbProf).
template <class Cfg, int PROFILE = 0>
class AxilShadow : public ShadowBase<AxilShadow<Cfg, PROFILE>> {
 public:
  using Soc = hls::MotionSoc<Cfg, 16, 0, 50000000, PROFILE>;
  template <class M>
  void before_edge(const M& m) {
    hls::AxilIn in;
    in.awvalid = m.s_axil_awvalid_i;
    in.awaddr = m.s_axil_awaddr_i;
    in.wvalid = m.s_axil_wvalid_i;
    in.wdata = m.s_axil_wdata_i;
    in.wstrb = m.s_axil_wstrb_i;
    in.bready = m.s_axil_bready_i;
    in.arvalid = m.s_axil_arvalid_i;
    in.araddr = m.s_axil_araddr_i;
    in.rready = m.s_axil_rready_i;
    typename Soc::Pins p;
    p.rst_n = m.rst_ni;
    p.probe = m.probe_i;
    p.estop = m.estop_i;
    face_.tick(p, in);
  }
  template <class M>
  void after_edge(const M& m, bool done, uint64_t clock) {
    const hls::AxilOut o = face_.outputs();
    this->differ(clock, "s_axil_awready_o", o.awready, m.s_axil_awready_o) ||
        this->differ(clock, "s_axil_wready_o", o.wready, m.s_axil_wready_o) ||
        this->differ(clock, "s_axil_arready_o", o.arready, m.s_axil_arready_o) ||
        this->differ(clock, "s_axil_bvalid_o", o.bvalid, m.s_axil_bvalid_o) ||
        this->differ(clock, "s_axil_rvalid_o", o.rvalid, m.s_axil_rvalid_o) ||
        (o.bvalid && this->differ(clock, "s_axil_bresp_o", o.bresp, m.s_axil_bresp_o)) ||
        (o.rvalid && this->differ(clock, "s_axil_rresp_o", o.rresp, m.s_axil_rresp_o)) ||
        (o.rvalid && this->differ(clock, "s_axil_rdata_o", o.rdata, m.s_axil_rdata_o));
    const auto* r = m.rootp;
    const typename ShadowBase<AxilShadow<Cfg, PROFILE>>::Inside in{
        r->motion_soc_axil__DOT__u_soc__DOT__cnt_q,
        r->motion_soc_axil__DOT__u_soc__DOT__head_q,
        r->motion_soc_axil__DOT__u_soc__DOT__time_q,
        r->motion_soc_axil__DOT__u_soc__DOT__wdog_left_q,
        r->motion_soc_axil__DOT__u_soc__DOT__mcnt_q,
        r->motion_soc_axil__DOT__u_soc__DOT__mhead_q,
        r->motion_soc_axil__DOT__u_soc__DOT__prof_feed};
    this->compare_pins(face_.soc(), m, done, in, clock, (1u << Cfg::AXES) - 1);
  }

 private:
  hls::MotionSocAxil<Soc> face_;
};

template <class Cfg, int PROFILE = 0>
class WbShadow : public ShadowBase<WbShadow<Cfg, PROFILE>> {
 public:
  using Soc = hls::MotionSoc<Cfg, 16, 1, 50000000, PROFILE>;
  // The pins are settled (clk_i low): Wishbone answers in this clock.
  template <class M>
  void before_edge(const M& m) {
    hls::WbIn in;
    in.cyc = m.wb_cyc_i;
    in.stb = m.wb_stb_i;
    in.we = m.wb_we_i;
    in.adr = m.wb_adr_i;
    in.dat = m.wb_dat_i;
    in.sel = m.wb_sel_i;
    typename Soc::Pins p;
    p.rst_n = m.rst_ni;
    p.probe = m.probe_i;
    p.estop = m.estop_i;
    hls::WbOut o;
    face_.tick(p, in, o);
    if (!p.rst_n) return;
    this->differ(clock_ + 1, "wb_ack_o", o.ack, m.wb_ack_o) ||
        this->differ(clock_ + 1, "wb_err_o", o.err, m.wb_err_o) ||
        this->differ(clock_ + 1, "wb_stall_o", o.stall, m.wb_stall_o) ||
        (o.ack && !in.we && this->differ(clock_ + 1, "wb_dat_o", o.dat, m.wb_dat_o));
  }
  template <class M>
  void after_edge(const M& m, bool done, uint64_t clock) {
    clock_ = clock;
    const auto* r = m.rootp;
    const typename ShadowBase<WbShadow<Cfg, PROFILE>>::Inside in{
        r->motion_soc_wb__DOT__u_soc__DOT__cnt_q,    r->motion_soc_wb__DOT__u_soc__DOT__head_q,
        r->motion_soc_wb__DOT__u_soc__DOT__time_q,   r->motion_soc_wb__DOT__u_soc__DOT__wdog_left_q,
        r->motion_soc_wb__DOT__u_soc__DOT__mcnt_q,   r->motion_soc_wb__DOT__u_soc__DOT__mhead_q,
        r->motion_soc_wb__DOT__u_soc__DOT__prof_feed};
    this->compare_pins(face_.soc(), m, done, in, clock, (1u << Cfg::AXES) - 1);
  }

 private:
  hls::MotionSocWb<Soc> face_;
  uint64_t clock_ = 0;
};

}  // namespace hwinterp::tb::bus

// The bus faces of motion_soc's HLS face (hls/motion_soc.h), clock for clock
// as rtl/motion_soc_axil.sv and rtl/motion_soc_wb.sv: PeakRDL-regblock's
// AXI4-Lite CPU interface (its acceptance registers for AR, AW and W, at most
// two transactions in flight, a two-entry response buffer; responses one
// clock after the request reaches the block) and its Wishbone interface
// (the request is the pins; ack or err, and the data, in the clock of the
// request; motion_soc_wb gates stb with cyc and masks ack with err). Pins as
// plain integers; the names follow the SystemVerilog tops.
#pragma once

#include <cstdint>

#include "hls/gen/motion_soc_regs.h"
#include "hls/motion_soc.h"

namespace hwinterp::hls {

struct AxilIn {
  bool awvalid = false, wvalid = false, bready = false, arvalid = false, rready = false;
  uint32_t awaddr = 0, wdata = 0, araddr = 0;
  uint32_t wstrb = 0;
};
struct AxilOut {
  bool awready = false, wready = false, bvalid = false, arready = false, rvalid = false;
  uint32_t bresp = 0, rresp = 0, rdata = 0;
};

// motion_soc_axil.
template <class Soc>
class MotionSocAxil {
 public:
  static constexpr uint32_t kAddrMask = (1u << motion_soc_regs::kAddrWidth) - 1;
  MotionSocAxil() { reset(); }
  void reset() {
    soc_.reset();
    prev_was_rd_ = arvalid_ = awvalid_ = wvalid_ = false;
    araddr_ = awaddr_ = wdata_ = wstrb_ = 0;
    n_in_flight_ = 0;
    for (auto& r : resp_) r = Resp();
    resp_wptr_ = resp_rptr_ = 0;
    dispatch();
  }

  // One rising edge with the pins of the clock.
  void tick(const typename Soc::Pins& p, const AxilIn& in) {
    if (!p.rst_n) {
      reset();
      motion_soc_regs::Response r;
      soc_.tick(p, motion_soc_regs::Request(), r);
      return;
    }
    // The request this clock (from the acceptance registers alone).
    motion_soc_regs::Request rq;
    const bool ar_accept = ar_accept_, aw_accept = aw_accept_;
    rq.req = req_;
    rq.is_wr = req_is_wr_;
    rq.addr = req_addr_;
    rq.wr_data = wdata_;
    rq.wr_biten = biten(wstrb_);
    const bool arready = !arvalid_ || ar_accept, awready = !awvalid_ || aw_accept,
               wready = !wvalid_ || aw_accept;
    // The response side.
    bool resp_acked = false;
    if (resp_rptr_ != resp_wptr_) {
      const Resp& r = resp_[resp_rptr_ & 1];
      resp_acked = r.is_wr ? in.bready : in.rready;
    }
    motion_soc_regs::Response rsp;
    soc_.tick(p, rq, rsp);

    // The acceptance registers.
    if (ar_accept) {
      prev_was_rd_ = true;
      arvalid_ = false;
    }
    if (in.arvalid && arready) {
      arvalid_ = true;
      araddr_ = in.araddr & kAddrMask;
    }
    if (aw_accept) {
      prev_was_rd_ = false;
      awvalid_ = false;
      wvalid_ = false;
    }
    if (in.awvalid && awready) {
      awvalid_ = true;
      awaddr_ = in.awaddr & kAddrMask;
    }
    if (in.wvalid && wready) {
      wvalid_ = true;
      wdata_ = in.wdata;
      wstrb_ = in.wstrb & 0xF;
    }
    if ((ar_accept || aw_accept) && !resp_acked)
      n_in_flight_ = (n_in_flight_ + 1) & 3;
    else if (!(ar_accept || aw_accept) && resp_acked)
      n_in_flight_ = (n_in_flight_ - 1) & 3;
    // The response buffer.
    if (rsp.rd_ack || rsp.wr_ack) {
      Resp& w = resp_[resp_wptr_ & 1];
      w.is_wr = !rsp.rd_ack;
      w.err = rsp.rd_ack ? rsp.rd_err : rsp.wr_err;
      if (rsp.rd_ack) w.rdata = rsp.rd_data;
      resp_wptr_ = (resp_wptr_ + 1) & 3;
    }
    if (resp_acked) resp_rptr_ = (resp_rptr_ + 1) & 3;
    dispatch();
  }

  // The bus pins after the last edge (they depend on the registers alone).
  AxilOut outputs() const {
    AxilOut o;
    o.arready = !arvalid_ || ar_accept_;
    o.awready = !awvalid_ || aw_accept_;
    o.wready = !wvalid_ || aw_accept_;
    if (resp_rptr_ != resp_wptr_) {
      const Resp& r = resp_[resp_rptr_ & 1];
      o.bvalid = r.is_wr;
      o.rvalid = !r.is_wr;
    }
    const Resp& r = resp_[resp_rptr_ & 1];
    o.rdata = r.rdata;
    o.bresp = o.rresp = r.err ? 2u : 0u;
    return o;
  }
  const Soc& soc() const { return soc_; }

 private:
  struct Resp {
    bool is_wr = false, err = false;
    uint32_t rdata = 0;
  };
  static uint32_t biten(uint32_t strb) {
    uint32_t b = 0;
    for (int i = 0; i < 4; ++i)
      if ((strb >> i) & 1) b |= 0xFFu << (8 * i);
    return b;
  }
  // Request dispatch (regblock's, no stalls): reads and writes alternate.
  void dispatch() {
    req_ = req_is_wr_ = ar_accept_ = aw_accept_ = false;
    req_addr_ = 0;
    if (n_in_flight_ < 2) {
      if (arvalid_ && !prev_was_rd_) {
        req_ = true;
        req_addr_ = araddr_ & ~3u;
        ar_accept_ = true;
      } else if (awvalid_ && wvalid_) {
        req_ = req_is_wr_ = true;
        req_addr_ = awaddr_ & ~3u;
        aw_accept_ = true;
      } else if (arvalid_) {
        req_ = true;
        req_addr_ = araddr_ & ~3u;
        ar_accept_ = true;
      }
    }
  }

  Soc soc_;
  bool prev_was_rd_, arvalid_, awvalid_, wvalid_;
  uint32_t araddr_, awaddr_, wdata_, wstrb_;
  uint32_t n_in_flight_;
  Resp resp_[2];
  uint32_t resp_wptr_, resp_rptr_;
  bool req_ = false, req_is_wr_ = false, ar_accept_ = false, aw_accept_ = false;
  uint32_t req_addr_ = 0;
};

struct WbIn {
  bool cyc = false, stb = false, we = false;
  uint32_t adr = 0;  // word address
  uint32_t dat = 0, sel = 0;
};
struct WbOut {
  bool ack = false, err = false, stall = false;
  uint32_t dat = 0;
};

// motion_soc_wb.
template <class Soc>
class MotionSocWb {
 public:
  void reset() { soc_.reset(); }
  // One rising edge; `out` gets the clock's response pins (before the edge).
  void tick(const typename Soc::Pins& p, const WbIn& in, WbOut& out) {
    motion_soc_regs::Request rq;
    rq.req = in.cyc && in.stb;
    rq.is_wr = in.we;
    rq.addr = (in.adr << 2) & ((1u << motion_soc_regs::kAddrWidth) - 1);
    rq.wr_data = in.dat;
    rq.wr_biten = 0;
    for (int i = 0; i < 4; ++i)
      if ((in.sel >> i) & 1) rq.wr_biten |= 0xFFu << (8 * i);
    motion_soc_regs::Response rsp;
    soc_.tick(p, rq, rsp);
    const bool err = rsp.rd_err || rsp.wr_err;
    out.err = p.rst_n && err;
    out.ack = p.rst_n && (rsp.rd_ack || rsp.wr_ack) && !err;
    out.dat = rsp.rd_data;
    out.stall = false;
  }
  const Soc& soc() const { return soc_; }

 private:
  Soc soc_;
};

}  // namespace hwinterp::hls

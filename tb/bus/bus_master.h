// Bus masters for the lockstep harness: an AXI4-Lite master and a Wishbone
// B4 classic master, clocked with a `verilator --cc` model of
// rtl/motion_soc_axil.sv or rtl/motion_soc_wb.sv (M: the Verilated class,
// its pins named as those tops'). One transaction in flight; the caller
// issues the next when the master is idle. Optional wait states: before each
// valid (AXI: address, data; Wishbone: the cycle) and before each ready of a
// response (AXI: bready, rready), a random 0..WaitStates::max clocks, from
// the master's own xorshift generator (no allocation, no virtual call).
//
// The clock, as the harness drives it (tb/bus/soc_run.h):
//   master.drive(m); m.clk_i = 0; m.eval();   // this clock's pins, settled
//   master.sample(m);                         // the handshakes at this edge
//   m.clk_i = 1; m.eval();                    // the edge
//   if (master.take(rsp)) ...                 // a transaction that ended
// A handshake is what both sides show before the edge (AXI: valid && ready;
// Wishbone classic: stb && (ack || err), acknowledged in the clock of the
// request by motion_soc_wb).
#pragma once

#include <cstdint>

namespace hwinterp::tb::bus {

enum class BusKind { kAxi4Lite, kWishbone };

struct BusTxn {
  bool write = false;
  uint32_t addr = 0;  // byte address
  uint32_t data = 0;
  uint8_t strb = 0xF;  // byte enables (AXI wstrb, Wishbone sel)
};
struct BusRsp {
  BusTxn txn;         // what it answers
  bool err = false;   // SLVERR / err_o
  uint32_t data = 0;  // read data
};

struct WaitStates {
  uint32_t max = 0;  // 0: none
  uint64_t seed = 1;
};

// xorshift64*: the masters' wait states.
class WaitRng {
 public:
  explicit WaitRng(const WaitStates& w) : max_(w.max), s_(w.seed ? w.seed : 1) {}
  uint32_t draw() {
    if (max_ == 0) return 0;
    s_ ^= s_ >> 12;
    s_ ^= s_ << 25;
    s_ ^= s_ >> 27;
    return static_cast<uint32_t>(((s_ * 0x2545F4914F6CDD1Dull) >> 33) % (max_ + 1));
  }

 private:
  uint32_t max_;
  uint64_t s_;
};

// AXI4-Lite: AW and W raised independently (each after its wait), held to
// their handshakes; then B (or AR, then R) with bready (rready) after a wait.
template <class M>
class Axi4LiteMaster {
 public:
  static constexpr BusKind kKind = BusKind::kAxi4Lite;
  explicit Axi4LiteMaster(const WaitStates& w = {}) : rng_(w) {}

  bool idle() const { return state_ == State::kIdle; }
  void issue(const BusTxn& t) {
    txn_ = t;
    state_ = t.write ? State::kWrite : State::kRead;
    a_done_ = w_done_ = false;
    a_wait_ = rng_.draw();
    w_wait_ = rng_.draw();
    r_wait_ = rng_.draw();
  }
  void drive(M& m) const {
    const bool wr = state_ == State::kWrite, rd = state_ == State::kRead;
    m.s_axil_awvalid_i = wr && !a_done_ && a_wait_ == 0;
    m.s_axil_awaddr_i = txn_.addr;
    m.s_axil_awprot_i = 0;
    m.s_axil_wvalid_i = wr && !w_done_ && w_wait_ == 0;
    m.s_axil_wdata_i = txn_.data;
    m.s_axil_wstrb_i = txn_.strb;
    m.s_axil_bready_i = state_ == State::kWriteResp && r_wait_ == 0;
    m.s_axil_arvalid_i = rd && a_wait_ == 0;
    m.s_axil_araddr_i = txn_.addr;
    m.s_axil_arprot_i = 0;
    m.s_axil_rready_i = state_ == State::kReadResp && r_wait_ == 0;
  }
  void sample(const M& m) {
    switch (state_) {
      case State::kIdle:
        break;
      case State::kWrite:
        if (m.s_axil_awvalid_i && m.s_axil_awready_o) a_done_ = true;
        if (m.s_axil_wvalid_i && m.s_axil_wready_o) w_done_ = true;
        if (!a_done_ && a_wait_) --a_wait_;
        if (!w_done_ && w_wait_) --w_wait_;
        if (a_done_ && w_done_) state_ = State::kWriteResp;
        break;
      case State::kRead:
        if (m.s_axil_arvalid_i && m.s_axil_arready_o)
          state_ = State::kReadResp;
        else if (a_wait_)
          --a_wait_;
        break;
      case State::kWriteResp:
        if (m.s_axil_bvalid_o && m.s_axil_bready_i)
          finish(m.s_axil_bresp_o != 0, 0);
        else if (r_wait_)
          --r_wait_;
        break;
      case State::kReadResp:
        if (m.s_axil_rvalid_o && m.s_axil_rready_i)
          finish(m.s_axil_rresp_o != 0, m.s_axil_rdata_o);
        else if (r_wait_)
          --r_wait_;
        break;
    }
  }
  bool take(BusRsp& r) {
    if (!has_rsp_) return false;
    r = rsp_;
    has_rsp_ = false;
    return true;
  }

 private:
  enum class State { kIdle, kWrite, kWriteResp, kRead, kReadResp };
  void finish(bool err, uint32_t data) {
    rsp_ = {txn_, err, data};
    has_rsp_ = true;
    state_ = State::kIdle;
  }
  WaitRng rng_;
  State state_ = State::kIdle;
  BusTxn txn_;
  bool a_done_ = false, w_done_ = false;
  uint32_t a_wait_ = 0, w_wait_ = 0, r_wait_ = 0;
  BusRsp rsp_;
  bool has_rsp_ = false;
};

// Wishbone B4 classic: cyc and stb raised after a wait and held to ack or err.
template <class M>
class WishboneMaster {
 public:
  static constexpr BusKind kKind = BusKind::kWishbone;
  explicit WishboneMaster(const WaitStates& w = {}) : rng_(w) {}

  bool idle() const { return !busy_; }
  void issue(const BusTxn& t) {
    txn_ = t;
    busy_ = true;
    wait_ = rng_.draw();
  }
  void drive(M& m) const {
    const bool on = busy_ && wait_ == 0;
    m.wb_cyc_i = on;
    m.wb_stb_i = on;
    m.wb_we_i = txn_.write;
    m.wb_adr_i = txn_.addr >> 2;
    m.wb_dat_i = txn_.data;
    m.wb_sel_i = txn_.strb;
  }
  void sample(const M& m) {
    if (!busy_) return;
    if (m.wb_stb_i && (m.wb_ack_o || m.wb_err_o)) {
      rsp_ = {txn_, static_cast<bool>(m.wb_err_o), txn_.write ? 0u : m.wb_dat_o};
      has_rsp_ = true;
      busy_ = false;
    } else if (wait_) {
      --wait_;
    }
  }
  bool take(BusRsp& r) {
    if (!has_rsp_) return false;
    r = rsp_;
    has_rsp_ = false;
    return true;
  }

 private:
  WaitRng rng_;
  bool busy_ = false;
  BusTxn txn_;
  uint32_t wait_ = 0;
  BusRsp rsp_;
  bool has_rsp_ = false;
};

}  // namespace hwinterp::tb::bus

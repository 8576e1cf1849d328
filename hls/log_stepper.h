// log_stepper, HLS face: the cycle behaviour of rtl/log_stepper.sv as a
// synthesizable C++ class (registers as members, tick() computes one rising
// clock edge). rtl/log_stepper.sv documents the behaviour (command, coarse
// engine, segment register, fine stage, abort, status);
// models/log_stepper_model.h states the arithmetic, bit for bit.
// Synthesizable subset: SystemC integers, fixed-size arrays, loops bounded by
// template parameters, no floats, no heap.
// hwinterp::hls::StepperModule<LogStepper<Cfg>> is its SC_MODULE.
//
// `Cfg` is a generated variant struct (cmake/cores.cmake): AXES (4), INT_W,
// FRAC_W, MUL_K, SEG_W, POS_W, TIM_W, FEED_W.
#pragma once

#include <systemc>

#include "hls/dda_line.h"
#include "hls/fields.h"
#include "hls/pin_types.h"
#include "hls/stepper_io.h"

namespace hwinterp::hls {

// The coarse engine's program: one micro-operation per entry, run in order
// (the RTL's `case (pc_q)` holds the same table); the divider runs beside it
// (started by kSqrt/kRecip, its result taken by kGet). Registers 0 and 1 are
// the constants 1.0 and 3.0; 2..9 hold the command.
namespace log_uop {
enum Op : unsigned char {
  kMul,    // dst = mul(s1, s2): MUL_CYC + 1 clocks, MUL_K bits of s2 a clock; sh = 1:
           // MUL_CYC clocks, the write on the next multiply's first clock (which
           // must not read dst)
  kSqrt,   // one clock: starts the divider on sqrt(s1) (SQRT_CYC clocks, two bits a clock)
  kRecip,  // one clock: starts the divider on recip(s1) (RECIP_CYC clocks, two bits a clock)
  kAdd,    // dst = s1 + s2: one clock; sh = 1: the cycle's last, go to kCycleStart
  kRsb,    // dst = 3.0 - (s1 << sh): one clock
  kPos,    // lattice position of axis dst = pos(s1, s2): as kMul
  kEmit,   // waits for the segment register, fills it (sh = 1: the even point,
           // passed over in a curve's first cycle)
  kGet,    // waits for the divider, dst = its result: one clock once it is done
};
// Registers: the command (B..K3), two per-curve constants, X and A, and
// eight temporaries shared by values whose lives do not overlap (the
// program's comments name the value each holds).
// clang-format off
enum Reg : unsigned char {
  kOne, kThree, kB, kAb, kDl, kXEnd, kK0, kK1, kK2, kK3, kAb2, kBdl, kX, kA,
  kQ,   // q, then D, then N15 / D
  kU,   // u, then N15
  kDx,  // dX10, then dX21
  kDa,  // dA10, then dA21
  kDp,  // d', then N14
  kE,   // e = d' s2, then N14 / D
  kT0, kT1,
  kRegs
};
// clang-format on
struct Uop {
  Op op;
  unsigned char dst, s1, s2, sh;
};
// pc 0-1 run once per command; each odd+even cycle runs pc 2-45 (its even
// point's positions and EMIT in the next cycle's pc 7-13, while the divider
// computes u).
inline constexpr int kCycleStart = 2;
inline constexpr Uop kProgram[] = {
    {kMul, kAb2, kAb, kAb, 0},  // 0  ab^2
    {kMul, kBdl, kB, kDl, 0},   // 1  b dl
    {kMul, kT0, kB, kX, 0},     // 2  b X0
    {kAdd, kQ, kT0, kOne, 0},   // 3  q = 1 + b X0
    {kMul, kT0, kQ, kQ, 0},     // 4  q^2
    {kAdd, kT0, kT0, kAb2, 0},  // 5  q^2 + ab^2
    {kSqrt, 0, kT0, 0, 0},      // 6  start: root
    {kPos, 0, kX, kK0, 1},      // 7  last cycle's even point: X steps
    {kPos, 1, kX, kK1, 0},      // 8  Y steps
    {kGet, kT0, 0, 0, 0},       // 9  root
    {kRecip, 0, kT0, 0, 0},     // 10 start: u = 1 / root
    {kPos, 2, kX, kK2, 1},      // 11 Z steps
    {kPos, 3, kA, kK3, 0},      // 12 A steps
    {kEmit, 0, 0, 0, 1},        // 13 even point (none in the first cycle); X2 >= x_end: the last
    {kGet, kU, 0, 0, 0},        // 14 u
    {kMul, kT0, kQ, kU, 1},     // 15 q u
    {kMul, kT1, kAb, kU, 1},    // 16 ab u
    {kMul, kDp, kBdl, kU, 1},   // 17 d' = dA10 / a
    {kMul, kE, kT1, kT1, 1},    // 18 s2 = sin^2 theta
    {kMul, kDx, kDl, kT0, 1},   // 19 dX10
    {kMul, kE, kDp, kE, 1},     // 20 e = d' s2
    {kMul, kDa, kDl, kT1, 0},   // 21 dA10
    {kRsb, kT0, kDp, 0, 2},     // 22 3 - 4d'
    {kMul, kT1, kE, kT0, 0},    // 23 e (3 - 4d')
    {kRsb, kQ, kT1, 0, 1},      // 24 D
    {kRecip, 0, kQ, 0, 0},      // 25 start: 1 / D
    {kMul, kT1, kDp, kE, 1},    // 26 d' e
    {kMul, kT0, kDp, kT0, 0},   // 27 d' (3 - 4d')
    {kRsb, kU, kT0, 0, 1},      // 28 N15
    {kRsb, kT0, kDp, 0, 3},     // 29 3 - 8d'
    {kMul, kT0, kT1, kT0, 0},   // 30 d' e (3 - 8d')
    {kRsb, kDp, kT0, 0, 1},     // 31 N14
    {kAdd, kX, kX, kDx, 0},     // 32 X1
    {kAdd, kA, kA, kDa, 0},     // 33 A1
    {kPos, 0, kX, kK0, 1},      // 34 X steps
    {kPos, 1, kX, kK1, 1},      // 35 Y steps
    {kPos, 2, kX, kK2, 1},      // 36 Z steps
    {kPos, 3, kA, kK3, 0},      // 37 A steps
    {kEmit, 0, 0, 0, 0},        // 38 odd point
    {kGet, kT0, 0, 0, 0},       // 39 1 / D
    {kMul, kE, kDp, kT0, 1},    // 40 N14 / D
    {kMul, kQ, kU, kT0, 1},     // 41 N15 / D
    {kMul, kDx, kE, kDx, 1},    // 42 dX21 = (N14 / D) dX10
    {kMul, kDa, kQ, kDa, 0},    // 43 dA21 = (N15 / D) dA10
    {kAdd, kX, kX, kDx, 0},     // 44 X2
    {kAdd, kA, kA, kDa, 1},     // 45 A2; the next cycle
};
inline constexpr int kProgramLength = sizeof(kProgram) / sizeof(kProgram[0]);
}  // namespace log_uop

template <class CfgT>
class LogStepper {
 public:
  using Cfg = CfgT;
  static constexpr int AXES = Cfg::AXES;
  static constexpr int INT_W = Cfg::INT_W;
  static constexpr int FRAC_W = Cfg::FRAC_W;
  static constexpr int W = INT_W + FRAC_W;
  static constexpr int MUL_K = Cfg::MUL_K;
  static constexpr int SEG_W = Cfg::SEG_W;
  static constexpr int POS_W = Cfg::POS_W;
  static constexpr int TIM_W = Cfg::TIM_W;
  static constexpr int FEED_W = Cfg::FEED_W;
  static_assert(AXES == 4, "log_stepper drives X, Y, Z and A");
  static_assert(FRAC_W >= 18 && INT_W >= 4 && W <= 62, "word format out of range");
  static_assert(MUL_K >= 1 && MUL_K <= W, "MUL_K out of range");
  static_assert(SEG_W >= 2 && SEG_W <= POS_W && POS_W <= 62, "SEG_W/POS_W out of range");
  static constexpr int MUL_CYC = (W + MUL_K - 1) / MUL_K;  // digits of a multiply
  static constexpr int SQRT_BITS = (W + FRAC_W + 1) / 2;   // root bits of sqrt(x 2^F)
  static constexpr int RECIP_BITS = FRAC_W + 1;            // quotient bits of 2^2F / x
  static constexpr int SQRT_CYC = (SQRT_BITS + 1) / 2;     // two bits a clock
  static constexpr int RECIP_CYC = (RECIP_BITS + 1) / 2;
  static constexpr int RECIP_PAD = 2 * RECIP_CYC - RECIP_BITS;  // a leading zero quotient bit
  static_assert(SQRT_BITS + 3 <= 64, "the square root's remainder needs SQRT_BITS + 3 bits");
  static constexpr int CNT_W = 7;
  static_assert(SQRT_CYC < 128 && RECIP_CYC < 128 && MUL_CYC < 128, "op counter too narrow");

  using word_t = sc_dt::sc_uint<W>;
  using prod_t = sc_dt::sc_biguint<2 * W + 1>;
  using rem_t = sc_dt::sc_uint<64>;  // the sqrt/recip remainder (<= max(SQRT_BITS + 3, W + 1) bits)
  using lpos_t = sc_dt::sc_uint<POS_W>;
  using seg_t = sc_dt::sc_uint<SEG_W>;

  // The fine stage: the dda_line engine over the four axes, SEG_W-bit
  // segment deltas, with the shared step/dir stage (hls/dda_line.h).
  struct FineCfg {
    static constexpr int AXES = 4, ACC_W = SEG_W, POS_W = CfgT::POS_W, TIM_W = CfgT::TIM_W,
                         FEED_W = CfgT::FEED_W;
  };
  using Fine = DdaLine<FineCfg>;

  // The core's own inputs: the command words (models/log_stepper_model.h).
  struct Own {
    word_t b = 0, ab = 0, dl = 0, x_end = 0;
    word_t k[4] = {};
    static auto fields() {  // hls/fields.h
      return std::make_tuple(HWINTERP_FIELD(cmd_b_i, &Own::b, kUnsigned),
                             HWINTERP_FIELD(cmd_ab_i, &Own::ab, kUnsigned),
                             HWINTERP_FIELD(cmd_dl_i, &Own::dl, kUnsigned),
                             HWINTERP_FIELD(cmd_x_end_i, &Own::x_end, kUnsigned),
                             HWINTERP_FIELD(cmd_k_i, &Own::k, kUnsigned));
    }
  };
  using Inputs = StepperInputs<Own, FEED_W, TIM_W>;
  using Outputs = StepperOutputs<AXES, POS_W>;

  LogStepper() { reset(); }

  void reset() {
    act_q_ = false;
    pc_q_ = 0;
    cnt_q_ = 0;
    for (int r = 0; r < log_uop::kRegs; ++r) reg_q_[r] = 0;
    acc_q_ = 0;
    pp_q_ = 0;
    wb_q_ = false;
    wb_pos_q_ = false;
    wb_dst_q_ = 0;
    rem_q_ = 0;
    res_q_ = 0;
    dv_act_q_ = false;
    dv_sqrt_q_ = false;
    dv_cnt_q_ = 0;
    dvs_q_ = 0;
    even_q_ = false;
    for (int i = 0; i < 4; ++i) {
      lnew_q_[i] = 0;
      lprev_q_[i] = 0;
      seg_q_[i] = 0;
    }
    seg_valid_q_ = false;
    seg_last_q_ = false;
    tag_n_q_ = 0;
    tag_q_[0] = tag_q_[1] = false;
    points_q_ = 0;
    fine_.reset();
  }

  void tick(const Inputs& in) {
    if (!in.rst_n) {
      reset();
      return;
    }
    const typename Fine::Outputs fo = fine_.outputs();
    const bool seg_take = seg_valid_q_ && fo.cmd_ready;
    const bool seg_free = !seg_valid_q_;  // the register as the engine sees it this clock
    const bool pop = fo.done;
    if (act_q_ && points_q_ && !seg_valid_q_ && !fo.busy) ++underrun_clocks_;

    typename Fine::Inputs fin;
    fin.rst_n = true;
    fin.cmd_valid = seg_valid_q_;
    for (int i = 0; i < 4; ++i) fin.cmd.delta[i] = seg_q_[i];
    fin.cmd.half_preload = true;
    fin.feed = in.feed;
    fin.timing = in.timing;
    fin.abort = in.abort;
    fine_.tick(fin);

    // Tags of the segments in the fine stage (at most three: its two buffer
    // entries and its engine), oldest first: does the segment end its curve.
    if (in.abort) {
      tag_n_q_ = 0;
      tag_q_[0] = tag_q_[1] = tag_q_[2] = false;
    } else {
      int n = tag_n_q_;
      if (pop) {
        tag_q_[0] = tag_q_[1];
        tag_q_[1] = tag_q_[2];
        tag_q_[2] = false;
        --n;
      }
      if (seg_take) {
        tag_q_[n] = seg_last_q_;
        ++n;
      }
      tag_n_q_ = n;
    }
    if (seg_take || in.abort) seg_valid_q_ = false;

    if (in.abort) {
      act_q_ = false;
      dv_act_q_ = false;
      wb_q_ = false;
    } else {
      // The divider's clock from its state before this edge; a start by the
      // engine on this edge replaces it.
      const bool dv_busy = dv_act_q_;
      bool started = false;
      if (act_q_) {
        write_back();
        started = step_engine(seg_free, dv_busy);
      } else if (in.cmd_valid) {
        load(in.cmd);
      }
      if (!started && dv_busy) divider_clock();
    }
  }

  Outputs outputs() const {
    Outputs o = fine_.outputs();
    o.cmd_ready = !act_q_;
    o.busy = o.busy || act_q_ || seg_valid_q_;
    o.done = o.done && tag_q_[0];
    return o;
  }

  // Clocks on which the fine stage stood idle waiting for the coarse engine
  // in the middle of a curve (a diagnostic of the model, not a pin).
  uint64_t underrun_clocks() const { return underrun_clocks_; }
  // Coarse points emitted since construction (a diagnostic, not a pin).
  uint64_t points_emitted() const { return points_emitted_; }

 private:
  word_t rd(int r) const {
    if (r == log_uop::kOne) return word_t(word_t(1) << FRAC_W);
    if (r == log_uop::kThree) return word_t(word_t(3) << FRAC_W);
    return reg_q_[r];
  }

  void load(const Own& c) {
    act_q_ = true;
    pc_q_ = 0;
    cnt_q_ = 0;
    reg_q_[log_uop::kB] = c.b;
    reg_q_[log_uop::kAb] = c.ab;
    reg_q_[log_uop::kDl] = c.dl;
    reg_q_[log_uop::kXEnd] = c.x_end;
    for (int i = 0; i < 4; ++i) {
      reg_q_[log_uop::kK0 + i] = c.k[i];
      lprev_q_[i] = 0;
    }
    reg_q_[log_uop::kX] = 0;
    reg_q_[log_uop::kA] = 0;
    even_q_ = false;
    points_q_ = 0;
  }

  // One clock of the divider: two digits of a restoring recurrence (the RTL
  // shares them too), steps j = 2c and 2c + 1:
  // sqrt: digit i = 2 SQRT_CYC-1-j of n = s 2^F, bits 2i+1..2i of n, i.e.
  //   bits 2i+1-F..2i-F of the operand s (zero below bit 0 and from bit W);
  //   trial 4 root + 1;
  // recip: 2^2F / s, the remainder starting at 2^(F-1-RECIP_PAD); trial s.
  void divider_clock() {
    const unsigned c = dv_cnt_q_.to_uint();
    rem_t res = res_q_, rem = rem_q_;
    for (int k = 0; k < 2; ++k) {
      rem_t rem2, trial;
      if (dv_sqrt_q_) {
        const int lo = 2 * (2 * SQRT_CYC - 1 - (2 * static_cast<int>(c) + k)) - FRAC_W;
        unsigned pair = 0;
        if (lo + 1 >= 0 && lo + 1 < W && dvs_q_[lo + 1]) pair |= 2;
        if (lo >= 0 && lo < W && dvs_q_[lo]) pair |= 1;
        rem2 = (rem << 2) | pair;
        trial = (res << 2) | 1;
      } else {
        rem2 = rem << 1;
        trial = rem_t(dvs_q_.to_uint64());
      }
      const bool bit = rem2 >= trial;
      rem = bit ? rem_t(rem2 - trial) : rem2;
      res = (res << 1) | rem_t(bit);
    }
    rem_q_ = rem;
    res_q_ = res;
    if (c + 1 == static_cast<unsigned>(dv_sqrt_q_ ? SQRT_CYC : RECIP_CYC)) dv_act_q_ = false;
    dv_cnt_q_ = c + 1;
  }

  // A handed-over multiply's write (its last addition), on the next
  // multiply's first clock: from acc_q_ and pp_q_ before that clock's edge.
  void write_back() {
    if (!wb_q_) return;
    wb_q_ = false;
    const prod_t acc = prod_t(acc_q_ + pp_q_);
    if (wb_pos_q_) {
      lnew_q_[wb_dst_q_] = pos_of(acc);
    } else {
      reg_q_[wb_dst_q_] = word_t((acc >> FRAC_W).range(W - 1, 0).to_uint64());
    }
  }

  static lpos_t pos_of(const prod_t& acc) {
    constexpr int SH = 2 * FRAC_W - 16;  // models::kLogPosShift = 16
    const prod_t rounded = acc + (prod_t(1) << (SH - 1));
    return lpos_t((rounded >> SH).range(POS_W - 1, 0).to_uint64());
  }

  void next_op() {
    pc_q_ = pc_q_ + 1;
    cnt_q_ = 0;
  }

  // One clock of the operation at pc_q_; `seg_free`: the segment register
  // was empty before this edge (a segment the fine stage takes on this edge
  // frees it from the next clock on); `dv_busy`: the divider runs. True when
  // the operation starts the divider.
  bool step_engine(bool seg_free, bool dv_busy) {
    const log_uop::Uop u = log_uop::kProgram[pc_q_.to_uint()];
    const word_t s1 = rd(u.s1), s2 = rd(u.s2);
    const unsigned c = cnt_q_.to_uint();
    switch (u.op) {
      case log_uop::kMul:
      case log_uop::kPos: {
        // Two stages: clock c < MUL_CYC forms pp = s1 digit_c << MUL_K c
        // (digit c: MUL_K bits of s2 from bit MUL_K c) into a register, and
        // the accumulator adds the previous clock's pp; clock MUL_CYC writes
        // acc + pp. MUL_CYC + 1 clocks; handed over (sh = 1) after clock
        // MUL_CYC - 1, the write on the next clock (write_back).
        const prod_t acc = c == 0 ? prod_t(0) : prod_t(acc_q_ + pp_q_);
        if (c < static_cast<unsigned>(MUL_CYC)) {
          const sc_dt::sc_uint<MUL_K> digit = word_t(s2 >> (MUL_K * c)).range(MUL_K - 1, 0);
          prod_t pp = prod_t(s1) * prod_t(digit);
          pp <<= MUL_K * c;
          pp_q_ = pp;
          acc_q_ = acc;
          if (u.sh && c + 1 == static_cast<unsigned>(MUL_CYC)) {
            wb_q_ = true;
            wb_pos_q_ = u.op == log_uop::kPos;
            wb_dst_q_ = u.dst;
            next_op();
          } else {
            cnt_q_ = c + 1;
          }
        } else if (u.op == log_uop::kMul) {
          reg_q_[u.dst] = word_t((acc >> FRAC_W).range(W - 1, 0).to_uint64());
          next_op();
        } else {
          lnew_q_[u.dst] = pos_of(acc);
          next_op();
        }
        break;
      }
      case log_uop::kSqrt:
      case log_uop::kRecip:
        dv_act_q_ = true;
        dv_sqrt_q_ = u.op == log_uop::kSqrt;
        dv_cnt_q_ = 0;
        dvs_q_ = s1;
        rem_q_ = dv_sqrt_q_ ? rem_t(0) : rem_t(rem_t(1) << (FRAC_W - 1 - RECIP_PAD));
        res_q_ = 0;
        next_op();
        return true;
      case log_uop::kGet:
        if (!dv_busy) {
          reg_q_[u.dst] = word_t(res_q_.to_uint64());
          next_op();
        }
        break;
      case log_uop::kAdd:
        reg_q_[u.dst] = s1 + s2;
        if (u.sh) {
          pc_q_ = log_uop::kCycleStart;
          cnt_q_ = 0;
          even_q_ = true;
        } else {
          next_op();
        }
        break;
      case log_uop::kRsb:
        reg_q_[u.dst] = rd(log_uop::kThree) - word_t(s1 << u.sh);
        next_op();
        break;
      case log_uop::kEmit:
        if (u.sh && !even_q_) {
          next_op();  // a curve's first cycle: no even point yet
        } else if (seg_free) {
          const bool last = u.sh && rd(log_uop::kX) >= rd(log_uop::kXEnd);
          for (int i = 0; i < 4; ++i) {
            seg_q_[i] = seg_t(lpos_t(lnew_q_[i] - lprev_q_[i]).range(SEG_W - 1, 0).to_uint64());
            lprev_q_[i] = lnew_q_[i];
          }
          seg_valid_q_ = true;
          seg_last_q_ = last;
          even_q_ = false;
          points_q_ = true;
          ++points_emitted_;
          if (last) {
            act_q_ = false;
          } else {
            next_op();
          }
        }
        break;
    }
    return false;
  }

  // Coarse engine.
  bool act_q_;                    // a curve is being computed
  sc_dt::sc_uint<6> pc_q_;        // the program entry running
  sc_dt::sc_uint<CNT_W> cnt_q_;   // clock within a multi-clock operation
  word_t reg_q_[log_uop::kRegs];  // registers 2.. (0 and 1 are constants)
  prod_t acc_q_, pp_q_;           // the multiplier's accumulator and registered partial product
  bool wb_q_, wb_pos_q_;          // a handed-over multiply's write pending, to a lattice position
  unsigned char wb_dst_q_;        // its register or axis
  bool even_q_;                   // an even point waits for its positions and EMIT
  // Divider: running, square root (else reciprocal), its clock, its operand,
  // remainder and root/quotient so far.
  bool dv_act_q_, dv_sqrt_q_;
  sc_dt::sc_uint<6> dv_cnt_q_;
  word_t dvs_q_;
  rem_t rem_q_, res_q_;
  lpos_t lnew_q_[4], lprev_q_[4];  // lattice positions of this point and the last
  bool points_q_;                  // a point of this curve has been emitted (diagnostic)
  // Segment register (the FIFO's entry in front of the fine stage's buffer).
  seg_t seg_q_[4];
  bool seg_valid_q_, seg_last_q_;
  // Tags of the segments in the fine stage.
  sc_dt::sc_uint<2> tag_n_q_;
  bool tag_q_[3];
  Fine fine_;
  // Diagnostics (not hardware): counted by the model, never reset.
  uint64_t underrun_clocks_ = 0;
  uint64_t points_emitted_ = 0;
};

}  // namespace hwinterp::hls

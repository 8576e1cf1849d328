// Jerk-limited feed profile: the path speed, clock by clock, for a stream of
// moves (issue 25). The cycle-accurate face; the double-precision side (the
// registers from machine limits, the time-optimal reference) is
// models/feed_profile_model.h.
//
// How it works. Time is cut into ticks of T = 2^TICK_W clocks. Two stages:
//   1. A trapezoid on an integer speed level c: per tick c goes up by 1, stays
//      or goes down by 1 (dc in {-1, 0, +1}).
//   2. A moving sum over the last L ticks (a boxcar FIR, L a register): the
//      speed is v_k = q * sum_{i<L} c_{k-i}, q a register (the speed quantum,
//      ops/clock * 2^SPD_W).
// So, per tick, the speed changes by dv_k = q (c_k - c_{k-L}), at most q*L
// (the acceleration limit a tick), and the acceleration by
// d2v_k = q (dc_k - dc_{k-L}), at most q (the jerk limit a tick^2) as long as
// a step never opposes the step L ticks before it. That is the reversal rule:
// +1 only if the step L ticks ago was not -1, -1 only if it was not +1. A
// boxcar keeps the distance: sum_k v_k = q L sum_k c_k exactly, only later, so
// the trapezoid counts the distance of the move in its own terms and never
// sees the delay. With L = A/J ticks, the profile of a move that reaches the
// acceleration limit is the time-optimal 7-phase S-curve; a shorter move has
// a flat acceleration phase where the optimum has none (see the Ruckig
// comparison, tests/profile/).
//
// Fixed point. v and q: ops/clock * 2^SPD_W (v <= 2^SPD_W: at most one
// operation a clock; the planner keeps q * L * target <= 2^SPD_W). The
// remaining distance R of the move: ops * 2^(SPD_W - TICK_W), so that a tick at
// level c travels exactly c * q * L of it (c * q * L * T / 2^SPD_W ops).
// Everything is integer and exact: the RTL computes the same numbers
// incrementally and gives the same bits.
//
// The braking rule (per tick, the largest allowed next level c' whose cost
// fits in R). cost(c') is the distance of this tick at c' plus the forced
// hold w' ticks at c' (the reversal rule: after a +1, L ticks before a -1)
// plus the braking B(c', e) = sum_{j=e}^{c'-1} j from c' down to the move's
// end level e plus e held L - 1 ticks (the settle), all times q*L. It is an
// upper bound of a legal continuation, and the continuation of a feasible
// choice is feasible on the next tick, so once feasible the move stays
// feasible: the level is at e when R runs out, never above, and has been at
// e for the last L ticks (tests/hls/feed_profile_test.cpp checks it on random
// moves; the argument is in docs/profile.md). The move ends on the tick
// R <= 0; its overshoot (< one tick at level e) is carried into the next move
// while moving, dropped at rest. At the program's end the block travels at
// least the ops given (distance >= N), so an engine behind it always reaches
// its last operation, at a speed of at most a few levels.
//
// Junctions. The speed lags the level: when a move's distance runs out (in
// the trapezoid's terms) the moving sum still owes it e L (L - 1) / 2
// level-ticks of distance, at most floor(L / 2) ticks at level e. So after
// a junction (a move ending at e > 0 while moving, the next one starting)
// the level may not rise for floor(L / 2) ticks (jhold_): every level the
// moving sum holds until the engine has taken the ended move's last
// operation is e or lower, and the speed there is at most q L e, the end
// speed (FeedProfile.JunctionsArePassedAtMostAtTheirEndSpeed). A move to
// rest (e = 0) has neither the settle nor the hold: the harness's exact-stop
// rule (tb/lockstep/profile_feed.h) waits for rest instead.
//
// Commands: valid/ready, one waiting (`pending`) and one next; at a tick
// boundary next becomes current when the current move is done, then pending
// becomes next: a command is current one whole tick after it became next at
// the earliest (the RTL computes its costs in that tick).
// hold_i: feed hold, the target becomes 0 (a controlled stop within the same
// limits); resume continues. Config (q, L): latched while the block is at
// rest (nothing queued, v = 0, no step in the window).
//
// Feed override ovr (9 bits, factor ovr / 128: 0..256 is 0..200 % in steps of
// 1/128 = 0.78 %; 257..511 act as 256; kOvrOne = 128 is 100 %). It is sampled
// on the boundary clock and rules the next boundary (a tick later: the RTL
// computes a boundary's choices during the tick before it). The cruise level
// in force is
//   target' = min(ceil(target * ovr / 128), top),  top = max if max != 0, else target
// where `target` is the programmed level and `max` the move's cap word (the
// planner's cap by the machine's limits; 0: the target itself, so the
// override can only slow the move down). Only the target is scaled: the end
// level and the braking rule are the move's own, so a junction is never
// entered faster than planned. At ovr = 128 target' = min(target, top): a
// move given as before (its cruise level as target, max = 0) runs the bits it
// ran before the override existed, and so does target = programmed, max = cap
// (tb/gcode/profile_plan.cpp). ceil keeps target' >= 1 for any ovr > 0;
// ovr = 0 gives target' = 0: the level comes down as under
// hold_i and rests with the move's distance left until the override rises.
// Every change is jerk-limited because the override moves only the target:
// the level still steps by -1, 0, +1 under the reversal rule, and the speed
// is still the moving sum, so |dv| <= q L and |d2v| <= q hold on every tick
// whatever the override does. A lower target only adds steps down and removes
// steps up; both keep a feasible state feasible (docs/profile.md), so each
// move still ends at or below its end level (1 for a move to rest) when its
// distance runs out.
//
// Per clock the feed word to feed_accum is v >> (SPD_W - FEED_W) plus the
// carry of a dither accumulator over the dropped bits, so that the ops over
// any span are the exact integral of v.
#pragma once

#include <systemc>

#include <cstdint>
#include <vector>

namespace hwinterp::hls {

template <int FEED_W, int SPD_W, int TICK_W, int LEN_W, int LVL_W, int OPS_W>
class FeedProfile {
  static_assert(FEED_W >= 1 && SPD_W > FEED_W && SPD_W <= 62, "speed widths");
  static_assert(TICK_W >= 6 && TICK_W < SPD_W, "a tick is at least 64 clocks");
  static_assert(LEN_W >= 0 && LEN_W <= 16 && LVL_W >= 2 && LVL_W <= 24 && OPS_W >= 2 && OPS_W <= 40,
                "field widths");

 public:
  static constexpr int kDropW = SPD_W - FEED_W;    // speed bits below the feed word
  static constexpr int kRShift = SPD_W - TICK_W;   // R = ops << kRShift
  static constexpr int kRW = OPS_W + kRShift + 2;  // R's bits, sign included
  static constexpr int kCostW = SPD_W + 2 * LVL_W + 2 * LEN_W + 8;
  static constexpr unsigned kMaxLen = 1u << LEN_W;
  using speed_t = sc_dt::sc_uint<SPD_W + 1>;
  using level_t = sc_dt::sc_uint<LVL_W>;
  using ops_t = sc_dt::sc_uint<OPS_W>;
  using r_t = sc_dt::sc_bigint<kRW>;
  using cost_t = sc_dt::sc_bigint<kCostW>;

  struct Command {
    ops_t ops = 0;       // engine operations of the move (>= 1)
    level_t target = 0;  // cruise level: speed q * L * target
    level_t end = 0;     // level when the move's last operation is taken
    level_t max = 0;     // the cap of the cruise level under the override (0: target)
  };
  static constexpr unsigned kOvrOne = 128;  // the override word of 100 %
  // The cruise level in force for `target`, `max` and the override word.
  static uint32_t override_target(uint32_t target, uint32_t max, unsigned ovr) {
    const uint64_t o = ovr > 2 * kOvrOne ? 2 * kOvrOne : ovr;
    const uint64_t scaled = (uint64_t(target) * o + kOvrOne - 1) / kOvrOne;
    const uint64_t top = max != 0 ? max : target;
    return static_cast<uint32_t>(scaled < top ? scaled : top);
  }
  // The state compared between the faces every clock.
  struct State {
    uint64_t v = 0, acc = 0, feed = 0;
    uint32_t c = 0, t = 0, idx = 0, up_age = 0, quiet = 0;
    bool cur = false, next = false, pend = false;
    bool operator==(const State& o) const {
      return v == o.v && acc == o.acc && feed == o.feed && c == o.c && t == o.t && idx == o.idx &&
             up_age == o.up_age && quiet == o.quiet && cur == o.cur && next == o.next &&
             pend == o.pend;
    }
  };

  void reset() {
    ring_qc_.assign(kMaxLen, 0);
    ring_dc_.assign(kMaxLen, 0);
    q_ = 0;
    len_ = 1;
    v_ = 0;
    acc_ = 0;
    feed_ = 0;
    c_ = 0;
    t_ = 0;
    idx_ = 0;
    up_age_ = (4u << LEN_W) - 1;  // as the RTL's all-ones reset: above kMaxLen, "long ago"
    quiet_ = (4u << LEN_W) - 1;
    r_ = 0;
    jhold_ = 0;
    ends_ = ends_above_ = 0;
    ovr_ = kOvrOne;
    cur_ = next_ = pend_ = false;
  }

  bool cmd_ready() const { return !pend_; }
  // Diagnostics of the braking rule (no RTL counterpart): the ticks on which
  // the current move's distance had run out, and those of them with the
  // level above the move's end level, or above 1 for a move to rest (0 while
  // every move's braking fits: each move's end level is one its successor can
  // brake from within its length, as tb/gcode/profile_plan.cpp plans them).
  uint64_t ends() const { return ends_; }
  uint64_t ends_above() const { return ends_above_; }
  // The feed word of this clock (operations per clock * 2^FEED_W), a register.
  uint64_t feed() const { return feed_; }
  bool busy() const { return cur_ || next_ || pend_ || v_ != 0 || quiet_ <= len_; }
  State state() const {
    return {v_, acc_, feed_, c_, t_, idx_, up_age_, quiet_, cur_, next_, pend_};
  }

  // One rising clock edge. q, len: the configuration pins (taken at rest);
  // a command is taken when cmd_valid and cmd_ready(); ovr: the override word
  // (sampled on the boundary clock, in force from the next boundary).
  void clock(bool cmd_valid, const Command& cmd, bool hold, uint64_t q, unsigned len,
             unsigned ovr = kOvrOne) {
    // The feed word and the dither run every clock on the speed in force.
    const uint64_t low_mask = (uint64_t(1) << kDropW) - 1;
    const uint64_t sum = acc_ + (v_ & low_mask);
    const uint64_t feed_d = ((v_ >> kDropW) + (sum >> kDropW)) & ((uint64_t(2) << FEED_W) - 1);
    const uint64_t acc_d = sum & low_mask;
    const bool rest = !busy();
    const bool take = cmd_valid && !pend_;
    if (t_ == 0) {
      boundary(hold);
      ovr_ = ovr & 511u;
    }
    if (take) {
      pend_cmd_ = cmd;
      pend_ = true;
    }
    if (rest) {
      q_ = q & ((uint64_t(1) << SPD_W) - 1);
      len_ = len < 1 ? 1 : (len > kMaxLen ? kMaxLen : len);
      idx_ = 0;
    }
    feed_ = feed_d;
    acc_ = acc_d;
    t_ = (t_ + 1) & ((1u << TICK_W) - 1);
  }

 private:
  // B(c, e) = sum_{j=e}^{c-1} j: the level-ticks of braking from c to e.
  static cost_t brake(uint32_t c, uint32_t e) {
    if (c <= e) return 0;
    cost_t n = cost_t(c) - cost_t(e);
    return (cost_t(c) + cost_t(e) - 1) * n / 2;
  }
  // The distance (R units) of a tick at c, w ticks held at c, then braking to e.
  cost_t cost(uint32_t c, uint32_t w, uint32_t e) const {
    return cost_t(q_) * cost_t(len_) * (cost_t(c) * cost_t(1 + w) + brake(c, e));
  }

  void boundary(bool hold) {
    // Commands move one place a boundary: next -> current (when the current
    // move is done), then pending -> next. So a command is current at the
    // second boundary after it was taken at the earliest, and the RTL has a
    // whole tick to compute with it.
    const bool moving = c_ != 0 || v_ != 0;
    // A junction: the move in progress ends at level e > 0 and the next one
    // starts on this tick (see jhold_ below).
    const bool junction = cur_ && r_ <= 0 && next_ && moving && cur_cmd_.end.to_uint() > 0;
    if (junction) jhold_ = len_ / 2;
    if ((!cur_ || r_ <= 0) && next_) {
      const r_t add = r_t(next_cmd_.ops.to_uint64()) << kRShift;
      r_ = (cur_ && moving) ? r_t(r_ + add) : add;
      cur_cmd_ = next_cmd_;
      cur_ = true;
      next_ = false;
    } else if (cur_ && r_ <= 0) {
      cur_ = false;
    }
    if (!next_ && pend_) {
      next_cmd_ = pend_cmd_;
      next_ = true;
      pend_ = false;
    }
    const bool free = hold || !cur_;  // no distance to fit: only slow down
    const uint32_t target =
        free ? 0 : override_target(cur_cmd_.target.to_uint(), cur_cmd_.max.to_uint(), ovr_);
    const uint32_t end = free ? 0 : cur_cmd_.end.to_uint();
    const int dc_old = ring_dc_[idx_];
    const bool up_ok = dc_old != -1, down_ok = dc_old != 1;
    const uint32_t w_hold = up_age_ >= len_ ? 0 : len_ - up_age_;
    // A move brakes no lower than its end level, and a move to rest no lower
    // than level 1 while distance is left: it ends at level 1 with less than
    // one level-tick overshot, rather than at 0 with distance still to go.
    const uint32_t floor = end > 0 ? end : (free ? 0 : 1);
    // The end level is reached at least L - 1 ticks before the distance runs
    // out, and held: the L levels of the moving sum are all e on the move's
    // last tick (e (L - 1) level-ticks, doubled as fits() doubles).
    const cost_t settle = cost_t(q_) * cost_t(len_) * cost_t(end) * cost_t(2 * (len_ - 1));
    const auto fits = [&](uint32_t c, uint32_t w) {
      return free || cost_t(2 * cost(c, w, end) + settle) <= cost_t(2 * r_);
    };
    uint32_t c = c_;
    if (c_ < target && up_ok && jhold_ == 0 && c_ + 1 < (1u << LVL_W) &&
        (fits(c_ + 1, len_) || c_ == 0)) {
      c = c_ + 1;  // from rest, a move too short to fit even one level still starts (it overshoots)
    } else if (c_ > 0 && down_ok && (c_ > target || (c_ > floor && !fits(c_, w_hold)))) {
      c = c_ - 1;
    }
    const int dc = int(c) - int(c_);
    if (jhold_ > 0) --jhold_;
    if (cur_) {
      r_ = r_ - r_t(cost_t(q_) * cost_t(len_) * cost_t(c));
      // The move's distance ran out on this tick: its level is at most its
      // end level (1 for a move to rest: its floor, above).
      const uint32_t e_max = cur_cmd_.end.to_uint() > 0 ? cur_cmd_.end.to_uint() : 1;
      if (r_ <= 0 && c > e_max) ++ends_above_;
      if (r_ <= 0) ++ends_;
    }
    const uint64_t v_mask = (uint64_t(2) << SPD_W) - 1;  // v and q*c: SPD_W + 1 bits, as the RTL
    const uint64_t qc = (q_ * c) & v_mask;
    v_ = (v_ + qc - ring_qc_[idx_]) & v_mask;
    ring_qc_[idx_] = qc;
    ring_dc_[idx_] = int8_t(dc);
    idx_ = idx_ + 1 == len_ ? 0 : idx_ + 1;
    up_age_ = dc == 1 ? 1 : (up_age_ > kMaxLen ? up_age_ : up_age_ + 1);
    quiet_ = dc != 0 ? 1 : (quiet_ > kMaxLen ? quiet_ : quiet_ + 1);
    c_ = c;
  }

  std::vector<uint64_t> ring_qc_;  // q * c of the last L ticks (RAM in the RTL)
  std::vector<int8_t> ring_dc_;    // dc of the last L ticks
  uint64_t q_ = 0, v_ = 0, acc_ = 0, feed_ = 0;
  uint32_t len_ = 1, c_ = 0, t_ = 0, idx_ = 0, up_age_ = 0, quiet_ = 0;
  // Ticks after a junction on which the level may not rise: the moving sum
  // still owes the ended move e L (L - 1) / 2 level-ticks of its distance
  // at level e, at most floor(L / 2) ticks of it; so the engine takes that
  // move's last operation on one of them, with every level it sums at e.
  uint32_t jhold_ = 0;
  unsigned ovr_ = kOvrOne;  // the override word of the next boundary
  r_t r_ = 0;
  uint64_t ends_ = 0, ends_above_ = 0;
  bool cur_ = false, next_ = false, pend_ = false;
  Command pend_cmd_, next_cmd_, cur_cmd_;
};

}  // namespace hwinterp::hls

// Feed-rate accumulator shared by every core: the cycle behaviour of
// rtl/feed_accum.sv (see there for the contract). The RTL keeps the tick in
// a register, computed a clock ahead; here the same tick is computed from
// the registered feed word when it is used, which gives the same value on
// every clock. Synthesizable subset.
#pragma once

#include <systemc>

namespace hwinterp::hls {

template <int FEED_W>
class FeedAccum {
 public:
  using feed_t = sc_dt::sc_uint<FEED_W + 1>;

  void reset() {
    phase_q_ = 0;
    feed_q_ = 0;
  }

  // The engine may do one operation this clock (like tick_o, with run the
  // engine's work flag of this clock).
  bool tick(bool run) const { return run && (feed_q_[FEED_W] || sum()[FEED_W]); }

  // One rising clock edge; `hold`: this clock's tick could not be used;
  // `feed`: the pins, in force from the next clock.
  void clock(const feed_t& feed, bool run, bool hold) {
    if (run && !feed_q_[FEED_W] && !(tick(run) && hold)) phase_q_ = sum().range(FEED_W - 1, 0);
    feed_q_ = feed;
  }

 private:
  feed_t sum() const { return feed_t(phase_q_) + feed_t(feed_q_.range(FEED_W - 1, 0)); }
  sc_dt::sc_uint<FEED_W> phase_q_ = 0;
  feed_t feed_q_ = 0;  // the feed word in force this clock
};

}  // namespace hwinterp::hls

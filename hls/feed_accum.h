// Feed-rate accumulator shared by every core: the cycle behaviour of
// rtl/feed_accum.sv (see there for the contract). Synthesizable subset.
#pragma once

#include <systemc>

namespace hwinterp::hls {

template <int FEED_W>
class FeedAccum {
 public:
  using feed_t = sc_dt::sc_uint<FEED_W + 1>;

  void reset() { phase_q_ = 0; }

  // The engine may do one operation this clock (combinational, like tick_o).
  bool tick(const feed_t& feed, bool run) const {
    return run && (feed[FEED_W] || sum(feed)[FEED_W]);
  }

  // One rising clock edge; `hold`: this clock's tick could not be used.
  void clock(const feed_t& feed, bool run, bool hold) {
    if (run && !feed[FEED_W] && !(tick(feed, run) && hold))
      phase_q_ = sum(feed).range(FEED_W - 1, 0);
  }

 private:
  feed_t sum(const feed_t& feed) const {
    return feed_t(phase_q_) + feed_t(feed.range(FEED_W - 1, 0));
  }
  sc_dt::sc_uint<FEED_W> phase_q_ = 0;
};

}  // namespace hwinterp::hls

#include "tb/lockstep/profile_feed.h"

#include <algorithm>
#include <sstream>

#include "Vfeed_profile_harness_cc.h"
#include "tb/lockstep/harness_profile.h"
#include "verilated.h"

namespace hwinterp::tb {

using Profile = HarnessProfile;

struct ProfileFeed::Faces {
  VerilatedContext context;
  std::unique_ptr<Vfeed_profile_harness_cc> rtl;
  Profile hls;
  uint64_t q = 0;
  unsigned len = 1;
};

ProfileFeed::ProfileFeed(uint64_t q, unsigned len, std::function<bool(ProfileWords&)> next)
    : f_(std::make_unique<Faces>()), next_(std::move(next)) {
  f_->q = q;
  f_->len = len;
  f_->rtl = std::make_unique<Vfeed_profile_harness_cc>(&f_->context);
  f_->hls.reset();
  auto& r = *f_->rtl;
  r.q_i = q;
  r.len_i = len;
  r.cmd_valid_i = 0;
  r.hold_i = 0;
  r.rst_ni = 0;
  for (int e : {0, 1, 0}) {  // reset over a rising edge
    r.clk_i = e;
    r.eval();
  }
  r.rst_ni = 1;
  r.eval();
}

ProfileFeed::~ProfileFeed() {
  f_->rtl->final();
  f_->rtl.reset();
  Verilated::threadContextp(Verilated::defaultContextp());
}

void ProfileFeed::hold_between(uint64_t from, uint64_t to) {
  hold_from_ = from;
  hold_to_ = std::max(from, to);
}

bool ProfileFeed::busy() const { return f_->hls.busy(); }

bool ProfileFeed::stranded() const { return rest_clocks_ > (uint64_t(4) << kProfileTickW); }

uint64_t ProfileFeed::clock() {
  auto& r = *f_->rtl;
  Profile& h = f_->hls;
  if (!valid_ && !done_) {
    if (next_(offered_))
      valid_ = true;
    else
      done_ = true;
  }
  const uint64_t feed = h.feed();
  if (failure_.empty()) {
    const auto s = h.state();
    if (r.feed_o != feed || r.level_o != s.c || r.speed_o != s.v || r.busy_o != h.busy() ||
        r.cmd_ready_o != h.cmd_ready()) {
      std::ostringstream os;
      os << "feed profile, clock " << clocks_ << ": RTL feed " << r.feed_o << " level " << r.level_o
         << " speed " << r.speed_o << ", HLS feed " << feed << " level " << s.c << " speed " << s.v;
      failure_ = os.str();
    }
  }
  Profile::Command cmd;
  cmd.ops = offered_.ops;
  cmd.target = offered_.target;
  cmd.end = offered_.end;
  const bool take = valid_ && h.cmd_ready();
  const bool hold = clocks_ >= hold_from_ && clocks_ < hold_to_;
  if (hold && !stop_.stopped) {
    const double word =
        static_cast<double>(feed) / static_cast<double>(uint64_t(1) << kProfileFeedW);
    if (!stop_.began) stop_ = {true, false, word, 0, 0};
    if (h.state().v == 0) {
      stop_.stopped = true;
    } else {
      stop_.ops += word;
      ++stop_.clocks;
    }
  }
  r.q_i = f_->q;
  r.len_i = f_->len;
  r.cmd_valid_i = valid_;
  r.cmd_ops_i = static_cast<uint32_t>(offered_.ops);
  r.cmd_target_i = offered_.target;
  r.cmd_end_i = offered_.end;
  r.hold_i = hold;
  r.clk_i = 1;
  r.eval();
  h.clock(valid_, cmd, hold, f_->q, f_->len);
  r.clk_i = 0;
  r.eval();
  if (take) {
    valid_ = false;
    ++taken_;
  }
  ++clocks_;
  rest_clocks_ = done_ && !h.busy() ? rest_clocks_ + 1 : 0;
  return feed;
}

}  // namespace hwinterp::tb

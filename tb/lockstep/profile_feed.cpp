#include "tb/lockstep/profile_feed.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "Vfeed_profile_harness_cc.h"
#include "models/feed_profile_model.h"
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
  r.ovr_i = Profile::kOvrOne;
  r.cmd_max_i = 0;
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

namespace {

double whole_real(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double v = text.empty() ? 0 : std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
    throw std::invalid_argument(what + " '" + text + "' is not a number");
  return v;
}

}  // namespace

std::vector<OverridePoint> parse_feed_override(const std::string& text) {
  std::vector<OverridePoint> out;
  size_t from = 0;
  while (true) {
    const size_t comma = text.find(',', from);
    const std::string item = text.substr(from, comma == std::string::npos ? comma : comma - from);
    const size_t colon = item.find(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("'" + item + "' is not AT:PCT (seconds:percent, e.g. 1.5:150)");
    OverridePoint p;
    p.at_s = whole_real(item.substr(0, colon), "AT");
    p.percent = whole_real(item.substr(colon + 1), "PCT");
    if (!(p.at_s >= 0)) throw std::invalid_argument("AT '" + item + "' is before 0 s");
    if (!(p.percent >= 0 && p.percent <= 200))
      throw std::invalid_argument("PCT '" + item + "' is outside 0..200 %");
    if (!out.empty() && p.at_s < out.back().at_s)
      throw std::invalid_argument("'" + item + "' comes before the step ahead of it");
    out.push_back(p);
    if (comma == std::string::npos) {
      if (models::override_word(p.percent) == 0)
        throw std::invalid_argument("the last step '" + item +
                                    "' stops the feed for good (the moves would never finish)");
      break;
    }
    from = comma + 1;
  }
  return out;
}

std::vector<OverrideStep> override_steps(const std::vector<OverridePoint>& points,
                                         double clock_hz) {
  std::vector<OverrideStep> out;
  for (const OverridePoint& p : points)
    out.push_back(
        {static_cast<uint64_t>(std::llround(p.at_s * clock_hz)), models::override_word(p.percent)});
  return out;
}

void ProfileFeed::override_schedule(std::vector<OverrideStep> steps) {
  for (size_t i = 1; i < steps.size(); ++i)
    if (steps[i].at < steps[i - 1].at)
      throw std::invalid_argument("feed override: the step at clock " +
                                  std::to_string(steps[i].at) + " comes before the one at " +
                                  std::to_string(steps[i - 1].at));
  ovr_steps_ = std::move(steps);
  ovr_next_ = 0;
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
  cmd.max = offered_.max;
  while (ovr_next_ < ovr_steps_.size() && ovr_steps_[ovr_next_].at <= clocks_)
    ovr_ = ovr_steps_[ovr_next_++].word;
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
  r.cmd_max_i = offered_.max;
  r.hold_i = hold;
  r.ovr_i = ovr_;
  r.clk_i = 1;
  r.eval();
  h.clock(valid_, cmd, hold, f_->q, f_->len, ovr_);
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

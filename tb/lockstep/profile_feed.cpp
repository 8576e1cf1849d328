#include "tb/lockstep/profile_feed.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include <string>

#include "hwinterp_profile_builds.h"
#include "models/feed_profile_model.h"
#include "tb/base/args.h"
#include "tb/lockstep/harness_profile.h"
#include "verilated.h"

namespace hwinterp::tb {

template <int W>
struct ProfileFeed::FacesOf {
  VerilatedContext context;
  std::unique_ptr<typename ProfileRtl<W>::type> rtl;
  HarnessProfileAt<W> hls;
};

struct ProfileFeed::Faces {
  uint64_t q = 0;
  unsigned len = 1;
#define HWINTERP_PROFILE_FACES(W) std::unique_ptr<FacesOf<W>> f##W;
  HWINTERP_PROFILE_FEED_WS(HWINTERP_PROFILE_FACES)
#undef HWINTERP_PROFILE_FACES
};

namespace {

// Both faces out of reset, the configuration on the RTL's pins.
template <class F>
void reset_faces(F& f, uint64_t q, unsigned len) {
  f.rtl = std::make_unique<typename decltype(f.rtl)::element_type>(&f.context);
  f.hls.reset();
  auto& r = *f.rtl;
  r.q_i = q;
  r.len_i = len;
  r.cmd_valid_i = 0;
  r.hold_i = 0;
  r.ovr_i = HarnessProfile::kOvrOne;
  r.cmd_max_i = 0;
  r.rst_ni = 0;
  for (int e : {0, 1, 0}) {  // reset over a rising edge
    r.clk_i = e;
    r.eval();
  }
  r.rst_ni = 1;
  r.eval();
}

}  // namespace

ProfileFeed::ProfileFeed(uint64_t q, unsigned len, std::function<bool(ProfileWords&)> next,
                         int feed_w)
    : f_(std::make_unique<Faces>()), next_(std::move(next)), feed_w_(feed_w) {
  f_->q = q;
  f_->len = len;
  switch (feed_w) {
#define HWINTERP_PROFILE_MAKE(W)               \
  case W:                                      \
    f_->f##W = std::make_unique<FacesOf<W>>(); \
    reset_faces(*f_->f##W, q, len);            \
    return;
    HWINTERP_PROFILE_FEED_WS(HWINTERP_PROFILE_MAKE)
#undef HWINTERP_PROFILE_MAKE
  }
  throw std::invalid_argument("feed profile: no build with " + std::to_string(feed_w) +
                              "-bit feed words");
}

template <class Fn>
auto ProfileFeed::visit(Fn&& fn) const {
  switch (feed_w_) {
#define HWINTERP_PROFILE_VISIT(W) \
  case W:                         \
    return fn(*f_->f##W);
    HWINTERP_PROFILE_FEED_WS(HWINTERP_PROFILE_VISIT)
#undef HWINTERP_PROFILE_VISIT
  }
  throw std::logic_error("feed profile: no build with " + std::to_string(feed_w_) +
                         "-bit feed words");
}

ProfileFeed::~ProfileFeed() {
  visit([](auto& f) { return (f.rtl->final(), 0); });
  f_.reset();
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
  const std::vector<std::string> items = cli::split_commas(text);
  for (const std::string& item : items) {
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
  }
  if (models::override_word(out.back().percent) == 0)
    throw std::invalid_argument("the last step '" + items.back() +
                                "' stops the feed for good (the moves would never finish)");
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

bool ProfileFeed::busy() const {
  return visit([](auto& f) { return f.hls.busy(); });
}

bool ProfileFeed::stranded() const { return rest_clocks_ > (uint64_t(4) << kProfileTickW); }

uint64_t ProfileFeed::clock() {
  return visit([this](auto& f) { return step(f); });
}

template <int W>
uint64_t ProfileFeed::step(FacesOf<W>& f) {
  using Profile = HarnessProfileAt<W>;
  auto& r = *f.rtl;
  Profile& h = f.hls;
  if (stop_open_ && !h.busy()) stop_open_ = false;
  if (!valid_ && !done_ && !stop_open_ && (!ready_ || ready_())) {
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
  typename Profile::Command cmd;
  cmd.ops = offered_.ops;
  cmd.target = offered_.target;
  cmd.end = offered_.end;
  cmd.max = offered_.max;
  while (ovr_next_ < ovr_steps_.size() && ovr_steps_[ovr_next_].at <= clocks_)
    ovr_ = ovr_steps_[ovr_next_++].word;
  const bool take = valid_ && h.cmd_ready();
  const bool hold = clocks_ >= hold_from_ && clocks_ < hold_to_;
  if (hold && !stop_.stopped) {
    const double word = static_cast<double>(feed) / static_cast<double>(uint64_t(1) << W);
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
    stop_open_ = offered_.end == 0;
  }
  ++clocks_;
  rest_clocks_ = done_ && !h.busy() ? rest_clocks_ + 1 : 0;
  return feed;
}

}  // namespace hwinterp::tb

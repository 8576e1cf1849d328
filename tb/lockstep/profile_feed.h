// The feed profile in front of motion_top, in lockstep: the cycle-accurate
// face (hls/feed_profile.h) and the Verilated RTL (rtl/feed_profile.sv) take
// the same moves and pins every clock and must give the same feed word, level,
// speed, busy and ready; the feed word drives motion_top's feed_i in both of
// its faces (the bench's frame). Built as the harness runs it: ticks of 1024
// clocks, moving sums up to 1024 ticks, 24-bit feed words
// (tb/lockstep/feed_profile_run.h).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hwinterp::tb {

// The feed word's fraction bits of the harness's build (motion_top_n3/n4's
// FEED_W); a core with a wider FEED_W takes the word shifted up, exactly.
inline constexpr int kProfileFeedW = 24;

struct ProfileWords {
  uint64_t ops = 0;
  uint32_t target = 0, end = 0;
  uint32_t max = 0;  // the cap of the cruise level (cmd_max_i; 0: the target)
};

// A feed override change: from clock `at` on, the block's ovr_i is `word`
// (factor word / 128: 128 is 100 %, 0..256 is 0..200 %).
struct OverrideStep {
  uint64_t at = 0;
  unsigned word = 128;
};

// A feed override schedule as given on the command line: AT:PCT[,AT:PCT...]
// (seconds from the run's start, percent 0..200), AT in non-decreasing order.
struct OverridePoint {
  double at_s = 0;
  double percent = 100;
};
// Throws std::invalid_argument naming the bad value (the last step must not
// be 0 %: the moves would never finish).
std::vector<OverridePoint> parse_feed_override(const std::string& text);
// The schedule in clocks and override words (models::override_word).
std::vector<OverrideStep> override_steps(const std::vector<OverridePoint>& points, double clock_hz);

// Exact stops. A move whose end level is 0 is an exact stop: the next move
// is offered only once the block is at rest (busy_o low), and so is the
// engine's next command (holds_next_command). The block joins moves at its
// trapezoid's level: the level is 0 when the move's distance runs out, but
// the speed, the moving sum of the last L levels, reaches 0 only up to L
// ticks later, and the distance the block travels past the move's end (less
// than a tick at level 1) is dropped at rest. A move or a command taken
// before then would start while the machine still moves: a corner or a
// reversal passed at speed, and an engine ahead of its profile.
class ProfileFeed {
 public:
  // `next` gives the profile's moves in order (false: none left). `feed_w`:
  // the feed word's fraction bits, the FEED_W of the core it drives (a
  // width of some variant of cmake/cores.cmake: the harness builds the block
  // at each; tb/lockstep/harness_profile.h); throws std::invalid_argument
  // for another.
  ProfileFeed(uint64_t q, unsigned len, std::function<bool(ProfileWords&)> next,
              int feed_w = kProfileFeedW);
  ~ProfileFeed();
  ProfileFeed(const ProfileFeed&) = delete;
  ProfileFeed& operator=(const ProfileFeed&) = delete;

  // `next` is asked for a move only on clocks where `ready` says so (a
  // source that knows its moves before it may offer them); unset: always.
  void source_ready(std::function<bool()> ready) { ready_ = std::move(ready); }
  // The engine has taken `commands` commands, one a move: its next command
  // must wait, as the last move taken is an exact stop the block has not
  // finished (see the top).
  bool holds_next_command(uint64_t commands) const { return stop_open_ && commands >= taken_; }
  // This clock's feed word (both faces' register), then one clock edge.
  uint64_t clock();
  int feed_w() const { return feed_w_; }
  bool failed() const { return !failure_.empty(); }
  const std::string& failure() const { return failure_; }  // the first mismatch
  uint64_t moves_taken() const { return taken_; }
  uint64_t clocks() const { return clocks_; }
  bool busy() const;
  bool source_done() const { return done_; }
  // Feed hold (the block's hold_i) on the clocks [from, to): a controlled
  // stop along the path within the profile's limits, then the planned
  // profile goes on. One window a run.
  void hold_between(uint64_t from, uint64_t to);
  // The stop of that hold: the speed when it began, the operations and
  // clocks from its first clock to the first clock at speed 0 (stopped is
  // false while the speed has not reached 0, or when no hold began).
  struct HoldStop {
    bool began = false, stopped = false;
    double speed = 0;  // operations per clock when the hold began
    double ops = 0;    // operations travelled until speed 0
    uint64_t clocks = 0;
  };
  const HoldStop& hold_stop() const { return stop_; }
  uint64_t hold_clocks() const { return hold_to_ - hold_from_; }
  // The feed override (the block's ovr_i), steps in clock order; 100 % before
  // the first. Throws std::invalid_argument when the clocks are not in order.
  void override_schedule(std::vector<OverrideStep> steps);
  unsigned override_word() const { return ovr_; }  // the word driven on the last clock
  // Every move was taken and the profile has been at rest for 4 ticks: an
  // engine still busy behind it will never finish (it fell behind, stalled
  // by its step/dir stage, and the profile's distance ran out first).
  bool stranded() const;

 private:
  // Both faces of the block at one feed width (profile_feed.cpp).
  struct Faces;
  template <int W>
  struct FacesOf;
  template <int W>
  uint64_t step(FacesOf<W>& f);
  // fn(the faces at feed_w_): the one switch over the builds (profile_feed.cpp).
  template <class Fn>
  auto visit(Fn&& fn) const;
  std::unique_ptr<Faces> f_;
  int feed_w_ = kProfileFeedW;
  std::function<bool(ProfileWords&)> next_;
  std::function<bool()> ready_;
  ProfileWords offered_;
  bool valid_ = false, done_ = false;
  bool stop_open_ = false;  // an exact stop taken: the next move waits for rest
  uint64_t taken_ = 0, clocks_ = 0, rest_clocks_ = 0;
  uint64_t hold_from_ = 0, hold_to_ = 0;
  std::vector<OverrideStep> ovr_steps_;
  size_t ovr_next_ = 0;
  unsigned ovr_ = 128;
  HoldStop stop_;
  std::string failure_;
};

}  // namespace hwinterp::tb

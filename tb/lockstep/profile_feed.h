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

namespace hwinterp::tb {

// The feed word's fraction bits of the harness's build (motion_top_n3/n4's
// FEED_W); a core with a wider FEED_W takes the word shifted up, exactly.
inline constexpr int kProfileFeedW = 24;

struct ProfileWords {
  uint64_t ops = 0;
  uint32_t target = 0, end = 0;
};

class ProfileFeed {
 public:
  // `next` gives the profile's moves in order (false: none left).
  ProfileFeed(uint64_t q, unsigned len, std::function<bool(ProfileWords&)> next);
  ~ProfileFeed();
  ProfileFeed(const ProfileFeed&) = delete;
  ProfileFeed& operator=(const ProfileFeed&) = delete;

  // This clock's feed word (both faces' register), then one clock edge.
  uint64_t clock();
  bool failed() const { return !failure_.empty(); }
  const std::string& failure() const { return failure_; }  // the first mismatch
  uint64_t moves_taken() const { return taken_; }
  uint64_t clocks() const { return clocks_; }
  bool busy() const;
  bool source_done() const { return done_; }
  // Every move was taken and the profile has been at rest for 4 ticks: an
  // engine still busy behind it will never finish (it fell behind, stalled
  // by its step/dir stage, and the profile's distance ran out first).
  bool stranded() const;

 private:
  struct Faces;
  std::unique_ptr<Faces> f_;
  std::function<bool(ProfileWords&)> next_;
  ProfileWords offered_;
  bool valid_ = false, done_ = false;
  uint64_t taken_ = 0, clocks_ = 0, rest_clocks_ = 0;
  std::string failure_;
};

}  // namespace hwinterp::tb

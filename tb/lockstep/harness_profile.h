// The feed profile's build as the harness runs it, described once: the
// cycle-accurate face (`hwinterp profile`, tb/lockstep/profile_feed.h), the
// model's registers (feed_profile_build) and, in rtl/CMakeLists.txt, the
// Verilated Vfeed_profile_harness_cc take these widths.
#pragma once

#include "hls/feed_profile.h"
#include "tb/lockstep/profile_feed.h"

namespace hwinterp::tb {

// 24-bit feed words (kProfileFeedW), 48 speed bits, ticks of 1024 clocks
// (20.48 us at 50 MHz), moving sums up to 1024 ticks (A/J up to 21 ms at
// 50 MHz), 16-bit levels, 28-bit moves.
inline constexpr int kProfileSpdW = 48, kProfileTickW = 10, kProfileLenW = 10, kProfileLvlW = 16,
                     kProfileOpsW = 28;
using HarnessProfile = hls::FeedProfile<kProfileFeedW, kProfileSpdW, kProfileTickW, kProfileLenW,
                                        kProfileLvlW, kProfileOpsW>;

}  // namespace hwinterp::tb

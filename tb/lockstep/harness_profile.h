// The feed profile's build as the harness runs it, described once: the
// cycle-accurate face (`hwinterp profile`, tb/lockstep/profile_feed.h), the
// model's registers (feed_profile_build) and, in rtl/CMakeLists.txt, the
// Verilated Vfeed_profile_f<W>_cc take these widths.
#pragma once

#include "hls/feed_profile.h"
#include "tb/lockstep/profile_feed.h"

namespace hwinterp::tb {

// 24-bit feed words (kProfileFeedW), 48 speed bits, ticks of 1024 clocks
// (20.48 us at 50 MHz), moving sums up to 1024 ticks (A/J up to 21 ms at
// 50 MHz), 16-bit levels, 28-bit moves.
inline constexpr int kProfileSpdW = 48, kProfileTickW = 10, kProfileLenW = 10, kProfileLvlW = 16,
                     kProfileOpsW = 28;
// The same build with W-bit feed words: the harness builds it at every FEED_W
// of cmake/cores.cmake's variants (rtl/CMakeLists.txt: Vfeed_profile_f<W>_cc,
// listed by HWINTERP_PROFILE_FEED_WS in hwinterp_profile_builds.h), so the
// block drives each core's feed_i at the core's own width.
template <int W>
using HarnessProfileAt =
    hls::FeedProfile<W, kProfileSpdW, kProfileTickW, kProfileLenW, kProfileLvlW, kProfileOpsW>;
using HarnessProfile = HarnessProfileAt<kProfileFeedW>;

}  // namespace hwinterp::tb

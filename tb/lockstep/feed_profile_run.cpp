#include "tb/lockstep/feed_profile_run.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "tb/lockstep/harness_profile.h"

namespace hwinterp::tb {
namespace {

using Profile = HarnessProfile;
constexpr int kTickClocks = 1 << kProfileTickW;
constexpr uint64_t kFull = uint64_t(1) << kProfileFeedW;

}  // namespace

models::ProfileBuild feed_profile_build(double clock_hz) {
  models::ProfileBuild b;
  b.spd_w = kProfileSpdW;
  b.tick_w = kProfileTickW;
  b.len_w = kProfileLenW;
  b.lvl_w = kProfileLvlW;
  b.clock_hz = clock_hz;
  return b;
}

ProfileRunResult run_feed_profile(const models::PathLimits& limits, double clock_hz,
                                  const std::vector<ProfileMove>& moves, bool keep_trace,
                                  const std::vector<OverrideStep>& override, double max_clocks) {
  ProfileRunResult res;
  const models::ProfileBuild build = feed_profile_build(clock_hz);
  res.regs = models::profile_registers(limits, build);
  res.tick_seconds = kTickClocks / clock_hz;
  std::vector<Profile::Command> cmds;
  std::vector<uint64_t> ends;  // cumulative ops at each move's end
  uint64_t need = 0;
  for (size_t i = 0; i < moves.size(); ++i) {
    const ProfileMove& m = moves[i];
    if (m.ops < 1 || m.ops >= (uint64_t(1) << 28)) {
      std::ostringstream os;
      os << "move " << i + 1 << ": ops " << m.ops << " is outside 1..2^28-1";
      throw std::invalid_argument(os.str());
    }
    Profile::Command c;
    c.ops = m.ops;
    c.target =
        m.target_speed > 0 ? models::profile_level(res.regs, m.target_speed) : res.regs.max_level;
    c.end = std::min<uint32_t>(c.target.to_uint(), models::profile_level(res.regs, m.end_speed));
    c.max = m.max_speed > 0 ? models::profile_level(res.regs, m.max_speed) : res.regs.max_level;
    if (c.target == 0) {  // a move at level 0 never ends
      std::ostringstream os;
      os << "move " << i + 1 << ": its speed "
         << (m.target_speed > 0 ? m.target_speed : limits.velocity)
         << " ops/s is below one level of the profile, " << res.regs.level_speed
         << " ops/s at this clock and these limits";
      throw std::invalid_argument(os.str());
    }
    cmds.push_back(c);
    need += m.ops;
    ends.push_back(need);
  }
  uint32_t entry = 0;
  for (const Profile::Command& c : cmds) {
    res.estimated_clocks += models::profile_move_clocks(
        res.regs, build, entry, c.ops.to_uint64(),
        c.max == 0 ? c.target.to_uint() : std::min(c.target.to_uint(), c.max.to_uint()),
        c.end.to_uint());
    entry = c.end.to_uint();
  }
  if (res.estimated_clocks > max_clocks) {
    std::ostringstream os;
    os << "the moves take about " << res.estimated_clocks << " clocks ("
       << res.estimated_clocks / clock_hz << " s) at this clock and these limits, beyond the "
       << "ceiling of " << max_clocks << " clocks (--max-clocks)";
    throw std::invalid_argument(os.str());
  }
  const uint64_t ceiling = static_cast<uint64_t>(std::min(max_clocks, 1e18));
  Profile p;
  p.reset();
  size_t sent = 0, done_moves = 0;
  uint64_t phase = 0;
  const double to_speed = std::ldexp(clock_hz, -48);  // v -> ops/s
  double v1 = 0, v2 = 0;
  int seen = 0;
  size_t ovr_next = 0;
  unsigned ovr = Profile::kOvrOne;
  for (uint64_t clk = 0; clk < ceiling; ++clk) {
    if (clk % kTickClocks == 0) {
      const double v = static_cast<double>(p.state().v) * to_speed;
      if (keep_trace) res.tick_speed.push_back(v);
      res.peak_speed = std::max(res.peak_speed, v);
      if (seen >= 1) res.peak_accel = std::max(res.peak_accel, std::abs(v - v1) / res.tick_seconds);
      if (seen >= 2)
        res.peak_jerk = std::max(res.peak_jerk,
                                 std::abs(v - 2 * v1 + v2) / (res.tick_seconds * res.tick_seconds));
      v2 = v1;
      v1 = v;
      ++seen;
    }
    phase += std::min(p.feed(), kFull);
    while (phase >= kFull && res.ops < need) {
      phase -= kFull;
      ++res.ops;
      while (done_moves < ends.size() && res.ops == ends[done_moves]) {
        res.move_end_clock.push_back(clk + 1);
        res.move_end_speed.push_back(static_cast<double>(p.state().v) * to_speed);
        ++done_moves;
      }
    }
    if (phase >= kFull) phase &= kFull - 1;  // carries past the stream's end are not taken
    if (res.ops == need && res.rest_clock == 0 && p.state().v == 0) res.rest_clock = clk;
    const bool valid = sent < cmds.size();
    const bool take = valid && p.cmd_ready();
    while (ovr_next < override.size() && override[ovr_next].at <= clk)
      ovr = override[ovr_next++].word;
    p.clock(valid, valid ? cmds[sent] : Profile::Command{}, false, res.regs.q, res.regs.len, ovr);
    if (take) ++sent;
    if (res.rest_clock != 0 && !p.busy()) break;
  }
  if (res.rest_clock == 0) {
    std::ostringstream os;
    os << "the profile did not finish within " << ceiling << " clocks (" << res.ops << " of "
       << need << " ops taken; estimated " << res.estimated_clocks << ")";
    throw std::runtime_error(os.str());
  }
  return res;
}

}  // namespace hwinterp::tb

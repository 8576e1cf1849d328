#include "tb/monitor/step_output_monitor.h"

namespace hwinterp::tb {

bool parse_step_type(const std::string& name, StepType& t) {
  if (name == "stepdir")
    t = StepType::kStepDir;
  else if (name == "updown")
    t = StepType::kUpDown;
  else if (name == "quad")
    t = StepType::kQuadrature;
  else
    return false;
  return true;
}

const char* step_type_name(StepType t) {
  switch (t) {
    case StepType::kUpDown:
      return "updown";
    case StepType::kQuadrature:
      return "quad";
    default:
      return "stepdir";
  }
}

StepOutputMonitors::StepOutputMonitors(const std::vector<StepType>& types) {
  axes_.reserve(types.size());
  for (size_t i = 0; i < types.size(); ++i)
    axes_.push_back(Axis{types[i], StepdirMonitor(static_cast<int>(i))});
}

void StepOutputMonitors::reset(uint64_t cycle) {
  for (Axis& x : axes_) {
    x.line.reset(cycle);
    x.have_fall = x.have_last = x.have_change = false;
  }
  a_ = b_ = pending_ = pending_dir_ = 0;
  after_reset_ = true;
}

uint32_t StepOutputMonitors::observe_change(uint64_t cycle, uint32_t a, uint32_t b,
                                            const StepdirTiming& t, uint32_t& dir,
                                            std::vector<TimingViolation>& kept, uint64_t& count) {
  const auto need = [](uint32_t s) -> uint64_t { return s == 0 ? 1 : s; };
  const auto violation = [&](int axis, const char* rule, uint64_t measured, uint64_t required) {
    record_capped(kept, count, TimingViolation{cycle, axis, rule, measured, required});
  };
  uint32_t steps = pending_, dirs = pending_dir_;
  pending_ = pending_dir_ = 0;
  for (size_t i = 0; i < axes_.size(); ++i) {
    Axis& x = axes_[i];
    const int ax = static_cast<int>(i);
    const bool ai = (a >> i) & 1, bi = (b >> i) & 1, pa = (a_ >> i) & 1, pb = (b_ >> i) & 1;
    switch (x.type) {
      case StepType::kStepDir:
        x.line.observe(cycle, ai, bi, t, kept, count);
        if (ai && !pa) pending_ |= 1u << i, pending_dir_ |= uint32_t{bi} << i;
        break;
      case StepType::kUpDown: {
        x.line.observe(cycle, ai || bi, false, t, kept, count);
        if (ai && bi) violation(ax, "updown_both", 1, 0);
        const bool rise = (ai || bi) && !(pa || pb), fall = !(ai || bi) && (pa || pb);
        if (rise) {
          const bool neg = bi;
          if (x.have_last && neg != x.last_neg && x.have_fall &&
              cycle - x.fall < need(t.dir_hold) + need(t.dir_setup))
            violation(ax, "updown_turn", cycle - x.fall, need(t.dir_hold) + need(t.dir_setup));
          x.last_neg = neg;
          x.have_last = true;
          pending_ |= 1u << i, pending_dir_ |= uint32_t{neg} << i;
        }
        if (fall) x.fall = cycle, x.have_fall = true;
        break;
      }
      case StepType::kQuadrature: {
        if (ai == pa && bi == pb) break;
        if (ai != pa && bi != pb) {
          violation(ax, "quad_state", 2, 1);
        } else {
          // Forward 00 10 11 01: phase p with (a, b) = (p1 ^ p0, p1).
          const unsigned p0 = (pb << 1) | (pa ^ pb), p1 = (bi << 1) | (ai ^ bi);
          const bool neg = ((p0 - 1u) & 3u) == p1;
          steps |= 1u << i, dirs |= uint32_t{neg} << i;
        }
        if (x.have_change && cycle - x.change < need(t.step_len) + need(t.step_space))
          violation(ax, "quad_dwell", cycle - x.change, need(t.step_len) + need(t.step_space));
        x.change = cycle;
        x.have_change = true;
        break;
      }
    }
  }
  a_ = a;
  b_ = b;
  after_reset_ = false;
  dir = dirs;
  return steps;
}

}  // namespace hwinterp::tb

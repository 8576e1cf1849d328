// motion_soc through its bus in the direct (plain C++) loop: a `verilator
// --cc` model of rtl/motion_soc_axil.sv or rtl/motion_soc_wb.sv, a bus
// master (tb/bus/bus_master.h) and the host's transactions (tb/bus/soc_host.h)
// clocked together, one clock edge per iteration, and the step outputs
// (out_a_o, out_b_o, of each axis's step type) followed on every clock:
// turned back into steps and checked against the step/dir timing set by
// tb/monitor/step_output_monitor.h, which reports each step one clock after
// the step stage's rise; done_o is reported one clock late as well.
//
// The run tells a sink, as the lockstep bench tells its MoveObserver, every
// clock with a rising step (pulses(clock, rising, dir), then move(at,
// command)) and every completed command (done(command, at)), the command
// being the count of done_o pulses before it (motion_top's done_o, read
// through tb/bus/motion_soc_probe.vlt). LatticeRecord keeps a run's step
// events and LatticeCheck compares another run with them as it goes: the
// same steps, in the same groups and order, and every command ending after
// the same step.
#pragma once

#include <verilated.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "models/lattice_path.h"
#include "tb/bus/bus_master.h"
#include "tb/bus/hls_shadow.h"
#include "tb/bus/soc_host.h"
#include "tb/monitor/step_output_monitor.h"
#include "tb/report/progress.h"

namespace hwinterp::tb::bus {

// A run's step events: one per clock with a rising step (the rising axes in
// bits 0..7, their directions, 1 = negative, in bits 8..15), and per
// completed command the number of events before its done_o. Two bytes per
// visited lattice point.
class LatticeRecord {
 public:
  void pulses(uint32_t rising, uint32_t dir) {
    events_.push_back(static_cast<uint16_t>((rising & 0xFFu) | ((dir & rising & 0xFFu) << 8)));
  }
  void done() { done_at_.push_back(events_.size()); }
  const std::vector<uint16_t>& events() const { return events_; }
  const std::vector<uint64_t>& done_at() const { return done_at_; }

 private:
  std::vector<uint16_t> events_;
  std::vector<uint64_t> done_at_;
};

// Another run against a record, step event by step event.
class LatticeCheck {
 public:
  explicit LatticeCheck(const LatticeRecord& r) : ref_(r) {}
  void pulses(uint32_t rising, uint32_t dir) {
    const uint16_t e = static_cast<uint16_t>((rising & 0xFFu) | ((dir & rising & 0xFFu) << 8));
    if (first_point_ < 0 &&
        (points_ >= ref_.events().size() || ref_.events()[static_cast<size_t>(points_)] != e))
      first_point_ = static_cast<int64_t>(points_);
    ++points_;
  }
  void done(uint64_t command) {
    if (first_end_ < 0 && (command >= ref_.done_at().size() ||
                           ref_.done_at()[static_cast<size_t>(command)] != points_))
      first_end_ = static_cast<int64_t>(command);
    ++dones_;
  }
  uint64_t points() const { return points_; }
  uint64_t dones() const { return dones_; }
  // The first point (0-based) that differs, or -1; a shorter run differs at
  // its length.
  int64_t first_point() const {
    if (first_point_ < 0 && points_ != ref_.events().size())
      return static_cast<int64_t>(std::min<uint64_t>(points_, ref_.events().size()));
    return first_point_;
  }
  // The first command that ended after a different step, or -1.
  int64_t first_end() const {
    if (first_end_ < 0 && dones_ != ref_.done_at().size())
      return static_cast<int64_t>(std::min<uint64_t>(dones_, ref_.done_at().size()));
    return first_end_;
  }
  bool same() const { return first_point() < 0 && first_end() < 0; }

 private:
  const LatticeRecord& ref_;
  uint64_t points_ = 0, dones_ = 0;
  int64_t first_point_ = -1, first_end_ = -1;
};

// When a bus run ends and how it reports on the way.
struct SocRunLimits {
  uint64_t drain = 0;           // clocks with no step after the last completed command
  uint64_t max_clocks = 0;      // the run's ceiling: a run past it has stalled
  uint64_t progress_every = 0;  // a progress line on stderr every this many clocks (0: none)
  double expected_clocks = 0;   // its estimate, for the line's percent (0: none)
};

struct SocRunResult {
  uint64_t clocks = 0;     // clock edges after reset
  uint64_t completed = 0;  // done_o pulses
  HostCounts host;
  models::LatticePoint end;  // the axes at the end (from the origin)
  bool timed_out = false;    // max_clocks passed first
  ShadowMismatch shadow;     // the HLS face's first difference (clock 0: none)
  // The step outputs against the timing set, by their types: the first few
  // violations and their count.
  std::vector<TimingViolation> timing_violations;
  uint64_t timing_violation_count = 0;
};

// Runs the host's program through `Model` (a Verilated motion_soc top) with
// master `Master<Model>`; Probe::done(model) reads motion_top's done_o.
// `shadow` (tb/bus/hls_shadow.h: the HLS face, or NoShadow) takes the same
// pins on every clock and is compared with the model. The run ends when the
// host is done, every push completed and `limits.drain` clocks passed with no
// step; at the HLS face's first difference; or after `limits.max_clocks`.
// Reset: two rising edges with rst_ni low (probe and e-stop low; the caller
// has put the bus pins in their idle state). before_edge(m) runs before each
// rising edge: an HLS shadow samples the pins there.
template <class Model, class BeforeEdge>
void reset_soc(Model& m, BeforeEdge&& before_edge) {
  m.probe_i = 0;
  m.estop_i = 0;
  m.rst_ni = 0;
  for (int i = 0; i < 2; ++i) {
    m.clk_i = 0;
    m.eval();
    before_edge(m);
    m.clk_i = 1;
    m.eval();
  }
  m.rst_ni = 1;
}

// One clock of a Verilated SoC top with its bus master and HLS shadow: the
// master drives the bus pins, the falling edge settles, the master and the
// shadow sample the pins, the rising edge; then the shadow compares (clock:
// the count it reports a difference at). Returns motion_top's done_o.
template <class Probe, class Model, class Master, class Shadow>
bool soc_clock(Model& m, Master& master, Shadow& shadow, uint64_t clock) {
  master.drive(m);
  m.clk_i = 0;
  m.eval();
  master.sample(m);
  shadow.before_edge(m);
  m.clk_i = 1;
  m.eval();
  const bool done = Probe::done(m);
  shadow.after_edge(m, done, clock);
  return done;
}

template <class Model, template <class> class Master, class Probe, class Src, class Sink,
          class Shadow>
SocRunResult run_soc(Src& src, const SocSetup& setup, Sink& sink, Shadow& shadow,
                     const WaitStates& waits, const SocRunLimits& limits) {
  struct RestoreThreadContext {
    ~RestoreThreadContext() { Verilated::threadContextp(Verilated::defaultContextp()); }
  } restore;
  VerilatedContext context;
  Model m(&context);
  Master<Model> master(waits);
  SocHost<Src> host(src, setup);
  SocRunResult r;
  r.end.assign(static_cast<size_t>(setup.axes), 0);
  master.drive(m);  // the bus idle
  reset_soc(m, [&](Model& mm) { shadow.before_edge(mm); });
  const uint32_t mask = (1u << setup.axes) - 1;
  std::vector<StepType> types;
  for (int i = 0; i < setup.axes; ++i)
    types.push_back(static_cast<StepType>(setup.step_type[static_cast<size_t>(i)]));
  StepOutputMonitors outputs(types);
  outputs.reset(0);
  const StepdirTiming timing{setup.step_len, setup.step_space, setup.dir_setup, setup.dir_hold};
  uint64_t quiet = 0;
  bool done_prev = false;
  BusTxn t;
  BusRsp rsp;
  tb::ProgressLine progress(limits.expected_clocks);
  while (r.clocks < limits.max_clocks) {
    if (master.idle() && host.next(t, m.irq_o)) master.issue(t);
    const bool done = soc_clock<Probe>(m, master, shadow, ++r.clocks);
    if (limits.progress_every && r.clocks % limits.progress_every == 0)
      progress.print(r.clocks, "motion_soc bus",
                     std::to_string(r.completed) + " commands done of " +
                         std::to_string(host.counts().pushes) + " pushed");
    if (shadow.failed()) break;
    if (master.take(rsp)) host.response(rsp);
    uint32_t dir = 0;
    const uint32_t rising = outputs.observe(r.clocks, m.out_a_o & mask, m.out_b_o & mask, timing,
                                            dir, r.timing_violations, r.timing_violation_count);
    if (rising) {
      for (int i = 0; i < setup.axes; ++i)
        if (rising >> i & 1) r.end[static_cast<size_t>(i)] += (dir >> i & 1) ? -1 : 1;
      sink.pulses(r.clocks, rising, dir);
      sink.move(r.end, r.completed);
      quiet = 0;
    } else {
      ++quiet;
    }
    // done_o one clock late too, after the steps of its clock.
    if (done_prev) sink.done(r.completed++, r.end);
    done_prev = done;
    if (host.finished() && r.completed >= host.counts().pushes && quiet >= limits.drain) break;
  }
  progress.finish();
  r.timed_out = r.clocks >= limits.max_clocks;
  r.shadow = shadow.mismatch();
  r.host = host.counts();
  m.final();
  return r;
}

}  // namespace hwinterp::tb::bus

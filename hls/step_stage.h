// The output stage shared by every core: per axis a StepdirAxis and a signed
// position counter, and once for all axes the settings as the axes take them
// (StepdirTiming): the cycle behaviour of rtl/step_stage.sv (see there for
// the contract). Synthesizable subset: SystemC integers, fixed arrays.
#pragma once

#include <systemc>

#include "hls/stepdir_axis.h"
#include "hls/stepper_io.h"

namespace hwinterp::hls {

template <int AXES, int POS_W, int TIM_W>
class StepStage {
 public:
  using pos_t = sc_dt::sc_uint<POS_W>;
  using Settings = StepdirSettings<TIM_W>;

  // What the engine asks of the stage on one clock.
  struct Request {
    bool want_valid[AXES];  // the running command moves the axis
    bool want_dir[AXES];    // ...in this direction (true: negative)
  };

  void reset() {
    timing_.reset();
    for (int i = 0; i < AXES; ++i) {
      axis_[i].reset();
      pos_q_[i] = 0;
    }
  }

  // A pulse in the requested direction may start on axis `i` on the next
  // clock (combinational; whether the axis moves at all is the engine's).
  bool ready(int i, const Request& r) const { return axis_[i].ready(r.want_dir[i]); }

  // One rising clock edge; fire[i] only for ready axes.
  void clock(const Settings& s, const Request& r, const bool (&fire)[AXES]) {
    const StepdirPrepared<TIM_W> p = timing_.prepare(s);
    timing_.clock();
    for (int i = 0; i < AXES; ++i) {
      axis_[i].tick(p, r.want_valid[i], r.want_dir[i], fire[i]);
      if (fire[i]) pos_q_[i] = r.want_dir[i] ? pos_t(pos_q_[i] - 1) : pos_t(pos_q_[i] + 1);
    }
  }

  bool step(int i) const { return axis_[i].step(); }
  bool dir(int i) const { return axis_[i].dir(); }
  const pos_t& pos(int i) const { return pos_q_[i]; }
  bool any_step() const {
    bool any = false;
    for (int i = 0; i < AXES; ++i) any = any || axis_[i].step();
    return any;
  }

  // The shared outputs of a core around this stage: busy_o while the engine
  // is busy (a command buffered or running) or a pulse is high.
  StepperOutputs<AXES, POS_W> outputs(bool cmd_ready, bool engine_busy, bool done) const {
    StepperOutputs<AXES, POS_W> o;
    o.cmd_ready = cmd_ready;
    o.step = 0;
    o.dir = 0;
    for (int i = 0; i < AXES; ++i) {
      o.step[i] = axis_[i].step();
      o.dir[i] = axis_[i].dir();
      o.pos[i] = pos_q_[i];
    }
    o.busy = engine_busy || any_step();
    o.done = done;
    return o;
  }

 private:
  StepdirTiming<TIM_W> timing_;
  StepdirAxis<TIM_W> axis_[AXES];
  pos_t pos_q_[AXES];
};

}  // namespace hwinterp::hls

// Direct lockstep mode: the HLS core's tick() and the `verilator --cc` model
// of rtl/dda_line.sv stepped together in a plain C++ loop, one clock edge per
// iteration: the fast mode for long regressions.
#pragma once

#include <verilated.h>

#include "dda_line_bench.h"
#include "dda_line_variants.h"
#include "hls/dda_line.h"
#include "pin_bits.h"

namespace hwinterp::tb {

template <class Cfg>
class DdaLineDirect {
  using Core = hls::DdaLine<Cfg>;
  using Rtl = typename RtlOf<Cfg>::Cc;
  static constexpr int AXES = Cfg::AXES, ACC_W = Cfg::ACC_W, POS_W = Cfg::POS_W;

 public:
  static void run(DdaLineBench& bench) {
    // A model makes its context the thread's current one; hand the thread
    // back to the default context when this one dies, or a later model
    // without an explicit context (the SystemC ones) would pick up a dangling
    // pointer (Verilator then deadlocks in its own fatal-error path).
    struct RestoreThreadContext {
      ~RestoreThreadContext() { Verilated::threadContextp(Verilated::defaultContextp()); }
    } restore;
    VerilatedContext context;
    Rtl rtl(&context);
    Core hls;
    typename Core::Inputs in;
    rtl.clk_i = 0;
    rtl.rst_ni = 0;
    rtl.eval();
    while (!bench.finished()) {
      const DdaLineFrame& f = bench.next_frame();
      drive(f, rtl, in);
      // Inputs and the rising edge in one eval: with rst_ni low the RTL's
      // asynchronous reset wins, as tick() with rst_n low does.
      rtl.clk_i = 1;
      rtl.eval();
      hls.tick(in);
      bench.observe(read(hls.outputs()), read(rtl));
      rtl.clk_i = 0;
      rtl.eval();
    }
    rtl.final();
  }

 private:
  static void drive(const DdaLineFrame& f, Rtl& rtl, typename Core::Inputs& in) {
    rtl.rst_ni = f.rst_n;
    rtl.cmd_valid_i = f.cmd_valid;
    for (int i = 0; i < AXES; ++i) {
      const uint64_t d = static_cast<uint64_t>(f.cmd_delta[static_cast<size_t>(i)]);
      put_bits(rtl.cmd_delta_i, i * ACC_W, ACC_W, d);
      in.cmd_delta[i] = d;
    }
    rtl.feed_i = static_cast<uint32_t>(f.feed);
    rtl.half_preload_i = f.half_preload;
    rtl.step_len_i = f.timing.step_len;
    rtl.step_space_i = f.timing.step_space;
    rtl.dir_setup_i = f.timing.dir_setup;
    rtl.dir_hold_i = f.timing.dir_hold;
    in.rst_n = f.rst_n;
    in.cmd_valid = f.cmd_valid;
    in.feed = f.feed;
    in.half_preload = f.half_preload;
    in.timing.step_len = f.timing.step_len;
    in.timing.step_space = f.timing.step_space;
    in.timing.dir_setup = f.timing.dir_setup;
    in.timing.dir_hold = f.timing.dir_hold;
  }

  static DdaLinePins read(const typename Core::Outputs& o) {
    DdaLinePins p;
    p.cmd_ready = o.cmd_ready;
    p.step = static_cast<uint32_t>(o.step.to_uint());
    p.dir = static_cast<uint32_t>(o.dir.to_uint());
    for (int i = 0; i < AXES; ++i) p.pos[static_cast<size_t>(i)] = o.pos[i].to_uint64();
    p.busy = o.busy;
    p.done = o.done;
    return p;
  }

  static DdaLinePins read(const Rtl& rtl) {
    DdaLinePins p;
    p.cmd_ready = rtl.cmd_ready_o;
    p.step = rtl.step_o;
    p.dir = rtl.dir_o;
    for (int i = 0; i < AXES; ++i)
      p.pos[static_cast<size_t>(i)] = get_bits(rtl.pos_o, i * POS_W, POS_W);
    p.busy = rtl.busy_o;
    p.done = rtl.done_o;
    return p;
  }
};

}  // namespace hwinterp::tb

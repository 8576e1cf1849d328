// SystemC lockstep mode: the HLS core's SC_MODULE and the `verilator --sc`
// model of rtl/dda_line.sv bound to the same input signals and one sc_clock.
// A process on the falling edge, when both DUTs' outputs have settled,
// compares them (through DdaLineBench) and drives the inputs the next rising
// edge samples: the same order of events as the direct mode.
#pragma once

#include <systemc>

#include "dda_line_bench.h"
#include "dda_line_variants.h"
#include "hls/dda_line_module.h"

namespace hwinterp::tb {

// Counts benches still running in one elaboration; the last one stops it.
class ScRunControl {
 public:
  void add() { ++running_; }
  void finished_one() {
    if (--running_ == 0) sc_core::sc_stop();
  }

 private:
  int running_ = 0;
};

template <class Cfg>
SC_MODULE(DdaLineScBench) {
  static constexpr int AXES = Cfg::AXES, ACC_W = Cfg::ACC_W, POS_W = Cfg::POS_W, TIM_W = Cfg::TIM_W,
                       FEED_W = Cfg::FEED_W;
  template <int W>
  using pin_t = hls::pin_t<W>;

  struct Outputs {
    sc_core::sc_signal<bool> cmd_ready, busy, done;
    sc_core::sc_signal<pin_t<AXES>> step, dir;
    sc_core::sc_signal<pin_t<AXES * POS_W>> pos;
  };

  // The clock falls first (t = 0), then rises every 10 ns from t = 5 ns.
  sc_core::sc_clock clk{"clk", 10, sc_core::SC_NS, 0.5, 0, sc_core::SC_NS, false};
  sc_core::sc_signal<bool> rst_n{"rst_n"}, cmd_valid{"cmd_valid"}, half_preload{"half_preload"};
  sc_core::sc_signal<pin_t<AXES * ACC_W>> cmd_delta{"cmd_delta"};
  sc_core::sc_signal<pin_t<FEED_W + 1>> feed{"feed"};
  sc_core::sc_signal<pin_t<TIM_W>> step_len{"step_len"}, step_space{"step_space"},
      dir_setup{"dir_setup"}, dir_hold{"dir_hold"};
  Outputs hls_out, rtl_out;
  hls::DdaLineModule<Cfg> hls{"hls"};
  typename RtlOf<Cfg>::Sc rtl{"rtl"};

  DdaLineScBench(sc_core::sc_module_name name, DdaLineBench & bench, ScRunControl & control)
      : sc_core::sc_module(name), bench_(bench), control_(control) {
    bind(hls, hls_out);
    bind(rtl, rtl_out);
    control_.add();
    SC_METHOD(on_falling_edge);
    sensitive << clk.negedge_event();
    dont_initialize();
  }
  SC_HAS_PROCESS(DdaLineScBench);

 private:
  template <class Dut>
  void bind(Dut & d, Outputs & o) {
    d.clk_i(clk);
    d.rst_ni(rst_n);
    d.cmd_valid_i(cmd_valid);
    d.cmd_ready_o(o.cmd_ready);
    d.cmd_delta_i(cmd_delta);
    d.feed_i(feed);
    d.half_preload_i(half_preload);
    d.step_len_i(step_len);
    d.step_space_i(step_space);
    d.dir_setup_i(dir_setup);
    d.dir_hold_i(dir_hold);
    d.step_o(o.step);
    d.dir_o(o.dir);
    d.pos_o(o.pos);
    d.busy_o(o.busy);
    d.done_o(o.done);
  }

  static DdaLinePins read(const Outputs& o) {
    DdaLinePins p;
    p.cmd_ready = o.cmd_ready.read();
    p.step = static_cast<uint32_t>(hls::pin_field<AXES>(o.step.read(), 0, AXES));
    p.dir = static_cast<uint32_t>(hls::pin_field<AXES>(o.dir.read(), 0, AXES));
    const pin_t<AXES* POS_W>& pos = o.pos.read();
    for (int i = 0; i < AXES; ++i)
      p.pos[static_cast<size_t>(i)] = hls::pin_field<AXES * POS_W>(pos, i * POS_W, POS_W);
    p.busy = o.busy.read();
    p.done = o.done.read();
    return p;
  }

  void drive(const DdaLineFrame& f) {
    rst_n.write(f.rst_n);
    cmd_valid.write(f.cmd_valid);
    for (int i = 0; i < AXES; ++i)
      hls::set_pin_field<AXES * ACC_W>(delta_, i * ACC_W, ACC_W,
                                       static_cast<uint64_t>(f.cmd_delta[static_cast<size_t>(i)]));
    cmd_delta.write(delta_);
    feed.write(f.feed);
    half_preload.write(f.half_preload);
    step_len.write(f.timing.step_len);
    step_space.write(f.timing.step_space);
    dir_setup.write(f.timing.dir_setup);
    dir_hold.write(f.timing.dir_hold);
  }

  void on_falling_edge() {
    // Benches in one elaboration share the kernel: a finished one idles
    // until the last one stops it, and must not observe those extra edges.
    if (stopped_) return;
    if (started_) bench_.observe(read(hls_out), read(rtl_out));
    started_ = true;
    if (bench_.finished()) {
      stopped_ = true;
      control_.finished_one();
      return;
    }
    drive(bench_.next_frame());
  }

  DdaLineBench& bench_;
  ScRunControl& control_;
  bool started_ = false;
  bool stopped_ = false;
  pin_t<AXES* ACC_W> delta_ = 0;  // kept: building a wide pin value allocates
};

}  // namespace hwinterp::tb

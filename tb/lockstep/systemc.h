// SystemC lockstep mode, for any core: the HLS core's SC_MODULE
// (hls::StepperModule) and the `verilator --sc` model of its RTL bound to the
// same input signals and one sc_clock. A process on the falling edge, when
// both DUTs' outputs have settled, compares them (through Bench<A>) and
// drives the inputs the next rising edge samples: the same order of events
// as the direct mode. The shared signals are here; the core's own come from
// its payload's field list (OwnSignals).
#pragma once

#include <systemc>

#include <tuple>
#include <utility>

#include "hls/stepper_module.h"
#include "hwinterp_variants.h"
#include "tb/lockstep/bench.h"
#include "tb/lockstep/payload_pins.h"

namespace hwinterp::tb {

// The core's own input signals, one per field of its payload Own
// (hls/fields.h), named as the RTL's ports and bound to both DUTs.
template <class Own>
class OwnSignals {
  template <class Tuple>
  struct Types;
  template <class... F>
  struct Types<std::tuple<F...>> {
    using signals = std::tuple<sc_core::sc_signal<hls::pin_t<F::kBits>>...>;
    using values = std::tuple<hls::pin_t<F::kBits>...>;
  };
  using Fields = decltype(Own::fields());
  static constexpr std::size_t kCount = hls::kFieldCount<Own>;

 public:
  OwnSignals() : OwnSignals(std::make_index_sequence<kCount>{}) {}

  // The Verilated --sc model: its port of each field's name.
  template <class Rtl>
  void bind_rtl(Rtl& rtl) {
    bind_rtl(rtl, std::make_index_sequence<kCount>{});
  }
  // The HLS SC_MODULE: its FieldPorts.
  template <class Module>
  void bind_hls(Module& m) {
    bind_hls(m, std::make_index_sequence<kCount>{});
  }
  void write(const Own& own) { write(own, std::make_index_sequence<kCount>{}); }

 private:
  template <std::size_t... I>
  explicit OwnSignals(std::index_sequence<I...>) : signals_(std::get<I>(Own::fields()).name...) {}
  template <class Rtl, std::size_t... I>
  void bind_rtl(Rtl& rtl, std::index_sequence<I...>) {
    const Fields fields = Own::fields();
    (std::get<I>(fields).port_of(rtl)(std::get<I>(signals_)), ...);
  }
  template <class Module, std::size_t... I>
  void bind_hls(Module& m, std::index_sequence<I...>) {
    (m.template own_port<I>()(std::get<I>(signals_)), ...);
  }
  template <std::size_t... I>
  void write(const Own& own, std::index_sequence<I...>) {
    const Fields fields = Own::fields();
    (write_field(std::get<I>(fields), own, std::get<I>(values_), std::get<I>(signals_)), ...);
  }
  template <class F, class Value, class Signal>
  static void write_field(const F& f, const Own& own, Value& v, Signal& s) {
    for (int i = 0; i < F::kCount; ++i)
      hls::set_pin_field<F::kBits>(v, i * F::kWidth, F::kWidth, f.get(own, i));
    s.write(v);
  }

  typename Types<Fields>::signals signals_;
  typename Types<Fields>::values values_{};  // kept: building a wide pin value allocates
};

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

template <class A, class Cfg>
SC_MODULE(ScBench) {
  static constexpr int AXES = Cfg::AXES, POS_W = Cfg::POS_W, TIM_W = Cfg::TIM_W,
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
  sc_core::sc_signal<bool> rst_n{"rst_n"}, cmd_valid{"cmd_valid"}, abort{"abort"};
  sc_core::sc_signal<pin_t<FEED_W + 1>> feed{"feed"};
  sc_core::sc_signal<pin_t<TIM_W>> step_len{"step_len"}, step_space{"step_space"},
      dir_setup{"dir_setup"}, dir_hold{"dir_hold"};
  using Own = OwnOf<A, Cfg>;
  OwnSignals<Own> own;  // the core's own input signals
  Outputs hls_out, rtl_out;
  hls::StepperModule<typename A::template Hls<Cfg>> hls{"hls"};
  typename RtlOf<Cfg>::Sc rtl{"rtl"};

  ScBench(sc_core::sc_module_name name, Bench<A> & bench, ScRunControl & control)
      : sc_core::sc_module(name), bench_(bench), control_(control) {
    bind(hls, hls_out);
    bind(rtl, rtl_out);
    own.bind_hls(hls);
    own.bind_rtl(rtl);
    control_.add();
    SC_METHOD(on_falling_edge);
    sensitive << clk.negedge_event();
    dont_initialize();
  }
  SC_HAS_PROCESS(ScBench);

 private:
  template <class Dut>
  void bind(Dut & d, Outputs & o) {
    d.clk_i(clk);
    d.rst_ni(rst_n);
    d.cmd_valid_i(cmd_valid);
    d.cmd_ready_o(o.cmd_ready);
    d.feed_i(feed);
    d.step_len_i(step_len);
    d.step_space_i(step_space);
    d.dir_setup_i(dir_setup);
    d.dir_hold_i(dir_hold);
    d.abort_i(abort);
    d.step_o(o.step);
    d.dir_o(o.dir);
    d.pos_o(o.pos);
    d.busy_o(o.busy);
    d.done_o(o.done);
  }

  static OutPins read(const Outputs& o) {
    OutPins p;
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

  void drive(const Frame<A>& f) {
    rst_n.write(f.rst_n);
    cmd_valid.write(f.cmd_valid);
    feed.write(f.feed);
    step_len.write(f.timing.step_len);
    step_space.write(f.timing.step_space);
    dir_setup.write(f.timing.dir_setup);
    dir_hold.write(f.timing.dir_hold);
    abort.write(f.abort);
    if (f.payload_serial() != payload_serial_) {
      payload_serial_ = f.payload_serial();
      A::to_own(f.cmd(), f.setup(), own_value_);
      own.write(own_value_);
    }
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

  Bench<A>& bench_;
  ScRunControl& control_;
  Own own_value_{};
  uint64_t payload_serial_ = ~uint64_t{0};  // none on the signals yet
  bool started_ = false;
  bool stopped_ = false;
};

}  // namespace hwinterp::tb

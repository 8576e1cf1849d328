// Direct lockstep mode, for any core: the HLS core's tick() and the
// `verilator --cc` model of its RTL stepped together in a plain C++ loop, one
// clock edge per iteration: the fast mode for long regressions. The shared
// pins are driven and read here, and the core's own from its payload's field
// list (hls/fields.h), with plain stores (the payload converted only on the
// clocks where it changes): no virtual call per pin per clock.
#pragma once

#include <verilated.h>

#include "hls/stepper_io.h"
#include "hwinterp_variants.h"
#include "tb/lockstep/bench.h"
#include "tb/lockstep/payload_pins.h"
#include "tb/lockstep/rtl_pins.h"

namespace hwinterp::tb {

// The shared outputs of an HLS core as plain integers.
template <int AXES, int POS_W>
OutPins read_outputs(const hls::StepperOutputs<AXES, POS_W>& o) {
  OutPins p;
  p.cmd_ready = o.cmd_ready;
  p.step = static_cast<uint32_t>(o.step.to_uint());
  p.dir = static_cast<uint32_t>(o.dir.to_uint());
  for (int i = 0; i < AXES; ++i) p.pos[static_cast<size_t>(i)] = o.pos[i].to_uint64();
  p.busy = o.busy;
  p.done = o.done;
  return p;
}

// The shared outputs of a `verilator --cc` model.
template <class Cfg, class Rtl>
OutPins read_outputs(const Rtl& rtl) {
  OutPins p;
  p.cmd_ready = rtl.cmd_ready_o;
  p.step = rtl.step_o;
  p.dir = rtl.dir_o;
  for (int i = 0; i < Cfg::AXES; ++i)
    p.pos[static_cast<size_t>(i)] = get_bits(rtl.pos_o, i * Cfg::POS_W, Cfg::POS_W);
  p.busy = rtl.busy_o;
  p.done = rtl.done_o;
  return p;
}

// The payload onto the Verilated --cc model's own input ports, field by
// field (hls/fields.h).
template <class Own, class Rtl>
void drive_own(const Own& own, Rtl& rtl) {
  hls::for_each_field<Own>([&](const auto& f, std::size_t) {
    using F = std::decay_t<decltype(f)>;
    auto& port = f.port_of(rtl);
    for (int i = 0; i < F::kCount; ++i) put_bits(port, i * F::kWidth, F::kWidth, f.get(own, i));
  });
}

// Drives one frame into the Verilated model and the HLS core's inputs. The
// payload is converted (A::to_own) only when its serial differs from
// `payload_serial` (the one on the pins, updated), but written to the model's
// ports on every clock: measured with tests/bench/bench_lockstep.cpp
// (BM_Rtl), the Verilated models ran up to 2.2x slower (ppc_arc_c24) when
// their payload ports were written only on a change.
template <class A, class Cfg, class Rtl, class Inputs>
void drive_inputs(const Frame<A>& f, Rtl& rtl, Inputs& in, uint64_t& payload_serial) {
  rtl.rst_ni = f.rst_n;
  rtl.cmd_valid_i = f.cmd_valid;
  rtl.feed_i = static_cast<uint32_t>(f.feed);
  rtl.step_len_i = f.timing.step_len;
  rtl.step_space_i = f.timing.step_space;
  rtl.dir_setup_i = f.timing.dir_setup;
  rtl.dir_hold_i = f.timing.dir_hold;
  rtl.abort_i = f.abort;
  in.rst_n = f.rst_n;
  in.cmd_valid = f.cmd_valid;
  in.feed = f.feed;
  in.timing.step_len = f.timing.step_len;
  in.timing.step_space = f.timing.step_space;
  in.timing.dir_setup = f.timing.dir_setup;
  in.timing.dir_hold = f.timing.dir_hold;
  in.abort = f.abort;
  if (f.payload_serial() != payload_serial) {
    payload_serial = f.payload_serial();
    A::to_own(f.cmd(), f.setup(), in.cmd);
  }
  drive_own(in.cmd, rtl);
}

// One clock of both DUTs: the frame's inputs, the rising edge (inputs and
// edge in one eval: with rst_ni low the RTL's asynchronous reset wins, as
// tick() with rst_n low does), both cores' outputs after it, the falling
// edge. Out of line on purpose: one copy per core and variant, whatever
// bench drives it, so the regression's bench and the speed benchmark's
// replay (tests/bench/bench_lockstep.cpp) run the very same code for the
// DUTs, and the two differ only by what the bench itself does.
template <class A, class Cfg, class Rtl, class Core>
[[gnu::noinline]] void clock_duts(const Frame<A>& f, Rtl& rtl, Core& hls, typename Core::Inputs& in,
                                  uint64_t& payload_serial, OutPins& hls_out, OutPins& rtl_out) {
  drive_inputs<A, Cfg>(f, rtl, in, payload_serial);
  rtl.clk_i = 1;
  rtl.eval();
  hls.tick(in);
  hls_out = read_outputs(hls.outputs());
  rtl_out = read_outputs<Cfg>(rtl);
  rtl.clk_i = 0;
  rtl.eval();
}

// Runs `bench` to its end in the direct mode. B is Bench<A>, or anything
// with its next_frame()/observe()/finished() protocol (the lockstep-speed
// benchmark records the frames through a wrapper).
template <class A, class Cfg, class B = Bench<A>>
void run_direct(B& bench) {
  using Core = typename A::template Hls<Cfg>;
  using Rtl = typename RtlOf<Cfg>::Cc;
  // A model makes its context the thread's current one; hand the thread back
  // to the default context when this one dies, or a later model without an
  // explicit context (the SystemC ones) would pick up a dangling pointer
  // (Verilator then deadlocks in its own fatal-error path).
  struct RestoreThreadContext {
    ~RestoreThreadContext() { Verilated::threadContextp(Verilated::defaultContextp()); }
  } restore;
  VerilatedContext context;
  Rtl rtl(&context);
  Core hls;
  typename Core::Inputs in;
  uint64_t payload_serial = ~uint64_t{0};  // none on the pins yet
  OutPins hls_out, rtl_out;
  rtl.clk_i = 0;
  rtl.rst_ni = 0;
  rtl.eval();
  while (!bench.finished()) {
    clock_duts<A, Cfg>(bench.next_frame(), rtl, hls, in, payload_serial, hls_out, rtl_out);
    bench.observe(hls_out, rtl_out);
  }
  rtl.final();
}

}  // namespace hwinterp::tb

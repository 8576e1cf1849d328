// The SC_MODULE face of every HLS core: the shared port contract of
// hls/stepper_io.h as SystemC ports with the RTL's names and Verilator's pin
// types (hls/pin_types.h), plus the core's own ports, so the module binds to
// the same signals as the `verilator --sc` model of the core's RTL.
//
// A core provides (see hls/dda_line.h):
//   Core::Cfg                 its variant configuration (cores.cmake)
//   Core::Own                 its payload, with its field list (hls/fields.h)
//   Core::Inputs/Outputs      StepperInputs<Own, ...> / StepperOutputs<...>
//   tick(const Inputs&), outputs()
// The payload's own ports (FieldPorts<Own>, one per field, named as in the
// RTL) become ports of this module: FieldPorts is a base constructed while
// the module is being elaborated.
#pragma once

#include <systemc>

#include "hls/fields.h"
#include "hls/pin_types.h"
#include "hls/stepper_io.h"

namespace hwinterp::hls {

// The shared ports, in RTL order.
template <class Cfg>
struct StepperPorts : sc_core::sc_module {
  static constexpr int AXES = Cfg::AXES, POS_W = Cfg::POS_W, TIM_W = Cfg::TIM_W,
                       FEED_W = Cfg::FEED_W;

  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};
  sc_core::sc_in<bool> cmd_valid_i{"cmd_valid_i"};
  sc_core::sc_out<bool> cmd_ready_o{"cmd_ready_o"};
  sc_core::sc_in<pin_t<FEED_W + 1>> feed_i{"feed_i"};
  sc_core::sc_in<pin_t<TIM_W>> step_len_i{"step_len_i"};
  sc_core::sc_in<pin_t<TIM_W>> step_space_i{"step_space_i"};
  sc_core::sc_in<pin_t<TIM_W>> dir_setup_i{"dir_setup_i"};
  sc_core::sc_in<pin_t<TIM_W>> dir_hold_i{"dir_hold_i"};
  sc_core::sc_in<bool> abort_i{"abort_i"};
  sc_core::sc_out<pin_t<AXES>> step_o{"step_o"};
  sc_core::sc_out<pin_t<AXES>> dir_o{"dir_o"};
  sc_core::sc_out<pin_t<AXES * POS_W>> pos_o{"pos_o"};
  sc_core::sc_out<bool> busy_o{"busy_o"};
  sc_core::sc_out<bool> done_o{"done_o"};

 protected:
  explicit StepperPorts(sc_core::sc_module_name name) : sc_core::sc_module(name) {}

  template <class Inputs>
  void read_shared(Inputs& in) const {
    in.rst_n = rst_ni.read();
    in.cmd_valid = cmd_valid_i.read();
    in.feed = feed_i.read();
    in.timing.step_len = step_len_i.read();
    in.timing.step_space = step_space_i.read();
    in.timing.dir_setup = dir_setup_i.read();
    in.timing.dir_hold = dir_hold_i.read();
    in.abort = abort_i.read();
  }

  void write_shared(const StepperOutputs<AXES, POS_W>& o) {
    cmd_ready_o.write(o.cmd_ready);
    step_o.write(o.step);
    dir_o.write(o.dir);
    for (int i = 0; i < AXES; ++i)
      set_pin_field<AXES * POS_W>(pos_, i * POS_W, POS_W, o.pos[i].to_uint64());
    pos_o.write(pos_);
    busy_o.write(o.busy);
    done_o.write(o.done);
  }

 private:
  pin_t<AXES* POS_W> pos_ = 0;  // kept: building a wide pin value allocates
};

template <class Core>
struct StepperModule : StepperPorts<typename Core::Cfg>, FieldPorts<typename Core::Own> {
  SC_HAS_PROCESS(StepperModule);

  explicit StepperModule(sc_core::sc_module_name name) : StepperPorts<typename Core::Cfg>(name) {
    // Asynchronous active-low reset, as the RTL's always_ff @(posedge clk_i or negedge rst_ni).
    SC_METHOD(on_edge);
    this->sensitive << this->clk_i.pos() << this->rst_ni.neg();
  }

  const Core& core() const { return core_; }

 private:
  void on_edge() {
    typename Core::Inputs in;
    this->read_shared(in);
    FieldPorts<typename Core::Own>::read(in.cmd);
    core_.tick(in);
    this->write_shared(core_.outputs());
  }

  Core core_;
};

}  // namespace hwinterp::hls

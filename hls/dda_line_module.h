// dda_line, HLS face as a cycle-accurate SC_MODULE with the RTL's ports (same
// names, same Verilator pin types), so it binds to the same signals as the
// `verilator --sc` model of rtl/dda_line.sv. Packed per-axis ports are
// flattened exactly as the RTL's `[AXES-1:0][W-1:0]`: axis i in bits
// [i*W +: W].
#pragma once

#include <systemc>

#include "hls/dda_line.h"
#include "hls/pin_types.h"

namespace hwinterp::hls {

template <class Cfg>
SC_MODULE(DdaLineModule) {
  using Core = DdaLine<Cfg>;
  static constexpr int AXES = Core::AXES, ACC_W = Core::ACC_W, POS_W = Core::POS_W,
                       TIM_W = Core::TIM_W, FEED_W = Core::FEED_W;

  sc_core::sc_in<bool> clk_i;
  sc_core::sc_in<bool> rst_ni;
  sc_core::sc_in<bool> cmd_valid_i;
  sc_core::sc_out<bool> cmd_ready_o;
  sc_core::sc_in<pin_t<AXES * ACC_W>> cmd_delta_i;
  sc_core::sc_in<pin_t<FEED_W + 1>> feed_i;
  sc_core::sc_in<bool> half_preload_i;
  sc_core::sc_in<pin_t<TIM_W>> step_len_i;
  sc_core::sc_in<pin_t<TIM_W>> step_space_i;
  sc_core::sc_in<pin_t<TIM_W>> dir_setup_i;
  sc_core::sc_in<pin_t<TIM_W>> dir_hold_i;
  sc_core::sc_out<pin_t<AXES>> step_o;
  sc_core::sc_out<pin_t<AXES>> dir_o;
  sc_core::sc_out<pin_t<AXES * POS_W>> pos_o;
  sc_core::sc_out<bool> busy_o;
  sc_core::sc_out<bool> done_o;

  SC_CTOR(DdaLineModule) {
    // Asynchronous active-low reset, as the RTL's always_ff @(posedge clk_i or negedge rst_ni).
    SC_METHOD(on_edge);
    sensitive << clk_i.pos() << rst_ni.neg();
  }

  const Core& core() const { return core_; }

 private:
  void on_edge() {
    typename Core::Inputs in;
    in.rst_n = rst_ni.read();
    in.cmd_valid = cmd_valid_i.read();
    const pin_t<AXES* ACC_W>& delta = cmd_delta_i.read();
    for (int i = 0; i < AXES; ++i)
      in.cmd_delta[i] = pin_field<AXES * ACC_W>(delta, i * ACC_W, ACC_W);
    in.feed = feed_i.read();
    in.half_preload = half_preload_i.read();
    in.timing.step_len = step_len_i.read();
    in.timing.step_space = step_space_i.read();
    in.timing.dir_setup = dir_setup_i.read();
    in.timing.dir_hold = dir_hold_i.read();
    core_.tick(in);

    const typename Core::Outputs o = core_.outputs();
    cmd_ready_o.write(o.cmd_ready);
    step_o.write(o.step);
    dir_o.write(o.dir);
    for (int i = 0; i < AXES; ++i)
      set_pin_field<AXES * POS_W>(pos_, i * POS_W, POS_W, o.pos[i].to_uint64());
    pos_o.write(pos_);
    busy_o.write(o.busy);
    done_o.write(o.done);
  }

  Core core_;
  pin_t<AXES* POS_W> pos_ = 0;  // kept: building a wide pin value allocates
};

}  // namespace hwinterp::hls

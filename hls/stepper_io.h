// The port contract every step-emitting core shares (README, "The port
// contract every core shares"), as the plain structs the HLS cores' tick() takes and returns:
//   inputs  clk_i (the tick() call), rst_ni, cmd_valid_i, the core's own
//           inputs (command payload and per-command settings), feed_i, the
//           four step/dir timing settings, abort_i;
//   outputs cmd_ready_o, per axis step_o, dir_o, pos_o; busy_o, done_o.
// Only `Own` differs between cores; the testbench handles everything else
// once for all of them.
#pragma once

#include <systemc>

#include "hls/stepdir_timing.h"

namespace hwinterp::hls {

// Pins sampled at a rising edge (rst_n is the asynchronous active-low reset).
template <class Own, int FEED_W, int TIM_W>
struct StepperInputs {
  bool rst_n = false;
  bool cmd_valid = false;
  Own cmd = {};  // the core's own inputs: command payload, per-command settings
  sc_dt::sc_uint<FEED_W + 1> feed = 0;
  StepdirSettings<TIM_W> timing = {};
  bool abort = false;
};

// Registered outputs after the edge.
template <int AXES, int POS_W>
struct StepperOutputs {
  bool cmd_ready;
  sc_dt::sc_uint<AXES> step, dir;
  sc_dt::sc_uint<POS_W> pos[AXES];
  bool busy, done;
};

}  // namespace hwinterp::hls

// Formal environment of fixed_ratio (scripts/formal.sh --blocks
// fixed_ratio): the core with narrow parameters and every input free on every
// clock (commands, feed, the four timing settings, abort), reset in the first
// cycle only. The properties:
//   rtl/formal/core_checks.sv    the port contract (rtl/formal/core_contract.sv:
//                                a_link, a_cap, a_busy, a_done, a_rise,
//                                a_abort, a_abort_len, a_len) on the core's
//                                ports and the commands its buffer (with its
//                                division) and engine hold, a_tick (a feed
//                                tick only while a command runs) and
//                                a_progress (at full feed the engine stalls
//                                only for an axis not ready), attached below;
//   rtl/fixed_ratio.sv           a_cnt_flags (its flag registers equal the
//                                compares they stand for), in its `ifdef
//                                FORMAL` block;
//   rtl/stepdir_axis.sv          a_fire_ready (the engine fires only a ready
//                                axis) and a_dir_next (READY_Q = 1: the
//                                direction it announced a clock ahead), per axis.
// scripts/formal.sh flattens the design and connects each wire of a
// `// link:` line to the core's signal (Yosys 0.23 has neither `bind` nor
// hierarchical references):
// link: hold_i[1]=dut.buf_valid_q hold_i[0]=dut.act_q run_i=dut.act_q tick_i=dut.tick
// link: advance_i=dut.advance want_i=dut.must ready_i=dut.unused_ready
// ACC_W = 2, FRAC_W = 3: deltas -2..1, a division of 5 clocks; TIM_W = 2:
// settings 0..3, pulses up to 3 clocks.
module fixed_ratio_props #(
  parameter int AXES    = 2,
  parameter int ACC_W   = 2,
  parameter int FRAC_W  = 3,
  parameter int POS_W   = 2,
  parameter int TIM_W   = 2,
  parameter int FEED_W  = 2
) (
  input logic                    clk_i,
  input logic                    rst_ni,
  input logic                    cmd_valid_i,
  input logic [AXES*ACC_W-1:0]   cmd_delta_i,
  input logic [FEED_W:0]         feed_i,
  input logic [TIM_W-1:0]        step_len_i,
  input logic [TIM_W-1:0]        step_space_i,
  input logic [TIM_W-1:0]        dir_setup_i,
  input logic [TIM_W-1:0]        dir_hold_i,
  input logic                    abort_i
);
  // The core's ports and, connected by the link lines above, its signals that
  // rtl/formal/core_checks.sv reads (run_i, tick_i, advance_i, want_i,
  // ready_i, hold_i).
  logic                  cmd_ready_o, busy_o, done_o, run_i, tick_i, advance_i;
  logic [AXES-1:0]       step_o, dir, want_i, ready_i;
  logic [AXES*POS_W-1:0] pos;
  logic [1:0]            hold_i;  // the buffer's command, the engine's
  core_checks #(.AXES(AXES), .TIM_W(TIM_W), .FEED_W(FEED_W), .HOLD(2)) u_checks (.*);

  fixed_ratio #(
    .AXES   (AXES),
    .ACC_W  (ACC_W),
    .FRAC_W (FRAC_W),
    .POS_W  (POS_W),
    .TIM_W  (TIM_W),
    .FEED_W (FEED_W)
  ) dut (
    .clk_i,
    .rst_ni,
    .cmd_valid_i,
    .cmd_ready_o,
    .cmd_delta_i,
    .feed_i,
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .abort_i,
    .step_o,
    .dir_o      (dir),
    .pos_o      (pos),
    .busy_o,
    .done_o
  );


  // Reset in the first cycle only.
  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;
  always_comb assume(rst_ni == !f_init);
endmodule

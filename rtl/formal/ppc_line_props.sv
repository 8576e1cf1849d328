// Formal environment of ppc_line (scripts/formal.sh --blocks ppc_line): the
// core with narrow parameters and every input free on every clock (commands,
// feed, the four timing settings, abort), reset in the first cycle only. The
// properties:
//   rtl/formal/core_checks.sv    the port contract (rtl/formal/core_contract.sv:
//                                a_link, a_cap, a_busy, a_done, a_rise,
//                                a_abort, a_abort_len, a_len) on the core's
//                                ports and the commands its buffer and engine
//                                hold, a_tick (a feed tick only while a
//                                command runs) and a_progress (at full feed
//                                the engine stalls only for an axis not
//                                ready), attached below;
//   rtl/stepdir_axis.sv          a_fire_ready (the engine fires only a ready
//                                axis), per axis.
// scripts/formal.sh flattens the design and connects each wire of a
// `// link:` line to the core's signal (Yosys 0.23 has neither `bind` nor
// hierarchical references):
// link: hold_i[1]=dut.buf_valid_q hold_i[0]=dut.act_q run_i=dut.act_q tick_i=dut.tick
// link: advance_i=dut.advance want_i=dut.carry ready_i=dut.ready
// ACC_W = 3: deltas -4..3, up to 8 operations a command; TIM_W = 2: settings
// 0..3, pulses up to 3 clocks.
module ppc_line_props #(
  parameter int AXES    = 2,
  parameter int ACC_W   = 3,
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

  ppc_line #(
    .AXES   (AXES),
    .ACC_W  (ACC_W),
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

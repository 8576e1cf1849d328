// Formal environment of motion_top (scripts/formal.sh --blocks motion_top):
// the core with narrow parameters and every input free on every clock (lines
// and arcs with their feed words, the feed gate, the four timing settings,
// abort), reset in the first cycle only. The properties are in the RTL's
// `ifdef FORMAL` blocks:
//   rtl/formal/core_contract.sv  the port contract (a_link, a_cap, a_busy,
//                                a_done, a_rise, a_abort, a_abort_len, a_len),
//                                instantiated by rtl/motion_top.sv on its
//                                ports and the commands buffers A and B and
//                                the engine hold;
//   rtl/motion_top.sv            a_tick (a feed tick only while a command
//                                runs) and a_progress (at full feed the
//                                engine stalls only for an axis not ready);
//   rtl/dda_axis.sv              a_carry_next, per axis;
//   rtl/stepdir_axis.sv          a_fire_ready (the engine fires only a ready
//                                axis), per axis.
// ACC_W = 4, COORD_W = 3, OPS_W = 3: line deltas -8..7, arc offsets -4..3,
// up to 7 arc operations; TIM_W = 2: settings 0..3, pulses up to 3 clocks.
module motion_top_props #(
  parameter int AXES    = 3,
  parameter int ACC_W   = 4,
  parameter int COORD_W = 3,
  parameter int OPS_W   = 3,
  parameter int POS_W   = 2,
  parameter int TIM_W   = 2,
  parameter int FEED_W  = 2
) (
  input logic                    clk_i,
  input logic                    rst_ni,
  input logic                    cmd_valid_i,
  input logic                    cmd_arc_i,
  input logic [AXES*ACC_W-1:0]   cmd_delta_i,
  input logic [1:0]              cmd_plane_i,
  input logic [2*COORD_W-1:0]    cmd_center_i,
  input logic [2*COORD_W-1:0]    cmd_end_i,
  input logic                    cmd_ccw_i,
  input logic [OPS_W-1:0]        cmd_ops_i,
  input logic [FEED_W:0]         cmd_feed_i,
  input logic [FEED_W:0]         feed_i,
  input logic [TIM_W-1:0]        step_len_i,
  input logic [TIM_W-1:0]        step_space_i,
  input logic [TIM_W-1:0]        dir_setup_i,
  input logic [TIM_W-1:0]        dir_hold_i,
  input logic                    abort_i
);
  logic                  cmd_ready, busy, done;
  logic [AXES-1:0]       step, dir;
  logic [AXES*POS_W-1:0] pos;

  motion_top #(
    .AXES   (AXES),
    .ACC_W  (ACC_W),
    .COORD_W(COORD_W),
    .OPS_W  (OPS_W),
    .POS_W  (POS_W),
    .TIM_W  (TIM_W),
    .FEED_W (FEED_W)
  ) dut (
    .clk_i,
    .rst_ni,
    .cmd_valid_i,
    .cmd_ready_o(cmd_ready),
    .cmd_arc_i,
    .cmd_delta_i,
    .cmd_plane_i,
    .cmd_center_i,
    .cmd_end_i,
    .cmd_ccw_i,
    .cmd_ops_i,
    .cmd_feed_i,
    .feed_i,
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .abort_i,
    .step_o     (step),
    .dir_o      (dir),
    .pos_o      (pos),
    .busy_o     (busy),
    .done_o     (done)
  );

  // Reset in the first cycle only.
  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;
  always_comb assume(rst_ni == !f_init);
endmodule

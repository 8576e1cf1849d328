// Formal environment of log_stepper (scripts/formal.sh --blocks
// log_stepper): the core with the narrowest parameters it accepts and every
// input free on every clock (curve commands, feed, the four timing settings,
// abort), reset in the first cycle only. scripts/formal.sh flattens the
// design and connects dut.f_fine_held to dut.u_fine.f_held (the segments the
// fine stage holds; Yosys 0.23 has no hierarchical references):
// link: dut.f_fine_held=dut.u_fine.f_held
// The properties are in the RTL's `ifdef FORMAL` blocks:
//   rtl/formal/core_contract.sv  the port contract (a_link, a_cap, a_busy,
//                                a_done, a_rise, a_abort, a_abort_len, a_len),
//                                twice: rtl/log_stepper.sv's on its ports and
//                                the curves it holds, and the fine stage's
//                                (rtl/dda_line.sv) on its own;
//   rtl/log_stepper.sv           a_tags, a_young, a_order (the segments in
//                                flight and the curves they end);
//   rtl/dda_line.sv              the fine stage's invariants and progress;
//   rtl/dda_axis.sv, rtl/stepdir_axis.sv  a_carry_next, a_fire_ready,
//                                a_dir_next, per axis.
// INT_W = 4, FRAC_W = 18 (the narrowest words), MUL_K = 11 (two digits a
// multiply), SEG_W = 2 (segment deltas -2..1), TIM_W = 2 (settings 0..3).
module log_stepper_props #(
  parameter int AXES   = 4,
  parameter int INT_W  = 4,
  parameter int FRAC_W = 18,
  parameter int MUL_K  = 11,
  parameter int SEG_W  = 2,
  parameter int POS_W  = 2,
  parameter int TIM_W  = 2,
  parameter int FEED_W = 1
) (
  input logic                          clk_i,
  input logic                          rst_ni,
  input logic                          cmd_valid_i,
  input logic [INT_W+FRAC_W-1:0]       cmd_b_i,
  input logic [INT_W+FRAC_W-1:0]       cmd_ab_i,
  input logic [INT_W+FRAC_W-1:0]       cmd_dl_i,
  input logic [INT_W+FRAC_W-1:0]       cmd_x_end_i,
  input logic [4*(INT_W+FRAC_W)-1:0]   cmd_k_i,
  input logic [FEED_W:0]               feed_i,
  input logic [TIM_W-1:0]              step_len_i,
  input logic [TIM_W-1:0]              step_space_i,
  input logic [TIM_W-1:0]              dir_setup_i,
  input logic [TIM_W-1:0]              dir_hold_i,
  input logic                          abort_i
);
  logic                  cmd_ready, busy, done;
  logic [AXES-1:0]       step, dir;
  logic [AXES*POS_W-1:0] pos;

  log_stepper #(
    .AXES  (AXES),
    .INT_W (INT_W),
    .FRAC_W(FRAC_W),
    .MUL_K (MUL_K),
    .SEG_W (SEG_W),
    .POS_W (POS_W),
    .TIM_W (TIM_W),
    .FEED_W(FEED_W)
  ) dut (
    .clk_i,
    .rst_ni,
    .cmd_valid_i,
    .cmd_ready_o(cmd_ready),
    .cmd_b_i,
    .cmd_ab_i,
    .cmd_dl_i,
    .cmd_x_end_i,
    .cmd_k_i,
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

// The step/dir timing settings as every axis of a step_stage takes them,
// computed once for all axes (rtl/stepdir_axis.sv):
//   - "0 acts as 1": each setting as a count of at least 1;
//   - the compares the axes' next-state logic needs at a phase start
//     (setting == 1, setting <= 2), so no axis compares a setting itself;
//   - fresh_o, high on the first clock after reset: the axes start their
//     counters then (the reset counts as the end of a pulse and a change of
//     dir, rtl/stepdir_axis.sv).
// Pure wiring and a few gates from the pins: a setting applies to every phase
// that starts on the clock that samples it, as before.
module stepdir_timing #(
  parameter int TIM_W = 16  // width of the timing settings and counters (>= 2)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  // hostmot2 timing in clocks, as on the core's pins (0 acts as 1)
  input  logic [TIM_W-1:0] step_len_i,
  input  logic [TIM_W-1:0] step_space_i,
  input  logic [TIM_W-1:0] dir_setup_i,
  input  logic [TIM_W-1:0] dir_hold_i,
  // the same, at least 1
  output logic [TIM_W-1:0] len_o,
  output logic [TIM_W-1:0] space_o,
  output logic [TIM_W-1:0] setup_o,
  output logic [TIM_W-1:0] hold_o,
  output logic             len_one_o,    // len_o == 1
  output logic             space_one_o,  // space_o == 1
  output logic             setup_one_o,  // setup_o == 1
  output logic             hold_one_o,   // hold_o == 1
  output logic             space_two_o,  // space_o <= 2
  output logic             setup_two_o,  // setup_o <= 2
  output logic             hold_two_o,   // hold_o <= 2
  output logic             fresh_o       // the first clock after reset
);
  // Parameter check at elaboration: Verilator and Yosys stop with the message
  // (Icarus 11 has no elaboration system tasks: it skips the check).
`ifndef __ICARUS__
  if (TIM_W < 2) begin : g_bad_tim_w
    $error("stepdir_timing: parameter TIM_W must be >= 2");
  end
`endif

  // v with bit 0 forced on when v == 0: the smallest change that makes 0 act as 1.
  function automatic logic [TIM_W-1:0] at_least_one(input logic [TIM_W-1:0] v);
    at_least_one = {v[TIM_W-1:1], v[0] | (v == '0)};
  endfunction
  // v <= 1 and v <= 2, for v as on the pins (0 acts as 1).
  function automatic logic le1(input logic [TIM_W-1:0] v);
    le1 = (v >> 1) == '0;
  endfunction
  function automatic logic le2(input logic [TIM_W-1:0] v);
    le2 = ((v >> 2) == '0) && !(v[1] && v[0]);
  endfunction

  assign len_o       = at_least_one(step_len_i);
  assign space_o     = at_least_one(step_space_i);
  assign setup_o     = at_least_one(dir_setup_i);
  assign hold_o      = at_least_one(dir_hold_i);
  assign len_one_o   = le1(step_len_i);
  assign space_one_o = le1(step_space_i);
  assign setup_one_o = le1(dir_setup_i);
  assign hold_one_o  = le1(dir_hold_i);
  assign space_two_o = le2(step_space_i);
  assign setup_two_o = le2(dir_setup_i);
  assign hold_two_o  = le2(dir_hold_i);

  logic fresh_q, fresh_d;
  assign fresh_d = 1'b0;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) fresh_q <= 1'b1;
    else fresh_q <= fresh_d;
  end
  assign fresh_o = fresh_q;
endmodule

// Formal properties of stepdir_axis (scripts/formal.sh: Yosys read_verilog
// -formal + yosys-smtbmc; immediate assertions, wrapper style).
//
// The wrapper drives the stage with free inputs and checks its outputs against
// monitors computed from those outputs alone, so the properties say what the
// header of rtl/stepdir_axis.sv promises, not how the stage is built. With
// L = max(step_len_i, 1), S = max(step_space_i, 1), U = max(dir_setup_i, 1),
// H = max(dir_hold_i, 1):
//   a_len     every step pulse is high for exactly L cycles;
//   a_space   step_o is low for at least S cycles between pulses;
//   a_dir_hi  dir_o never changes while step_o is high (rise cycle included);
//   a_hold    dir_o changes only after step_o has been low for at least H cycles;
//   a_setup   step_o rises only after dir_o has held its value for at least U cycles;
//   a_fire    a fire_i always starts a pulse on the next clock (no step lost);
//   a_ready   ready_o is exactly "a pulse may start now": want_valid_i, dir_o
//             already equal to want_dir_i, step_o low for at least S cycles
//             and dir_o held for at least U cycles (never late, never early);
//   a_turn    dir_o turns to want_dir_i on the clock after step_o has been low
//             for at least H cycles while want_valid_i asks for the other way.
// Reset counts as the end of a pulse and a change of dir, so every rule above
// also holds for the first pulse after reset, measured from the reset.
// Assumptions: reset in the first cycle only; the settings hold their value
// after reset (run-time changes are not covered); the engine fires only a
// ready axis (fire_i -> ready_o, as dda_line's stall logic guarantees).
// want_valid_i, want_dir_i and fire_i are otherwise free every cycle.
module stepdir_axis_props #(
  parameter int TIM_W = 4
) (
  input logic             clk_i,
  input logic             rst_ni,
  input logic [TIM_W-1:0] step_len_i,
  input logic [TIM_W-1:0] step_space_i,
  input logic [TIM_W-1:0] dir_setup_i,
  input logic [TIM_W-1:0] dir_hold_i,
  input logic             want_valid_i,
  input logic             want_dir_i,
  input logic             fire_i
);
  logic ready, step, dir;

  stepdir_axis #(
    .TIM_W(TIM_W)
  ) dut (
    .clk_i,
    .rst_ni,
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .want_valid_i,
    .want_dir_i,
    .fire_i,
    .ready_o(ready),
    .step_o (step),
    .dir_o  (dir)
  );

  // Monitor counters are one bit wider than the settings and saturate, so
  // "at least N" is exact for every setting.
  localparam int MonW = TIM_W + 1;
  localparam logic [MonW-1:0] MonSat = {MonW{1'b1}};
  localparam logic [MonW-1:0] MonOne = MonW'(1);

  logic [MonW-1:0] len, space, setup, hold;
  assign len   = (step_len_i == '0) ? MonOne : MonW'(step_len_i);
  assign space = (step_space_i == '0) ? MonOne : MonW'(step_space_i);
  assign setup = (dir_setup_i == '0) ? MonOne : MonW'(dir_setup_i);
  assign hold  = (dir_hold_i == '0) ? MonOne : MonW'(dir_hold_i);

  // Previous-cycle outputs and counts; the reset counts as the end of a pulse
  // and a change of dir (the header's promise): the first cycle after it is
  // the first cycle low and with this dir (lo = dage = 1), so the
  // previous-cycle ages restart at 0.
  logic            p_step, p_dir, p_fire, p_turn;
  logic [MonW-1:0] p_hi, p_lo, p_dage;
  logic [MonW-1:0] hi, lo, dage;  // this cycle, including this cycle
  assign hi   = !step ? '0 : p_step ? ((p_hi == MonSat) ? p_hi : p_hi + MonOne) : MonOne;
  assign lo   = step ? '0 : !p_step ? ((p_lo == MonSat) ? p_lo : p_lo + MonOne) : MonOne;
  assign dage = (dir != p_dir) ? MonOne : (p_dage == MonSat) ? p_dage : p_dage + MonOne;

  logic legal, turn;  // a pulse may start; dir_o may turn
  assign legal = want_valid_i && (want_dir_i == dir) && !step && (lo >= space) && (dage >= setup);
  assign turn  = want_valid_i && (want_dir_i != dir) && !step && (lo >= hold);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      p_step <= 1'b0;
      p_dir  <= 1'b0;
      p_fire <= 1'b0;
      p_turn <= 1'b0;
      p_hi   <= '0;
      p_lo   <= '0;
      p_dage <= '0;
    end else begin
      p_step <= step;
      p_dir  <= dir;
      p_fire <= fire_i;
      p_turn <= turn;
      p_hi   <= hi;
      p_lo   <= lo;
      p_dage <= dage;
    end
  end

  // Reset in the first cycle only; settings constant afterwards.
  logic f_init = 1'b1;
  logic [4*TIM_W-1:0] f_set;
  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    f_set  <= {step_len_i, step_space_i, dir_setup_i, dir_hold_i};
  end

  always_comb begin
    assume(rst_ni == !f_init);
    if (!f_init) assume({step_len_i, step_space_i, dir_setup_i, dir_hold_i} == f_set);
    if (fire_i) assume(ready);
    if (!f_init) begin
      a_len_high: assert(hi <= len);
      a_len_fall: assert(!(p_step && !step) || p_hi == len);
      a_space: assert(!(step && !p_step) || p_lo >= space);
      a_dir_hi: assert(!step || dir == p_dir);
      a_hold: assert(dir == p_dir || (!p_step && p_lo >= hold));
      a_setup: assert(!(step && !p_step) || p_dage >= setup);
      a_fire: assert(!p_fire || (step && !p_step));
      a_ready: assert(ready == legal);
      a_turn: assert(!p_turn || dir != p_dir);
    end
  end
endmodule

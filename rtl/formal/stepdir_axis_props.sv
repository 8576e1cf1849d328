// Formal properties of stepdir_axis (scripts/formal.sh: Yosys read_verilog
// -formal + yosys-smtbmc; immediate assertions, wrapper style).
//
// The wrapper drives the axis, with its settings prepared by stepdir_timing
// as in step_stage, from free inputs and checks its outputs against monitors
// computed from those outputs and the settings alone, so the properties say
// what the header of rtl/stepdir_axis.sv promises, not how the axis is built.
// The settings are free on every clock: a phase keeps the setting of the
// clock it starts on. With L the max(step_len_i, 1) of the clock a pulse
// fired on, S and H the max(step_space_i, 1) and max(dir_hold_i, 1) of the
// clock the last pulse fell on, U the max(dir_setup_i, 1) of the clock dir_o
// last turned on:
//   a_len     every step pulse is high for exactly L cycles;
//   a_space   step_o is low for at least S cycles between pulses;
//   a_dir_hi  dir_o never changes while step_o is high (rise cycle included);
//   a_hold    dir_o changes only after step_o has been low for at least H cycles;
//   a_setup   step_o rises only after dir_o has held its value for at least U cycles;
//   a_fire    a fire_i always starts a pulse on the next clock (no step lost);
//   a_ready   ready_o is exactly "a pulse in direction want_dir_i may start
//             now": dir_o already equal to want_dir_i, step_o low for at
//             least S cycles and dir_o held for at least U cycles (never late,
//             never early; want_valid_i is the engine's business);
//   a_turn    dir_o turns to want_dir_i on the clock after step_o has been low
//             for at least H cycles while want_valid_i asks for the other way.
// Reset counts as the end of a pulse and a change of dir, with the settings
// of the first clock after it, so every rule above also holds for the first
// pulse after reset, measured from the reset; on that first clock ready_o is
// low and dir_o does not turn (a_first).
// Assumptions: reset in the first cycle only; the engine fires only a ready
// axis (fire_i -> ready_o, as every core's stall logic guarantees); with
// READY_Q = 1, want_dir_next_i on each clock is want_dir_i of the next (from
// the second clock after reset on; ready_o is low on the first anyway), so
// a_ready proves the registered ready_o exact; likewise want_step_next_i is
// want_step_i of the next clock, and want_step_i is low on the first clock
// after reset (no core runs a command then), so a_block proves block_o
// exact:
//   a_block   READY_Q = 1: block_o == want_step_i && !ready_o (READY_Q = 0: 0).
// want_valid_i, want_dir_i, fire_i and the settings are otherwise free every cycle.
module stepdir_axis_props #(
  parameter int TIM_W   = 4,
  parameter bit READY_Q = 1'b0  // the stage's ready_o mode (rtl/stepdir_axis.sv)
) (
  input logic             clk_i,
  input logic             rst_ni,
  input logic [TIM_W-1:0] step_len_i,
  input logic [TIM_W-1:0] step_space_i,
  input logic [TIM_W-1:0] dir_setup_i,
  input logic [TIM_W-1:0] dir_hold_i,
  input logic             want_valid_i,
  input logic             want_dir_i,
  input logic             want_dir_next_i,
  input logic             want_step_i,  // the engine wants a pulse now (what want_step_next_i said)
  input logic             want_step_next_i,
  input logic             fire_i
);
  logic ready, block, step, dir;
  logic [TIM_W-1:0] len, space, setup, hold;
  logic len_one, space_one, setup_one, hold_one, space_two, setup_two, hold_two, fresh;

  stepdir_timing #(
    .TIM_W(TIM_W)
  ) u_timing (
    .clk_i,
    .rst_ni,
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .len_o      (len),
    .space_o    (space),
    .setup_o    (setup),
    .hold_o     (hold),
    .len_one_o  (len_one),
    .space_one_o(space_one),
    .setup_one_o(setup_one),
    .hold_one_o (hold_one),
    .space_two_o(space_two),
    .setup_two_o(setup_two),
    .hold_two_o (hold_two),
    .fresh_o    (fresh)
  );

  stepdir_axis #(
    .TIM_W  (TIM_W),
    .READY_Q(READY_Q)
  ) dut (
    .clk_i,
    .rst_ni,
    .len_i      (len),
    .space_i    (space),
    .setup_i    (setup),
    .hold_i     (hold),
    .len_one_i  (len_one),
    .space_one_i(space_one),
    .setup_one_i(setup_one),
    .hold_one_i (hold_one),
    .space_two_i(space_two),
    .setup_two_i(setup_two),
    .hold_two_i (hold_two),
    .fresh_i    (fresh),
    .want_valid_i,
    .want_dir_i,
    .want_dir_next_i,
    .want_step_next_i,
    .fire_i,
    .ready_o    (ready),
    .block_o    (block),
    .step_o     (step),
    .dir_o      (dir)
  );

  // Monitor counters are one bit wider than the settings and saturate, so
  // "at least N" is exact for every setting.
  localparam int MonW = TIM_W + 1;
  localparam logic [MonW-1:0] MonSat = {MonW{1'b1}};
  localparam logic [MonW-1:0] MonOne = MonW'(1);

  function automatic logic [MonW-1:0] at_least_one(input logic [TIM_W-1:0] v);
    at_least_one = (v == '0) ? MonOne : MonW'(v);
  endfunction

  // Previous-cycle outputs, counts and settings (the settings the last clock
  // edge sampled); the reset counts as the end of a pulse and a change of dir
  // (the header's promise): the first cycle after it is the first cycle low
  // and with this dir (lo = dage = 1), so the previous-cycle ages restart at 0.
  logic            p_step, p_dir, p_fire, p_turn;
  logic            p_first = 1'b0;
  logic [MonW-1:0] p_hi, p_lo, p_dage;
  logic [TIM_W-1:0] p_len, p_space, p_setup, p_hold;
  logic [MonW-1:0] hi, lo, dage;  // this cycle, including this cycle
  assign hi   = !step ? '0 : p_step ? ((p_hi == MonSat) ? p_hi : p_hi + MonOne) : MonOne;
  assign lo   = step ? '0 : !p_step ? ((p_lo == MonSat) ? p_lo : p_lo + MonOne) : MonOne;
  assign dage = (dir != p_dir) ? MonOne : (p_dage == MonSat) ? p_dage : p_dage + MonOne;

  // The settings each phase started with: L of the pulse now high (or last
  // high), S and H of the last fall, U of the last turn; the reset's phases
  // take the settings of the first clock edge after it (p_first).
  logic [MonW-1:0] q_len, q_space, q_hold, q_setup;  // registered
  logic [MonW-1:0] c_len, c_space, c_hold, c_setup;  // this cycle
  logic rise, fall, turned;
  assign rise    = step && !p_step;
  assign fall    = !step && p_step;
  assign turned  = dir != p_dir;
  assign c_len   = rise ? at_least_one(p_len) : q_len;
  assign c_space = (fall || p_first) ? at_least_one(p_space) : q_space;
  assign c_hold  = (fall || p_first) ? at_least_one(p_hold) : q_hold;
  assign c_setup = (turned || p_first) ? at_least_one(p_setup) : q_setup;

  logic first;  // the first cycle after reset
  logic legal, turn;  // a pulse may start; dir_o may turn
  assign legal = !first && (want_dir_i == dir) && !step && (lo >= c_space) && (dage >= c_setup);
  assign turn  = !first && want_valid_i && (want_dir_i != dir) && !step && (lo >= c_hold);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      p_step  <= 1'b0;
      p_dir   <= 1'b0;
      p_fire  <= 1'b0;
      p_turn  <= 1'b0;
      p_hi    <= '0;
      p_lo    <= '0;
      p_dage  <= '0;
      q_len   <= MonOne;
      q_space <= MonOne;
      q_hold  <= MonOne;
      q_setup <= MonOne;
    end else begin
      p_step  <= step;
      p_dir   <= dir;
      p_fire  <= fire_i;
      p_turn  <= turn;
      p_hi    <= hi;
      p_lo    <= lo;
      p_dage  <= dage;
      q_len   <= c_len;
      q_space <= c_space;
      q_hold  <= c_hold;
      q_setup <= c_setup;
    end
  end

  // Reset in the first cycle only; `first` is the cycle after it.
  logic f_init = 1'b1;
  logic f_first = 1'b0;
  logic p_want_next = 1'b0;  // want_dir_next_i of the previous clock
  logic p_step_next = 1'b0;  // want_step_next_i of the previous clock
  always_ff @(posedge clk_i) begin
    f_init  <= 1'b0;
    f_first <= f_init;
    p_first <= f_first;
    p_want_next <= want_dir_next_i;
    p_step_next <= want_step_next_i;
    p_len   <= step_len_i;
    p_space <= step_space_i;
    p_setup <= dir_setup_i;
    p_hold  <= dir_hold_i;
  end
  assign first = f_first;

  always_comb begin
    assume(rst_ni == !f_init);
    if (fire_i) assume(ready);
    if (READY_Q && !f_init && !first) assume(want_dir_i == p_want_next);
    if (!f_init) assume(want_step_i == (!first && p_step_next));
    if (!f_init) begin
      a_len_high: assert(hi <= c_len);
      a_len_fall: assert(!fall || p_hi == q_len);
      a_space: assert(!rise || p_lo >= q_space);
      a_dir_hi: assert(!step || dir == p_dir);
      a_hold: assert(dir == p_dir || (!p_step && p_lo >= q_hold));
      a_setup: assert(!rise || p_dage >= q_setup);
      a_fire: assert(!p_fire || rise);
      a_ready: assert(ready == legal);
      a_turn: assert(!p_turn || turned);
      a_first: assert(!first || !ready);
      a_block: assert(block == (READY_Q && want_step_i && !ready));
      a_no_turn: assert(!p_first || !turned);
    end
  end
endmodule

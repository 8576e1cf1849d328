// Step/dir output stage of one axis (the hostmot2 timing set).
//
// Run-time settings, in clock cycles; a setting of 0 acts as 1:
//   step_len_i    step_o high for exactly max(step_len_i, 1) cycles
//   step_space_i  step_o low for at least max(step_space_i, 1) cycles between pulses
//   dir_setup_i   dir_o stable at least max(dir_setup_i, 1) cycles before step_o rises
//   dir_hold_i    dir_o stable at least max(dir_hold_i, 1) cycles after step_o falls
// The stage never violates them: ready_o says whether a pulse may start on the
// next clock, and the engine only fires a ready axis (it stalls otherwise), so
// no step is ever lost. A setting applies from the clock that samples it.
//
// dir_o follows want_dir_i by itself as soon as the hold time allows it, so
// a reversal costs only the hold + setup times, not a round trip.
//
// Reset (asynchronous) is not a safe stop: it ends a pulse at once and sets
// dir_o to 0 whatever it was (abort_i of the core is the safe stop). The stage
// then counts the reset as the end of a pulse and as a change of dir_o: the
// first pulse after reset waits step_space and dir_setup, and a turn of dir_o
// waits dir_hold, counted from the reset.
// dir_o = 0 means positive motion, 1 negative (the sign bit of the delta).
module stepdir_axis #(
  parameter int TIM_W = 16
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic [TIM_W-1:0] step_len_i,
  input  logic [TIM_W-1:0] step_space_i,
  input  logic [TIM_W-1:0] dir_setup_i,
  input  logic [TIM_W-1:0] dir_hold_i,
  input  logic             want_valid_i,  // the active command moves this axis...
  input  logic             want_dir_i,    // ...in this direction
  input  logic             fire_i,        // start a pulse next clock (only when ready_o)
  output logic             ready_o,
  output logic             step_o,
  output logic             dir_o
);
  localparam logic [TIM_W-1:0] One = TIM_W'(1);
  // Not '1: Yosys (<= 0.58) reads '1 in a typed localparam as 1 (YosysHQ/yosys#5465).
  localparam logic [TIM_W-1:0] Sat = {TIM_W{1'b1}};

  // Cycle counters include the current cycle, so "held for n cycles" is cnt >= n.
  logic             step_q, step_d;
  logic             dir_q, dir_d;
  logic [TIM_W-1:0] high_q, high_d;  // cycles step_o has been high
  logic [TIM_W-1:0] low_q, low_d;  // cycles step_o has been low (saturating)
  logic [TIM_W-1:0] dir_age_q, dir_age_d;  // cycles dir_o has held its value (saturating)

  logic [TIM_W-1:0] len, space, setup, hold;
  assign len   = (step_len_i == '0) ? One : step_len_i;
  assign space = (step_space_i == '0) ? One : step_space_i;
  assign setup = (dir_setup_i == '0) ? One : dir_setup_i;
  assign hold  = (dir_hold_i == '0) ? One : dir_hold_i;

  logic dir_change;
  assign dir_change = !step_q && want_valid_i && (want_dir_i != dir_q) && (low_q >= hold);
  assign ready_o = !step_q && want_valid_i && (want_dir_i == dir_q) && (low_q >= space) &&
                   (dir_age_q >= setup);

  always_comb begin
    step_d = step_q;
    high_d = high_q;
    low_d  = low_q;
    if (step_q) begin
      if (high_q >= len) begin
        step_d = 1'b0;
        low_d  = One;
      end else begin
        high_d = high_q + One;
      end
    end else if (fire_i) begin
      step_d = 1'b1;
      high_d = One;
    end else if (low_q != Sat) begin
      low_d = low_q + One;
    end

    dir_d     = dir_q;
    dir_age_d = (dir_age_q != Sat) ? dir_age_q + One : dir_age_q;
    if (dir_change) begin
      dir_d     = want_dir_i;
      dir_age_d = One;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      step_q    <= 1'b0;
      dir_q     <= 1'b0;
      high_q    <= '0;
      low_q     <= One;  // as if a pulse had just ended...
      dir_age_q <= One;  // ...and dir_o had just changed
    end else begin
      step_q    <= step_d;
      dir_q     <= dir_d;
      high_q    <= high_d;
      low_q     <= low_d;
      dir_age_q <= dir_age_d;
    end
  end

  assign step_o = step_q;
  assign dir_o  = dir_q;
endmodule

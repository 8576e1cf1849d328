// Feed-rate accumulator (DDS) shared by every core: decides on which clocks
// the core's engine may do one operation.
//
// feed_i is sampled every clock and applies from the next clock on (one
// clock of latency, so that the tick is a register). Each clock while run_i
// is high, a FEED_W-bit phase adds the feed word; its carry is a tick. A feed
// word >= 2^FEED_W is full feed: a tick on every clock. A feed word of 0 is
// feed hold: no tick, the phase holds. When the engine cannot use a tick
// (hold_i: an axis that must step is not ready), the phase keeps its value,
// so the same tick comes again on the next clock: ticks are delayed, never
// lost. The phase is not cleared between commands (the rate stays
// continuous across back-to-back commands).
//
// Timing: tick_o is a register. The next clock's carry is computed for both
// phases the clock may leave (kept, or advanced), from the feed word on the
// pins, and hold_i and run_next_i only choose: the engine's late signals
// reach the tick through one gate, and the carry chains start at registers
// and pins.
module feed_accum #(
  parameter int FEED_W = 16  // phase width (>= 1); feed_i is FEED_W + 1 bits
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  input  logic [FEED_W:0] feed_i,      // operations per clock = feed / 2^FEED_W (capped at 1), from the next clock
  input  logic            run_i,       // the engine has work this clock: the phase advances
  input  logic            hold_i,      // this clock's tick cannot be used: keep the phase
  input  logic            run_next_i,  // the engine has work on the next clock
  output logic            tick_o       // the engine may do one operation this clock (only with run_i)
);
  // Parameter check at elaboration: Verilator and Yosys stop with the message
  // (Icarus 11 has no elaboration system tasks: it skips the check).
`ifndef __ICARUS__
  if (FEED_W < 1) begin : g_bad_feed_w
    $error("feed_accum: parameter FEED_W must be >= 1");
  end
`endif

  logic [FEED_W:0]   feed_q, feed_d;  // the feed word in force this clock
  logic [FEED_W-1:0] phase_q, phase_d;
  logic              tick_q, tick_d;
  logic [FEED_W-1:0] sum;  // this clock's add (its carry is tick_q)
  logic [FEED_W:0]   keep_next, add_next;  // the next clock's add, from either phase
  logic              adv;  // the phase advances this clock

  assign sum       = phase_q + feed_q[FEED_W-1:0];
  assign keep_next = {1'b0, phase_q} + {1'b0, feed_i[FEED_W-1:0]};
  assign add_next  = {1'b0, sum} + {1'b0, feed_i[FEED_W-1:0]};
  assign adv       = run_i && !feed_q[FEED_W] && !(tick_q && hold_i);
  // Continuous assignments, not part-selects inside always_comb: Icarus 11
  // does not support constant selects in always_* processes.
  assign feed_d    = feed_i;
  assign phase_d   = adv ? sum : phase_q;
  assign tick_d    = run_next_i && (feed_i[FEED_W] || (adv ? add_next[FEED_W] : keep_next[FEED_W]));
  assign tick_o    = tick_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      feed_q  <= '0;
      phase_q <= '0;
      tick_q  <= 1'b0;
    end else begin
      feed_q  <= feed_d;
      phase_q <= phase_d;
      tick_q  <= tick_d;
    end
  end
endmodule

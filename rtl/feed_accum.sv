// Feed-rate accumulator (DDS) shared by every core: decides on which clocks
// the core's engine may do one operation.
//
// Each clock while run_i is high a FEED_W-bit phase adds feed_i[FEED_W-1:0];
// its carry is a tick. feed_i >= 2^FEED_W (the top bit set) is full feed: a
// tick on every clock. feed_i = 0 is feed hold: no tick, the phase holds.
// When the engine cannot use a tick (hold_i: an axis that must step is not
// ready), the phase keeps its value, so the same tick comes again on the next
// clock: ticks are delayed, never lost. The phase is not cleared between
// commands (the rate stays continuous across back-to-back commands).
module feed_accum #(
  parameter int FEED_W = 16  // phase width; feed_i is FEED_W + 1 bits
) (
  input  logic          clk_i,
  input  logic          rst_ni,
  input  logic [FEED_W:0] feed_i,  // operations per clock = feed_i / 2^FEED_W (capped at 1)
  input  logic          run_i,   // the engine has work: the phase advances
  input  logic          hold_i,  // this clock's tick cannot be used: keep the phase
  output logic          tick_o   // the engine may do one operation this clock
);
  logic [FEED_W-1:0] phase_q, phase_d;
  logic [FEED_W:0]   sum;
  logic              full;

  assign full   = feed_i[FEED_W];
  assign sum    = {1'b0, phase_q} + {1'b0, feed_i[FEED_W-1:0]};
  assign tick_o = run_i && (full || sum[FEED_W]);
  // A continuous assignment, not a part-select inside always_comb: Icarus 11
  // does not support constant selects in always_* processes.
  assign phase_d = (run_i && !full && !(tick_o && hold_i)) ? sum[FEED_W-1:0] : phase_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) phase_q <= '0;
    else phase_q <= phase_d;
  end
endmodule

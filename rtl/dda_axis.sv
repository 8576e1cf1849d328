// dda_axis: one axis of the DDA engine: an accumulator that adds the axis's
// magnitude each iteration and steps on its carry out of the modulus, kept
// one iteration ahead (s_q = accumulator + increment), so the carry of the
// iteration at hand is a register (carry_o).
//
// The accumulator is W bits wide with an offset that puts the modulus at
// 2^W: its carry out is always the adder's top bit.
//   MODULUS_2N = 1 (dda_line): modulus 2^n; the bits n and up are held at
//     one (hm_i, the command's high mask). s_q keeps them at one itself (the
//     mask is ORed in after each add), so an iteration adds s_q + mag.
//     A load's add is a0_i + b_mag_i with a0 = hm, plus 2^(n-1) with the half
//     preload, and b_mag_i < 2^n: no bit of the two is set in both but, with
//     the half preload, bit n-1, so the sum's low bits (mask held) are
//     a0 ^ b_mag and its carry is |(a0 & b_mag). No adder on the load.
//   MODULUS_2N = 0 (general modulus N, e.g. a helical axis slaved to an arc's
//     N operations): the offset is 2^W - N; an iteration adds s + mag, or
//     s + dc after a carry, with dc = mag + 2^W - N given with the command
//     (for modulus 2^n, dc = mag | hm). dc has W + 1 bits: mag <= N, and an
//     axis that steps on every iteration (mag = N) has dc = 2^W. A load's add
//     is the first value plus the magnitude: a0_i + b_mag_i.
//
// Timing: MODULUS_2N = 1: the adder's operands are registers (s_q, mag_q);
// the load's choice (pre_i, a register) and the mask come after it, in the
// LUTs that end the carry chain. MODULUS_2N = 0: the operands select on pre_i
// and the running registers. The clock's late signals (ld_i, en_i) only
// enable registers.
module dda_axis #(
  parameter int W          = 32,  // magnitude and accumulator width (>= 2)
  parameter bit MODULUS_2N = 1    // 1: modulus 2^n with the high mask; 0: general modulus
) (
  input  logic         clk_i,
  input  logic         rst_ni,
  input  logic         pre_i,    // this clock's add, if any, is a load's (register)
  input  logic         ld_i,     // load the next command's magnitude (and dc) this clock
  input  logic         en_i,     // take this clock's add (a load or an iteration)
  input  logic [W-1:0] a0_i,     // the next command's first accumulator value (with the offset)
  input  logic [W-1:0] b_mag_i,  // the next command's magnitude
  input  logic [W:0]   b_dc_i,   // the next command's increment after a carry (MODULUS_2N = 0)
  input  logic [W-1:0] hm_i,     // the running command's high mask (MODULUS_2N = 1)
  output logic         carry_o,  // this iteration steps the axis
  output logic         carry_next_o  // carry_o of the next clock (from the clock's late en_i)
);
  // Parameter check at elaboration: Verilator and Yosys stop with the message
  // (Icarus 11 has no elaboration system tasks: it skips the check).
`ifndef __ICARUS__
  if (W < 2) begin : g_bad_w
    $error("dda_axis: parameter W must be >= 2");
  end
`endif

  logic [W-1:0] mag_q, mag_d;
  logic [W:0]   s_q, s_d;
  logic [W:0]   s_new;  // this clock's add (a load's or an iteration's)

  assign carry_o = s_q[W];
  assign mag_d   = ld_i ? b_mag_i : mag_q;
  assign s_d     = en_i ? s_new : s_q;

  if (MODULUS_2N) begin : g_2n
    logic       unused_dc;  // no dc in this mode
    logic [W:0] sum;
    assign unused_dc = ^b_dc_i;
    assign sum       = {1'b0, s_q[W-1:0]} + {1'b0, mag_q};
    assign s_new     = pre_i ? {|(a0_i & b_mag_i), a0_i ^ b_mag_i} : {sum[W], sum[W-1:0] | hm_i};
    // The next carry, with the add's carry out (the latest signal: the end of
    // the carry chain) choosing in the last LUT. The two nets are kept: ABC
    // sees a carry chain's output as early as a register and would otherwise
    // put it under the late en_i.
    (* keep *) logic take_sum;     // the next carry is the add's
    (* keep *) logic carry_other;  // the next carry if not
    assign take_sum     = en_i && !pre_i;
    assign carry_other  = en_i ? |(a0_i & b_mag_i) : s_q[W];
    assign carry_next_o = take_sum ? sum[W] : carry_other;
  end else begin : g_n
    logic       unused_hm;  // no high mask in this mode
    logic [W-1:0] x;
    logic [W:0] y, dc_q, dc_d;
    assign unused_hm = ^hm_i;
    assign x         = pre_i ? a0_i : s_q[W-1:0];
    assign y         = pre_i ? {1'b0, b_mag_i} : (s_q[W] ? dc_q : {1'b0, mag_q});
    assign s_new     = {1'b0, x} + y;
    assign carry_next_o = en_i ? s_new[W] : s_q[W];
    assign dc_d      = ld_i ? b_dc_i : dc_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) dc_q <= '0;
      else dc_q <= dc_d;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      mag_q <= '0;
      s_q   <= '0;
    end else begin
      mag_q <= mag_d;
      s_q   <= s_d;
    end
  end

`ifdef FORMAL
  // Formal (scripts/formal.sh, in every core that uses this axis): the next
  // carry, built apart for timing, is the next state's carry.
  always_comb begin
    if (rst_ni) a_carry_next: assert(carry_next_o == s_d[W]);
  end
`endif
endmodule

// magnitude: the sign and the absolute value of a two's complement number,
// |x| in W unsigned bits (|-2^(W-1)| = 2^(W-1) fits).
//
// Built as (x - 1) ^ all ones for a negative x, one adder whose sum bits take
// the XOR: Yosys maps `x[W-1] ? -x : x` to an adder, an XOR and a mux per bit
// (93 iCE40 LUT4 at W = 32, against 32 here). The top bit is the adder's
// own top sum bit, neg ^ (the carry into it), with the sign as the top bit
// of the first operand: it is set just for x = -2^(W-1), and it stays in the
// chain's last cell (taken as neg && !carry, it needed one more cell and a
// route after the chain). Computed as the other bits, its LUT would read the
// sign on two inputs, which nextpnr-ice40 0.4 cannot route when the LUT
// shares its cell with a carry (its router circles for ever).
module magnitude #(
  parameter int W = 32  // width of x and of |x| (>= 2)
) (
  input  logic [W-1:0] x_i,    // two's complement
  output logic [W-1:0] mag_o,  // |x|, unsigned
  output logic         neg_o   // x < 0
);
  // Parameter check at elaboration: Verilator and Yosys stop with the message
  // (Icarus 11 has no elaboration system tasks: it skips the check).
`ifndef __ICARUS__
  if (W < 2) begin : g_bad_w
    $error("magnitude: parameter W must be >= 2");
  end
`endif

  logic [W-1:0] low;  // x[W-2:0] - neg; bit W-1: neg ^ the carry out of the bits below

  assign neg_o = x_i[W-1];
  assign low   = x_i + {1'b0, {(W - 1) {neg_o}}};
  assign mag_o = {low[W-1], low[W-2:0] ^ {(W - 1) {neg_o}}};
endmodule

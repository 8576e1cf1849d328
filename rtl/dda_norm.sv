// dda_norm: the DDA engine's normalisation of a command, from the OR of its
// magnitudes (which has the bit length n of the largest one): the masks
// the engine works with. Combinational; the suffix OR is written as a
// log-depth prefix network (a chain of ORs maps to ten LUT levels at W = 32).
module dda_norm #(
  parameter int W = 32  // magnitude width (>= 1)
) (
  input  logic [W-1:0] any_i,  // OR of the command's magnitudes
  output logic [W-1:0] low_o,  // 2^n - 1: the iterations after the first
  output logic [W-1:0] hm_o,   // ~low_o: the accumulator bits held at one
  output logic [W-1:0] top_o   // 2^(n-1) alone (0 when n = 0): one half, for the half preload
);
  // Parameter check at elaboration: Verilator and Yosys stop with the message
  // (Icarus 11 has no elaboration system tasks: it skips the check).
`ifndef __ICARUS__
  if (W < 1) begin : g_bad_w
    $error("dda_norm: parameter W must be >= 1");
  end
`endif

  always_comb begin
    low_o = any_i;
    for (int sh = 1; sh < W; sh = sh * 2) low_o = low_o | (low_o >> sh);
  end
  assign hm_o  = ~low_o;
  assign top_o = low_o ^ (low_o >> 1);
endmodule

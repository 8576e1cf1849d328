// prim_ram_1r1w: a simple dual-port RAM, one write port and one registered
// read port on one clock, as iCE40 (SB_RAM40_4K) and ECP5 (DP16KD) block RAM
// infer it in Yosys. No reset: block RAM has none, so its contents and the
// read register start unknown (the user must not read a word it has not
// written). The one exception to the reset-and-copy register rule
// (scripts/rtl_style.py accepts the no-reset block only in prim_ram_*.sv).
//
// Write: wdata_i goes into word waddr_i at the edge where we_i is high.
// Read: rdata_o is word raddr_i as it was before the edge where re_i was high
// (a read and a write of the same word in one clock read the old word), held
// until the next read.
module prim_ram_1r1w #(
  parameter int WIDTH = 32,  // bits a word (>= 1)
  parameter int DEPTH = 16   // words (>= 2)
) (
  input  logic                     clk_i,
  input  logic                     we_i,
  input  logic [$clog2(DEPTH)-1:0] waddr_i,
  input  logic [WIDTH-1:0]         wdata_i,
  input  logic                     re_i,
  input  logic [$clog2(DEPTH)-1:0] raddr_i,
  output logic [WIDTH-1:0]         rdata_o
);
`ifndef __ICARUS__
  if (WIDTH < 1) begin : g_bad_width
    $error("prim_ram_1r1w: parameter WIDTH must be >= 1");
  end
  if (DEPTH < 2) begin : g_bad_depth
    $error("prim_ram_1r1w: parameter DEPTH must be >= 2");
  end
`endif

  logic [WIDTH-1:0] mem_q [DEPTH];
  logic [WIDTH-1:0] rdata_q;

  always_ff @(posedge clk_i) begin
    if (we_i) mem_q[waddr_i] <= wdata_i;
    if (re_i) rdata_q <= mem_q[raddr_i];
  end

  assign rdata_o = rdata_q;
endmodule

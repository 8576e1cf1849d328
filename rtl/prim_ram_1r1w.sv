// prim_ram_1r1w: a simple dual-port RAM, one write port and one registered
// read port on one clock, as iCE40 (SB_RAM40_4K) and ECP5 (DP16KD) block RAM
// infer it in Yosys. No reset: block RAM has none, so its contents and the
// read register start unknown (the user must not read a word it has not
// written). The one exception to the reset-and-copy register rule
// (scripts/rtl_style.py accepts the no-reset block only in prim_ram_*.sv).
//
// Write: wdata_i goes into word waddr_i at the edge where we_i is high.
// Read: rdata_o is word raddr_i as it was before the edge where re_i was high,
// held until the next read.
//
// A read and a write of the same word in one clock (SAME_WORD_RW):
//   1: the read gives the old word. iCE40 and ECP5 block RAM leave that case
//      undefined, so Yosys builds it around the RAM: the write delayed one
//      clock in flip-flops and a bypass multiplexer on the read data (about
//      2 * WIDTH flip-flops and WIDTH LUTs).
//   0: the user never does it (a FIFO whose read and write pointers differ
//      whenever both ports act); the RAM is used as it is (Yosys's
//      no_rw_check), and simulation stops with an error if it happens (a
//      formal proof of the user, with FORMAL defined, asserts it instead:
//      rtl/formal/etherbone_engine_props.sv, feed_profile_props.sv).
module prim_ram_1r1w #(
  parameter int WIDTH = 32,          // bits a word (>= 1)
  parameter int DEPTH = 16,          // words (>= 2)
  parameter bit SAME_WORD_RW = 1'b1  // see above
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

  logic [WIDTH-1:0] rdata_q;

  if (SAME_WORD_RW) begin : g_old_word
    logic [WIDTH-1:0] mem_q [DEPTH];
    always_ff @(posedge clk_i) begin
      if (we_i) mem_q[waddr_i] <= wdata_i;
      if (re_i) rdata_q <= mem_q[raddr_i];
    end
  end else begin : g_no_rw_check
    (* no_rw_check *) logic [WIDTH-1:0] mem_q [DEPTH];
    always_ff @(posedge clk_i) begin
      if (we_i) mem_q[waddr_i] <= wdata_i;
      if (re_i) rdata_q <= mem_q[raddr_i];
    end
`ifdef FORMAL
    // A proof of the user (etherbone_engine, feed_profile) checks it.
    always_comb begin
      if (we_i && re_i) a_same_word: assert(waddr_i != raddr_i);
    end
`else
`ifndef SYNTHESIS
    always_ff @(posedge clk_i) begin
      if (we_i && re_i && waddr_i == raddr_i) begin
        $error("prim_ram_1r1w: a read and a write of word %0d in one clock (SAME_WORD_RW = 0)",
               waddr_i);
      end
    end
`endif
`endif
  end

  assign rdata_o = rdata_q;
endmodule

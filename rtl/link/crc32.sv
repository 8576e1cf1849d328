// crc32: the CRC-32 of IEEE 802.3 (Ethernet's FCS, zlib's crc32) over a
// byte stream, one byte a clock: reflected, polynomial 0x04C11DB7 (0xEDB88320
// reflected), initial value 0xFFFFFFFF. crc_o is the register itself, before
// the final XOR: a frame's CRC is ~crc_o, sent least significant byte first;
// run over a frame and its CRC so sent, the register ends at the residue
// 0xDEBB20E3 (the receiver's check, rtl/link/etherbone_engine.sv).
//
// At the edge of a clock with en_i high the register takes the CRC of its
// value (or of 0xFFFFFFFF, with init_i high too) and data_i; with init_i
// alone it takes 0xFFFFFFFF. The update is the eight bit steps of the
// reflected shift register unrolled (about 80 LUT4 on iCE40).
module crc32 (
  input  logic        clk_i,
  input  logic        rst_ni,   // asynchronous, active low: 0xFFFFFFFF
  input  logic        init_i,   // start a new CRC (with en_i: at this byte)
  input  logic        en_i,     // take data_i
  input  logic [7:0]  data_i,
  output logic [31:0] crc_o     // the register (the CRC is its complement)
);
  logic [31:0] crc_q, crc_d, start;

  // The register after one byte, least significant bit first.
  function automatic logic [31:0] step(input logic [31:0] c, input logic [7:0] d);
    logic [31:0] r;
    r = c;
    for (int i = 0; i < 8; i++) begin
      r = (r[0] ^ d[i]) ? ((r >> 1) ^ 32'hEDB8_8320) : (r >> 1);
    end
    step = r;
  endfunction

  assign start = init_i ? 32'hFFFF_FFFF : crc_q;
  assign crc_d = en_i ? step(start, data_i) : start;
  assign crc_o = crc_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      crc_q <= 32'hFFFF_FFFF;
    end else begin
      crc_q <= crc_d;
    end
  end
endmodule

// link_guard: the sequence guard of a host link (docs/link.md, "The sequence
// guard"), an inline Wishbone B4 classic filter between the link's bus
// master (s_*, upstream) and the bus (m_*, downstream). 32-bit data, word
// addresses (adr is the byte address / 4, as LiteX's Wishbone), 4 byte
// selects, err on both sides; one transaction at a time (no pipelining, no
// stall).
//
// Window: the 512 words at WIN_BASE (rtl/regs/link_guard.rdl):
//   word 0        write SEQ, read EXPECT
//   words 1..255  write STREAM (a read: err)
//   words 256..259 read ACCEPTED, STALE, DROPPED, ERRORS (a write: err)
//   other words   err
// An access answered err changes nothing. SEQ, STREAM and the counters are
// taken and read whole (sel is ignored for them).
//
// SEQ write: equal to EXPECT, the guard opens and EXPECT counts up (ACCEPTED
// is EXPECT: both start at 0 and count the same event, so one register holds
// both); else it closes and STALE counts up. Either way the stream parser
// restarts at "header".
// STREAM words, in the order they arrive (which of words 1..255 a word is
// written to does not matter): a header {count[31:24], word_address[23:0]}
// (count 0: ignored, the next word is a header again), then count data words.
// Open: data word i becomes one downstream write to word_address + i (the
// address wraps at 2^24 words) with the upstream write's sel and data, and
// the upstream write is answered when the bus answers it: ack, or err when
// the bus answers err (ERRORS counts it). Closed: the data word is acked at
// once, not written, and DROPPED counts it. The guard starts closed and stays
// open or closed until the next SEQ write. Counters are 32 bits and wrap.
//
// Timing: no added clock anywhere. Outside the window every signal passes
// through unchanged (m_* = s_*, s_* = m_*, combinational); a forwarded data
// word is the same: its downstream request is in the clock of the upstream
// one and the bus's answer is the upstream answer in the same clock. The
// guard answers its own accesses (SEQ, headers, closed data words, reads of
// its words, err) in the clock of the request, combinationally from
// cyc & stb & adr & we, as motion_soc_wb does; its state changes at the edge
// that ends that clock. m_cyc_o is s_cyc_i throughout (a master that holds
// cyc over a record keeps the downstream cycle too); m_stb_o is low in the
// clocks of the guard's own accesses.
// Note for LiteX: LiteEth's Etherbone master waits for ack only (an err
// leaves it waiting until the bus timeout acks): a board that must survive
// err should feed it s_ack_o | s_err_o.
// Formal: rtl/formal/link_guard_props.sv (scripts/formal.sh --blocks
// link_guard). Tests: tests/link/.
module link_guard #(
  // Word address (byte address / 4) of the guard's 512-word window: a
  // multiple of 512 below 2^30. The default is 0x0008_0000 / 4, where
  // rtl/regs/board.rdl places the guard.
  parameter int unsigned WIN_BASE = 32'h0002_0000
) (
  input  logic        clk_i,
  input  logic        rst_ni,   // asynchronous, active low: closed, EXPECT and counters 0
  // upstream: the link's bus master (Wishbone B4 classic subordinate port)
  input  logic        s_cyc_i,
  input  logic        s_stb_i,
  input  logic        s_we_i,
  input  logic [29:0] s_adr_i,  // word address
  input  logic [31:0] s_dat_i,
  input  logic [3:0]  s_sel_i,
  output logic [31:0] s_dat_o,
  output logic        s_ack_o,
  output logic        s_err_o,
  // downstream: the bus (Wishbone B4 classic manager port)
  output logic        m_cyc_o,
  output logic        m_stb_o,
  output logic        m_we_o,
  output logic [29:0] m_adr_o,  // word address
  output logic [31:0] m_dat_o,
  output logic [3:0]  m_sel_o,
  input  logic [31:0] m_dat_i,
  input  logic        m_ack_i,
  input  logic        m_err_i
);
`ifndef __ICARUS__
  if (WIN_BASE % 512 != 0 || WIN_BASE >= 32'h4000_0000) begin : g_bad_win_base
    $error("link_guard: parameter WIN_BASE must be a multiple of 512 below 2^30");
  end
`endif

  localparam logic [29:0] WinAdr = WIN_BASE[29:0];

  logic        open_q, open_d;        // the guard takes the stream's data words
  logic [7:0]  left_q, left_d;        // data words left in the chunk (0: the next word is a header)
  logic [23:0] addr_q, addr_d;        // word address of the chunk's next data word
  logic [31:0] expect_q, expect_d;    // EXPECT (= ACCEPTED)
  logic [31:0] stale_q, stale_d;      // STALE
  logic [31:0] dropped_q, dropped_d;  // DROPPED
  logic [31:0] errors_q, errors_d;    // ERRORS

  // Decode of the upstream request.
  logic       req, in_win, is_seq, is_stream, is_count, fwd, own, own_ok, done;
  logic [8:0] off;
  assign req       = s_cyc_i && s_stb_i;
  assign in_win    = s_adr_i[29:9] == WinAdr[29:9];
  assign off       = s_adr_i[8:0];
  assign is_seq    = off == 9'd0;
  assign is_stream = !off[8] && !is_seq;           // words 1..255
  assign is_count  = off[8:2] == 7'b100_0000;      // words 256..259
  // A data word of an open guard goes to the bus; every other access in the
  // window is the guard's own, answered now.
  assign fwd       = in_win && s_we_i && is_stream && left_q != 8'd0 && open_q;
  assign own       = in_win && !fwd;
  assign own_ok    = s_we_i ? (is_seq || is_stream) : (is_seq || is_count);
  assign done      = s_ack_o || s_err_o;           // the upstream access ends at this edge

  // Downstream: the upstream request, or the forwarded data word at its
  // target; nothing in the clock of an own access.
  assign m_cyc_o = s_cyc_i;
  assign m_stb_o = req && !own;
  assign m_we_o  = s_we_i;
  assign m_adr_o = in_win ? {6'd0, addr_q} : s_adr_i;
  assign m_dat_o = s_dat_i;
  assign m_sel_o = s_sel_i;

  // Upstream answer (ack and err never together, and only to a request).
  assign s_ack_o = req && (own ? own_ok : (m_ack_i && !m_err_i));
  assign s_err_o = req && (own ? !own_ok : m_err_i);
  // Read data: the bus's outside the window; in it, word 0 and 256 EXPECT
  // (= ACCEPTED), 257..259 the counters (other words answer err: what they
  // read is of no matter). AND-OR of one-hot selects: 3 LUT4 a bit, against
  // 4 for the case statement.
  logic [1:0] rsel;
  assign rsel = off[1:0] & {2{off[8]}};
  assign s_dat_o = ({32{!in_win}} & m_dat_i)
                 | ({32{in_win && rsel == 2'd0}} & expect_q)
                 | ({32{in_win && rsel == 2'd1}} & stale_q)
                 | ({32{in_win && rsel == 2'd2}} & dropped_q)
                 | ({32{in_win && rsel == 2'd3}} & errors_q);

  // State: changes only at the edge that ends an answered window write.
  logic seq_wr, stream_wr, match;
  assign seq_wr    = done && in_win && s_we_i && is_seq;
  assign stream_wr = done && in_win && s_we_i && is_stream;
  assign match     = s_dat_i == expect_q;
  always_comb begin
    open_d    = open_q;
    left_d    = left_q;
    addr_d    = addr_q;
    expect_d  = expect_q;
    stale_d   = stale_q;
    dropped_d = dropped_q;
    errors_d  = errors_q;
    if (seq_wr) begin
      open_d = match;
      left_d = 8'd0;
      if (match) expect_d = expect_q + 32'd1;
      else stale_d = stale_q + 32'd1;
    end
    if (stream_wr) begin
      if (left_q == 8'd0) begin
        left_d = s_dat_i[31:24];
        addr_d = s_dat_i[23:0];
      end else begin
        left_d = left_q - 8'd1;
        addr_d = addr_q + 24'd1;
        if (!open_q) dropped_d = dropped_q + 32'd1;
        else if (s_err_o) errors_d = errors_q + 32'd1;
      end
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      open_q    <= 1'b0;
      left_q    <= 8'd0;
      addr_q    <= 24'd0;
      expect_q  <= 32'd0;
      stale_q   <= 32'd0;
      dropped_q <= 32'd0;
      errors_q  <= 32'd0;
    end else begin
      open_q    <= open_d;
      left_q    <= left_d;
      addr_q    <= addr_d;
      expect_q  <= expect_d;
      stale_q   <= stale_d;
      dropped_q <= dropped_d;
      errors_q  <= errors_d;
    end
  end
endmodule

// Formal properties of etherbone_engine (scripts/formal.sh --blocks
// etherbone_engine): the frame buffer's checks and the Wishbone manager.
//
// Every input free on every clock (the decoded frame's events, the reply's
// ready, the bus's answers and read data), but for the decoder's contract:
// a data byte comes alone (in_err_i may come with in_end_i). Reset in the
// first cycle only. BUF_BYTES = 16 (the smallest), CNT_W = 4.
// The props file keeps its own account of the frame being received (the
// bytes the engine may store: those of an idle engine while they fit; their
// CRC-32, computed bit by bit here; whether the frame is already lost) and
// its verdict at each end: whole (no error, no byte lost), 16..BUF_BYTES
// bytes, CRC residue 0xDEBB20E3. Then:
//   a_start   the engine leaves idle only on the clock after an end whose
//             frame passed that verdict: no bus access, no reply, nothing
//             of a frame runs unless it was whole and its CRC right;
//   a_cyc     cyc only while the engine runs (busy) and stb is cyc;
//   a_hold    a request (cyc & stb) stays, with its address, data, we and
//             sel unchanged, until the bus answers it (ack or err), and cyc
//             drops on the clock after the answer;
//   a_buf     the buffer is written only while idle and read only while
//             busy (one port at a time: prim_ram_1r1w's SAME_WORD_RW = 0
//             holds);
//   a_rx      the engine's frame length, lost flag and (for a frame under
//             way) CRC register are the account's, and nothing is stored
//             while busy (the invariant that
//             closes the induction, with a_fsm: a valid state, cyc
//             exactly in the two bus states, no reply byte pending in the
//             states before the reply and in the bus states, a fetch only
//             in the states that wait for one).
// Linked registers and wires (scripts/formal.sh connects them):
// link: f_st=u_dut.st_q f_len=u_dut.len_q f_bad=u_dut.bad_q f_crc=u_dut.u_crc.crc_q
// link: f_store=u_dut.store f_re=u_dut.re f_fl=u_dut.fl_q f_fp=u_dut.fp_q
// link: f_on=u_dut.on_q f_od=u_dut.od_q
module etherbone_engine_props #(
  parameter int BUF_BYTES = 16,
  parameter int CNT_W     = 4
) (
  input logic        clk_i,
  input logic        rst_ni,
  input logic        in_data_i,
  input logic [7:0]  in_byte_i,
  input logic        in_end_i,
  input logic        in_err_i,
  input logic        out_ready_i,
  input logic [31:0] m_dat_i,
  input logic        m_ack_i,
  input logic        m_err_i
);
  localparam int AW = $clog2(BUF_BYTES);
  localparam logic [4:0] StIdle = 5'd0, StWWait = 5'd5, StRWait = 5'd10;

  logic             out_valid, out_end, m_cyc, m_stb, m_we, busy;
  logic [7:0]       out_byte;
  logic [29:0]      m_adr;
  logic [31:0]      m_dat;
  logic [3:0]       m_sel;
  logic [CNT_W-1:0] frames_run, frames_bad, bus_errors;

  etherbone_engine #(
    .BUF_BYTES(BUF_BYTES),
    .CNT_W    (CNT_W)
  ) u_dut (
    .clk_i,
    .rst_ni,
    .in_data_i,
    .in_byte_i,
    .in_end_i,
    .in_err_i,
    .out_valid_o (out_valid),
    .out_end_o   (out_end),
    .out_byte_o  (out_byte),
    .out_ready_i,
    .m_cyc_o     (m_cyc),
    .m_stb_o     (m_stb),
    .m_we_o      (m_we),
    .m_adr_o     (m_adr),
    .m_dat_o     (m_dat),
    .m_sel_o     (m_sel),
    .m_dat_i,
    .m_ack_i,
    .m_err_i,
    .frames_run_o(frames_run),
    .frames_bad_o(frames_bad),
    .bus_errors_o(bus_errors),
    .busy_o      (busy)
  );

  // linked
  logic [4:0]  f_st;
  logic [AW:0] f_len;
  logic        f_bad, f_store, f_re, f_fp, f_od;
  logic [31:0] f_crc;
  logic [2:0]  f_fl;
  logic [3:0]  f_on;

  // The CRC-32 register after one byte, one bit at a time.
  function automatic logic [31:0] crc_byte(input logic [31:0] c, input logic [7:0] d);
    logic [31:0] r;
    logic        fb;
    r = c;
    for (int i = 0; i < 8; i++) begin
      fb = r[0] ^ d[i];
      r  = {1'b0, r[31:1]};
      if (fb) r = r ^ 32'hEDB8_8320;
    end
    crc_byte = r;
  endfunction

  // The account of the frame under way.
  logic [AW:0] a_len;
  logic        a_lost;
  logic [31:0] a_crc;
  logic        fits, pass, p_pass, p_busy, p_req, p_answer, p_we;
  logic [29:0] p_adr;
  logic [31:0] p_dat;
  logic [3:0]  p_sel;
  assign fits = !busy && a_len < (AW + 1)'(BUF_BYTES);
  assign pass = in_end_i && !busy && !a_lost && !in_err_i && a_len >= (AW + 1)'(16) &&
                a_crc == 32'hDEBB_20E3;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      a_len    <= '0;
      a_lost   <= 1'b0;
      a_crc    <= 32'hFFFF_FFFF;
      p_pass   <= 1'b0;
      p_busy   <= 1'b0;
      p_req    <= 1'b0;
      p_answer <= 1'b0;
      p_we     <= 1'b0;
      p_adr    <= 30'd0;
      p_dat    <= 32'd0;
      p_sel    <= 4'd0;
    end else begin
      if (in_end_i) begin
        a_len  <= '0;
        a_lost <= 1'b0;
      end else begin
        if (in_data_i && fits) begin
          a_len <= a_len + (AW + 1)'(1);
          a_crc <= crc_byte(a_len == '0 ? 32'hFFFF_FFFF : a_crc, in_byte_i);
        end
        if (in_err_i || (in_data_i && !fits)) a_lost <= 1'b1;
      end
      p_pass   <= pass;
      p_busy   <= busy;
      p_req    <= m_cyc && m_stb;
      p_answer <= m_ack_i || m_err_i;
      p_we     <= m_we;
      p_adr    <= m_adr;
      p_dat    <= m_dat;
      p_sel    <= m_sel;
    end
  end

  // the states that wait for a fetch: Hdr, Rec, WBase, WData, RBase, RAddr, PSend
  logic fetching;
  assign fetching = f_st == 5'd1 || f_st == 5'd2 || f_st == 5'd3 || f_st == 5'd4 ||
                    f_st == 5'd7 || f_st == 5'd9 || f_st == 5'd16;

  // the states with no reply byte pending: Idle, Hdr, Rec, WBase, WData,
  // WWait, RAddr, RWait, Drop
  logic quiet;
  assign quiet = f_st <= 5'd5 || f_st == 5'd9 || f_st == 5'd10 || f_st == 5'd17;

  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;

  always_comb begin
    assume(rst_ni == !f_init);
    if (in_data_i) assume(!in_end_i && !in_err_i);
    if (!f_init) begin
      if (busy && !p_busy) a_start: assert(p_pass);
      a_cyc: assert((!m_cyc || busy) && m_stb == m_cyc);
      if (p_req && !p_answer) begin
        a_hold: assert(m_cyc && m_stb && m_we == p_we && m_adr == p_adr && m_dat == p_dat &&
                       m_sel == p_sel);
      end
      if (p_req && p_answer) a_drop: assert(!m_cyc);
      a_buf: assert((!f_store || !busy) && (!f_re || busy));
      a_busy: assert(busy == (f_st != StIdle));
      a_fsm: assert(m_cyc == (f_st == StWWait || f_st == StRWait) &&
                    (!quiet || (f_on == 4'd0 && !f_od)) && f_st <= 5'd17 &&
                    (f_fl == 3'd0 && !f_fp || fetching));
      a_rx: assert(f_len == a_len && f_bad == a_lost && (busy ? a_len == '0 : a_len == '0 || f_crc == a_crc));
    end
  end
endmodule

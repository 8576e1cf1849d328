// Formal properties of link_guard (scripts/formal.sh --blocks link_guard).
//
// Every input free on every clock (the upstream master and the downstream
// bus need not keep any Wishbone rule: the guard's promises hold whatever
// they do); reset in the first cycle only. The props file keeps its own
// model of the guard from docs/link.md (f_*: EXPECT, ACCEPTED, the counters,
// open/closed, the chunk's header address, the data word's index in the
// chunk, the words left) from the upstream accesses it sees answered, and
// checks the guard's outputs against it:
//   a_wb      Wishbone: upstream ack and err never together and only to a
//             request (cyc & stb); downstream stb only with cyc;
//   a_pass    outside the window the guard is transparent: every m_* is its
//             s_* and every s_* answer is the bus's (ack masked by err);
//   a_fwd     a downstream request from a window access is a data word of
//             an open guard: a write, to the header's address plus the
//             word's index in the chunk, with the word's data and sel, and
//             its answer is the upstream answer in the same clock (so each
//             upstream stream word gives at most one downstream write, and
//             every downstream write ends with the upstream one: a_one);
//   a_take    ... and every such data word of an open guard goes to the bus;
//   a_own     every other window access is answered in its own clock, err
//             exactly for the accesses the map forbids (a read of STREAM, a
//             write of a counter, words 260..511), with no downstream request;
//   a_read    a read of word 0 or 256..259 returns the model's EXPECT,
//             ACCEPTED, STALE, DROPPED, ERRORS (32-bit, wrapping);
//   a_expect  the guard's EXPECT register changes only by +1, and only at
//             the edge of an answered SEQ write whose data equals it;
//   a_state   the guard's registers are the model's (the invariant that
//             closes the induction, with a_chunk: a chunk's index and words
//             left add up to at most 255), through the `// link:` line
//             (scripts/formal.sh connects each wire to the register):
// link: f_open=u_dut.open_q f_left=u_dut.left_q f_addr=u_dut.addr_q f_dexp=u_dut.expect_q
// link: f_dstale=u_dut.stale_q f_ddrop=u_dut.dropped_q f_derr=u_dut.errors_q
// WIN_BASE here is 3 * 512 words (not the board's 0x20000), so both the
// high address bits and the offset bits are exercised at a small constant.
module link_guard_props #(
  parameter int unsigned WIN_BASE = 32'd1536
) (
  input logic        clk_i,
  input logic        rst_ni,
  input logic        s_cyc_i,
  input logic        s_stb_i,
  input logic        s_we_i,
  input logic [29:0] s_adr_i,
  input logic [31:0] s_dat_i,
  input logic [3:0]  s_sel_i,
  input logic [31:0] m_dat_i,
  input logic        m_ack_i,
  input logic        m_err_i
);
  logic [31:0] s_dat_o, m_dat_o;
  logic        s_ack_o, s_err_o, m_cyc_o, m_stb_o, m_we_o;
  logic [29:0] m_adr_o;
  logic [3:0]  m_sel_o;

  link_guard #(.WIN_BASE(WIN_BASE)) u_dut (
    .clk_i,
    .rst_ni,
    .s_cyc_i,
    .s_stb_i,
    .s_we_i,
    .s_adr_i,
    .s_dat_i,
    .s_sel_i,
    .s_dat_o,
    .s_ack_o,
    .s_err_o,
    .m_cyc_o,
    .m_stb_o,
    .m_we_o,
    .m_adr_o,
    .m_dat_o,
    .m_sel_o,
    .m_dat_i,
    .m_ack_i,
    .m_err_i
  );

  // The guard's registers (linked).
  logic        f_open;
  logic [7:0]  f_left;
  logic [23:0] f_addr;
  logic [31:0] f_dexp, f_dstale, f_ddrop, f_derr;

  // The model.
  logic        m_open;                    // open
  logic [7:0]  m_left;                    // data words left in the chunk
  logic [23:0] m_base;                    // the chunk header's word address
  logic [7:0]  m_idx;                     // index of the chunk's next data word
  logic [31:0] m_expect, m_accepted, m_stale, m_dropped, m_errors;
  logic [31:0] p_dexp;                    // the guard's EXPECT on the last clock
  logic        p_seq_match;               // last clock: an answered SEQ write equal to it

  logic        req, win, wr, seq, stream, count, data_word, answered;
  logic [8:0]  off;
  assign req       = s_cyc_i && s_stb_i;
  assign win       = {2'd0, s_adr_i} >= WIN_BASE && {2'd0, s_adr_i} < WIN_BASE + 32'd512;
  assign off       = 9'(s_adr_i - WIN_BASE[29:0]);
  assign wr        = s_we_i;
  assign seq       = off == 9'd0;
  assign stream    = off >= 9'd1 && off <= 9'd255;
  assign count     = off >= 9'd256 && off <= 9'd259;
  assign data_word = win && req && wr && stream && m_left != 8'd0;
  assign answered  = s_ack_o || s_err_o;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      m_open      <= 1'b0;
      m_left      <= 8'd0;
      m_base      <= 24'd0;
      m_idx       <= 8'd0;
      m_expect    <= 32'd0;
      m_accepted  <= 32'd0;
      m_stale     <= 32'd0;
      m_dropped   <= 32'd0;
      m_errors    <= 32'd0;
      p_dexp      <= 32'd0;
      p_seq_match <= 1'b0;
    end else begin
      p_dexp      <= f_dexp;
      p_seq_match <= win && req && wr && seq && answered && s_dat_i == f_dexp;
      if (win && req && wr && seq && answered) begin
        m_left <= 8'd0;
        if (s_dat_i == m_expect) begin
          m_open     <= 1'b1;
          m_expect   <= m_expect + 32'd1;
          m_accepted <= m_accepted + 32'd1;
        end else begin
          m_open  <= 1'b0;
          m_stale <= m_stale + 32'd1;
        end
      end
      if (win && req && wr && stream && answered) begin
        if (m_left == 8'd0) begin
          m_left <= s_dat_i[31:24];
          m_base <= s_dat_i[23:0];
          m_idx  <= 8'd0;
        end else begin
          m_left <= m_left - 8'd1;
          m_idx  <= m_idx + 8'd1;
          if (!m_open) m_dropped <= m_dropped + 32'd1;
          else if (s_err_o) m_errors <= m_errors + 32'd1;
        end
      end
    end
  end

  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;

  always_comb begin
    assume(rst_ni == !f_init);
    if (!f_init) begin
      a_wb: assert(!(s_ack_o && s_err_o) && (!answered || req) && (!m_stb_o || m_cyc_o));
      if (!win) begin
        a_pass: assert(m_cyc_o == s_cyc_i && m_stb_o == req && m_we_o == s_we_i &&
                       m_adr_o == s_adr_i && m_dat_o == s_dat_i && m_sel_o == s_sel_i &&
                       s_dat_o == m_dat_i && s_ack_o == (req && m_ack_i && !m_err_i) &&
                       s_err_o == (req && m_err_i));
      end
      if (win && m_stb_o) begin
        a_fwd: assert(data_word && m_open && m_we_o && m_adr_o == {6'd0, m_base + 24'(m_idx)} &&
                      m_dat_o == s_dat_i && m_sel_o == s_sel_i &&
                      s_ack_o == (m_ack_i && !m_err_i) && s_err_o == m_err_i);
      end
      if (win && m_stb_o && (m_ack_i || m_err_i)) a_one: assert(answered);
      if (data_word && m_open) a_take: assert(m_stb_o);
      if (win && req && !(data_word && m_open)) begin
        a_own: assert(!m_stb_o && answered &&
                      s_err_o == !(wr ? (seq || stream) : (seq || count)));
      end
      if (win && req && !wr && s_ack_o) begin
        if (off == 9'd257) a_read_stale: assert(s_dat_o == m_stale);
        if (off == 9'd258) a_read_dropped: assert(s_dat_o == m_dropped);
        if (off == 9'd259) a_read_errors: assert(s_dat_o == m_errors);
        if (seq) a_read_expect: assert(s_dat_o == m_expect);
        if (off == 9'd256) a_read_accepted: assert(s_dat_o == m_accepted);
      end
      a_expect: assert(f_dexp == p_dexp || (p_seq_match && f_dexp == p_dexp + 32'd1));
      a_chunk: assert(9'(m_left) + 9'(m_idx) <= 9'd255);
      a_state: assert(f_open == m_open && f_left == m_left && f_addr == m_base + 24'(m_idx) &&
                      f_dexp == m_expect && f_dexp == m_accepted && f_dstale == m_stale &&
                      f_ddrop == m_dropped && f_derr == m_errors);
    end
  end
endmodule

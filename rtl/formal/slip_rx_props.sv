// Formal properties of slip_rx (scripts/formal.sh --blocks slip_rx): the
// SLIP decoder's escape rule (RFC 1055, strict). Every input free on every
// clock; reset in the first cycle only. The props file keeps its own escape
// state (m_esc: the last character taken was an ESC not yet used) and checks
// the outputs for the character of the clock before:
//   a_idle   no character: no output;
//   a_ferr   a character with a framing error: err_o alone;
//   a_end    END: end_o, with err_o exactly when an ESC was pending;
//   a_esc    after ESC: 0xDC gives data 0xC0, 0xDD data 0xDB, anything
//            else err_o (no data);
//   a_open   ESC: no output (it escapes the next character);
//   a_data   any other character: data_o with the character itself; so END
//            and ESC never come out as data unless sent escaped;
//   a_one    at most one of data_o, end_o and err_o, but for err_o with end_o;
//   a_state  the block's escape flag is m_esc (the induction's invariant).
// link: f_esc=u_dut.esc_q
module slip_rx_props (
  input logic       clk_i,
  input logic       rst_ni,
  input logic       valid_i,
  input logic [7:0] data_i,
  input logic       ferr_i
);
  logic       data_o, end_o, err_o, f_esc;
  logic [7:0] byte_o;

  slip_rx u_dut (
    .clk_i,
    .rst_ni,
    .valid_i,
    .data_i,
    .ferr_i,
    .data_o,
    .byte_o,
    .end_o,
    .err_o
  );

  logic       m_esc, p_valid, p_ferr, p_esc;
  logic [7:0] p_data;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      m_esc   <= 1'b0;
      p_valid <= 1'b0;
      p_ferr  <= 1'b0;
      p_esc   <= 1'b0;
      p_data  <= 8'd0;
    end else begin
      if (valid_i) m_esc <= !ferr_i && !m_esc && data_i == 8'hDB;
      p_valid <= valid_i;
      p_ferr  <= ferr_i;
      p_esc   <= m_esc;
      p_data  <= data_i;
    end
  end

  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;

  always_comb begin
    assume(rst_ni == !f_init);
    if (!f_init) begin
      a_state: assert(f_esc == m_esc);
      a_one: assert(!(data_o && (end_o || err_o)));
      if (!p_valid) begin
        a_idle: assert(!data_o && !end_o && !err_o);
      end else if (p_ferr) begin
        a_ferr: assert(err_o && !data_o && !end_o);
      end else if (p_data == 8'hC0) begin
        a_end: assert(end_o && err_o == p_esc);
      end else if (p_esc) begin
        if (p_data == 8'hDC) a_esc_end: assert(data_o && byte_o == 8'hC0 && !err_o);
        else if (p_data == 8'hDD) a_esc_esc: assert(data_o && byte_o == 8'hDB && !err_o);
        else a_esc_bad: assert(err_o && !data_o && !end_o);
      end else if (p_data == 8'hDB) begin
        a_open: assert(!data_o && !end_o && !err_o);
      end else begin
        a_data: assert(data_o && byte_o == p_data && !end_o && !err_o);
      end
    end
  end
endmodule

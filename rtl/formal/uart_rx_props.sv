// Formal properties of uart_rx (scripts/formal.sh --blocks uart_rx): the
// receiver's bit timing, at DIV = 8 clocks a bit (the least it takes).
// The props file drives rx_i as an ideal 8N1 sender at DIV clocks a bit:
// a character of a free byte starts whenever start_i says so while the line
// is idle or in a stop bit's last clock (so back to back as well as after
// any gap); reset in the first cycle only. With e the clocks since the
// character's start bit began (m_bit * DIV + m_cnt) and H = DIV / 2:
//   a_valid  valid_o is high exactly once a character, at e = H + 3 + 9 DIV
//            (the stop bit sampled at its middle through the two-flop
//            synchronizer), with data_o the byte sent and ferr_o low: every
//            character sent is received, once, right, and nothing else is;
//   a_state  the receiver's registers are what e says (idle until the
//            synchronized start edge, the start bit's half, each data bit
//            sampled at its middle with the bits so far in the shift
//            register, the stop bit, idle again before the character ends)
//            (the induction's invariant), through the `// link:` lines:
// link: f_meta=u_dut.meta_q f_line=u_dut.line_q f_st=u_dut.st_q f_cnt=u_dut.cnt_q
// link: f_bit=u_dut.bit_q f_sh=u_dut.sh_q f_valid=u_dut.valid_q f_ferr=u_dut.ferr_q
module uart_rx_props #(
  parameter int DIV = 8
) (
  input logic       clk_i,
  input logic       rst_ni,
  input logic       start_i,  // start a character now, if the line allows
  input logic [7:0] byte_i    // its byte
);
  localparam int CW = $clog2(DIV);
  localparam int H = DIV / 2;
  localparam logic [2:0] Idle = 3'd0, Start = 3'd1, Data = 3'd2, Stop = 3'd3;

  logic          rx, valid, ferr;
  logic [7:0]    data;
  logic          f_meta, f_line, f_valid, f_ferr;
  logic [2:0]    f_st, f_bit;
  logic [CW-1:0] f_cnt;
  logic [7:0]    f_sh;

  uart_rx #(.DIV(DIV)) u_dut (
    .clk_i,
    .rst_ni,
    .rx_i   (rx),
    .valid_o(valid),
    .data_o (data),
    .ferr_o (ferr)
  );

  // The sender.
  logic          m_act, m_last;
  logic [3:0]    m_bit;
  logic [CW-1:0] m_cnt;
  logic [7:0]    m_byte;
  assign m_last = m_act && m_bit == 4'd9 && m_cnt == CW'(DIV - 1);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      m_act  <= 1'b0;
      m_bit  <= 4'd0;
      m_cnt  <= '0;
      m_byte <= 8'd0;
    end else if (start_i && (!m_act || m_last)) begin
      m_act  <= 1'b1;
      m_bit  <= 4'd0;
      m_cnt  <= '0;
      m_byte <= byte_i;
    end else if (m_last) begin
      m_act <= 1'b0;
    end else if (m_act) begin
      if (m_cnt == CW'(DIV - 1)) begin
        m_cnt <= '0;
        m_bit <= m_bit + 4'd1;
      end else begin
        m_cnt <= m_cnt + CW'(1);
      end
    end
  end
  always_comb begin
    if (!m_act) rx = 1'b1;
    else if (m_bit == 4'd0) rx = 1'b0;
    else if (m_bit <= 4'd8) rx = m_byte[m_bit-4'd1];
    else rx = 1'b1;
  end

  // The line one and two clocks ago.
  logic p1, p2;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      p1 <= 1'b1;
      p2 <= 1'b1;
    end else begin
      p1 <= rx;
      p2 <= p1;
    end
  end

  // Where the receiver must be at e.
  logic [7:0]    e, ed;
  logic [3:0]    k;       // the data bit sampled next (8: the stop bit)
  logic [CW-1:0] c;
  logic [7:0]    mask;    // the bits of sh already sampled
  assign e    = 8'(m_bit) * 8'(DIV) + 8'(m_cnt);
  assign ed   = e - 8'(H + 3);
  assign k    = 4'(ed / 8'(DIV));
  assign c    = CW'(ed % 8'(DIV));
  assign mask = k >= 4'd8 ? 8'hFF : 8'hFF << (4'd8 - k);

  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;

  always_comb begin
    assume(rst_ni == !f_init);
    if (!f_init) begin
      a_valid: assert(valid == (m_act && e == 8'(H + 3 + 9 * DIV)) &&
                      (!valid || (data == m_byte && !ferr)));
      a_sync: assert(f_meta == p1 && f_line == p2 && !f_ferr && f_valid == valid);
      a_range: assert(m_bit <= 4'd9 && m_cnt <= CW'(DIV - 1));
      if (!m_act || e <= 8'd2 || e >= 8'(H + 3 + 9 * DIV)) begin
        a_idle: assert(f_st == Idle);
      end else if (e <= 8'(H + 2)) begin
        a_start: assert(f_st == Start && f_cnt == CW'(H - 1) - CW'(e - 8'd3));
      end else if (k <= 4'd7) begin
        a_data: assert(f_st == Data && f_cnt == CW'(DIV - 1) - c && f_bit == k[2:0] &&
                       (f_sh & mask) == ((m_byte << (4'd8 - k)) & mask));
      end else begin
        a_stop: assert(f_st == Stop && f_cnt == CW'(DIV - 1) - c && f_sh == m_byte);
      end
      if (m_act && e >= 8'(H + 3 + 9 * DIV)) a_held: assert(f_sh == m_byte);
    end
  end
endmodule

// Formal properties of uart_tx (scripts/formal.sh --blocks uart_tx): the
// bit timing, at DIV = 5 (odd) clocks a bit. valid_i and data_i free on
// every clock; reset in the first cycle only. The props file follows the
// character it saw taken (valid_i and ready_o) bit by bit (m_bit 0: start,
// 1..8: data, 9: stop; m_cnt: clocks into the bit) and checks:
//   a_line   tx_o is the start bit (0), the data bits least significant
//            first, the stop bit (1), each for exactly DIV clocks from the
//            clock after the take, and 1 when no character is on the line;
//   a_ready  ready_o is high exactly when idle or in a stop bit's last clock
//            (back-to-back characters: 10 * DIV clocks each);
//   a_state  the block's registers are what the character's position says
//            (the induction's invariant), through the `// link:` line:
// link: f_busy=u_dut.busy_q f_cnt=u_dut.cnt_q f_left=u_dut.left_q f_sh=u_dut.sh_q
module uart_tx_props #(
  parameter int DIV = 5
) (
  input logic       clk_i,
  input logic       rst_ni,
  input logic       valid_i,
  input logic [7:0] data_i
);
  localparam int CW = $clog2(DIV);
  logic          ready, tx, f_busy;
  logic [CW-1:0] f_cnt;
  logic [3:0]    f_left;
  logic [8:0]    f_sh;

  uart_tx #(.DIV(DIV)) u_dut (
    .clk_i,
    .rst_ni,
    .valid_i,
    .data_i,
    .ready_o(ready),
    .tx_o   (tx)
  );

  logic          m_act;
  logic [3:0]    m_bit;
  logic [CW-1:0] m_cnt;
  logic [7:0]    m_byte;
  logic          m_last;
  assign m_last = m_act && m_bit == 4'd9 && m_cnt == CW'(DIV - 1);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      m_act  <= 1'b0;
      m_bit  <= 4'd0;
      m_cnt  <= '0;
      m_byte <= 8'd0;
    end else if (valid_i && ready) begin
      m_act  <= 1'b1;
      m_bit  <= 4'd0;
      m_cnt  <= '0;
      m_byte <= data_i;
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

  logic line;
  logic [17:0] rest;
  assign rest = {9'h1FF, 1'b1, m_byte} >> m_bit;  // the bits after bit m_bit, then ones
  always_comb begin
    if (!m_act) line = 1'b1;
    else if (m_bit == 4'd0) line = 1'b0;
    else if (m_bit <= 4'd8) line = m_byte[m_bit-4'd1];
    else line = 1'b1;
  end

  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;

  always_comb begin
    assume(rst_ni == !f_init);
    if (!f_init) begin
      a_line: assert(tx == line);
      a_ready: assert(ready == (!m_act || m_last));
      a_range: assert(m_bit <= 4'd9 && m_cnt <= CW'(DIV - 1));
      a_state: assert(f_busy == m_act && (!m_act || (f_cnt == CW'(DIV - 1) - m_cnt &&
                      f_left == 4'd9 - m_bit && f_sh == rest[8:0])));
    end
  end
endmodule

// uart_tx: a UART transmitter, 8N1 (start bit 0, 8 data bits least
// significant first, stop bit 1), DIV clocks a bit.
//
// ready_o is high while the transmitter is idle and in the last clock of a
// stop bit; a byte offered with valid_i in such a clock is taken at its edge.
// tx_o (a flip-flop, high when idle) gives its start bit from the next clock
// on, then the data bits and the stop bit, each exactly DIV clocks: bytes
// offered back to back take 10 * DIV clocks each.
// Formal: rtl/formal/uart_tx_props.sv (scripts/formal.sh --blocks uart_tx).
module uart_tx #(
  parameter int DIV = 16  // clocks a bit (>= 2)
) (
  input  logic       clk_i,
  input  logic       rst_ni,   // asynchronous, active low: idle, line high
  input  logic       valid_i,  // a byte to send
  input  logic [7:0] data_i,
  output logic       ready_o,  // valid_i's byte is taken at this edge
  output logic       tx_o      // the line
);
`ifndef __ICARUS__
  if (DIV < 2) begin : g_bad_div
    $error("uart_tx: parameter DIV must be >= 2");
  end
`endif

  localparam int CW = DIV > 1 ? $clog2(DIV) : 1;
  localparam logic [CW-1:0] Full = CW'(DIV - 1);

  logic          busy_q, busy_d;  // a character is on the line
  logic          line_q, line_d;  // tx_o
  logic [8:0]    sh_q, sh_d;      // the bits after the one on the line: data, then the stop bit
  logic [3:0]    left_q, left_d;  // how many of them
  logic [CW-1:0] cnt_q, cnt_d;    // clocks left of the bit on the line, minus one

  // The last clock of a stop bit (or idle): a byte offered now starts its
  // start bit on the next clock.
  logic last;
  assign last = !busy_q || (cnt_q == '0 && left_q == 4'd0);

  always_comb begin
    busy_d = busy_q;
    line_d = line_q;
    sh_d   = sh_q;
    left_d = left_q;
    cnt_d  = cnt_q;
    if (last) begin
      busy_d = valid_i;
      line_d = !valid_i;
      sh_d   = {1'b1, data_i};
      left_d = 4'd9;
      cnt_d  = Full;
    end else if (cnt_q != '0) begin
      cnt_d = cnt_q - CW'(1);
    end else begin
      line_d = sh_q[0];
      sh_d   = {1'b1, sh_q[8:1]};
      left_d = left_q - 4'd1;
      cnt_d  = Full;
    end
  end

  assign ready_o = last;
  assign tx_o    = line_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q <= 1'b0;
      line_q <= 1'b1;
      sh_q   <= 9'h1FF;
      left_q <= 4'd0;
      cnt_q  <= '0;
    end else begin
      busy_q <= busy_d;
      line_q <= line_d;
      sh_q   <= sh_d;
      left_q <= left_d;
      cnt_q  <= cnt_d;
    end
  end
endmodule

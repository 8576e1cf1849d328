// slip_tx: SLIP (RFC 1055) encoding of a frame's bytes into characters for
// a UART transmitter (rtl/link/uart_tx.sv), for rtl/link/etherbone_engine.sv.
//
// In: a byte stream (valid_i, ready_o), each byte either data or, with
// end_i, a frame delimiter. Out: characters (valid_o, ready_i):
//   a delimiter         END 0xC0
//   data 0xC0 (END)     ESC 0xDB, 0xDC
//   data 0xDB (ESC)     ESC 0xDB, 0xDD
//   any other data      the byte itself
// in order. A byte is taken (ready_o) only while no character of the last
// one waits; the first character of a byte is offered from the next clock,
// an escape's second one in the clock after the first is taken.
module slip_tx (
  input  logic       clk_i,
  input  logic       rst_ni,   // asynchronous, active low: nothing waiting
  input  logic       valid_i,  // a byte to send
  input  logic       end_i,    // with valid_i: a delimiter (END), data_i ignored
  input  logic [7:0] data_i,
  output logic       ready_o,  // the byte is taken at this edge
  output logic       valid_o,  // a character to send
  output logic [7:0] data_o,
  input  logic       ready_i   // the character is taken at this edge
);
  localparam logic [7:0] End = 8'hC0, Esc = 8'hDB, EscEnd = 8'hDC, EscEsc = 8'hDD;

  logic       out_q, out_d;          // data_o is offered
  logic [7:0] char_q, char_d;        // data_o
  logic       second_q, second_d;    // an escape's second character waits
  logic [7:0] next_q, next_d;        // which

  always_comb begin
    out_d    = out_q;
    char_d   = char_q;
    second_d = second_q;
    next_d   = next_q;
    if (out_q && ready_i) begin
      out_d    = second_q;
      char_d   = next_q;
      second_d = 1'b0;
    end
    if (ready_o && valid_i) begin
      out_d = 1'b1;
      if (end_i) begin
        char_d = End;
      end else if (data_i == End || data_i == Esc) begin
        char_d   = Esc;
        second_d = 1'b1;
        next_d   = data_i == End ? EscEnd : EscEsc;
      end else begin
        char_d = data_i;
      end
    end
  end

  assign ready_o = !out_q;  // (second_q only with out_q)
  assign valid_o = out_q;
  assign data_o  = char_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      out_q    <= 1'b0;
      char_q   <= 8'd0;
      second_q <= 1'b0;
      next_q   <= 8'd0;
    end else begin
      out_q    <= out_d;
      char_q   <= char_d;
      second_q <= second_d;
      next_q   <= next_d;
    end
  end
endmodule

// uart_rx: a UART receiver, 8N1 (one start bit, 8 data bits least
// significant first, one stop bit), DIV clocks a bit.
//
// rx_i goes through two flip-flops (it may be asynchronous). A falling edge
// of the synchronized line starts a character; the start bit is sampled
// DIV/2 clocks later (still low: a character; high: a glitch, ignored), each
// data bit DIV clocks after the one before, so at the middle of its bit
// time, then the stop bit. The clock after the stop bit's sample, valid_o is
// high for one clock with the byte on data_o (held until the next
// character's) and ferr_o high if the stop bit was low (a framing error;
// the receiver then waits for the line to go high before it looks for the
// next start bit, so a break gives one error). After a good stop bit it
// looks for the next start bit at once, half a bit before the sender's stop
// bit ends. A sender's bit time may differ from DIV clocks by as much as the
// half bit the sampling point can slip over the ten bits, minus the 1-2
// clocks of the synchronizer and the edge detection: about +-4.5 % at DIV =
// 16 (tests/link/ drives it 3 % off).
// Formal: rtl/formal/uart_rx_props.sv (scripts/formal.sh --blocks uart_rx).
module uart_rx #(
  parameter int DIV = 16  // clocks a bit (>= 8)
) (
  input  logic       clk_i,
  input  logic       rst_ni,   // asynchronous, active low: idle, no byte
  input  logic       rx_i,     // the line (idle high)
  output logic       valid_o,  // one clock: a character received
  output logic [7:0] data_o,   // its data bits
  output logic       ferr_o    // with valid_o: its stop bit was low
);
`ifndef __ICARUS__
  if (DIV < 8) begin : g_bad_div
    $error("uart_rx: parameter DIV must be >= 8");
  end
`endif

  localparam int CW = DIV > 1 ? $clog2(DIV) : 1;
  localparam logic [CW-1:0] Full = CW'(DIV - 1);
  localparam logic [CW-1:0] Half = CW'(DIV / 2 - 1);

  typedef enum logic [2:0] {
    Idle,   // waiting for a start bit
    Start,  // counting to the middle of the start bit
    Data,   // counting to the middle of the next data bit
    Stop,   // counting to the middle of the stop bit
    Break   // after a framing error: waiting for the line to go high
  } state_e;

  logic          meta_q, meta_d, line_q, line_d;  // the synchronizer
  state_e        st_q, st_d;
  logic [CW-1:0] cnt_q, cnt_d;    // clocks to the next sample, minus one
  logic [2:0]    bit_q, bit_d;    // data bit sampled next
  logic [7:0]    sh_q, sh_d;      // data bits, shifted in from the top
  logic          valid_q, valid_d, ferr_q, ferr_d;

  assign meta_d = rx_i;
  assign line_d = meta_q;

  always_comb begin
    st_d    = st_q;
    cnt_d   = cnt_q == '0 ? cnt_q : cnt_q - CW'(1);
    bit_d   = bit_q;
    sh_d    = sh_q;
    valid_d = 1'b0;
    ferr_d  = ferr_q;
    unique case (st_q)
      Idle: begin
        if (!line_q) begin
          st_d  = Start;
          cnt_d = Half;
        end
      end
      Start: begin
        if (cnt_q == '0) begin
          st_d  = line_q ? Idle : Data;
          cnt_d = Full;
          bit_d = 3'd0;
        end
      end
      Data: begin
        if (cnt_q == '0) begin
          sh_d  = {line_q, sh_q[7:1]};
          cnt_d = Full;
          bit_d = bit_q + 3'd1;
          if (bit_q == 3'd7) st_d = Stop;
        end
      end
      Stop: begin
        if (cnt_q == '0) begin
          valid_d = 1'b1;
          ferr_d  = !line_q;
          st_d    = line_q ? Idle : Break;
        end
      end
      default: begin  // Break
        if (line_q) st_d = Idle;
      end
    endcase
  end

  assign valid_o = valid_q;
  assign data_o  = sh_q;
  assign ferr_o  = ferr_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      meta_q  <= 1'b1;
      line_q  <= 1'b1;
      st_q    <= Idle;
      cnt_q   <= '0;
      bit_q   <= 3'd0;
      sh_q    <= 8'd0;
      valid_q <= 1'b0;
      ferr_q  <= 1'b0;
    end else begin
      meta_q  <= meta_d;
      line_q  <= line_d;
      st_q    <= st_d;
      cnt_q   <= cnt_d;
      bit_q   <= bit_d;
      sh_q    <= sh_d;
      valid_q <= valid_d;
      ferr_q  <= ferr_d;
    end
  end
endmodule

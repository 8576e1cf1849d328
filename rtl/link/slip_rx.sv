// slip_rx: SLIP (RFC 1055) decoding of a received byte stream, with the
// receiver's framing errors, for rtl/link/etherbone_engine.sv.
//
// Every received character (valid_i) gives, on the next clock, at most one
// of: a data byte (data_o with byte_o), the end of a frame (end_o), an error
// of the current frame (err_o), or nothing; err_o and end_o may come
// together (the frame ended and was bad):
//   a character with a framing error (ferr_i)   err_o (not decoded further)
//   END 0xC0                                     end_o
//   ESC 0xDB                                     nothing; the next one is escaped
//   ESC, then 0xDC / 0xDD                        data 0xC0 / 0xDB
//   ESC, then END                                err_o and end_o
//   ESC, then anything else (or a framing error) err_o
//   any other byte                               data, the byte itself
// A frame is what lies between two end_o; the escape state does not carry
// over an END or an error. So END and ESC never appear as data unless sent
// escaped, and an escape that is not one of the two never passes unnoticed.
// Formal: rtl/formal/slip_rx_props.sv (scripts/formal.sh --blocks slip_rx).
module slip_rx (
  input  logic       clk_i,
  input  logic       rst_ni,   // asynchronous, active low: no escape pending
  input  logic       valid_i,  // a character received
  input  logic [7:0] data_i,
  input  logic       ferr_i,   // with valid_i: it had a framing error
  output logic       data_o,   // a data byte of the frame: byte_o
  output logic [7:0] byte_o,
  output logic       end_o,    // the frame ends
  output logic       err_o     // the frame is bad
);
  localparam logic [7:0] End = 8'hC0, Esc = 8'hDB, EscEnd = 8'hDC, EscEsc = 8'hDD;

  logic       esc_q, esc_d;    // the last character was an ESC
  logic       data_q, data_d, end_q, end_d, err_q, err_d;
  logic [7:0] byte_q, byte_d;

  always_comb begin
    esc_d  = esc_q;
    data_d = 1'b0;
    end_d  = 1'b0;
    err_d  = 1'b0;
    byte_d = byte_q;
    if (valid_i) begin
      esc_d = 1'b0;
      if (ferr_i) begin
        err_d = 1'b1;
      end else if (data_i == End) begin
        end_d = 1'b1;
        err_d = esc_q;
      end else if (esc_q) begin
        if (data_i == EscEnd || data_i == EscEsc) begin
          data_d = 1'b1;
          byte_d = data_i == EscEnd ? End : Esc;
        end else begin
          err_d = 1'b1;
        end
      end else if (data_i == Esc) begin
        esc_d = 1'b1;
      end else begin
        data_d = 1'b1;
        byte_d = data_i;
      end
    end
  end

  assign data_o = data_q;
  assign byte_o = byte_q;
  assign end_o  = end_q;
  assign err_o  = err_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      esc_q  <= 1'b0;
      data_q <= 1'b0;
      end_q  <= 1'b0;
      err_q  <= 1'b0;
      byte_q <= 8'd0;
    end else begin
      esc_q  <= esc_d;
      data_q <= data_d;
      end_q  <= end_d;
      err_q  <= err_d;
      byte_q <= byte_d;
    end
  end
endmodule

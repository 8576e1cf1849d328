// uart_etherbone: the host link over a UART (docs/link.md, "UART framing"):
// Etherbone packets in SLIP frames with a CRC-32, run as a Wishbone B4
// classic manager, the replies sent back the same way.
//
//   rx_i -> uart_rx -> slip_rx -> etherbone_engine (frame buffer, checks,
//   the bus master, the reply) -> slip_tx -> uart_tx -> tx_o
//
// The line is 8N1 at BAUD with DIV = CLK_HZ / BAUD clocks a bit (rounded to
// the nearest); CLK_HZ / BAUD must be at least 8 and DIV's rounding within
// 2 % of it. rtl/link/etherbone_engine.sv states which frames run, the
// subset of Etherbone, the reply and the counters: a frame runs only if it
// is whole (no framing error, no bad escape, 16..BUF_BYTES bytes, CRC
// right) and its packet's format is right; a frame received while another
// runs or its reply is being sent is dropped and counted (not buffered).
// Bus: 32-bit data, word addresses (byte address / 4), sel = the record's
// byte enable; one access at a time, cyc and stb high together from a
// register until ack or err, low for at least a clock between accesses.
// A read the bus answers with err reads 0xFFFFFFFF.
// The buffer is BUF_BYTES bytes of block RAM (rtl/prim_ram_1r1w.sv: 2
// SB_RAM40_4K on iCE40 at 1024 bytes).
module uart_etherbone #(
  parameter int unsigned CLK_HZ    = 50_000_000,  // clock, Hz
  parameter int unsigned BAUD      = 115_200,     // bits a second (CLK_HZ / BAUD >= 8)
  parameter int          BUF_BYTES = 1024,        // frame buffer: a power of two, 16..4096
  parameter int          CNT_W     = 16           // monitoring counters' width (1..32)
) (
  input  logic             clk_i,
  input  logic             rst_ni,        // asynchronous, active low
  input  logic             rx_i,          // UART in (idle high; asynchronous)
  output logic             tx_o,          // UART out (idle high)
  // Wishbone B4 classic manager
  output logic             m_cyc_o,
  output logic             m_stb_o,
  output logic             m_we_o,
  output logic [29:0]      m_adr_o,       // word address
  output logic [31:0]      m_dat_o,
  output logic [3:0]       m_sel_o,
  input  logic [31:0]      m_dat_i,
  input  logic             m_ack_i,
  input  logic             m_err_i,
  // monitoring (wrapping counters)
  output logic [CNT_W-1:0] frames_run_o,  // frames that passed every check and ran
  output logic [CNT_W-1:0] frames_bad_o,  // frames dropped (CRC, framing, escape, length, format, busy)
  output logic [CNT_W-1:0] bus_errors_o,  // accesses the bus answered with err
  output logic             busy_o         // a frame runs or its reply is being sent
);
  localparam int unsigned DivU = BAUD == 0 ? 0 : (CLK_HZ + BAUD / 2) / BAUD;
  localparam int unsigned Off = DivU * BAUD > CLK_HZ ? DivU * BAUD - CLK_HZ : CLK_HZ - DivU * BAUD;
  localparam int Div = DivU;  // clocks a bit
`ifndef __ICARUS__
  if (BAUD == 0 || CLK_HZ / BAUD < 8) begin : g_bad_baud
    $error("uart_etherbone: parameters CLK_HZ and BAUD must be CLK_HZ / BAUD >= 8");
  end else if (Off > CLK_HZ / 50) begin : g_bad_rate
    $error("uart_etherbone: parameters CLK_HZ and BAUD must be within 2 %% of a whole DIV");
  end
  if (BUF_BYTES < 16 || BUF_BYTES > 4096 || (BUF_BYTES & (BUF_BYTES - 1)) != 0) begin : g_bad_buf
    $error("uart_etherbone: parameter BUF_BYTES must be a power of two, 16..4096");
  end
  if (CNT_W < 1 || CNT_W > 32) begin : g_bad_cnt_w
    $error("uart_etherbone: parameter CNT_W must be 1..32");
  end
`endif

  logic       rx_valid, rx_ferr;
  logic [7:0] rx_data;
  uart_rx #(.DIV(Div)) u_rx (
    .clk_i,
    .rst_ni,
    .rx_i,
    .valid_o(rx_valid),
    .data_o (rx_data),
    .ferr_o (rx_ferr)
  );

  logic       in_data, in_end, in_err;
  logic [7:0] in_byte;
  slip_rx u_slip_rx (
    .clk_i,
    .rst_ni,
    .valid_i(rx_valid),
    .data_i (rx_data),
    .ferr_i (rx_ferr),
    .data_o (in_data),
    .byte_o (in_byte),
    .end_o  (in_end),
    .err_o  (in_err)
  );

  logic       out_valid, out_end, out_ready;
  logic [7:0] out_byte;
  etherbone_engine #(
    .BUF_BYTES(BUF_BYTES),
    .CNT_W    (CNT_W)
  ) u_engine (
    .clk_i,
    .rst_ni,
    .in_data_i  (in_data),
    .in_byte_i  (in_byte),
    .in_end_i   (in_end),
    .in_err_i   (in_err),
    .out_valid_o(out_valid),
    .out_end_o  (out_end),
    .out_byte_o (out_byte),
    .out_ready_i(out_ready),
    .m_cyc_o,
    .m_stb_o,
    .m_we_o,
    .m_adr_o,
    .m_dat_o,
    .m_sel_o,
    .m_dat_i,
    .m_ack_i,
    .m_err_i,
    .frames_run_o,
    .frames_bad_o,
    .bus_errors_o,
    .busy_o
  );

  logic       tx_valid, tx_ready;
  logic [7:0] tx_data;
  slip_tx u_slip_tx (
    .clk_i,
    .rst_ni,
    .valid_i(out_valid),
    .end_i  (out_end),
    .data_i (out_byte),
    .ready_o(out_ready),
    .valid_o(tx_valid),
    .data_o (tx_data),
    .ready_i(tx_ready)
  );

  uart_tx #(.DIV(Div)) u_tx (
    .clk_i,
    .rst_ni,
    .valid_i(tx_valid),
    .data_i (tx_data),
    .ready_o(tx_ready),
    .tx_o
  );
endmodule

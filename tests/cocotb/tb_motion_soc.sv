// cocotb top: motion_soc behind AXI4-Lite (rtl/motion_soc_axil.sv, u_axil)
// and behind Wishbone (rtl/motion_soc_wb.sv, u_wb) side by side on one clock,
// so one Verilated build runs the tests on both buses (SOC_BUS picks the
// instance). The AXI4-Lite ports carry the names cocotbext-axi's
// AxiLiteBus.from_prefix(dut, "s_axil") looks for.
module tb_motion_soc #(
  parameter int FIFO_DEPTH = 8,
  parameter int PROFILE    = 0,  // 1: both instances with the feed profile (rtl/motion_soc.sv)
  parameter int TICK_W     = 10  // the profile's tick, 2^TICK_W clocks
) (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        probe_i,
  input  logic        estop_i,
  // AXI4-Lite
  input  logic        s_axil_awvalid,
  output logic        s_axil_awready,
  input  logic [9:0]  s_axil_awaddr,
  input  logic [2:0]  s_axil_awprot,
  input  logic        s_axil_wvalid,
  output logic        s_axil_wready,
  input  logic [31:0] s_axil_wdata,
  input  logic [3:0]  s_axil_wstrb,
  output logic        s_axil_bvalid,
  input  logic        s_axil_bready,
  output logic [1:0]  s_axil_bresp,
  input  logic        s_axil_arvalid,
  output logic        s_axil_arready,
  input  logic [9:0]  s_axil_araddr,
  input  logic [2:0]  s_axil_arprot,
  output logic        s_axil_rvalid,
  input  logic        s_axil_rready,
  output logic [31:0] s_axil_rdata,
  output logic [1:0]  s_axil_rresp,
  output logic [2:0]  axil_out_a_o,
  output logic [2:0]  axil_out_b_o,
  output logic        axil_irq_o,
  // Wishbone
  input  logic        wb_cyc_i,
  input  logic        wb_stb_i,
  input  logic        wb_we_i,
  input  logic [7:0]  wb_adr_i,
  input  logic [31:0] wb_dat_i,
  input  logic [3:0]  wb_sel_i,
  output logic [31:0] wb_dat_o,
  output logic        wb_ack_o,
  output logic        wb_err_o,
  output logic        wb_stall_o,
  output logic [2:0]  wb_out_a_o,
  output logic [2:0]  wb_out_b_o,
  output logic        wb_irq_o
);
  motion_soc_axil #(
    .FIFO_DEPTH(FIFO_DEPTH),
    .PROFILE   (PROFILE),
    .TICK_W    (TICK_W)
  ) u_axil (
    .clk_i, .rst_ni,
    .s_axil_awvalid_i(s_axil_awvalid), .s_axil_awready_o(s_axil_awready),
    .s_axil_awaddr_i (s_axil_awaddr),  .s_axil_awprot_i (s_axil_awprot),
    .s_axil_wvalid_i (s_axil_wvalid),  .s_axil_wready_o (s_axil_wready),
    .s_axil_wdata_i  (s_axil_wdata),   .s_axil_wstrb_i  (s_axil_wstrb),
    .s_axil_bvalid_o (s_axil_bvalid),  .s_axil_bready_i (s_axil_bready),
    .s_axil_bresp_o  (s_axil_bresp),
    .s_axil_arvalid_i(s_axil_arvalid), .s_axil_arready_o(s_axil_arready),
    .s_axil_araddr_i (s_axil_araddr),  .s_axil_arprot_i (s_axil_arprot),
    .s_axil_rvalid_o (s_axil_rvalid),  .s_axil_rready_i (s_axil_rready),
    .s_axil_rdata_o  (s_axil_rdata),   .s_axil_rresp_o  (s_axil_rresp),
    .probe_i, .estop_i,
    .out_a_o(axil_out_a_o), .out_b_o(axil_out_b_o), .irq_o(axil_irq_o)
  );

  motion_soc_wb #(
    .FIFO_DEPTH(FIFO_DEPTH),
    .PROFILE   (PROFILE),
    .TICK_W    (TICK_W)
  ) u_wb (
    .clk_i, .rst_ni, .wb_cyc_i, .wb_stb_i, .wb_we_i, .wb_adr_i, .wb_dat_i, .wb_sel_i,
    .wb_dat_o, .wb_ack_o, .wb_err_o, .wb_stall_o,
    .probe_i, .estop_i,
    .out_a_o(wb_out_a_o), .out_b_o(wb_out_b_o), .irq_o(wb_irq_o)
  );
endmodule

// motion_soc_axil: motion_soc (rtl/motion_soc.sv) behind the AXI4-Lite
// register block PeakRDL-regblock generates from rtl/regs/motion_soc.rdl
// (rtl/regs/gen/motion_soc_regs_axil.sv). 32-bit data, byte addresses of
// ADDR_W bits (the map's 10; the block decodes them all). An unmapped address,
// a read of a write-only register and a write of a read-only one answer
// SLVERR. The block accepts up to two transactions in flight and answers a
// read or a write in one clock after it takes it.
module motion_soc_axil #(
  parameter int AXES       = 3,
  parameter int ACC_W      = 32,
  parameter int COORD_W    = 24,
  parameter int OPS_W      = 28,
  parameter int POS_W      = 32,
  parameter int TIM_W      = 16,
  parameter int FEED_W     = 16,
  parameter int FIFO_DEPTH = 16,
  parameter int unsigned CLK_HZ = 50_000_000,
  // the feed profile (rtl/motion_soc.sv states these)
  parameter int PROFILE    = 0,
  parameter int SPD_W      = 48,
  parameter int TICK_W     = 10,
  parameter int LEN_W      = 10,
  parameter int PROF_LVL_W = 16,
  parameter int MV_OPS_W   = 28
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  // AXI4-Lite subordinate
  input  logic            s_axil_awvalid_i,
  output logic            s_axil_awready_o,
  input  logic [9:0]      s_axil_awaddr_i,
  input  logic [2:0]      s_axil_awprot_i,
  input  logic            s_axil_wvalid_i,
  output logic            s_axil_wready_o,
  input  logic [31:0]     s_axil_wdata_i,
  input  logic [3:0]      s_axil_wstrb_i,
  output logic            s_axil_bvalid_o,
  input  logic            s_axil_bready_i,
  output logic [1:0]      s_axil_bresp_o,
  input  logic            s_axil_arvalid_i,
  output logic            s_axil_arready_o,
  input  logic [9:0]      s_axil_araddr_i,
  input  logic [2:0]      s_axil_arprot_i,
  output logic            s_axil_rvalid_o,
  input  logic            s_axil_rready_i,
  output logic [31:0]     s_axil_rdata_o,
  output logic [1:0]      s_axil_rresp_o,
  // Machine
  input  logic            probe_i,
  input  logic            estop_i,
  output logic [AXES-1:0] out_a_o,
  output logic [AXES-1:0] out_b_o,
  output logic            irq_o
);
  motion_soc_regs_pkg::motion_soc_regs__in_t  hwif_in;
  motion_soc_regs_pkg::motion_soc_regs__out_t hwif_out;

  motion_soc_regs_axil u_regs (
    .clk           (clk_i),
    .arst_n        (rst_ni),
    .s_axil_awready(s_axil_awready_o),
    .s_axil_awvalid(s_axil_awvalid_i),
    .s_axil_awaddr (s_axil_awaddr_i),
    .s_axil_awprot (s_axil_awprot_i),
    .s_axil_wready (s_axil_wready_o),
    .s_axil_wvalid (s_axil_wvalid_i),
    .s_axil_wdata  (s_axil_wdata_i),
    .s_axil_wstrb  (s_axil_wstrb_i),
    .s_axil_bready (s_axil_bready_i),
    .s_axil_bvalid (s_axil_bvalid_o),
    .s_axil_bresp  (s_axil_bresp_o),
    .s_axil_arready(s_axil_arready_o),
    .s_axil_arvalid(s_axil_arvalid_i),
    .s_axil_araddr (s_axil_araddr_i),
    .s_axil_arprot (s_axil_arprot_i),
    .s_axil_rready (s_axil_rready_i),
    .s_axil_rvalid (s_axil_rvalid_o),
    .s_axil_rdata  (s_axil_rdata_o),
    .s_axil_rresp  (s_axil_rresp_o),
    .hwif_in       (hwif_in),
    .hwif_out      (hwif_out)
  );

  motion_soc #(
    .AXES      (AXES),
    .ACC_W     (ACC_W),
    .COORD_W   (COORD_W),
    .OPS_W     (OPS_W),
    .POS_W     (POS_W),
    .TIM_W     (TIM_W),
    .FEED_W    (FEED_W),
    .FIFO_DEPTH(FIFO_DEPTH),
    .BUS       (0),
    .CLK_HZ    (CLK_HZ),
    .PROFILE   (PROFILE),
    .SPD_W     (SPD_W),
    .TICK_W    (TICK_W),
    .LEN_W     (LEN_W),
    .PROF_LVL_W(PROF_LVL_W),
    .MV_OPS_W  (MV_OPS_W)
  ) u_soc (
    .clk_i,
    .rst_ni,
    .hwif_out_i(hwif_out),
    .hwif_in_o (hwif_in),
    .probe_i,
    .estop_i,
    .out_a_o,
    .out_b_o,
    .irq_o
  );
endmodule

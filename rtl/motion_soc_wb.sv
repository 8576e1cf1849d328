// motion_soc_wb: motion_soc (rtl/motion_soc.sv) behind the Wishbone B4
// register block PeakRDL-regblock generates from rtl/regs/motion_soc.rdl
// (rtl/regs/gen/motion_soc_regs_wb.sv). 32-bit data, word addresses (adr_i is
// the byte address / 4, as LiteX's Wishbone), 4 byte selects. Classic
// cycles (LiteX's): the block acknowledges in the clock of the request (ack_o,
// or err_o on an unmapped address, a read of a write-only or a write of a
// read-only register), combinationally from cyc_i & stb_i; stall_o stays 0.
// Tested with classic single cycles, back to back and with idle gaps
// (tests/cocotb/); pipelined masters are not tested.
module motion_soc_wb #(
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
  // Wishbone B4 subordinate
  input  logic            wb_cyc_i,
  input  logic            wb_stb_i,
  input  logic            wb_we_i,
  input  logic [7:0]      wb_adr_i,   // word address
  input  logic [31:0]     wb_dat_i,
  input  logic [3:0]      wb_sel_i,
  output logic [31:0]     wb_dat_o,
  output logic            wb_ack_o,
  output logic            wb_err_o,
  output logic            wb_stall_o,
  // Machine
  input  logic            probe_i,
  input  logic            estop_i,
  output logic [AXES-1:0] out_a_o,
  output logic [AXES-1:0] out_b_o,
  output logic            irq_o
);
  motion_soc_regs_pkg::motion_soc_regs__in_t  hwif_in;
  motion_soc_regs_pkg::motion_soc_regs__out_t hwif_out;
  logic ack, err;

  // regblock's Wishbone block takes stb alone as the request, and raises ack
  // with err: cyc gates the request and err masks ack here, as Wishbone B4
  // requires (ACK and ERR never together).
  assign wb_ack_o = ack && !err;
  assign wb_err_o = err;

  motion_soc_regs_wb u_regs (
    .clk     (clk_i),
    .arst_n  (rst_ni),
    .wb_cyc  (wb_cyc_i),
    .wb_stb  (wb_cyc_i && wb_stb_i),
    .wb_we   (wb_we_i),
    .wb_stall(wb_stall_o),
    .wb_adr  ({wb_adr_i, 2'b00}),
    .wb_odat (wb_dat_i),
    .wb_sel  (wb_sel_i),
    .wb_ack  (ack),
    .wb_err  (err),
    .wb_idat (wb_dat_o),
    .hwif_in (hwif_in),
    .hwif_out(hwif_out)
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
    .BUS       (1),
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

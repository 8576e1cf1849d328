// ppc_arc_prep: the PPC arc engine's command preparation, done when a
// command is taken into a buffer (combinational). From the arc's centre and
// end relative to the start (G-code I, J and the end offset) it forms what
// rtl/ppc_arc_engine.sv loads:
//   s = start - centre = -C,  e = end - centre = E - C  (PW = COORD_W + 1 bits)
//   E = end - start                                   (COORD_W bits)
// packed in prep_o (PREP_W = 4 * PW + 2 * COORD_W = 6 * COORD_W + 4 bits):
//   [0 +: PW] s_x, [PW +: PW] s_y, [2*PW +: PW] e_x, [3*PW +: PW] e_y,
//   [4*PW +: COORD_W] E_x, [4*PW+COORD_W +: COORD_W] E_y.
// Users: rtl/ppc_arc.sv and rtl/motion_top.sv; hls/ppc_arc_engine.h
// (PpcArcEngine::prepare) is the same in C++.
module ppc_arc_prep #(
  parameter int COORD_W = 24  // width of the signed coordinates (3..60)
) (
  input  logic [2*COORD_W-1:0] center_i,  // centre - start: x at [0 +: COORD_W], y above
  input  logic [2*COORD_W-1:0] end_i,     // end - start: x at [0 +: COORD_W], y above
  output logic [6*COORD_W+3:0] prep_o     // s, e, E as above
);
  // Parameter check at elaboration: Verilator and Yosys stop with the message
  // (Icarus 11 has no elaboration system tasks: it skips the check). The
  // range is rtl/ppc_arc_engine.sv's, which loads what this module prepares.
`ifndef __ICARUS__
  if (COORD_W < 3 || COORD_W > 60) begin : g_bad_coord_w
    $error("ppc_arc_prep: parameter COORD_W must be 3..60");
  end
`endif

  localparam int PW = COORD_W + 1;

  for (genvar i = 0; i < 2; i++) begin : g_axis
    logic [PW-1:0] c, d;  // centre and end offsets, sign extended
    assign c = {center_i[i*COORD_W+COORD_W-1], center_i[i*COORD_W +: COORD_W]};
    assign d = {end_i[i*COORD_W+COORD_W-1], end_i[i*COORD_W +: COORD_W]};
    assign prep_o[i*PW +: PW]                 = -c;
    assign prep_o[(2+i)*PW +: PW]             = d - c;
    assign prep_o[4*PW+i*COORD_W +: COORD_W]  = end_i[i*COORD_W +: COORD_W];
  end
endmodule

// step_encode: one axis's step output type, hostmot2's set, from the step/dir
// pair a core's step stage drives (rtl/step_stage.sv). Any core's step_o and
// dir_o can be put through it; motion_soc puts every axis through one, with
// the type a register (STEP_TYPE).
//
// type_i, taken while step_i is low (a pulse keeps the type it started with):
//   0 step/dir    a_o = step_i,             b_o = dir_i
//   1 up/down     a_o = step_i && !dir_i,   b_o = step_i && dir_i
//                 (a pulse on a_o for a positive step, on b_o for a negative)
//   2 quadrature  each rising step_i moves the phase p one state, up for a
//                 positive step, down for a negative, in every type (so a
//                 switch to quadrature starts where the position is, mod 4);
//                 (a_o, b_o) = (p[1] ^ p[0], p[1]): 00 10 11 01 forward, A
//                 leading, the reverse backward. Registers: glitch-free.
//   3             as 0
// Timing: types 0 and 1 are step_i and dir_i through gates, so the stage's
// timing is theirs (an up/down pulse lasts as the step pulse, pulses of an
// axis are STEP_SPACE apart, opposite ones DIR_HOLD + DIR_SETUP); a
// quadrature state lasts from one rising step to the next, at least
// STEP_LEN + STEP_SPACE clocks of the stage's settings, and its output changes
// one clock after the rising step.
// Formal: rtl/formal/step_encode_props.sv (scripts/formal.sh --blocks
// step_encode). Model: hls/step_encode.h, bit for bit.
module step_encode (
  input  logic       clk_i,
  input  logic       rst_ni,  // asynchronous, active low: step/dir type, phase 00
  input  logic [1:0] type_i,  // the type to use from the next pulse on (0..3)
  input  logic       step_i,  // the step stage's step_o (dir_i steady while it is high)
  input  logic       dir_i,   // the step stage's dir_o (1: negative)
  output logic       a_o,     // step, up or phase A
  output logic       b_o      // dir, down or phase B
);
  logic       step_q, step_d;    // step_i on the last clock (its rise moves the phase)
  logic [1:0] type_q, type_d;    // the type in use
  logic [1:0] phase_q, phase_d;  // the quadrature state p

  assign step_d  = step_i;
  assign type_d  = step_i ? type_q : type_i;
  assign phase_d = !(step_i && !step_q) ? phase_q : (dir_i ? phase_q - 2'd1 : phase_q + 2'd1);

  always_comb begin
    unique case (type_q)
      2'd1: begin
        a_o = step_i && !dir_i;
        b_o = step_i && dir_i;
      end
      2'd2: begin
        a_o = phase_q[1] ^ phase_q[0];
        b_o = phase_q[1];
      end
      default: begin
        a_o = step_i;
        b_o = dir_i;
      end
    endcase
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      step_q  <= 1'b0;
      type_q  <= 2'd0;
      phase_q <= 2'd0;
    end else begin
      step_q  <= step_d;
      type_q  <= type_d;
      phase_q <= phase_d;
    end
  end
endmodule

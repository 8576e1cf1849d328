// log_stepper: the odd-even third-order logarithmic-curve stepper of paper
// 001_46110e999325a38e.txt in hardware, driving X, Y, Z and A.
//
// command -> coarse engine (fixed point) -> segment register -> fine stage
// (dda_line: its buffer, DDA engine, feed and step/dir stage) -> step/dir
//
// Command: one curve A = a ln(1 + b X), in unsigned fixed-point words of
// INT_W integer and FRAC_W fraction bits (W = INT_W + FRAC_W):
//   cmd_b_i      b = 2 tan C / D1 (1/mm)
//   cmd_ab_i     a b = 2 tan S / D1 (rad/mm)
//   cmd_dl_i     dl, the instruction interpolation length (mm)
//   cmd_x_end_i  the stop rule: whole odd+even cycles until an even point
//                has X >= x_end (mm)
//   cmd_k_i      per axis (k_i at [i*W +: W]) steps per unit / 2^16: X, Y and
//                Z per mm of X (Y = X tan C and Z = X tan C sin r fold tan C
//                and sin r in), A per rad.
// The curve starts where the axes are. cmd_ready_o (a register) is high
// while no curve is being computed: the next curve's command is taken while
// the fine stage still runs the last segments of the previous one.
//
// Coarse engine: a micro-programmed datapath over a register file (the
// program is the `rom` function below, the same table as hls/log_stepper.h)
// with two units that run at the same time:
//  - the engine, one operation at a time: a two-stage multiplier that takes
//    MUL_K bits of its second operand a clock (MUL_CYC + 1 clocks, MUL_CYC =
//    ceil(W / MUL_K); the exact product truncated to the format), adds and
//    3 - (x << s) in one clock. A multiply marked in the program (sh = 1:
//    the next operation is a multiply that does not read its result) hands
//    over after MUL_CYC clocks: its last addition and its write happen on the
//    next multiply's first clock (the multiplier takes a new operation every
//    MUL_CYC clocks);
//  - the divider: a square root or a reciprocal by restoring digit
//    recurrence, two result bits a clock (radix 4: the two bits chosen by
//    three subtractions side by side, from the remainder r and root R so far
//    16 r + 4 bits of the radicand against 8 R + 1, 16 R + 4 and 24 R + 9,
//    4 r against d, 2 d and 3 d; the same bits as one a clock: a square root
//    takes SQRT_CYC = ceil(ceil((W + FRAC_W) / 2) / 2) clocks, a reciprocal
//    RECIP_CYC = ceil((FRAC_W + 1) / 2); an odd count of result bits starts
//    with a leading zero bit). The engine starts it in one clock (SQRT, RECIP: the
//    divider keeps its own copy of the operand) and goes on with the
//    operations that do not need its result (the previous even point's
//    lattice positions while u = 1 / sqrt(q^2 + ab^2) is computed, the rest
//    of N14 and N15 and the odd point while 1 / D is); GET waits for the
//    result and writes it to a register.
// Pipeline depth: the divider one operation deep beside the engine; the
// multiplier two stages (partial product, accumulate and write), with an
// initiation interval of MUL_CYC clocks between independent multiplies and
// MUL_CYC + 1 before a dependent one.
// models/log_stepper_model.h gives the arithmetic bit for bit, the
// normalised even step (one reciprocal for both of Eq. 14's and Eq. 15's
// ratios) and the accepted commands. A point's lattice positions are
// rounded from its absolute X and A (pos = round(x k 2^16)), so rounding
// never accumulates; the segment delta is the difference to the previous
// point's (all four axes move forward: every delta is >= 0).
//
// Clocks per odd+even cycle (two points), nothing waiting, with M =
// MUL_CYC + 1 (25 multiplies, 15 of them handing over a clock early; the
// three GETs' waits are the max terms):
//   25 M + 1 + max(1, SQRT_CYC + 2 - 2 M) + max(1, RECIP_CYC + 1 - 2 M)
//        + max(1, RECIP_CYC - 1 - 7 M)
// (log_stepper_n4: 144, 72 a point; log_stepper_edge: 183).
//
// Pipeline: the coarse engine computes the next point while the fine stage
// runs the previous ones. Between them sit the segment register and the fine
// stage's one-entry buffer (a two-entry FIFO): the engine stops at a point
// until the segment register is free. The fine stage waits on the coarse
// engine only when a segment runs fewer clocks than the engine needs for a
// point: a segment whose largest delta has n bits runs 2^n DDA iterations,
// 2^n 2^FEED_W / feed_i clocks.
//
// Fine stage: dda_line (rtl/dda_line.sv) with AXES = 4, ACC_W = SEG_W and
// half preload: each segment is a DDA line, exact at its end, within the
// DDA bound of it in between. Its step/dir stage, position counters, feed
// and timing inputs are this core's.
//
// Abort: abort_i high at a clock edge stops the coarse engine, empties the
// segment register and aborts the fine stage (rtl/dda_line.sv: the running
// segment ends, its buffer is dropped, a pulse already high keeps its
// length); a command offered on that edge is not taken. No done_o for the
// aborted curve. The core takes commands again from the next clock on.
//
// Status: busy_o while a curve is being computed, a segment waits or the
// fine stage is busy; done_o pulses for one clock with the last iteration of
// a curve's last segment; step_o, dir_o and pos_o are the fine stage's.
module log_stepper #(
  parameter int AXES   = 4,   // X, Y, Z, A (fixed: must be 4)
  parameter int INT_W  = 10,  // integer bits of the coarse engine's words (>= 4; INT_W + FRAC_W <= 62)
  parameter int FRAC_W = 30,  // fraction bits of the coarse engine's words (>= 18)
  parameter int MUL_K  = 10,  // multiplier bits per clock (1..INT_W + FRAC_W)
  parameter int SEG_W  = 16,  // width of the signed segment deltas, the fine stage's ACC_W (2..POS_W)
  parameter int POS_W  = 32,  // position counter width (SEG_W..62)
  parameter int TIM_W  = 16,  // step/dir timing settings width (>= 2)
  parameter int FEED_W = 16   // feed accumulator width (>= 1)
) (
  input  logic                  clk_i,               // clock
  input  logic                  rst_ni,              // asynchronous, active low
  // Command stream: one curve per command
  input  logic                  cmd_valid_i,         // a command is offered on cmd_*_i
  output logic                  cmd_ready_o,         // the buffer is free: an offered command is taken
  input  logic [INT_W+FRAC_W-1:0]      cmd_b_i,      // b (1/mm)
  input  logic [INT_W+FRAC_W-1:0]      cmd_ab_i,     // a b (rad/mm)
  input  logic [INT_W+FRAC_W-1:0]      cmd_dl_i,     // dl (mm)
  input  logic [INT_W+FRAC_W-1:0]      cmd_x_end_i,  // stop at an even point with X >= x_end (mm)
  input  logic [4*(INT_W+FRAC_W)-1:0]  cmd_k_i,      // steps per unit / 2^16, axis i at [i*W +: W]
  // Run-time settings
  input  logic [FEED_W:0]       feed_i,              // operations per clock = feed_i / 2^FEED_W
  input  logic [TIM_W-1:0]      step_len_i,          // step pulse length, clocks (0 acts as 1)
  input  logic [TIM_W-1:0]      step_space_i,        // min low time between pulses, clocks
  input  logic [TIM_W-1:0]      dir_setup_i,         // dir stable before a step rises, clocks
  input  logic [TIM_W-1:0]      dir_hold_i,          // dir stable after a step falls, clocks
  input  logic                  abort_i,  // end the curve, drop its segments (one clock)
  // Step/dir and status
  output logic [AXES-1:0]       step_o,              // step pulses, axis i in bit i
  output logic [AXES-1:0]       dir_o,               // 1: negative motion
  output logic [AXES*POS_W-1:0] pos_o,               // signed positions, axis i at [i*POS_W +: POS_W]
  output logic                  busy_o,              // a command buffered or running, or a pulse high
  output logic                  done_o               // one clock per completed command
);
  localparam int W         = INT_W + FRAC_W;
  localparam int MulCyc    = (W + MUL_K - 1) / MUL_K;
  localparam int SqrtBits  = (W + FRAC_W + 1) / 2;  // root bits of sqrt(x 2^F)
  localparam int RecipBits = FRAC_W + 1;  // quotient bits of 2^2F / x
  localparam int SqrtCyc   = (SqrtBits + 1) / 2;  // two bits a clock
  localparam int RecipCyc  = (RecipBits + 1) / 2;
  localparam int RecipPad  = 2 * RecipCyc - RecipBits;  // a leading zero quotient bit (0 or 1)
  localparam int RadW      = 4 * SqrtCyc;
  localparam int RemW      = (SqrtBits + 3 > W + 1) ? SqrtBits + 3 : W + 1;
  localparam int ProdW     = 2 * W + 1;
  localparam int PosSh     = 2 * FRAC_W - 16;  // models::kLogPosShift = 16
  localparam int NRegs     = 22;
  localparam int CycleStart = 2;
  localparam int RegK0     = 6;  // RK0, as an int for the load loop

  // ---------------------------------------------------------------------------
  // Parameter checks at elaboration: Verilator and Yosys stop with the
  // message (Icarus 11 has no elaboration system tasks: it skips them). The
  // ranges are the HLS face's (hls/log_stepper.h), and so the lockstep
  // verification's; the operation counter (cnt_q, 7 bits) needs every
  // operation's clocks below 128, which W <= 62 gives.
`ifndef __ICARUS__
  if (AXES != 4) begin : g_bad_axes
    $error("log_stepper: parameter AXES must be 4");
  end
  if (INT_W < 4) begin : g_bad_int_w
    $error("log_stepper: parameter INT_W must be >= 4");
  end
  if (FRAC_W < 18) begin : g_bad_frac_w
    $error("log_stepper: parameter FRAC_W must be >= 18");
  end
  if (W > 62) begin : g_bad_w
    $error("log_stepper: parameters INT_W + FRAC_W must be <= 62");
  end
  if (MUL_K < 1 || MUL_K > W) begin : g_bad_mul_k
    $error("log_stepper: parameter MUL_K must be 1..INT_W + FRAC_W");
  end
  if (SEG_W < 2 || SEG_W > POS_W) begin : g_bad_seg_w
    $error("log_stepper: parameter SEG_W must be 2..POS_W");
  end
  if (POS_W > 62) begin : g_bad_pos_w
    $error("log_stepper: parameter POS_W must be <= 62");
  end
  if (TIM_W < 2) begin : g_bad_tim_w
    $error("log_stepper: parameter TIM_W must be >= 2");
  end
  if (FEED_W < 1) begin : g_bad_feed_w
    $error("log_stepper: parameter FEED_W must be >= 1");
  end
`endif

  // Operations and registers (hls/log_stepper.h, namespace log_uop).
  localparam logic [2:0] OpMul = 3'd0, OpSqrt = 3'd1, OpRecip = 3'd2, OpAdd = 3'd3,
                         OpRsb = 3'd4, OpPos = 3'd5, OpEmit = 3'd6, OpGet = 3'd7;
  localparam logic [4:0] ROne = 5'd0, RThree = 5'd1, RB = 5'd2, RAb = 5'd3, RDl = 5'd4,
                         RXEnd = 5'd5, RK0 = 5'd6, RK1 = 5'd7, RK2 = 5'd8, RK3 = 5'd9,
                         RAb2 = 5'd10, RBdl = 5'd11, RX = 5'd12, RA = 5'd13, RQ = 5'd14,
                         RU = 5'd15, RDx = 5'd16, RDa = 5'd17, RDp = 5'd18, RE = 5'd19,
                         RT0 = 5'd20, RT1 = 5'd21;

  // ---------------------------------------------------------------------------
  // Program ROM (`rom`), read one clock ahead: dec_q holds the entry of
  // pc_q, registered from the entry of pc_d, so no clock's path starts with
  // the decode. (Pipeline registers only: the pins see no difference.)
  logic [5:0]  pc_q, pc_d;
  logic [19:0] ent_d;  // rom(pc_d): {op, dst, src1, src2, sh}
  logic [9:0]  dec_q, dec_d;  // {op, dst, sh} of pc_q (the sources go to the operand registers)
  logic [2:0]  op;
  logic [4:0]  dst;
  logic [1:0]  sh;
  logic [4:0]  src1_d, src2_d;

  function automatic logic [19:0] rom(input logic [5:0] pc);
    logic [2:0] f_op;
    logic [4:0] f_dst, f_s1, f_s2;
    logic [1:0] f_sh;
    f_op = OpMul; f_dst = RT0; f_s1 = ROne; f_s2 = ROne; f_sh = 2'd0;
    case (pc)
      6'd0: begin f_op = OpMul; f_dst = RAb2; f_s1 = RAb; f_s2 = RAb; end  // ab^2
      6'd1: begin f_op = OpMul; f_dst = RBdl; f_s1 = RB; f_s2 = RDl; end  // b dl
      6'd2: begin f_op = OpMul; f_dst = RT0; f_s1 = RB; f_s2 = RX; end  // b X0
      6'd3: begin f_op = OpAdd; f_dst = RQ; f_s1 = RT0; f_s2 = ROne; end  // q = 1 + b X0
      6'd4: begin f_op = OpMul; f_dst = RT0; f_s1 = RQ; f_s2 = RQ; end  // q^2
      6'd5: begin f_op = OpAdd; f_dst = RT0; f_s1 = RT0; f_s2 = RAb2; end  // q^2 + ab^2
      6'd6: begin f_op = OpSqrt; f_s1 = RT0; end  // start: root
      6'd7: begin f_op = OpPos; f_dst = 5'd0; f_s1 = RX; f_s2 = RK0; f_sh = 2'd1; end  // last cycle's even point: X steps
      6'd8: begin f_op = OpPos; f_dst = 5'd1; f_s1 = RX; f_s2 = RK1; end  // Y steps
      6'd9: begin f_op = OpGet; f_dst = RT0; end  // root
      6'd10: begin f_op = OpRecip; f_s1 = RT0; end  // start: u = 1 / root
      6'd11: begin f_op = OpPos; f_dst = 5'd2; f_s1 = RX; f_s2 = RK2; f_sh = 2'd1; end  // Z steps
      6'd12: begin f_op = OpPos; f_dst = 5'd3; f_s1 = RA; f_s2 = RK3; end  // A steps
      6'd13: begin f_op = OpEmit; f_sh = 2'd1; end  // even point (none in the first cycle); X2 >= x_end: the last
      6'd14: begin f_op = OpGet; f_dst = RU; end  // u
      6'd15: begin f_op = OpMul; f_dst = RT0; f_s1 = RQ; f_s2 = RU; f_sh = 2'd1; end  // q u
      6'd16: begin f_op = OpMul; f_dst = RT1; f_s1 = RAb; f_s2 = RU; f_sh = 2'd1; end  // ab u
      6'd17: begin f_op = OpMul; f_dst = RDp; f_s1 = RBdl; f_s2 = RU; f_sh = 2'd1; end  // d' = dA10 / a
      6'd18: begin f_op = OpMul; f_dst = RE; f_s1 = RT1; f_s2 = RT1; f_sh = 2'd1; end  // s2 = sin^2 theta
      6'd19: begin f_op = OpMul; f_dst = RDx; f_s1 = RDl; f_s2 = RT0; f_sh = 2'd1; end  // dX10
      6'd20: begin f_op = OpMul; f_dst = RE; f_s1 = RDp; f_s2 = RE; f_sh = 2'd1; end  // e = d' s2
      6'd21: begin f_op = OpMul; f_dst = RDa; f_s1 = RDl; f_s2 = RT1; end  // dA10
      6'd22: begin f_op = OpRsb; f_dst = RT0; f_s1 = RDp; f_sh = 2'd2; end  // 3 - 4d'
      6'd23: begin f_op = OpMul; f_dst = RT1; f_s1 = RE; f_s2 = RT0; end  // e (3 - 4d')
      6'd24: begin f_op = OpRsb; f_dst = RQ; f_s1 = RT1; f_sh = 2'd1; end  // D
      6'd25: begin f_op = OpRecip; f_s1 = RQ; end  // start: 1 / D
      6'd26: begin f_op = OpMul; f_dst = RT1; f_s1 = RDp; f_s2 = RE; f_sh = 2'd1; end  // d' e
      6'd27: begin f_op = OpMul; f_dst = RT0; f_s1 = RDp; f_s2 = RT0; end  // d' (3 - 4d')
      6'd28: begin f_op = OpRsb; f_dst = RU; f_s1 = RT0; f_sh = 2'd1; end  // N15
      6'd29: begin f_op = OpRsb; f_dst = RT0; f_s1 = RDp; f_sh = 2'd3; end  // 3 - 8d'
      6'd30: begin f_op = OpMul; f_dst = RT0; f_s1 = RT1; f_s2 = RT0; end  // d' e (3 - 8d')
      6'd31: begin f_op = OpRsb; f_dst = RDp; f_s1 = RT0; f_sh = 2'd1; end  // N14
      6'd32: begin f_op = OpAdd; f_dst = RX; f_s1 = RX; f_s2 = RDx; end  // X1
      6'd33: begin f_op = OpAdd; f_dst = RA; f_s1 = RA; f_s2 = RDa; end  // A1
      6'd34: begin f_op = OpPos; f_dst = 5'd0; f_s1 = RX; f_s2 = RK0; f_sh = 2'd1; end  // X steps
      6'd35: begin f_op = OpPos; f_dst = 5'd1; f_s1 = RX; f_s2 = RK1; f_sh = 2'd1; end  // Y steps
      6'd36: begin f_op = OpPos; f_dst = 5'd2; f_s1 = RX; f_s2 = RK2; f_sh = 2'd1; end  // Z steps
      6'd37: begin f_op = OpPos; f_dst = 5'd3; f_s1 = RA; f_s2 = RK3; end  // A steps
      6'd38: begin f_op = OpEmit; end  // odd point
      6'd39: begin f_op = OpGet; f_dst = RT0; end  // 1 / D
      6'd40: begin f_op = OpMul; f_dst = RE; f_s1 = RDp; f_s2 = RT0; f_sh = 2'd1; end  // N14 / D
      6'd41: begin f_op = OpMul; f_dst = RQ; f_s1 = RU; f_s2 = RT0; f_sh = 2'd1; end  // N15 / D
      6'd42: begin f_op = OpMul; f_dst = RDx; f_s1 = RE; f_s2 = RDx; f_sh = 2'd1; end  // dX21 = (N14 / D) dX10
      6'd43: begin f_op = OpMul; f_dst = RDa; f_s1 = RQ; f_s2 = RDa; end  // dA21 = (N15 / D) dA10
      6'd44: begin f_op = OpAdd; f_dst = RX; f_s1 = RX; f_s2 = RDx; end  // X2
      6'd45: begin f_op = OpAdd; f_dst = RA; f_s1 = RA; f_s2 = RDa; f_sh = 2'd1; end  // A2; the next cycle
      default: ;
    endcase
    rom = {f_op, f_dst, f_s1, f_s2, f_sh};
  endfunction

  assign op     = dec_q[9:7];
  assign dst    = dec_q[6:2];
  assign sh     = dec_q[1:0];
  assign ent_d  = rom(pc_d);
  assign dec_d  = {ent_d[19:12], ent_d[1:0]};
  assign src1_d = ent_d[11:7];
  assign src2_d = ent_d[6:2];

  // ---------------------------------------------------------------------------
  // Register file: registers 2..NRegs-1, flat (W bits each); 0 and 1 read as
  // the constants 1.0 and 3.0.
  logic [NRegs*W-1:0] reg_q, reg_d;
  logic [W-1:0]       s1_q, s2_q;  // operand registers

  // (Assigned to its name, not `return`: Yosys 0.23 has no return statement.)
  function automatic logic [W-1:0] rd(input logic [NRegs*W-1:0] regs, input logic [4:0] r);
    if (r == ROne) rd = W'(1) << FRAC_W;
    else if (r == RThree) rd = W'(3) << FRAC_W;
    else rd = regs[r*W +: W];
  endfunction

  // The two operand registers: s1_q/s2_q hold register src1/src2 of the entry
  // at pc_q, read one clock ahead (from the register file as the command
  // load leaves it, with the write port's value bypassed) by AND-OR selects.
  // (A variable part-select `reg_q[src*W +: W]` made Yosys build a 1232-bit
  // barrel shifter per port.)
  logic [NRegs*W-1:0] reg_ld;  // reg_q with this clock's command load
  logic [W-1:0]       s1_d, s2_d, rd1, rd2;

  function automatic logic [W-1:0] rd_any(input logic [NRegs*W-1:0] regs, input logic [4:0] r);
    logic [W-1:0] v;
    v = ({W{r == ROne}} & (W'(1) << FRAC_W)) | ({W{r == RThree}} & (W'(3) << FRAC_W));
    for (int i = 2; i < NRegs; i++) v = v | ({W{r == 5'(i)}} & regs[i*W +: W]);
    rd_any = v;
  endfunction

  assign rd1  = rd_any(reg_ld, src1_d);
  assign rd2  = rd_any(reg_ld, src2_d);
  assign s1_d = (we && wdst == src1_d) ? wdata : rd1;
  assign s2_d = (we && wdst == src2_d) ? wdata : rd2;

  // ---------------------------------------------------------------------------
  // Datapath units (their state: acc_q, rem_q, res_q).
  logic                    act_q, act_d;
  logic [6:0]              cnt_q, cnt_d;
  logic [ProdW-1:0]        acc_q, acc_d, acc_sum, acc_full, pp_q, pp_d, pos_round;
  // A multiply's write one clock after its hand-over (sh = 1): pending, to
  // a lattice position (POS), and to which register or axis.
  logic                    wb_q, wb_d, wb_pos_q, wb_pos_d;
  logic [4:0]              wb_dst_q, wb_dst_d, wdst;
  logic                    ovl;  // the multiply at pc_q hands over early
  logic                    first_q, first_d;  // cnt_q == 0, registered from cnt_d (a unit's first clock)
  logic [MUL_K-1:0]        digit_q;  // digit cnt_q of s2 (registered)
  logic [W+MUL_K-1:0]      prod;   // s1 times one digit
  logic [RemW-1:0]         rem_q, rem_d, res_q, res_d;
  // The divider's three trial subtractions (CW bits) and their borrows: the
  // differences' top bits and the root's and the square-root remainder's
  // top bits are zero (the remainder stays below the divisor and below
  // 2 R + 1, R below 2^SqrtBits): not read.
  localparam int CW = RemW + 2;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [CW-1:0]           dv_a, dv_t1, dv_t2, dv_t3, dv_r1, dv_r2, dv_r3, dv_r;
  logic [RemW:0]           m3_q, m3_d;  // 3 R + 1 (square root) or 3 d (reciprocal)
  /* verilator lint_on UNUSEDSIGNAL */
  logic                    dv_b1, dv_b2, dv_b3;
  logic [1:0]              dv_qd;  // the two result bits
  // The divider: running, square root (else reciprocal), its clock, its
  // divisor (the reciprocal's operand).
  logic                    dv_act_q, dv_act_d, dv_sqrt_q, dv_sqrt_d, dv_start, dv_last;
  logic [5:0]              dv_cnt_q, dv_cnt_d;
  logic [W-1:0]            dvs_q, dvs_d;
  logic                    even_q, even_d;  // an even point waits for its positions and EMIT
  // The square root's radicand s1 2^FRAC_W, top digits first: loaded from
  // the operand at the start, shifted by two digits on each clock of the
  // divider (a shift register instead of a select by the counter).
  logic [RadW-1:0]         rad_q, rad_d;
  logic                    cnt_last;
  logic [4*POS_W-1:0]      lnew_q, lnew_d, lprev_q, lprev_d;
  // Segment register and the tags of the segments in the fine stage.
  logic [4*SEG_W-1:0]      seg_q, seg_d;
  logic                    seg_valid_q, seg_valid_d, seg_last_q, seg_last_d;
  logic [1:0]              tag_n_q, tag_n_d;
  logic [2:0]              tag_q, tag_d;  // at most three: dda_line's two buffer entries and its engine
  logic                    emit_last;
  logic                    cmd_take;

  // Fine stage outputs.
  logic                    fine_ready, fine_busy, fine_done;

  assign dv_start  = act_q && !abort_i && (op == OpSqrt || op == OpRecip);
  assign dv_last   = dv_cnt_q == (dv_sqrt_q ? 6'(SqrtCyc - 1) : 6'(RecipCyc - 1));
  assign rad_d     = dv_start ? RadW'(s1_q) << FRAC_W : rad_q << 4;
  // Multiplier: digit cnt of s2 times s1, placed at bit MUL_K cnt. The digit
  // and the place (one-hot) are registered one clock ahead, from the next
  // operand and count, so the product starts at registers. (AND-OR selects:
  // a shift by MUL_K * cnt_q made Yosys build barrel shifters for every value
  // of the 7-bit counter.)
  logic [MUL_K-1:0]  digit_d;
  logic [MulCyc-1:0] place_q, place_d;
  always_comb begin
    digit_d = '0;
    for (int j = 0; j < MulCyc; j++) begin
      place_d[j] = cnt_d == 7'(j);
      // Digit 0 (a new operation's first) from the next operand, the write
      // port's value bypassed; the others from the operand register, which
      // holds the same value while the operation runs (nothing writes an
      // operand of a running operation): the multiplier's carry chain then
      // feeds only digit 0.
      digit_d    = digit_d | ({MUL_K{place_d[j]}} & MUL_K'(((j == 0) ? s2_d : s2_q) >> (MUL_K * j)));
    end
    pp_d = '0;
    for (int j = 0; j < MulCyc; j++) begin
      pp_d = pp_d | ({ProdW{place_q[j]}} & (ProdW'(prod) << (MUL_K * j)));
    end
  end
  assign prod      = s1_q * digit_q;
  assign first_d   = cnt_d == '0;
  // Two stages: pp_q registers s1 digit_cnt << MUL_K cnt (cnt < MulCyc), the
  // accumulator adds it a clock later; at cnt = MulCyc, acc_full is the
  // product (or, handed over, on the next multiply's first clock).
  // A position's product (OpPos) starts the accumulator at its rounding
  // constant 2^(PosSh - 1) instead of 0, so acc_full is already rounded: the
  // position is acc_full >> PosSh, with no second add behind the
  // accumulator's (the other products start at 0, the constant never reaches
  // the register file: an OpPos product is written to lnew only).
  assign acc_full  = acc_q + pp_q;
  assign acc_sum   = !first_q ? acc_full : (op == OpPos) ? ProdW'(1) << (PosSh - 1) : '0;
  assign pos_round = acc_full;
  assign ovl       = (op == OpMul || op == OpPos) && sh[0];
  // X >= x_end, registered from the registers (X changes only on its ADDs,
  // pc 32 and 44, nine operations or more before the even EMIT reads it,
  // pc 13): the stop rule's compare is off the EMIT -> pc path and off the
  // write port's path (the multiplier's final add).
  logic past_end_q, past_end_d;
  assign past_end_d = reg_q[RX*W +: W] >= reg_q[RXEnd*W +: W];
  assign emit_last = sh[0] && past_end_q;
  assign cmd_take  = cmd_valid_i && !act_q && !abort_i;

  // Two result bits a clock (radix 4), the three trials side by side:
  //   square root, remainder r and root R so far, a = 16 r + the next two
  //   digits of n = s1 2^FRAC_W (the top four bits of rad_q), trials
  //   q (8 R + q) for q = 1, 2, 3: 8 R + 1, 16 R + 4, 8 (3 R + 1) + 1;
  //   reciprocal, a = 4 r, trials d, 2 d, 3 d.
  // The two bits are the largest q whose trial is <= a, the new remainder
  // a minus it: the same as two radix-2 steps.
  always_comb begin
    if (dv_sqrt_q) begin
      dv_a  = {rem_q[CW-5:0], rad_q[RadW-1 -: 4]};
      dv_t1 = {res_q[CW-4:0], 3'b001};
      dv_t2 = {res_q[CW-5:0], 4'b0100};
      dv_t3 = {m3_q[CW-4:0], 3'b001};
    end else begin
      dv_a  = {rem_q, 2'b00};
      dv_t1 = CW'(dvs_q);
      dv_t2 = CW'({dvs_q, 1'b0});
      dv_t3 = CW'(m3_q);
    end
    {dv_b1, dv_r1} = {1'b0, dv_a} - {1'b0, dv_t1};
    {dv_b2, dv_r2} = {1'b0, dv_a} - {1'b0, dv_t2};
    {dv_b3, dv_r3} = {1'b0, dv_a} - {1'b0, dv_t3};
    if (!dv_b3) begin
      dv_qd = 2'd3;
      dv_r  = dv_r3;
    end else if (!dv_b2) begin
      dv_qd = 2'd2;
      dv_r  = dv_r2;
    end else if (!dv_b1) begin
      dv_qd = 2'd1;
      dv_r  = dv_r1;
    end else begin
      dv_qd = 2'd0;
      dv_r  = dv_a;
    end
  end

  // The divider's registers: the start loads the operand and the initial
  // remainder; each running clock makes two result bits.
  always_comb begin
    dv_act_d  = dv_act_q;
    dv_sqrt_d = dv_sqrt_q;
    dv_cnt_d  = dv_cnt_q;
    dvs_d     = dvs_q;
    m3_d      = m3_q;
    rem_d     = rem_q;
    res_d     = res_q;
    if (abort_i) begin
      dv_act_d = 1'b0;
    end else if (dv_start) begin
      dv_act_d  = 1'b1;
      dv_sqrt_d = op == OpSqrt;
      dv_cnt_d  = '0;
      dvs_d     = s1_q;
      m3_d      = (op == OpSqrt) ? (RemW+1)'(1) : (RemW+1)'(s1_q) + (RemW+1)'({s1_q, 1'b0});
      rem_d     = (op == OpSqrt) ? '0 : RemW'(1) << (FRAC_W - 1 - RecipPad);
      res_d     = '0;
    end else if (dv_act_q) begin
      rem_d    = dv_r[RemW-1:0];
      res_d    = {res_q[RemW-3:0], dv_qd};
      // 3 R' + 1 with R' = 4 R + q: 4 (3 R + 1) + 3 q - 3.
      if (dv_sqrt_q) begin
        unique case (dv_qd)
          2'd0: m3_d = {m3_q[RemW-2:0], 2'b00} - (RemW+1)'(3);
          2'd1: m3_d = {m3_q[RemW-2:0], 2'b00};
          2'd2: m3_d = {m3_q[RemW-2:0], 2'b00} + (RemW+1)'(3);
          default: m3_d = {m3_q[RemW-2:0], 2'b00} + (RemW+1)'(6);
        endcase
      end
      dv_cnt_d = dv_cnt_q + 6'd1;
      if (dv_last) dv_act_d = 1'b0;
    end
  end

  // The one register-file write port: what the operation at pc_q writes on
  // its last clock, or a handed-over multiply's product (then the operation
  // at pc_q is a multiply on its first clock: it writes nothing). (One port
  // for every operation: a variable-index write per operation made Yosys
  // build a 1232-bit shifter for each.)
  logic [W-1:0] wdata;
  logic         we;
  always_comb begin
    if (wb_q) begin
      wdata = W'(acc_full >> FRAC_W);
    end else begin
      unique case (op)
        OpMul:          wdata = W'(acc_full >> FRAC_W);
        OpGet:          wdata = W'(res_q);
        OpAdd:          wdata = s1_q + s2_q;
        OpRsb:          wdata = rd(reg_q, RThree) - (s1_q << sh);
        default:        wdata = '0;
      endcase
    end
    wdst = wb_q ? wb_dst_q : dst;
    we = act_q && !abort_i &&
         ((wb_q && !wb_pos_q) ||
          (cnt_last && !ovl && (op == OpMul || op == OpGet || op == OpAdd || op == OpRsb)));
  end

  // Register i: the command's word on a take (B..K3; X and A restart at 0),
  // the write port's value when it names i.
  for (genvar i = 2; i < NRegs; i++) begin : g_reg
    logic [W-1:0] load;
    logic         loads;
    if (5'(i) == RB) begin : g_b
      assign load = cmd_b_i;
    end else if (5'(i) == RAb) begin : g_ab
      assign load = cmd_ab_i;
    end else if (5'(i) == RDl) begin : g_dl
      assign load = cmd_dl_i;
    end else if (5'(i) == RXEnd) begin : g_x_end
      assign load = cmd_x_end_i;
    end else if (i >= RegK0 && i < RegK0 + 4) begin : g_k
      assign load = cmd_k_i[(i - RegK0)*W +: W];
    end else begin : g_zero
      assign load = '0;
    end
    assign loads = (i <= RegK0 + 3) || 5'(i) == RX || 5'(i) == RA;
    assign reg_ld[i*W +: W] = (cmd_take && loads) ? load : reg_q[i*W +: W];
    assign reg_d[i*W +: W]  = (we && wdst == 5'(i)) ? wdata : reg_ld[i*W +: W];
  end
  assign reg_ld[2*W-1:0] = '0;  // registers 0 and 1 are constants, never stored
  assign reg_d[2*W-1:0]  = '0;

  always_comb begin
    act_d       = act_q;
    pc_d        = pc_q;
    cnt_d       = cnt_q;
    acc_d       = acc_q;
    wb_d        = 1'b0;
    wb_pos_d    = wb_pos_q;
    wb_dst_d    = wb_dst_q;
    even_d      = even_q;
    lnew_d      = lnew_q;
    lprev_d     = lprev_q;
    seg_d       = seg_q;
    seg_last_d  = seg_last_q;
    seg_valid_d = seg_valid_q && !(fine_ready || abort_i);
    cnt_last    = 1'b0;
    unique case (op)
      OpMul, OpPos:    cnt_last = (cnt_q == (sh[0] ? 7'(MulCyc - 1) : 7'(MulCyc)));
      OpGet:           cnt_last = !dv_act_q;
      OpSqrt, OpRecip, OpAdd, OpRsb: cnt_last = 1'b1;
      default:         cnt_last = 1'b0;
    endcase
    if (abort_i) begin
      act_d = 1'b0;
    end else if (act_q) begin
      if (op == OpMul || op == OpPos) acc_d = acc_sum;
      if (op == OpPos && cnt_last && !ovl)
        lnew_d[dst[1:0]*POS_W +: POS_W] = POS_W'(pos_round >> PosSh);
      if (wb_q && wb_pos_q)
        lnew_d[wb_dst_q[1:0]*POS_W +: POS_W] = POS_W'(pos_round >> PosSh);
      if (ovl && cnt_last) begin
        wb_d     = 1'b1;
        wb_pos_d = op == OpPos;
        wb_dst_d = dst;
      end
      if (op == OpEmit) begin
        if (sh[0] && !even_q) begin
          pc_d = pc_q + 6'd1;  // the first cycle: no even point yet
        end else if (!seg_valid_q) begin
          for (int i = 0; i < 4; i++)
            seg_d[i*SEG_W +: SEG_W] =
                SEG_W'(lnew_q[i*POS_W +: POS_W] - lprev_q[i*POS_W +: POS_W]);
          lprev_d     = lnew_q;
          seg_valid_d = 1'b1;
          seg_last_d  = emit_last;
          even_d      = 1'b0;
          if (emit_last) act_d = 1'b0;
          else pc_d = pc_q + 6'd1;
        end
      end else if (cnt_last) begin
        // The last ADD of a cycle (sh = 1) computes its even point and goes
        // to the next cycle.
        if (op == OpAdd && sh[0]) begin
          pc_d   = 6'(CycleStart);
          even_d = 1'b1;
        end else begin
          pc_d = pc_q + 6'd1;
        end
        cnt_d = '0;
      end else begin
        cnt_d = cnt_q + 7'd1;
      end
    end else if (cmd_take) begin
      act_d   = 1'b1;
      pc_d    = '0;
      cnt_d   = '0;
      even_d  = 1'b0;
      lprev_d = '0;
    end
  end

  // Tags: does the segment end its curve; oldest (tag_q[0]) first.
  logic [1:0] n;
  logic [2:0] t;
  always_comb begin
    n = tag_n_q;
    t = tag_q;
    if (fine_done) begin
      t = {1'b0, t[2:1]};
      n = n - 2'd1;
    end
    if (seg_valid_q && fine_ready) begin
      case (n)
        2'd0: t[0] = seg_last_q;
        2'd1: t[1] = seg_last_q;
        default: t[2] = seg_last_q;
      endcase
      n = n + 2'd1;
    end
    tag_n_d = abort_i ? 2'd0 : n;
    tag_d   = abort_i ? 3'b000 : t;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      act_q       <= 1'b0;
      pc_q        <= '0;
      cnt_q       <= '0;
      reg_q       <= '0;
      past_end_q  <= 1'b0;
      rad_q       <= '0;
      first_q     <= 1'b1;
      digit_q     <= '0;
      place_q     <= '0;
      dec_q       <= '0;  // rom(0) is {OpMul, ...}: op 0, and nothing runs before a take
      s1_q        <= '0;
      s2_q        <= '0;
      acc_q       <= '0;
      pp_q        <= '0;
      wb_q        <= 1'b0;
      wb_pos_q    <= 1'b0;
      wb_dst_q    <= '0;
      rem_q       <= '0;
      res_q       <= '0;
      dv_act_q    <= 1'b0;
      dv_sqrt_q   <= 1'b0;
      dv_cnt_q    <= '0;
      dvs_q       <= '0;
      m3_q        <= '0;
      even_q      <= 1'b0;
      lnew_q      <= '0;
      lprev_q     <= '0;
      seg_q       <= '0;
      seg_valid_q <= 1'b0;
      seg_last_q  <= 1'b0;
      tag_n_q     <= '0;
      tag_q       <= '0;
    end else begin
      act_q       <= act_d;
      pc_q        <= pc_d;
      cnt_q       <= cnt_d;
      reg_q       <= reg_d;
      dec_q       <= dec_d;
      past_end_q  <= past_end_d;
      rad_q       <= rad_d;
      first_q     <= first_d;
      digit_q     <= digit_d;
      place_q     <= place_d;
      s1_q        <= s1_d;
      s2_q        <= s2_d;
      acc_q       <= acc_d;
      pp_q        <= pp_d;
      wb_q        <= wb_d;
      wb_pos_q    <= wb_pos_d;
      wb_dst_q    <= wb_dst_d;
      rem_q       <= rem_d;
      res_q       <= res_d;
      dv_act_q    <= dv_act_d;
      dv_sqrt_q   <= dv_sqrt_d;
      dv_cnt_q    <= dv_cnt_d;
      dvs_q       <= dvs_d;
      m3_q        <= m3_d;
      even_q      <= even_d;
      lnew_q      <= lnew_d;
      lprev_q     <= lprev_d;
      seg_q       <= seg_d;
      seg_valid_q <= seg_valid_d;
      seg_last_q  <= seg_last_d;
      tag_n_q     <= tag_n_d;
      tag_q       <= tag_d;
    end
  end

  // ---------------------------------------------------------------------------
  // Fine stage: the dda_line core over the four axes, half preload.
  dda_line #(
    .AXES  (4),
    .ACC_W (SEG_W),
    .POS_W (POS_W),
    .TIM_W (TIM_W),
    .FEED_W(FEED_W)
  ) u_fine (
    .clk_i,
    .rst_ni,
    .cmd_valid_i   (seg_valid_q),
    .cmd_ready_o   (fine_ready),
    .cmd_delta_i   (seg_q),
    .feed_i,
    .half_preload_i(1'b1),
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .abort_i,
    .step_o,
    .dir_o,
    .pos_o,
    .busy_o        (fine_busy),
    .done_o        (fine_done)
  );

  assign cmd_ready_o = !act_q;
  assign busy_o      = act_q || seg_valid_q || fine_busy;
  assign done_o      = fine_done && tag_q[0];

`ifdef FORMAL
  // ---------------------------------------------------------------------------
  // Formal (scripts/formal.sh, rtl/formal/log_stepper_props.sv): the port
  // contract every core shares (rtl/formal/core_contract.sv), a command
  // being a curve: it is held from its take until the done_o of its last
  // segment, by the coarse engine (act_q) while it is computed, then by its
  // last segment, in the segment register or in the fine stage (a tag set).
  // The fine stage's own contract counts the segments it holds (u_fine's
  // f_held, which scripts/formal.sh connects to f_fine_held after
  // flattening: Yosys 0.23 has no hierarchical references); the tags follow
  // them one for one.
  logic [1:0] f_fine_held;  // u_fine.f_held, connected by scripts/formal.sh
  logic [3:0] f_seq;  // the segments in flight, oldest first: the tags, then the segment register
  logic [2:0] f_n;  // how many
  logic [2:0] f_held, f_lasts;
  logic       f_young;  // the youngest segment in flight ends its curve (1 when none)
  logic       f_young_none;  // no segment in flight
  logic [19:0] f_ent;  // rom(pc_q)
  assign f_ent = rom(pc_q);
  always_comb begin
    f_seq = 4'(tag_q & ((3'd1 << tag_n_q) - 3'd1));
    f_n   = 3'(tag_n_q);
    if (seg_valid_q) begin
      f_seq[tag_n_q] = seg_last_q;
      f_n            = f_n + 3'd1;
    end
    f_lasts = 3'(f_seq[0]) + 3'(f_seq[1]) + 3'(f_seq[2]) + 3'(f_seq[3]);
    f_young = (f_n == '0) || f_seq[f_n - 3'd1];
    f_young_none = f_n == '0;
    f_held  = 3'(act_q) + f_lasts - 3'(done_o);
  end

  core_contract #(
    .AXES  (AXES),
    .TIM_W (TIM_W),
    .CAP   (3),
    .HELD_W(3)
  ) u_contract (
    .clk_i,
    .rst_ni,
    .cmd_valid_i,
    .cmd_ready_o,
    .abort_i,
    .step_len_i,
    .step_o,
    .busy_o,
    .done_o,
    .held_i(f_held)
  );

  always_comb begin
    if (rst_ni) begin
      // The tags follow the fine stage's segments one for one (a segment's
      // tag goes on the clock after its done).
      a_tags: assert(tag_n_q == f_fine_held + 2'(fine_done));
      // A segment that does not end its curve is followed by one of the same
      // curve, or the curve is still being computed; one that ends its curve
      // by the first of a later curve (every curve has two segments or more).
      a_young: assert(f_young || act_q);
      a_order: assert(!(f_seq[0] && f_seq[1]) && !(f_seq[1] && f_seq[2]) &&
                      !(f_seq[2] && f_seq[3]));
      // The program: the decoded operation is the one at pc_q, and a curve
      // whose predecessor's last segment is still the youngest in flight has
      // not yet passed its first (odd) point, nor made an even one.
      a_pc: assert(pc_q <= 6'd45 && op == f_ent[19:17] && sh == f_ent[1:0]);
      a_first: assert(!act_q || f_young_none || !f_young || (pc_q <= 6'd38 && !even_q));
    end
  end
`endif
endmodule

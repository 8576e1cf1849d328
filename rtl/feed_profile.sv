// Jerk-limited feed profile: the path speed, clock by clock, for a stream of
// moves; its feed word goes to feed_accum. The contract, the fixed-point
// formats and the braking rule are stated once, in hls/feed_profile.h (the
// cycle-accurate face this RTL is compared with on every clock); in short:
//   - ticks of 2^TICK_W clocks; per tick a speed level c moves by -1, 0 or +1
//     (a trapezoid with an exact braking rule), and the speed is
//     v = q * (sum of c over the last L ticks): per tick |dv| <= q*L and
//     |d2v| <= q, the acceleration and jerk limits;
//   - a move (ops, target level, end level) ends on the tick its remaining
//     distance R (ops << (SPD_W - TICK_W)) runs out; the next starts there;
//   - hold_i brings the speed to rest within the same limits; release resumes;
//   - ovr_i, the feed override (factor ovr_i / 128, 0..200 %; above 256 acts
//     as 256), sampled on the boundary clock for the next boundary: the cruise
//     level in force is min(ceil(target * ovr / 128), cmd_max ? cmd_max : target).
//
// How the RTL gets the HLS face's numbers. Everything the boundary clock
// (t = 0) decides depends on state fixed for the whole tick before it (the
// command in force at the next boundary is known a tick ahead:
// hls/feed_profile.h moves commands next -> current before pending -> next),
// except hold_i, which is sampled on the boundary clock itself. So one
// sequential multiply-accumulate unit (MAC: P = P0 + A * B, B's bits LSB
// first, one a clock) computes, during the tick, the level and the speed the
// boundary would give for hold_i low and for hold_i high, and the boundary
// clock only chooses between two registers. The arithmetic that follows a
// boundary (the distance R less this tick's travel, the product q * c_old
// of the ring's level) is done by the same MAC at the start of the next
// tick; R is internal, so no output sees the difference. The override's target (above) is a small
// shift-add multiplier of its own (9 clocks, from the end of QC, when the
// command of the next boundary is known), long done before GO reads it.
// Per tick, in order (SEQ_CLOCKS clocks, checked
// against 2^TICK_W below):
//   R     ~R = ~rp + (q L) c_new   (R is held inverted: ~(a - b) = ~a + b)
//   QC    q c_old, c_old the level of the boundary L ticks back (the ring
//         word read at t = 2, after the level of the boundary just passed
//         is written at t = 1)
//   QL    q L
//   X0    2 e (L - 1) + (c + e - 1)(c - e) [c > e] + c * 2 (1 + w)
//   X1    X0 + c * 2 (L - w + [c >= e]) + 2 (L + 1)
//   F1 F0 fits: (q L) X <= 2 rp, as (q L) X + ~(2 rp) < 2^RW (no overflow)
//   GO    the next level for hold low and high (registers)
//   V0 V1 v + q c' - q c_old for each of them
// The MAC's accumulator is cut in three parts with the carries between them
// registered (each added into the next part on the next clock; two clocks
// more after the last bit let them ripple through), so no carry chain is
// longer than about RW / 3. The last L levels live in a
// block RAM (prim_ram_1r1w); words not written since reset read as 0 (a
// high-water mark), as the HLS face's ring starts at 0. The ring holds the
// levels c, not the products q c the HLS face keeps (ring_qc_): q changes
// only at rest (busy_o low), and at rest every word written since reset
// holds level 0 (no step of the level within the last L ticks and no move,
// so the level came down to 0 more than L ticks ago; a shorter L reads a
// subset of those words), so q c_old with the q in force equals the product
// the HLS face stored. LVL_W + 2 bits a word instead of SPD_W + 3: 5
// SB_RAM40_4K instead of 13 at LVL_W 16, LEN_W 10.
module feed_profile #(
  parameter int FEED_W = 16,  // feed word fraction bits, as feed_accum (>= 1)
  parameter int SPD_W  = 48,  // speed fraction bits (FEED_W < SPD_W <= 62)
  parameter int TICK_W = 10,  // a tick is 2^TICK_W clocks (>= 8: the sequencer needs SEQ_CLOCKS)
  parameter int LEN_W  = 10,  // the moving sum is at most 2^LEN_W ticks (1..16)
  parameter int LVL_W  = 16,  // speed level bits (2..24)
  parameter int OPS_W  = 28   // operations of a move (2..40)
) (
  input  logic              clk_i,           // the clock
  input  logic              rst_ni,          // asynchronous reset, active low
  // configuration, latched while the block is at rest (busy_o low)
  input  logic [SPD_W-1:0]  q_i,             // speed quantum: ops/clock * 2^SPD_W (jerk a tick^2)
  input  logic [LEN_W:0]    len_i,           // L, ticks of the moving sum (0 acts as 1, capped at 2^LEN_W)
  // moves
  input  logic              cmd_valid_i,     // a move is offered
  output logic              cmd_ready_o,     // the move is taken when valid and ready
  input  logic [OPS_W-1:0]  cmd_ops_i,       // its engine operations (>= 1)
  input  logic [LVL_W-1:0]  cmd_target_i,    // its cruise level
  input  logic [LVL_W-1:0]  cmd_end_i,       // its level at its last operation
  input  logic [LVL_W-1:0]  cmd_max_i,       // its cruise level's cap (0: its target)
  input  logic              hold_i,          // feed hold: come to rest within the limits
  input  logic [8:0]        ovr_i,           // feed override, ovr_i / 128 (128: 100 %)
  // outputs
  output logic [FEED_W:0]   feed_o,          // operations per clock * 2^FEED_W, to feed_accum (a register)
  output logic [LVL_W-1:0]  level_o,         // the trapezoid's level c
  output logic [SPD_W:0]    speed_o,         // the speed v, ops/clock * 2^SPD_W
  output logic              busy_o           // moves queued, or moving, or settling
);
  localparam int DROP = SPD_W - FEED_W;            // speed bits below the feed word
  localparam int RSH = SPD_W - TICK_W;             // R = ops << RSH
  localparam int RW = OPS_W + RSH + 2;             // R, signed
  localparam int RHW = RW - RSH;                   // R's bits at and above the move's LSB
  localparam int MAXLEN = 1 << LEN_W;
  localparam int AGE_W = LEN_W + 2;                // counts up to MAXLEN + 1
  localparam int QL_W = SPD_W + LEN_W + 1;         // q * L
  localparam int VW = SPD_W + 1;                   // v, q * c
  localparam int XW = ((2 * LVL_W > LVL_W + LEN_W) ? 2 * LVL_W : LVL_W + LEN_W) + 4;  // X0, X1
  // the MAC's accumulator: every result above fits (mod 2^PW where stated)
  localparam int PW0 = (RW + 1 > QL_W) ? RW + 1 : QL_W;
  localparam int PW1 = (PW0 > VW + 1) ? PW0 : VW + 1;
  localparam int PW = (PW1 > XW) ? PW1 : XW;
  localparam int PLW = PW / 3;                     // its low part
  localparam int PMW = PW / 3;                     // its middle part
  localparam int PHW = PW - PLW - PMW;             // its high part
  localparam int PMH = PLW + PMW;                  // the high part's first bit
  // clocks from the boundary to the last result, with a margin (see the header)
  localparam int SEQ_CLOCKS = 5 * LVL_W + 4 * LEN_W + 2 * XW + 62;

`ifndef __ICARUS__
  if (FEED_W < 1 || SPD_W <= FEED_W || SPD_W > 62) begin : g_bad_spd_w
    $error("feed_profile: parameters need 1 <= FEED_W < SPD_W <= 62");
  end
  if (TICK_W >= SPD_W || TICK_W > 24 || (1 << TICK_W) < SEQ_CLOCKS) begin : g_bad_tick_w
    $error("feed_profile: parameter TICK_W: 2^TICK_W clocks must hold the sequencer's clocks");
  end
  if (LEN_W < 1 || LEN_W > 16) begin : g_bad_len_w
    $error("feed_profile: parameter LEN_W must be 1..16");
  end
  if (LVL_W < 2 || LVL_W > 24) begin : g_bad_lvl_w
    $error("feed_profile: parameter LVL_W must be 2..24");
  end
  if (OPS_W < 2 || OPS_W > 40) begin : g_bad_ops_w
    $error("feed_profile: parameter OPS_W must be 2..40");
  end
`endif

  // ---- state ----
  logic [TICK_W-1:0] t_q, t_d;                 // clock within the tick; 0: the boundary
  logic              bnd_q, bnd_d;             // t_q == 0 (a register: it enables much)
  logic [VW-1:0]     v_q, v_d;                 // speed
  logic [DROP-1:0]   acc_q, acc_d;             // dither of the dropped speed bits
  logic [FEED_W:0]   feed_q, feed_d;
  logic [LVL_W-1:0]  c_q, c_d;                 // level
  logic [LEN_W-1:0]  idx_q, idx_d;             // ring position
  logic [LEN_W:0]    hw_q, hw_d;               // ring words written since reset
  logic [AGE_W-1:0]  up_age_q, up_age_d;       // ticks since the last +1 (saturates at MAXLEN + 1)
  logic [AGE_W-1:0]  quiet_q, quiet_d;         // ticks since the last step of c (saturates)
  logic [LEN_W-1:0]  jh_q, jh_d;               // boundaries after a junction without a +1 (to come)
  logic [LEN_W-1:0]  jhn_q, jhn_d;             // jh_q as the next boundary will see it
  logic              jblk_q, jblk_d;           // the next boundary may not step up (a junction's hold)
  logic [RW-1:0]     nr_q, nr_d;               // ~R: the distance left of the current move, inverted
  logic [RW-1:0]     nrp_q, nrp_d;             // ~R after the next boundary's promotion
  logic              cur_q, cur_d, next_q, next_d, pend_q, pend_d;
  logic [LVL_W-1:0]  cur_tgt_q, cur_tgt_d, cur_end_q, cur_end_d;
  logic [LVL_W-1:0]  cur_top_q, cur_top_d, next_top_q, next_top_d, pend_top_q, pend_top_d;
  // the override: its word for the next boundary, and the multiplier
  logic [8:0]        ovr_q, ovr_d;
  logic              mstart_q, mstart_d;       // load the multiplier
  logic [3:0]        mcnt_q, mcnt_d;           // its bits left
  logic [LVL_W+8:0]  mp_q, mp_d;               // {partial product, multiplier bits left}
  logic [LVL_W+1:0]  scaled_q, scaled_d;       // ceil(target * ovr / 128)
  logic [OPS_W-1:0]  next_ops_q, next_ops_d, pend_ops_q, pend_ops_d;
  logic [LVL_W-1:0]  next_tgt_q, next_tgt_d, next_end_q, next_end_d;
  logic [LVL_W-1:0]  pend_tgt_q, pend_tgt_d, pend_end_q, pend_end_d;
  logic [SPD_W-1:0]  q_q, q_d;                 // configuration in force
  logic [LEN_W:0]    len_q, len_d;
  // what the next boundary promotes (fixed for the tick once R is known)
  logic              promote_q, promote_d, curp_q, curp_d;
  // the boundary just passed, for the arithmetic that follows it
  logic              curb_q, curb_d, upb_q, upb_d, dnb_q, dnb_d;
  logic [LEN_W-1:0]  idxb_q, idxb_d;
  // the next boundary's choices: [0] hold_i low, [1] hold_i high
  logic [1:0]        gu_q, gu_d, gd_q, gd_d;
  logic [VW-1:0]     vn0_q, vn0_d, vn1_q, vn1_d;   // the speed
  logic [XW-1:0]     x0_q, x0_d;
  logic [QL_W-1:0]   ql_q, ql_d;               // q * L
  logic              fits0_q, fits0_d, fits1_q, fits1_d;
  logic              rvalid_q, rvalid_d;       // the ring word read was written since reset
  // the sequencer and its MAC
  logic [4:0]        ph_q, ph_d;               // the operation in progress
  // (The clocks that load and capture are known a clock ahead: registers.)
  logic              load_q, load_d;           // load the operands of lop_q on this clock
  logic [4:0]        lop_q, lop_d;
  logic              cap_q, cap_d;             // ph_q's results are ready: capture them
  logic              run_q, run_d;             // the MAC is stepping (cnt_q != 0)
  logic [5:0]        cnt_q, cnt_d;             // clocks left: B's bits, then two for the last carries
  logic [PW-1:0]     ma_q, ma_d;               // A, shifted left a bit a clock
  logic              ma_over_q, ma_over_d;     // A has shifted a one out of its top
  logic [XW-1:0]     mb_q, mb_d;               // B, shifted right a bit a clock
  logic [PLW-1:0]    pl_q, pl_d;               // P, low part
  logic [PMW-1:0]    pm_q, pm_d;               // P, middle part
  logic [PHW-1:0]    ph_hi_q, ph_hi_d;         // P, high part
  logic              pc_q, pc_d;               // the carry from the low part, due in the middle
  logic              pcm_q, pcm_d;             // the carry from the middle part, due in the high
  logic              ci_q, ci_d;               // a carry into bit 0 on the first bit
  logic              pover_q, pover_d;         // P has overflowed 2^PW (before the last clock)
  logic              pco_q, pco_d;             // the high part's carry out on the last clock

  localparam logic [4:0] OpIdle = 5'd0, OpR = 5'd1, OpQc = 5'd2, OpQl = 5'd3, OpEl = 5'd4,
                         OpBrk = 5'd5, OpCw = 5'd6, OpD1 = 5'd7, OpD2 = 5'd8, OpF1 = 5'd9,
                         OpF0 = 5'd10, OpGo = 5'd11, OpGo2 = 5'd12, OpV0a = 5'd13, OpV0b = 5'd14,
                         OpV1a = 5'd15, OpV1b = 5'd16;

  // ---- the ring RAM: {dc up, dc down, c} per tick ----
  // Written at t = 1 (the level, its step and the ring position of the
  // boundary just passed are registers by then), read at t = 2 (so with
  // L = 1 the read gives the word just written): never a read and a write in
  // one clock.
  logic              ram_we, ram_re;
  logic [LVL_W+1:0]  ram_wdata, ram_rdata;
  logic [PW-1:0]     p_full;
  assign p_full = {ph_hi_q, pm_q, pl_q};
  assign ram_we = t_q == TICK_W'(1);
  assign ram_re = t_q == TICK_W'(2);
  prim_ram_1r1w #(.WIDTH(LVL_W + 2), .DEPTH(MAXLEN), .SAME_WORD_RW(1'b0)) u_ring (
    .clk_i   (clk_i),
    .we_i    (ram_we),
    .waddr_i (idxb_q),
    .wdata_i (ram_wdata),
    .re_i    (ram_re),
    .raddr_i (idx_q),
    .rdata_o (ram_rdata)
  );
  assign ram_wdata = {upb_q, dnb_q, c_q};

  // The word read, registered once more in the fabric (block RAM's clock to
  // out is long); read at t = 2, it is first used at QC's load, clocks later.
  // q c_old is QC's product (qco_q), taken at QC's capture.
  logic [LVL_W+1:0] rdq_q, rdq_d;
  logic rd_up, rd_dn;
  logic [LVL_W-1:0] c_old;
  logic [VW-1:0] qco_q, qco_d;
  assign rdq_d  = ram_rdata;
  assign rd_up  = rvalid_q && rdq_q[LVL_W+1];
  assign rd_dn  = rvalid_q && rdq_q[LVL_W];
  assign c_old  = rvalid_q ? rdq_q[LVL_W-1:0] : '0;

  // busy: moves queued, or moving (v != 0), or settling (a step of the
  // level within the last L ticks: quiet <= L). A register, busy_q, computed
  // from the next state (rest enables every register of q and L, so it
  // comes from a flip-flop): "moving" from a flag of its own (vnz_q, with
  // vn0nz_q and vn1nz_q beside the two candidate speeds), "settling" from
  // the saturating increment of quiet_q computed ahead (qinc_q). The formal
  // file asserts that all of them equal what they stand for (a_busy, a_vnz).
  logic busy_q, busy_d, settle_d, rest, boundary;
  logic vnz_q, vnz_d, vn0nz_q, vn0nz_d, vn1nz_q, vn1nz_d;
  logic [AGE_W-1:0] qinc_q, qinc_d;            // quiet_q + 1, saturated (read at boundaries)
  assign rest     = !busy_q;
  assign boundary = bnd_q;
  assign bnd_d    = (t_q == '1);
  assign qinc_d   = ({1'b0, quiet_q} > (AGE_W + 1)'(MAXLEN)) ? quiet_q : quiet_q + AGE_W'(1);

  // ---- the next boundary's promotion, from R (valid after OpR) ----
  // (r_done and moving are registers, valid from the second clock of OpQc,
  // which writes promote_q and nrp_q on each of its clocks: the last wins.)
  logic r_done, promote, moving, r_done_d, moving_d, r_done_q, moving_q;
  logic [LVL_W-1:0] tgt_p, end_p, end_p_d;
  logic [RHW-1:0] ops_r;
  assign r_done_d = !nr_q[RW-1] || (nr_q == '1);   // R <= 0
  assign r_done   = r_done_q;
  assign promote = (!cur_q || r_done) && next_q;
  assign moving_d = (c_q != '0) || vnz_q;
  assign moving   = moving_q;
  assign ops_r   = RHW'(next_ops_q);
  assign end_p_d = promote_q ? next_end_q : cur_end_q;
  assign end_p   = end_p_q;

  // The junction's hold (hls/feed_profile.h, jhold_): when the next boundary
  // ends a move at level e > 0 while moving and starts the next, that
  // boundary and the floor(L / 2) - 1 after it may not step up. (promote_q
  // is valid from OpQc on; the first to read jblk_q is OpGo2. jhn_q and
  // jblk_q are registers of what is fixed for the rest of the tick.)
  logic junction;
  assign junction = promote_q && cur_q && moving_q && (cur_end_q != '0);
  assign jhn_d    = junction ? len_q[LEN_W:1] : jh_q;
  assign jblk_d   = (jhn_q != '0);

  // w_hold: ticks c must still hold before a -1 may follow the last +1
  // (The small operands are registers: their inputs are fixed for the tick
  // from OpQc on, and the first to use them is OpEl.)
  logic             aged;
  logic [LEN_W+1:0] w1x2_d, lw1x2_d, w1x2_q, lw1x2_q;
  // c > e and c >= e, registered a clock before the sums that take them
  // (end_p_q is known a clock after QC; the first sum read is at BRK)
  logic             cgt_q, cgt_d, cge_q, cge_d;
  assign cgt_d   = c_q > end_p;
  assign cge_d   = c_q >= end_p;
  assign aged  = ({1'b0, up_age_q} >= {2'b0, len_q});
  // 2 (1 + w) and 2 (L - w + [c >= e]); L - w is L when aged, else up_age
  assign w1x2_d  = aged ? (LEN_W + 2)'(2) : {len_q - up_age_q[LEN_W:0] + (LEN_W + 1)'(1), 1'b0};
  assign lw1x2_d = {(aged ? len_q : up_age_q[LEN_W:0]) + (LEN_W + 1)'(cge_q), 1'b0};

  // ---- the next boundary's choices for hold_i low (0) and high (1) ----
  // Two clocks: the compares (registered), then the choices. hold_i high:
  // free, target and end 0 (only down, when the reversal rule allows).
  // (The target and the floor for hold_i low are registers too.)
  logic free0;
  logic [LVL_W-1:0] tgt_e, floor_lvl, tgt_e_d, floor_d, tgt_e_q, floor_q;
  assign free0     = !curp_q;
  assign tgt_p     = promote_q ? next_tgt_q : cur_tgt_q;
  logic [LVL_W-1:0] top_p, tgt_o;
  assign top_p     = promote_q ? next_top_q : cur_top_q;
  assign tgt_o     = ({2'b0, top_p} < scaled_q) ? top_p : scaled_q[LVL_W-1:0];
  assign tgt_e_d   = free0 ? '0 : tgt_o;
  // the end level if not free, else 0; at least 1 when not free
  assign floor_d   = free0 ? '0 : ((end_p != '0) ? end_p : LVL_W'(1));
  assign tgt_e     = tgt_e_q;
  assign floor_lvl = floor_q;
  logic             lt_q, lt_d, gt_q, gt_d, gtf_q, gtf_d, cz_q, cz_d, cmax_q, cmax_d;
  logic             f0_q, f0_d, f1_q, f1_d;
  logic [LVL_W-1:0] cp1_q, cp1_d, cm1_q, cm1_d;
  logic [1:0]       go_up_c, go_dn_c;
  logic [LVL_W-1:0] cn0, cn1;                  // the level after the boundary (for OpV0a, OpV1a)
  assign go_up_c[0] = lt_q && !rd_dn && !cmax_q && (f1_q || cz_q) && !jblk_q;
  assign go_dn_c[0] = !go_up_c[0] && !cz_q && !rd_up && (gt_q || (gtf_q && !f0_q));
  assign go_up_c[1] = 1'b0;
  assign go_dn_c[1] = !cz_q && !rd_up;
  assign cn0 = gu_q[0] ? cp1_q : (gd_q[0] ? cm1_q : c_q);
  assign cn1 = gd_q[1] ? cm1_q : c_q;

  // ---- the MAC: operands of the operation loaded this clock ----
  logic            cap, load;
  logic [4:0]      nxt, lop;
  logic [PW-1:0]   la, lp;
  logic [XW-1:0]   lb;
  logic            lc;
  logic [5:0]      lk;
  logic [LVL_W-1:0] end_p_q;                  // the end level after the promotion
  logic [LVL_W:0]  cpe_d, cpe_q;                 // (c + e - 1) when c > e, else 0
  assign cpe_d = cgt_q ? {1'b0, c_q} + {1'b0, end_p} - (LVL_W + 1)'(1) : '0;
  logic [LEN_W:0]  lm1_d, lm1_q;                 // L - 1
  logic [LEN_W:0]  lp1_d, lp1_q;               // L + 1 (L < 2^(LEN_W+1) - 1)
  logic [LVL_W-1:0] cme_d, cme_q;                // c - e (used when c > e)
  logic [VW-1:0]   nqc_old;                    // ~(q c_old): + 1 below, so - q c_old
  assign lm1_d     = len_q - (LEN_W + 1)'(1);
  assign lp1_d     = len_q + (LEN_W + 1)'(1);
  assign cme_d     = c_q - end_p;
  assign nqc_old = ~qco_q;
  logic [LVL_W:0]  c2;                         // 2 c
  logic [RW:0]     nrp1;                       // ~(2 rp) = 2 ~rp + 1
  assign c2      = {c_q, 1'b0};
  assign nrp1    = {nrp_q, 1'b1};
  // the capture clock of ph_q: its bits and its flush done
  // cap: the clock after a MAC operation's last bit, and GO and GO2 right after OpF0
  assign cap    = cap_q;
  assign cap_d  = (run_q && (cnt_q == 6'd1)) || (cap_q && ((ph_q == OpF0) || (ph_q == OpGo)));
  assign nxt    = (ph_q == OpV1b) ? OpIdle : ph_q + 5'd1;
  // load: at t = 1 (OpR), after GO2 (OpV0a), and with the capture of every MAC
  // operation but the last of a run (OpF0, OpV1b), the next one
  assign lop    = lop_q;
  assign load   = load_q;
  assign load_d = bnd_q || (cap_q && (ph_q == OpGo2)) ||
                  (run_q && (cnt_q == 6'd1) && (ph_q != OpF0) && (ph_q != OpV1b));
  assign lop_d  = bnd_q ? OpR : nxt;

  always_comb begin
    la = '0;
    lb = '0;
    lp = '0;
    lc = 1'b0;
    lk = '0;
    unique case (lop)
      OpR:   begin la = curb_q ? PW'(ql_q) : '0; lb = XW'(c2); lp = PW'(nrp1); lk = 6'(LVL_W + 1); end
      OpQc:  begin la = PW'(q_q);   lb = XW'(c_old);                            lk = 6'(LVL_W + 1); end
      OpQl:  begin la = PW'(q_q);   lb = XW'(len_q);                            lk = 6'(LEN_W + 1); end
      OpEl:  begin la = PW'(end_p); lb = XW'({lm1_q, 1'b0});                      lk = 6'(LEN_W + 2); end
      OpBrk: begin la = PW'(cpe_q); lb = XW'(cme_q);          lp = p_full;       lk = 6'(LVL_W); end
      OpCw:  begin la = PW'(c_q);   lb = XW'(w1x2_q);         lp = p_full;       lk = 6'(LEN_W + 2); end
      OpD1:  begin la = PW'(c_q);   lb = XW'(lw1x2_q);         lp = p_full;       lk = 6'(LEN_W + 2); end
      OpD2:  begin la = PW'(lp1_q); lb = XW'(2);      lp = p_full;       lk = 6'd2; end
      OpF1:  begin la = PW'(ql_q);  lb = p_full[XW-1:0];     lp = PW'(nrp1);      lk = 6'(XW); end
      OpF0:  begin la = PW'(ql_q);  lb = x0_q;               lp = PW'(nrp1);      lk = 6'(XW); end
      OpV0a: begin la = PW'(q_q);   lb = XW'(cn0);            lp = PW'(v_q);     lk = 6'(LVL_W); end
      OpV1a: begin la = PW'(q_q);   lb = XW'(cn1);            lp = PW'(v_q);     lk = 6'(LVL_W); end
      OpV0b, OpV1b: begin la = PW'(nqc_old); lb = XW'(1);    lp = p_full; lc = 1'b1; lk = 6'd1; end
      default: ;
    endcase
  end

  // ---- the MAC and the sequencer ----
  logic            mbit;
  logic [PLW:0]    sum_lo;
  logic [PMW:0]    sum_mid;
  logic [PHW:0]    sum_hi;
  // B holds no bits above its count: it is 0 on the last two clocks (the flush)
  assign mbit   = mb_q[0];
  assign sum_lo = {1'b0, pl_q} + {1'b0, mbit ? ma_q[PLW-1:0] : PLW'(0)} + (PLW + 1)'(ci_q);
  assign sum_mid = {1'b0, pm_q} + {1'b0, mbit ? ma_q[PMH-1:PLW] : PMW'(0)} + (PMW + 1)'(pc_q);
  assign sum_hi = {1'b0, ph_hi_q} + {1'b0, mbit ? ma_q[PW-1:PMH] : PHW'(0)} + (PHW + 1)'(pcm_q);

  logic over_rw;  // (q L) X > 2 rp: the candidate does not fit
  // {~rp, 1} is 2^RW + ~(2 rp) when rp >= 0: it fits when P stays below 2^(RW + 1)
  assign over_rw = pover_q || pco_q || ((p_full >> (RW + 1)) != '0);

  always_comb begin
    ph_d      = ph_q;
    run_d     = run_q;
    cnt_d     = cnt_q;
    ma_d      = ma_q;
    ma_over_d = ma_over_q;
    mb_d      = mb_q;
    pl_d      = pl_q;
    pm_d      = pm_q;
    ph_hi_d   = ph_hi_q;
    pc_d      = pc_q;
    pcm_d     = pcm_q;
    ci_d      = 1'b0;
    pover_d   = pover_q;
    pco_d     = pco_q;
    nr_d      = nr_q;
    nrp_d     = nrp_q;
    promote_d = promote_q;
    curp_d    = curp_q;
    ql_d      = ql_q;
    x0_d      = x0_q;
    fits0_d   = fits0_q;
    fits1_d   = fits1_q;
    gu_d      = gu_q;
    lt_d      = lt_q;
    gt_d      = gt_q;
    gtf_d     = gtf_q;
    cz_d      = cz_q;
    cmax_d    = cmax_q;
    f0_d      = f0_q;
    f1_d      = f1_q;
    cp1_d     = cp1_q;
    cm1_d     = cm1_q;
    gd_d      = gd_q;
    vn0_d     = vn0_q;
    vn1_d     = vn1_q;
    vn0nz_d   = vn0nz_q;
    vn1nz_d   = vn1nz_q;
    qco_d     = qco_q;
    if (run_q) begin
      // A bit of B (the last two clocks, with B empty: the last carries only).
      pl_d      = sum_lo[PLW-1:0];
      pc_d      = sum_lo[PLW];
      pm_d      = sum_mid[PMW-1:0];
      pcm_d     = sum_mid[PMW];
      ph_hi_d   = sum_hi[PHW-1:0];
      pco_d     = sum_hi[PHW];
      pover_d   = pover_q || pco_q || (mbit && ma_over_q);
      ma_d      = ma_q << 1;
      ma_over_d = ma_over_q || ma_q[PW-1];
      mb_d      = mb_q >> 1;
      cnt_d     = cnt_q - 6'd1;
      run_d     = (cnt_q != 6'd1);
    end
    if (ph_q == OpQc) begin
      // R is known: the next boundary's promotion and R after it.
      promote_d = promote;
      curp_d    = promote || (cur_q && !r_done);
      if (!promote) nrp_d = nr_q;
      else if (cur_q && moving) nrp_d = {nr_q[RW-1:RSH] - ops_r, nr_q[RSH-1:0]};
      else nrp_d = {~ops_r, {RSH{1'b1}}};
    end
    if (cap) begin
      unique case (ph_q)
        OpR:   nr_d = p_full[RW:1];
        OpQc:  qco_d = p_full[VW-1:0];
        OpQl:  ql_d = p_full[QL_W-1:0];
        OpCw:  x0_d = p_full[XW-1:0];
        OpF1:  fits1_d = nrp_q[RW-1] && !over_rw;
        OpF0:  fits0_d = nrp_q[RW-1] && !over_rw;
        OpGo: begin
          lt_d   = c_q < tgt_e;
          gt_d   = c_q > tgt_e;
          gtf_d  = c_q > floor_lvl;
          cz_d   = c_q == '0;
          cmax_d = c_q == '1;
          f0_d   = free0 || fits0_q;
          f1_d   = free0 || fits1_q;
          cp1_d  = c_q + LVL_W'(1);
          cm1_d  = c_q - LVL_W'(1);
        end
        OpGo2: begin
          gu_d = go_up_c;
          gd_d = go_dn_c;
        end
        OpV0b: begin vn0_d = p_full[VW-1:0]; vn0nz_d = (p_full[VW-1:0] != '0); end
        OpV1b: begin vn1_d = p_full[VW-1:0]; vn1nz_d = (p_full[VW-1:0] != '0); end
        default: ;
      endcase
      ph_d = nxt;
    end
    if (load) begin
      ph_d      = lop;
      ma_d      = la;
      ma_over_d = 1'b0;
      mb_d      = lb;
      pl_d      = lp[PLW-1:0];
      pm_d      = lp[PMH-1:PLW];
      ph_hi_d   = lp[PW-1:PMH];
      pc_d      = 1'b0;
      pcm_d     = 1'b0;
      ci_d      = lc;
      pover_d   = 1'b0;
      pco_d     = 1'b0;
      cnt_d     = lk + 6'd2;
      run_d     = 1'b1;
    end
  end

  // ---- the override's target: tgt_p * ovr_q, LSB first, then the ceiling ----
  // (tgt_p and ovr_q are fixed from the clock after QC's capture to the next
  // boundary; the product is ready 10 clocks later, tgt_e_q 2 after that.)
  logic [LVL_W:0] msum;
  assign mstart_d = cap && (ph_q == OpQc);
  assign msum     = {1'b0, mp_q[LVL_W+8:9]} + ((mp_q[0]) ? {1'b0, tgt_p} : '0);
  always_comb begin
    mcnt_d = mcnt_q;
    mp_d   = mp_q;
    if (mstart_q) begin
      mcnt_d = 4'd9;
      mp_d   = {LVL_W'(0), ovr_q};
    end else if (mcnt_q != '0) begin
      mcnt_d = mcnt_q - 4'd1;
      mp_d   = {msum, mp_q[8:1]};
    end
  end
  assign scaled_d = (LVL_W + 2)'(mp_q[LVL_W+8:7]) + (LVL_W + 2)'(mp_q[6:0] != '0);
  assign ovr_d    = !boundary ? ovr_q : ((ovr_i > 9'd256) ? 9'd256 : ovr_i);

  // ---- the boundary: the level, the speed, the commands, the ring position ----
  logic go_up, go_down;
  assign go_up   = hold_i ? gu_q[1] : gu_q[0];
  assign go_down = hold_i ? gd_q[1] : gd_q[0];

  // The feed word: the speed's top bits plus the dither's carry, chosen
  // between v_hi and v_hi + 1 (two carry chains side by side, not in a row).
  logic [DROP:0]   dsum;
  logic [FEED_W:0] vhi, vhi1;
  assign dsum = {1'b0, acc_q} + {1'b0, v_q[DROP-1:0]};
  assign vhi  = v_q[SPD_W:DROP];
  assign vhi1 = vhi + (FEED_W + 1)'(1);

  always_comb begin
    t_d        = t_q + TICK_W'(1);
    acc_d      = dsum[DROP-1:0];
    feed_d     = dsum[DROP] ? vhi1 : vhi;
    v_d        = v_q;
    vnz_d      = vnz_q;
    c_d        = c_q;
    idx_d      = idx_q;
    hw_d       = hw_q;
    up_age_d   = up_age_q;
    quiet_d    = quiet_q;
    jh_d       = jh_q;
    cur_d      = cur_q;
    next_d     = next_q;
    pend_d     = pend_q;
    cur_tgt_d  = cur_tgt_q;
    cur_end_d  = cur_end_q;
    cur_top_d  = cur_top_q;
    next_top_d = next_top_q;
    pend_top_d = pend_top_q;
    next_ops_d = next_ops_q;
    next_tgt_d = next_tgt_q;
    next_end_d = next_end_q;
    pend_ops_d = pend_ops_q;
    pend_tgt_d = pend_tgt_q;
    pend_end_d = pend_end_q;
    q_d        = q_q;
    len_d      = len_q;
    curb_d     = curb_q;
    upb_d      = upb_q;
    dnb_d      = dnb_q;
    idxb_d     = idxb_q;
    rvalid_d   = rvalid_q;
    if (ram_re) rvalid_d = ({1'b0, idx_q} < hw_q);
    if (boundary) begin
      // Commands: next -> current, then pending -> next.
      cur_d = curp_q;
      if (promote_q) begin
        cur_tgt_d = next_tgt_q;
        cur_end_d = next_end_q;
        cur_top_d = next_top_q;
      end
      next_d = next_q && !promote_q;
      if (!next_d && pend_q) begin
        next_d     = 1'b1;
        next_ops_d = pend_ops_q;
        next_tgt_d = pend_tgt_q;
        next_end_d = pend_end_q;
        next_top_d = pend_top_q;
        pend_d     = 1'b0;
      end
      c_d    = go_up ? c_q + LVL_W'(1) : (go_down ? c_q - LVL_W'(1) : c_q);
      v_d    = hold_i ? vn1_q : vn0_q;
      vnz_d  = hold_i ? vn1nz_q : vn0nz_q;
      curb_d = curp_q;
      upb_d  = go_up;
      dnb_d  = go_down;
      idxb_d = idx_q;
      idx_d = ({1'b0, idx_q} + (LEN_W + 1)'(1) == len_q) ? '0 : idx_q + LEN_W'(1);
      if ({1'b0, idx_q} >= hw_q) hw_d = {1'b0, idx_q} + (LEN_W + 1)'(1);
      jh_d     = jblk_q ? jhn_q - LEN_W'(1) : '0;
      up_age_d = go_up ? AGE_W'(1) :
                 (({1'b0, up_age_q} > (AGE_W + 1)'(MAXLEN)) ? up_age_q : up_age_q + AGE_W'(1));
      quiet_d  = (go_up || go_down) ? AGE_W'(1) : qinc_q;
    end
    if (cmd_valid_i && !pend_q) begin
      pend_d     = 1'b1;
      pend_ops_d = cmd_ops_i;
      pend_tgt_d = cmd_target_i;
      pend_end_d = cmd_end_i;
      pend_top_d = (cmd_max_i != '0) ? cmd_max_i : cmd_target_i;
    end
    if (rest) begin
      q_d   = q_i;
      len_d = (len_i == '0) ? (LEN_W + 1)'(1) :
              ((len_i > (LEN_W + 1)'(MAXLEN)) ? (LEN_W + 1)'(MAXLEN) : len_i);
      idx_d = '0;
    end
  end

  // quiet_d <= len_d, with a step of the level (quiet_d = 1 <= L) apart
  assign settle_d = (boundary && (go_up || go_down)) ||
                    ({1'b0, boundary ? qinc_q : quiet_q} <= {2'b0, len_d});
  assign busy_d   = cur_d || next_d || pend_d || vnz_d || settle_d;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cpe_q   <= '0;
      cgt_q   <= 1'b0;
      cge_q   <= 1'b0;
      end_p_q <= '0;
      r_done_q <= 1'b0;
      moving_q <= 1'b0;
      tgt_e_q <= '0;
      floor_q <= '0;
      cme_q   <= '0;
      lm1_q   <= '0;
      lp1_q   <= '0;
      w1x2_q  <= '0;
      lw1x2_q <= '0;
      ovr_q    <= 9'd128;
      mstart_q <= 1'b0;
      mcnt_q   <= '0;
      mp_q     <= '0;
      scaled_q <= '0;
      cur_top_q  <= '0;
      next_top_q <= '0;
      pend_top_q <= '0;
    end else begin
      cpe_q   <= cpe_d;
      cgt_q   <= cgt_d;
      cge_q   <= cge_d;
      end_p_q <= end_p_d;
      r_done_q <= r_done_d;
      moving_q <= moving_d;
      tgt_e_q <= tgt_e_d;
      floor_q <= floor_d;
      cme_q   <= cme_d;
      lm1_q   <= lm1_d;
      lp1_q   <= lp1_d;
      w1x2_q  <= w1x2_d;
      lw1x2_q <= lw1x2_d;
      ovr_q    <= ovr_d;
      mstart_q <= mstart_d;
      mcnt_q   <= mcnt_d;
      mp_q     <= mp_d;
      scaled_q <= scaled_d;
      cur_top_q  <= cur_top_d;
      next_top_q <= next_top_d;
      pend_top_q <= pend_top_d;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      t_q        <= '0;
      bnd_q      <= 1'b1;
      busy_q     <= 1'b0;
      qinc_q     <= '1;
      vnz_q      <= 1'b0;
      vn0nz_q    <= 1'b0;
      vn1nz_q    <= 1'b0;
      v_q        <= '0;
      acc_q      <= '0;
      feed_q     <= '0;
      c_q        <= '0;
      idx_q      <= '0;
      hw_q       <= '0;
      up_age_q   <= '1;  // any count above MAXLEN is "long ago"; it stays there
      quiet_q    <= '1;
      jh_q       <= '0;
      jhn_q      <= '0;
      jblk_q     <= 1'b0;
      nr_q       <= '1;  // R = 0
      nrp_q      <= '1;
      cur_q      <= 1'b0;
      next_q     <= 1'b0;
      pend_q     <= 1'b0;
      cur_tgt_q  <= '0;
      cur_end_q  <= '0;
      next_ops_q <= '0;
      next_tgt_q <= '0;
      next_end_q <= '0;
      pend_ops_q <= '0;
      pend_tgt_q <= '0;
      pend_end_q <= '0;
      q_q        <= '0;
      len_q      <= 1;
      promote_q  <= 1'b0;
      curp_q     <= 1'b0;
      curb_q     <= 1'b0;
      upb_q      <= 1'b0;
      dnb_q      <= 1'b0;
      idxb_q     <= '0;
      gu_q       <= '0;
      lt_q       <= 1'b0;
      gt_q       <= 1'b0;
      gtf_q      <= 1'b0;
      cz_q       <= 1'b0;
      cmax_q     <= 1'b0;
      f0_q       <= 1'b0;
      f1_q       <= 1'b0;
      cp1_q      <= '0;
      cm1_q      <= '0;
      gd_q       <= '0;
      vn0_q      <= '0;
      vn1_q      <= '0;
      x0_q       <= '0;
      ql_q       <= '0;
      fits0_q    <= 1'b0;
      fits1_q    <= 1'b0;
      rvalid_q   <= 1'b0;
      rdq_q      <= '0;
      qco_q      <= '0;
      ph_q       <= '0;  // OpIdle
      load_q     <= 1'b0;
      lop_q      <= '0;
      cap_q      <= 1'b0;
      run_q      <= 1'b0;
      cnt_q      <= '0;
      ma_q       <= '0;
      ma_over_q  <= 1'b0;
      mb_q       <= '0;
      pl_q       <= '0;
      pm_q       <= '0;
      ph_hi_q    <= '0;
      pc_q       <= 1'b0;
      pcm_q      <= 1'b0;
      ci_q       <= 1'b0;
      pover_q    <= 1'b0;
      pco_q      <= 1'b0;
    end else begin
      t_q        <= t_d;
      bnd_q      <= bnd_d;
      busy_q     <= busy_d;
      qinc_q     <= qinc_d;
      vnz_q      <= vnz_d;
      vn0nz_q    <= vn0nz_d;
      vn1nz_q    <= vn1nz_d;
      v_q        <= v_d;
      acc_q      <= acc_d;
      feed_q     <= feed_d;
      c_q        <= c_d;
      idx_q      <= idx_d;
      hw_q       <= hw_d;
      up_age_q   <= up_age_d;
      quiet_q    <= quiet_d;
      jh_q       <= jh_d;
      jhn_q      <= jhn_d;
      jblk_q     <= jblk_d;
      nr_q       <= nr_d;
      nrp_q      <= nrp_d;
      cur_q      <= cur_d;
      next_q     <= next_d;
      pend_q     <= pend_d;
      cur_tgt_q  <= cur_tgt_d;
      cur_end_q  <= cur_end_d;
      next_ops_q <= next_ops_d;
      next_tgt_q <= next_tgt_d;
      next_end_q <= next_end_d;
      pend_ops_q <= pend_ops_d;
      pend_tgt_q <= pend_tgt_d;
      pend_end_q <= pend_end_d;
      q_q        <= q_d;
      len_q      <= len_d;
      promote_q  <= promote_d;
      curp_q     <= curp_d;
      curb_q     <= curb_d;
      upb_q      <= upb_d;
      dnb_q      <= dnb_d;
      idxb_q     <= idxb_d;
      gu_q       <= gu_d;
      lt_q       <= lt_d;
      gt_q       <= gt_d;
      gtf_q      <= gtf_d;
      cz_q       <= cz_d;
      cmax_q     <= cmax_d;
      f0_q       <= f0_d;
      f1_q       <= f1_d;
      cp1_q      <= cp1_d;
      cm1_q      <= cm1_d;
      gd_q       <= gd_d;
      vn0_q      <= vn0_d;
      vn1_q      <= vn1_d;
      x0_q       <= x0_d;
      ql_q       <= ql_d;
      fits0_q    <= fits0_d;
      fits1_q    <= fits1_d;
      rvalid_q   <= rvalid_d;
      rdq_q      <= rdq_d;
      qco_q      <= qco_d;
      ph_q       <= ph_d;
      load_q     <= load_d;
      lop_q      <= lop_d;
      cap_q      <= cap_d;
      run_q      <= run_d;
      cnt_q      <= cnt_d;
      ma_q       <= ma_d;
      ma_over_q  <= ma_over_d;
      mb_q       <= mb_d;
      pl_q       <= pl_d;
      pm_q       <= pm_d;
      ph_hi_q    <= ph_hi_d;
      pc_q       <= pc_d;
      pcm_q      <= pcm_d;
      ci_q       <= ci_d;
      pover_q    <= pover_d;
      pco_q      <= pco_d;
    end
  end

  assign cmd_ready_o = !pend_q;
  assign feed_o      = feed_q;
  assign level_o     = c_q;
  assign speed_o     = v_q;
  assign busy_o      = busy_q;
endmodule

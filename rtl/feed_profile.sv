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
//   - hold_i brings the speed to rest within the same limits; release resumes.
//
// How the RTL gets the HLS face's numbers: the braking rule compares products
// of up to SPD_W + LEN_W + 2*LVL_W bits. They depend only on state that is
// fixed for a whole tick (the command in force at the next boundary is known a
// tick ahead: hls/feed_profile.h moves commands next -> current before
// pending -> next), so one sequential shift-add multiplier computes them
// during the tick (SEQ_CLOCKS clocks, checked against 2^TICK_W below), and the
// boundary clock only chooses among registered results. The last L levels
// live in a block RAM (prim_ram_1r1w), read one clock after each boundary;
// words not written since reset read as 0 (a high-water mark), as the HLS
// face's ring starts at 0.
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
  input  logic              hold_i,          // feed hold: come to rest within the limits
  // outputs
  output logic [FEED_W:0]   feed_o,          // operations per clock * 2^FEED_W, to feed_accum (a register)
  output logic [LVL_W-1:0]  level_o,         // the trapezoid's level c
  output logic [SPD_W:0]    speed_o,         // the speed v, ops/clock * 2^SPD_W
  output logic              busy_o           // moves queued, or moving, or settling
);
  localparam int DROP = SPD_W - FEED_W;            // speed bits below the feed word
  localparam int RSH = SPD_W - TICK_W;             // R = ops << RSH
  localparam int RW = OPS_W + RSH + 2;             // R, signed
  localparam int MAXLEN = 1 << LEN_W;
  localparam int AGE_W = LEN_W + 2;                // counts up to MAXLEN + 1
  localparam int QL_W = SPD_W + LEN_W + 1;         // q * L
  localparam int XW = ((2 * LVL_W > LVL_W + LEN_W) ? 2 * LVL_W : LVL_W + LEN_W) + 4;
  localparam int MW = QL_W + XW;                   // product width
  localparam int CW = (MW > RW + 1) ? MW : RW + 1; // compare width
  localparam int SEQ_CLOCKS = 9 * 2 + (LEN_W + 1) * 2 + 3 * LVL_W + 2 * (LEN_W + 2) + 2 * XW + 2;

`ifndef __ICARUS__
  if (FEED_W < 1 || SPD_W <= FEED_W || SPD_W > 62) begin : g_bad_spd_w
    $error("feed_profile: parameters need 1 <= FEED_W < SPD_W <= 62");
  end
  if (TICK_W >= SPD_W || TICK_W > 24 || (1 << TICK_W) < SEQ_CLOCKS + 2) begin : g_bad_tick_w
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
  logic [SPD_W:0]    v_q, v_d;                 // speed
  logic [DROP-1:0]   acc_q, acc_d;             // dither of the dropped speed bits
  logic [FEED_W:0]   feed_q, feed_d;
  logic [LVL_W-1:0]  c_q, c_d;                 // level
  logic [LEN_W-1:0]  idx_q, idx_d;             // ring position
  logic [LEN_W:0]    hw_q, hw_d;               // ring words written since reset
  logic [AGE_W-1:0]  up_age_q, up_age_d;       // ticks since the last +1 (saturates at MAXLEN + 1)
  logic [AGE_W-1:0]  quiet_q, quiet_d;         // ticks since the last step of c (saturates)
  logic signed [RW-1:0] r_q, r_d;              // distance left of the current move
  logic              cur_q, cur_d, next_q, next_d, pend_q, pend_d;
  logic [LVL_W-1:0]  cur_tgt_q, cur_tgt_d, cur_end_q, cur_end_d;
  logic [OPS_W-1:0]  next_ops_q, next_ops_d, pend_ops_q, pend_ops_d;
  logic [LVL_W-1:0]  next_tgt_q, next_tgt_d, next_end_q, next_end_d;
  logic [LVL_W-1:0]  pend_tgt_q, pend_tgt_d, pend_end_q, pend_end_d;
  logic [SPD_W-1:0]  q_q, q_d;                 // configuration in force
  logic [LEN_W:0]    len_q, len_d;
  // the sequencer: one shift-add multiplier, phases 1..9, then done (10)
  logic [3:0]        ph_q, ph_d;
  logic              load_q, load_d;           // load the operands of phase ph_q
  logic [5:0]        cnt_q, cnt_d;             // multiplier bits left
  logic [MW-1:0]     mul_a_q, mul_a_d, mul_p_q, mul_p_d;
  logic [XW-1:0]     mul_b_q, mul_b_d;
  logic [QL_W-1:0]   ql_q, ql_d;               // q * L
  logic [SPD_W:0]    qc_q, qc_d;               // q * c (mod 2^(SPD_W+1), as the speed)
  logic [RW-1:0]     qlc_q, qlc_d;             // q * L * c (mod 2^RW, as R)
  logic [2*LVL_W:0]  brk2_q, brk2_d;           // 2 B(c, e) = (c + e - 1)(c - e), 0 when c <= e
  logic [LVL_W+LEN_W+1:0] cw_q, cw_d;          // c * (1 + w_hold)
  logic [LVL_W+LEN_W+1:0] cl_q, cl_d;          // c * (1 + L)
  logic [LVL_W+LEN_W:0]   el_q, el_d;          // e * (L - 1)
  logic              fits0_q, fits0_d, fits1_q, fits1_d;
  logic signed [RW-1:0] rp_q, rp_d;            // R after the next boundary's promotion
  logic              rvalid_q, rvalid_d;       // the ring word read was written since reset

  // ---- the ring RAM: {dc up, dc down, q*c (SPD_W + 1 bits)} per tick ----
  logic              ram_we, ram_re;
  logic [SPD_W+2:0]  ram_wdata, ram_rdata;
  prim_ram_1r1w #(.WIDTH(SPD_W + 3), .DEPTH(MAXLEN)) u_ring (
    .clk_i   (clk_i),
    .we_i    (ram_we),
    .waddr_i (idx_q),
    .wdata_i (ram_wdata),
    .re_i    (ram_re),
    .raddr_i (idx_q),
    .rdata_o (ram_rdata)
  );

  // ---- what the next boundary promotes (fixed for the whole tick) ----
  logic moving, r_done, promote, cur_p, busy, rest, boundary;
  logic [LVL_W-1:0] tgt_p, end_p;
  assign moving   = (c_q != '0) || (v_q != '0);
  assign r_done   = (r_q <= 0);
  assign promote  = (!cur_q || r_done) && next_q;
  assign cur_p    = promote || (cur_q && !r_done);
  assign tgt_p    = promote ? next_tgt_q : cur_tgt_q;
  assign end_p    = promote ? next_end_q : cur_end_q;
  assign busy     = cur_q || next_q || pend_q || (v_q != '0) || ({1'b0, quiet_q} <= {2'b0, len_q});
  assign rest     = !busy;
  assign boundary = (t_q == '0);

  // w_hold: ticks c must still hold before a -1 may follow the last +1
  logic [LEN_W:0] w_hold;
  assign w_hold = ({1'b0, up_age_q} >= {2'b0, len_q}) ? '0 : len_q - up_age_q[LEN_W:0];

  // ---- the sequencer's operands ----
  logic [XW-1:0] x0, x1, bc1x2;
  // 2 B(c+1, e) = 2 B(c, e) + 2c when c >= e, else 0
  assign bc1x2 = (c_q >= end_p) ? XW'(brk2_q) + XW'({c_q, 1'b0}) : '0;
  // X0 = 2 (c (1 + w) + B(c, e)) + e (L - 1); X1 the same for c + 1 and w = L
  assign x0 = XW'({cw_q, 1'b0}) + XW'(brk2_q) + XW'(el_q);
  assign x1 = XW'({cl_q, 1'b0}) + XW'({len_q, 1'b0}) + XW'(2) + bc1x2 + XW'(el_q);

  logic [LVL_W-1:0] c_minus_e;
  assign c_minus_e = c_q - end_p;

  logic signed [CW-1:0] r2;  // 2 R after promotion, for the compares
  assign r2 = CW'(rp_q) <<< 1;

  always_comb begin
    ph_d    = ph_q;
    load_d  = 1'b0;
    cnt_d   = cnt_q;
    mul_a_d = mul_a_q;
    mul_b_d = mul_b_q;
    mul_p_d = mul_p_q;
    ql_d    = ql_q;
    qc_d    = qc_q;
    qlc_d   = qlc_q;
    brk2_d  = brk2_q;
    cw_d    = cw_q;
    cl_d    = cl_q;
    el_d    = el_q;
    fits0_d = fits0_q;
    fits1_d = fits1_q;
    rp_d    = rp_q;
    if (t_q == TICK_W'(1)) begin
      // Start: the promotion's R, then phase 1.
      if (promote) rp_d = (cur_q && moving) ? r_q + (RW'(next_ops_q) <<< RSH) : (RW'(next_ops_q) <<< RSH);
      else rp_d = r_q;
      ph_d   = 4'd1;
      load_d = 1'b1;
    end else if (load_q) begin
      mul_p_d = '0;
      unique case (ph_q)
        4'd1: begin mul_a_d = MW'(q_q);   mul_b_d = XW'(len_q);  cnt_d = 6'(LEN_W + 1); end
        4'd2: begin mul_a_d = MW'(q_q);   mul_b_d = XW'(c_q);    cnt_d = 6'(LVL_W); end
        4'd3: begin mul_a_d = MW'(ql_q);  mul_b_d = XW'(c_q);    cnt_d = 6'(LVL_W); end
        4'd4: begin
          mul_a_d = (c_q > end_p) ? MW'(c_q) + MW'(end_p) - MW'(1) : '0;
          mul_b_d = XW'(c_minus_e);
          cnt_d   = 6'(LVL_W);
        end
        4'd5: begin mul_a_d = MW'(c_q);   mul_b_d = XW'(w_hold) + XW'(1); cnt_d = 6'(LEN_W + 2); end
        4'd6: begin mul_a_d = MW'(c_q);   mul_b_d = XW'(len_q) + XW'(1);  cnt_d = 6'(LEN_W + 2); end
        4'd7: begin mul_a_d = MW'(end_p); mul_b_d = XW'(len_q) - XW'(1);  cnt_d = 6'(LEN_W + 1); end
        4'd8: begin mul_a_d = MW'(ql_q);  mul_b_d = x0;          cnt_d = 6'(XW); end
        4'd9: begin mul_a_d = MW'(ql_q);  mul_b_d = x1;          cnt_d = 6'(XW); end
        default: begin mul_a_d = '0;      mul_b_d = '0;          cnt_d = '0; end
      endcase
    end else if (cnt_q != '0) begin
      // One bit a clock, the multiplier's LSB first.
      if (mul_b_q[0]) mul_p_d = mul_p_q + mul_a_q;
      mul_a_d = mul_a_q << 1;
      mul_b_d = mul_b_q >> 1;
      cnt_d   = cnt_q - 6'd1;
    end else if (ph_q >= 4'd1 && ph_q <= 4'd9) begin
      // Phase ph_q done: keep its product, then the next phase.
      unique case (ph_q)
        4'd1: ql_d   = QL_W'(mul_p_q);
        4'd2: qc_d   = (SPD_W + 1)'(mul_p_q);
        4'd3: qlc_d  = RW'(mul_p_q);
        4'd4: brk2_d = (2 * LVL_W + 1)'(mul_p_q);
        4'd5: cw_d   = (LVL_W + LEN_W + 2)'(mul_p_q);
        4'd6: cl_d   = (LVL_W + LEN_W + 2)'(mul_p_q);
        4'd7: el_d   = (LVL_W + LEN_W + 1)'(mul_p_q);
        4'd8: fits0_d = !rp_q[RW-1] && (CW'(mul_p_q) <= r2);
        4'd9: fits1_d = !rp_q[RW-1] && (CW'(mul_p_q) <= r2);
        default: ;
      endcase
      ph_d   = ph_q + 4'd1;
      load_d = (ph_q != 4'd9);
    end
  end

  // ---- the boundary: the level's step, R, the speed, the ring ----
  logic free, up_ok, down_ok, fits0, fits1, go_up, go_down, rd_up, rd_dn;
  logic [LVL_W-1:0] floor_lvl, tgt_e, end_e;
  logic [SPD_W:0]   qc_old;
  logic [SPD_W:0]   qc_new;
  logic [RW-1:0]    qlc_new;
  assign free      = hold_i || !cur_p;
  assign tgt_e     = free ? '0 : tgt_p;
  assign end_e     = free ? '0 : end_p;
  assign floor_lvl = (end_e != '0) ? end_e : (free ? '0 : LVL_W'(1));
  assign rd_up     = rvalid_q && ram_rdata[SPD_W+2];
  assign rd_dn     = rvalid_q && ram_rdata[SPD_W+1];
  assign qc_old    = rvalid_q ? ram_rdata[SPD_W:0] : '0;
  assign up_ok     = !rd_dn;
  assign down_ok   = !rd_up;
  assign fits0     = free || fits0_q;
  assign fits1     = free || fits1_q;
  assign go_up     = (c_q < tgt_e) && up_ok && (c_q != '1) && (fits1 || (c_q == '0));
  assign go_down   = !go_up && (c_q != '0) && down_ok &&
                     ((c_q > tgt_e) || ((c_q > floor_lvl) && !fits0));
  assign qc_new    = go_up ? qc_q + (SPD_W + 1)'(q_q) :
                     go_down ? qc_q - (SPD_W + 1)'(q_q) : qc_q;
  assign qlc_new   = go_up ? qlc_q + RW'(ql_q) :
                     go_down ? qlc_q - RW'(ql_q) : qlc_q;
  assign ram_we    = boundary;
  assign ram_wdata = {go_up, go_down, qc_new};
  assign ram_re    = (t_q == TICK_W'(1));

  logic [DROP:0] dsum;
  assign dsum = {1'b0, acc_q} + {1'b0, v_q[DROP-1:0]};

  always_comb begin
    t_d        = t_q + TICK_W'(1);
    acc_d      = dsum[DROP-1:0];
    feed_d     = v_q[SPD_W:DROP] + (FEED_W + 1)'(dsum[DROP]);
    v_d        = v_q;
    c_d        = c_q;
    idx_d      = idx_q;
    hw_d       = hw_q;
    up_age_d   = up_age_q;
    quiet_d    = quiet_q;
    r_d        = r_q;
    cur_d      = cur_q;
    next_d     = next_q;
    pend_d     = pend_q;
    cur_tgt_d  = cur_tgt_q;
    cur_end_d  = cur_end_q;
    next_ops_d = next_ops_q;
    next_tgt_d = next_tgt_q;
    next_end_d = next_end_q;
    pend_ops_d = pend_ops_q;
    pend_tgt_d = pend_tgt_q;
    pend_end_d = pend_end_q;
    q_d        = q_q;
    len_d      = len_q;
    rvalid_d   = rvalid_q;
    if (ram_re) rvalid_d = ({1'b0, idx_q} < hw_q);
    if (boundary) begin
      // Commands: next -> current, then pending -> next.
      cur_d = cur_p;
      if (promote) begin
        cur_tgt_d = next_tgt_q;
        cur_end_d = next_end_q;
      end
      next_d = next_q && !promote;
      if (!next_d && pend_q) begin
        next_d     = 1'b1;
        next_ops_d = pend_ops_q;
        next_tgt_d = pend_tgt_q;
        next_end_d = pend_end_q;
        pend_d     = 1'b0;
      end
      r_d = cur_p ? rp_q - $signed(qlc_new) : rp_q;
      c_d = go_up ? c_q + LVL_W'(1) : (go_down ? c_q - LVL_W'(1) : c_q);
      v_d = v_q + qc_new - qc_old;
      idx_d = ({1'b0, idx_q} + (LEN_W + 1)'(1) == len_q) ? '0 : idx_q + LEN_W'(1);
      if ({1'b0, idx_q} >= hw_q) hw_d = {1'b0, idx_q} + (LEN_W + 1)'(1);
      up_age_d = go_up ? AGE_W'(1) :
                 (({1'b0, up_age_q} > (AGE_W + 1)'(MAXLEN)) ? up_age_q : up_age_q + AGE_W'(1));
      quiet_d  = (go_up || go_down) ? AGE_W'(1) :
                 (({1'b0, quiet_q} > (AGE_W + 1)'(MAXLEN)) ? quiet_q : quiet_q + AGE_W'(1));
    end
    if (cmd_valid_i && !pend_q) begin
      pend_d     = 1'b1;
      pend_ops_d = cmd_ops_i;
      pend_tgt_d = cmd_target_i;
      pend_end_d = cmd_end_i;
    end
    if (rest) begin
      q_d   = q_i;
      len_d = (len_i == '0) ? (LEN_W + 1)'(1) :
              ((len_i > (LEN_W + 1)'(MAXLEN)) ? (LEN_W + 1)'(MAXLEN) : len_i);
      idx_d = '0;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      t_q        <= '0;
      v_q        <= '0;
      acc_q      <= '0;
      feed_q     <= '0;
      c_q        <= '0;
      idx_q      <= '0;
      hw_q       <= '0;
      up_age_q   <= '1;  // any count above MAXLEN is "long ago"; it stays there
      quiet_q    <= '1;
      r_q        <= '0;
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
      ph_q       <= '0;
      load_q     <= 1'b0;
      cnt_q      <= '0;
      mul_a_q    <= '0;
      mul_b_q    <= '0;
      mul_p_q    <= '0;
      ql_q       <= '0;
      qc_q       <= '0;
      qlc_q      <= '0;
      brk2_q     <= '0;
      cw_q       <= '0;
      cl_q       <= '0;
      el_q       <= '0;
      fits0_q    <= 1'b0;
      fits1_q    <= 1'b0;
      rp_q       <= '0;
      rvalid_q   <= 1'b0;
    end else begin
      t_q        <= t_d;
      v_q        <= v_d;
      acc_q      <= acc_d;
      feed_q     <= feed_d;
      c_q        <= c_d;
      idx_q      <= idx_d;
      hw_q       <= hw_d;
      up_age_q   <= up_age_d;
      quiet_q    <= quiet_d;
      r_q        <= r_d;
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
      ph_q       <= ph_d;
      load_q     <= load_d;
      cnt_q      <= cnt_d;
      mul_a_q    <= mul_a_d;
      mul_b_q    <= mul_b_d;
      mul_p_q    <= mul_p_d;
      ql_q       <= ql_d;
      qc_q       <= qc_d;
      qlc_q      <= qlc_d;
      brk2_q     <= brk2_d;
      cw_q       <= cw_d;
      cl_q       <= cl_d;
      el_q       <= el_d;
      fits0_q    <= fits0_d;
      fits1_q    <= fits1_d;
      rp_q       <= rp_d;
      rvalid_q   <= rvalid_d;
    end
  end

  assign cmd_ready_o = !pend_q;
  assign feed_o      = feed_q;
  assign level_o     = c_q;
  assign speed_o     = v_q;
  assign busy_o      = busy;
endmodule

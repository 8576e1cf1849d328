// Formal environment of feed_profile (scripts/formal.sh --blocks
// feed_profile): the block with narrow parameters and every input free on
// every clock (the configuration pins, the moves, hold_i, ovr_i), reset in the first
// cycle only. BMC from reset and k-induction (the properties hold at every
// depth):
//   a_reset   the clock after reset: speed 0, level 0, not busy, ready;
//   a_level   the level changes only on the clock after a tick boundary (at
//             most once a tick), and by +1 or -1;
//   a_hold    with hold_i high on a boundary the level does not rise (the
//             block's choice "up" for hold_i high is never set: a_gu1);
//   a_speed   the speed changes only on the clock after a tick boundary;
//   a_feed    the feed word is the speed's top FEED_W + 1 bits or one more
//             (the dither's carry);
//   a_ready   cmd_ready_o is low exactly while a move waits in the pending
//             slot, and busy_o is high while a move is pending, next or
//             current, or the speed is not 0;
//   a_vnz     the block's flags "speed not 0" and "candidate speed not 0"
//             equal the ORs of those registers (busy_o uses the flag);
//   a_busy    busy_o (a register, computed from the next state) is exactly
//             "a move pending, next or current, or the speed not 0, or a
//             step of the level within the last L ticks" (a_qinc: the
//             increment of quiet it reads at boundaries is computed ahead;
//             a_bnd: the boundary flag is t = 0; a_len: 1 <= L <= 2^LEN_W);
//   a_take    a move taken (valid and ready) is in the pending slot on the
//             next clock, with its fields (its cap: cmd_max_i, or the target if 0);
//   a_ovr     the override word in force is at most 256 (200 %) and changes
//             only on the clock after a tick boundary, to ovr_i saturated;
//   a_pend    a pending move stays, unchanged, until a boundary moves it to
//             the next slot, unchanged: it is never overwritten or dropped;
//   a_next    a next move stays, unchanged, until a boundary promotes it to
//             the current one (target and end level); a promotion always
//             makes a current move (a_curp).
// Not here: the speed bound (v <= 2^SPD_W while q * L * target <= 2^SPD_W)
// and the braking rule span a whole tick and the ring's L words, beyond what
// induction over these registers closes; tests/hls/feed_profile_test.cpp
// checks them, and tests/hls/feed_profile_rtl_test.cpp that the RTL equals
// hls/feed_profile.h on every clock.
// scripts/formal.sh flattens the design and connects each wire of a
// `// link:` line to the block's register (Yosys 0.23 has neither `bind` nor
// hierarchical references):
// link: f_bnd=dut.bnd_q f_pend=dut.pend_q f_next=dut.next_q f_cur=dut.cur_q f_promote=dut.promote_q
// link: f_pend_ops=dut.pend_ops_q f_pend_tgt=dut.pend_tgt_q f_pend_end=dut.pend_end_q
// link: f_next_ops=dut.next_ops_q f_next_tgt=dut.next_tgt_q f_next_end=dut.next_end_q
// link: f_cur_tgt=dut.cur_tgt_q f_cur_end=dut.cur_end_q f_gu1=dut.gu_q[1]
// link: f_curp=dut.curp_q f_pend_top=dut.pend_top_q f_ovr=dut.ovr_q
// link: f_vnz=dut.vnz_q f_vn0nz=dut.vn0nz_q f_vn1nz=dut.vn1nz_q f_vn0=dut.vn0_q f_vn1=dut.vn1_q
// link: f_quiet=dut.quiet_q f_len=dut.len_q f_qinc=dut.qinc_q f_t=dut.t_q
// SPD_W = 8, TICK_W = 7 (the sequencer needs 91 of its 128 clocks at these
// widths), levels 0..3, moves of up to 3 operations, L up to 2.
module feed_profile_props #(
  parameter int FEED_W = 2,
  parameter int SPD_W  = 8,
  parameter int TICK_W = 7,
  parameter int LEN_W  = 1,
  parameter int LVL_W  = 2,
  parameter int OPS_W  = 2
) (
  input logic              clk_i,
  input logic              rst_ni,
  input logic [SPD_W-1:0]  q_i,
  input logic [LEN_W:0]    len_i,
  input logic              cmd_valid_i,
  input logic [OPS_W-1:0]  cmd_ops_i,
  input logic [LVL_W-1:0]  cmd_target_i,
  input logic [LVL_W-1:0]  cmd_end_i,
  input logic [LVL_W-1:0]  cmd_max_i,
  input logic              hold_i,
  input logic [8:0]        ovr_i
);
  localparam int DROP = SPD_W - FEED_W;

  logic              cmd_ready, busy;
  logic [FEED_W:0]   feed;
  logic [LVL_W-1:0]  level;
  logic [SPD_W:0]    speed;

  feed_profile #(
    .FEED_W(FEED_W),
    .SPD_W (SPD_W),
    .TICK_W(TICK_W),
    .LEN_W (LEN_W),
    .LVL_W (LVL_W),
    .OPS_W (OPS_W)
  ) dut (
    .clk_i,
    .rst_ni,
    .q_i,
    .len_i,
    .cmd_valid_i,
    .cmd_ready_o(cmd_ready),
    .cmd_ops_i,
    .cmd_target_i,
    .cmd_end_i,
    .cmd_max_i,
    .hold_i,
    .ovr_i,
    .feed_o     (feed),
    .level_o    (level),
    .speed_o    (speed),
    .busy_o     (busy)
  );

  // The block's registers (connected by scripts/formal.sh, see above).
  logic             f_bnd, f_pend, f_next, f_cur, f_promote, f_gu1, f_curp;
  logic [OPS_W-1:0] f_pend_ops, f_next_ops;
  logic [LVL_W-1:0] f_pend_tgt, f_pend_end, f_next_tgt, f_next_end, f_cur_tgt, f_cur_end;
  logic [LVL_W-1:0] f_pend_top;
  logic [8:0]       f_ovr;
  logic             f_vnz, f_vn0nz, f_vn1nz;
  logic [LEN_W+1:0] f_quiet, f_qinc;
  logic [LEN_W:0]   f_len;
  logic [TICK_W-1:0] f_t;
  logic [SPD_W:0]   f_vn0, f_vn1;

  // Their values and the inputs' on the clock before.
  logic             p_bnd, p_hold, p_take, p_pend, p_next, p_promote;
  logic [OPS_W-1:0] p_ops, p_pend_ops, p_next_ops;
  logic [LVL_W-1:0] p_tgt, p_end, p_pend_tgt, p_pend_end, p_next_tgt, p_next_end, p_level;
  logic [SPD_W:0]   p_speed;
  logic [LVL_W-1:0] p_max;
  logic [8:0]       p_ovr, p_ovr_i;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      p_bnd      <= 1'b0;
      p_hold     <= 1'b0;
      p_take     <= 1'b0;
      p_pend     <= 1'b0;
      p_next     <= 1'b0;
      p_promote  <= 1'b0;
      p_ops      <= '0;
      p_tgt      <= '0;
      p_end      <= '0;
      p_pend_ops <= '0;
      p_pend_tgt <= '0;
      p_pend_end <= '0;
      p_next_ops <= '0;
      p_next_tgt <= '0;
      p_next_end <= '0;
      p_level    <= '0;
      p_speed    <= '0;
      p_max      <= '0;
      p_ovr      <= 9'd128;
      p_ovr_i    <= '0;
    end else begin
      p_bnd      <= f_bnd;
      p_hold     <= hold_i;
      p_take     <= cmd_valid_i && cmd_ready;
      p_pend     <= f_pend;
      p_next     <= f_next;
      p_promote  <= f_promote;
      p_ops      <= cmd_ops_i;
      p_tgt      <= cmd_target_i;
      p_end      <= cmd_end_i;
      p_pend_ops <= f_pend_ops;
      p_pend_tgt <= f_pend_tgt;
      p_pend_end <= f_pend_end;
      p_next_ops <= f_next_ops;
      p_next_tgt <= f_next_tgt;
      p_next_end <= f_next_end;
      p_level    <= level;
      p_speed    <= speed;
      p_max      <= cmd_max_i;
      p_ovr      <= f_ovr;
      p_ovr_i    <= ovr_i;
    end
  end

  // Reset in the first cycle only; f_after: the first clock after it.
  logic f_init = 1'b1;
  logic f_after = 1'b0;
  always_ff @(posedge clk_i) begin
    f_init  <= 1'b0;
    f_after <= f_init;
  end

  logic [FEED_W:0] p_vhi;
  assign p_vhi = p_speed[SPD_W:DROP];

  always_comb begin
    assume(rst_ni == !f_init);
    if (f_after) a_reset: assert(speed == '0 && level == '0 && !busy && cmd_ready);
    if (!f_init) begin
      a_level: assert(level == p_level ||
                      (p_bnd && (level == p_level + LVL_W'(1) || level == p_level - LVL_W'(1))));
      a_gu1: assert(!f_gu1);
      a_curp: assert(!f_promote || f_curp);
      a_hold: assert(!(p_bnd && p_hold) || level == p_level || level == p_level - LVL_W'(1));
      a_speed: assert(speed == p_speed || p_bnd);
      a_feed: assert(feed == p_vhi || feed == p_vhi + (FEED_W + 1)'(1));
      a_take: assert(!p_take ||
                     (f_pend && f_pend_ops == p_ops && f_pend_tgt == p_tgt && f_pend_end == p_end &&
                      f_pend_top == ((p_max != '0) ? p_max : p_tgt)));
      a_ovr: assert(f_ovr <= 9'd256 &&
                    (p_bnd ? f_ovr == ((p_ovr_i > 9'd256) ? 9'd256 : p_ovr_i) : f_ovr == p_ovr));
      a_pend: assert(!p_pend ||
                     (f_pend && f_pend_ops == p_pend_ops && f_pend_tgt == p_pend_tgt &&
                      f_pend_end == p_pend_end) ||
                     (p_bnd && f_next && f_next_ops == p_pend_ops && f_next_tgt == p_pend_tgt &&
                      f_next_end == p_pend_end));
      a_next: assert(!p_next ||
                     (f_next && f_next_ops == p_next_ops && f_next_tgt == p_next_tgt &&
                      f_next_end == p_next_end) ||
                     (p_bnd && p_promote && f_cur && f_cur_tgt == p_next_tgt &&
                      f_cur_end == p_next_end));
    end
    a_bnd: assert(f_bnd == (f_t == '0));
    a_len: assert(f_len >= (LEN_W + 1)'(1) && f_len <= (LEN_W + 1)'(1 << LEN_W));
    // the increment computed ahead: stale only on the clock after a boundary
    if (!f_init) a_qinc: assert(p_bnd || f_qinc == (({1'b0, f_quiet} > (LEN_W + 3)'(1 << LEN_W)) ?
                                                  f_quiet : f_quiet + (LEN_W + 2)'(1)));
    a_busy: assert(busy == (f_pend || f_next || f_cur || speed != '0 ||
                            {1'b0, f_quiet} <= {2'b0, f_len}));
    a_vnz: assert(f_vnz == (speed != '0) && f_vn0nz == (f_vn0 != '0) && f_vn1nz == (f_vn1 != '0));
    a_ready: assert(cmd_ready == !f_pend && (!(f_pend || f_next || f_cur || speed != '0) || busy));
  end
endmodule

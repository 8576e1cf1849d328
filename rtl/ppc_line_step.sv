// ppc_line_step: the point-by-point comparison (PPC) line engine shared by
// ppc_line (its whole engine) and ppc_arc (its closing line). It holds one
// line of |dx|, |dy| steps and decides, per operation, which axis steps; the
// caller owns the directions, the feed and the step/dir stage.
//
// Rule (models::PpcLineRule::kGuarded, models/ppc.h): with F = y|dx| - x|dy|
// (x, y the steps taken so far), an operation steps x when
//   (F >= 0 and x has steps left) or y has none left,
// else y; an x step does F -= |dy|, a y step F += |dx|. Exactly |dx| + |dy|
// operations, each stepping one axis; axis-parallel lines (F stays 0) end
// exactly. -|dy| <= F < |dx| throughout, so F needs MAG_W + 1 signed bits.
// A zero-length line has one operation that steps nothing (last_o at once).
//
// Timing: the flags "x has steps left", "y has steps left" and "at most one
// step left in total" are registers, decided a clock ahead from the counters
// (each is the reduction of the counters it stands for, kept equal to it at
// every clock), so every output is one LUT of registers (a flag, F's sign):
// the caller's stall/advance logic never waits on a MAG_W-bit reduction. An
// operation is two MAG_W+1-bit adds (F after an x step, after a y step; the
// rule picks one) and a decrement.
module ppc_line_step #(
  parameter int MAG_W = 32  // width of the magnitudes |dx|, |dy| (unsigned), 3..62
) (
  input  logic             clk_i,      // clock
  input  logic             rst_ni,     // asynchronous, active low
  input  logic             load_i,     // start a line: |dx| = load_ax_i, |dy| = load_ay_i, F = 0
  input  logic [MAG_W-1:0] load_ax_i,  // |dx|
  input  logic [MAG_W-1:0] load_ay_i,  // |dy|
  // The load's flags, from the caller's registers (equal to the reductions of
  // load_a*_i whenever load_i is high): the flags' load then waits on no
  // MAG_W-bit reduction of what may be the caller's late arithmetic.
  input  logic [1:0]       load_nz_i,  // |dx| != 0 (bit 0), |dy| != 0 (bit 1)
  input  logic [1:0]       load_le1_i, // |dx| <= 1 (bit 0), |dy| <= 1 (bit 1)
  input  logic             advance_i,  // do this clock's operation (load_i wins over it)
  output logic             x_left_o,   // x still has steps to take
  output logic             y_left_o,   // y still has steps to take
  output logic             step_x_o,   // this clock's operation steps x
  output logic             step_y_o,   // this clock's operation steps y
  output logic             last_o      // this clock's operation is the line's last
);
  // Parameter check at elaboration: Verilator and Yosys stop with the message
  // (Icarus 11 has no elaboration system tasks: it skips the check). 3: the
  // flags' compares read bits 2 and up; 62: the range the HLS face
  // (hls/ppc_line_step.h), and so the lockstep verification, covers.
`ifndef __ICARUS__
  if (MAG_W < 3 || MAG_W > 62) begin : g_bad_mag_w
    $error("ppc_line_step: parameter MAG_W must be 3..62");
  end
`endif

  logic [MAG_W-1:0] ax_q, ax_d, ay_q, ay_d;  // |dx|, |dy| of the running line
  logic [MAG_W-1:0] xl_q, xl_d, yl_q, yl_d;  // steps left per axis
  logic [MAG_W:0]   f_q, f_d;  // F, two's complement
  logic [MAG_W:0]   f_x, f_y, f_step;  // F after an x step, after a y step, after this one
  logic             x_left_q, x_left_d, y_left_q, y_left_d;  // |xl_q, |yl_q
  logic             last_q, last_d;  // xl_q + yl_q <= 1
  logic             last_step;  // last_q after this clock's step
  logic             op;  // this clock's operation steps an axis
  logic             pick_x;  // the rule chooses x (it steps only if x has steps left)
  logic             ld_last;  // the loaded line has at most one step
  logic             xl_le2, yl_le2;  // xl_q <= 2, yl_q <= 2

  assign x_left_o = x_left_q;
  assign y_left_o = y_left_q;
  assign pick_x   = (!f_q[MAG_W] && x_left_q) || !y_left_q;
  assign step_x_o = pick_x && x_left_q;
  assign step_y_o = !pick_x;  // implies y_left_q
  // At most one step left in total (none: a zero-length line).
  assign last_o   = last_q;

  // x step: F - |dy|; y step: F + |dx|. Both sums from registers, the rule's
  // choice after them: pick_x selects a result instead of waiting at the
  // start of a MAG_W+1-bit carry chain (the price: one more adder).
  assign f_x = f_q - {1'b0, ay_q};
  assign f_y = f_q + {1'b0, ax_q};
  assign f_step = pick_x ? f_x : f_y;

  // The flags a clock ahead. After one step the total left is at most one
  // exactly when it is at most two now: xl + yl <= 2.
  assign ld_last = !(&load_nz_i) && (&load_le1_i);
  assign xl_le2  = (xl_q[MAG_W-1:2] == '0) && !(xl_q[1] && xl_q[0]);
  assign yl_le2  = (yl_q[MAG_W-1:2] == '0) && !(yl_q[1] && yl_q[0]);
  assign last_step = xl_le2 && yl_le2 && !(xl_q[1] && y_left_q) && !(yl_q[1] && x_left_q);
  assign op        = advance_i && (step_x_o || step_y_o);

  always_comb begin
    ax_d     = ax_q;
    ay_d     = ay_q;
    xl_d     = xl_q;
    yl_d     = yl_q;
    f_d      = f_q;
    x_left_d = x_left_q;
    y_left_d = y_left_q;
    last_d   = last_q;
    if (load_i) begin
      ax_d     = load_ax_i;
      ay_d     = load_ay_i;
      xl_d     = load_ax_i;
      yl_d     = load_ay_i;
      f_d      = '0;
      x_left_d = load_nz_i[0];
      y_left_d = load_nz_i[1];
      last_d   = ld_last;
    end else if (op) begin
      f_d    = f_step;
      last_d = last_step;
      if (step_x_o) begin
        xl_d     = xl_q - MAG_W'(1);
        x_left_d = |xl_q[MAG_W-1:1];  // xl_q >= 1: xl_q - 1 != 0 iff xl_q >= 2
      end else begin
        yl_d     = yl_q - MAG_W'(1);
        y_left_d = |yl_q[MAG_W-1:1];
      end
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ax_q     <= '0;
      ay_q     <= '0;
      xl_q     <= '0;
      yl_q     <= '0;
      f_q      <= '0;
      x_left_q <= 1'b0;
      y_left_q <= 1'b0;
      last_q   <= 1'b1;
    end else begin
      ax_q     <= ax_d;
      ay_q     <= ay_d;
      xl_q     <= xl_d;
      yl_q     <= yl_d;
      f_q      <= f_d;
      x_left_q <= x_left_d;
      y_left_q <= y_left_d;
      last_q   <= last_d;
    end
  end

`ifdef FORMAL
  // Formal (scripts/formal.sh, in ppc_line's and ppc_arc's proofs): each
  // flag equals the reduction of the counters it stands for, at every clock
  // since a load whose flags were the reductions of the load (the caller's
  // promise: ppc_line passes the reductions themselves; ppc_arc_engine its
  // flags of g, equal to them for every command its widths accept).
  logic           f_ld_ok, f_ld_ok_q, f_ld_ok_d;
  logic [MAG_W:0] f_total;  // steps left in total
  assign f_ld_ok   = load_nz_i == {load_ay_i != '0, load_ax_i != '0} &&
                     load_le1_i == {load_ay_i <= MAG_W'(1), load_ax_i <= MAG_W'(1)};
  assign f_ld_ok_d = load_i ? f_ld_ok : f_ld_ok_q;
  assign f_total   = {1'b0, xl_q} + {1'b0, yl_q};
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) f_ld_ok_q <= 1'b1;
    else f_ld_ok_q <= f_ld_ok_d;
  end
  always_comb begin
    if (rst_ni) begin
      a_flags: assert(!f_ld_ok_q || (x_left_q == (xl_q != '0) && y_left_q == (yl_q != '0) &&
                                     last_q == (f_total <= (MAG_W + 1)'(1))));
    end
  end
`endif
endmodule

// Step/dir output stage of one axis (the hostmot2 timing set).
//
// Run-time settings, in clock cycles; a setting of 0 acts as 1:
//   step_len     step_o high for exactly max(step_len, 1) cycles
//   step_space   step_o low for at least max(step_space, 1) cycles between pulses
//   dir_setup    dir_o stable at least max(dir_setup, 1) cycles before step_o rises
//   dir_hold     dir_o stable at least max(dir_hold, 1) cycles after step_o falls
// A phase takes the setting of the clock it starts on and keeps it: a pulse
// the step_len of the clock that fires it, the space and the hold the values
// of the clock the pulse falls on, the setup the value of the clock dir_o
// turns on. (With settings that do not change, this is the same as checking
// every clock.) The stage never violates them: ready_o says whether a pulse
// may start on the next clock, and the engine only fires a ready axis (it
// stalls otherwise), so no step is ever lost.
//
// dir_o follows want_dir_i by itself as soon as the hold time allows it, so
// a reversal costs only the hold + setup times, not a round trip.
//
// Reset (asynchronous) is not a safe stop: it ends a pulse at once and sets
// dir_o to 0 whatever it was (abort_i of the core is the safe stop). The stage
// then counts the reset as the end of a pulse and as a change of dir_o: the
// first pulse after reset waits step_space and dir_setup, and a turn of dir_o
// waits dir_hold, counted from the reset with the settings of the first clock
// after it. On that first clock the axis is not ready and does not turn
// (no core runs a command on it).
// dir_o = 0 means positive motion, 1 negative (the sign bit of the delta).
//
// ready_o answers for a pulse in the direction want_dir_i, whether or not
// want_valid_i asks for one (the engine fires only axes its command moves).
//
// Timing: every compare a clock needs is decided a clock ahead into a flag
// register (tim_one_q, hold_ok_q, setup_ok_q), and the counters count down
// to 1 (no compare against a setting). ready_o is decided a clock ahead too:
// READY_Q = 0, for either direction (ok_pos_q, ok_neg_q), selected by
// want_dir_i; READY_Q = 1, as one register for the direction the engine
// says on want_dir_next_i it will want on the next clock (the same values).
// With READY_Q = 1 the stage also says, as a register, whether the engine
// must stall for this axis (block_o: the engine wants a pulse now, as it said
// on want_step_next_i a clock ago, and ready_o is low), so the engine's stall
// is an OR of registers, one per axis, not a tree of wants and readies.
// fire_i, the engine's late signal, enters the next state only at its last
// gate. The settings arrive prepared once for all axes by
// rtl/stepdir_timing.sv.
module stepdir_axis #(
  parameter int TIM_W   = 16,   // width of the settings and counters (>= 2)
  parameter bit READY_Q = 1'b0  // 1: ready_o a register, from want_dir_next_i (0 or 1)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  // The settings, each at least 1, and their compares (rtl/stepdir_timing.sv)
  input  logic [TIM_W-1:0] len_i,
  input  logic [TIM_W-1:0] space_i,
  input  logic [TIM_W-1:0] setup_i,
  input  logic [TIM_W-1:0] hold_i,
  input  logic             len_one_i,    // len_i == 1
  input  logic             space_one_i,  // space_i == 1
  input  logic             setup_one_i,  // setup_i == 1
  input  logic             hold_one_i,   // hold_i == 1
  input  logic             space_two_i,  // space_i <= 2
  input  logic             setup_two_i,  // setup_i <= 2
  input  logic             hold_two_i,   // hold_i <= 2
  input  logic             fresh_i,      // the first clock after reset
  // The engine
  input  logic             want_valid_i,  // the active command moves this axis...
  input  logic             want_dir_i,    // ...in this direction
  input  logic             want_dir_next_i,  // want_dir_i of the next clock (READY_Q = 1; else unused)
  input  logic             want_step_next_i,  // the engine wants a pulse on the next clock (READY_Q = 1; else unused)
  input  logic             fire_i,        // start a pulse next clock (only when ready_o)
  output logic             ready_o,
  output logic             block_o,       // a pulse wanted (want_step_next_i a clock ago) and not ready_o (READY_Q = 1; else 0)
  // The pins
  output logic             step_o,
  output logic             dir_o
);
  // Parameter check at elaboration: Verilator and Yosys stop with the message
  // (Icarus 11 has no elaboration system tasks: it skips the check).
`ifndef __ICARUS__
  if (TIM_W < 2) begin : g_bad_tim_w
    $error("stepdir_axis: parameter TIM_W must be >= 2");
  end
`endif

  localparam logic [TIM_W-1:0] One = TIM_W'(1);

  // tim_q: while step_o is high, its cycles left, this one included; while
  // low, the space still to wait, plus one. hold_q and setup_q likewise count
  // the hold (from the fall) and the setup (from the turn) down to 1. Until
  // the first pulse (first turn) after reset, tim_q and hold_q (setup_q) are
  // one more than that (v_q, w_q): they start on the first clock after
  // reset, which counts as the first clock of the phases the reset began.
  logic             step_q, step_d;
  logic             dir_q, dir_d;
  logic [TIM_W-1:0] tim_q, tim_d;
  logic [TIM_W-1:0] hold_q, hold_d;
  logic [TIM_W-1:0] setup_q, setup_d;
  logic             v_q, v_d;
  logic             w_q, w_d;
  // Flags, each a compare of the counters above decided a clock ahead.
  logic             tim_one_q, tim_one_d;  // tim (without v) <= 1: last high cycle / space done
  logic             hold_ok_q, hold_ok_d;  // step_o low and the hold done: dir_o may turn
  logic             setup_ok_q, setup_ok_d;  // the setup done

  // c - off <= 2 for a counter c with offset off (0 or 1).
  function automatic logic le2_off(input logic [TIM_W-1:0] c, input logic off);
    le2_off = ((c >> 2) == '0) && (off || !(c[1] && c[0]));
  endfunction

  logic turn;
  assign turn    = hold_ok_q && want_valid_i && (want_dir_i != dir_q);

  // The next state in two parts: what it would be without a pulse starting
  // (the _nf values, from registers and want_* only), and fire_i, the
  // engine's late signal, choosing at the end.
  logic             step_nf, v_nf, tim_one_nf, hold_ok_nf, pulse_nf;
  logic [TIM_W-1:0] tim_nf;
  always_comb begin
    step_nf    = step_q;
    tim_nf     = tim_q;
    hold_d     = hold_q;
    v_nf       = v_q;
    tim_one_nf = tim_one_q;
    hold_ok_nf = hold_ok_q;
    if (fresh_i) begin
      // The reset ended a pulse one clock ago.
      tim_nf     = space_i;
      hold_d     = hold_i;
      tim_one_nf = space_two_i;
      hold_ok_nf = hold_two_i;
    end else if (step_q) begin
      if (tim_one_q) begin
        step_nf    = 1'b0;
        tim_nf     = space_i;
        hold_d     = hold_i;
        v_nf       = 1'b0;
        tim_one_nf = space_one_i;
        hold_ok_nf = hold_one_i;
      end else begin
        tim_nf     = tim_q - One;
        tim_one_nf = le2_off(tim_q, 1'b0);
      end
    end else begin
      if (!tim_one_q) begin
        tim_nf     = tim_q - One;
        tim_one_nf = le2_off(tim_q, v_q);
      end
      // (A pulse starting now leaves the hold count to the fall, which reloads it.)
      if (!hold_ok_q) begin
        hold_d     = hold_q - One;
        hold_ok_nf = le2_off(hold_q, v_q);
      end
    end

    dir_d      = dir_q;
    setup_d    = setup_q;
    w_d        = w_q;
    setup_ok_d = setup_ok_q;
    if (fresh_i) begin
      setup_d    = setup_i;
      setup_ok_d = setup_two_i;
    end else if (turn) begin
      dir_d      = want_dir_i;
      setup_d    = setup_i;
      w_d        = 1'b0;
      setup_ok_d = setup_one_i;
    end else if (!setup_ok_q) begin
      setup_d    = setup_q - One;
      setup_ok_d = le2_off(setup_q, w_q);
    end
    pulse_nf = !step_nf && tim_one_nf && setup_ok_d;
  end

  // fire_i only ever comes with step_q low (a ready axis).
  assign step_d    = step_nf || fire_i;
  assign tim_d     = fire_i ? len_i : tim_nf;
  assign v_d       = v_nf && !fire_i;
  assign tim_one_d = fire_i ? len_one_i : tim_one_nf;
  assign hold_ok_d = hold_ok_nf && !fire_i;

  // ready_o: a pulse may start (step_o low, space and setup done) and dir_o
  // is the direction wanted.
  if (READY_Q) begin : g_ready_q
    // Decided a clock ahead, for the direction wanted on the next clock.
    logic ready_q, ready_d, block_q, block_d;
    assign ready_d = pulse_nf && !fire_i && (want_dir_next_i == dir_d);
    assign block_d = want_step_next_i && !ready_d;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        ready_q <= 1'b0;
        block_q <= 1'b0;
      end else begin
        ready_q <= ready_d;
        block_q <= block_d;
      end
    end
    assign ready_o = ready_q;
    assign block_o = block_q;
  end else begin : g_ready_mux
    // Decided a clock ahead for either direction, selected by want_dir_i.
    logic unused_next;  // no prediction in this mode
    logic ok_pos_q, ok_pos_d, ok_neg_q, ok_neg_d;  // with dir_o = 0, with dir_o = 1
    assign unused_next = want_dir_next_i ^ want_step_next_i;
    assign block_o     = 1'b0;
    assign ok_pos_d    = pulse_nf && !fire_i && !dir_d;
    assign ok_neg_d    = pulse_nf && !fire_i && dir_d;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        ok_pos_q <= 1'b0;
        ok_neg_q <= 1'b0;
      end else begin
        ok_pos_q <= ok_pos_d;
        ok_neg_q <= ok_neg_d;
      end
    end
    assign ready_o = want_dir_i ? ok_neg_q : ok_pos_q;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      step_q     <= 1'b0;
      dir_q      <= 1'b0;
      tim_q      <= '0;
      hold_q     <= '0;
      setup_q    <= '0;
      v_q        <= 1'b1;
      w_q        <= 1'b1;
      tim_one_q  <= 1'b0;
      hold_ok_q  <= 1'b0;
      setup_ok_q <= 1'b0;
    end else begin
      step_q     <= step_d;
      dir_q      <= dir_d;
      tim_q      <= tim_d;
      hold_q     <= hold_d;
      setup_q    <= setup_d;
      v_q        <= v_d;
      w_q        <= w_d;
      tim_one_q  <= tim_one_d;
      hold_ok_q  <= hold_ok_d;
      setup_ok_q <= setup_ok_d;
    end
  end

  assign step_o = step_q;
  assign dir_o  = dir_q;

`ifdef FORMAL
  // Formal (scripts/formal.sh): the engine's side of the contract above, an
  // assumption in rtl/formal/stepdir_axis_props.sv and step_stage_props.sv,
  // proved in every core's proof: the engine fires only a ready axis, and
  // with READY_Q = 1 its want_dir_next_i was right (from the second clock
  // after reset; on the first ready_o is low).
  logic f_want_dir_next_q, f_want_dir_next_d;
  assign f_want_dir_next_d = want_dir_next_i;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) f_want_dir_next_q <= 1'b0;
    else f_want_dir_next_q <= f_want_dir_next_d;
  end
  always_comb begin
    if (rst_ni) begin
      a_fire_ready: assert(!fire_i || ready_o);
      a_dir_next: assert(!READY_Q || fresh_i || want_dir_i == f_want_dir_next_q);
    end
  end
`endif
endmodule

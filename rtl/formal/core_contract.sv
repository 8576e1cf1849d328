// The port contract every core shares (README, "The port contract every core
// shares"; each core's header), as properties of its ports, for
// scripts/formal.sh (Yosys read_verilog -formal, yosys-smtbmc).
//
// A core instantiates this checker inside its `ifdef FORMAL` block, or its
// props file attaches it through rtl/formal/core_checks.sv (Yosys 0.23 has
// neither `bind` nor hierarchical references: scripts/formal.sh connects the
// props file's wires to the core's signals), on the core's ports and one
// number from its registers: held_i, the commands it holds (taken and
// neither completed nor dropped by an abort: its buffer entries and the
// running command). The checker counts the same from the ports alone,
//   pend   commands taken (cmd_valid_i && cmd_ready_o at an edge) minus those
//          completed (done_o) since the last abort edge (which drops every
//          command, one taken on that same edge too);
//   held   pend without the command whose done_o is high this clock,
// and asserts:
//   a_link       held == held_i (and pend >= done_o): a taken command stays
//                in the core until its done_o or an abort, never dropped,
//                never doubled; done_o never comes without a command;
//   a_cap        held <= CAP: the core never takes a command it has no room for;
//   a_busy       busy_o == (held != 0 || a step_o high): busy exactly while a
//                command is held or a pulse is high;
//   a_done       done_o only after a clock with busy_o high;
//   a_rise       a step_o rises only on the clock after one that held a
//                command and had no abort (no step from an idle core, none
//                from an abort edge);
//   a_abort      from the clock after an abort edge until the next taken
//                command: nothing held, no done_o, no step_o rising;
//   a_abort_len  k clocks after an abort edge (and no command taken since),
//                busy_o only while some axis still has the pulse that was
//                high at the edge, with k <= L - 1 (L: that pulse's
//                max(step_len_i, 1) of the clock that fired it): busy_o falls
//                at most L - 1 clocks after the abort edge;
//   a_len        every pulse is high for exactly its L clocks, across aborts:
//                a pulse already high at an abort keeps its length.
// No assumption on any input; the caller assumes only a reset in the first
// cycle.
module core_contract #(
  parameter int AXES   = 2,  // axes
  parameter int TIM_W  = 16, // width of step_len_i
  parameter int CAP    = 3,  // commands the core can hold at once
  parameter int HELD_W = 2   // width of held_i
) (
  input logic              clk_i,
  input logic              rst_ni,
  input logic              cmd_valid_i,
  input logic              cmd_ready_o,
  input logic              abort_i,
  input logic [TIM_W-1:0]  step_len_i,
  input logic [AXES-1:0]   step_o,
  input logic              busy_o,
  input logic              done_o,
  input logic [HELD_W-1:0] held_i  // commands the core's registers hold
);
  localparam int PW = HELD_W + 1;
  // Monitor counters: L <= 2^TIM_W - 1; the clocks since an abort saturate
  // at 2^TIM_W, where no pulse of the edge can still be high.
  localparam int MonW = TIM_W + 1;
  localparam logic [MonW-1:0] MonOne = MonW'(1);
  localparam logic [MonW-1:0] MonSat = {1'b1, {TIM_W{1'b0}}};

  logic          take;
  logic [PW-1:0] pend_q, pend_d, held;
  assign take   = cmd_valid_i && cmd_ready_o;
  assign held   = pend_q - PW'(done_o);
  assign pend_d = abort_i ? '0 : held + PW'(take);

  // Clocks since the last abort edge: 1 on the clock after it, 0 once a
  // command is taken (or before any abort).
  logic [MonW-1:0] since_q, since_d;
  assign since_d = abort_i ? MonOne :
                   take ? '0 :
                   (since_q == '0 || since_q == MonSat) ? since_q : since_q + MonOne;

  // The previous clock.
  logic            busy_p_q, abort_p_q;
  logic [PW-1:0]   held_p_q;
  logic [AXES-1:0] step_p_q;
  logic [TIM_W-1:0] len_p_q;  // step_len_i of the previous clock (a pulse rising now fired on it)

  logic [AXES-1:0] rise, fall;
  assign rise = step_o & ~step_p_q;
  assign fall = ~step_o & step_p_q;

  // Per axis: the pulse's L and its clocks high so far (this one included).
  logic [AXES*MonW-1:0] len_q, len_d, hi_q, hi_d;
  logic [AXES-1:0]      len_ok, fall_ok, fits;
  for (genvar i = 0; i < AXES; i++) begin : g_axis
    logic [MonW-1:0] l, h;
    assign l = !rise[i] ? len_q[i*MonW +: MonW] :
               (len_p_q == '0) ? MonOne : MonW'(len_p_q);
    assign h = !step_o[i] ? '0 :
               !step_p_q[i] ? MonOne :
               (hi_q[i*MonW +: MonW] == MonSat) ? MonSat : hi_q[i*MonW +: MonW] + MonOne;
    assign len_d[i*MonW +: MonW] = l;
    assign hi_d[i*MonW +: MonW]  = h;
    assign len_ok[i]  = h <= l;
    assign fall_ok[i] = !fall[i] || hi_q[i*MonW +: MonW] == len_q[i*MonW +: MonW];
    assign fits[i]    = step_o[i] && since_q < l;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      pend_q    <= '0;
      since_q   <= '0;
      busy_p_q  <= 1'b0;
      abort_p_q <= 1'b0;
      held_p_q  <= '0;
      step_p_q  <= '0;
      len_p_q   <= '0;
      len_q     <= {AXES{MonOne}};
      hi_q      <= '0;
    end else begin
      pend_q    <= pend_d;
      since_q   <= since_d;
      busy_p_q  <= busy_o;
      abort_p_q <= abort_i;
      held_p_q  <= held;
      step_p_q  <= step_o;
      len_p_q   <= step_len_i;
      len_q     <= len_d;
      hi_q      <= hi_d;
    end
  end

  always_comb begin
    if (rst_ni) begin
      a_link: assert(pend_q >= PW'(done_o) && held == PW'(held_i));
      a_cap: assert(held <= PW'(CAP));
      a_busy: assert(busy_o == (held != '0 || step_o != '0));
      a_done: assert(!done_o || busy_p_q);
      a_rise: assert(rise == '0 || (held_p_q != '0 && !abort_p_q));
      a_abort: assert(since_q == '0 || (held == '0 && !done_o && rise == '0));
      a_abort_len: assert(since_q == '0 || !busy_o || fits != '0);
      a_len: assert(len_ok == {AXES{1'b1}} && fall_ok == {AXES{1'b1}});
    end
  end
endmodule

// What a core's props file attaches to the core (scripts/formal.sh): the
// port contract every core shares (rtl/formal/core_contract.sv, on the core's
// ports and the commands the core holds, one a bit of hold_i: a buffer entry
// or the engine holding one) and the engine's progress:
//   a_progress  while a command runs (run_i) with full feed (feed_i >=
//               2^FEED_W on the clock before) and no abort, the engine
//               advances on every clock but one on which an axis its
//               advance steps (want_i) is not ready (ready_i): it waits for
//               the step/dir timing only, and rtl/formal/stepdir_axis_props.sv
//               proves that ready_o waits for exactly that (never longer;
//               dir_o turns as soon as the hold allows);
//   a_tick      a feed tick (tick_i) only while a command runs.
// The props file instantiates it with `.*`, on the core's ports and on wires
// that scripts/formal.sh connects to the core's own signals after flattening
// (each props file lists them in its `// link:` lines: Yosys 0.23 has neither
// `bind` nor hierarchical references), so the RTL carries no copy of it.
module core_checks #(
  parameter int AXES   = 2,  // axes
  parameter int TIM_W  = 16, // width of step_len_i
  parameter int FEED_W = 2,  // feed_i is FEED_W + 1 bits, full at 2^FEED_W
  parameter int HOLD   = 2   // places that hold a command (its capacity)
) (
  input logic              clk_i,
  input logic              rst_ni,
  input logic              cmd_valid_i,
  input logic              cmd_ready_o,
  input logic              abort_i,
  input logic [FEED_W:0]   feed_i,
  input logic [TIM_W-1:0]  step_len_i,
  input logic [AXES-1:0]   step_o,
  input logic              busy_o,
  input logic              done_o,
  input logic [HOLD-1:0]   hold_i,     // per place: it holds a command
  input logic              run_i,      // a command runs in the engine
  input logic              tick_i,     // the feed accumulator's tick
  input logic              advance_i,  // the engine advances this clock
  input logic [AXES-1:0]   want_i,     // the axes its advance steps
  input logic [AXES-1:0]   ready_i     // the step/dir stage's ready per axis
);
  localparam int HeldW = $clog2(HOLD + 1);
  logic [HeldW-1:0] held;  // the commands the core holds
  always_comb begin
    held = '0;
    for (int i = 0; i < HOLD; i++) held = held + HeldW'(hold_i[i]);
  end

  core_contract #(
    .AXES  (AXES),
    .TIM_W (TIM_W),
    .CAP   (HOLD),
    .HELD_W(HeldW)
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
    .held_i(held)
  );

  logic full_q, full_d;  // feed_i full (on the clock before)
  assign full_d = feed_i[FEED_W];
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) full_q <= 1'b0;
    else full_q <= full_d;
  end

  always_comb begin
    if (rst_ni) begin
      a_progress: assert(!(run_i && full_q && !abort_i) || advance_i || (want_i & ~ready_i) != '0);
      a_tick: assert(!tick_i || run_i);
    end
  end
endmodule

// Place-and-route harness for dda_line (synthesis only; scripts/synth.sh).
//
// The bare core has ~2*AXES*32 + 100 I/O bits, far more than any iCE40
// package has pins. The harness gives it 6 pins with registered boundaries:
//   in:  a shift register (shift_i enables it, sin_i enters at bit 0) holds
//        every core input, so each core input is a flip-flop output;
//   out: a shift register with parallel load (cap_i) takes every core output
//        and shifts it out on sout_o, so every output bit stays observable and
//        synthesis removes nothing; each core output sees one LUT (the load
//        mux) before a flip-flop, so the harness adds no logic depth to the
//        core's own register-to-register paths;
//   rst_ni is synchronised (asynchronous assert, synchronous release).
// Overhead: InW + OutW + 2 flip-flops and about OutW LUTs (the load muxes).
module dda_line_harness #(
  parameter int AXES   = 2,
  parameter int ACC_W  = 32,
  parameter int POS_W  = 32,
  parameter int TIM_W  = 16,
  parameter int FEED_W = 16
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic shift_i,
  input  logic sin_i,
  input  logic cap_i,
  output logic sout_o
);
  // cmd_valid, cmd_delta, feed, half_preload, four timing settings.
  localparam int InW = 1 + AXES * ACC_W + (FEED_W + 1) + 1 + 4 * TIM_W;
  // cmd_ready, step, dir, pos, busy, done.
  localparam int OutW = 1 + 2 * AXES + AXES * POS_W + 2;

  logic [1:0] rst_sync_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) rst_sync_q <= '0;
    else rst_sync_q <= {rst_sync_q[0], 1'b1};
  end

  logic [InW-1:0] in_q;
  always_ff @(posedge clk_i) begin
    if (shift_i) in_q <= {in_q[InW-2:0], sin_i};
  end

  logic                    cmd_valid, cmd_ready, half_preload, busy, done;
  logic [AXES*ACC_W-1:0]   cmd_delta;
  logic [FEED_W:0]         feed;
  logic [TIM_W-1:0]        step_len, step_space, dir_setup, dir_hold;
  logic [AXES-1:0]         step, dir;
  logic [AXES*POS_W-1:0]   pos;
  assign {cmd_valid, cmd_delta, feed, half_preload, step_len, step_space, dir_setup,
          dir_hold} = in_q;

  dda_line #(
    .AXES  (AXES),
    .ACC_W (ACC_W),
    .POS_W (POS_W),
    .TIM_W (TIM_W),
    .FEED_W(FEED_W)
  ) u_core (
    .clk_i,
    .rst_ni        (rst_sync_q[1]),
    .cmd_valid_i   (cmd_valid),
    .cmd_ready_o   (cmd_ready),
    .cmd_delta_i   (cmd_delta),
    .feed_i        (feed),
    .half_preload_i(half_preload),
    .step_len_i    (step_len),
    .step_space_i  (step_space),
    .dir_setup_i   (dir_setup),
    .dir_hold_i    (dir_hold),
    .step_o        (step),
    .dir_o         (dir),
    .pos_o         (pos),
    .busy_o        (busy),
    .done_o        (done)
  );

  logic [OutW-1:0] out_q;
  always_ff @(posedge clk_i) begin
    if (cap_i) out_q <= {cmd_ready, step, dir, pos, busy, done};
    else out_q <= {out_q[OutW-2:0], 1'b0};
  end
  assign sout_o = out_q[OutW-1];
endmodule

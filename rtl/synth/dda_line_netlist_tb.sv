// Lockstep check of a Yosys netlist of dda_line against the RTL (scripts/synth.sh
// --check-netlist). The netlist (module dda_line_net, the variant's parameters
// baked in) comes from the same flow as the reported figures, so agreement
// shows that those figures are for this RTL: neither the Yosys view of it
// (scripts/synth/sv_flatten.py) nor synthesis changed its behaviour.
//
// Both cores get the same random stimulus and every output is compared on
// every clock. Deltas mostly have short bit lengths so that commands finish
// and the whole command/step/dir cycle is exercised; settings change now and
// then; reset is asserted at random (about every 20000 clocks). Ends with $finish after CYCLES
// clocks, or $fatal on the first mismatch.
module dda_line_netlist_tb #(
  parameter int AXES   = 2,
  parameter int ACC_W  = 32,
  parameter int POS_W  = 32,
  parameter int TIM_W  = 16,
  parameter int FEED_W = 16,
  parameter int CYCLES = 200000
);
  logic                  clk = 1'b0;
  /* verilator lint_off SYNCASYNCNET */  // the cores' asynchronous reset, driven off the clock
  logic                  rst_n = 1'b0;
  /* verilator lint_on SYNCASYNCNET */
  logic                  cmd_valid = 1'b0, half_preload = 1'b0;
  logic [AXES*ACC_W-1:0] cmd_delta = '0;
  logic [FEED_W:0]       feed = {1'b1, FEED_W'(0)};  // full feed
  logic [TIM_W-1:0]      step_len = '0, step_space = '0, dir_setup = '0, dir_hold = '0;

  // Outputs: cmd_ready, step, dir, pos, busy, done.
  localparam int OutW = 1 + 2 * AXES + AXES * POS_W + 2;
  logic [OutW-1:0]       out_rtl, out_net;

  dda_line #(
    .AXES  (AXES),
    .ACC_W (ACC_W),
    .POS_W (POS_W),
    .TIM_W (TIM_W),
    .FEED_W(FEED_W)
  ) u_rtl (
    .clk_i         (clk),
    .rst_ni        (rst_n),
    .cmd_valid_i   (cmd_valid),
    .cmd_ready_o   (out_rtl[OutW-1]),
    .cmd_delta_i   (cmd_delta),
    .feed_i        (feed),
    .half_preload_i(half_preload),
    .step_len_i    (step_len),
    .step_space_i  (step_space),
    .dir_setup_i   (dir_setup),
    .dir_hold_i    (dir_hold),
    .step_o        (out_rtl[OutW-2-:AXES]),
    .dir_o         (out_rtl[OutW-2-AXES-:AXES]),
    .pos_o         (out_rtl[2+:AXES*POS_W]),
    .busy_o        (out_rtl[1]),
    .done_o        (out_rtl[0])
  );

  dda_line_net u_net (
    .clk_i         (clk),
    .rst_ni        (rst_n),
    .cmd_valid_i   (cmd_valid),
    .cmd_ready_o   (out_net[OutW-1]),
    .cmd_delta_i   (cmd_delta),
    .feed_i        (feed),
    .half_preload_i(half_preload),
    .step_len_i    (step_len),
    .step_space_i  (step_space),
    .dir_setup_i   (dir_setup),
    .dir_hold_i    (dir_hold),
    .step_o        (out_net[OutW-2-:AXES]),
    .dir_o         (out_net[OutW-2-AXES-:AXES]),
    .pos_o         (out_net[2+:AXES*POS_W]),
    .busy_o        (out_net[1]),
    .done_o        (out_net[0])
  );

  // A random delta: bit length mostly 0..10, now and then up to ACC_W-1 (such a
  // command runs until the next random reset); random sign.
  function automatic logic [ACC_W-1:0] rand_delta();
    int unsigned len = ($urandom % 64 == 0) ? $urandom % ACC_W : $urandom % 11;
    logic [ACC_W-1:0] mag = ACC_W'($urandom) & ((ACC_W'(1) << len) - ACC_W'(1));
    return ($urandom % 2 == 1) ? -mag : mag;
  endfunction

  function automatic logic [TIM_W-1:0] rand_timing();
    return TIM_W'($urandom % 6);
  endfunction

  int unsigned cycle = 0, dones = 0, steps = 0, reversals = 0;
  logic [AXES-1:0] dir_prev = '0;
  // The stimulus seed is Verilator's: run with +verilator+seed+N.
  initial forever #5 clk = ~clk;

  // Compare and drive on the falling edge, away from the rising edge the cores use.
  always @(negedge clk) begin
    if (out_rtl !== out_net) begin
      $display("MISMATCH at cycle %0d: rtl %h net %h", cycle, out_rtl, out_net);
      $fatal(1, "netlist differs from RTL");
    end
    if (rst_n) begin
      dones <= dones + 32'(out_rtl[0]);
      steps <= steps + 32'($countones(out_rtl[OutW-2-:AXES]));
      reversals <= reversals + 32'($countones(out_rtl[OutW-2-AXES-:AXES] ^ dir_prev));
    end
    dir_prev <= out_rtl[OutW-2-AXES-:AXES];
    cycle <= cycle + 1;
    if (cycle == CYCLES) begin
      $display("netlist matches RTL: %0d cycles, %0d commands done, %0d step pulses, %0d dir changes",
               cycle, dones, steps, reversals);
      $finish;
    end
    rst_n <= !(cycle < 3 || $urandom % 20000 == 0);
    cmd_valid <= ($urandom % 4 == 0);
    for (int i = 0; i < AXES; i++) cmd_delta[i*ACC_W+:ACC_W] <= rand_delta();
    half_preload <= $urandom % 2 == 1;
    if ($urandom % 1000 == 0) begin
      case ($urandom % 4)
        0, 1: feed <= {1'b1, FEED_W'(0)};  // full feed
        2: feed <= {1'b0, FEED_W'($urandom)};
        default: feed <= {1'b0, FEED_W'($urandom % 64)} << ($urandom % FEED_W);
      endcase
      step_len <= rand_timing();
      step_space <= rand_timing();
      dir_setup <= rand_timing();
      dir_hold <= rand_timing();
    end
  end
endmodule

// Plain Verilog testbench: replays the input frames of a dda_line
// co-simulation (hwinterp cosim --dump-frames FILE; format in
// tb/dda_line_frames.h) into rtl/dda_line.sv, one clock edge per line, and
// prints the cycle count, the steps per axis, the done pulses and the final
// outputs, for comparison with the co-simulation's report. It runs the RTL alone in
// any Verilog simulator (scripts/bench_speed.sh times it under Icarus).
// Usage: vvp sim +frames=FILE   (parameters set with iverilog -P).
module dda_line_replay_tb #(
  parameter int AXES   = 2,
  parameter int ACC_W  = 32,
  parameter int POS_W  = 32,
  parameter int TIM_W  = 16,
  parameter int FEED_W = 16
);
  localparam int FrameW = 2 + AXES * ACC_W + (FEED_W + 1) + 1 + 4 * TIM_W;

  logic                       clk_i = 1'b0;
  logic                       rst_ni;
  logic                       cmd_valid_i;
  logic                       cmd_ready_o;
  logic [AXES-1:0][ACC_W-1:0] cmd_delta_i;
  logic [FEED_W:0]            feed_i;
  logic                       half_preload_i;
  logic [TIM_W-1:0]           step_len_i, step_space_i, dir_setup_i, dir_hold_i;
  logic [AXES-1:0]            step_o, dir_o;
  logic [AXES-1:0][POS_W-1:0] pos_o;
  logic                       busy_o, done_o;

  dda_line #(
    .AXES(AXES), .ACC_W(ACC_W), .POS_W(POS_W), .TIM_W(TIM_W), .FEED_W(FEED_W)
  ) u_dut (.*);

  logic [FrameW-1:0] frame;
  integer fd, cycles;
  string path;

  // Steps are counted on rising edges of step_o, done pulses as they come,
  // over the whole file (resets between cases do not clear them).
  integer steps_q[AXES];
  integer dones_q = 0;
  logic [AXES-1:0] step_prev_q = '0;
  initial for (int i = 0; i < AXES; i++) steps_q[i] = 0;
  always_ff @(posedge clk_i) begin
    for (int i = 0; i < AXES; i++) if (step_o[i] && !step_prev_q[i]) steps_q[i] <= steps_q[i] + 1;
    if (done_o) dones_q <= dones_q + 1;
    step_prev_q <= step_o;
  end

  initial begin
    if (!$value$plusargs("frames=%s", path)) begin
      $display("dda_line_replay_tb: give +frames=FILE");
      $finish;
    end
    fd = $fopen(path, "r");
    if (fd == 0) begin
      $display("dda_line_replay_tb: cannot read %s", path);
      $finish;
    end
    cycles = 0;
    while ($fscanf(fd, "%h\n", frame) == 1) begin
      {rst_ni, cmd_valid_i, cmd_delta_i, feed_i, half_preload_i,
       step_len_i, step_space_i, dir_setup_i, dir_hold_i} = frame;
      #1 clk_i = 1'b1;
      #1 clk_i = 1'b0;
      cycles = cycles + 1;
    end
    $fclose(fd);
    #1;
    $display("cycles %0d", cycles);
    $display("done_pulses %0d", dones_q);
    $display("idle %0d ready %0d dir %b", !busy_o, cmd_ready_o, dir_o);
    for (int i = 0; i < AXES; i++) $display("axis %0d steps %0d pos %0d", i, steps_q[i], $signed(pos_o[i]));
    $finish;
  end
endmodule

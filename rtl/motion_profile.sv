// motion_profile: motion_top behind the jerk-limited feed profile
// (rtl/feed_profile.sv): the profile's feed word is motion_top's feed_i, so
// the moves run along the profile's S-curve or trapezoid (issue 25;
// docs/profile.md). What the synthesis tables call "feed_profile in
// motion_top": wiring only, no logic of its own.
//
// The command stream is motion_top's (cmd_*_i; a command's feed word 0
// follows feed_i, the profile). The profile's moves come on their own port
// (mv_*_i), one a command, in the same order, each with the command's engine
// operations (models::motion_operations: 2^n for a line, N for an arc), its
// cruise level, its end level and its cap: the motion compiler plans them
// (tb/gcode/profile_plan.h). After a move that ends at level 0 (an exact
// stop), the host offers the next move and the next command only once
// prof_busy_o is low (tb/lockstep/profile_feed.h states why). The lockstep
// harness runs the two modules side by side with this wiring
// (tb/lockstep/profile_feed.h drives motion_top's feed_i with the profile's
// feed word); this top exists for synthesis (scripts/synth.sh, the block
// motion_profile_n3 of cmake/cores.cmake).
module motion_profile #(
  // motion_top's (rtl/motion_top.sv states their ranges)
  parameter int AXES    = 3,   // axes (3..6)
  parameter int ACC_W   = 32,  // signed line and slaved delta width (4..62)
  parameter int COORD_W = 24,  // signed arc coordinate width (3..60)
  parameter int OPS_W   = 28,  // arc operation count width (1..ACC_W - 1)
  parameter int POS_W   = 32,  // position counter width (2..64)
  parameter int TIM_W   = 16,  // step/dir timing width (>= 2)
  parameter int FEED_W  = 24,  // feed word fraction bits, motion_top's and the profile's (>= 1)
  // feed_profile's (rtl/feed_profile.sv states their ranges)
  parameter int SPD_W   = 48,  // speed fraction bits (FEED_W < SPD_W <= 62)
  parameter int TICK_W  = 10,  // a tick is 2^TICK_W clocks
  parameter int LEN_W   = 10,  // the moving sum is at most 2^LEN_W ticks
  parameter int LVL_W   = 16,  // speed level bits
  parameter int MV_OPS_W = 28  // operations of a move (2..40; >= every command's count)
) (
  input  logic                  clk_i,          // clock
  input  logic                  rst_ni,         // asynchronous, active low
  // motion_top's command stream
  input  logic                  cmd_valid_i,    // a command is offered on cmd_*_i
  output logic                  cmd_ready_o,    // an offered command is taken
  input  logic                  cmd_arc_i,      // 0 line, 1 arc
  input  logic [AXES*ACC_W-1:0] cmd_delta_i,    // signed steps per axis
  input  logic [1:0]            cmd_plane_i,    // arc plane: 0 XY, 1 ZX, 2 YZ
  input  logic [2*COORD_W-1:0]  cmd_center_i,   // arc centre - start
  input  logic [2*COORD_W-1:0]  cmd_end_i,      // arc end - start
  input  logic                  cmd_ccw_i,      // arc direction, 1: counter-clockwise
  input  logic [OPS_W-1:0]      cmd_ops_i,      // arc operations N (>= 1)
  input  logic [FEED_W:0]       cmd_feed_i,     // the move's feed word; 0: the profile's
  // the profile's moves, one a command, in the same order
  input  logic                  mv_valid_i,     // a move is offered
  output logic                  mv_ready_o,     // the move is taken when valid and ready
  input  logic [MV_OPS_W-1:0]   mv_ops_i,       // its engine operations (>= 1)
  input  logic [LVL_W-1:0]      mv_target_i,    // its cruise level
  input  logic [LVL_W-1:0]      mv_end_i,       // its level at its last operation
  input  logic [LVL_W-1:0]      mv_max_i,       // its cruise level's cap (0: its target)
  // the profile's registers and controls
  input  logic [SPD_W-1:0]      q_i,            // speed quantum (latched at rest)
  input  logic [LEN_W:0]        len_i,          // L, ticks of the moving sum (latched at rest)
  input  logic                  hold_i,         // feed hold: a controlled stop along the path
  input  logic [8:0]            ovr_i,          // feed override, ovr_i / 128 (128: 100 %)
  // motion_top's settings
  input  logic [TIM_W-1:0]      step_len_i,     // step pulse length, clocks
  input  logic [TIM_W-1:0]      step_space_i,   // min low time between pulses, clocks
  input  logic [TIM_W-1:0]      dir_setup_i,    // dir stable before a step rises, clocks
  input  logic [TIM_W-1:0]      dir_hold_i,     // dir stable after a step falls, clocks
  input  logic                  abort_i,        // the immediate stop (one clock)
  // outputs
  output logic [AXES-1:0]       step_o,         // step pulses, axis i in bit i
  output logic [AXES-1:0]       dir_o,          // 1: negative motion
  output logic [AXES*POS_W-1:0] pos_o,          // signed positions
  output logic                  busy_o,         // motion_top busy
  output logic                  done_o,         // one clock per completed command
  output logic [LVL_W-1:0]      prof_level_o,   // the profile's level
  output logic                  prof_busy_o     // the profile's moves queued, moving or settling
);
  logic [FEED_W:0] feed;
  logic [SPD_W:0]  speed_unused;

  feed_profile #(
    .FEED_W(FEED_W),
    .SPD_W (SPD_W),
    .TICK_W(TICK_W),
    .LEN_W (LEN_W),
    .LVL_W (LVL_W),
    .OPS_W (MV_OPS_W)
  ) u_profile (
    .clk_i,
    .rst_ni,
    .q_i,
    .len_i,
    .cmd_valid_i (mv_valid_i),
    .cmd_ready_o (mv_ready_o),
    .cmd_ops_i   (mv_ops_i),
    .cmd_target_i(mv_target_i),
    .cmd_end_i   (mv_end_i),
    .cmd_max_i   (mv_max_i),
    .hold_i,
    .ovr_i,
    .feed_o      (feed),
    .level_o     (prof_level_o),
    .speed_o     (speed_unused),
    .busy_o      (prof_busy_o)
  );

  motion_top #(
    .AXES   (AXES),
    .ACC_W  (ACC_W),
    .COORD_W(COORD_W),
    .OPS_W  (OPS_W),
    .POS_W  (POS_W),
    .TIM_W  (TIM_W),
    .FEED_W (FEED_W)
  ) u_motion (
    .clk_i,
    .rst_ni,
    .cmd_valid_i,
    .cmd_ready_o,
    .cmd_arc_i,
    .cmd_delta_i,
    .cmd_plane_i,
    .cmd_center_i,
    .cmd_end_i,
    .cmd_ccw_i,
    .cmd_ops_i,
    .cmd_feed_i,
    .feed_i      (feed),
    .step_len_i,
    .step_space_i,
    .dir_setup_i,
    .dir_hold_i,
    .abort_i,
    .step_o,
    .dir_o,
    .pos_o,
    .busy_o,
    .done_o
  );

  // The speed is the feed word's source; only the feed word leaves.
  logic unused;
  assign unused = ^speed_unused;
endmodule

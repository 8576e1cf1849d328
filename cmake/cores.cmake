# Every core variant the project builds, verifies and synthesizes.
# AXES: axes; ACC_W: DDA accumulator width; POS_W: position counter width;
# TIM_W: width of the step/dir timing settings and counters; FEED_W: feed-rate
# accumulator width (feed_i = 2^FEED_W is full feed, one DDA iteration a clock).
# DEFAULT_*: run-time step/dir timing defaults in clock cycles (testbench only).
set(dda_line_timing DEFAULT_STEP_LEN=2 DEFAULT_STEP_SPACE=2 DEFAULT_DIR_SETUP=3 DEFAULT_DIR_HOLD=3)
hwinterp_core_variant(CORE dda_line NAME dda_line_n2
  PARAMS AXES=2 ACC_W=32 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${dda_line_timing})
hwinterp_core_variant(CORE dda_line NAME dda_line_n4
  PARAMS AXES=4 ACC_W=32 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${dda_line_timing})
# Odd widths everywhere, so that width-dependent bugs surface (run by the
# conformance suite and the regression).
hwinterp_core_variant(CORE dda_line NAME dda_line_edge
  PARAMS AXES=3 ACC_W=12 POS_W=15 TIM_W=4 FEED_W=7 DEFAULTS ${dda_line_timing})
hwinterp_finish_variants()

# Every core variant the project builds, verifies and synthesizes.
# AXES: axes; ACC_W: DDA accumulator width (dda_line); POS_W: position counter width;
# TIM_W: width of the step/dir timing settings and counters; FEED_W: feed-rate
# accumulator width (feed_i = 2^FEED_W is full feed, one DDA iteration a clock).
# DEFAULT_*: run-time step/dir timing defaults in clock cycles (testbench only).
set(dda_line_timing DEFAULT_STEP_LEN=2 DEFAULT_STEP_SPACE=2 DEFAULT_DIR_SETUP=3 DEFAULT_DIR_HOLD=3)
hwinterp_core_variant(CORE dda_line NAME dda_line_n2
  PARAMS AXES=2 ACC_W=32 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${dda_line_timing})
hwinterp_core_variant(CORE dda_line NAME dda_line_n4
  PARAMS AXES=4 ACC_W=32 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${dda_line_timing})
# ppc_line: ACC_W is the width of each signed delta. ppc_arc: COORD_W is the
# width of each signed command coordinate (centre and end, relative to the
# start); its internal widths follow from it (rtl/ppc_arc.sv). Both are planar
# (AXES = 2). The _edge variants use odd narrow widths (TIM_W = 5: random
# streams draw step/dir timings up to 16 clocks).
set(ppc_timing DEFAULT_STEP_LEN=2 DEFAULT_STEP_SPACE=2 DEFAULT_DIR_SETUP=3 DEFAULT_DIR_HOLD=3)
hwinterp_core_variant(CORE ppc_line NAME ppc_line_a32
  PARAMS AXES=2 ACC_W=32 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${ppc_timing})
hwinterp_core_variant(CORE ppc_line NAME ppc_line_edge
  PARAMS AXES=2 ACC_W=11 POS_W=13 TIM_W=5 FEED_W=5 DEFAULTS ${ppc_timing})
hwinterp_core_variant(CORE ppc_arc NAME ppc_arc_c24
  PARAMS AXES=2 COORD_W=24 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${ppc_timing})
hwinterp_core_variant(CORE ppc_arc NAME ppc_arc_edge
  PARAMS AXES=2 COORD_W=9 POS_W=13 TIM_W=5 FEED_W=5 DEFAULTS ${ppc_timing})
hwinterp_finish_variants()

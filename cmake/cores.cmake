# Every core variant the project builds, verifies and synthesizes: the one
# configuration source of the RTL, the HLS cores, the models, the testbench
# (which finds the cores and variants here) and synthesis.
# Shared by every core: AXES: axes; POS_W: position counter width; TIM_W:
# width of the step/dir timing settings and counters; FEED_W: feed-rate
# accumulator width (feed_i = 2^FEED_W is full feed, one operation a clock).
# DEFAULT_*: run-time step/dir timing defaults in clock cycles (testbench only).
# The _edge variants use odd, narrow widths everywhere, so that
# width-dependent bugs surface (run by the conformance suite and the regression).
set(timing DEFAULT_STEP_LEN=2 DEFAULT_STEP_SPACE=2 DEFAULT_DIR_SETUP=3 DEFAULT_DIR_HOLD=3)

# dda_line: ACC_W is the accumulator and signed delta width.
hwinterp_core_variant(CORE dda_line NAME dda_line_n2
  PARAMS AXES=2 ACC_W=32 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${timing})
hwinterp_core_variant(CORE dda_line NAME dda_line_n4
  PARAMS AXES=4 ACC_W=32 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${timing})
hwinterp_core_variant(CORE dda_line NAME dda_line_edge
  PARAMS AXES=3 ACC_W=12 POS_W=15 TIM_W=4 FEED_W=7 DEFAULTS ${timing})

# ppc_line: ACC_W is the width of each signed delta. ppc_arc: COORD_W is the
# width of each signed command coordinate (centre and end, relative to the
# start); its internal widths follow from it (rtl/ppc_arc.sv). Both are planar
# (AXES = 2).
hwinterp_core_variant(CORE ppc_line NAME ppc_line_a32
  PARAMS AXES=2 ACC_W=32 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${timing})
hwinterp_core_variant(CORE ppc_line NAME ppc_line_edge
  PARAMS AXES=2 ACC_W=11 POS_W=13 TIM_W=5 FEED_W=5 DEFAULTS ${timing})
hwinterp_core_variant(CORE ppc_arc NAME ppc_arc_c24
  PARAMS AXES=2 COORD_W=24 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${timing})
hwinterp_core_variant(CORE ppc_arc NAME ppc_arc_edge
  PARAMS AXES=2 COORD_W=9 POS_W=13 TIM_W=5 FEED_W=5 DEFAULTS ${timing})
# fixed_ratio: ACC_W is the width of each signed delta; FRAC_W the rate
# words' fraction bits, ACC_W + 3: the rate rounding adds at most 1/16 step
# to the lag of a minor axis, the error bound stays below 1 step up to 4
# axes, and every line up to 2^((FRAC_W-1)/2) steps runs tick for tick as the
# paper's exact-frequency generator (rtl/fixed_ratio.sv,
# models/fixed_ratio_model.h).
hwinterp_core_variant(CORE fixed_ratio NAME fixed_ratio_n2
  PARAMS AXES=2 ACC_W=32 FRAC_W=35 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${timing})
hwinterp_core_variant(CORE fixed_ratio NAME fixed_ratio_n4
  PARAMS AXES=4 ACC_W=32 FRAC_W=35 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${timing})
hwinterp_core_variant(CORE fixed_ratio NAME fixed_ratio_edge
  PARAMS AXES=3 ACC_W=11 FRAC_W=14 POS_W=13 TIM_W=5 FEED_W=5 DEFAULTS ${timing})
# log_stepper: X, Y, Z and A (AXES = 4). INT_W/FRAC_W: the coarse engine's
# unsigned fixed-point words; MUL_K: multiplier bits per clock (a multiply
# takes ceil((INT_W + FRAC_W) / MUL_K) clocks); SEG_W: the signed segment
# deltas of the fine stage (dda_line's ACC_W). models/log_stepper_model.h
# states the arithmetic and the accepted curves.
hwinterp_core_variant(CORE log_stepper NAME log_stepper_n4
  PARAMS AXES=4 INT_W=10 FRAC_W=30 MUL_K=10 SEG_W=16 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${timing})
hwinterp_core_variant(CORE log_stepper NAME log_stepper_edge
  PARAMS AXES=4 INT_W=11 FRAC_W=27 MUL_K=7 SEG_W=13 POS_W=27 TIM_W=5 FEED_W=7 DEFAULTS ${timing})
# log_stepper_dsp: n4's words with MUL_K = INT_W + FRAC_W, a whole multiply a
# clock, for the families with DSP blocks (ECP5: Yosys maps the 40x40 product
# to MULT18X18D); on iCE40 the product is LUTs.
hwinterp_core_variant(CORE log_stepper NAME log_stepper_dsp
  PARAMS AXES=4 INT_W=10 FRAC_W=30 MUL_K=40 SEG_W=16 POS_W=32 TIM_W=16 FEED_W=16 DEFAULTS ${timing})
# motion_top: lines (DDA, ACC_W-bit signed deltas, also the slaved axes'),
# arcs (PPC rule M, COORD_W-bit signed centre and end, OPS_W-bit operation
# counts), 3 axes (X Y Z) or 4 (X Y Z A). rtl/motion_top.sv. FEED_W = 24:
# a part program's feed words need the resolution (at 50 MHz one LSB of a
# 16-bit word is 763 operations/s, and a 10 mm move at F400 would run 10 %
# fast; at 24 bits, 3 operations/s).
hwinterp_core_variant(CORE motion_top NAME motion_top_n3
  PARAMS AXES=3 ACC_W=32 COORD_W=24 OPS_W=28 POS_W=32 TIM_W=16 FEED_W=24 DEFAULTS ${timing})
hwinterp_core_variant(CORE motion_top NAME motion_top_n4
  PARAMS AXES=4 ACC_W=32 COORD_W=24 OPS_W=28 POS_W=32 TIM_W=16 FEED_W=24 DEFAULTS ${timing})
hwinterp_core_variant(CORE motion_top NAME motion_top_edge
  PARAMS AXES=3 ACC_W=15 COORD_W=11 OPS_W=14 POS_W=17 TIM_W=5 FEED_W=7 DEFAULTS ${timing})

# Blocks synthesized beside the cores (scripts/synth.sh, the synthesis tables):
# designs that are not lockstep cores. hwinterp_synth_block(NAME <row> TOP
# <module> FILES <list> [YOSYS yowasp] [VARIANT <variant>] [PARAMS K=V...]):
# the top module, its RTL file list rtl/<list>.f, and its parameters: a core
# variant's, then PARAMS (cmake/variants.cmake).
# motion_soc (docs/soc.md) behind each bus at motion_top_n3's widths, the
# FIFO at its default depth; YoWASP Yosys, as Debian's 0.23 does not read the
# PeakRDL register block.
hwinterp_synth_block(NAME motion_soc_axil_n3 TOP motion_soc_axil FILES motion_soc YOSYS yowasp
  VARIANT motion_top_n3 PARAMS FIFO_DEPTH=16)
hwinterp_synth_block(NAME motion_soc_wb_n3 TOP motion_soc_wb FILES motion_soc YOSYS yowasp
  VARIANT motion_top_n3 PARAMS FIFO_DEPTH=16)
# ... and the AXI4-Lite top with the jerk-limited feed profile (PROFILE=1,
# rtl/motion_soc.sv) at the profile's widths of feed_profile below.
set(soc_profile PROFILE=1 SPD_W=48 TICK_W=10 LEN_W=10 PROF_LVL_W=16 MV_OPS_W=28)
hwinterp_synth_block(NAME motion_soc_axil_prof_n3 TOP motion_soc_axil FILES motion_soc YOSYS yowasp
  VARIANT motion_top_n3 PARAMS FIFO_DEPTH=16 ${soc_profile})
# ... and the Wishbone top with the profile at the same widths: the build for
# the iCE40-HX8K breakout board (docs/soc.md, "The iCE40-HX8K breakout board:
# the whole gateware": it does not fit yet).
hwinterp_synth_block(NAME motion_soc_wb_prof_n3 TOP motion_soc_wb FILES motion_soc YOSYS yowasp
  VARIANT motion_top_n3 PARAMS FIFO_DEPTH=16 ${soc_profile})
# feed_profile: the jerk-limited feed profile (docs/profile.md) at the widths
# the harness runs it (tb/lockstep/harness_profile.h; rtl/CMakeLists.txt
# Verilates Vfeed_profile_f<W>_cc from this line, at every variant's FEED_W).
hwinterp_synth_block(NAME feed_profile TOP feed_profile FILES feed_profile
  PARAMS FEED_W=24 SPD_W=48 TICK_W=10 LEN_W=10 LVL_W=16 OPS_W=28)
# motion_profile: motion_top behind the feed profile (rtl/motion_profile.sv),
# at motion_top_n3's widths and the profile's above.
hwinterp_synth_block(NAME motion_profile_n3 TOP motion_profile FILES motion_profile
  VARIANT motion_top_n3 PARAMS SPD_W=48 TICK_W=10 LEN_W=10 LVL_W=16 MV_OPS_W=28)

# Boards (boards/, docs/boards.md): motion_soc_wb with the feed profile
# (${soc_profile}) on a LiteX SoC, its system clock and its host link:
# the Colorlight 5A-75B v8.0 (ECP5, Etherbone over its Gigabit PHY, 4 axes on
# LiteX-CNC's step/dir pins, 50 MHz from its 25 MHz oscillator), the Sipeed
# Tang Nano 20K (Gowin GW2AR-18, a UART over its USB bridge, 4 axes, its
# 27 MHz oscillator) and the Lattice iCE40-HX8K breakout board (a UART over
# its FT2232H, 3 axes, its 12 MHz oscillator).
hwinterp_board(NAME colorlight_5a_75b VARIANT motion_top_n4 LINK etherbone SYS_HZ 50000000
  PARAMS FIFO_DEPTH=64 ${soc_profile})
hwinterp_board(NAME tang_nano_20k VARIANT motion_top_n4 LINK uart SYS_HZ 27000000 BAUD 1000000
  PARAMS FIFO_DEPTH=64 ${soc_profile})
hwinterp_board(NAME ice40_hx8k_breakout VARIANT motion_top_n3 LINK uart SYS_HZ 12000000 BAUD 1000000
  PARAMS FIFO_DEPTH=16 ${soc_profile})
# Simulated builds at slower clocks besides each board's own (hwinterp
# board-sim --clock-hz): whole programs in the tests' time. A UART at 8
# clocks a bit, the bridge's least. And one without the feed profile (FEED
# drives the feed, as in a board built with PROFILE = 0) for each link.
hwinterp_board_sim(BOARD colorlight_5a_75b SYS_HZ 1000000)
hwinterp_board_sim(BOARD colorlight_5a_75b SYS_HZ 1000000 NO_PROFILE)
hwinterp_board_sim(BOARD tang_nano_20k SYS_HZ 2000000 BAUD 250000)
hwinterp_board_sim(BOARD tang_nano_20k SYS_HZ 2000000 BAUD 250000 NO_PROFILE)
hwinterp_finish_variants()

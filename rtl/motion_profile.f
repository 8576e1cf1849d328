# motion_profile: motion_top behind the feed profile (rtl/motion_profile.sv), a
# block synthesized beside the cores. motion_top's list comes first, unchanged
# (scripts/rtl_param_check.py reads every list's prefixes), then feed_profile's.
stepdir_timing.sv
stepdir_axis.sv
step_stage.sv
feed_accum.sv
magnitude.sv
dda_norm.sv
dda_axis.sv
ppc_line_step.sv
ppc_arc_prep.sv
ppc_arc_engine.sv
motion_top.sv
prim_ram_1r1w.sv
feed_profile.sv
motion_profile.sv

# motion_soc: motion_top behind the register block (rtl/motion_soc_axil.sv or
# rtl/motion_soc_wb.sv as the top). motion_top's list comes first, unchanged
# (scripts/rtl_param_check.py reads every list's prefixes); the register
# block is generated from rtl/regs/motion_soc.rdl (scripts/regs/generate.py).
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
regs/gen/motion_soc_regs_pkg.sv
regs/gen/motion_soc_regs_axil.sv
regs/gen/motion_soc_regs_wb.sv
prim_ram_1r1w.sv
feed_profile.sv
step_encode.sv
motion_soc.sv
motion_soc_axil.sv
motion_soc_wb.sv

stepdir_timing.sv
stepdir_axis.sv
step_stage.sv
feed_accum.sv
ppc_line_step.sv
ppc_arc_prep.sv
ppc_arc_engine.sv
ppc_arc.sv

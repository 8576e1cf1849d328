stepdir_timing.sv
stepdir_axis.sv
step_stage.sv
feed_accum.sv
magnitude.sv
dda_norm.sv
dda_axis.sv
dda_line.sv

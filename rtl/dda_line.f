stepdir_timing.sv
stepdir_axis.sv
step_stage.sv
feed_accum.sv
magnitude.sv
dda_line.sv

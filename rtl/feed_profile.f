# feed_profile: a block, not a lockstep core (the jerk-limited feed profile;
# docs/profile.md): synthesized on its own by scripts/synth.sh (cmake/cores.cmake
# hwinterp_synth_block) and proved by scripts/formal.sh.
prim_ram_1r1w.sv
feed_profile.sv

# rtl/link/etherbone_engine.sv and its blocks, dependencies first (paths from rtl/link/).
../prim_ram_1r1w.sv
crc32.sv
etherbone_engine.sv

# rtl/link/uart_etherbone.sv and its blocks, dependencies first (paths from
# rtl/link/). scripts/formal.sh, scripts/soc_lint.sh and rtl/CMakeLists.txt read it.
../prim_ram_1r1w.sv
crc32.sv
uart_rx.sv
uart_tx.sv
slip_rx.sv
slip_tx.sv
etherbone_engine.sv
uart_etherbone.sv

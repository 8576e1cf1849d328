#!/usr/bin/python3
"""Builds motion_soc behind both buses (tests/cocotb/tb_motion_soc.sv) with
Verilator and runs the cocotb tests (tests/cocotb/test_motion_soc.py) through
each bus.

usage: tests/cocotb/run.py [--bus axil,wb] [--build-dir DIR] [--testcase NAME[,NAME]] [--seed N]
                           [--hwinterp PATH]

--hwinterp: the hwinterp executable the gcode_program test compiles its
program with (default build/tb/hwinterp).

Exit 0 when every test passes on every bus, 1 when one fails, 2 on bad
usage. The Verilated model is rebuilt only when a source changed (make's
rule).
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bus", default="axil,wb")
    ap.add_argument("--build-dir", default=os.path.join(ROOT, "build", "cocotb"))
    ap.add_argument("--testcase", default=None)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--hwinterp", default=os.path.join(ROOT, "build", "tb", "hwinterp"))
    a = ap.parse_args(argv)
    a.build_dir = os.path.abspath(a.build_dir)  # the tests run in tests/cocotb/
    buses = a.bus.split(",")
    for b in buses:
        if b not in ("axil", "wb"):
            print(f"run.py: unknown bus '{b}' (axil or wb)", file=sys.stderr)
            return 2
    from cocotb.runner import get_runner, get_results

    rtl = os.path.join(ROOT, "rtl")
    with open(os.path.join(rtl, "motion_soc.f")) as f:
        files = [os.path.join(rtl, l.strip()) for l in f if l.strip() and not l.startswith("#")]
    top = "tb_motion_soc"
    files.append(os.path.join(HERE, f"{top}.sv"))
    os.makedirs(a.build_dir, exist_ok=True)
    os.environ.setdefault("MAKEFLAGS", f"-j{os.environ.get('HWINTERP_JOBS', '2')}")
    if sys.prefix != sys.base_prefix:  # the simulator's embedded Python: the venv's
        os.environ["VIRTUAL_ENV"] = sys.prefix
    runner = get_runner("verilator")
    runner.build(verilog_sources=files, hdl_toplevel=top, build_dir=a.build_dir,
                 build_args=[os.path.join(rtl, "regs", "lint.vlt"), "-Wno-fatal",
                             "--x-assign", "unique", "--x-initial", "unique",
                             "-CFLAGS", "-O1"],
                 log_file=os.path.join(a.build_dir, "build.log"))
    bad = 0
    for bus in buses:
        results = runner.test(test_module="test_motion_soc", hdl_toplevel=top,
                              test_dir=HERE, build_dir=a.build_dir, testcase=a.testcase,
                              seed=a.seed, extra_env={"SOC_BUS": bus,
                                                    "HWINTERP_EXE": os.path.abspath(a.hwinterp)},
                              results_xml=os.path.join(a.build_dir, f"results_{bus}.xml"),
                              log_file=os.path.join(a.build_dir, f"test_{bus}.log"))
        n, failed = get_results(results)
        print(f"cocotb {bus}: {n - failed}/{n} tests pass (log: {a.build_dir}/test_{bus}.log)")
        bad |= failed > 0 or n == 0
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/python3
"""Builds motion_soc behind both buses (tests/cocotb/tb_motion_soc.sv) with
Verilator and runs the cocotb tests (tests/cocotb/test_motion_soc.py) through
each bus; then the same with the feed profile built in (PROFILE=1) and its
tests (tests/cocotb/test_motion_soc_profile.py).

usage: tests/cocotb/run.py [--bus axil,wb] [--build-dir DIR] [--testcase NAME[,NAME]] [--seed N]
                           [--hwinterp PATH] [--module test_motion_soc|test_motion_soc_profile]

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
    ap.add_argument("--module", default=None,
                    help="test_motion_soc or test_motion_soc_profile only (default: both)")
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
    bad = 0
    # Two builds: motion_soc as it is by default (test_motion_soc), and with
    # the feed profile (PROFILE=1, ticks of 256 clocks so that a move takes
    # some 10^4 clocks: test_motion_soc_profile) in <build-dir>/profile.
    builds = [("test_motion_soc", a.build_dir, {}),
              ("test_motion_soc_profile", os.path.join(a.build_dir, "profile"),
               {"PROFILE": 1, "TICK_W": 8})]
    for module, build_dir, params in builds:
        if a.module and module != a.module:
            continue
        os.makedirs(build_dir, exist_ok=True)
        runner = get_runner("verilator")
        runner.build(verilog_sources=files, hdl_toplevel=top, build_dir=build_dir,
                     parameters=params,
                     build_args=[os.path.join(rtl, "regs", "lint.vlt"), "-Wno-fatal",
                                 "--x-assign", "unique", "--x-initial", "unique",
                                 "-CFLAGS", "-O1"],
                     log_file=os.path.join(build_dir, "build.log"))
        for bus in buses:
            results = runner.test(test_module=module, hdl_toplevel=top,
                                  test_dir=HERE, build_dir=build_dir, testcase=a.testcase,
                                  seed=a.seed, extra_env={"SOC_BUS": bus,
                                                        "HWINTERP_EXE": os.path.abspath(a.hwinterp)},
                                  results_xml=os.path.join(build_dir, f"results_{bus}.xml"),
                                  log_file=os.path.join(build_dir, f"test_{bus}.log"))
            n, failed = get_results(results)
            print(f"cocotb {module} {bus}: {n - failed}/{n} tests pass "
                  f"(log: {build_dir}/test_{bus}.log)")
            bad |= failed > 0 or n == 0
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

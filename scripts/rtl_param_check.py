#!/usr/bin/python3
"""Proves that every RTL module refuses bad parameters at elaboration.

usage: scripts/rtl_param_check.py [--variants FILE] [--jobs N]

Every module in rtl/ checks its parameters with `$error` in a generate `if`
(the constraint is written next to each parameter's comment). This runs, for
each case below, Verilator 5 (`verilator --lint-only -Wall --top-module M
-GP=V`, the flags CMake verilates with) and Yosys (`read_verilog -sv; chparam;
hierarchy -check -top M`, as scripts/synth.sh and scripts/formal.sh read the
RTL):

  bad   one parameter out of its range (the others at their defaults, or as
        given): both tools must fail, and both must print the module's
        message naming the parameter ("<module>: parameter <P> must be ...");
  good  every variant of --variants (build/generated/variants.txt: name, core,
        P=V...): both tools must pass.

It also compiles rtl/dda_line.f with Icarus Verilog 11 (scripts/bench_speed.sh
replays the RTL in it), which has no elaboration system tasks: the checks are
skipped there (`ifndef __ICARUS__`) and the RTL must still compile.

Exit 0 when every case behaves, 1 naming every case that does not, 2 on bad
usage. --jobs (default $HWINTERP_JOBS or 2) runs cases side by side.
"""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (module, {parameter: value} overrides, parameter named in the message).
BAD = [
    ("feed_accum", {"FEED_W": 0}, "FEED_W"),
    ("stepdir_timing", {"TIM_W": 1}, "TIM_W"),
    ("stepdir_axis", {"TIM_W": 1}, "TIM_W"),
    ("step_stage", {"AXES": 0}, "AXES"),
    ("step_stage", {"POS_W": 1}, "POS_W"),
    ("step_stage", {"TIM_W": 1}, "TIM_W"),
    ("magnitude", {"W": 1}, "W"),
    ("dda_norm", {"W": 0}, "W"),
    ("dda_axis", {"W": 1}, "W"),
    ("dda_line", {"AXES": 0}, "AXES"),
    ("dda_line", {"AXES": 33}, "AXES"),
    ("dda_line", {"ACC_W": 1}, "ACC_W"),
    ("dda_line", {"ACC_W": 63}, "ACC_W"),
    ("dda_line", {"POS_W": 1}, "POS_W"),
    ("dda_line", {"POS_W": 65}, "POS_W"),
    ("dda_line", {"TIM_W": 1}, "TIM_W"),
    ("dda_line", {"FEED_W": 0}, "FEED_W"),
    ("ppc_line_step", {"MAG_W": 2}, "MAG_W"),
    ("ppc_line_step", {"MAG_W": 63}, "MAG_W"),
    ("ppc_line", {"AXES": 3}, "AXES"),
    ("ppc_line", {"ACC_W": 2}, "ACC_W"),
    ("ppc_line", {"ACC_W": 63}, "ACC_W"),
    ("ppc_line", {"POS_W": 65}, "POS_W"),
    ("ppc_line", {"TIM_W": 1}, "TIM_W"),
    ("ppc_line", {"FEED_W": 0}, "FEED_W"),
    ("ppc_arc_prep", {"COORD_W": 2}, "COORD_W"),
    ("ppc_arc_engine", {"COORD_W": 2}, "COORD_W"),
    ("ppc_arc_engine", {"COORD_W": 61}, "COORD_W"),
    ("ppc_arc", {"AXES": 3}, "AXES"),
    ("ppc_arc", {"COORD_W": 2}, "COORD_W"),
    ("ppc_arc", {"COORD_W": 61}, "COORD_W"),
    ("ppc_arc", {"POS_W": 1}, "POS_W"),
    ("ppc_arc", {"TIM_W": 1}, "TIM_W"),
    ("ppc_arc", {"FEED_W": 0}, "FEED_W"),
    ("fixed_ratio", {"AXES": 0}, "AXES"),
    ("fixed_ratio", {"AXES": 33}, "AXES"),
    ("fixed_ratio", {"ACC_W": 1}, "ACC_W"),
    ("fixed_ratio", {"ACC_W": 32, "FRAC_W": 32}, "FRAC_W"),
    ("fixed_ratio", {"FRAC_W": 63}, "FRAC_W"),
    ("fixed_ratio", {"POS_W": 65}, "POS_W"),
    ("fixed_ratio", {"TIM_W": 1}, "TIM_W"),
    ("fixed_ratio", {"FEED_W": 0}, "FEED_W"),
    ("log_stepper", {"AXES": 3}, "AXES"),
    ("log_stepper", {"INT_W": 3}, "INT_W"),
    ("log_stepper", {"FRAC_W": 17}, "FRAC_W"),
    ("log_stepper", {"INT_W": 33, "FRAC_W": 30}, "INT_W + FRAC_W"),
    ("log_stepper", {"MUL_K": 0}, "MUL_K"),
    ("log_stepper", {"MUL_K": 41}, "MUL_K"),
    ("log_stepper", {"SEG_W": 1}, "SEG_W"),
    ("log_stepper", {"SEG_W": 33}, "SEG_W"),
    ("log_stepper", {"POS_W": 63}, "POS_W"),
    ("log_stepper", {"TIM_W": 1}, "TIM_W"),
    ("log_stepper", {"FEED_W": 0}, "FEED_W"),
    ("motion_top", {"AXES": 2}, "AXES"),
    ("motion_top", {"AXES": 7}, "AXES"),
    ("motion_top", {"ACC_W": 3, "OPS_W": 2}, "ACC_W"),
    ("motion_top", {"ACC_W": 63}, "ACC_W"),
    ("motion_top", {"COORD_W": 2}, "COORD_W"),
    ("motion_top", {"COORD_W": 61}, "COORD_W"),
    ("motion_top", {"OPS_W": 0}, "OPS_W"),
    ("motion_top", {"OPS_W": 32}, "OPS_W"),
    ("motion_top", {"POS_W": 1}, "POS_W"),
    ("motion_top", {"TIM_W": 1}, "TIM_W"),
    ("motion_top", {"FEED_W": 0}, "FEED_W"),
    # the host link's blocks (rtl/link/)
    ("link_guard", {"WIN_BASE": 100}, "WIN_BASE"),
    ("link_guard", {"WIN_BASE": 2**30}, "WIN_BASE"),
    ("uart_rx", {"DIV": 7}, "DIV"),
    ("uart_tx", {"DIV": 1}, "DIV"),
    ("etherbone_engine", {"BUF_BYTES": 8}, "BUF_BYTES"),
    ("etherbone_engine", {"BUF_BYTES": 24}, "BUF_BYTES"),
    ("etherbone_engine", {"BUF_BYTES": 8192}, "BUF_BYTES"),
    ("etherbone_engine", {"CNT_W": 0}, "CNT_W"),
    ("etherbone_engine", {"CNT_W": 33}, "CNT_W"),
    ("uart_etherbone", {"CLK_HZ": 1000000, "BAUD": 200000}, "CLK_HZ and BAUD"),
    ("uart_etherbone", {"CLK_HZ": 1000000, "BAUD": 105000}, "CLK_HZ and BAUD"),
    ("uart_etherbone", {"BUF_BYTES": 100}, "BUF_BYTES"),
    ("uart_etherbone", {"CNT_W": 0}, "CNT_W"),
]


def file_lists():
    """module -> its RTL files, dependencies first (a prefix of rtl/<core>.f or
    rtl/link/<block>.f, whose paths are relative to their folder); a module of
    rtl/link/ without a list is its file alone."""
    out = {}
    for folder in ("rtl", os.path.join("rtl", "link")):
        d = os.path.join(ROOT, folder)
        for name in sorted(os.listdir(d)):
            if not name.endswith(".f"):
                continue
            with open(os.path.join(d, name)) as f:
                files = [os.path.normpath(os.path.join(d, l.strip()))
                         for l in f if l.strip() and not l.startswith("#")]
            for k, sv in enumerate(files):
                out.setdefault(os.path.basename(sv)[:-3], files[:k + 1])
    d = os.path.join(ROOT, "rtl", "link")
    for name in sorted(os.listdir(d)):
        if name.endswith(".sv"):
            out.setdefault(name[:-3], [os.path.join(d, name)])
    return out


def run(cmd):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


def verilator(top, files, params):
    return run(["verilator", "--lint-only", "-Wall", "--top-module", top] +
               [f"-G{k}={v}" for k, v in params.items()] + files)


def yosys(top, files, params):
    chparam = "".join(f" -set {k} {v}" for k, v in params.items())
    script = f"read_verilog -sv {' '.join(files)};"
    if chparam:
        script += f" chparam{chparam} {top};"
    script += f" hierarchy -check -top {top}"
    return run(["yosys", "-q", "-p", script])


def case(kind, top, files, params, name):
    """Returns None when the case behaves, else a message."""
    label = f"{kind} {top} {' '.join(f'{k}={v}' for k, v in params.items()) or '(defaults)'}"
    wrong = []
    for tool, fn in (("verilator", verilator), ("yosys", yosys)):
        rc, out = fn(top, files, params)
        if kind == "good":
            if rc != 0:
                wrong.append(f"{tool} failed: {out.strip().splitlines()[0] if out.strip() else rc}")
        else:
            msg = re.compile(re.escape(f"{top}: parameter") + r"s? " + re.escape(name) + r" must be")
            if rc == 0:
                wrong.append(f"{tool} accepted it")
            elif not msg.search(out):
                first = out.strip().splitlines()[0] if out.strip() else ""
                wrong.append(f"{tool} failed without naming {name}: {first}")
    return f"{label}: " + "; ".join(wrong) if wrong else None


def icarus():
    with open(os.path.join(ROOT, "rtl", "dda_line.f")) as f:
        files = [os.path.join(ROOT, "rtl", l.strip()) for l in f if l.strip() and not l.startswith("#")]
    # Into a file of its own, never os.devnull: iverilog makes its output
    # executable, and as root it turned /dev/null into mode 0755.
    with tempfile.TemporaryDirectory() as tmp:
        rc, out = run(["iverilog", "-g2012", "-o", os.path.join(tmp, "dda_line.vvp"), "-s",
                       "dda_line"] + files)
    return None if rc == 0 else f"icarus rtl/dda_line.f: failed: {out.strip().splitlines()[0]}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--variants", default=os.path.join(ROOT, "build", "generated", "variants.txt"))
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("HWINTERP_JOBS", "2")))
    args = ap.parse_args()
    if args.jobs < 1:
        print(f"rtl_param_check.py: --jobs {args.jobs}: must be >= 1", file=sys.stderr)
        return 2
    if not os.path.isfile(args.variants):
        print(f"rtl_param_check.py: no variants file '{args.variants}'", file=sys.stderr)
        return 2
    for tool in ("verilator", "yosys", "iverilog"):
        if subprocess.run(["sh", "-c", f"command -v {tool}"], stdout=subprocess.DEVNULL).returncode:
            print(f"rtl_param_check.py: {tool} not found (scripts/setup.sh installs it)", file=sys.stderr)
            return 2
    lists = file_lists()
    jobs = []
    with open(args.variants) as f:
        for line in f:
            fields = line.split()
            if len(fields) < 2:
                continue
            core, params = fields[1], dict(kv.split("=", 1) for kv in fields[2:])
            jobs.append(("good", core, lists[core], params, ""))
    for top, params, name in BAD:
        jobs.append(("bad", top, lists[top], params, name))
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(case, *j) for j in jobs] + [pool.submit(icarus)]
        wrong = [f.result() for f in futures]
    wrong = [w for w in wrong if w]
    for w in wrong:
        print(f"rtl_param_check: {w}")
    n_good = sum(1 for j in jobs if j[0] == "good")
    print(f"rtl_param_check: {n_good} variants elaborate, {len(jobs) - n_good} bad parameters refused "
          f"by Verilator and Yosys with the parameter's name, Icarus compiles rtl/dda_line.f: "
          f"{'FAILED, ' + str(len(wrong)) + ' case(s)' if wrong else 'all hold'}")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())

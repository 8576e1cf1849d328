#!/usr/bin/env python3
"""ctest synth_peer_litexcnc: the synthesis peer still elaborates as scripts/synth.sh expects.

Usage: check_litexcnc_stepgen.py OUT_DIR

With the pinned packages (scripts/requirements.txt), litexcnc_stepgen.py writes LiteX-CNC's
stepgen for 1 and 2 axes; Debian's Yosys reads each (hierarchy -check, proc, check -assert);
the ports are the ones the pin harness needs (clk_i, rst_ni) and one step/dir pair and one
set of CSR ports per axis; the configuration is LiteX-CNC's default (50 MHz, 400 kHz, no soft
stop, so shift 5 and pick-off 32/37/53). A litexcnc, litex or migen that elaborates another
circuit, or none, fails here in seconds instead of halfway through a synthesis run.
Exit 0 = all hold; 1 = a check failed (each named).
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    out = argv[1]
    os.makedirs(out, exist_ok=True)
    bad = []
    for axes in (1, 2):
        name = "peer_check_n%d" % axes
        v, info_path, ports_path = (os.path.join(out, name + ext) for ext in
                                    (".v", ".json", "_ports.json"))
        subprocess.run([sys.executable, os.path.join(HERE, "litexcnc_stepgen.py"), "--axes",
                        str(axes), "--name", name, "--out", v, "--info", info_path],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        r = subprocess.run(["yosys", "-q", "-p", "read_verilog -sv %s; hierarchy -check -top %s; "
                            "proc; check -assert; write_json %s" % (v, name, ports_path)],
                           capture_output=True, text=True)
        if r.returncode:
            bad.append("%d axes: Yosys does not read %s: %s" % (axes, v, r.stderr.strip()[-300:]))
            continue
        with open(ports_path) as f:
            ports = json.load(f)["modules"][name]["ports"]
        with open(info_path) as f:
            info = json.load(f)
        want = {"clk_i": ("input", 1), "rst_ni": ("input", 1)}
        for i in range(axes):
            want.update({
                "stepgen%d_step_o" % i: ("output", 1),
                "stepgen%d_dir_o" % i: ("output", 1),
                "csr_stepgen_%d_speed_target_i" % i: ("input", 31),
                "csr_stepgen_%d_max_acceleration_i" % i: ("input", 32),
                "csr_stepgen_%d_position_o" % i: ("output", 64),
            })
        for p, (d, w) in want.items():
            got = ports.get(p)
            if not got or (got["direction"], len(got["bits"])) != (d, w):
                bad.append("%d axes: port %s: want %s [%d], got %s" % (
                    axes, p, d, w, got and (got["direction"], len(got["bits"]))))
        n_step = sum(1 for p in ports if p.endswith("_step_o"))
        if n_step != axes:
            bad.append("%d axes: %d step outputs" % (axes, n_step))
        cfg = info["config"]
        for k, v_want in (("clock_frequency_hz", 50000000), ("max_frequency_hz", 400000),
                          ("soft_stop", False), ("index_pin", None), ("shift", 5),
                          ("pick_off", [32, 37, 53])):
            if cfg.get(k) != v_want:
                bad.append("%d axes: config %s = %r, want %r" % (axes, k, cfg.get(k), v_want))
    for b in bad:
        sys.stderr.write("check_litexcnc_stepgen: %s\n" % b)
    if not bad:
        print("check_litexcnc_stepgen: LiteX-CNC stepgen (1 and 2 axes) elaborates, reads and "
              "has the expected ports and configuration")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""The ports of every variant's RTL, as JSON: for each variant of
<build>/generated/variants.txt (the configure-time copy of cmake/cores.cmake),
the ports of rtl/<core>.sv in declaration order with their widths evaluated
at the variant's parameters.

usage: scripts/rtl_ports.py VARIANTS_TXT

Prints {"<variant>": [{"name": ..., "dir": "input"|"output", "bits": N}, ...]}.
The declarations are read as scripts/port_pages.py reads them (one port a
line, `input logic [MSB:LSB] name, // comment`); a range is an expression
of the module's parameters (+ - * / parentheses, $clog2). The unit test
PayloadFields.MatchTheRtlPorts compares these with the field lists of the
HLS payloads (hls/fields.h).
Exit status: 0 done, 2 bad input (names it).
"""
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from port_pages import header  # noqa: E402

RANGE = re.compile(r"^\[(.+):(.+)\]$")
SAFE = re.compile(r"^[A-Za-z0-9_+\-*/() $]*$")


def evaluate(expr, params, where):
    if not SAFE.match(expr):
        raise ValueError("%s: range expression '%s' is not arithmetic" % (where, expr))
    text = expr.replace("$clog2", "clog2")
    try:
        return int(eval(text, {"__builtins__": {}},
                        dict(params, clog2=lambda v: max(0, math.ceil(math.log2(v))))))
    except Exception as e:  # noqa: BLE001 - any failure is bad input, named
        raise ValueError("%s: cannot evaluate '%s' (%s)" % (where, expr, e))


def ports(core, params):
    _, _, decls, _ = header(core)
    out = []
    for name, direction, rng, _, _ in decls:
        bits = 1
        if rng:
            m = RANGE.match(rng.replace(" ", ""))
            if not m:
                raise ValueError("rtl/%s.sv: port %s has range %s" % (core, name, rng))
            where = "rtl/%s.sv: %s" % (core, name)
            bits = evaluate(m.group(1), params, where) - evaluate(m.group(2), params, where) + 1
        out.append({"name": name, "dir": direction, "bits": bits})
    return out


def main(argv):
    if len(argv) != 1:
        sys.stderr.write(__doc__)
        return 2
    result = {}
    try:
        with open(argv[0]) as f:
            for line in f:
                words = line.split()
                if not words:
                    continue
                variant, core = words[0], words[1]
                params = {k: int(v) for k, v in (w.split("=", 1) for w in words[2:])}
                result[variant] = ports(core, params)
    except (OSError, ValueError) as e:
        sys.stderr.write("rtl_ports: %s\n" % e)
        return 2
    print(json.dumps(result, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/env python3
"""Refuses SystemVerilog that Yosys 0.23 reads wrongly without a message.

Usage: yosys_compat.py FILE...   (exit 1 and one message per offending line)

Most constructs Yosys 0.23 does not support stop it with an error naming the
line (2-D packed arrays, for one), and scripts/synth.sh passes that error on.
This check is for the silent ones, where Yosys synthesizes, and a formal tool
proves, a different circuit from the one every simulator runs:

  An unbased unsized fill literal ('1, 'x, 'z) initialising a parameter that
  has a declared type or range is read as one bit, zero-extended
  (YosysHQ/yosys#5465, fixed after 0.58): `localparam logic [15:0] Sat = '1;`
  becomes 16'h0001 and `localparam int I = '1;` becomes 1. Write the width
  out, e.g. {W{1'b1}}. ('0, and an untyped `localparam X = '1`, are read
  right.) The same literal as a parameter override, #('1), is not detected.
"""
import re
import sys


def code_mask(text):
    """Returns text with comments and string literals blanked (same length)."""
    out = list(text)
    i, n = 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif text[i] == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            j += 1
        else:
            i += 1
            continue
        for k in range(i, min(j, n)):
            if out[k] != "\n":
                out[k] = " "
        i = j
    return "".join(out)


FILL_PARAM = re.compile(r"\b(?:localparam|parameter)\b([^;=]*)=\s*'[1xXzZ](?![\w'])")


def check(path):
    with open(path) as f:
        code = code_mask(f.read())
    bad = []
    for m in FILL_PARAM.finditer(code):
        decl = m.group(1)
        # `localparam X = '1` (name only) is read right; a type or range breaks it.
        if len(decl.split()) >= 2 or "[" in decl:
            bad.append("%s:%d: %s" % (path, code.count("\n", 0, m.start()) + 1,
                                      " ".join(m.group(0).split())))
    return bad


def main(argv):
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        return 2
    bad = [b for path in argv[1:] for b in check(path)]
    for b in bad:
        sys.stderr.write("yosys_compat: %s\n    Yosys 0.23 reads this fill literal as one bit, "
                         "zero-extended (YosysHQ/yosys#5465); write the width out, "
                         "e.g. {W{1'b1}}\n" % b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/python3
"""Checks the register style of the RTL (rtl/*.sv, rtl/link/*.sv; not rtl/formal/).

usage: scripts/rtl_style.py [FILE...]   (default: every rtl/*.sv and rtl/link/*.sv)

Every always_ff block is the lowRISC / PULP common_cells register: an
asynchronous reset and a copy, nothing else,

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin x_q <= <constant>; ... end
      else begin x_q <= x_d; ... end
    end

(a constant: a literal, or a member of an enum the file declares), so every
flip-flop's name ends in _q, its next value is computed into x_d
outside the block (always_comb or assign), and the block holds no enable, no
arithmetic and no other branch. One exception: a RAM primitive
(rtl/prim_ram_*.sv) writes its words and its read register in a block clocked
by clk_i alone (block RAM has no reset; Yosys infers it only so), every
target still named _q. And a simulation checker: an always_ff clocked by clk_i
alone inside `ifndef SYNTHESIS`, assigning nothing (it only reports, with
$error), is no register and is left alone. Exit 1 with one line per offence
(file:line: what), 0 when every block keeps the rule.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONST = re.compile(r"^(?:'[01xX]|\d+'[bBdDhH][0-9a-fA-F_xX]+|\d+)$")
NBA = re.compile(r"([\w.]+)\s*<=\s*([^;]+);")
RAM_NBA = re.compile(r"([\w.]+)(?:\[[^\]]*\])?\s*<=\s*([^;]+);")
RAM_HEAD = re.compile(r"always_ff\s*@\s*\(\s*posedge\s+clk_i\s*\)")
HEAD = re.compile(r"always_ff\s*@\s*\(\s*posedge\s+clk_i\s+or\s+negedge\s+rst_ni\s*\)")


def strip_comments(text):
    """Blanks comments and strings, keeping every newline (line numbers hold)."""
    text = re.sub(r"/\*.*?\*/", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    return re.sub(r'"[^"\n]*"', '""', text)


def block_end(code, start):
    """Index just past the always_ff statement that starts at start."""
    m = re.compile(r"\b(begin|end)\b|;").search
    depth, i, seen_begin = 0, start, False
    while True:
        t = m(code, i)
        if t is None:
            return len(code)
        if t.group(0) == "begin":
            depth += 1
            seen_begin = True
        elif t.group(0) == "end":
            depth -= 1
            if depth == 0:
                return t.end()
        elif not seen_begin or depth == 0:
            # a single-statement always_ff (or if/else without begin): runs to
            # the statement after `else`
            if re.search(r"\belse\b", code[start:t.end()]):
                return t.end()
        i = t.end()


def in_sim_only(code, pos):
    """Whether pos lies inside an `ifndef SYNTHESIS ... `endif (or `else)."""
    depth_open = []
    for t in re.finditer(r"`(ifndef|ifdef|else|endif)\b\s*(\w*)", code[:pos]):
        kind, name = t.group(1), t.group(2)
        if kind in ("ifndef", "ifdef"):
            depth_open.append(kind == "ifndef" and name == "SYNTHESIS")
        elif kind == "else" and depth_open:
            depth_open[-1] = False
        elif kind == "endif" and depth_open:
            depth_open.pop()
    return bool(depth_open) and depth_open[-1]


def enum_members(code):
    """Names of the members of every `typedef enum ... { ... }` in code (constants too)."""
    names = set()
    for body in re.findall(r"\btypedef\s+enum\b[^{]*\{([^}]*)\}", code):
        for item in body.split(","):
            m = re.match(r"\s*([A-Za-z_]\w*)", item)
            if m:
                names.add(m.group(1))
    return names


def check(path):
    with open(path) as f:
        code = strip_comments(f.read())
    enums = enum_members(code)
    bad = []
    for m in re.finditer(r"\balways_ff\b", code):
        line = code.count("\n", 0, m.start()) + 1
        where = f"{os.path.relpath(path, ROOT)}:{line}"
        head = HEAD.match(code, m.start())
        ram = RAM_HEAD.match(code, m.start())
        if ram and in_sim_only(code, m.start()):
            body = code[ram.end():block_end(code, ram.end())]
            if not RAM_NBA.search(body):
                continue  # a checker: reports, assigns nothing
        if ram and os.path.basename(path).startswith("prim_ram_"):
            body = code[ram.end():block_end(code, ram.end())]
            for lhs, _ in RAM_NBA.findall(body):
                if not lhs.endswith("_q"):
                    bad.append(f"{where}: RAM word or read register `{lhs}` does not end in _q")
            continue
        if not head:
            bad.append(f"{where}: always_ff not clocked by clk_i with the asynchronous rst_ni")
            continue
        body = code[head.end():block_end(code, head.end())]
        split = re.search(r"\bif\s*\(\s*!\s*rst_ni\s*\)(.*?)\belse\b(.*)$", body, re.S)
        if not split:
            bad.append(f"{where}: no `if (!rst_ni) ... else ...` reset branch")
            continue
        reset, run = split.group(1), split.group(2)
        for part, what in ((reset, "reset"), (run, "copy")):
            if re.search(r"\b(if|case|for|unique|priority)\b", part):
                bad.append(f"{where}: a branch or loop in the {what} branch (compute the next value into _d)")
        for lhs, rhs in NBA.findall(reset):
            if not lhs.endswith("_q"):
                bad.append(f"{where}: flip-flop `{lhs}` does not end in _q")
            elif not CONST.match(rhs.strip()) and rhs.strip() not in enums:
                bad.append(f"{where}: `{lhs}` resets to `{rhs.strip()}`, not a constant")
        for lhs, rhs in NBA.findall(run):
            if not lhs.endswith("_q"):
                bad.append(f"{where}: flip-flop `{lhs}` does not end in _q")
            elif rhs.strip() != lhs[:-2] + "_d":
                bad.append(f"{where}: `{lhs} <= {rhs.strip()}`: the copy branch may only take {lhs[:-2]}_d")
        left = NBA.sub("", reset + run)
        if re.sub(r"\b(begin|end)\b|\s", "", left):
            bad.append(f"{where}: statements other than `x_q <= ...` in the block")
    return bad


def main(argv):
    if any(a in ("-h", "--help") for a in argv):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    files = argv or sorted(os.path.join(ROOT, d, n) for d in ("rtl", os.path.join("rtl", "link"))
                           for n in os.listdir(os.path.join(ROOT, d)) if n.endswith(".sv"))
    bad = []
    for path in files:
        if not os.path.isfile(path):
            print(f"rtl_style.py: no such file '{path}'", file=sys.stderr)
            return 2
        bad += check(path)
    for b in bad:
        print(b)
    if not bad:
        print(f"rtl_style: {len(files)} files, every always_ff is a reset and a copy of _d into _q")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

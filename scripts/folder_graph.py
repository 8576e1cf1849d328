#!/usr/bin/env python3
"""The folder graph of tb/ from its #include lines: which folder includes
which, the circles, and each folder's layer.

usage: scripts/folder_graph.py [--check] [--markdown] [ROOT]

ROOT is the folder whose subfolders are the nodes (default tb). A file in
ROOT/<folder>/... that includes "ROOT/<other>/..." is an edge folder -> other
(nested folders count as their top folder: tb/cores/dda_line is `cores`).

  --check     exit 1 naming every circle (folders that include each other,
              directly or around a loop); the unit test `folder_graph` runs it
  --markdown  print the graph as a markdown table (folder, layer, includes),
              as docs/harness.md shows it
Without options: print one line per edge and the circles.
Exit status: 0 no circle, 1 a circle, 2 bad usage.
"""
import os
import re
import sys

INCLUDE = r'#include\s+"{root}/([A-Za-z0-9_]+)/'


def edges(root):
    """folder -> set of folders it includes, from every source file under root."""
    name = os.path.basename(os.path.normpath(root))
    inc = re.compile(INCLUDE.format(root=re.escape(name)))
    out = {}
    for d, _, files in os.walk(root):
        rel = os.path.relpath(d, root).split(os.sep)[0]
        if rel == ".":
            continue
        out.setdefault(rel, set())
        for f in sorted(files):
            if not f.endswith((".h", ".hpp", ".cpp", ".cc")):
                continue
            with open(os.path.join(d, f), errors="replace") as fh:
                for m in inc.finditer(fh.read()):
                    if m.group(1) != rel:
                        out[rel].add(m.group(1))
    for targets in list(out.values()):
        for t in targets:
            out.setdefault(t, set())
    return out


def circles(g):
    """The strongly connected sets of more than one folder (Tarjan), sorted."""
    index, low, stack, on, found = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(g[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            c = []
            while True:
                w = stack.pop()
                on.discard(w)
                c.append(w)
                if w == v:
                    break
            if len(c) > 1:
                found.append(sorted(c))

    sys.setrecursionlimit(10000)
    for v in sorted(g):
        if v not in index:
            visit(v)
    return sorted(found)


def layers(g):
    """folder -> layer: 0 for a folder that includes none, else 1 + the highest
    layer it includes (only for a graph without circles)."""
    memo = {}

    def layer(v):
        if v not in memo:
            memo[v] = 0 if not g[v] else 1 + max(layer(w) for w in g[v])
        return memo[v]

    return {v: layer(v) for v in g}


def markdown(g):
    lay = layers(g)
    rows = ["| folder | layer | includes |", "|---|---|---|"]
    for v in sorted(g, key=lambda v: (-lay[v], v)):
        inc = ", ".join("`%s`" % w for w in sorted(g[v], key=lambda w: (-lay[w], w))) or "nothing"
        rows.append("| `%s` | %d | %s |" % (v, lay[v], inc))
    return "\n".join(rows)


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    flags = [a for a in argv if a.startswith("--")]
    bad = [f for f in flags if f not in ("--check", "--markdown")]
    if bad or len(args) > 1:
        sys.stderr.write(__doc__)
        return 2
    root = args[0] if args else "tb"
    if not os.path.isdir(root):
        sys.stderr.write("folder_graph: '%s' is not a folder\n" % root)
        return 2
    g = edges(root)
    found = circles(g)
    for c in found:
        print("circle: " + " <-> ".join(c))
    if "--markdown" in flags and not found:
        print(markdown(g))
    elif "--check" not in flags:
        for v in sorted(g):
            for w in sorted(g[v]):
                print("%s -> %s" % (v, w))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

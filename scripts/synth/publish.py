#!/usr/bin/env python3
"""Publishes synthesis results: docs/synth.json, the synthesis table of
docs/synthesis.md and the synth-columns blocks of README.md and docs/**/*.md.

Usage: publish.py [--check] [--variants FILE] [--family FAMILY [--same-netlist]] [SYNTH_JSON...]

  SYNTH_JSON    a synth.json written by scripts/synth.sh (synth_report.py); its
                full (place-and-route) results replace the published ones of the
                same variants in docs/synth.json. Results of --generic-only runs
                are refused: the table needs the iCE40 figures. A published
                record keeps its ECP5 or Gowin figures when the new one has none
                of that family and was measured on the same RTL (rtl_sha256);
                on other RTL they are dropped, with a warning.
  --family F    merge only family F's figures (ecp5 or gowin: the "ecp5" or
                "gowin" part of each record) of SYNTH_JSON into the published
                records of the same variants and peers, every other figure as
                published: e.g. the output of `scripts/synth.sh --family gowin`.
                Each variant must be published already and the family's figures
                measured on the RTL the published ones were (rtl_sha256; a peer:
                the same generated Verilog, source_sha256); exit 2 otherwise.
                The family's part keeps the date, git revision and command of
                the run it comes from.
  --same-netlist  with --family: a published record measured on other RTL is
                taken as measured on today's when the RTL changed only where
                synthesis does not read it, as SYNTH_JSON's record shows: its
                Yosys generic netlist (step 1: cells by type, the same Yosys)
                is the published one. The record then takes today's rtl_sha256
                and keeps the old one with the evidence (rtl_sha256_before);
                a netlist that differs is exit 2, as without the option
  --variants F  the build's generated/variants.txt: every variant it lists must
                be published, and no other (checked with --check); the blocks of
                generated/blocks.txt beside it (hwinterp_synth_block in
                cmake/cores.cmake) may be published too, after the variants
  --check       write nothing; exit 1 if a table or block is not what docs/synth.json
                renders, if a published variant (or its Gowin figures) was measured
                on RTL other than today's rtl/<core>.f files (rtl_sha256), or if a
                variant is missing

Without --check (and after merging), docs/synthesis.md's text between the two
`synth-table` marker lines is rewritten from docs/synth.json, and so is each
`synth-columns` block in README.md and docs/**/*.md (a marker naming variants,
e.g. `<!-- synth-columns: fixed_ratio_n2 dda_line_n2; written by ... -->`, up
to `<!-- end synth-columns -->`: a small table with one column per named
variant, for prose that compares cores): no synthesis figure in the
documentation is written by hand.

Exit status: 0 done / consistent, 1 inconsistent (names each variant), 2 bad input.
"""
import glob
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from synth_report import (ROOT, axes_of, axis_pairs, per_axis, render_ecp5_table,  # noqa: E402
                          render_gowin_table, render_peer_rows, rtl_digest, tool_text)

PUBLISHED = os.path.join(ROOT, "docs", "synth.json")
# The page with the synthesis table, and every page that may hold synth-columns blocks.
TABLE_DOC = os.path.join(ROOT, "docs", "synthesis.md")


def column_docs():
    return [os.path.join(ROOT, "README.md")] + sorted(
        glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))
BEGIN = "<!-- synth-table: written by scripts/synth/publish.py from docs/synth.json; do not edit -->"
END = "<!-- end synth-table -->"
# <!-- synth-columns: V1 V2 ...; written by scripts/synth/publish.py from docs/synth.json; do not edit -->
COLUMNS_RE = re.compile(r"<!-- synth-columns: ([\w ]+); written by scripts/synth/publish.py from "
                        r"docs/synth.json; do not edit -->\n.*?<!-- end synth-columns -->", re.S)
# The cores the issue-12 target (100 MHz on HX8K at every seed) is set for; log_stepper's own
# aim is 40 MHz (issue 9).
TARGET_MHZ = {"log_stepper": 40.0}
DEFAULT_TARGET_MHZ = 100.0
# ECP5 (issue 27): the fine cores at 150 MHz at every seed; log_stepper's aim is points per
# second, not a clock (None: no target).
ECP5_TARGET_MHZ = {"log_stepper": None}
DEFAULT_ECP5_TARGET_MHZ = 150.0
# Gowin: this project's Tang Nano 20K target (boards/hwinterp_litex/targets/tang_nano_20k.py)
# runs the SoC at the board's 27 MHz oscillator, litex-boards' own target for the board at
# 48 MHz through the rPLL; 60 MHz = 48 MHz with 25 % to spare for nextpnr-himbaechel-gowin's
# timing model, whose author found its Fmax about 20 % higher than the vendor tools'
# (YosysHQ/nextpnr#1345). The same for every core: the board has one clock.
GOWIN_TARGET_MHZ = {}
DEFAULT_GOWIN_TARGET_MHZ = 60.0
# The families whose figures are one part of a record ("ecp5", "gowin"), mergeable apart.
PART_FAMILIES = ("ecp5", "gowin")
REQUIREMENTS = os.path.join(ROOT, "scripts", "requirements.txt")


def fail(msg, code=2):
    sys.stderr.write("publish: %s\n" % msg)
    sys.exit(code)


def load(path):
    """(variants, peers) of a synth.json."""
    try:
        with open(path) as f:
            d = json.load(f)
    except (OSError, ValueError) as e:
        fail("cannot read %s: %s" % (path, e))
    if not isinstance(d, dict) or not isinstance(d.get("variants"), list):
        fail("%s has no 'variants' list" % path)
    return d["variants"], d.get("peers", [])


def pinned(package):
    """The version scripts/requirements.txt pins for `package`, or None."""
    with open(REQUIREMENTS) as f:
        for line in f:
            m = re.match(r"^\s*([A-Za-z0-9_.-]+)==(\S+)", line)
            if m and m.group(1).lower() == package.lower():
                return m.group(2)
    return None


def short(name):
    """A readable register or cell name: without the pin harness's u_core. and nextpnr's
    _SB_... mapping suffix."""
    name = re.sub(r"^u_core\.", "", name)
    return re.sub(r"_SB_\w+.*$", "", name)


def path_text(cp):
    if not cp:
        return "-"
    steps = "%d LUT" % cp["lut_levels"]
    if cp["carry_steps"]:
        steps += " + %d carry" % cp["carry_steps"]
    return "`%s` -> `%s` (%s; %.1f ns logic, %.1f ns routing)" % (
        short(cp["from_net"]), short(cp["to_cell"]), steps, cp["logic_ns"], cp["routing_ns"])


def seed_text(p):
    """A seed's Fmax in a table cell: MHz, "no route" (timed out) or "does not fit"."""
    if "fmax_mhz" in p:
        return "%.2f" % p["fmax_mhz"]
    return "does not fit" if "no_fit" in p else "no route"


def target(r):
    return TARGET_MHZ.get(r["core"], DEFAULT_TARGET_MHZ)


def ecp5_target(r):
    return ECP5_TARGET_MHZ.get(r["core"], DEFAULT_ECP5_TARGET_MHZ)


def gowin_target(r):
    return GOWIN_TARGET_MHZ.get(r["core"], DEFAULT_GOWIN_TARGET_MHZ)


def missed_by(results, family, target):
    """The variants with figures of `family` ("ecp5", "gowin") whose lowest seed misses
    target(r), or whose seeds did not all route."""
    missed = []
    for r in results:
        t, e = target(r), r.get(family)
        if t is None or e is None:
            continue
        if e.get("fmax_min_mhz") is None or e["fmax_min_mhz"] < t or \
                not all("fmax_mhz" in p for p in e["runs"]):
            missed.append(r["variant"])
    return missed


def gowin_section(results):
    """Gowin (every variant with Gowin results): the table and the target line."""
    table = render_gowin_table(results)
    if not table:
        return []
    g0 = next(r["gowin"] for r in results if "gowin" in r)
    missed = missed_by(results, "gowin", gowin_target)
    absent = [r["variant"] for r in results if "gowin" not in r]
    out = ["", "Gowin (%s, chip database %s, the %s's part; %s, %s; pins: `%s`):" % (
        g0["device"], g0["family"], g0["board"], tool_text(g0["tools"]["yosys"]),
        tool_text(g0["tools"]["nextpnr"]), g0["cst"]), ""] + table
    out += ["", "Gowin target (%d MHz at every seed) missed by: %s." % (
        DEFAULT_GOWIN_TARGET_MHZ, ", ".join("`%s`" % v for v in missed) or "none")]
    if absent:
        out += ["No Gowin figures (run `scripts/synth.sh --family gowin`): %s." % ", ".join(
            "`%s`" % v for v in absent)]
    return out


def ecp5_section(results, peers):
    """ECP5 (every variant with ECP5 results), Gowin, and the peers beside, with the
    ratios."""
    out = []
    table = render_ecp5_table(results)
    if table:
        e0 = next(r["ecp5"] for r in results if "ecp5" in r)
        missed = missed_by(results, "ecp5", ecp5_target)
        out += ["", "ECP5 (%s, %s, speed %s; %s, %s):" % (
            e0["device"], e0["package"], e0["speed"], e0["tools"]["yosys"], e0["tools"]["nextpnr"]),
            ""] + table
        out += ["", "ECP5 target (%d MHz at every seed) missed by: %s." % (
            DEFAULT_ECP5_TARGET_MHZ, ", ".join("`%s`" % v for v in missed) or "none")]
    out += gowin_section(results)
    rows = render_peer_rows(results, peers)
    if rows:
        out += ["", "The peers, measured by the same script in the same flow:", ""] + rows
    return out


def per_axis_rows(results):
    """LUT4/carry/FF per axis from two variants of one core that differ only in AXES
    (synth_report.axis_pairs and per_axis, as the peer rows compute it)."""
    rows = []
    for core, (lo, hi) in axis_pairs(results).items():
        per = per_axis(lo, hi, "ice40")
        rows.append("| `%s` | `%s` - `%s`, / %d | %.0f / %.0f / %.0f |" % (
            core, hi["variant"], lo["variant"], axes_of(hi) - axes_of(lo), per["lut4"],
            per["carry"], per["ff"]))
    return rows


def render(results, peers=()):
    seeds = sorted({p["seed"] for r in results for p in r["harness"]["hx8k"]})
    out = [BEGIN, "",
           "| variant | iCE40 core LUT4 / CARRY / FF / BRAM | HX8K Fmax, seeds %s (MHz) | target |"
           " critical path, first seed: from -> to | UP5K (sg48), seed %d | measured on, RTL |" % (
               "/".join(str(s) for s in seeds), results[0]["up5k"]["seed"]),
           "|---|---|---|---|---|---|---|"]
    missed = []
    for r in results:
        c, h, u = r["ice40_core"], r["harness"], r["up5k"]
        fm = " / ".join(seed_text(p) for p in h["hx8k"])
        t = target(r)
        ok = h["fmax_min_mhz"] is not None and h["fmax_min_mhz"] >= t and \
            all("fmax_mhz" in p for p in h["hx8k"])
        if not ok:
            missed.append(r["variant"])
        mac = ", %d SB_MAC16" % u["dsp_used"] if u.get("dsp_used") else ""
        if u["fits"]:
            up = "fits, %s of %s LC%s, %.2f MHz" % (u.get("lc_used"), u.get("lc_available"), mac,
                                                     u.get("fmax_mhz", 0))
        else:
            why = u.get("reason", "")[len("does not fit"):]
            up = "does not fit%s (%s LUT4 with the harness%s)" % (
                why, u.get("lut4", "?"), "" if "ICESTORM_DSP" in why else mac)
        out.append("| `%s` | %d / %d / %d / %d | %s | %d MHz: %s | %s | %s | %s, `%s` |" % (
            r["variant"], c["lut4"], c["carry"], c["ff"], c.get("bram", 0), fm, t,
            "met" if ok else "missed", h["hx8k"][0].get("no_fit") or
            path_text(h["hx8k"][0].get("critical_path")), up,
            r.get("date", "?"), (r.get("rtl_sha256") or "?")[:8]))
    axis = per_axis_rows(results)
    if axis:
        out += ["", "Per axis (two variants of a core that differ only in `AXES`):", "",
                "| core | from | LUT4 / CARRY / FF per axis |", "|---|---|---|"] + axis
    out += ["", "Target missed by: %s." % (", ".join("`%s`" % v for v in missed) or "none")]
    out += ecp5_section(results, peers)
    out += ["", END]
    return "\n".join(out)


def render_columns(names, by_name):
    """A synth-columns block: area and Fmax of the named variants, one column each."""
    missing = [v for v in names if v not in by_name]
    if missing:
        fail("a synth-columns block names unpublished variants: %s" % ", ".join(missing))
    rs = [by_name[v] for v in names]
    out = ["<!-- synth-columns: %s; written by scripts/synth/publish.py from docs/synth.json; "
           "do not edit -->" % " ".join(names), "",
           "| | %s |" % " | ".join("`%s`" % v for v in names),
           "|---|" + "---|" * len(names),
           "| iCE40 core LUT4 / carry / FF | %s |" % " | ".join(
               "%d / %d / %d" % (r["ice40_core"]["lut4"], r["ice40_core"]["carry"],
                                 r["ice40_core"]["ff"]) for r in rs),
           "| HX8K Fmax, seeds %s (MHz) | %s |" % (
               "/".join(str(p["seed"]) for p in rs[0]["harness"]["hx8k"]), " | ".join(
                   " / ".join(seed_text(p)
                              for p in r["harness"]["hx8k"]) for r in rs))]
    if all("ecp5" in r for r in rs):
        out += ["| ECP5 core LUT4 / CCU2C / FF | %s |" % " | ".join(
                    "%d / %d / %d" % (r["ecp5"]["core"]["lut4"], r["ecp5"]["core"]["carry"],
                                      r["ecp5"]["core"]["ff"]) for r in rs),
                "| ECP5 Fmax, seeds %s (MHz) | %s |" % (
                    "/".join(str(p["seed"]) for p in rs[0]["ecp5"]["runs"]), " | ".join(
                        " / ".join(seed_text(p)
                                   for p in r["ecp5"]["runs"]) for r in rs))]
    if all("gowin" in r for r in rs):
        out += ["| Gowin core LUT4 / ALU / FF | %s |" % " | ".join(
                    "%d / %d / %d" % (r["gowin"]["core"]["lut4"], r["gowin"]["core"]["alu"],
                                      r["gowin"]["core"]["ff"]) for r in rs),
                "| Gowin Fmax, seeds %s (MHz) | %s |" % (
                    "/".join(str(p["seed"]) for p in rs[0]["gowin"]["runs"]), " | ".join(
                        " / ".join(seed_text(p)
                                   for p in r["gowin"]["runs"]) for r in rs))]
    out += ["", "<!-- end synth-columns -->"]
    return "\n".join(out)


def with_columns(text, by_name):
    """text with every synth-columns block rendered again from docs/synth.json."""
    return COLUMNS_RE.sub(lambda m: render_columns(m.group(1).split(), by_name), text)


def table_parts():
    with open(TABLE_DOC) as f:
        text = f.read()
    if text.count(BEGIN) != 1 or text.count(END) != 1 or text.index(BEGIN) > text.index(END):
        fail("docs/synthesis.md needs exactly one pair of synth-table markers:\n  %s\n  %s"
             % (BEGIN, END))
    head, rest = text.split(BEGIN, 1)
    body, tail = rest.split(END, 1)
    return head, BEGIN + body + END, tail


def read_variants(path):
    try:
        with open(path) as f:
            return [l.split()[0] for l in f if l.strip()]
    except OSError as e:
        fail("cannot read --variants %s: %s" % (path, e))


def read_blocks(vfile):
    """The block names of the blocks.txt beside a variants.txt ([] when there is none)."""
    path = os.path.join(os.path.dirname(vfile), "blocks.txt")
    return read_variants(path) if os.path.exists(path) else []


def same_source(old, new):
    """Whether two records were measured on the same RTL (a peer: the same generated
    Verilog)."""
    key = "source_sha256" if "peer" in new else "rtl_sha256"
    return old.get(key) is not None and old.get(key) == new.get(key)


def with_family(record, fam, part):
    """record with `part` as its figures of family `fam`."""
    r = dict(record)
    r[fam] = part
    fams = list(r.get("families", []))
    if fam not in fams:
        fams.append(fam)
    r["families"] = [f for f in ("ice40",) + PART_FAMILIES if f in fams] + \
        [f for f in fams if f not in ("ice40",) + PART_FAMILIES]
    return r


def replace_record(old, new, warnings):
    """new, keeping old's ECP5 or Gowin figures where new has none of that family and both
    were measured on the same RTL; dropped (with a warning) on other RTL."""
    for fam in PART_FAMILIES:
        if old is None or fam not in old or fam in new:
            continue
        if same_source(old, new):
            new = with_family(new, fam, old[fam])
        else:
            warnings.append("%s: its published %s figures were measured on other RTL than the "
                            "new record; dropped (run scripts/synth.sh --family %s)" % (
                                new["variant"], fam, fam))
    return new


def same_netlist(old, new):
    """Whether two records' Yosys generic netlists have the same cells by type, by the same
    Yosys (a record's step 1)."""
    og, ng = old.get("generic") or {}, new.get("generic") or {}
    return bool(og.get("cells_by_type")) and og.get("cells_by_type") == ng.get("cells_by_type") \
        and old.get("tools", {}).get("yosys_generic") == new.get("tools", {}).get("yosys_generic")


def rehash(old, new):
    """old, taken as measured on new's RTL (publish.py --same-netlist): new's rtl_sha256, the
    old one kept with what showed the netlist the same."""
    r = dict(old)
    before = old.get("rtl_sha256")
    r["rtl_sha256"] = new["rtl_sha256"]
    for fam in PART_FAMILIES:
        if fam in r and r[fam].get("rtl_sha256") == before:
            r[fam] = dict(r[fam], rtl_sha256=new["rtl_sha256"])
    r["rtl_sha256_before"] = {
        "rtl_sha256": before, "git": new.get("git", ""), "date": new.get("date", ""),
        "why": "the RTL changed only where synthesis does not read it: the Yosys generic netlist "
               "of today's RTL (%s, %d cells, cells by type) is the published one" % (
                   new["tools"].get("yosys_generic", "?"), new["generic"]["cells"])}
    return r


def merge_family(old, new, fam, path, netlist_same=False):
    """old with new's figures of family `fam` (publish.py --family); with netlist_same
    (--same-netlist), old measured on other RTL whose generic netlist is that of new, measured
    on today's RTL, is rehashed."""
    name = new.get("variant")
    if old is None:
        fail("%s: %s is not published; publish a full run of it first (--family merges one "
             "family into a published record)" % (path, name))
    if fam not in new:
        fail("%s: %s has no %s figures (run scripts/synth.sh --family %s)" % (path, name, fam,
                                                                             fam))
    if not same_source(old, new) and netlist_same and "peer" not in new and \
            new.get("rtl_sha256") == rtl_digest(new.get("filelist", new["core"])) and \
            same_netlist(old, new):  # only towards today's RTL
        old = rehash(old, new)
    if not same_source(old, new):
        fail("%s: %s's %s figures were measured on other RTL than the published ones (%s %s, "
             "published %s): synthesize every family again" % (
                 path, name, fam, "source_sha256" if "peer" in new else "rtl_sha256",
                 (new.get("source_sha256") or new.get("rtl_sha256") or "none")[:12],
                 (old.get("source_sha256") or old.get("rtl_sha256") or "none")[:12]))
    return with_family(old, fam, new[fam])


def main(argv):
    check, vfile, inputs, family, netlist_same = False, None, [], None, False
    args = list(argv[1:])
    while args:
        a = args.pop(0)
        if a == "--check":
            check = True
        elif a == "--variants":
            if not args:
                fail("--variants needs a file")
            vfile = args.pop(0)
        elif a == "--family":
            if not args:
                fail("--family needs a family (%s)" % ", ".join(PART_FAMILIES))
            family = args.pop(0)
            if family not in PART_FAMILIES:
                fail("--family: '%s' is not a family whose figures merge apart (%s)" % (
                    family, ", ".join(PART_FAMILIES)))
        elif a == "--same-netlist":
            netlist_same = True
        elif a in ("-h", "--help"):
            sys.stderr.write(__doc__)
            return 2
        elif a.startswith("-"):
            fail("unknown option '%s'" % a)
        else:
            inputs.append(a)
    if check and inputs:
        fail("--check takes no SYNTH_JSON (it writes nothing)")
    if family and not inputs:
        fail("--family %s needs a SYNTH_JSON to merge" % family)
    if netlist_same and not family:
        fail("--same-netlist works with --family only")

    published, published_peers = load(PUBLISHED) if os.path.exists(PUBLISHED) else ([], [])
    by_name = {r["variant"]: r for r in published}
    peer_by_name = {p["variant"]: p for p in published_peers}
    warnings = []
    for path in inputs:
        variants, peers = load(path)
        for r in variants:
            if family:
                by_name[r["variant"]] = merge_family(by_name.get(r["variant"]), r, family, path,
                                                     netlist_same)
                continue
            if "harness" not in r:
                fail("%s: %s is a --generic-only result (no iCE40 figures); run synth.sh "
                     "without --generic-only" % (path, r.get("variant")))
            by_name[r["variant"]] = replace_record(by_name.get(r["variant"]), r, warnings)
        for p in peers:
            if family:
                peer_by_name[p["variant"]] = merge_family(peer_by_name.get(p["variant"]), p,
                                                          family, path)
            elif "harness" in p:
                peer_by_name[p["variant"]] = replace_record(peer_by_name.get(p["variant"]), p,
                                                            warnings)
    peers = [peer_by_name[v] for v in sorted(peer_by_name)]
    # Without --variants, the published order (then new variants by name), so a
    # plain merge renders the table as a --check --variants run does.
    blocks = read_blocks(vfile) if vfile else []
    order = read_variants(vfile) + blocks if vfile else \
        [r["variant"] for r in published] + sorted(v for v in by_name if v not in
                                                  {r["variant"] for r in published})
    results = [by_name[v] for v in order if v in by_name]
    results += [r for v, r in sorted(by_name.items()) if v not in order]

    problems = []
    if vfile:
        problems += ["%s: not published (run scripts/synth.sh --variant %s, then publish.py "
                     "its synth.json)" % (v, v) for v in order
                     if v not in by_name and v not in blocks]
        problems += ["%s: published but not a variant of cmake/cores.cmake" % v
                     for v in by_name if v not in order]
    for p in peers:
        info = p.get("peer") or {}
        versions = dict([info.get("package", "").split()] if info.get("package") else [])
        versions.update({k: info[k] for k in ("litex", "migen") if k in info})
        for pkg, version in sorted(versions.items()):
            if pinned(pkg) not in (None, version):
                problems.append("%s: measured with %s %s, scripts/requirements.txt pins %s: "
                                "synthesize it again" % (p["variant"], pkg, version, pinned(pkg)))
    for r in results:
        now = rtl_digest(r.get("filelist", r["core"]))
        for fam in PART_FAMILIES:
            part = r.get(fam) or {}
            if part.get("rtl_sha256", now) != now:
                problems.append("%s: its %s figures were measured on other RTL than rtl/%s.f "
                                "lists today (rtl_sha256 %s): run scripts/synth.sh --family %s" % (
                                    r["variant"], fam, r.get("filelist", r["core"]),
                                    part["rtl_sha256"][:12], fam))
        if r.get("rtl_sha256") != now:
            problems.append("%s: measured on other RTL than rtl/%s.f lists today (rtl_sha256 %s, "
                            "now %s): synthesize it again" % (r["variant"],
                                                              r.get("filelist", r["core"]),
                                                              (r.get("rtl_sha256") or "none")[:12],
                                                              now[:12]))
    head, section, tail = table_parts()
    table = render(results, peers) if results else BEGIN + "\n" + END
    by_variant = {r["variant"]: r for r in results}
    others = [p for p in column_docs() if os.path.abspath(p) != os.path.abspath(TABLE_DOC)]
    if check:
        if section != table:
            problems.append("docs/synthesis.md's synthesis table is not what docs/synth.json "
                            "renders: run scripts/synth/publish.py")
        stale = [TABLE_DOC] if head + tail != with_columns(head, by_variant) + \
            with_columns(tail, by_variant) else []
        for path in others:
            with open(path) as f:
                text = f.read()
            if text != with_columns(text, by_variant):
                stale.append(path)
        problems += ["a synth-columns block of %s is not what docs/synth.json renders: run "
                     "scripts/synth/publish.py" % os.path.relpath(p, ROOT) for p in stale]
        for p in problems:
            sys.stderr.write("publish: %s\n" % p)
        return 1 if problems else 0
    if inputs:
        with open(PUBLISHED, "w") as f:
            json.dump({"variants": results, "peers": peers}, f, indent=2)
            f.write("\n")
    with open(TABLE_DOC, "w") as f:
        f.write(with_columns(head, by_variant) + table + with_columns(tail, by_variant))
    for path in others:
        with open(path) as f:
            text = f.read()
        new = with_columns(text, by_variant)
        if new != text:
            with open(path, "w") as f:
                f.write(new)
    for p in warnings + problems:
        sys.stderr.write("publish: warning: %s\n" % p)
    sys.stdout.write("publish: %d variants in docs/synth.json, docs/synthesis.md's table and "
                     "every synth-columns block written\n" % len(results))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""Renders every measured figure in README.md and docs/**/*.md from the JSON data
files under docs/data/ (and the variant list from cmake/cores.cmake).

usage: scripts/docs/render.py [--check]
       scripts/docs/render.py --import KIND FILE [--seconds S] [--load L]

A block in the markdown is

    <!-- render: NAME [ARG]; from SOURCE by scripts/docs/render.py; do not edit -->
    ...
    <!-- end render -->

and its text is what the renderer NAME makes of SOURCE (a docs/data/*.json file,
or cmake/cores.cmake). Without options every block is rewritten. Each measured
data file holds the figures and `command` (what measured them), `date` and
`commit` (the tree measured; `recorded_in`: the commit that first stated an
imported figure), so a later run can refresh it.

  --check        write nothing; exit 1 naming every block that is not what its
                 source renders, an unknown block name, a data file without
                 command/date/commit, and a data file no block uses
  --import KIND FILE
                 make docs/data/KIND.json from a fresh report, with today's date
                 and the HEAD commit, then render every block. KIND:
                   regress    build/reports/regress.json of scripts/regress.sh
                              (--seconds S: its wall time; --load L: the load
                              average while it ran)
                   reproduce  hwinterp reproduce --json FILE
                   gcode      build/reports/gcode/*.json: hwinterp gcode
                              tests/data/gcode/<program>.ngc --mode direct --json FILE,
                              one FILE per committed program (several FILEs)
                   profile_programs  the same with --machine
                              tests/data/gcode/machine_profile.json --feed programmed
                              (the profile on), one FILE per program
                   back_to_back  hwinterp cosim --core C --job
                              docs/data/back_to_back.job --mode direct --json FILE,
                              for fixed_ratio, dda_line, ppc_line (three FILEs)
                   log_stepper   hwinterp cosim --core log_stepper --paper-log
                              [--mode direct] --json FILE (per mode), and --variant V
                              --random 3000 --seed 7 --mode direct --json FILE per
                              variant (--seconds T1,T2: their wall times; --load L)
                   planner    build/tests/bench_planner --benchmark_format=json
                              --benchmark_out=FILE
                 Other data files are measured by the command they name and
                 edited by hand (or imported from the commit that stated them).

Exit status: 0 done / consistent, 1 inconsistent, 2 bad input.
"""
import datetime
import glob
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(ROOT, "docs", "data")
BLOCK = re.compile(r"<!-- render: ([^;>]+); from ([^;>]+) by scripts/docs/render.py; do not edit -->\n"
                   r"(.*?)<!-- end render -->", re.S)
OPEN = re.compile(r"<!-- render:")
# Data files that are reference data, not measurements (no command/date/commit).
REFERENCE = {"papers.json"}


def fail(msg, code=2):
    sys.stderr.write("render: %s\n" % msg)
    sys.exit(code)


def load(name):
    path = os.path.join(DATA, name)
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail("cannot read docs/data/%s: %s" % (name, e))


# ---------------------------------------------------------------- formatting

def grp(n):
    """An integer with thin groups of three: 1 053 662 148."""
    s = "%d" % n
    out = ""
    while len(s) > 3:
        out = " " + s[-3:] + out
        s = s[:-3]
    return s + out


def f4(x):
    return "%.4f" % x


def mclk(x):
    """Clocks per second in M, three significant digits."""
    return ("%.3g" % (x / 1e6))


def duration(s):
    s = int(round(s))
    if s < 60:
        return "%d s" % s
    return "%d min %d s" % (s // 60, s % 60)


def source(d, what="Measured"):
    """The provenance line every measured block ends with."""
    at = "`%s`" % d["commit"]
    if d.get("recorded_in"):
        at += " (stated in README at `%s`)" % d["recorded_in"]
    return "<sub>%s with `%s` on %s, %s%s.</sub>" % (
        what, d["command"], at, d["date"],
        ("; " + d["machine"]) if d.get("machine") else "")


def table(head, rows):
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return out


# ---------------------------------------------------------------- renderers
# Each renderer: (source, function(arg) -> list of lines). The block holds the
# lines with a blank line before and after.

def r_variants(core):
    """The variants of cmake/cores.cmake: of one core, or every core (core = None)."""
    text = open(os.path.join(ROOT, "cmake", "cores.cmake")).read()
    rows = []
    for m in re.finditer(r"hwinterp_core_variant\(CORE (\w+) NAME (\w+)\s+PARAMS ([^)]*?)\s+DEFAULTS",
                         text):
        c, name, params = m.group(1), m.group(2), m.group(3).split()
        if core and c != core:
            continue
        rows.append(["`%s`" % name] + ([] if core else ["`%s`" % c]) +
                    [", ".join("`%s`" % p.replace("=", " = ") for p in params)])
    if not rows:
        fail("cmake/cores.cmake has no variant of %s" % core)
    return table(["variant"] + ([] if core else ["core"]) + ["parameters"], rows)


def r_papers(_):
    d = load("papers.json")
    rows = [["%s: %s" % (p["id"], p["alias"]),
             "[`%s`](../../shared/papers/%s)" % (p["file"], p["file"]),
             p["topic"], p["takes"], "`--paper %s`" % p["reproduce"]] for p in d["papers"]]
    return table(["paper", "file (`../shared/papers/`)", "topic", "what the project takes from it",
                  "`hwinterp reproduce`"], rows)


def paper_map():
    return {p["reproduce"]: p for p in load("papers.json")["papers"]}


def reproduce():
    d = load("reproduce.json")
    return d, {p["paper"]: p for p in d["papers"]}


def r_reproduced(_):
    d, P = reproduce()
    names = paper_map()
    rows = []
    for key, p in P.items():
        rows.append(["%s: %s" % (names[key]["id"], names[key]["alias"]), "`%s`" % key,
                     p["rows_compared"],
                     "all" if p["ok"] else "**not all**"])
    return table(["paper", "`--paper`", "rows compared with the paper", "rows that match"], rows) + [
        "", source(d)]


def r_worst40(_):
    d, P = reproduce()
    w = P["ratio"]["worst_up_to_40"]
    rows = [[m, f4(w[m])] for m in ("fixed ratio", "DDA plain", "DDA half", "PPC", "min deviation",
                                     "Bresenham")]
    return ["Worst path error (steps) over every 2-axis line with `|dx|, |dy| <= 40`, from the "
            "models:", ""] + table(["method", "worst error"], rows) + ["", source(d)]


def hw_worst(P, col):
    return max(l[col]["max_error"] for l in P["ratio"]["hardware"])


def hw_ticks(P, col, line=1):
    return [l for l in P["ratio"]["hardware"] if l["line"] == line][0][col]["ticks"]


def row(P, key, start):
    for r in P[key]["rows"]:
        if r["figure"].startswith(start):
            return r
    fail("reproduce.json: paper %s has no row '%s'" % (key, start))


def r_hw_lines(_):
    """The eight lines on the hardware, beside the exact-frequency and divider models."""
    d, P = reproduce()
    cols = [("exact_frequency", "exact f (model)"), ("dividers_1mhz", "dividers 1 MHz (model)"),
            ("fixed_ratio", "`fixed_ratio`"), ("dda_line", "`dda_line`"),
            ("dda_line half", "`dda_line` half"), ("ppc_line", "`ppc_line`")]
    rows = []
    for l in P["ratio"]["hardware"]:
        rows.append(["L%d" % l["line"]] + ["%s / %g" % (f4(l[c]["max_error"]), round(l[c]["ticks"], 1))
                                            for c, _ in cols])
    return ["Paper 004's eight lines, max error (steps) / completion ticks; the hardware "
            "columns are the HLS core and the RTL in lockstep against their model, ticks read "
            "at the pins:", ""] + table(["line"] + [n for _, n in cols], rows) + ["", source(d)]


def r_pick(_):
    """README's pick-a-core table: reproduce figures and back-to-back clocks."""
    d, P = reproduce()
    b = load("back_to_back.json")
    per = {r["variant"]: "%.1f" % (r["cycles"] / r["commands"]) for r in b["runs"]}
    fr, dd, pp = "fixed_ratio_n2", "dda_line_n2", "ppc_line_a32"
    rows = [
        ["completion of a line, ticks", "`max(\\|dx\\|,\\|dy\\|)`: the fewest",
         "`2^n` (n = bit length of the longest delta): up to `2 max`", "`\\|dx\\| + \\|dy\\|`: up to `2 max`"],
        ["paper 004's line 1 `(0,0)->(20,40)`, ticks (hardware)",
         "%g" % hw_ticks(P, "fixed_ratio"), "%g" % hw_ticks(P, "dda_line"), "%g" % hw_ticks(P, "ppc_line")],
        ["error bound, 2 axes (steps)", "`<= 0.5625`", "`< 1` plain, `<= 0.7071` half preload",
         "`<= max/L < 1`"],
        ["worst error on the eight lines (hardware)", f4(hw_worst(P, "fixed_ratio")),
         "%s plain, %s half" % (f4(hw_worst(P, "dda_line")), f4(hw_worst(P, "dda_line half"))),
         f4(hw_worst(P, "ppc_line"))],
        ["axes", "N", "N", "2 (`ppc_arc` for arcs)"],
        ["1-step commands back to back, clocks each (200 in a row)", "%s (`FRAC_W + 4` = 39)" % per[fr],
         per[dd], per[pp]],
    ]
    return table(["", "`%s`" % fr, "`%s`" % dd, "`%s`" % pp], rows) + [
        "", source(d) + " " + source(b)]


def r_ppc_line1(_):
    d, P = reproduce()
    ops = row(P, "ratio", "PPC operations on line 1, hardware")["ours"]
    clocks = row(P, "ratio", "  its clocks at feed 1/2")["ours"]
    return ["Paper 004's line 1 `(0,0)->(20,40)` takes %s operations on `ppc_line_a32` and %s "
            "clocks from reset at feed 1/2 with timing 1,1,1,1 (2 per operation, and reset, take, "
            "load, the last fall and the tail)." % (ops, clocks), "", source(d)]


def r_dividers(_):
    d, P = reproduce()
    l1 = [x for x in P["ratio"]["divider_1mhz"] if x["line"] == 1][0]
    return ["With integer clock dividers at 1 MHz (the model) paper 004's line 1 is %s steps off "
            "the line; `fixed_ratio` in lockstep has %s at worst on the eight lines, equal to its "
            "model tick for tick." % ("%.2f" % l1["max_error"], f4(hw_worst(P, "fixed_ratio"))),
            "", source(d)]


def r_log_paper(_):
    d, P = reproduce()
    L = load("log_stepper.json")
    hw = P["log"]["hardware"]
    p = L["paper_curve"]
    lastx = row(P, "log", "hardware: last X")
    return ["The paper's curve on `%s` in lockstep (1000 steps/mm, 1000 steps/deg, dl = 0.2 mm): "
            "%d points, each %d steps from the double model's point rounded to steps; last X %s mm "
            "on the lattice (paper %s)." % (hw["variant"], hw["points"], hw["max_point_error_steps"],
                                            lastx["ours"], lastx["paper"]), "",
            "`%s` runs it in %s clocks at full feed with the default timing, path error %s steps "
            "(the 4-axis DDA bound with half preload is 1), ErPA of the lattice path %.3g rad, "
            "%s." % (p["command"], grp(p["cycles"]), f4(p["max_path_error_steps"]), p["max_erpa_rad"],
                     "in both lockstep modes" if len(p["modes"]) == 2 else
                     "in the %s mode" % p["modes"][0]), "", source(d) + " " + source(L)]


def r_log_random(_):
    L = load("log_stepper.json")
    rows = [["`%s`" % r["variant"], grp(r["points"]), grp(r["cycles"]), r["max_point_error_steps"],
             f4(r["max_path_error_steps"]),
             "%.1f s" % r["seconds"] if r.get("seconds") is not None else "-"] for r in L["random"]]
    return ["Random curves, `%s` per variant:" % L["random_command"], ""] + table(
        ["variant", "points", "clocks", "worst point error (steps)", "path error (steps)", "wall"],
        rows) + ["", source(L)]


def r_regress(_):
    d = load("regress.json")
    rows = [["`%s`" % c, v["runs"], v["cases"], grp(v["cycles"]), "pass" if v["passed"] else "**FAIL**"]
            for c, v in d["cores"].items()]
    text = ["%d variants, %d runs, %d cases, %s clocks, %s%s. The direct-mode runs took %.1f s "
            "together; the SystemC runs share one elaboration and run side by side in %.0f s." % (
                d["variants"], d["runs"], d["cases"], grp(d["cycles"]),
                "every case passed" if d["passed"] else "**some cases failed**",
                (", in %s wall time with the build in place" % duration(d["wall_seconds"]))
                if d.get("wall_seconds") else "", d["direct_seconds"], d["systemc_seconds"])]
    return text + [""] + table(["core", "runs", "cases", "clocks", "result"], rows) + ["", source(d)]


def r_regress_short(_):
    d = load("regress.json")
    return ["Measured at `%s` (%s): %d variants, %d cases, %.1f M clocks, %s, in %s with the "
            "build in place (%s)." % (d["commit"], d["date"], d["variants"], d["cases"],
                                      d["cycles"] / 1e6,
                                      "all passed" if d["passed"] else "**some failed**",
                                      duration(d["wall_seconds"]), d["machine"])]


def r_test_suite(_):
    d = load("test_suite.json")
    return ["Measured at `%s` (%s): %s for %d tests on a clean clone, the build included "
            "(Debian packages already installed; %s)." % (d["commit"], d["date"],
                                                          duration(d["wall_seconds"]), d["tests"],
                                                          d["machine"])]


def r_lockstep(_):
    d = load("lockstep_speed.json")
    rows = [["`%s`" % v["variant"], v["clocks"], "%g" % v["rtl"], "%g" % v["hls"], "%g" % v["lockstep"],
             "%g" % v["full"], "%d %%" % v["checks_percent"]] for v in d["variants"]]
    cs = [v["checks_percent"] for v in d["variants"]]
    over = d["over_lockstep_percent"]
    ex = ", ".join("`%s` %d %% (runs: %s)" % (k, v["median"], ", ".join("%d" % x for x in v["runs"]))
                   for k, v in over["exceptions"].items())
    return table(["variant", "clocks", "RTL", "HLS", "lockstep", "full", "checks"], rows) + [
        "", "The checks cost %d to %d %% of the full mode's time. Counted against the lockstep "
        "time instead (`full / lockstep - 1`), the medians are %d to %d %% except %s." % (
            min(cs), max(cs), over["others"][0], over["others"][1], ex), "", source(d)]


def r_perf_checks(_):
    d = load("lockstep_speed.json")
    p = d["profile"]
    parts = ", ".join("%s %.1f %%" % (k, v) for k, v in p["share_percent"].items())
    return ["`perf record` of `%s`'s full mode alone (`%s`, the replay switched off by hand): %s "
            "of the samples; the two DUTs take %d %%." % (p["variant"], p["command"], parts,
                                                         p["duts_percent"]), "", source(d)]


def r_simulators(_):
    d = load("simulators.json")
    r = d["rates"]
    return ["One 4-axis `dda_line` stream of %s clocks, best of 3: direct mode %s M clocks/s, "
            "SystemC mode %s M, Icarus Verilog running the RTL alone on the same input frames %s k "
            "(it reproduces the same steps, positions and done pulses): the direct mode is %dx "
            "Icarus, the SystemC mode %dx." % (
                grp(d["clocks"]), "%.2f" % (r["direct"] / 1e6), "%.2f" % (r["systemc"] / 1e6),
                "%.1f" % (r["icarus"] / 1e3), round(r["direct"] / r["icarus"]),
                round(r["systemc"] / r["icarus"])), "", source(d)]


def r_memory(_):
    d = load("memory.json")
    rows = [["`%s`" % v["variant"], grp(v["clocks"]),
             "%.3g M, %.1f" % (v["direct"]["clocks_per_second"] / 1e6, v["direct"]["peak_mib"]),
             "%.3g M, %.1f" % (v["systemc"]["clocks_per_second"] / 1e6, v["systemc"]["peak_mib"])]
            for v in d["variants"]]
    t = d["traces"]
    return table(["variant", "clocks", "direct: clocks/s, peak MiB", "SystemC: clocks/s, peak MiB"],
                 rows) + ["", "Traces of a 4-axis `dda_line` stream (%s clocks): VCD %.1f MB per "
                          "million clocks, FST %.1f MB per million clocks." % (
                              grp(t["clocks"]), t["vcd_mb_per_mclock"], t["fst_mb_per_mclock"]),
                          "", source(d)]


def r_soak(_):
    d = load("soak.json")
    rows = [["`%s`" % c["core"], grp(c["commands_per_stream"]), grp(c["clocks"]), c["cases"],
             c["mismatches"], c["timing_violations"], c["scoreboard_errors"]] for c in d["cores"]]
    total = sum(c["clocks"] for c in d["cores"])
    worst = "; ".join("`%s` %.8g (bound %.8g)" % (w["variant"], w["error"], w["bound"])
                      for w in d["fixed_ratio_worst"])
    return table(["core", "random commands per stream", "clocks", "cases", "mismatches",
                  "timing violations", "scoreboard errors"], rows) + [
        "", "%.1f * 10^9 clocks over the variants of %s. `dda_line` alone took %d s "
        "(`scripts/soak.sh --cores dda_line`). The worst `fixed_ratio` path errors against their "
        "command's bound: %s." % (total / 1e9, ", ".join("`%s`" % c["core"] for c in d["cores"]),
                                  d["dda_line_seconds"], worst), "", source(d)]


def r_fuzz(_):
    d = load("fuzz.json")
    runs = []
    for r in d["runs"]:
        runs.append("%d s a target: %s" % (r["seconds"], ", ".join(
            "`%s` %s inputs%s" % (t["target"], grp(t["inputs"]),
                                   (" (coverage %d)" % t["coverage"]) if t.get("coverage") else "")
            for t in r["targets"])))
    return ["Measured, clean: " + "; ".join(runs) + ".", "", source(d)]


def r_sanitize(_):
    d = load("sanitize.json")
    return ["All %d tests pass with no sanitizer report (the tests took %d s after the build). "
            "UBSan's `shift-base` check is off: SystemC's own `sc_int` sign extension (`%s`) trips "
            "it in every signed HLS datapath (the first run with it on: %d tests, all at that line, "
            "nothing else)." % (d["tests"], d["test_seconds"], d["shift_base"]["where"],
                                d["shift_base"]["tests"]), "", source(d)]


def r_sharding(_):
    d = load("sharding.json")
    s = d["scaling"]
    parts = []
    for r in s["runs"]:
        rates = [s["clocks"] / t / 1e6 for t in r["seconds"]]
        parts.append("%d shard%s %s s (%s M clocks/s)" % (
            r["shards"], "s" if r["shards"] > 1 else "", " and ".join("%.1f" % t for t in r["seconds"]),
            " to ".join("%.1f" % x for x in sorted({round(x, 1) for x in rates}))))
    base = min(s["runs"][0]["seconds"]), max(s["runs"][0]["seconds"])
    two = min(s["runs"][1]["seconds"]), max(s["runs"][1]["seconds"])
    sl = d["slurm"]
    return ["Scaling, the same %s-clock regression (`%s`, two interleaved rounds, wall time "
            "including the merge): %s, a speed-up of %.1f to %.1f." % (
                grp(s["clocks"]), s["command"], ", ".join(parts), base[0] / two[1], base[1] / two[0]),
            "", "`%s` (ctest `slurm_array`): %d array tasks, %d cases, %s, %.1f s." % (
                sl["command"], sl["tasks"], sl["cases"], sl["result"], sl["seconds"]),
            "", source(d)]


def r_gcode_programs(_):
    d = load("gcode_programs.json")
    rows = []
    for p in d["programs"]:
        m = p["moves"]
        c = p["commands"]
        rows.append(["`%s`" % p["program"], "%d (%d / %d / %d)" % (m["total"], m["rapid"], m["feed"], m["arc"]),
                     "%d (%d / %d)" % (c["total"], c["line"], c["arc"]),
                     "%.4f mm = %.3f steps (line %d)" % (p["max_contour_error_mm"],
                                                         p["max_contour_error_steps"], p["max_line"]),
                     "%.3f s" % p["programmed_seconds"], "%.3f s" % p["feed_word_seconds"],
                     grp(p["clocks"]), grp(p["visited_points"])])
    short = max((1 - p["feed_word_seconds"] / p["programmed_seconds"]) * 100 for p in d["programs"])
    return table(["program", "moves (rapid / feed / arc)", "commands (line / arc)",
                  "max contour error", "machining time, F", "from the feed words",
                  "clocks at full feed", "visited points"], rows) + [
        "", "The feed-word time is at most %.2f %% short of the programmed time." % short,
        "", source(d)]


def r_gcode_bench(_):
    d = load("gcode_bench.json")
    rows = [[grp(r["moves"]), grp(r["commands"]), grp(r["steps"]), grp(r["clocks"]), "%.1f s" % r["seconds"],
             grp(round(r["steps"] / r["seconds"])), grp(round(r["clocks"] / r["seconds"])),
             "%.1f MiB" % r["peak_mib"]] for r in d["runs"]]
    return table(["moves", "commands", "steps", "clocks", "wall", "steps/s end to end", "clocks/s",
                  "peak memory"], rows) + ["", source(d)]


def r_netlist(_):
    d = load("netlist_check.json")
    return ["`%s` passes: %s-command random streams with aborts and feed holds, %s clocks, every "
            "output equal on every clock." % (d["command"], d["commands"], " and ".join(
                "%s on `%s`" % (grp(v["clocks"]), v["variant"]) for v in d["variants"])), "", source(d)]


def r_planner(_):
    d = load("planner_bench.json")
    ms = [c["ms"] for c in d["cases"]]
    return ["Every case of Tables 1 and 3 plans in %.2g to %.2g ms of CPU time (`%s`)." % (
        min(ms), max(ms), d["command"]),
            "", source(d)]


def r_synth_blocks(_):
    d = load("synth_blocks.json")
    rows = [["`%s`" % b["block"], b["what"], b["instances"], b["lut4"], b["carry"], b["ff"]]
            for b in d["blocks"]]
    t = d["total"]
    return ["`%s` without flattening, per module instance (%s, not flattened, so the total, %d "
            "LUT4 / %d carry / %d FF, differs a little from the table's):" % (
                d["variant"], d["tool"], t["lut4"], t["carry"], t["ff"]), ""] + table(
        ["module", "what", "instances", "LUT4", "carry", "FF"], rows) + ["", source(d)]


def r_link_size(_):
    d = load("link_size.json")
    rows = [["`%s`" % b["block"], b["params"], b["lut4"], b["carry"], b["ff"], b["bram"],
             "%d LC, %d RAM" % (b["hx8k_lc"], b["hx8k_ram"]), "%.2f MHz" % b["fmax_mhz"]]
            for b in d["blocks"]]
    parts = [["`%s`" % m["module"], m["lut4"], m["carry"], m["ff"], m["bram"]]
             for m in d["uart_etherbone_blocks"]]
    return table(["block", "parameters", "LUT4", "carry", "FF", "SB_RAM40_4K",
                  "HX8K, in the pin harness", "Fmax there"], rows) + [
        "", "`uart_etherbone` not flattened, per block (so its total differs a little):", ""] + table(
        ["block", "LUT4", "carry", "FF", "SB_RAM40_4K"], parts) + ["", "%s (%s)." % (
            d["what"][0].upper() + d["what"][1:], d["tool"]), "", source(d)]


def synth_missed_paths(family):
    """The critical path at every seed of each variant that misses its target on a family
    ("hx8k", "ecp5" or "gowin"; docs/synth.json, as scripts/synth/publish.py writes it)."""
    sys.path.insert(0, os.path.join(ROOT, "scripts", "synth"))
    import publish  # noqa: E402  (its path texts and targets)
    import synth_report  # noqa: E402  (the ECP5 path text: registers with their RTL lines)
    with open(os.path.join(ROOT, "docs", "synth.json")) as f:
        results = json.load(f)["variants"]
    if family == "hx8k":
        target, runs_of, path = publish.target, lambda r: r["harness"]["hx8k"], publish.path_text
    else:
        target = publish.ecp5_target if family == "ecp5" else publish.gowin_target
        runs_of = lambda r: r.get(family, {}).get("runs", [])  # noqa: E731
        path = synth_report.ecp5_path_text
    rows = []
    for r in results:
        t, runs = target(r), runs_of(r)
        if t is None or all(p.get("fmax_mhz", 0) >= t for p in runs):
            continue
        rows += [["`%s`" % r["variant"], p["seed"], publish.seed_text(p),
                  path(p.get("critical_path"))] for p in runs]
    name = {"gowin": "Gowin"}.get(family, family.upper())
    return table(["variant", "seed", "%s Fmax (MHz)" % name,
                  "critical path: from -> to"], rows)


def r_synth_paths(_):
    return synth_missed_paths("hx8k")


def r_synth_paths_ecp5(_):
    return synth_missed_paths("ecp5")


def r_synth_paths_gowin(_):
    return synth_missed_paths("gowin")


def r_folder_graph(_):
    """tb/'s folder graph from its includes (scripts/folder_graph.py)."""
    sys.path.insert(0, os.path.join(ROOT, "scripts"))
    import folder_graph  # noqa: E402
    g = folder_graph.edges(os.path.join(ROOT, "tb"))
    found = folder_graph.circles(g)
    if found:
        return ["Circles: " + "; ".join(" <-> ".join(c) for c in found)]
    return [folder_graph.markdown(g), "",
            "<sub>Computed from the `#include` lines by `scripts/folder_graph.py --markdown tb`; "
            "layer 0 includes no other folder, every other folder only lower layers.</sub>"]


def r_soc_timing(_):
    """docs/soc.md: the timing the cocotb tests measure."""
    d = load("soc.json")
    w, p, f = d["watchdog"], d["probe"], d["fifo"]
    rows = [
        ("watchdog, `WDOG_PERIOD` = %d: bite after the last kick's write" % w["period"],
         "%d (P + 1)" % w["bite_after_kick"]),
        ("probe latch, filter %d: `LATCH_TIME` after the pin rose" % p["filter"],
         "%d (2 synchronizer + %d filter + 1)" % (p["latch_after_pin"], p["filter"])),
        ("snapshot armed for `SNAP_AT` = T", "`SNAP_TIME` = T exactly"),
        ("timed command, `CMD_AT` = T, core idle", "taken at `TIME` = T exactly"),
        ("FIFO depth %d with the feed held" % f["depth"],
         "%d pushes taken (%d in the FIFO, %d in the core), the next sets `EVENTS.overflow`"
         % (f["taken"], f["depth"], f["taken"] - f["depth"])),
    ]
    return table(["What", "Clocks"], rows) + ["", source(d)]


def r_soc_tests(_):
    """docs/soc.md: what the cocotb run took and counted."""
    d = load("soc.json")
    a, b = d["buses"]["axil"], d["buses"]["wb"]

    def counts(r):
        return "%d reads, %d writes, %d illegal accesses, %d pushes taken, %d refused (FIFO full)" % (
            r["read"], r["write"], r["illegal"], r["push"], r["refused"])
    return ["%d/%d tests pass on AXI4-Lite and %d/%d on Wishbone in %s, the Verilated build "
            "included (the tests themselves: %.1f s and %.1f s). Every readable word's reset "
            "value (%d words) and all %d unmapped word addresses are checked on each bus. The "
            "random traffic (%d operations): AXI4-Lite %s; Wishbone %s." % (
                a["passed"], a["tests"], b["passed"], b["tests"], duration(d["seconds"]),
                a["test_seconds"], b["test_seconds"], d["reset_words"], d["unmapped_words"],
                d["random_ops"], counts(a["random"]), counts(b["random"])), "", source(d)]


def r_profile_ruckig(_):
    """docs/profile.md: the feed profile's move times against Ruckig's."""
    d = load("profile_ruckig.json")
    pct = lambda x: "%+.3f %%" % (100 * x)
    rows = [["%d %s" % (d[k]["n"], what)] + [pct(d[k][q]) for q in ("min", "median", "p90", "max")]
            for k, what in (("rest_to_rest", "rest to rest"), ("end_speed", "to an end speed"))]
    return table(["moves", "min", "median", "p90", "max"], rows) + ["", source(d)]


def r_profile_programs(_):
    """docs/profile.md: the committed programs at their programmed feeds with the S-curve."""
    d = load("profile_programs.json")
    rows = []
    for p in d["programs"]:
        path = p["path"]
        worst = max(p["axes"], key=lambda a: a["accel_share"])
        jworst = max(p["axes"], key=lambda a: a["jerk_share"])
        rows.append(["`%s`" % p["program"], "%.3f s" % p["programmed_seconds"],
                     "%.3f s" % p["profile_seconds"],
                     "%.3g mm/s, %.4g mm/s^2, %.4g mm/s^3" % (path["speed"], path["accel"], path["jerk"]),
                     "%s %.0f %%" % (worst["axis"], 100 * worst["accel_share"]),
                     "%s %.0f %%" % (jworst["axis"], 100 * jworst["jerk_share"]),
                     grp(p["clocks"]), "yes" if p["passed"] else "NO"])
    return table(["program", "time at F, no acceleration", "time at the S-curve",
                  "path peaks: speed, accel, jerk", "highest axis accel / its limit",
                  "highest axis jerk / its limit", "clocks", "within the limits, same points"],
                 rows) + ["", d["what"] + ".", "", source(d)]


def r_boards(_):
    """docs/synthesis.md's Boards section: each board's bitstream build (scripts/board.sh:
    hwinterp_litex/build.py), the peer's beside."""
    d = load("boards.json")
    order = ["colorlight_5a_75b", "tang_nano_20k", "ice40_hx8k_breakout"]
    names = [n for n in order if n in d["boards"]] + sorted(
        n for n in d["boards"] if n not in order)
    rows, tools = [], []
    for n in names:
        b = d["boards"][n]
        u = next((r["utilization"] for r in b["runs"] if r.get("utilization")), {})

        def cell(k):
            if k not in u:
                return "-"
            c = u[k]
            return "%s / %s `%s`" % (grp(c["used"]), grp(c["available"]), c["cell"])
        seeds = []  # [seeds, text]: seeds with the same text in one entry
        for r in b["runs"]:
            if "no_fit" in r:
                text = "does not fit (%s)" % ", ".join(
                    "`%s` %s of %s" % (o["cell"], grp(o["used"]), grp(o["available"]))
                    for o in r["no_fit"])
            else:
                text = "%.2f%s" % (r["fmax_mhz"],
                                   "" if r["fmax_mhz"] >= b["need_mhz"] else " (**slow**)")
            if seeds and seeds[-1][1] == text and "does not fit" in text:
                seeds[-1][0].append(r["seed"])
            else:
                seeds.append([[r["seed"]], text])
        seeds = ["%s: %s" % ("/".join(str(x) for x in ss), text) for ss, text in seeds]
        sizes = [r["bitstream_bytes"] for r in b["runs"] if "bitstream_bytes" in r]
        size = " / ".join(grp(x) for x in sizes) if sizes else "-"
        rows.append(["`%s`" % n, b["what"], cell("lut"), cell("ff"), cell("bram"),
                     "%g, needs %.2f" % (b["sys_mhz"], b["need_mhz"]), "; ".join(seeds), size,
                     "yes" if b["passed"] else "**no**",
                     "`%s` at `%s`, %s" % (b["command"], b["commit"], b["date"])])
        t = b["tools"]
        yosys = re.sub(r"^(Yosys \S+ \(git sha1 \w+).*$", r"\1)", t["yosys"])
        pnr = re.sub(r'^"?([^"\s]+)"? -- Next Generation Place and Route \(Version (.*)\)$',
                     r"\1 \2", t["nextpnr"])
        tools.append("`%s`: %s; %s; %s; LiteX %s" % (n, yosys, pnr, t["packer"], t["litex"]))
    slow = []
    for n in names:
        b = d["boards"][n]
        for r in b["runs"]:
            cp = r.get("critical_path")
            if "fmax_mhz" in r and r["fmax_mhz"] < b["need_mhz"] and cp:
                slow.append("- `%s`, seed %d: `%s` -> `%s`, %.2f ns logic + %.2f ns routing, "
                            "through cells named after %s." % (
                                n, r["seed"], cp["from"], cp["to"], cp["logic_ns"],
                                cp["routing_ns"], ", ".join("`%s`" % x for x in cp["through"])))
    if slow:
        slow = ["", "The critical path of each seed below its target (nextpnr's names of the "
                "flattened netlist):", ""] + slow
    return table(["board", "design", "logic used / part", "FF used / part", "BRAM used / part",
                  "sys clock (MHz)", "Fmax per seed (MHz)", "bitstream (bytes)", "passes",
                  "measured with"], rows) + [
        "", "Fmax: nextpnr's figure for the system clock's domain; each seed must reach "
        "%.2f x the system clock. Logic, FF, BRAM: nextpnr's placed cells (ECP5 `TRELLIS_COMB` "
        "is a LUT4 or half a carry, Gowin's `LUT4` without its `ALU` carry cells, iCE40 "
        "`ICESTORM_LC` a LUT4 with its flip-flop, the iCE40's FF the netlist's `SB_DFF*`). "
        "Bitstream: the packed file of each seed, in seed order (ECP5 `.bit` compressed; "
        "Gowin's `.fs` is text, a character a bit)." % d["margin"]] + slow + ["", "Tools: " + "; ".join(tools) + ".", "",
                                                source(d)]


def r_board_link(_):
    """docs/boards.md: the host link streaming moves into the simulated boards
    (scripts/board_link_bench.py)."""
    d = load("board_link.json")
    rows = []
    for c in d["cases"]:
        tc = c["transport_counts"]
        link = "Etherbone/UDP" if c["link"] == "etherbone" else "UART %s baud" % grp(c["baud"])
        wire = ("%s a command: %s/s on the wire" % (
            "%.0f bytes" % c["bytes_per_command"], grp(round(c["wire_commands_per_s"])))
            if c.get("wire_commands_per_s") else "%.1f commands a packet" % c["commands_per_packet"])
        rows.append(["`%s` at %g MHz%s" % (c["board"], c["sys_hz"] / 1e6,
                                           "" if c["profile"] else ", no profile"),
                     link, "%s of %g ms" % (grp(c["moves"]), c["move_s"] * 1e3),
                     "%.4f / %.4f" % (c["machine_time_s"], c["planned_time_s"]),
                     grp(round(c["commands_per_machine_s"])), grp(c["packets"]),
                     c["full_polls"], grp(tc["bytes_sent"]) + " / " + grp(tc["bytes_received"]),
                     wire, "yes" if c["passed"] else "**no**"])
    return table(["board", "link", "moves", "machine time / planned (s)",
                  "commands a second of machine time", "packets", "polls with the FIFO full",
                  "bytes to / from the board", "link", "passed"], rows) + ["", source(d)]


def r_linuxcnc_pins(_):
    """docs/linuxcnc.md: the HAL component's pins and parameters, as
    sw/hal/hwinterp.comp declares them (halcompile's `pin`/`param` lines)."""
    rows = []
    decl = re.compile(r'^(pin|param)\s+(in|out|rw|r)\s+(\w+)\s+([\w.#]+)(\[[^\]]*\])?'
                      r'(?:\s*=\s*([^"\s]+))?\s*"([^"]*)"\s*;')
    with open(os.path.join(ROOT, "sw", "hal", "hwinterp.comp")) as f:
        for line in f:
            m = decl.match(line.strip())
            if not m:
                continue
            kind, d, typ, name, arr, default, doc = m.groups()
            name = "hwinterp." + name.replace("##", "NN").replace("_", "-")
            rows.append(["`%s`" % name, kind, d, typ, default or "", doc])
    if not rows:
        fail("sw/hal/hwinterp.comp declares no pins")
    return table(["name", "kind", "direction", "type", "default", "what"], rows) + [
        "", "<sub>From `sw/hal/hwinterp.comp`; `NN` is the stepgen's number, 00 to "
        "personality - 1.</sub>"]


def linuxcnc_run_name(r, what):
    """A SIL run's name in the tables: the program (or fault), and the link
    when it is the UART (with its servo period)."""
    if r.get("link", "").startswith("serial:"):
        return "%s over the UART (%s baud, %g ms period)" % (
            what, r["link"].rsplit("@", 1)[-1], r["servo_period_s"] * 1e3)
    return what


def r_linuxcnc_runs(_):
    """docs/linuxcnc.md: LinuxCNC, the HAL component and the simulated board,
    per program (scripts/linuxcnc/sil_all.sh)."""
    d = load("linuxcnc_sil.json")
    rows = []
    for r in d["runs"]:
        if r.get("fault"):
            continue
        if r.get("missing"):
            rows.append(["`%s`" % os.path.basename(r["program"])] + ["(no report)"] * 9 + ["**no**"])
            continue
        drv = r.get("driver", {})
        periods = max(r["periods_run"], 1)
        rows.append([
            linuxcnc_run_name(r, "`%s`" % os.path.basename(r["program"])), grp(r["periods_run"]),
            "%s / %s" % (grp(r["boundaries_checked"] - r["boundaries_with_error"]),
                         grp(r["boundaries_checked"])),
            "%d" % max(r["ferror_at_boundaries_max_steps"]), "%.2f" % r["ferror_inside_period_max_steps"],
            str(r["late_commands"]),
            "%.3f (%s missed)" % (drv.get("stats.sends", 0) / periods, r["missed_slots"]),
            "%s / %s" % (drv.get("stats.bytes-sent-max", "-"), drv.get("stats.bytes-received-max", "-")),
            "yes" if r["end_equal"] else "**no**",
            "%.2f / %.2f / %.2f" % (r["machining_s_linuxcnc"] or 0, r["motion_s_commanded"],
                                   r["motion_s_board"]),
            "yes" if r["passed"] else "**no**"])
    updates = ["<sub>Again: %s with `%s` on `%s`, %s.</sub>" % (
        ", ".join("`%s`" % p for p in u["programs"]), u["command"], u["commit"], u["date"])
        for u in d.get("updates", [])]
    return table(["program", "periods", "boundaries at 0 error / checked",
                  "max following error at a boundary (steps)", "max inside a period (steps)",
                  "late commands", "packets sent a period", "bytes a packet, most (to / from)",
                  "end positions equal", "machining s: LinuxCNC / commanded motion / board's steps",
                  "passed"], rows) + ["", source(d)] + (["", *updates] if updates else [])


def r_linuxcnc_trace(_):
    """docs/linuxcnc.md: corners.ngc through LinuxCNC and the board, as
    charts (Mermaid, drawn where the Markdown is read) from the run's trace
    in docs/data/linuxcnc_sil.json."""
    d = load("linuxcnc_sil.json")
    r = next((r for r in d["runs"] if os.path.basename(r["program"]) == "corners.ngc" and
              not r.get("fault") and not r.get("link", "").startswith("serial:") and r.get("trace")),
             None)
    if r is None:
        fail("docs/data/linuxcnc_sil.json: no trace of corners.ngc over UDP")
    tr = r["trace"]
    xs = "[%s]" % ", ".join('"%.1f"' % t for t in tr["t_s"])
    out = []
    for axis in ("x", "y"):
        cmd, brd = tr[axis + "_cmd"], tr[axis + "_board"]
        out += ["```mermaid", "xychart-beta",
                '    title "%s: LinuxCNC\'s lattice point and the board\'s step pins at the '
                'boundaries"' % axis.upper(),
                '    x-axis "board time (s)" %s' % xs,
                '    y-axis "%s (steps)"' % axis.upper(),
                "    line [%s]" % ", ".join(map(str, cmd)),
                "    line [%s]" % ", ".join(map(str, brd)), "```", ""]
    worst = tr["ferror_max"]
    out += ["```mermaid", "xychart-beta",
            '    title "Largest following error of any joint at the boundaries (steps)"',
            '    x-axis "board time (s)" %s' % xs,
            '    y-axis "steps" 0 --> %d' % max(1, max(worst)),
            "    bar [%s]" % ", ".join(map(str, worst)), "```", "",
            "<sub>%d samples of %s boundaries (%s at 0 error): in each chart the first line is "
            "LinuxCNC's, the second the board's; the bars are the largest error at the "
            "boundaries between two samples.</sub>" % (
                len(tr["t_s"]), grp(r["boundaries_checked"]),
                grp(r["boundaries_checked"] - r["boundaries_with_error"])),
            "", source(d)]
    again = [u for u in d.get("updates", []) if "corners.ngc" in u["programs"]]
    if again:
        out += ["", "<sub>Again: `corners.ngc` with `%s` on `%s`, %s.</sub>" % (
            again[-1]["command"], again[-1]["commit"], again[-1]["date"])]
    return out


def r_linuxcnc_planner(_):
    """docs/linuxcnc.md: LinuxCNC's planner against ours on the same programs
    and machine (scripts/linuxcnc/planner_compare.py)."""
    d = load("linuxcnc_planner.json")
    rows, notes = [], []
    for p in d["programs"]:
        cells = ["`%s`" % os.path.basename(p["program"]), "%.2f" % p["linuxcnc_s"]]
        for prof in ("trapezoid", "scurve"):
            r = p.get(prof, {})
            if not r.get("passed"):
                cells.append("refused" if r.get("error") else "**failed**")
                msg = (r.get("error") or "").strip().splitlines()
                if msg and prof == "trapezoid":
                    notes.append("`%s`: %s" % (os.path.basename(p["program"]),
                                               msg[-1].split("error: ", 1)[-1]))
            else:
                cells.append("%.2f (%+.1f %%)" % (r["s"], 100.0 * (r["s"] / p["linuxcnc_s"] - 1)))
        cells.append("%.2f" % p["trapezoid"]["programmed_s"] if p.get("trapezoid", {}).get("passed")
                     else "")
        rows.append(cells)
    return (table(["program", "LinuxCNC (s, the board's steps)", "ours, trapezoid (s)",
                   "ours, S-curve (s)", "at the programmed feed (s)"], rows) +
            ["", "Refused by `hwinterp gcode`: " + "; ".join(notes)] * bool(notes) +
            ["", source(d)])


def r_linuxcnc_faults(_):
    """docs/linuxcnc.md: the faults on corners.ngc (scripts/linuxcnc/sil_all.sh)."""
    d = load("linuxcnc_sil.json")
    rows = []
    for r in d["runs"]:
        f = r.get("fault", "")
        if not f:
            continue
        kind = f.split()[0]
        if kind == "kill":
            what = ("watchdog bit %.1f ms after the last boundary sampled; %d steps after the bite" %
                    ((r.get("bite_s", 0) - r.get("last_boundary_s", 0)) * 1e3,
                     r.get("steps_after_bite", -1)))
        elif kind == "estop":
            what = ("the board stopped (CTRL.abort_motion); %d steps after the stop; %d queued "
                    "boundaries dropped" % (r.get("steps_after_stop_boundary", -1),
                                          r["boundaries_dropped_by_stop"]))
        else:
            what = ("the driver saw the link down after %.0f ms, the joints faulted; the watchdog "
                    "bit; %d machine-on attempts (the first refused: LinuxCNC was not where the "
                    "board stopped); the MDI move from the board's position; %d boundaries lost "
                    "with the link" % ((r.get("fault_seen_s") or 0) * 1e3, r.get("on_attempts") or 0,
                                      r["boundaries_dropped_by_stop"]))
        rows.append([linuxcnc_run_name(r, "`%s`" % f), grp(r["periods_run"]),
                     "%s / %s" % (grp(r["boundaries_checked"] - r["boundaries_with_error"]),
                                  grp(r["boundaries_checked"])),
                     what, "yes" if r["passed"] else "**no**"])
    return table(["fault (s into corners.ngc)", "periods", "boundaries at 0 error / checked",
                  "what happened", "passed"], rows) + ["", source(d)]


RENDERERS = {
    "folder-graph": ("tb", r_folder_graph),
    "synth-paths": ("docs/synth.json", r_synth_paths),
    "synth-paths-ecp5": ("docs/synth.json", r_synth_paths_ecp5),
    "synth-paths-gowin": ("docs/synth.json", r_synth_paths_gowin),
    "variants": ("cmake/cores.cmake", r_variants),
    "papers": ("docs/data/papers.json", r_papers),
    "reproduced": ("docs/data/reproduce.json", r_reproduced),
    "worst-40": ("docs/data/reproduce.json", r_worst40),
    "hardware-lines": ("docs/data/reproduce.json", r_hw_lines),
    "pick": ("docs/data/reproduce.json docs/data/back_to_back.json", r_pick),
    "ppc-line1": ("docs/data/reproduce.json", r_ppc_line1),
    "dividers": ("docs/data/reproduce.json", r_dividers),
    "log-paper": ("docs/data/reproduce.json docs/data/log_stepper.json", r_log_paper),
    "log-random": ("docs/data/log_stepper.json", r_log_random),
    "regress": ("docs/data/regress.json", r_regress),
    "regress-short": ("docs/data/regress.json", r_regress_short),
    "test-suite": ("docs/data/test_suite.json", r_test_suite),
    "lockstep": ("docs/data/lockstep_speed.json", r_lockstep),
    "perf-checks": ("docs/data/lockstep_speed.json", r_perf_checks),
    "simulators": ("docs/data/simulators.json", r_simulators),
    "memory": ("docs/data/memory.json", r_memory),
    "soak": ("docs/data/soak.json", r_soak),
    "fuzz": ("docs/data/fuzz.json", r_fuzz),
    "sanitize": ("docs/data/sanitize.json", r_sanitize),
    "sharding": ("docs/data/sharding.json", r_sharding),
    "gcode-programs": ("docs/data/gcode_programs.json", r_gcode_programs),
    "gcode-bench": ("docs/data/gcode_bench.json", r_gcode_bench),
    "netlist": ("docs/data/netlist_check.json", r_netlist),
    "planner": ("docs/data/planner_bench.json", r_planner),
    "synth-blocks": ("docs/data/synth_blocks.json", r_synth_blocks),
    "link-size": ("docs/data/link_size.json", r_link_size),
    "boards": ("docs/data/boards.json", r_boards),
    "board-link": ("docs/data/board_link.json", r_board_link),
    "soc-timing": ("docs/data/soc.json", r_soc_timing),
    "soc-tests": ("docs/data/soc.json", r_soc_tests),
    "profile-ruckig": ("docs/data/profile_ruckig.json", r_profile_ruckig),
    "profile-programs": ("docs/data/profile_programs.json", r_profile_programs),
    "linuxcnc-pins": ("sw/hal/hwinterp.comp", r_linuxcnc_pins),
    "linuxcnc-runs": ("docs/data/linuxcnc_sil.json", r_linuxcnc_runs),
    "linuxcnc-faults": ("docs/data/linuxcnc_sil.json", r_linuxcnc_faults),
    "linuxcnc-trace": ("docs/data/linuxcnc_sil.json", r_linuxcnc_trace),
    "linuxcnc-planner": ("docs/data/linuxcnc_planner.json", r_linuxcnc_planner),
}


def render_block(spec):
    parts = spec.split()
    name, arg = parts[0], (parts[1] if len(parts) > 1 else None)
    if name not in RENDERERS or len(parts) > 2:
        raise KeyError(spec)
    src, fn = RENDERERS[name]
    body = fn(arg)
    return ("<!-- render: %s; from %s by scripts/docs/render.py; do not edit -->\n\n%s\n\n"
            "<!-- end render -->" % (spec, src, "\n".join(body))), src


# ---------------------------------------------------------------- documents

def documents():
    out = [os.path.join(ROOT, "README.md")]
    out += sorted(glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))
    return out


def rendered(text, rel, problems, used):
    def sub(m):
        try:
            block, src = render_block(m.group(1).strip())
        except KeyError:
            problems.append("%s: unknown render block '%s'" % (rel, m.group(1)))
            return m.group(0)
        used.update(s for s in src.split() if s.startswith("docs/data/"))
        return block
    n_open = len(OPEN.findall(text))
    new = BLOCK.sub(sub, text)
    if len(BLOCK.findall(text)) != n_open:
        problems.append("%s: a render marker without its end marker, or malformed" % rel)
    return new


def check_data(problems, used):
    for path in sorted(glob.glob(os.path.join(DATA, "*.json"))):
        name = os.path.basename(path)
        rel = "docs/data/" + name
        d = load(name)
        if name not in REFERENCE:
            for k in ("command", "date", "commit"):
                if not d.get(k):
                    problems.append("%s: no '%s' (what measured it, when, on which commit)" % (rel, k))
        if rel not in used:
            problems.append("%s: no render block uses it" % rel)


# ---------------------------------------------------------------- imports

def git_head():
    try:
        h = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short=7", "HEAD"], capture_output=True,
                           text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no",
                                "--", "rtl", "hls", "models", "tb", "cmake"],
                               capture_output=True, text=True).stdout.strip()
        return h + ("-dirty" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail("cannot read %s: %s" % (path, e))


def stamp(command, extra, opts):
    d = {"command": command, "date": datetime.date.today().isoformat(), "commit": git_head()}
    if opts.get("load"):
        d["machine"] = "2 cores shared with other jobs, load average %s" % opts["load"]
    d.update(extra)
    return d


def import_regress(files, opts):
    if len(files) != 1:
        fail("--import regress takes one build/reports/regress.json")
    r = read_json(files[0])
    if "runs" not in r or "cores" not in r:
        fail("%s is not a hwinterp regress report" % files[0])
    extra = {
        "what": "scripts/regress.sh: every core's regression cases in every variant and both "
                "lockstep modes (hwinterp regress; build/reports/regress.json)",
        "seed": r["seed"], "random_commands": r["random_commands"],
        "variants": len({x["variant"] for x in r["runs"]}), "runs": len(r["runs"]),
        "cases": sum(c["cases"] for c in r["cores"].values()),
        "cycles": sum(c["cycles"] for c in r["cores"].values()),
        "passed": r["passed"], "cores": r["cores"],
        # direct runs one after the other; the SystemC runs share one elaboration, and each
        # reports its seconds
        "direct_seconds": round(sum(x["seconds"] for x in r["runs"] if x["mode"] == "direct"), 1),
        "systemc_seconds": round(max([x["seconds"] for x in r["runs"] if x["mode"] == "systemc"]
                                     or [0]), 1),
    }
    if opts.get("seconds"):
        extra["wall_seconds"] = float(opts["seconds"])
    return stamp("scripts/regress.sh", extra, opts)


def import_reproduce(files, opts):
    if len(files) != 1:
        fail("--import reproduce takes one JSON of hwinterp reproduce --json FILE")
    r = read_json(files[0])
    if "papers" not in r:
        fail("%s is not a hwinterp reproduce report" % files[0])
    big = {"table1", "table3", "lines"}  # the full tables: printed by the command, not rendered
    papers = []
    for p in r["papers"]:
        q = {k: v for k, v in p.items() if k not in big}
        # the rows the command compares with the paper: its figure rows, or (oli) its tables
        q["rows_compared"] = len(p.get("rows", [])) or sum(
            len(p.get(k, [])) for k in ("table1", "table3", "nishioka", "cam2_inflections"))
        papers.append(q)
    return stamp("hwinterp reproduce --json FILE", {
        "what": "hwinterp reproduce: every paper's figures beside ours (the full tables are in the "
                "command's own output)", "ok": r["ok"], "papers": papers}, opts)


def import_gcode(files, opts):
    progs = []
    for path in files:
        r = read_json(path)
        try:
            progs.append({
                "program": os.path.basename(r["program"]),
                "variant": r["variant"],
                "passed": r["passed"],
                "moves": {"total": r["moves"], "rapid": r["traverses"], "feed": r["feeds"],
                          "arc": r["arcs"]},
                "commands": {"total": r["commands"], "line": r["line_commands"],
                             "arc": r["arc_commands"]},
                "max_contour_error_mm": r["max_contour_error_mm"],
                "max_contour_error_steps": r["max_contour_error_steps"],
                "max_line": r["max_contour_error_line"],
                "programmed_seconds": r["programmed_time_s"],
                "feed_word_seconds": r["feed_word_time_s"],
                "clocks": r["simulated_clocks"], "visited_points": r["visited_points"],
            })
        except (KeyError, TypeError) as e:
            fail("%s: not a hwinterp gcode report (no %s)" % (path, e))
    return stamp("hwinterp gcode tests/data/gcode/<program>.ngc --mode direct --json FILE", {
        "what": "the committed programs on the default machine (tests/data/gcode/"
                "machine_default.json), full feed", "programs": progs}, opts)


def import_profile_programs(files, opts):
    progs = []
    for path in files:
        r = read_json(path)
        try:
            k = r["kinematics"]
            prof = r["profile"]
            if prof["kind"] == "off":
                fail("%s: a run without the feed profile" % path)
            axes = []
            for name, a in k["axes"].items():
                if not a["speed"]["max"]:
                    continue
                axes.append({"axis": name,
                             "accel_share": a["accel"]["max"] / a["accel"]["limit"],
                             "jerk_share": a["jerk"]["max"] / a["jerk"]["limit"]})
            progs.append({
                "program": os.path.basename(r["program"]),
                "variant": r["variant"], "mode": r["mode"], "kind": prof["kind"],
                "passed": r["passed"] and not prof["failures"],
                "programmed_seconds": r["programmed_time_s"],
                "profile_seconds": prof["time_s"], "clocks": r["simulated_clocks"],
                "path": {q: k["path"][q]["max"] for q in ("speed", "accel", "jerk")},
                "axes": axes,
            })
        except (KeyError, TypeError, ZeroDivisionError) as e:
            fail("%s: not a hwinterp gcode report with a profile (%s)" % (path, e))
    return stamp("hwinterp gcode tests/data/gcode/<program>.ngc --machine "
                 "tests/data/gcode/machine_profile.json --feed programmed --json FILE "
                 "(ctest -L long -R GcodeProfileAll)", {
                     "what": "the committed programs at their programmed feeds with the S-curve "
                             "profile on tests/data/gcode/machine_profile.json (500 kHz), the "
                             "kinematics estimated from the step stream in 10 ms windows; "
                             "\"same points\": the same lattice points in the same order as "
                             "the run without the profile", "programs": progs}, opts)


def import_back_to_back(files, opts):
    runs = []
    for path in files:
        r = read_json(path)
        if "cycles" not in r or "variant" not in r:
            fail("%s is not a hwinterp cosim report" % path)
        runs.append({"core": r["core"], "variant": r["variant"], "cycles": r["cycles"],
                     "commands": r["commands"], "passed": r["passed"]})
    return stamp("hwinterp cosim --core C --job docs/data/back_to_back.job --mode direct --json FILE", {
        "what": "short commands back to back: 200 one-step diagonal lines (move 1 1) at full feed "
                "with 1-clock timing, clocks from reset to the end of the case, per command",
        "runs": runs}, opts)


def import_log_stepper(files, opts):
    """Reports of the paper's curve (cosim --paper-log: case 001_log, one per lockstep mode) and
    of random runs (the others, in order); --seconds T1,T2,...: the random runs' wall times."""
    paper, rand = [], []
    for path in files:
        r = read_json(path)
        if r.get("core") != "log_stepper" or "points" not in r:
            fail("%s is not a hwinterp cosim report of log_stepper" % path)
        (paper if [c.get("case") for c in r.get("cases", [])] == ["001_log"] else rand).append(r)
    if not paper or not rand:
        fail("--import log_stepper takes the --paper-log reports and the random runs' reports")
    for q in paper[1:]:
        if (q["cycles"], q["max_path_error_steps"]) != (paper[0]["cycles"],
                                                        paper[0]["max_path_error_steps"]):
            fail("the --paper-log reports differ between modes")
    secs = [float(x) for x in opts["seconds"].split(",")] if opts.get("seconds") else []
    if secs and len(secs) != len(rand):
        fail("--seconds needs one wall time per random run")
    p = paper[0]
    random = [{"variant": r["variant"], "points": r["points"], "cycles": r["cycles"],
               "max_point_error_steps": int(r["max_point_error_steps"]),
               "max_path_error_steps": r["max_path_error_steps"],
               "seconds": secs[i] if secs else None, "passed": r["passed"]}
              for i, r in enumerate(rand)]
    extra = {
        "what": "log_stepper in lockstep: the paper's curve (paper 001, dl = 0.2 mm, 1000 steps/mm "
                "and /deg) at full feed with the default timing; random curves per variant",
        "paper_curve": {"command": "hwinterp cosim --core log_stepper --paper-log",
                        "variant": p["variant"], "modes": [q["mode"] for q in paper],
                        "cycles": p["cycles"], "points": p["points"],
                        "max_point_error_steps": p["max_point_error_steps"],
                        "max_path_error_steps": p["max_path_error_steps"],
                        "max_erpa_rad": p["max_erpa_rad"], "passed": all(q["passed"] for q in paper)},
        "random_command": "hwinterp cosim --core log_stepper --variant V --random 3000 --seed 7 "
                          "--mode direct",
        "random": random}
    return stamp("hwinterp cosim --core log_stepper --paper-log [--mode direct] --json FILE; "
                 "hwinterp cosim --core log_stepper --variant V --random 3000 --seed 7 --mode "
                 "direct --json FILE", extra, opts)


def import_planner(files, opts):
    if len(files) != 1:
        fail("--import planner takes one bench_planner --benchmark_format=json output")
    r = read_json(files[0])
    cases = [{"case": b["name"], "ms": round(b["cpu_time"], 3), "segments": int(b["segments"])}
             for b in r.get("benchmarks", []) if b["name"].startswith("Plan/")]
    if not cases:
        fail("%s has no Plan/ benchmarks" % files[0])
    return stamp("build/tests/bench_planner --benchmark_format=json", {
        "what": "the optimal-linear-interpolation planner (paper 000) on every case of the "
                "paper's Table 1 (Cam 1) and Table 3 (Cam 2): CPU time per plan",
        "cases": cases}, opts)


IMPORTS = {"regress": import_regress, "reproduce": import_reproduce, "gcode": import_gcode,
           "profile_programs": import_profile_programs,
           "back_to_back": import_back_to_back, "log_stepper": import_log_stepper,
           "planner": import_planner}
# The data file each import writes.
IMPORT_FILES = {"gcode": "gcode_programs.json", "planner": "planner_bench.json",
                "profile_programs": "profile_programs.json"}


# ---------------------------------------------------------------- main

def main(argv):
    check, kind, files, opts = False, None, [], {}
    args = list(argv[1:])
    while args:
        a = args.pop(0)
        if a == "--check":
            check = True
        elif a == "--import":
            if not args:
                fail("--import needs KIND and FILE")
            kind = args.pop(0)
            if kind not in IMPORTS:
                fail("unknown --import kind '%s' (one of %s)" % (kind, ", ".join(IMPORTS)))
        elif a in ("--seconds", "--load"):
            if not args:
                fail("%s needs a value" % a)
            opts[a[2:]] = args.pop(0)
        elif a in ("-h", "--help"):
            sys.stdout.write(__doc__)
            return 0
        elif a.startswith("-"):
            fail("unknown option '%s'" % a)
        elif kind:
            files.append(a)
        else:
            fail("unexpected argument '%s'" % a)
    if check and kind:
        fail("--check writes nothing; it takes no --import")
    if kind:
        if not files:
            fail("--import %s needs a FILE" % kind)
        d = IMPORTS[kind](files, opts)
        path = os.path.join(DATA, IMPORT_FILES.get(kind, kind + ".json"))
        with open(path, "w") as f:
            json.dump(d, f, indent=1)
            f.write("\n")
        print("render: wrote %s" % os.path.relpath(path, ROOT))

    problems, used, stale = [], set(), []
    for path in documents():
        rel = os.path.relpath(path, ROOT)
        with open(path) as f:
            text = f.read()
        new = rendered(text, rel, problems, used)
        if new != text:
            if check:
                stale.append(rel)
            else:
                with open(path, "w") as f:
                    f.write(new)
                print("render: wrote %s" % rel)
    check_data(problems, used)
    for rel in stale:
        problems.append("%s: a render block is not what its source renders; run "
                        "scripts/docs/render.py" % rel)
    for p in problems:
        sys.stderr.write("render: %s\n" % p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

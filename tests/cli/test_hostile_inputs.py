"""The hostile-input sweep (issue 38): every case of hostile_inputs.json run
through the real hwinterp, argv without a shell, in a fresh directory.

A defect is any of: a signal or a run past the time limit (a run that never
ends), an exit code outside the case's (a refusal that should have been one,
exit 1 for bad input), a refusal without its message on stderr or naming the
wrong thing, a PASS printed by a refused run, a file the case gave changed
(unless it is an output of a completed run), a temporary left behind, a file
a shell would have created from a name (injection). The suite counts them:
0 is the only pass.
"""
import json
import os
import subprocess
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
SPEC = json.loads((HERE / "hostile_inputs.json").read_text())
HWINTERP = os.environ.get("HWINTERP", str(HERE.parents[1] / "build" / "tb" / "hwinterp"))
# A hang detector, not a speed target: every case finishes in seconds.
TIME_LIMIT_S = 120


def expand(text, tokens):
    for token, (char, count) in tokens.items():
        text = text.replace(token, char * count)
    return text


def lay_out(case, d):
    """The case's files in d: the fixtures, then its own (null removes one)."""
    files = dict(SPEC["fixtures"])
    files.update(case.get("files", {}))
    for name, text in files.items():
        if text is None:
            continue
        text = expand(text, case.get("expand", {}))
        (d / name).write_bytes(text.encode("utf-8", "surrogateescape"))
    for key, (old, new) in case.get("replace", {}).items():
        f = d / key.split("#")[0]
        text = f.read_text()
        assert old in text, f"case {case['name']}: '{old}' not in {f.name}"
        f.write_text(text.replace(old, new, 1))
    for name, target in case.get("links", {}).items():
        os.link(d / target, d / name)
    for name, target in case.get("symlinks", {}).items():
        os.symlink(target, d / name)
    for name in case.get("dirs", []):
        (d / name).mkdir()


def snapshot(d):
    return {p.name: (p.read_bytes() if p.is_file() else None) for p in d.iterdir()}


def argv_of(case, d):
    args = list(SPEC["bases"][case["base"]]) if "base" in case else []
    args += case.get("args", [])
    return [HWINTERP] + [a.replace("$D", str(d)) for a in args]


def defects(case, d):
    """What went wrong in one case (empty: nothing)."""
    lay_out(case, d)
    before = snapshot(d)
    try:
        r = subprocess.run(argv_of(case, d), cwd=d, capture_output=True, timeout=TIME_LIMIT_S,
                           stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return [f"still running after {TIME_LIMIT_S} s"]
    out = r.stdout.decode(errors="replace")
    err = r.stderr.decode(errors="replace")
    found = []
    if r.returncode < 0:
        found.append(f"killed by signal {-r.returncode}")
    elif r.returncode not in case["exit"]:
        found.append(f"exit {r.returncode}, expected {case['exit']}: {err.strip()[-300:]}")
    if r.returncode == 2:
        if not err.strip():
            found.append("refused without a message on stderr")
        if "named" in case and case["named"] not in err:
            found.append(f"the message does not name '{case['named']}': {err.strip()[-300:]}")
        if "PASS" in out:
            found.append("printed PASS, then refused")
    writes = set(case.get("writes", [])) if r.returncode == 0 else set()
    after = snapshot(d)
    for name, content in before.items():
        if name in writes:
            continue
        if name not in after:
            found.append(f"{name} was removed")
        elif after[name] != content:
            found.append(f"{name} was changed")
    for name in after:
        if name.startswith(".hwinterp-"):
            found.append(f"temporary {name} left behind")
        if name.startswith("PWNED"):
            found.append(f"{name} created: a name reached a shell")
    return found


@pytest.mark.parametrize("case", SPEC["cases"], ids=[c["name"] for c in SPEC["cases"]])
def test_hostile_input(case, tmp_path):
    found = defects(case, tmp_path)
    assert not found, f"{case['name']}: " + "; ".join(found)


def test_the_sweep_is_the_size_the_docs_give():
    # docs/command-line.md cites the sweep's size; names are unique.
    names = [c["name"] for c in SPEC["cases"]]
    assert len(names) == len(set(names))
    docs = (HERE.parents[1] / "docs" / "command-line.md").read_text()
    assert f"holds {len(names)}\ninputs" in docs or f"holds {len(names)} inputs" in docs, \
        f"docs/command-line.md does not give the sweep's {len(names)} inputs"

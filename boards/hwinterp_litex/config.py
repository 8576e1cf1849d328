"""The boards' configuration, read from cmake/cores.cmake (the one source).

cmake/cores.cmake declares each board with hwinterp_board(NAME VARIANT LINK
SYS_HZ [BAUD] [PARAMS]) after the motion_top variant whose widths it takes
(hwinterp_core_variant). This module reads those declarations without CMake,
so that a board builds from a fresh clone; cmake/variants.cmake reads the same
lines for the simulated boards.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field

from .rtl import ROOT

CORES_CMAKE = os.path.join(ROOT, "cmake", "cores.cmake")


@dataclass(frozen=True)
class BoardConfig:
    name: str
    variant: str  # the motion_top variant whose widths it takes
    link: str  # "etherbone" or "uart"
    sys_hz: int  # the system clock, motion_soc's CLK_HZ
    baud: int  # the UART's rate (0 for Etherbone)
    params: dict = field(default_factory=dict)  # motion_soc_wb's parameters

    @property
    def axes(self) -> int:
        return int(self.params["AXES"])


def _calls(text: str, function: str):
    """The argument lists of every call of `function` (comments removed)."""
    text = re.sub(r"#[^\n]*", "", text)
    for m in re.finditer(function + r"\(([^)]*)\)", text):
        yield m.group(1).split()


def _expand(words, variables):
    out = []
    for w in words:
        m = re.fullmatch(r"\$\{(\w+)\}", w)
        out.extend(variables.get(m.group(1), []) if m else [w])
    return out


def _keywords(words, singles, lists):
    """cmake_parse_arguments: single-value keywords and list keywords."""
    values, key = {}, None
    for w in words:
        if w in singles or w in lists:
            key = w
            values.setdefault(key, [])
        elif key is not None:
            values[key].append(w)
    return values


def _params(words):
    return dict(w.split("=", 1) for w in words)


def boards(path: str = CORES_CMAKE) -> dict[str, BoardConfig]:
    """Every board of cmake/cores.cmake by name."""
    with open(path) as f:
        text = f.read()
    variables = {}
    for args in _calls(text, "set"):
        if args:
            variables[args[0]] = args[1:]
    variants = {}
    for args in _calls(text, "hwinterp_core_variant"):
        kw = _keywords(args, {"CORE", "NAME"}, {"PARAMS", "DEFAULTS"})
        variants[kw["NAME"][0]] = _params(_expand(kw.get("PARAMS", []), variables))
    result = {}
    for args in _calls(text, "hwinterp_board"):
        kw = _keywords(_expand(args, variables), {"NAME", "VARIANT", "LINK", "SYS_HZ", "BAUD"},
                       {"PARAMS"})
        name, variant = kw["NAME"][0], kw["VARIANT"][0]
        if variant not in variants:
            raise ValueError(f"{path}: board {name}: no variant {variant}")
        params = dict(variants[variant])
        params.update(_params(kw.get("PARAMS", [])))
        result[name] = BoardConfig(name=name, variant=variant, link=kw["LINK"][0],
                                   sys_hz=int(kw["SYS_HZ"][0]),
                                   baud=int(kw.get("BAUD", ["0"])[0]),
                                   params={k: int(v) for k, v in params.items()})
    return result


def board(name: str) -> BoardConfig:
    """One board by name; an unknown name raises ValueError naming the known ones."""
    known = boards()
    if name not in known:
        raise ValueError(f"unknown board '{name}' (boards: {', '.join(sorted(known))})")
    return known[name]

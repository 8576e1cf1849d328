"""Step streams as lattice points, and the comparisons the board tests make.

A step stream (CSV clock,axis,dir: hwinterp gcode --step-times, hwinterp
board-sim --steps-csv) becomes the sequence of lattice points it visits: the
steps of one clock are one move from point to point (the engine's operation),
so two runs that visit the same points in the same order and group their
steps the same way agree, whatever their clocks (a host's stream arrives when
it arrives; the profile's speed is the same, the pauses between moves are
not).
"""
import csv

LETTERS = "XYZABC"


def points(path, axes):
    """The lattice points of a step stream, from the origin."""
    at = [0] * axes
    out = [tuple(at)]
    clock = None
    with open(path) as f:
        for row in csv.DictReader(f):
            c = int(row["clock"])
            if clock is not None and c != clock:
                out.append(tuple(at))
            clock = c
            at[LETTERS.index(row["axis"])] += int(row["dir"])
    if clock is not None:
        out.append(tuple(at))
    return out


def first_difference(a, b):
    """The index of the first point where the sequences differ, or None."""
    for i, (p, q) in enumerate(zip(a, b)):
        if p != q:
            return i
    return None if len(a) == len(b) else min(len(a), len(b))


def move_ends(moves_csv, axes):
    """Per move of hwinterp gcode --moves-csv: its commands and lattice end."""
    out = []
    with open(moves_csv) as f:
        for row in csv.DictReader(f):
            out.append((int(row["commands"]),
                        tuple(int(row[f"{LETTERS[i].lower()}_steps"]) for i in range(axes))))
    return out


def command_ends(commands_csv, axes):
    """Per command the board completed (hwinterp board-sim --commands-csv): where it ended."""
    with open(commands_csv) as f:
        return [tuple(int(r[f"{LETTERS[i]}_steps"]) for i in range(axes))
                for r in csv.DictReader(f)]


def board_move_ends(commands_csv, moves, axes):
    """The board's position after each move's last command."""
    ends = command_ends(commands_csv, axes)
    out, k = [], 0
    for n, _ in moves:
        k += n
        out.append(ends[k - 1] if 0 < k <= len(ends) else None)
    return out

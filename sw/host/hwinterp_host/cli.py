"""hwinterp-host: stream part programs to a board running motion_soc
(docs/host.md).

    hwinterp-host info URI [--json]
    hwinterp-host status URI [--json]
    hwinterp-host abort URI
    hwinterp-host plan PROG.ngc --machine M.json [--json]
    hwinterp-host run PROG.ngc --machine M.json --board URI [options]

URI: udp:HOST[:PORT] (port 1234) or serial:DEV[@BAUD] (1000000).
Exit codes: 0 done; 1 a check failed (the final position differs, an
EVENTS overflow/refused/wdog/estop bit, an abort, a dead link); 2 bad input
(one line naming the value).
"""
from __future__ import annotations

import argparse
import json
import os
import select
import signal
import sys
import time
from typing import List, Optional

from . import __version__
from .board import Board, Stager, bit, fields, read_id
from .gen.regs import link as G
from .gen.regs import motion as M
from .link import DEAD_AFTER_S, MAX_STREAM, RETRY_S, LinkError, Session, chunks_of
from .program import ProgramError, find_hwinterp, plan
from .report import report, write_json, write_moves_csv
from .run import BoardMismatch, Controls, RunOptions, Runner, check_board
from .transport import TransportError, UriError, open_transport, parse_uri

EXIT_OK, EXIT_FAILED, EXIT_USAGE = 0, 1, 2
KEYS_HELP = ("keys (stdin a terminal): space hold/resume, + / - override +/-10 % (with the "
             "profile), a abort; signals: SIGINT/SIGTERM abort then exit 1 (a second one exits "
             "at once, the watchdog stops the board), SIGUSR1 hold/resume")


class Usage(Exception):
    """Bad input: exit 2 with this one line."""


class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise Usage(message)


def one_line(text: str) -> str:
    return " ".join(str(text).split())


def add_link_options(p):
    p.add_argument("--timeout-ms", type=float, default=DEAD_AFTER_S * 1e3,
                   help="the link is dead after this long without a reply to a packet "
                        "(default %(default)g; raise it for a slow simulated board)")
    p.add_argument("--retry-ms", type=float, default=RETRY_S * 1e3,
                   help="an attempt's wait for its reply before the packet is sent again, "
                        "besides its time on the wire (default %(default)g)")


def make_parser() -> Parser:
    ap = Parser(prog="hwinterp-host", description=__doc__.split("\n\n")[0],
                epilog="docs/host.md describes the link, the commands and their outputs.")
    ap.add_argument("--version", action="version", version=f"hwinterp-host {__version__}")
    sub = ap.add_subparsers(dest="cmd", metavar="COMMAND", parser_class=Parser)
    sub.required = True

    p = sub.add_parser("info", help="the board's ID registers in words")
    p.add_argument("uri", metavar="URI")
    p.add_argument("--json", action="store_true", help="print JSON instead")
    add_link_options(p)

    p = sub.add_parser("status", help="STATUS, EVENTS, FIFO, positions (a snapshot), watchdog, "
                                      "the guard's counters")
    p.add_argument("uri", metavar="URI")
    p.add_argument("--json", action="store_true", help="print JSON instead")
    add_link_options(p)

    p = sub.add_parser("abort", help="CTRL.abort_motion: the running move ends, the FIFO is dropped")
    p.add_argument("uri", metavar="URI")
    add_link_options(p)

    p = sub.add_parser("plan", help="plan a part program with hwinterp, no board: the commands, "
                                    "moves and stream words it takes")
    add_plan_options(p)
    p.add_argument("--json", action="store_true", help="print JSON instead")

    p = sub.add_parser("run", help="plan a part program with hwinterp and stream it to the board",
                       epilog=KEYS_HELP)
    add_plan_options(p)
    p.add_argument("--board", metavar="URI", required=True, help="udp:HOST[:PORT] or serial:DEV[@BAUD]")
    p.add_argument("--json", metavar="FILE", help="the report (hwinterp gcode's keys, and 'board')")
    p.add_argument("--moves-csv", metavar="FILE", help="one row per move (hwinterp gcode's columns)")
    p.add_argument("--watchdog-ms", type=float, default=500.0,
                   help="WDOG_PERIOD: the board stops the motion when no packet came for this long "
                        "(default %(default)g; 0: off)")
    p.add_argument("--fifo-low", metavar="N", type=int,
                   help="FIFO_LOW, the refill mark (default: half the FIFO's depth)")
    p.add_argument("--poll-ms", type=float, default=5.0,
                   help="the poll interval while the FIFO is above its mark (default %(default)g)")
    p.add_argument("--progress", metavar="S", type=float,
                   help="seconds between progress updates on stderr (default 0.5 on a terminal, "
                        "5 otherwise; 0: none)")
    p.add_argument("--snapshot-s", type=float, default=1.0,
                   help="a position snapshot for the progress this often (default %(default)g; 0: never)")
    add_link_options(p)
    return ap


def add_plan_options(p):
    p.add_argument("program", metavar="PROG.ngc", help="RS274/NGC (or, with --canon, rs274 -g output)")
    p.add_argument("--machine", metavar="M.json", required=True, help="the machine file")
    p.add_argument("--canon", action="store_true", help="PROG is LinuxCNC's canonical commands")
    p.add_argument("--profile", choices=("scurve", "trapezoid", "off"),
                   help="the feed profile (overrides the machine file's); needs a board with it")
    p.add_argument("--variant", metavar="V", help="the motion_top variant the board's widths are "
                                                   "(default: hwinterp's, the first with the "
                                                   "machine's axes)")
    p.add_argument("--feed", choices=("full", "programmed"), default="programmed",
                   help="programmed: the program's feeds (default); full: every move at full feed")
    p.add_argument("--profile-window", metavar="N", type=int, help="the profile planner's look-ahead")
    p.add_argument("--hwinterp", metavar="PATH", help="the hwinterp executable (default: $HWINTERP, "
                                                       "else the repository's build/tb/hwinterp)")


# ------------------------------------------------------------------ helpers
def open_session(args) -> Session:
    if args.timeout_ms <= 0 or args.retry_ms <= 0:
        raise Usage(f"--timeout-ms {args.timeout_ms:g} / --retry-ms {args.retry_ms:g}: both must be > 0")
    uri = parse_uri(args.uri)
    try:
        t = open_transport(uri)
    except TransportError as e:
        raise LinkError(str(e)) from None
    return Session(t, retry_s=args.retry_ms / 1e3, dead_after_s=args.timeout_ms / 1e3)


def link_name(uri) -> str:
    return ("Etherbone over UDP" if str(uri).startswith("udp:")
            else "Etherbone over a UART (SLIP + CRC-32)")


def cmd_info(args) -> int:
    s = open_session(args)
    ident = read_id(s)
    guard = dict(zip(("expect", "accepted", "stale", "dropped", "errors"),
                     s.read([G.SEQ.addr] + [r.addr for r in (G.ACCEPTED, G.STALE, G.DROPPED, G.ERRORS)])))
    if args.json:
        print(json.dumps({"uri": str(s.uri), "link": link_name(s.uri), "id": ident.to_json(),
                          "guard": guard}, indent=2))
        return EXIT_OK
    d = ident.to_json()
    print(f"board {s.uri} ({link_name(s.uri)})")
    why = ident.problem()
    if why:
        print(f"{s.uri}: {why}", file=sys.stderr)
        return EXIT_FAILED
    print(f"  motion_soc {ident.major}.{ident.minor}, core {d['core_name']}, {ident.axes} axes, "
          f"{d['bus_name']} register block")
    print(f"  widths: ACC_W {ident.acc_w}, COORD_W {ident.coord_w}, OPS_W {ident.ops_w}, "
          f"POS_W {ident.pos_w}, TIM_W {ident.tim_w}, FEED_W {ident.feed_w}")
    print(f"  clock {ident.clock_hz} Hz ({ident.clock_hz / 1e6:g} MHz)")
    print(f"  command FIFO {ident.fifo_depth} commands")
    if ident.profile:
        print(f"  feed profile: yes (SPD_W {ident.spd_w}, ticks of {1 << ident.tick_w} clocks "
              f"(TICK_W {ident.tick_w}), LEN_W {ident.len_w}, LVL_W {ident.lvl_w})")
    else:
        print("  feed profile: no (FEED drives the feed)")
    print(f"  step outputs: {', '.join(ident.step_type_names()) or 'none listed'}")
    print(f"  link guard: EXPECT {guard['expect']}, accepted {guard['accepted']}, "
          f"stale {guard['stale']}, dropped {guard['dropped']}, errors {guard['errors']}")
    return EXIT_OK


def set_bits(reg, word) -> str:
    names = [f.name for f in reg.fields if f.width == 1 and f.get(word)]
    return " ".join(names) if names else "-"


def cmd_status(args) -> int:
    s = open_session(args)
    ident = read_id(s)
    why = ident.problem()
    if why:
        print(f"{s.uri}: {why}", file=sys.stderr)
        return EXIT_FAILED
    b = Board(s, ident)
    st = b.status()
    snap = b.snapshot_plain()
    expect = s.read([G.SEQ.addr])[0]
    if args.json:
        out = {k: v for k, v in st.items() if k != "raw"}
        out["guard"]["expect"] = expect
        out["snapshot"] = {"time": snap.time, "pos": snap.pos}
        out["uri"] = str(s.uri)
        print(json.dumps(out, indent=2))
        return EXIT_OK
    hz = ident.clock_hz or 1
    f = st["fifo"]
    wd = st["watchdog"]
    print(f"board {s.uri}")
    print(f"  STATUS 0x{st['raw']['STATUS']:08x}: {set_bits(M.STATUS, st['raw']['STATUS'])}")
    print(f"  EVENTS 0x{st['raw']['EVENTS']:08x}: {set_bits(M.EVENTS, st['raw']['EVENTS'])}")
    print(f"  FIFO {f['fill']} of {f['depth']} commands (room {f['room']}), low-water mark {f['low']}")
    print(f"  TIME {st['time']} clocks = {st['time'] / hz:.6f} s")
    axes = " ".join(f"{'XYZABC'[i]} {p}" for i, p in enumerate(snap.pos))
    print(f"  position (snapshot at TIME {snap.time}): {axes} steps")
    if wd["period"]:
        print(f"  watchdog: period {wd['period']} clocks ({wd['period'] / hz * 1e3:g} ms), "
              f"{wd['left']} left")
    else:
        print("  watchdog: off")
    if ident.profile:
        pc = st["prof_ctrl"]
        print(f"  feed profile: hold {pc['hold']}, override {pc['ovr'] * 100 / 128:g} %")
    else:
        print(f"  FEED {st['feed']}" + (" (feed hold)" if st["feed"] == 0 else ""))
    g = st["guard"]
    print(f"  link guard: EXPECT {expect}, accepted {g['accepted']}, stale {g['stale']}, "
          f"dropped {g['dropped']}, errors {g['errors']}")
    return EXIT_OK


def cmd_abort(args) -> int:
    s = open_session(args)
    ident = read_id(s)
    why = ident.problem()
    if why:
        print(f"{s.uri}: {why}", file=sys.stderr)
        return EXIT_FAILED
    s.open()
    b = Board(s, ident)
    w = b.packet([(M.CTRL.addr, bit(M.CTRL, "abort_motion"))], [M.STATUS.addr, M.FIFO_LEVEL.addr])
    print(f"{s.uri}: aborted (CTRL.abort_motion); STATUS {set_bits(M.STATUS, w[0])}, "
          f"FIFO {fields(M.FIFO_LEVEL, w[1])['fill']}")
    return EXIT_OK


# ------------------------------------------------------------------ run
class Terminal:
    """The progress line on stderr, and the keyboard on stdin."""

    def __init__(self, every_s: Optional[float], controls: Controls):
        self.tty = sys.stderr.isatty()
        self.every = (0.5 if self.tty else 5.0) if every_s is None else every_s
        self.ctl = controls
        self.last = -1e9
        self.keys = sys.stdin.isatty()
        self._saved = None
        self.shown = False

    def __enter__(self):
        if self.keys:
            import termios
            import tty
            fd = sys.stdin.fileno()
            self._saved = termios.tcgetattr(fd)
            tty.setcbreak(fd)
        return self

    def __exit__(self, *exc):
        if self._saved is not None:
            import termios
            termios.tcsetattr(sys.stdin.fileno(), termios.TCSADRAIN, self._saved)
        if self.shown and self.tty:
            sys.stderr.write("\n")

    def wait(self, s: float):
        if not self.keys:
            time.sleep(s)
            return
        r, _, _ = select.select([sys.stdin], [], [], s)
        if r:
            for ch in os.read(sys.stdin.fileno(), 64).decode(errors="replace"):
                if ch == " ":
                    self.ctl.toggle_hold += 1
                elif ch in "+=":
                    self.ctl.ovr_steps += 1
                elif ch in "-_":
                    self.ctl.ovr_steps -= 1
                elif ch in "aA":
                    self.ctl.request_abort("abort key")

    def progress(self, info: dict):
        if self.every <= 0:
            return
        now = time.monotonic()
        if not info["final"] and now - self.last < self.every:
            return
        self.last = now
        pos = " ".join(f"{'XYZABC'[i]} {p}" for i, p in enumerate(info["pos"]))
        ovr = f"ovr {info['ovr_pct']} %" if info["profile"] else ""
        line = (f"moves {info['moves']}/{info['total']}  commands {info['pushed']}/{info['commands']}"
                f"  FIFO {info['fill']}  t {info['time_s']:.3f} s  {pos}"
                + ("  HOLD" if info["hold"] else "") + (f"  {ovr}" if ovr else ""))
        if self.tty:
            sys.stderr.write("\r" + line + "\x1b[K")
            self.shown = True
        else:
            sys.stderr.write(line + "\n")
        sys.stderr.flush()


def check_writable(path: Optional[str], opt: str):
    """Usage naming the option when `path` cannot be written (nothing is created)."""
    if not path:
        return
    if os.path.exists(path):
        if os.path.isdir(path):
            raise Usage(f"{opt}: '{path}' is a directory")
        if not os.access(path, os.W_OK):
            raise Usage(f"{opt}: cannot write '{path}'")
        return
    d = os.path.dirname(path) or "."
    if not os.path.isdir(d):
        raise Usage(f"{opt}: cannot write '{path}': no directory '{d}'")
    if not os.access(d, os.W_OK):
        raise Usage(f"{opt}: cannot write '{path}': directory '{d}' is not writable")


def check_inputs(args):
    for path, what in ((args.program, "PROG"), (args.machine, "--machine")):
        if not os.path.isfile(path):
            raise Usage(f"{what}: no file '{path}'")
    if args.profile_window is not None and args.profile_window < 1:
        raise Usage(f"--profile-window {args.profile_window}: must be >= 1")


def plan_of(args, hw):
    extra = ["--profile-window", str(args.profile_window)] if args.profile_window else []
    return plan(hw, args.program, args.machine, profile=args.profile, variant=args.variant,
                feed=args.feed, extra=extra, canon=args.canon)


def cmd_plan(args) -> int:
    check_inputs(args)
    try:
        hw = find_hwinterp(args.hwinterp)
    except ProgramError as e:
        raise Usage(str(e))
    prog = plan_of(args, hw)
    st = Stager(prog.axes, prog.profiled)
    words = []
    for c in prog.commands:
        words.append(len(chunks_of(st.writes(c))))
        st.commit(c)
    # packets with an unlimited FIFO: commands while they fit the stream (the watchdog's kick too)
    kick = len(chunks_of([(M.WDOG_KICK.addr, 1)]))
    packets, used = 0, MAX_STREAM
    for w in words:
        if used + w > MAX_STREAM:
            packets, used = packets + 1, kick
        used += w
    out = {"program": prog.raw.get("program"), "variant": prog.raw.get("variant"),
           "widths": prog.widths, "clock_hz": prog.clock_hz, "profile": prog.profile,
           "moves": len(prog.moves), "commands": len(prog.commands), "end": prog.end,
           "stream_words": sum(words), "max_words": max(words, default=0),
           "packets_unlimited_fifo": packets,
           "programmed_time_s": prog.totals.get("programmed_time_s"),
           "feed_word_time_s": prog.totals.get("feed_word_time_s")}
    if args.json:
        print(json.dumps(out, indent=2))
        return EXIT_OK
    n = len(words) or 1
    print(f"{prog.raw.get('program')} on {prog.raw.get('variant')} ({prog.axes} axes, "
          f"{prog.clock_hz} Hz, profile {prog.profile.get('kind', 'off')})")
    print(f"  {len(prog.moves)} moves, {len(prog.commands)} commands, lattice end {prog.end}")
    print(f"  {sum(words)} stream words: {sum(words) / n:.2f} a command, at most {max(words, default=0)}; "
          f"{packets} packet{'s' if packets != 1 else ''} if the FIFO took every command")
    print(f"  programmed time {out['programmed_time_s']} s, from the feed words {out['feed_word_time_s']} s")
    return EXIT_OK


def cmd_run(args) -> int:
    check_inputs(args)
    uri = parse_uri(args.board)
    check_writable(args.json, "--json")
    check_writable(args.moves_csv, "--moves-csv")
    if args.watchdog_ms < 0:
        raise Usage(f"--watchdog-ms {args.watchdog_ms:g}: must be >= 0")
    if args.poll_ms <= 0:
        raise Usage(f"--poll-ms {args.poll_ms:g}: must be > 0")
    try:
        hw = find_hwinterp(args.hwinterp)
    except ProgramError as e:
        raise Usage(str(e))
    args.uri = args.board
    s = open_session(args)
    ident = read_id(s)
    why = ident.problem()
    if why:
        raise BoardMismatch(f"{uri}: {why}")
    if args.fifo_low is not None and not 0 <= args.fifo_low < ident.fifo_depth:
        raise Usage(f"--fifo-low {args.fifo_low}: the board's FIFO holds {ident.fifo_depth} "
                    f"(give 0..{ident.fifo_depth - 1})")
    prog = plan_of(args, hw)
    check_board(ident, prog, uri)
    if args.watchdog_ms * 1e-3 * prog.clock_hz > 0xFFFFFFFF:
        raise Usage(f"--watchdog-ms {args.watchdog_ms:g}: more than WDOG_PERIOD's 2^32 clocks "
                    f"at {prog.clock_hz} Hz")

    controls = Controls()
    signals = {}

    def on_stop(signum, frame):
        if controls.abort:
            raise SystemExit(EXIT_FAILED)   # a second one: at once (the watchdog stops the board)
        controls.request_abort(signal.Signals(signum).name)

    def on_usr1(signum, frame):
        controls.toggle_hold += 1

    for sig, h in ((signal.SIGINT, on_stop), (signal.SIGTERM, on_stop), (signal.SIGUSR1, on_usr1)):
        signals[sig] = signal.signal(sig, h)
    opts = RunOptions(watchdog_ms=args.watchdog_ms, fifo_low=args.fifo_low,
                      poll_s=args.poll_ms / 1e3, snapshot_s=args.snapshot_s)
    try:
        with Terminal(args.progress, controls) as term:
            runner = Runner(Board(s, ident), prog, opts, controls, progress=term.progress,
                            poll_input=term.wait)
            res = runner.run()
    finally:
        for sig, h in signals.items():
            signal.signal(sig, h)

    if args.moves_csv:
        with open(args.moves_csv, "w") as f:
            write_moves_csv(f, prog, res.completed and res.passed)
    if args.json:
        write_json(args.json, report(prog, ident, res, uri, s.counts, s.t.counts))
    c = s.counts
    summary = (f"{uri}: {res.pushed}/{len(prog.commands)} commands in {c.packets} packets, "
               f"{c.retransmits} retransmits, {c.stale_replies} stale replies")
    if res.passed:
        print(f"{summary}; machine time {(res.time1 - res.time0) / prog.clock_hz:.6f} s; "
              f"moved {res.moved} steps = the program's lattice end")
        print("PASS")
        return EXIT_OK
    print(summary)
    print(f"FAIL: {one_line(res.failure) or 'the run did not complete'}")
    return EXIT_FAILED


def main(argv: Optional[List[str]] = None) -> int:
    ap = make_parser()
    try:
        args = ap.parse_args(argv)
        return {"info": cmd_info, "status": cmd_status, "abort": cmd_abort, "plan": cmd_plan,
                "run": cmd_run}[args.cmd](args)
    except (Usage, UriError, ProgramError, BoardMismatch) as e:
        print(f"hwinterp-host: {one_line(e)}", file=sys.stderr)
        return EXIT_USAGE
    except (LinkError, TimeoutError) as e:
        print(f"hwinterp-host: {one_line(e)}", file=sys.stderr)
        return EXIT_FAILED
    except KeyboardInterrupt:      # outside a run's own handler (e.g. while hwinterp plans)
        print("hwinterp-host: interrupted", file=sys.stderr)
        return EXIT_FAILED
    except BrokenPipeError:
        return EXIT_FAILED


if __name__ == "__main__":
    sys.exit(main())

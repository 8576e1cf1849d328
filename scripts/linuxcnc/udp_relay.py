#!/usr/bin/env python3
"""A UDP relay on 127.0.0.1 between LinuxCNC's driver and the simulated
board, to cut the link for the `--fault cut` run of scripts/linuxcnc/sil.sh.

It forwards every datagram both ways. When the file --cut-file appears
(headless.py writes it at the fault's time, holding a duration in seconds)
it drops everything both ways for that long, then forwards again. Writes
its port to --port-file, and what it dropped to stdout when stopped.
"""
import argparse
import os
import select
import signal
import socket
import sys
import time


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--board-port", type=int, required=True)
    ap.add_argument("--port-file", required=True)
    ap.add_argument("--cut-file", required=True)
    a = ap.parse_args()
    host = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)   # faces the driver
    host.bind(("127.0.0.1", 0))
    board = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)  # faces the board
    board.connect(("127.0.0.1", a.board_port))
    with open(a.port_file + ".tmp", "w") as f:
        f.write(str(host.getsockname()[1]))
    os.replace(a.port_file + ".tmp", a.port_file)
    peer = None
    cut_until = None
    counts = {"forwarded": 0, "dropped": 0}
    stop = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    while not stop:
        if cut_until is None and os.path.exists(a.cut_file):
            cut_until = time.monotonic() + float(open(a.cut_file).read().strip() or 0)
            print(f"cut for {cut_until - time.monotonic():.3f} s", flush=True)
        cut = cut_until is not None and time.monotonic() < cut_until
        ready, _, _ = select.select([host, board], [], [], 0.01)
        for s in ready:
            data, addr = s.recvfrom(2048)
            if cut:
                counts["dropped"] += 1
                continue
            counts["forwarded"] += 1
            if s is host:
                peer = addr
                board.send(data)
            elif peer:
                host.sendto(data, peer)
    print(counts, flush=True)


if __name__ == "__main__":
    sys.exit(main())

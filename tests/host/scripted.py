"""A scripted in-process transport for the session's tests: every packet
the host sends goes to a FakeBoard (or is lost) as the script says, and
its reply comes back on time, late, twice, mangled or never. Time is a
fake clock the transport advances while the host waits, so no test sleeps.

Script actions, one per packet sent (then "ok" when the script runs out):
  ok             served, the reply delivered at once
  drop_request   lost on the way: the board never sees it
  drop_reply     served, the reply lost
  dup            the packet arrives twice: served twice, both replies delivered
  late           served, the reply delivered `late_s` later (after the host gave up on it)
  mangle         served, the reply's length cut (not a reply the host can read)
"""
from hwinterp_host.transport import Transport, TransportCounts, UdpUri


class FakeClock:
    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now


class ScriptedTransport(Transport):
    def __init__(self, board, script=(), late_s=0.3, uri=UdpUri("fake", 1234)):
        self.board, self.script, self.late_s, self.uri = board, list(script), late_s, uri
        self.clock = FakeClock()
        self.counts = TransportCounts()
        self.queue = []      # (deliver_at, bytes)
        self.sent = []       # every packet the host sent
        self.actions = []

    def send(self, packet):
        self.sent.append(packet)
        self.counts.sent += 1
        act = self.script.pop(0) if self.script else "ok"
        self.actions.append(act)
        if act == "drop_request":
            return
        reply = self.board.serve(packet)
        if act == "dup":
            again = self.board.serve(packet)
            for r in (reply, again):
                if r is not None:
                    self.queue.append((self.clock.now, r))
            return
        if reply is None or act == "drop_reply":
            return
        if act == "mangle":
            reply = reply[:-2]
        at = self.clock.now + (self.late_s if act == "late" else 0.0)
        self.queue.append((at, reply))

    def recv(self, timeout_s):
        self.queue.sort(key=lambda x: x[0])
        if self.queue and self.queue[0][0] <= self.clock.now + timeout_s:
            at, data = self.queue.pop(0)
            self.clock.now = max(self.clock.now, at)
            self.counts.received += 1
            return data
        self.clock.now += timeout_s
        return None

"""The host links of a board: Etherbone over UDP (LiteEth) and over a UART,
both through the sequence guard (docs/link.md).

    add_etherbone_link(soc, phy, ...)   LiteEth's MAC/IP/UDP/Etherbone with the
                                        frame dropper, then the guard
    add_uart_link(soc, pads, baud)      rtl/link/uart_etherbone.sv, then the guard

Both put the guard (rtl/link/link_guard.sv) between the link's Wishbone
master and the SoC bus, its window where rtl/regs/board.rdl puts it.
"""

from __future__ import annotations

from migen import Cat, ClockSignal, If, Instance, Memory, ResetSignal, Signal

from litex.gen import LiteXModule
from litex.soc.interconnect import stream, wishbone
from litex.soc.interconnect.csr import CSRStatus

from . import rtl
from .motion_soc import _param


class EthFrameDropper(LiteXModule):
    """Store-and-forward of received Ethernet frames that drops a frame whose
    FCS failed.

    LiteEth's MAC checks the FCS but only flags a bad frame on its last beat
    (`error`), after IP, UDP and Etherbone have taken its first words: a
    corrupted Etherbone write would run. Placed at the end of the MAC's
    receive path, this buffers each frame whole (DEPTH words of the core's
    data path) and passes it on only when its last beat came without error;
    a frame that fails, or that does not fit in the free space, is dropped
    whole (`dropped` counts them). Its sink is always ready: the PHY cannot
    be held back.
    """

    def __init__(self, description, depth=512):
        assert depth & (depth - 1) == 0, "depth must be a power of two"
        self.sink = sink = stream.Endpoint(description)
        self.source = source = stream.Endpoint(description)
        self.dropped = Signal(32)  # frames dropped (bad FCS or no room)
        self._dropped = CSRStatus(32, description="Received frames dropped (bad FCS or no room).")
        self.comb += self._dropped.status.eq(self.dropped)

        dw = len(sink.data)
        bew = len(sink.last_be)
        aw = (depth - 1).bit_length()
        # A buffered word: data, last_be, last.
        mem = Memory(dw + bew + 1, depth)
        wr = mem.get_port(write_capable=True)
        rd = mem.get_port()  # synchronous read
        self.specials += mem, wr, rd

        wp = Signal(aw + 1)  # write pointer (one wrap bit)
        cp = Signal(aw + 1)  # commit pointer: the end of the last whole frame
        cp_seen = Signal(aw + 1)  # cp a clock later, for the reader
        rp = Signal(aw + 1)  # read pointer
        bad = Signal()  # the frame being received will be dropped
        room = Signal(aw + 1)

        beat = sink.valid & sink.ready
        self.comb += [
            sink.ready.eq(1),
            room.eq(depth - (wp - rp)),
            wr.adr.eq(wp[:aw]),
            wr.dat_w.eq(Cat(sink.data, sink.last_be, sink.last)),
            wr.we.eq(beat & ~bad & (room != 0)),
        ]
        frame_fails = Signal()
        self.comb += frame_fails.eq(bad | (room == 0) | (sink.error != 0))
        self.sync += [
            If(beat,
                If(sink.last,
                    bad.eq(0),
                    If(frame_fails,
                        wp.eq(cp),  # drop the whole frame
                        self.dropped.eq(self.dropped + 1),
                    ).Else(
                        wp.eq(wp + 1),
                        cp.eq(wp + 1),
                    ),
                ).Else(
                    If(room == 0, bad.eq(1)).Else(wp.eq(wp + 1)),
                ),
            ),
            # The reader sees a commit a clock late, so that the word it reads
            # at a newly committed address was written a clock before.
            cp_seen.eq(cp),
        ]
        # The reader: the read port always reads the word at the next read
        # pointer, so rd.dat_r holds the word at rp.
        advance = source.valid & source.ready
        rp_next = Signal(aw + 1)
        self.comb += [
            rp_next.eq(rp + advance),
            rd.adr.eq(rp_next[:aw]),
            source.valid.eq(rp != cp_seen),
            source.data.eq(rd.dat_r[:dw]),
            source.last_be.eq(rd.dat_r[dw:dw + bew]),
            source.last.eq(rd.dat_r[dw + bew]),
            source.error.eq(0),
        ]
        self.sync += rp.eq(rp_next)


class LinkGuard(LiteXModule):
    """rtl/link/link_guard.sv between a link's Wishbone master (`upstream`,
    connect the link's master to it) and the SoC bus (`downstream`, add it as
    a bus master). With `err_as_ack` the guard's err also ends the cycle as
    an ack upstream: LiteEth's Etherbone master waits for ack only (an err
    would hang it), so a refused access answers there as an ack that wrote
    nothing (what it reads is of no matter); the host sees the refusal in the
    guard's counters (docs/link.md)."""

    def __init__(self, platform, win_base: int, err_as_ack: bool = False):
        self.upstream = up = wishbone.Interface(data_width=32, adr_width=30)
        self.downstream = dn = wishbone.Interface(data_width=32, adr_width=30)
        s_ack, s_err = Signal(), Signal()
        if err_as_ack:
            self.comb += [up.ack.eq(s_ack | s_err), up.err.eq(0)]
        else:
            self.comb += [up.ack.eq(s_ack), up.err.eq(s_err)]
        self.specials += Instance(
            "link_guard",
            name="link_guard",
            p_WIN_BASE=_param(win_base >> 2),
            i_clk_i=ClockSignal("sys"),
            i_rst_ni=~ResetSignal("sys"),
            i_s_cyc_i=up.cyc, i_s_stb_i=up.stb, i_s_we_i=up.we, i_s_adr_i=up.adr,
            i_s_dat_i=up.dat_w, i_s_sel_i=up.sel,
            o_s_dat_o=up.dat_r, o_s_ack_o=s_ack, o_s_err_o=s_err,
            o_m_cyc_o=dn.cyc, o_m_stb_o=dn.stb, o_m_we_o=dn.we, o_m_adr_o=dn.adr,
            o_m_dat_o=dn.dat_w, o_m_sel_o=dn.sel,
            i_m_dat_i=dn.dat_r, i_m_ack_i=dn.ack, i_m_err_i=dn.err,
        )
        for path in rtl.file_list("link/link_guard"):
            platform.add_source(path)


class WishboneSlice(LiteXModule):
    """A registered stage on a classic Wishbone: `sink` faces the master,
    `source` the slave. The master's request is latched and given to the
    slave from flip-flops; the slave's answer (ack or err, and the read
    data) is latched and returned the clock after. Two clocks more an access,
    and no path from the master's request logic to the slave's or back."""

    def __init__(self):
        self.sink = up = wishbone.Interface(data_width=32, adr_width=30)
        self.source = down = wishbone.Interface(data_width=32, adr_width=30)
        req, resp = Signal(), Signal()
        ack_q, err_q = Signal(), Signal()
        adr_q, dat_w_q, dat_r_q = Signal(30), Signal(32), Signal(32)
        we_q, sel_q = Signal(), Signal(4)
        take = Signal()
        done = Signal()
        self.comb += [
            take.eq(up.cyc & up.stb & ~req & ~resp),
            done.eq(req & (down.ack | down.err)),
            down.cyc.eq(req), down.stb.eq(req), down.adr.eq(adr_q), down.dat_w.eq(dat_w_q),
            down.we.eq(we_q), down.sel.eq(sel_q),
            up.ack.eq(resp & ack_q), up.err.eq(resp & err_q), up.dat_r.eq(dat_r_q),
        ]
        self.sync += [
            If(take, req.eq(1), adr_q.eq(up.adr), dat_w_q.eq(up.dat_w), we_q.eq(up.we),
               sel_q.eq(up.sel)).Elif(done, req.eq(0)),
            resp.eq(done),
            If(done, ack_q.eq(down.ack), err_q.eq(down.err), dat_r_q.eq(down.dat_r)),
        ]


def _add_guarded_master(soc, name, master, err_as_ack=False, sliced=False):
    """The guard in front of `master` (with `sliced`, through a registered
    WishboneSlice), its downstream a master of the bus."""
    guard = LinkGuard(soc.platform, rtl.board_map().link_base, err_as_ack)
    setattr(soc, name + "_guard", guard)
    if sliced:
        sl = WishboneSlice()
        setattr(soc, name + "_slice", sl)
        soc.comb += [master.connect(sl.sink), sl.source.connect(guard.upstream)]
    else:
        soc.comb += master.connect(guard.upstream)
    soc.bus.add_master(name=name, master=guard.downstream)
    return guard


def add_etherbone_link(soc, phy, mac_address=0x10E2D5000000, ip_address="192.168.1.50",
                       udp_port=1234, buffer_depth=255, dropper_depth=512):
    """LiteEth's UDP/IP core on `phy` (32-bit data path in the sys domain),
    the frame dropper at the end of the MAC's receive path, Etherbone on
    `udp_port`, and the guard in front of the bus."""
    from liteeth.common import eth_phy_description
    from liteeth.core import LiteEthUDPIPCore
    from liteeth.frontend.etherbone import LiteEthEtherbone

    ethcore = LiteEthUDPIPCore(
        phy=phy, mac_address=mac_address, ip_address=ip_address, clk_freq=soc.clk_freq,
        dw=32, with_sys_datapath=True, with_icmp=True)
    # The dropper goes last in the MAC's receive pipeline (before its source);
    # the pipeline is built when the MAC core is finalized.
    rx = ethcore.mac.core.rx_datapath
    dropper = EthFrameDropper(eth_phy_description(32), depth=dropper_depth)
    rx.dropper = dropper
    rx.pipeline.insert(len(rx.pipeline) - 1, dropper)
    # Registered valid and ready (stream.Buffer) where the MAC meets the
    # depacketizers and the packetizers: LiteEth's stream stages pass ready
    # through their logic, so without the cuts one combinational path ran
    # from the transmit CDC FIFO's pointers through every transmit and
    # receive state machine (IP, UDP, Etherbone's arbiter, UDP, IP, ARP,
    # MAC) into the dropper's read address: the Colorlight's critical path
    # at 50.44 MHz (docs/boards.md). Two clocks more a frame each way.
    rx.cut = stream.Buffer(eth_phy_description(32), pipe_valid=True, pipe_ready=True)
    rx.pipeline.insert(len(rx.pipeline) - 1, rx.cut)
    tx = ethcore.mac.core.tx_datapath
    tx.cut = stream.Buffer(eth_phy_description(32), pipe_valid=True, pipe_ready=True)
    tx.pipeline.insert(1, tx.cut)
    soc.ethcore = ethcore
    soc.etherbone = LiteEthEtherbone(ethcore.udp, udp_port, buffer_depth=buffer_depth)
    _fix_record_receiver(soc.etherbone.record.receiver)
    # LiteEth's Etherbone master reads its record FIFO's block RAM, computes
    # the address and waits the ack in one clock: the slice keeps that out
    # of the bus's decode (the Colorlight's critical path at 47.6 MHz).
    return _add_guarded_master(soc, "etherbone", soc.etherbone.wishbone.bus, err_as_ack=True,
                               sliced=True)


def _fix_record_receiver(receiver):
    """LiteEth 2024.12's record receiver (LiteEthEtherboneRecordReceiver)
    never takes the base return address of a record that writes and reads:
    its RECEIVE_BASE_RET_ADDR state latches the word but does not raise the
    FIFO's ready, so the reads start at that word (the first value read is
    from the base return address, the last address is left over and spoils
    the next packet). A packet of writes only or reads only is not affected
    (LiteX's own RemoteClient sends only those). The guarded packets write
    and read in one record, so the state takes its word here."""
    receiver.fsm.act("RECEIVE_BASE_RET_ADDR", receiver.fifo.source.ready.eq(1))


class UartEtherbone(LiteXModule):
    """rtl/link/uart_etherbone.sv: Etherbone in SLIP frames with a CRC-32 over
    a UART (8N1 at `baud`); its Wishbone master is `bus`. With `counters`,
    its frame and error counters are CSRs (frames run, frames dropped, bus
    errors)."""

    def __init__(self, platform, pads, clk_hz: int, baud: int, counters=True):
        self.bus = bus = wishbone.Interface(data_width=32, adr_width=30)
        cnt_w = 16
        frames_run, frames_bad, bus_errors = Signal(cnt_w), Signal(cnt_w), Signal(cnt_w)
        busy = Signal()
        self.specials += Instance(
            "uart_etherbone",
            name="uart_etherbone",
            p_CLK_HZ=_param(clk_hz),
            p_BAUD=_param(baud),
            p_CNT_W=_param(cnt_w),
            i_clk_i=ClockSignal("sys"),
            i_rst_ni=~ResetSignal("sys"),
            i_rx_i=pads.rx,
            o_tx_o=pads.tx,
            o_m_cyc_o=bus.cyc, o_m_stb_o=bus.stb, o_m_we_o=bus.we, o_m_adr_o=bus.adr,
            o_m_dat_o=bus.dat_w, o_m_sel_o=bus.sel,
            i_m_dat_i=bus.dat_r, i_m_ack_i=bus.ack, i_m_err_i=bus.err,
            o_frames_run_o=frames_run, o_frames_bad_o=frames_bad, o_bus_errors_o=bus_errors,
            o_busy_o=busy,
        )
        if counters:
            self._frames_run = CSRStatus(cnt_w, description="Frames that passed every check and ran.")
            self._frames_bad = CSRStatus(cnt_w, description="Frames dropped (CRC, framing, escape, length, format, busy).")
            self._bus_errors = CSRStatus(cnt_w, description="Accesses the bus answered with an error.")
            self.comb += [self._frames_run.status.eq(frames_run),
                          self._frames_bad.status.eq(frames_bad),
                          self._bus_errors.status.eq(bus_errors)]
        for path in rtl.file_list("link/uart_etherbone"):
            platform.add_source(path)


def add_uart_link(soc, pads, baud: int, counters=True):
    """The UART Etherbone bridge on `pads` (rx, tx), then the guard."""
    soc.uart_link = UartEtherbone(soc.platform, pads, soc.clk_freq, baud, counters=counters)
    return _add_guarded_master(soc, "uart_link", soc.uart_link.bus)

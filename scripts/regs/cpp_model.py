"""A PeakRDL-style exporter: the C++ face of a register block compiled from
SystemRDL, written to follow what PeakRDL-regblock generates for the same
description behind its internal CPU interface (one request a clock, the
address decode, the field logic and the readback), for the HLS face of a SoC
(hls/) and a testbench's bus master. tests/hls/soc_regs_model_test.cpp checks
it against the description (reset values, access rights, error responses,
write-1-to-clear, single pulses, swmod and swacc strobes, sticky events, and
20000 random requests); behind hls/motion_soc.h it is compared clock for
clock with the generated SystemVerilog in `hwinterp gcode --bus`
(tb/bus/hls_shadow.h: every bus response and the SoC's pins).

    CppModelExporter().export(top_addrmap_node, "hls/gen/x.h", namespace="...")

It writes one header: the register map as tables (every register and field
with its address, access and reset, for bus masters and tests), the hwif_in
and hwif_out structs named as regblock's SystemVerilog structs, and a class
`Block` whose eval() takes one clock's request on regblock's internal CPU
interface (req, is_wr, addr, wr_data, wr_biten) and the hardware inputs, and
gives the response (rd_ack, rd_err, rd_data, wr_ack, wr_err), the hardware
outputs of that clock and the next state, which commit() takes at the edge.

It models the subset of SystemRDL and of regblock's options the project
uses, and refuses anything else by name (validate()): 32-bit accesses;
registers of 32 or 64 bits, every field inside one 32-bit word; sw r, w or
rw; hw r, w or na; onwrite woclr; singlepulse, swmod, swacc; level intr
stickybit fields with an enable, and precedence; reset values; no external
blocks, counters, hwset/hwclr, we/wel, read or write buffering, onread side
effects or paritycheck. The register block it stands for must be generated
with err_if_bad_addr and err_if_bad_rw, and no retiming (the combinational
response regblock makes by default), as scripts/regs/generate.py does.
"""

from systemrdl.node import AddrmapNode, FieldNode, RegNode, RegfileNode, MemNode
from systemrdl.rdltypes import OnWriteType, OnReadType, PrecedenceType, InterruptType


class UnsupportedError(Exception):
    pass


def _regs(top):
    """Every register of the map in address order, arrays unrolled to (node, index)."""
    out = []
    for node in top.descendants(unroll=False):
        if isinstance(node, (RegfileNode, MemNode)) or (isinstance(node, AddrmapNode) and node is not top):
            raise UnsupportedError(f"{node.get_path()}: only registers directly in the addrmap are modelled")
        if isinstance(node, RegNode):
            out.append(node)
    return out


def _words(reg):
    return reg.get_property("regwidth") // 32


class CppModelExporter:
    def validate(self, top):
        for reg in _regs(top):
            p = reg.get_path()
            if reg.external:
                raise UnsupportedError(f"{p}: external registers are not modelled")
            if reg.get_property("accesswidth") != 32 or reg.get_property("regwidth") not in (32, 64):
                raise UnsupportedError(f"{p}: only 32-bit accesses to 32- or 64-bit registers")
            if reg.is_array and len(reg.array_dimensions) != 1:
                raise UnsupportedError(f"{p}: only one-dimensional register arrays")
            for udp in ("buffer_reads", "buffer_writes"):
                if udp in reg.list_properties(include_udp=True) and reg.get_property(udp):
                    raise UnsupportedError(f"{p}: {udp} is not modelled")
            for f in reg.fields():
                fp = f.get_path()
                if f.lsb // 32 != f.msb // 32 and (f.is_sw_writable or f.get_property("intr")):
                    raise UnsupportedError(f"{fp}: a writable field must lie inside one 32-bit word")
                if f.msb < f.lsb:
                    raise UnsupportedError(f"{fp}: msb0 fields are not modelled")
                for prop in ("counter", "hwset", "hwclr", "we", "wel", "paritycheck", "sticky",
                             "swwe", "swwel", "hwenable", "hwmask", "rclr", "rset"):
                    if f.get_property(prop):
                        raise UnsupportedError(f"{fp}: property {prop} is not modelled")
                if f.get_property("onread") is not None:
                    raise UnsupportedError(f"{fp}: onread side effects are not modelled")
                ow = f.get_property("onwrite")
                if ow not in (None, OnWriteType.woclr):
                    raise UnsupportedError(f"{fp}: onwrite {ow} is not modelled")
                intr = f.get_property("intr")
                if intr:
                    if f.get_property("intr type") not in (None, InterruptType.level):
                        raise UnsupportedError(f"{fp}: only level interrupts are modelled")
                    if not f.get_property("stickybit"):
                        raise UnsupportedError(f"{fp}: interrupts must be stickybit")
                    if f.get_property("mask") or f.get_property("haltenable") or f.get_property("haltmask"):
                        raise UnsupportedError(f"{fp}: mask/halt are not modelled (use enable)")
                elif f.is_hw_writable and f.is_sw_writable:
                    raise UnsupportedError(f"{fp}: sw-writable fields written by hw are modelled only as interrupts")

    # ------------------------------------------------------------------ naming
    @staticmethod
    def _storage(f, idx):
        reg = f.parent
        return f"q.{reg.inst_name}" + (f"[{idx}]" if reg.is_array else "") + f".{f.inst_name}"

    @staticmethod
    def _has_storage(f):
        return f.is_sw_writable or bool(f.get_property("intr"))

    # ------------------------------------------------------------------ export
    def export(self, top, path, namespace, source, generator):
        self.validate(top)
        regs = _regs(top)
        L = []
        w = L.append
        w(f"// Generated from {source} by {generator}; do not edit.")
        w("// The register block's C++ face (scripts/regs/cpp_model.py): PeakRDL-regblock's")
        w("// register block from the same description, behind its internal CPU interface")
        w("// (one request a clock; no bus protocol).")
        w("#pragma once")
        w("")
        w("#include <cstdint>")
        w("")
        w(f"namespace {namespace} {{")
        w("")
        size = top.size
        addr_w = max(1, (size - 1).bit_length())
        w(f"inline constexpr int kAddrWidth = {addr_w};  // byte address bits")
        w(f"inline constexpr uint32_t kSize = 0x{size:x};  // bytes")
        w("")
        # ---- tables
        w("// Access of a register or field from software.")
        w("enum class Sw { kR, kW, kRw };")
        w("struct RegDesc {")
        w("  const char* name;")
        w("  uint32_t addr;    // byte address of element 0")
        w("  uint32_t count;   // array elements (1: not an array)")
        w("  uint32_t stride;  // bytes between elements")
        w("  uint32_t words;   // 32-bit words per element")
        w("  Sw sw;")
        w("};")
        w("struct FieldDesc {")
        w("  int reg;          // index into kRegs")
        w("  const char* name;")
        w("  int lsb, width;   // in the register (64-bit registers: lsb up to 63)")
        w("  Sw sw;")
        w("  bool hw_writes;   // its value comes from (or is set by) the hardware")
        w("  uint64_t reset;")
        w("  bool woclr, singlepulse;")
        w("};")

        def sw_of(node):
            if isinstance(node, RegNode):
                r, wr = node.has_sw_readable, node.has_sw_writable
            else:
                r, wr = node.is_sw_readable, node.is_sw_writable
            return "Sw::kRw" if r and wr else ("Sw::kR" if r else "Sw::kW")

        w("inline constexpr RegDesc kRegs[] = {")
        for r in regs:
            count = r.array_dimensions[0] if r.is_array else 1
            stride = r.array_stride if r.is_array else 0
            w(f'    {{"{r.inst_name}", 0x{r.raw_absolute_address:x}, {count}, {stride}, {_words(r)}, {sw_of(r)}}},')
        w("};")
        w("inline constexpr FieldDesc kFields[] = {")
        for i, r in enumerate(regs):
            for f in r.fields():
                reset = f.get_property("reset") or 0
                w(f'    {{{i}, "{f.inst_name}", {f.lsb}, {f.width}, {sw_of(f)}, '
                  f'{"true" if f.is_hw_writable else "false"}, 0x{reset:x}ull, '
                  f'{"true" if f.get_property("onwrite") == OnWriteType.woclr else "false"}, '
                  f'{"true" if f.get_property("singlepulse") else "false"}}},')
        w("};")
        w("")
        w("// Byte addresses.")
        for r in regs:
            const = "k" + "".join(p.capitalize() for p in r.inst_name.split("_"))
            if r.is_array:
                w(f"constexpr uint32_t {const}(int i) {{ return 0x{r.raw_absolute_address:x} + 0x{r.array_stride:x} * static_cast<uint32_t>(i); }}")
                w(f"inline constexpr int {const}Count = {r.array_dimensions[0]};")
            else:
                w(f"inline constexpr uint32_t {const} = 0x{r.raw_absolute_address:x};")
        w("")
        # ---- hwif structs
        w("// regblock's hwif_in: what the hardware drives (hw-writable fields' next).")
        w("struct HwifIn {")
        for r in regs:
            fs = [f for f in r.fields() if f.is_hw_writable]
            if not fs:
                continue
            w("  struct {")
            for f in fs:
                w(f"    struct {{ uint64_t next = 0; }} {f.inst_name};")
            w(f"  }} {r.inst_name}" + (f"[{r.array_dimensions[0]}]" if r.is_array else "") + ";")
        w("};")
        w("")
        w("// regblock's hwif_out: field values the hardware reads, strobes, interrupts.")
        w("struct HwifOut {")
        for r in regs:
            members = []
            for f in r.fields():
                parts = []
                if f.is_hw_readable:
                    parts.append("uint64_t value = 0;")
                if f.get_property("swmod"):
                    parts.append("bool swmod = false;")
                if f.get_property("swacc"):
                    parts.append("bool swacc = false;")
                if parts:
                    members.append(f"    struct {{ {' '.join(parts)} }} {f.inst_name};")
            has_intr = any(f.get_property("intr") for f in r.fields())
            if has_intr:
                members.append("    bool intr = false;")
            if not members:
                continue
            w("  struct {")
            L.extend(members)
            w(f"  }} {r.inst_name}" + (f"[{r.array_dimensions[0]}]" if r.is_array else "") + ";")
        w("};")
        w("")
        # ---- the block
        w("// One request on regblock's internal CPU interface (its cpuif_* signals).")
        w("struct Request {")
        w("  bool req = false, is_wr = false;")
        w("  uint32_t addr = 0;      // byte address")
        w("  uint32_t wr_data = 0;")
        w("  uint32_t wr_biten = 0;  // bit enables (byte strobes widened)")
        w("};")
        w("struct Response {")
        w("  bool rd_ack = false, rd_err = false, wr_ack = false, wr_err = false;")
        w("  uint32_t rd_data = 0;")
        w("};")
        w("")
        w("class Block {")
        w(" public:")
        w("  // The registers: every field with storage.")
        w("  struct Storage {")
        for r in regs:
            fs = [f for f in r.fields() if self._has_storage(f)]
            if not fs:
                continue
            w("    struct {")
            for f in fs:
                w(f"      uint64_t {f.inst_name} = 0x{(f.get_property('reset') or 0):x}ull;")
            w(f"    }} {r.inst_name}" + (f"[{r.array_dimensions[0]}]" if r.is_array else "") + ";")
        w("  };")
        w("  Storage q;  // after the last edge")
        w("")
        w("  void reset() { q = Storage(); d_ = q; }")
        w("  void commit() { q = d_; }")
        w("")
        w("  // hwif_out from the registers alone (no request): values and interrupts.")
        w("  void outputs(HwifOut& o) const {")
        for r in regs:
            n = r.inst_name
            rng = [None] if not r.is_array else list(range(r.array_dimensions[0]))
            for idx in rng:
                sub = "" if idx is None else f"[{idx}]"
                for f in r.fields():
                    if f.is_hw_readable:
                        if self._has_storage(f):
                            w(f"    o.{n}{sub}.{f.inst_name}.value = q.{n}{sub}.{f.inst_name};")
                        else:
                            w(f"    o.{n}{sub}.{f.inst_name}.value = 0x{(f.get_property('reset') or 0):x}ull;")
                    if f.get_property("swmod"):
                        w(f"    o.{n}{sub}.{f.inst_name}.swmod = false;")
                    if f.get_property("swacc"):
                        w(f"    o.{n}{sub}.{f.inst_name}.swacc = false;")
                ifs = [f for f in r.fields() if f.get_property("intr")]
                if ifs:
                    terms = []
                    for f in ifs:
                        en = f.get_property("enable")
                        t = f"q.{n}{sub}.{f.inst_name}"
                        if en is not None:
                            if not isinstance(en, FieldNode):
                                raise UnsupportedError(f"{f.get_path()}: enable must reference a field")
                            er = en.parent
                            if er.is_array:
                                raise UnsupportedError(f"{f.get_path()}: enable in an array")
                            t = f"({t} & q.{er.inst_name}.{en.inst_name})"
                        terms.append(f"{t} != 0")
                    w(f"    o.{n}{sub}.intr = " + " || ".join(terms) + ";")
        w("  }")
        w("")
        w("  // One clock: the request and the hardware inputs give the response and")
        w("  // hwif_out of this clock (before the edge); the next state waits for commit().")
        w("  void eval(const Request& rq, const HwifIn& in, Response& rsp, HwifOut& o) {")
        w("    outputs(o);")
        w("    d_ = q;")
        w("    const bool rd = rq.req && !rq.is_wr, wr = rq.req && rq.is_wr;")
        w("    bool valid_addr = false, valid_rw = false;")
        w("    uint32_t data = 0;")
        w("    const uint32_t a = rq.addr;")
        w("    const uint64_t wd = rq.wr_data, be = rq.wr_biten;")
        w("    (void)wd;")
        w("    (void)be;")
        # per register element, per word
        for r in regs:
            n = r.inst_name
            rng = [None] if not r.is_array else list(range(r.array_dimensions[0]))
            for idx in rng:
                sub = "" if idx is None else f"[{idx}]"
                base = r.raw_absolute_address + (0 if idx is None else idx * r.array_stride)
                for word in range(_words(r)):
                    addr = base + 4 * word
                    wfs = [f for f in r.fields() if f.lsb // 32 <= word <= f.msb // 32]
                    readable, writable = r.has_sw_readable, r.has_sw_writable
                    w(f"    if (a == 0x{addr:x}) {{  // {n}{sub}" + (f" word {word}" if _words(r) > 1 else ""))
                    w("      valid_addr = true;")
                    if readable and writable:
                        w("      valid_rw = true;")
                        strobe = "rq.req"
                    elif readable:
                        w("      valid_rw = rd;")
                        strobe = "rd"
                    else:
                        w("      valid_rw = wr;")
                        strobe = "wr"
                    w(f"      const bool strb = {strobe};")
                    w("      (void)strb;")
                    # readback
                    if readable:
                        for f in wfs:
                            if not f.is_sw_readable:
                                continue
                            olo, ohi = max(f.lsb, 32 * word), min(f.msb, 32 * word + 31)
                            shift, n_bits, lo = olo - f.lsb, ohi - olo + 1, olo - 32 * word
                            mask = (1 << n_bits) - 1
                            if self._has_storage(f):
                                src = f"q.{n}{sub}.{f.inst_name}"
                            elif f.is_hw_writable:
                                src = f"in.{n}{sub}.{f.inst_name}.next"
                            else:
                                src = f"0x{(f.get_property('reset') or 0):x}ull"
                            w(f"      data |= static_cast<uint32_t>((({src} >> {shift}) & 0x{mask:x}ull) << {lo});")
                    # strobes
                    for f in wfs:
                        if f.get_property("swmod"):
                            lo = f.lsb % 32
                            m = ((1 << f.width) - 1) << lo
                            w(f"      o.{n}{sub}.{f.inst_name}.swmod = strb && rq.is_wr && (be & 0x{m:x}ull) != 0;")
                        if f.get_property("swacc"):
                            w(f"      o.{n}{sub}.{f.inst_name}.swacc = strb;")
                    w("    }")
        # field logic: every storage field, regblock's conditionals in precedence order
        w("    // Field logic.")
        for r in regs:
            n = r.inst_name
            rng = [None] if not r.is_array else list(range(r.array_dimensions[0]))
            for idx in rng:
                sub = "" if idx is None else f"[{idx}]"
                base = r.raw_absolute_address + (0 if idx is None else idx * r.array_stride)
                for f in r.fields():
                    if not self._has_storage(f):
                        continue
                    word = f.lsb // 32
                    addr = base + 4 * word
                    lo = f.lsb % 32
                    mask = (1 << f.width) - 1
                    cur = f"q.{n}{sub}.{f.inst_name}"
                    nxt = f"d_.{n}{sub}.{f.inst_name}"
                    conds = []  # (predicate, assignment)
                    sw = []
                    if f.is_sw_writable:
                        dsl = f"((wd >> {lo}) & 0x{mask:x}ull)"
                        bsl = f"((be >> {lo}) & 0x{mask:x}ull)"
                        pred = f"wr && a == 0x{addr:x}"
                        if f.get_property("onwrite") == OnWriteType.woclr:
                            sw.append((pred, f"{cur} & ~({dsl} & {bsl})"))
                        else:
                            sw.append((pred, f"({cur} & ~{bsl}) | ({dsl} & {bsl})"))
                        if f.get_property("singlepulse"):
                            sw.append(("true", "0"))
                    hw = []
                    if f.get_property("intr"):
                        src = f"in.{n}{sub}.{f.inst_name}.next"
                        if f.width == 1:
                            hw.append((f"({src} & 1) != 0", "1"))
                        else:
                            hw.append((f"({src} & 0x{mask:x}ull) != 0", f"{cur} | ({src} & 0x{mask:x}ull)"))
                    if f.get_property("precedence") == PrecedenceType.sw:
                        conds = sw + hw
                    else:
                        conds = hw + sw
                    first = True
                    for pred, val in conds:
                        kw = "if" if first else "} else if"
                        w(f"    {kw} ({pred}) {{")
                        w(f"      {nxt} = ({val}) & 0x{mask:x}ull;")
                        first = False
                    if conds:
                        w("    }")
        w("    const bool err = rq.req && (!valid_addr || !valid_rw);")
        w("    rsp.rd_ack = rd;")
        w("    rsp.rd_err = rd && err;")
        w("    rsp.rd_data = data;")
        w("    rsp.wr_ack = wr;")
        w("    rsp.wr_err = wr && err;")
        w("  }")
        w("")
        w(" private:")
        w("  Storage d_;")
        w("};")
        w("")
        w(f"}}  // namespace {namespace}")
        text = "\n".join(L) + "\n"
        with open(path, "w") as fh:
            fh.write(text)

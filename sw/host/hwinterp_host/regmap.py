"""The register map's types: what gen/regs.py (generated from the SystemRDL
description by scripts/regs/py_model.py) is made of. A Block is one
addrmap of the board's bus (motion_soc, the link guard) with its registers
at absolute byte addresses; a register's fields give their position, width,
software access and reset value. Nothing here holds an address: every
address comes from the generated module.

    from hwinterp_host.gen.regs import motion
    motion.STATUS.addr                 # absolute byte address
    motion.STATUS.f.busy.get(word)     # a field's value in a read word
    motion.SNAP_POS[2]                 # numbered copies as a list (SNAP_POS2)
"""
from __future__ import annotations

from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Dict, Iterable, Tuple


@dataclass(frozen=True)
class Field:
    name: str
    lsb: int      # in the register (a 64-bit register's fields go up to bit 63)
    width: int
    sw: str       # software access: "r", "w" or "rw"
    reset: int    # the reset value (0 where the description gives none)
    hw: bool      # the hardware writes it (its value is live)
    woclr: bool   # write 1 to clear
    singlepulse: bool

    @property
    def mask(self) -> int:
        """The field's bits in the register."""
        return ((1 << self.width) - 1) << self.lsb

    def get(self, value: int) -> int:
        """The field's value in a register value."""
        return (value >> self.lsb) & ((1 << self.width) - 1)

    def put(self, v: int) -> int:
        """v in the field's place; ValueError when it does not fit."""
        if v < 0 or v >> self.width:
            raise ValueError(f"{self.name}: {v} does not fit {self.width} bits")
        return v << self.lsb


@dataclass(frozen=True)
class Reg:
    name: str     # the instance name, upper case (ID_MAGIC, SNAP_POS0, ...)
    addr: int     # absolute byte address on the board's bus
    offset: int   # byte offset in its block
    width: int    # 32 or 64 bits (64: two words, the low one first)
    sw: str       # "r", "w" or "rw": what software may do with it
    external: bool
    fields: Tuple[Field, ...]
    f: SimpleNamespace = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        object.__setattr__(self, "f", SimpleNamespace(**{x.name: x for x in self.fields}))

    @property
    def words(self) -> int:
        return self.width // 32

    @property
    def word_addrs(self) -> Tuple[int, ...]:
        """The byte address of each 32-bit word, the low word first."""
        return tuple(self.addr + 4 * i for i in range(self.words))

    @property
    def reset(self) -> int:
        v = 0
        for x in self.fields:
            v |= x.reset << x.lsb
        return v


@dataclass(frozen=True)
class Mem:
    name: str
    addr: int
    offset: int
    entries: int
    width: int
    sw: str


class Block:
    """One addrmap of the board: its registers by name (attribute or
    `reg(name)`), its numbered copies as lists, its memories."""

    def __init__(self, name: str, type_name: str, base: int, size: int,
                 regs: Iterable[Reg], mems: Iterable[Mem] = (),
                 arrays: Dict[str, Tuple[str, ...]] | None = None):
        self.name, self.type_name, self.base, self.size = name, type_name, base, size
        self.regs: Tuple[Reg, ...] = tuple(regs)
        self.mems: Tuple[Mem, ...] = tuple(mems)
        self._by_name: Dict[str, object] = {r.name: r for r in self.regs}
        self._by_name.update({m.name: m for m in self.mems})
        self.arrays: Dict[str, Tuple[Reg, ...]] = {
            stem: tuple(self._by_name[n] for n in names) for stem, names in (arrays or {}).items()}
        self._by_addr = {a: r for r in self.regs for a in r.word_addrs}

    def __getattr__(self, name: str):
        d = self.__dict__
        if name in d.get("arrays", {}):
            return list(d["arrays"][name])
        if name in d.get("_by_name", {}):
            return d["_by_name"][name]
        raise AttributeError(f"{self.name} has no register {name}")

    def reg(self, name: str) -> Reg:
        """A register by its upper-case instance name; KeyError naming it."""
        r = self._by_name.get(name)
        if not isinstance(r, Reg):
            raise KeyError(f"{self.name} has no register {name}")
        return r

    def at(self, addr: int) -> Reg | None:
        """The register one of whose words is at absolute byte address addr."""
        return self._by_addr.get(addr)

    def contains(self, addr: int) -> bool:
        return self.base <= addr < self.base + self.size

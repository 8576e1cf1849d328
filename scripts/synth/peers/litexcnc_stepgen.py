#!/usr/bin/env python3
"""Elaborates LiteX-CNC's step generator to Verilog with its own Migen code (a synthesis peer).

Usage: litexcnc_stepgen.py --axes N --name MODULE --out FILE.v [--info FILE.json]

Nothing of LiteX-CNC is kept in this repository: the code is the `litexcnc`
package pinned in scripts/requirements.txt (installed into .venv/ by
scripts/setup.sh, with the `litex` and `migen` it imports), and the Verilog is
written into the build directory by scripts/synth.sh.

What runs is LiteX-CNC's own code, unchanged:
  - litexcnc.config.modules.stepgen: StepgenModuleConfig with N instances of
    StepgenInstanceConfig in its default configuration (max_frequency 400 kHz,
    soft_stop False, pins StepGenPinoutStepDirConfig 'step_dir', no index pin);
  - litexcnc.firmware.modules.stepgen.StepgenModule.create_from_config(soc,
    watchdog, config): per axis, StepgenModule(pads, pick_off=(32, 32 + shift,
    32 + shift + 16), soft_stop, create_pads) with shift =
    StepgenInstanceConfig.calculate_shift(50 MHz) (LiteX-CNC's default
    clock_frequency, LitexCNC_Firmware.clock_frequency) = 5, so pick_off
    (32, 37, 53), and the SoC glue that create_from_config adds to soc.sync
    (the CSRs into the stepgen's registers, its position and speed back into
    status CSRs, the new segment taken when wall_clock >= stepgen_apply_time).

What is replaced, and only that: create_from_config gets a stand-in `soc`
(this script's top Migen module) whose MMIO_inst holds plain Migen Signals
where LiteX-CNC's MMIO has CSRs, and a stand-in `watchdog`:
  - CSRStorage fields / storage (written by the host over Etherbone/SPI in
    LiteX-CNC) -> top-level inputs: reset.storage, stepgen_apply_time.storage
    (64), stepgen_<i>_stepdata.fields {steplen 10, dir_hold_time 10,
    dir_setup_time 12}, stepgen_<i>_speed_target_index_enable.fields
    {speed_target 31, index_enable 1}, stepgen_<i>_max_acceleration.storage (32);
  - CSRStatus status / fields (read by the host) -> top-level outputs, still
    assigned in soc.sync as LiteX-CNC does, so they stay registers:
    stepgen_<i>_position.status (64), stepgen_<i>_speed_index.fields {speed 31,
    index_flag 1};
  - stepgen_apply_time.we / dat_w (the stepgen's write back into that CSR,
    write_from_dev=True) -> top-level outputs;
  - wall_clock.status (64; a counter the SoC, not the stepgen, increments every
    clock) -> a top-level input;
  - watchdog.has_bitten (the watchdog module's output) -> a top-level input;
  - soc.platform.request('stepgen', i) -> a Record (step, dir) whose two bits
    are top-level outputs (LiteX-CNC's own create_pads drives them);
  - the `sys` clock domain: clk_i, and its synchronous reset driven by ~rst_ni
    (LiteX's CRG drives sys_rst on the card).
The CSR bank, the Etherbone/SPI bridge, the watchdog, the wall clock counter and
the rest of the SoC are not in the netlist. create_from_config's debug print
of the CSR fields goes to stderr.
"""
import argparse
import contextlib
import json
import sys
from types import SimpleNamespace

from migen import ClockDomain, Module, Record, Signal
from migen.fhdl import verilog

import litexcnc
from litexcnc.config.modules.stepgen import (StepgenInstanceConfig, StepgenModuleConfig,
                                             StepGenPinoutStepDirConfig)
from litexcnc.firmware.modules.stepgen import StepgenModule

CLOCK_HZ = 50_000_000  # LitexCNC_Firmware.clock_frequency's default


class _Platform:
    """soc.platform: request() hands out the step/dir pads of one stepgen."""

    def __init__(self, top):
        self.top = top

    def add_extension(self, _ios):
        pass

    def request(self, name, index):
        assert name == "stepgen"
        pads = Record([("step", 1), ("dir", 1)])
        pads.step.name_override = "stepgen%d_step_o" % index
        pads.dir.name_override = "stepgen%d_dir_o" % index
        self.top.outputs += [pads.step, pads.dir]
        return pads


class PeerTop(Module):
    """The stand-in SoC: create_from_config adds the stepgens and their glue to it."""

    def __init__(self, axes):
        self.inputs, self.outputs = [], []

        def inp(name, width):
            s = Signal(width, name_override=name + "_i")
            self.inputs.append(s)
            return s

        def outp(name, width):
            s = Signal(width, name_override=name + "_o")
            self.outputs.append(s)
            return s

        self.clk_i = Signal(name_override="clk_i")
        self.rst_ni = Signal(name_override="rst_ni")
        self.clock_domains.cd_sys = ClockDomain("sys")
        self.cd_sys.clk = self.clk_i
        self.comb += self.cd_sys.rst.eq(~self.rst_ni)

        self.platform = _Platform(self)
        self.clock_frequency = CLOCK_HZ
        mmio = SimpleNamespace()
        mmio.reset = SimpleNamespace(storage=inp("csr_reset", 1))
        mmio.wall_clock = SimpleNamespace(status=inp("wall_clock", 64))
        mmio.stepgen_apply_time = SimpleNamespace(storage=inp("csr_stepgen_apply_time", 64),
                                                  we=outp("csr_stepgen_apply_time_we", 1),
                                                  dat_w=outp("csr_stepgen_apply_time_dat_w", 64))
        for i in range(axes):
            p = "csr_stepgen_%d_" % i
            setattr(mmio, "stepgen_%d_stepdata" % i, SimpleNamespace(fields=SimpleNamespace(
                steplen=inp(p + "steplen", 10), dir_hold_time=inp(p + "dir_hold_time", 10),
                dir_setup_time=inp(p + "dir_setup_time", 12))))
            # speed_target's CSR field resets to 0x40000000 (speed 0): as an input it is
            # whatever the harness drives, as every other input.
            setattr(mmio, "stepgen_%d_speed_target_index_enable" % i, SimpleNamespace(
                fields=SimpleNamespace(speed_target=inp(p + "speed_target", 31),
                                       index_enable=inp(p + "index_enable", 1))))
            setattr(mmio, "stepgen_%d_max_acceleration" % i,
                    SimpleNamespace(storage=inp(p + "max_acceleration", 32)))
            setattr(mmio, "stepgen_%d_position" % i, SimpleNamespace(status=outp(p + "position", 64)))
            setattr(mmio, "stepgen_%d_speed_index" % i, SimpleNamespace(fields=SimpleNamespace(
                speed=outp(p + "speed", 31), index_flag=outp(p + "index_flag", 1))))
        self.MMIO_inst = mmio
        watchdog = SimpleNamespace(has_bitten=inp("watchdog_has_bitten", 1))

        self.config = StepgenModuleConfig(instances=[
            StepgenInstanceConfig(pins=StepGenPinoutStepDirConfig(
                stepgen_type="step_dir", step_pin="stepgen%d:step" % i, dir_pin="stepgen%d:dir" % i))
            for i in range(axes)])
        with contextlib.redirect_stdout(sys.stderr):
            StepgenModule.create_from_config(self, watchdog, self.config)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--axes", type=int, required=True)
    ap.add_argument("--name", required=True, help="the Verilog module name")
    ap.add_argument("--out", required=True, help="the Verilog file to write")
    ap.add_argument("--info", help="a JSON file describing the elaboration")
    a = ap.parse_args(argv[1:])
    if a.axes < 1:
        sys.stderr.write("litexcnc_stepgen: --axes %d: not a positive number of axes\n" % a.axes)
        return 2
    top = PeerTop(a.axes)
    ios = {top.clk_i, top.rst_ni} | set(top.inputs) | set(top.outputs)
    conv = verilog.convert(top, ios=ios, name=a.name, create_clock_domains=False)
    with open(a.out, "w") as f:
        f.write("// Generated by scripts/synth/peers/litexcnc_stepgen.py from LiteX-CNC %s "
                "(PyPI litexcnc), %d axes; not part of hwinterp.\n" % (_version(), a.axes))
        f.write(str(conv))
    if a.info:
        inst = top.config.instances[0]
        shift = inst.calculate_shift(CLOCK_HZ)
        info = {
            "package": "litexcnc %s" % _version(),
            "migen": _version("migen"),
            "litex": _version("litex"),
            "module": "litexcnc.firmware.modules.stepgen.StepgenModule",
            "built_by": "StepgenModule.create_from_config(soc, watchdog, StepgenModuleConfig)",
            "axes": a.axes,
            "config": {"clock_frequency_hz": CLOCK_HZ, "max_frequency_hz": inst.max_frequency,
                       "soft_stop": inst.soft_stop, "stepgen_type": inst.pins.stepgen_type,
                       "index_pin": inst.pins.index_pin, "shift": shift,
                       "pick_off": [32, 32 + shift, 32 + shift + 16]},
            "replaced": "CSRStorage fields/storage -> top-level inputs; CSRStatus status/fields "
                        "and stepgen_apply_time we/dat_w -> top-level outputs (registered in "
                        "soc.sync as in LiteX-CNC); wall_clock.status and watchdog.has_bitten -> "
                        "top-level inputs; sys clock domain -> clk_i, reset ~rst_ni",
            "inputs": {s.name_override: len(s) for s in top.inputs},
            "outputs": {s.name_override: len(s) for s in top.outputs},
        }
        with open(a.info, "w") as f:
            json.dump(info, f, indent=2)
            f.write("\n")
    return 0


def _version(dist="litexcnc"):
    from importlib.metadata import version
    return version(dist)


if __name__ == "__main__":
    sys.exit(main(sys.argv))

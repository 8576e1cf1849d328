"""The boards' gateware: one module per board of cmake/cores.cmake
(hwinterp_board), each with `make_soc(cfg, **options) -> (platform, soc)`
for the board itself (hwinterp_litex/sim.py builds the same SoC for
simulation) and `FLOW`, what its bitstream flow needs (hwinterp_litex/build.py).
"""

import importlib


def target(name: str):
    """The target module of a board."""
    return importlib.import_module(f"{__name__}.{name}")

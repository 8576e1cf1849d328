"""boards/hwinterp_litex/build.py (scripts/board.sh) without the tool chain:
its refusal of bad input, and how it reads nextpnr's reports and logs, judges
a seed and takes LiteX's packer options. The builds themselves are the ctest
entries board_build_<board> (labels long and board_build)."""

import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "boards"))

from hwinterp_litex import build  # noqa: E402


def run_build(*args, tmp_path):
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "boards"))
    return subprocess.run([sys.executable, "-m", "hwinterp_litex.build", "--out", str(tmp_path)]
                          + list(args), capture_output=True, text=True, env=env)


def test_unknown_board_exits_2_naming_it(tmp_path):
    r = run_build("--board", "nexys_a7", tmp_path=tmp_path)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "'nexys_a7'" in lines[0]
    assert "colorlight_5a_75b" in lines[0]  # the known boards are listed


@pytest.mark.parametrize("seeds,bad", [("1 x 3", "'x'"), ("-4", "'-4'"), ("1 1", "'1 1'"),
                                       ("", "''"), ("99999999999", "'99999999999'")])
def test_bad_seed_exits_2_naming_it(tmp_path, seeds, bad):
    r = run_build("--board", "tang_nano_20k", "--seeds", seeds, tmp_path=tmp_path)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and bad in lines[0]
    assert not os.listdir(tmp_path)  # nothing built


def test_board_sh_refuses_an_option_for_a_board(tmp_path):
    r = subprocess.run([os.path.join(ROOT, "scripts", "board.sh"), "--seeds", "1"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "'--seeds'" in r.stderr


LOG = """Info: Device utilisation:
Info: \t         ICESTORM_LC: 11286/ 7680   146%
Info: \t        ICESTORM_RAM:    40/   32   125%
Info: \t               SB_IO:    12/  256     4%

ERROR: Unable to place cell 'x_RAM', no BELs remaining to implement cell type 'ICESTORM_RAM'
"""


def test_overflow_names_every_cell_type_over_the_part(tmp_path):
    log = tmp_path / "nextpnr.log"
    log.write_text(LOG)
    assert build.overflow(str(log)) == [
        {"cell": "ICESTORM_LC", "used": 11286, "available": 7680},
        {"cell": "ICESTORM_RAM", "used": 40, "available": 32}]


def test_a_failure_that_is_not_a_fit_is_no_overflow(tmp_path):
    log = tmp_path / "nextpnr.log"
    log.write_text(LOG.split("ERROR")[0] + "ERROR: Failed to route net 'n'\n")
    assert build.overflow(str(log)) == []


def test_sys_fmax_takes_the_clock_constrained_at_the_system_clock():
    report = {"fmax": {"eth_rx_clk": {"achieved": 140.0, "constraint": 125.0},
                       "crg_clkout": {"achieved": 61.3, "constraint": 50.0},
                       "eth_tx_clk": {"achieved": 90.0, "constraint": 125.0}}}
    assert build.sys_fmax(report, 50_000_000) == ("crg_clkout", 61.3)
    with pytest.raises(build.Failed, match="27.000 MHz"):
        build.sys_fmax(report, 27_000_000)


def test_sys_fmax_takes_the_clock_asked_for_at_the_margin():
    report = {"fmax": {"eth_rx_clk": {"achieved": 136.4, "constraint": 125.0},
                       "sys_clk": {"achieved": 60.53, "constraint": 57.501}}}
    assert build.sys_fmax(report, 50_000_000) == ("sys_clk", 60.53)


def test_margin_lpf_asks_the_reference_port_for_the_margin(tmp_path):
    lpf = tmp_path / "b.lpf"
    lpf.write_text('FREQUENCY PORT "eth_rx_clk" 125.0 MHz;\nFREQUENCY PORT "clk25" 25.0 MHz;\n')
    g = build.Gateware(name="b", family="ecp5", flow={"sys_ref": "clk25"}, sys_hz=50_000_000,
                       dir=str(tmp_path), ys="", constraints=str(lpf), pre_pack=None, what="")
    text = open(build.margin_lpf(g, str(tmp_path))).read()
    assert 'FREQUENCY PORT "clk25" 28.75 MHz;' in text
    assert 'FREQUENCY PORT "eth_rx_clk" 125.0 MHz;' in text
    g.flow = {"sys_ref": "clk27"}
    with pytest.raises(build.Failed, match="clk27"):
        build.margin_lpf(g, str(tmp_path))


def test_verdict_names_the_seed_and_fmax_below_the_margin():
    result = {"board": "b", "sys_mhz": 50.0, "need_mhz": 57.5,
              "runs": [{"seed": 1, "fmax_mhz": 57.5}, {"seed": 2, "fmax_mhz": 57.49},
                       {"seed": 3, "no_fit": [{"cell": "LUT4", "used": 9, "available": 8}]}]}
    bad = build.verdict(result)
    assert len(bad) == 2
    assert "seed 2" in bad[0] and "57.49" in bad[0]
    assert "seed 3" in bad[1] and "9 LUT4" in bad[1] and "8" in bad[1]
    result["runs"] = result["runs"][:1]
    assert build.verdict(result) == []


def test_packer_flags_are_litex_s_without_its_files(tmp_path):
    (tmp_path / "build_t.sh").write_text(
        "set -e\nyosys -l t.rpt t.ys\n"
        "ecppack  --bootaddr 0   --compress  t.config --svf t.svf --bit t.bit \n")
    g = build.Gateware(name="t", family="ecp5", flow={}, sys_hz=1, dir=str(tmp_path), ys="",
                       constraints="", pre_pack=None, what="")
    assert build.litex_packer_flags(g) == ["--bootaddr", "0", "--compress"]
    (tmp_path / "build_t.sh").write_text(
        "gowin_pack -d GW2A-18C -o t.fs t_routed.json --mspi_as_gpio --done_as_gpio\n")
    g.family = "gowin"
    assert build.litex_packer_flags(g) == ["--mspi_as_gpio", "--done_as_gpio"]


def test_gateware_digest_ignores_litex_s_date_and_follows_the_sources(tmp_path):
    (tmp_path / "t.v").write_text("// LiteX sha1 : 1234567\n// Date       : 2026-01-01 00:00:00\n"
                                  "module t; endmodule\n")
    (tmp_path / "r.sv").write_text("module r; endmodule\n")
    (tmp_path / "t.ys").write_text("read_verilog -sv %s\nread_verilog %s\nsynth_ecp5 -top t\n" % (
        tmp_path / "r.sv", tmp_path / "t.v"))
    (tmp_path / "t.lpf").write_text('LOCATE COMP "clk" SITE "P6";\n')
    g = build.Gateware(name="t", family="ecp5", flow={}, sys_hz=1, dir=str(tmp_path),
                       ys=str(tmp_path / "t.ys"), constraints=str(tmp_path / "t.lpf"),
                       pre_pack=None, what="")
    first = build.gateware_digest(g)
    (tmp_path / "t.v").write_text("// LiteX sha1 : 89abcde\n// Date       : 2026-02-02 01:01:01\n"
                                  "module t; endmodule\n")
    assert build.gateware_digest(g) == first
    (tmp_path / "r.sv").write_text("module r; wire w; endmodule\n")
    assert build.gateware_digest(g) != first


def test_critical_path_is_the_last_report_of_the_clock(tmp_path):
    log = tmp_path / "nextpnr.log"
    log.write_text(
        "Info: Critical path report for clock 'clk' (posedge -> posedge):\n"
        "Info:   clk-to-q  1.00  1.00 Source early_q_TRELLIS_FF_Q.Q\n"
        "Info: 1.00 ns logic, 0.00 ns routing\n\n"
        "Info: Critical path report for clock 'clk' (posedge -> posedge):\n"
        "Info:   clk-to-q  5.61  5.61 Source storage_6.0.0.DOA8\n"
        "Info:    routing  1.32  6.93 Net storage_6.0.0_DOA8[2] (22,25) -> (22,16)\n"
        "Info:                          Sink addr_TRELLIS_FF_Q_1_DI_LUT4_Z.C\n"
        "Info:      logic  0.24  7.17 Source addr_TRELLIS_FF_Q_1_DI_LUT4_Z.F\n"
        "Info:    routing  0.41  7.58 Net n (47,17) -> (47,17)\n"
        "Info:                          Sink led_TRELLIS_FF_CE.CE\n"
        "Info: 5.85 ns logic, 1.73 ns routing\n\n"
        "Info: Critical path report for clock 'eth' (posedge -> posedge):\n")
    cp = build.critical_path(str(log), "clk")
    assert cp == {"from": "storage_6.0.0.DOA8", "to": "led_TRELLIS_FF_CE.CE", "logic_ns": 5.85,
                  "routing_ns": 1.73, "through": ["storage_6", "addr"]}
    assert build.critical_path(str(log), "sys") is None

"""`stickslip brake ...`: the command-line contract of issue 3."""

import json

import pytest

from stickslip.brake import BrakeParams, PhysicalParams, coefficients, growth_rates, steady_sliding
from stickslip.cli import run


def _json(args, capsys):
    code = run(args)
    out, err = capsys.readouterr()
    assert code == 0, err
    return json.loads(out)


def test_coefficients_contract(capsys):
    data = _json(["brake", "coefficients", "--xi", "1.5", "--nu", "0.3", "--gamma", "1e-6", "--json"], capsys)
    assert set(data) - {"units"} == {"a", "b", "g", "h", "D", "A", "B", "C1", "C2"} and data["units"]["D"]["units"] == "1"
    assert data["a"] == pytest.approx(coefficients(1.5, 0.3, 1e-6).a)


def test_steady_contract_and_positive_pressure(capsys):
    data = _json(["brake", "steady", "--xi", "1.5", "--nu", "0.3", "--delta", "0.004", "--friction", "0.2", "--json"],
                 capsys)
    assert {"p_e", "q_e", "U_e", "V_e"} <= set(data) and data["p_e"] > 0
    assert data["q_e"] == pytest.approx(0.2 * data["p_e"]) and data["U_e"] == 0.004


def test_stability_contract(capsys):
    data = _json(["brake", "stability", "--xi", "1.5", "--nu", "0.3", "--gamma", "1e-6", "--delta", "0.004",
                  "--friction", "0.2", "--wave-numbers", "1-20", "--json"], capsys)
    assert [m["n"] for m in data["modes"]] == list(range(1, 21))
    assert all(set(m) == {"n", "growth_rate", "frequency"} for m in data["modes"])
    expected = growth_rates(BrakeParams(1.5, 0.3, 1e-6, 0.004, 0.2), range(1, 21)).growth_rate
    assert [m["growth_rate"] for m in data["modes"]] == pytest.approx(list(expected))


def test_physical_options_match_the_dimensionless_ones(capsys):
    data = _json(["brake", "stability", "--omega", "50", "--mismatch", "1e-4", "--friction", "0.7", "--wave-numbers", "8",
                  "--json"], capsys)
    p = PhysicalParams(50.0, 1e-4, 0.7).dimensionless()
    assert data["modes"][0]["growth_rate"] == pytest.approx(float(growth_rates(p, [8]).growth_rate[0]))
    data = _json(["brake", "steady", "--inner-radius", "0.1", "--outer-radius", "0.2", "--mismatch", "4e-4",
                  "--friction", "0.2", "--json"], capsys)
    assert data["p_e"] == pytest.approx(steady_sliding(2.0, 0.3, 0.004, 0.2).p_e)


@pytest.mark.parametrize("args, name", [
    (["coefficients", "--xi", "0.9", "--gamma", "1"], "xi"),
    (["coefficients", "--xi", "1.5", "--nu", "0.5", "--gamma", "1"], "nu"),
    (["coefficients", "--xi", "1.5", "--gamma", "-1"], "gamma"),
    (["coefficients", "--xi", "1.5"], "--gamma"),
    (["steady", "--xi", "1.5", "--delta", "-0.1"], "delta"),
    (["steady", "--xi", "1.5", "--delta", "0.01", "--friction", "nan"], "friction"),
    (["stability", "--xi", "1.5", "--gamma", "1", "--delta", "0.01", "--wave-numbers", "x-3"], "--wave-numbers"),
    (["coefficients", "--xi", "1.5", "--outer-radius", "0.2", "--gamma", "1"], "--xi"),
])
def test_bad_input_is_one_line_and_exit_2(args, name, capsys):
    code = run(["brake", *args, "--json"])
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and err.count("\n") == 1 and name in err


def test_wave_contract(capsys):
    data = _json(["brake", "wave", "--xi", "1.5", "--nu", "0.3", "--gamma", "9.345e-7", "--delta", "0.001",
                  "--friction", "0.7", "--wave-number", "8", "--json"], capsys)
    assert {"c", "regime", "zones"} <= set(data) and data["c"] < 0
    assert all(set(z) >= {"kind", "start", "end"} for z in data["zones"])
    assert data["zones"][0]["start"] == 0 and abs(data["zones"][-1]["end"] - 2 * 3.141592653589793 / 8) < 1e-9


def test_wave_not_found_exits_1_and_says_what_was_tried(capsys):
    code = run(["brake", "wave", "--omega", "1", "--mismatch", "4e-4", "--friction", "0.2", "--wave-number", "4",
                "--regime", "stick-separation", "--json"])
    out, err = capsys.readouterr()
    assert code == 1 and out == "" and err.count("\n") == 1 and "scanned" in err


def test_wave_continuation_reports_zone_events(tmp_path, capsys):
    data = _json(["brake", "continue", "--omega", "50", "--mismatch", "1e-5", "--friction", "0.7", "--wave-number", "4",
                  "--parameter", "delta", "--stop", "2.5e-6", "--points", "20", "--out", str(tmp_path / "b.nc"),
                  "--json"], capsys)
    kinds = [(e["kind"], tuple(e["zones"])) for e in data["events"]]
    assert ("death", ("slip",)) in kinds and len(data["c"]) == len(data["values"]) and (tmp_path / "b.nc").exists()


def test_spectrum_contract_and_refusals(capsys):
    """The wave's stability on two rings; refused: a ring size that is not a multiple of the wave
    number (one line naming the option, exit 2). A wave that separates is followed on the ring whose
    nodes may leave the shaft; one whose discrete wave is not found ends in one line, exit 1."""
    data = _json(["brake", "spectrum", "--omega", "100", "--mismatch", "1e-4", "--friction", "0.2", "--nodes", "32,64",
                  "--json"], capsys)
    assert data["nodes"] == [32, 64] and data["structure"] == "stick|slip" and not data["stable"]
    assert data["growth_per_period"] == data["growth_per_period_by_nodes"][-1] > 0
    assert data["speed_error_by_nodes"][1] < data["speed_error_by_nodes"][0] < 0.02
    for args, name in ((["--nodes", "30"], "--nodes = 30"), (["--nodes", "64,x"], "--nodes"),
                       (["--nodes", "4096"], "--nodes = 4096")):
        base = {"--omega": "100", "--mismatch": "1e-4", "--friction": "0.2"}
        for k, v in zip(args[::2], args[1::2]):
            base[k] = v
        code = run(["brake", "spectrum", *[x for kv in base.items() for x in kv], "--json"])
        out, err = capsys.readouterr()
        assert code == 2 and out == "" and err.count("\n") == 1 and name in err, err
    data = _json(["brake", "spectrum", "--omega", "50", "--mismatch", "1.2e-6", "--friction", "0.7", "--nodes", "32",
                  "--json"], capsys)
    assert data["separates"] and data["structure"] == "stick|slip|separation" and data["growth_per_period"] > 0
    code = run(["brake", "spectrum", "--omega", "100", "--mismatch", "1e-5", "--friction", "0.2", "--wave-number", "8",
                "--regime", "stick-slip-separation-reverse-slip", "--nodes", "64"])
    out, err = capsys.readouterr()
    assert code == 1 and out == "" and err.count("\n") == 1 and "no wave of the ring of 64 nodes" in err


def test_bad_regime_is_a_usage_error(capsys):
    code = run(["brake", "wave", "--xi", "1.5", "--gamma", "1e-6", "--delta", "0.001", "--friction", "0.7",
                "--regime", "chaos"])
    assert code == 2 and "--regime" in capsys.readouterr().err


def test_regime_map_command(tmp_path, capsys):
    data = _json(["brake", "map", "--out", str(tmp_path / "w.zarr"), "--x", "friction=0.2:0.7:2",
                  "--y", "mismatch=1e-6:1e-4:2:log", "--workers", "1", "--json"], capsys)
    assert data["points"] == 4 and sum(data["counts"].values()) == 4 and data["counts"].get("stick-slip", 0) >= 1
    assert run(["brake", "map", "--out", str(tmp_path / "x.nc")]) == 2
    assert run(["brake", "map", "--out", str(tmp_path / "y.zarr"), "--y", "mismatch=0:1e-4:3:log"]) == 2

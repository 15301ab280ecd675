"""`stickslip halfspace ...`: the command-line contract of issue 4."""

import json

import pytest
import xarray as xr

from stickslip.cli import run
from stickslip.halfspace import inverse_problem

COMMON = ["--v-star", "0.001", "--nu", "0.3", "--mu", "0.5"]


def _call(args, capsys):
    code = run(args)
    out, err = capsys.readouterr()
    return code, out, err


def test_inverse_contract(capsys):
    code, out, _ = _call(["halfspace", "inverse", "--b", "2", "--c", "-0.7", *COMMON, "--json"], capsys)
    data = json.loads(out)
    assert code == 0 and {"v", "T", "alpha", "D", "beta1", "beta2", "gamma1", "gamma2"} <= set(data)
    ref = inverse_problem(2.0, -0.7, 0.001, nu=0.3, mu=0.5)
    assert data["v"] == pytest.approx(float(ref.v)) and data["D"] < 0


def test_direct_round_trip_and_no_solution(capsys):
    ref = inverse_problem(3.0, -0.5, 0.001, nu=0.3, mu=0.5)
    code, out, _ = _call(["halfspace", "direct", "--T", repr(float(ref.T)), "--v", repr(float(ref.v)), *COMMON,
                          "--json"], capsys)
    data = json.loads(out)
    assert code == 0 and data["c"] == pytest.approx(-0.5, rel=1e-6) and data["b"] == pytest.approx(3.0, rel=1e-6)
    code, out, err = _call(["halfspace", "direct", "--T", "1e-3", "--v", "1e-3", *COMMON, "--json"], capsys)
    assert code == 1 and out == "" and err.startswith("no solution:") and err.count("\n") == 1


def test_fields_writes_netcdf_and_plot(tmp_path, capsys):
    nc, png = tmp_path / "f.nc", tmp_path / "f.png"
    code, out, _ = _call(["halfspace", "fields", "--b", "3", "--c", "-0.7", *COMMON, "--points", "501", "--out",
                          str(nc), "--plot", str(png), "--json"], capsys)
    assert code == 0 and json.loads(out)["exponent_slip_to_stick"] < 0
    ds = xr.load_dataset(nc)
    assert "sigma_yy" in ds and png.stat().st_size > 10_000


@pytest.mark.parametrize("args, name", [
    (["inverse", "--b", "1", "--c", "-0.7"], "b"), (["inverse", "--b", "2", "--c", "0.2"], "c"),
    (["inverse", "--b", "2", "--c", "-1.5"], "c"), (["inverse", "--b", "2", "--c", "-0.5", "--mu", "-1"], "mu"),
    (["inverse", "--b", "2", "--c", "-0.5", "--nu", "0.6"], "nu"),
    (["direct", "--T", "-1", "--v", "0.01"], "T"),
])
def test_bad_input_is_one_line_and_exit_2(args, name, capsys):
    code, out, err = _call(["halfspace", *args, "--v-star", "0.001", "--json"], capsys)  # nu, mu: defaults
    assert code == 2 and out == "" and err.count("\n") == 1 and name in err

"""The command line as a user meets it: JSON on stdout, one-line errors, exit codes."""

import json
import subprocess
import sys

import pytest
import xarray as xr

from stickslip.cli import run

BASE = ["oscillator", "cycle", "--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2",
        "--fs", "0.6", "--fd", "0.4"]


def _run(args, capsys):
    code = run(args)
    out, err = capsys.readouterr()
    return code, out, err


def test_cycle_json_contract(capsys):
    code, out, err = _run(BASE + ["--json"], capsys)
    assert code == 0
    data = json.loads(out)
    assert {"period", "stick_time", "slip_time", "x_min", "x_max", "floquet_multipliers"} <= set(data)
    assert data["stick_time"] == pytest.approx(2.0) and sorted(data["floquet_multipliers"]) == pytest.approx([0, 1], abs=1e-12)


def test_cycle_with_each_law(capsys):
    for extra in (["--law", "linear-weakening", "--tau", "0.5", "--fs", "0.4"],
                  ["--law", "stribeck", "--tau", "0.1", "--damping", "0.05"]):
        code, out, _ = _run(BASE + extra + ["--json"], capsys)
        assert code == 0 and json.loads(out)["period"] > 0


@pytest.mark.parametrize("change, name", [
    (["--fs", "0.3"], "fs"), (["--mass", "-1"], "mass"), (["--stiffness", "0"], "stiffness"),
    (["--normal-force", "nan"], "normal_force"), (["--belt-speed", "0"], "belt_speed"), (["--damping", "-0.1"], "damping"),
    (["--law", "stribeck"], "tau"),
])
def test_bad_input_is_one_line_and_exit_2(change, name, capsys):
    code, out, err = _run(BASE + change + ["--json"], capsys)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and name in err and "must be" in err


def test_usage_errors_are_one_line_too(capsys):
    for args in (BASE[:-2], BASE + ["--mass", "heavy"], ["oscillator", "cycle", "--bogus", "1"]):
        code, out, err = _run(args, capsys)
        assert code == 2 and err.count("\n") == 1 and "Traceback" not in err


def test_no_cycle_exits_1(capsys):
    code, out, err = _run(BASE + ["--damping", "0.5", "--json"], capsys)
    assert code == 1 and err.startswith("no solution:") and err.count("\n") == 1


def test_simulate_writes_netcdf_with_units_and_plot(tmp_path, capsys):
    nc, png = tmp_path / "run.nc", tmp_path / "run.png"
    args = ["oscillator", "simulate", *BASE[2:], "--t-end", "30", "--x0", "-1.5", "--out", str(nc), "--plot", str(png),
            "--json"]
    code, out, err = _run(args, capsys)
    assert code == 0 and json.loads(out)["reverse_slip_segments"] >= 1
    ds = xr.load_dataset(nc)
    assert ds["x"].attrs["units"] == "m" and ds["t"].attrs["units"] == "s"
    assert png.stat().st_size > 10_000


def test_output_paths_are_validated(tmp_path, capsys):
    code, _, err = _run(BASE + ["--out", str(tmp_path / "x.txt")], capsys)
    assert code == 2 and "--out" in err
    code, _, err = _run(BASE + ["--out", str(tmp_path / "missing" / "x.nc")], capsys)
    assert code == 2 and "existing directory" in err


def test_stability_and_continuation_commands(capsys):
    args = ["oscillator", "stability", *BASE[2:], "--law", "stribeck", "--tau", "0.1", "--damping", "0.05", "--json"]
    code, out, _ = _run(args, capsys)
    data = json.loads(out)
    assert code == 0 and data["hopf_points"][0]["criticality"] == "subcritical"
    args = ["oscillator", "continue", *BASE[2:], "--stop", "0.5", "--json"]
    code, out, _ = _run(args, capsys)
    data = json.loads(out)
    assert code == 0 and data["points"][-1]["belt_speed"] == pytest.approx(0.5)


def test_installed_entry_point_runs():
    proc = subprocess.run([sys.executable, "-m", "stickslip", "oscillator", "cycle", "--help"], capture_output=True,
                          text=True)
    assert proc.returncode == 0 and "--belt-speed" in proc.stdout

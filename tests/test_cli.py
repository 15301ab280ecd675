"""The command line as a user meets it: JSON on stdout, one-line errors, exit codes."""

import json
import subprocess
import sys

from pathlib import Path

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
                  ["--law", "stribeck", "--vs", "0.1", "--damping", "0.05"]):
        code, out, _ = _run(BASE + extra + ["--json"], capsys)
        assert code == 0 and json.loads(out)["period"] > 0


@pytest.mark.parametrize("change, name", [
    (["--fs", "0.3"], "--fs"), (["--mass", "-1"], "--mass"), (["--stiffness", "0"], "--stiffness"),
    (["--normal-force", "nan"], "--normal-force"), (["--belt-speed", "0"], "--belt-speed"),
    (["--damping", "-0.1"], "--damping"), (["--law", "stribeck"], "--vs"), (["--law", "stribeck", "--tau", "0.1"], "--tau"),
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
    assert code == 2 and "existing folder" in err


OSC = ["--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2", "--fs", "0.6", "--fd", "0.4"]
BRAKE = ["--omega", "50", "--mismatch", "1e-4", "--friction", "0.7"]
BLOCK = Path(__file__).resolve().parents[1] / "examples" / "block_on_belt" / "block.toml"
#: (command, the option, a suffix it needs, whether it is a folder, the library function it must not reach)
OUTPUTS = [
    (["oscillator", "simulate", *OSC, "--t-end", "5"], "--out", ".nc", False, "stickslip.oscillator.simulate"),
    (["oscillator", "simulate", *OSC, "--t-end", "5"], "--plot", ".png", False, "stickslip.oscillator.simulate"),
    (["oscillator", "map", *OSC], "--out", ".zarr", True, "stickslip.oscillator.regimes.regime_map"),
    (["brake", "integrate", *BRAKE, "--transits", "1"], "--out", ".nc", False, "stickslip.brake.integrate"),
    (["brake", "fem", *BRAKE, "--transits", "1"], "--out", ".nc", False, "stickslip.brake.fem.integrate_fem"),
    (["brake", "map"], "--out", ".zarr", True, "stickslip.brake.maps.wave_regime_map"),
    (["brake", "campaign"], "--out", "", True, "stickslip.brake.fem.campaign.statistics"),
    (["halfspace", "fields", "--b", "11.358", "--c", "-0.7", "--v-star", "0.001"], "--out", ".nc", False,
     "stickslip.halfspace.wave_from_inverse"),
    (["reproduce", "--only", "fig2"], "--out", "", True, "stickslip.report.reproduce"),
    *[(["fem", command, str(BLOCK)], option, suffix, False, "stickslip.fem.config.load_config")
      for command, option, suffix in (("steady", "--out", ".nc"), ("cea", "--out", ".nc"), ("cea", "--xdmf", ".xdmf"),
                                      ("run", "--out", ".nc"), ("run", "--xdmf", ".xdmf"))],
]


def _bad_paths(tmp_path, suffix, folder):
    a_file = tmp_path / f"file{suffix}"
    a_file.write_text("x")
    a_dir = tmp_path / f"dir{suffix}"
    a_dir.mkdir()
    bad = {"missing parent": tmp_path / "missing" / "sub" / f"x{suffix}", "under a file": a_file / f"x{suffix}",
           "unwritable": Path("/proc") / f"x{suffix}"}
    bad.update({"a file": a_file} if folder else {"a folder": a_dir, "missing parent": tmp_path / "no" / f"x{suffix}"})
    if folder:
        del bad["missing parent"]  # a folder's missing parents are created
    return bad


@pytest.mark.parametrize("args, option, suffix, folder, target", OUTPUTS, ids=[f"{o[0][0]} {o[0][1]} {o[1]}"
                                                                               for o in OUTPUTS])
def test_bad_output_paths_fail_before_any_work(args, option, suffix, folder, target, tmp_path, capsys, monkeypatch):
    module, _, name = target.rpartition(".")
    monkeypatch.setattr(module + "." + name, lambda *a, **k: pytest.fail("the work started"), raising=True)
    for what, path in _bad_paths(tmp_path, suffix, folder).items():
        code, _, err = _run(args + [option, str(path)], capsys)
        assert code == 2 and err.count("\n") == 1 and option in err, (what, err)


def test_stability_and_continuation_commands(capsys):
    args = ["oscillator", "stability", *BASE[2:], "--law", "stribeck", "--vs", "0.1", "--damping", "0.05", "--json"]
    code, out, _ = _run(args, capsys)
    data = json.loads(out)
    assert code == 0 and data["hopf_points"][0]["criticality"] == "subcritical"
    # the equilibrium's quantities with their own meanings (a cycle's "orbitally stable" was printed)
    assert "steady sliding" in data["units"]["stable"]["long_name"], data["units"]["stable"]
    assert "equilibrium" in data["units"]["kind"]["long_name"], data["units"]["kind"]
    args = ["oscillator", "continue", *BASE[2:], "--stop", "0.5", "--json"]
    code, out, _ = _run(args, capsys)
    data = json.loads(out)
    assert code == 0 and data["points"][-1]["belt_speed"] == pytest.approx(0.5)


def test_installed_entry_point_runs():
    proc = subprocess.run([sys.executable, "-m", "stickslip", "oscillator", "cycle", "--help"], capture_output=True,
                          text=True)
    assert proc.returncode == 0 and "--belt-speed" in proc.stdout


@pytest.mark.parametrize("args", [
    ["brake", "fem", "--omega", "50", "--mismatch", "0", "--friction", "0.7", "--transits", "1", "--json"],
    ["halfspace", "inverse", "--b", "1e300", "--c", "-0.7", "--v-star", "0.001", "--json"],
], ids=["fem mismatch 0", "inverse b 1e300"])
def test_a_non_finite_result_is_never_printed_with_exit_0(args, capsys):
    """Inputs that once printed NaN with exit 0 (issue 9): now an error, nothing on stdout."""
    code, out, err = _run(args, capsys)
    assert code in (1, 2) and out == "" and err.strip()


@pytest.mark.parametrize("args, option", [
    (["oscillator", "simulate", *OSC, "--t-end", "5", "--samples", "1000000000000"], "--samples"),
    (["oscillator", "simulate", *OSC, "--t-end", "5", "--samples", "0"], "--samples"),
    (["halfspace", "fields", "--b", "11.358", "--c", "-0.7", "--v-star", "0.001", "--points", "1000000000000"],
     "--points"),
    (["brake", "stability", "--xi", "1.5", "--nu", "0.3", "--gamma", "1e-6", "--delta", "0.004", "--friction", "0.2",
      "--wave-numbers", "1-99999999"], "--wave-numbers"),
    (["brake", "continue", "--omega", "50", "--mismatch", "1e-5", "--friction", "0.7", "--wave-number", "4", "--stop",
      "2.5e-6", "--points", "1000000000"], "--points"),
], ids=["samples 1e12", "samples 0", "points 1e12", "modes 1e8", "branch points 1e9"])
def test_absurd_sizes_are_refused_up_front(args, option, capsys):
    code, out, err = _run(args, capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and option in err and ("from 1 to" in err or "an integer in [" in err)


@pytest.mark.parametrize("args, option", [
    (["oscillator", "simulate", *OSC, "--t-end", "1e300"], "--t-end"),
    (["brake", "integrate", "--omega", "50", "--mismatch", "1e-4", "--friction", "0.7", "--transits", "1e300"],
     "--transits"),
    (["brake", "fem", "--xi", "1.0000001", "--gamma", "1e-6", "--delta", "0.004", "--friction", "0.2",
      "--transits", "1"], "--xi"),
], ids=["t-end 1e300", "transits 1e300", "xi 1.0000001 (vanishing step)"])
def test_runs_that_would_not_end_are_refused_up_front_with_the_limit(args, option, capsys):
    """These used to run until killed (issue 9). The thin wall is now refused by its radius
    ratio (its coefficients lose their digits before its time step vanishes)."""
    code, out, err = _run(args, capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and option in err and ("<=" in err or "in [" in err or "in (" in err)


def test_version_and_figure_list(capsys):
    from stickslip import __version__
    from stickslip.figures import registry

    assert run(["--version"]) == 0
    assert capsys.readouterr().out.strip() == f"stickslip {__version__}"
    assert run(["reproduce", "--list", "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["figures"].keys() == registry().keys() and err == ""


def test_help_texts_keep_their_units(capsys):
    """Issue 10: rich markup ate ``[kg]``, ``[m/s]``, ``[rad/s]`` out of --help."""
    import re

    import typer.main

    from stickslip.cli import app

    def commands(cmd, path):
        if hasattr(cmd, "commands"):
            for name, sub in cmd.commands.items():
                yield from commands(sub, path + [name])
        else:
            yield path, cmd

    checked = 0
    for path, cmd in commands(typer.main.get_command(app), []):
        assert run([*path, "--help"]) == 0
        shown = " ".join(capsys.readouterr().out.split())
        for param in cmd.params:
            for unit in re.findall(r"\[[^\]]+\]", getattr(param, "help", None) or ""):
                assert unit in shown, (path, param.name, unit)
                checked += 1
    assert checked > 20


def test_a_parameter_that_is_no_number_is_refused(capsys):
    """Issue 10: `--parameter name` (the law's label) was offered and crashed with exit 3."""
    for command in (["continue", "--stop", "0.3"], ["stability"]):
        assert run(["oscillator", *command, *OSC, "--parameter", "name"]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--parameter" in err and "belt_speed" in err


def test_the_command_line_loads_no_model_before_a_command_needs_it():
    """`stickslip --help` (and every command's start) does not import the models: they load
    with the command that uses them (all of them once took 2.5 s before any work)."""
    import subprocess
    import sys

    code = ("import sys, stickslip.cli; print(' '.join(sorted({m.split('.')[1] for m in sys.modules "
            "if m.startswith('stickslip.') and m.split('.')[1] in ('brake', 'oscillator', 'fem', 'halfspace', "
            "'contact', 'friction')})))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == []


def _cells(text: str, column: int) -> str:
    """The text of one column of a rich table, its folded lines joined."""
    return "".join(line.split("│")[column].strip() for line in text.splitlines() if line.count("│") >= column + 1)


@pytest.mark.parametrize("width", ["40", "60", "100"])
def test_a_human_table_folds_a_long_value_instead_of_cutting_it(width, monkeypatch, capsys):
    """Issue 44: a narrow terminal or a pipe showed `stick-slip-separati…`."""
    from stickslip.cli.common import emit

    monkeypatch.setenv("COLUMNS", width)
    value = "stick-slip-separation-with-reverse-slip-and-overshoot"
    emit({"regime": value, "records": [{"regime": value, "n": 1}]}, False, "a result")
    out = capsys.readouterr().out
    assert "…" not in out and _cells(out, 2).count(value) == 1 and value in _cells(out, 1)

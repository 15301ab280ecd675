"""The edge classes of issue 44, a sample of each (the whole draw, with counts by class:
``python -m tests.fuzz_report``): special files as inputs and outputs, a scheduler address that
answers but is not Dask, repeated values in lists, deep nesting and subnormal numbers in config
files, options that mean something together given apart, two spellings of one key in one file,
a sweep's combination rule broken at some point of its grid, and every public function of the
API with bad arguments. Each refusal names the option or file as the user wrote it, comes before
any work (nothing is written), and raises the package's own errors."""

from __future__ import annotations

import json
import os
import pathlib
import signal
import socket
import subprocess
import sys

import pytest

from stickslip.cli import app, run
from stickslip.cli.common import output_folder, output_path
from stickslip.errors import NoSolutionError, ParameterError

from .fuzz_harness import SYSTEM_FILE, example_config, time_limit
from .fuzz_report import (APART, SWEEP_FIXED, SWEEP_HEAD, FakeServer, judge_api, public_callables, required,
                          special)




def refused(capsys, args, *words, seconds: int = 30):
    with time_limit(seconds):
        code = run(args)
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and err.count("\n") == 1 and "Traceback" not in err, (code, out, err)
    for w in words:
        assert w in err, (w, err)
    return err


def _socket_file(folder: pathlib.Path, name: str) -> str:
    path = folder / name
    s = socket.socket(socket.AF_UNIX)
    s.bind(str(path))
    s.close()
    return str(path)


KINDS = ["a FIFO", "a dangling link", "a folder", "/dev/null", "a link to a FIFO", "a socket"]
READERS = [(["system", "stability"], "system file"), (["fem", "steady"], "config")]


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("command, name", READERS, ids=["system file", "fem config"])
def test_a_special_file_as_a_config_is_refused_at_once(command, name, kind, tmp_path, capsys):
    """A FIFO blocked the reader for ever (a hang), a folder or a socket gave the OS's word, a
    dangling link "no such file" without saying it is a link: each is one line naming the file."""
    path = _socket_file(tmp_path, "in.toml") if kind == "a socket" else special(kind, tmp_path, "in.toml")
    what = {"a FIFO": "FIFO", "a dangling link": "dangling symbolic link", "a folder": "a folder",
            "/dev/null": "a device", "a link to a FIFO": "FIFO", "a socket": "a socket"}[kind]
    refused(capsys, [*command, path, "--json"], name, "regular file", what, seconds=20)


def test_a_special_file_as_a_sweep_config_is_refused(tmp_path):
    from stickslip.cli.study import read_study

    for kind in ("a FIFO", "a dangling link"):
        with time_limit(20), pytest.raises(ParameterError, match="regular file") as err:
            read_study(pathlib.Path(special(kind, tmp_path, kind[2:] + ".toml")), app)
        assert err.value.name == "CONFIG"


OUTPUTS = [("--out", ".nc"), ("--plot", ".png"), ("--xdmf", ".xdmf")]


@pytest.mark.parametrize("kind", ["a FIFO", "a dangling link", "/dev/null", "a socket"])
@pytest.mark.parametrize("option, suffix", OUTPUTS)
def test_a_special_file_as_an_output_is_refused_even_with_overwrite(option, suffix, kind, tmp_path):
    """With --overwrite a FIFO or a link to /dev/null behind a name with the right suffix was
    replaced by the result (as root, /dev/null itself), and without it the check that the file
    holds a run opened the FIFO and waited for ever. output_path writes nothing: safe to ask
    about a device."""
    path = _socket_file(tmp_path, "o" + suffix) if kind == "a socket" else special(kind, tmp_path, "o" + suffix)
    for overwrite in (True, False, None):
        with time_limit(10), pytest.raises(ParameterError, match="regular file or a new name") as err:
            output_path(option, pathlib.Path(path), suffix, overwrite)
        assert err.value.name == option and err.value.value == path


@pytest.mark.slow  # 15 s: the child is forked from a process that ran each command once (fuzz_harness.trial)
def test_a_fifo_as_a_checkpoint_or_an_output_is_refused_on_the_command_line(tmp_path):
    """In a forked child with a time limit: netCDF's open of a FIFO blocks in C, where no signal
    handler of this process can stop it."""
    from .fuzz_harness import trial

    fifo = special("a FIFO", tmp_path, "o.nc")
    osc = ["--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2", "--fs", "0.6", "--fd", "0.4"]
    for args in (["oscillator", "cycle", *osc, "--out", fifo],
                 ["brake", "integrate", "--omega", "50", "--mismatch", "1e-4", "--friction", "0.7", "--nodes", "32",
                  "--transits", "1", "--out", fifo]):
        t = trial(args, timeout=30)
        assert t.code == 2 and t.out == "" and t.err.count("\n") == 1 and "--out" in t.err and "FIFO" in t.err, t
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o.nc"]


@pytest.mark.parametrize("kind", ["a FIFO", "a dangling link"])
def test_a_special_file_as_a_store_is_refused(kind, tmp_path):
    path = pathlib.Path(special(kind, tmp_path, "s.zarr"))
    with pytest.raises(ParameterError, match="a folder") as err:
        output_folder("--out", path, ".zarr")
    assert err.value.name == "--out" and {"a FIFO": "FIFO", "a dangling link": "dangling"}[kind] in str(err.value)


def test_a_scheduler_that_answers_garbage_is_refused_before_the_store(tmp_path):
    """A server that answers but is not Dask: exit 3 with MemoryError (the garbage read as a
    frame length of 3 EiB) after the store was made; now refused by the address check, within
    2 x CONNECT_SECONDS (here at once), before anything is written."""
    from stickslip.cluster import reachable
    from stickslip.sweep import run_sweep

    server = FakeServer("garbage", lifetime=60)
    try:
        with time_limit(40):
            with pytest.raises(ParameterError, match="not as a Dask scheduler") as err:
                reachable(server.address, "--scheduler")
            assert err.value.name == "--scheduler" and err.value.value == server.address
            with pytest.raises(ParameterError, match="not as a Dask scheduler"):
                run_sweep(_one, {"x": [1.0, 2.0]}, tmp_path / "s.zarr", outputs={"y": "1"}, scheduler=server.address)
    finally:
        server.stop()  # its sockets closed here, not by the garbage collector in a later test
    assert list(tmp_path.iterdir()) == []


def _one(x):
    return {"y": x}


@pytest.mark.slow
def test_a_scheduler_that_never_answers_is_refused_within_the_stated_time(tmp_path, capsys):
    """Accepts the connection and says nothing: refused within 2 x CONNECT_SECONDS (20 s)."""
    from stickslip.cluster import CONNECT_SECONDS

    server = FakeServer("silent", lifetime=120)
    sweep = tmp_path / "s.toml"
    sweep.write_text(SWEEP_HEAD + SWEEP_FIXED + "fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = [0.1, 0.2]\n")
    try:
        with time_limit(int(2 * CONNECT_SECONDS) + 20):
            refused(capsys, ["sweep", str(sweep), "--out", str(tmp_path / "s.zarr"), "--scheduler", server.address],
                    "--scheduler", "not as a Dask scheduler", seconds=int(2 * CONNECT_SECONDS) + 15)
    finally:
        server.stop()  # the held connections closed here, not by the garbage collector in a later test
    assert not (tmp_path / "s.zarr").exists()


def _study(tmp_path, text):
    from stickslip.cli.study import read_study

    path = tmp_path / "sweep.toml"
    path.write_text(text)
    with pytest.raises(ParameterError) as err:
        read_study(path, app)
    assert err.value.name == "CONFIG"
    return err.value.allowed


@pytest.mark.parametrize("values", ["[0.1, 0.1]", "[0.1, 0.2, 0.1]", "{ start = 0.2, stop = 0.2, num = 3 }"])
def test_a_swept_value_given_twice_is_refused(values, tmp_path):
    why = _study(tmp_path, SWEEP_HEAD + SWEEP_FIXED + f"fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = {values}\n")
    assert "axes.belt_speed repeats 0.1" in why or "axes.belt_speed repeats 0.2" in why, why


def test_repeated_values_on_the_command_line_and_in_the_api(tmp_path, capsys):
    from stickslip.sweep import run_sweep

    refused(capsys, ["brake", "stability", "--xi", "1.5", "--nu", "0.3", "--gamma", "1e-6", "--delta", "0.004",
                     "--friction", "0.2", "--wave-numbers", "1-3,2"], "--wave-numbers", "2 is given twice")
    refused(capsys, ["oscillator", "map", "--mass", "1", "--stiffness", "1", "--normal-force", "1", "--fs", "0.6",
                     "--fd", "0.4", "--x", "belt_speed=0.2:0.2:3", "--y", "damping=0.01:0.02:2", "--out",
                     str(tmp_path / "m.zarr")], "--x = 'belt_speed=0.2:0.2:3'", "3 distinct values")
    with pytest.raises(ParameterError, match="distinct") as err:
        run_sweep(_one, {"x": [1.0, 1.0]}, tmp_path / "s.zarr", outputs={"y": "1"}, scheduler="synchronous")
    assert err.value.name == "axes['x']"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("kind", ["array", "table"])
def test_a_deeply_nested_system_file_or_sweep_config_is_named(kind, tmp_path):
    """tomllib recursed until Python's limit: exit 3 with RecursionError for a system file and a
    sweep config (the fem config said it already)."""
    from stickslip.system.config import read_table

    deep = "deep = " + ("[" * 3000 + "1" + "]" * 3000 if kind == "array" else "{a=" * 3000 + "1" + "}" * 3000) + "\n"
    path = tmp_path / "s.toml"
    path.write_text(deep + pathlib.Path(SYSTEM_FILE).read_text())
    with pytest.raises(ParameterError, match="nested") as err:
        read_table(path)
    assert err.value.name == "system file"
    assert "nested" in _study(tmp_path, deep + SWEEP_HEAD + SWEEP_FIXED + "fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = [0.1]\n")


@pytest.mark.parametrize("value", ["1e-320", "-4.9e-324"])
def test_a_subnormal_number_in_a_sweep_config_is_named(value, tmp_path):
    why = _study(tmp_path, SWEEP_HEAD + SWEEP_FIXED + f"fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = [0.1, {value}]\n")
    assert "subnormal" in why and "axes.belt_speed" in why, why


@pytest.mark.parametrize("fixed", ["normal_force = 1.0\nnormal-force = 2.0\n", "normal-force = 1.0\nnormal_force = 1.0\n"])
def test_two_spellings_of_one_option_in_a_sweep_config_are_refused(fixed, tmp_path):
    """The second spelling silently replaced the first (normal_force = 1 ran at 2)."""
    why = _study(tmp_path, SWEEP_HEAD + "[fixed]\nmass = 1.0\nstiffness = 1.0\n" + fixed
                 + "fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = [0.1, 0.2]\n")
    assert "fixed.normal_force and fixed.normal-force" in why or "fixed.normal-force and fixed.normal_force" in why
    assert "given twice" in why


def test_two_spellings_of_one_config_number_in_a_fem_sweep_are_refused(tmp_path):
    pad = pathlib.Path(example_config())
    (tmp_path / "pad.toml").write_text(pad.read_text().replace('mesh = "pad.msh"', f'mesh = "{pad.with_suffix(".msh")}"'))
    why = _study(tmp_path, 'command = "fem steady"\nconfig = "pad.toml"\noutputs = ["normal_force"]\n[fixed]\n'
                 'friction = 0.4\ncontact.friction = 0.3\n[axes]\nsurface.speed = [1.0, 2.0]\n')
    assert "fixed.friction and fixed.contact.friction are one config number (contact.friction)" in why, why


@pytest.mark.parametrize("fixed, axes, first", [
    ("fd = 0.4\n", "fs = [0.5, 0.3]\n", "axes.fs = 0.3 with fixed.fd = 0.4"),
    ("fs = 0.5\n", "fd = [0.3, 0.6]\n", "fixed.fs = 0.5 with axes.fd = 0.6"),
    ("", "fs = [0.5, 0.6]\nfd = [0.3, 0.55]\n", "axes.fs = 0.5 with axes.fd = 0.55"),
])
def test_a_sweep_whose_grid_breaks_fs_at_least_fd_is_refused_before_any_point(fixed, axes, first, tmp_path, capsys):
    """It computed the good points, stored them, and ended with exit 1 naming the failed ones."""
    sweep = tmp_path / "s.toml"
    sweep.write_text(SWEEP_HEAD + SWEEP_FIXED + fixed + "[axes]\n" + axes + "belt_speed = [0.1, 0.2]\n")
    refused(capsys, ["sweep", str(sweep), "--out", str(tmp_path / "s.zarr"), "--workers", "1"], "CONFIG", first,
            "--fs must be >= --fd at every point of the grid")
    assert not (tmp_path / "s.zarr").exists()


@pytest.mark.parametrize("args, name", APART[:6], ids=[" ".join(a[:2]) + " " + n for a, n in APART[:6]])
def test_an_option_given_without_the_one_it_needs_is_refused(args, name, tmp_path, capsys):
    args = [example_config() if a == "{config}" else a.replace("{tmp}", str(tmp_path)) for a in args]
    refused(capsys, args, name)
    assert list(tmp_path.iterdir()) == []


def test_a_window_no_run_can_fill_is_refused_before_the_run(tmp_path, capsys):
    """fem run --window 1e-300 integrated, wrote the run, then refused the window (found by
    tests/fuzz_report.py as a late refusal)."""
    refused(capsys, ["fem", "run", example_config(), "--transits", "2", "--out", str(tmp_path / "g.nc"), "--window",
                     "1e-300"], "--window = 1e-300", ">= 0.0625 transits")
    assert list(tmp_path.iterdir()) == []


def test_first_lyapunov_coefficient_and_run_sweep_check_their_arguments(tmp_path):
    """Both had no input checks: a number for the field gave TypeError, NaN in x0 went to
    numpy's eig (LinAlgError), a number for the point function went to the workers."""
    import numpy as np

    from stickslip.rsf import first_lyapunov_coefficient
    from stickslip.sweep import run_sweep

    def field(u):
        return np.array([-u[1], u[0]])

    for kwargs, name in [({"field": 1.0, "x0": [0.0, 0.0]}, "field"), ({"field": field, "x0": [np.nan, 0.0]}, "x0"),
                         ({"field": field, "x0": []}, "x0"), ({"field": field, "x0": [0.0]}, "x0"),
                         ({"field": field, "x0": "x"}, "x0"), ({"field": field, "x0": [0.0, 0.0], "step": -1.0}, "step"),
                         ({"field": lambda u: u[:1], "x0": [0.0, 0.0]}, "field")]:
        with pytest.raises(ParameterError) as err:
            first_lyapunov_coefficient(**kwargs)
        assert err.value.name == name, (kwargs, err.value)
    for kwargs, name in [({"func": 1.0}, "func"), ({"scheduler": "nowhere"}, "scheduler"), ({"scheduler": 3}, "scheduler")]:
        with pytest.raises(ParameterError) as err:
            run_sweep(**{"func": _one, "axes": {"x": [1.0]}, "store": tmp_path / "s.zarr", "outputs": {"y": "1"},
                         "scheduler": "synchronous", **kwargs})
        assert err.value.name == name
    assert list(tmp_path.iterdir()) == []


def test_the_shape_integrals_refuse_a_ratio_whose_square_overflows():
    """xi = 1e300 gave NaN integrals without a word (found by tests/fuzz_report.py)."""
    from stickslip.brake import shape_integrals

    with pytest.raises(ParameterError, match=r"in \(1, 1e150\]") as err:
        shape_integrals([2.0, 1e300])
    assert err.value.name == "xi" and all(v > 0 for v in shape_integrals([1.5, 1e150])[0])


#: A sample of the public callables for the fast set (the slow set walks them all).
SAMPLE = ["stickslip.oscillator.limit_cycle", "stickslip.oscillator.simulate", "stickslip.oscillator.hopf_points",
          "stickslip.brake.transit_time", "stickslip.brake.shape_integrals", "stickslip.brake.ring.initial_from_wave",
          "stickslip.brake.waves.energy_balance", "stickslip.contact.state_fractions", "stickslip.contact.pattern_shift",
          "stickslip.system.monodromy", "stickslip.system.saltation", "stickslip.friction.make_law",
          "stickslip.halfspace.periodic_X", "stickslip.files.content_digest", "stickslip.fem.read_body",
          "stickslip.sweep.evaluate_point", "stickslip.rsf.first_lyapunov_coefficient", "stickslip.brake.maps.wave_regime_map"]


@pytest.mark.parametrize("label", SAMPLE)
def test_a_public_function_given_bad_arguments_raises_a_parameter_error_naming_one(label, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    func = public_callables()[label]
    names = required(func)
    for value in (float("nan"), -1.0, "x", None, [], [[1.0], [1.0, 2.0]]):
        try:
            func(**{k: value for k in names})
        except (ParameterError, NoSolutionError) as err:
            assert judge_api(type(err).__name__, getattr(err, "name", None), set(names)) == "clean error", (value, err)
        else:
            raise AssertionError(f"{label} took {value!r} for {names}")


#: Public callables left raising Python's or numpy's exceptions, and why (tests/fuzz_report.py
#: counts them as foreign exceptions): `Mode` is an Enum (``Mode(x)`` is Python's lookup); the
#: others are records the solvers and readers build (`read_solid` a `Solid`), not entry points.
#: (`plotting` and `results.scalars` were here until they could import `errors`: they check their
#: arguments now.)
KNOWN = ("stickslip.oscillator.Mode(",
         "stickslip.oscillator.Trajectory(", "stickslip.brake.waves.ZoneFlows(", "stickslip.fem.BodySystem(",
         "stickslip.system.Flow(", "stickslip.fem.Solid(", "stickslip.fem.SolidSystem(")


@pytest.mark.slow
def test_every_public_function_given_bad_arguments_raises_the_packages_errors():
    """The whole walk of the public modules' ``__all__`` (docs/api), from a fresh interpreter
    (forking this test process, which may hold Dask's threads, can deadlock)."""
    code = ("import json, sys; sys.argv = ['x']; from tests import fuzz_report as f; import random; "
            "bad = []\n"
            "for klass, label, func, kwargs, names, record in f.api_cases(random.Random(0), 0):\n"
            "    outcome, message, name, _ = f.api_trial(func, kwargs, 60)\n"
            "    judged = f.judge_api(outcome, name, names, record, message)\n"
            "    if judged in f.FAILURES: bad.append([label, judged, outcome, message[:200]])\n"
            "print(json.dumps(bad))")
    done = subprocess.run([sys.executable, "-c", code], cwd=pathlib.Path(__file__).resolve().parents[1],
                          capture_output=True, text=True, timeout=3000, env={**os.environ, "PYTHONWARNINGS": "ignore"})
    assert done.returncode == 0, done.stderr[-2000:]
    bad = json.loads(done.stdout.strip().splitlines()[-1])
    assert [b for b in bad if not b[0].startswith(KNOWN)] == []


def _plot_args():
    """Good arguments of every public plotting function, and bad ones with the name each must give."""
    import numpy as np
    import xarray as xr
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    fig, line = Figure(), Line2D([], [], label="a")
    ax = fig.subplots()
    t = np.linspace(0.0, 1.0, 5)
    osc = xr.Dataset({"t": ("t", t), "x": ("t", t), "v": ("t", t), "mode": ("t", np.ones(5, int))})
    branch = xr.Dataset({"parameter_value": ("p", t), "stable": ("p", t > 0.5), "amplitude": ("p", t),
                         "period": ("p", t)})
    regime = xr.Dataset({"regime": (("a", "b"), np.zeros((2, 2)))}, coords={"a": [1.0, 2.0], "b": [1.0, 2.0]})
    waves = xr.Dataset({k: ("i", t) for k in ("x", "zone", "stress_yy", "stress_xy", "u_xx", "slip_velocity",
                                              "material_velocity")})
    nan = float("nan")
    return {
        "new_figure": ({}, [({"fig": ax}, "fig"), ({"ncols": 0}, "ncols"), ({"size": (nan, 1.0)}, "size")]),
        "save": ({"fig": fig, "path": "f.png"}, [({"fig": ax}, "fig"), ({"path": "f.xyz"}, "path"),
                                                ({"path": None}, "path"), ({"dpi": -1.0}, "dpi")]),
        "modal_line": ({"ax": ax, "x": t, "y": t, "mode": t}, [({"ax": fig}, "ax"), ({"x": "x"}, "x"),
                                                               ({"y": t[:2]}, "y"), ({"lw": nan}, "lw")]),
        "oscillator_phase": ({"ax": ax, "ds": osc}, [({"ax": None}, "ax"), ({"ds": {"x": t}}, "ds"),
                                                     ({"ds": osc.drop_vars("v")}, "ds"), ({"title": 3}, "title")]),
        "state_image": ({"ax": ax, "state": np.zeros((2, 3))}, [({"ax": 1.0}, "ax"), ({"state": t}, "state"),
                                                                ({"extent": (0, 1)}, "extent")]),
        "state_legend": ({"ax": ax}, [({"ax": "x"}, "ax")]),
        "zone_legend": ({"ax": ax}, [({"ax": []}, "ax"), ({"kinds": ["stik"]}, "kinds"), ({"marker": 1}, "marker")]),
        "mode_handles": ({}, [({"modes": (2,)}, "modes"), ({"modes": 1.0}, "modes")]),
        "legend_beside": ({"ax": ax, "handles": [line]}, [({"ax": None}, "ax")]),
        "legend_above": ({"ax": ax, "handles": [line]}, [({"ax": None}, "ax"), ({"handles": 3}, "handles")]),
        "wrap": ({"text": "a b"}, [({"text": None}, "text"), ({"width": 0}, "width")]),
        "label_curves": ({"ax": ax, "curves": [(t, t)], "labels": ["a"]},
                         [({"ax": fig}, "ax"), ({"curves": [(t, t[:2])]}, "curves[0]"), ({"curves": 1.0}, "curves"),
                          ({"labels": []}, "labels"), ({"shrink": 0.0}, "shrink")]),
        "plot_cycle": ({"ds": osc}, [({"ds": None}, "ds"), ({"ds": osc.drop_vars("t")}, "ds"), ({"fig": 1}, "fig")]),
        "plot_trajectory": ({"ds": osc}, [({"ds": []}, "ds"), ({"fig": "x"}, "fig")]),
        "plot_branch": ({"ds": branch}, [({"ds": osc}, "ds"), ({"fig": ax}, "fig")]),
        "plot_oscillator_map": ({"ds": regime, "regimes": {0: "steady"}},
                                [({"ds": osc}, "ds"), ({"regimes": {1: "x"}}, "regimes"),
                                 ({"regimes": {"a": "x"}}, "regimes"), ({"fig": 0.0}, "fig")]),
        "plot_interface_fields": ({"ds": waves}, [({"ds": osc}, "ds"), ({"fig": ax}, "fig")]),
        "legibility_problems": ({"fig": fig}, [({"fig": ax}, "fig"), ({"width_in": -1.0}, "width_in")]),
    }


@pytest.mark.parametrize("name", list(_plot_args()))
def test_each_plotting_function_refuses_bad_arguments_naming_them(name, tmp_path, monkeypatch):
    """Each raised AttributeError or TypeError from matplotlib, numpy or xarray (``plot_cycle(None)``:
    'NoneType' object is not subscriptable); now a ParameterError naming the argument as passed."""
    from stickslip import plotting

    monkeypatch.chdir(tmp_path)
    good, bad = _plot_args()[name]
    func = getattr(plotting, name)
    for change, expect in bad:
        with pytest.raises(ParameterError) as err:
            func(**{**good, **change})
        assert err.value.name == expect, (change, str(err.value))
    func(**good)  # the checks let good arguments through
    assert list(tmp_path.iterdir()) == ([tmp_path / "f.png"] if name == "save" else [])


def test_results_scalars_refuses_what_is_not_a_dict():
    from stickslip.results import scalars

    for kwargs, name in [({"data": None}, "data"), ({"data": [1.0]}, "data"), ({"data": {}, "prefix": 1}, "prefix")]:
        with pytest.raises(ParameterError) as err:
            scalars(**kwargs)
        assert err.value.name == name
    assert scalars({"a": {"b": 1.0}, "c": "x"}, "r.") == [("r.a.b", 1.0), ("r.c", "x")]


def test_a_complex_number_where_real_ones_are_taken_is_refused_not_cut_to_its_real_part():
    """numpy turns 1 + 2j into 1.0 with a warning only: the wave's profile at phi = 1 + 2j was computed at
    phi = 1 (found by the API fuzz's ComplexWarning). The validators refuse complex numbers, naming the
    argument."""
    import numpy as np

    from stickslip import validation
    from stickslip.brake import BrakeParams, travelling_wave

    for value in (1 + 2j, [0.5, 1j], np.array([1.0 + 0j])):
        with pytest.raises(ParameterError, match="phi"):
            validation.real_array("phi", value)
        with pytest.raises(ParameterError, match="x"):
            validation.finite_array("x", value)
    wave = travelling_wave(BrakeParams.from_physical(50.0, 1e-4, 0.7), 4)
    with pytest.raises(ParameterError, match="phi"):
        wave.evaluate(1 + 2j)
    assert np.isfinite(wave.evaluate([0.1, 0.2])["P"]).all()

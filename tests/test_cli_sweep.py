"""`stickslip sweep CONFIG.toml` (issue 25): any command over a grid, checked before it runs,
on dask.distributed, resumable."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from stickslip.cli import run

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

OSCILLATOR = """
command = "oscillator cycle"
outputs = ["period", "stick_time", "amplitude"]
[fixed]
mass = 1.0
stiffness = 1.0
normal_force = 2.0
fd = 0.3
[axes]
belt_speed = { start = 0.1, stop = 0.4, num = 4 }
fs = [0.4, 0.5, 0.6]
"""


def _write(folder: Path, text: str, name="sweep.toml") -> Path:
    path = folder / name
    path.write_text(text)
    return path


def _open(store) -> xr.Dataset:
    import warnings

    with warnings.catch_warnings():  # a killed write leaves zarr's temporary file (the resume removes it)
        warnings.filterwarnings("ignore", "Object at .* is not recognized as a component")
        return xr.open_zarr(store, consolidated=False).load()


def test_an_oscillator_sweep_gives_the_closed_form_stick_time(tmp_path, capsys):
    """Coulomb friction, no damping: the stick phase lasts 2 (fs - fd) N / (k V) (the spring
    force sweeps from -(fs - fd) N to +(fs - fd) N relative to its slip value at belt speed V),
    at every point of the grid, each axis where it belongs."""
    config = _write(tmp_path, OSCILLATOR)
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr"), "--scheduler", "synchronous", "--json"]) == 0
    ds = _open(tmp_path / "s.zarr")
    V, fs = np.meshgrid(ds["belt_speed"].values, ds["fs"].values, indexing="ij")
    assert ds["stick_time"].dims == ("belt_speed", "fs") and ds["done"].all()
    np.testing.assert_allclose(ds["stick_time"].values, 2 * (fs - 0.3) * 2.0 / (1.0 * V), rtol=1e-9)
    np.testing.assert_allclose(ds["belt_speed"].values, [0.1, 0.2, 0.3, 0.4])
    assert ds["period"].attrs["units"] == "s" and ds["stick_time"].attrs["units"] == "s"
    out = capsys.readouterr().out
    assert '"grid_points": 12' in out and '"computed_now": 12' in out
    import json

    units = json.loads(out)["units"]  # each output with its meaning in the swept command's model
    assert units["outputs.period"] == {"units": "s", "long_name": "period of the limit cycle"}, units
    assert units["outputs.stick_time"]["long_name"] == "time in stick per period", units


def test_a_fem_sweep_over_the_configs_numbers(tmp_path):
    """`fem steady` on the block over its friction and its pressure (a log range): the friction
    force is f times the normal force (every node slips), the normal force the pressure times
    the 0.1 m top face."""
    for name in ("block.toml", "mesh.py"):
        (tmp_path / name).write_bytes((EXAMPLES / "block_on_belt" / name).read_bytes())
    subprocess.run([sys.executable, "mesh.py", "block.msh", "0.005"], cwd=tmp_path, check=True)
    config = _write(tmp_path, """
command = "fem steady"
config = "block.toml"
outputs = ["normal_force", "friction_force"]
[axes]
friction = { start = 0.1, stop = 0.5, num = 3 }
"load[0].pressure" = { start = 1e5, stop = 1e7, num = 3, scale = "log" }
""")
    assert run(["sweep", str(config), "--out", str(tmp_path / "f.zarr"), "--scheduler", "synchronous"]) == 0
    ds = _open(tmp_path / "f.zarr")
    assert ds["normal_force"].dims == ("contact_friction", "load_0_pressure")
    f, p = np.meshgrid(ds["contact_friction"].values, ds["load_0_pressure"].values, indexing="ij")
    np.testing.assert_allclose(ds["load_0_pressure"].values, [1e5, 1e6, 1e7], rtol=1e-12)
    np.testing.assert_allclose(ds["normal_force"].values, 0.1 * p, rtol=1e-9)
    np.testing.assert_allclose(ds["friction_force"].values, f * ds["normal_force"].values, rtol=1e-9)
    (tmp_path / "block.toml").write_text((tmp_path / "block.toml").read_text() + "\n# a comment changes nothing\n")
    assert run(["sweep", str(config), "--out", str(tmp_path / "f.zarr"), "--scheduler", "synchronous"]) == 0
    subprocess.run([sys.executable, "mesh.py", "block.msh", "0.01"], cwd=tmp_path, check=True)  # another mesh
    assert run(["sweep", str(config), "--out", str(tmp_path / "f.zarr"), "--scheduler", "synchronous"]) == 2


def test_every_problem_of_a_sweep_config_in_one_line(tmp_path, capsys):
    config = _write(tmp_path, """
command = "oscillator cycle"
outputs = ["period", "perod"]
colour = "blue"
[fixed]
mass = 1.0
stiffness = 1.0
normal_force = 1.0
fd = 0.3
wheels = 4
[axes]
belt_speed = [-1.0, 0.2]
fs = { start = 0.0, stop = 0.5, num = 3, scale = "log" }
""")
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr")]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and err.startswith("error: invalid CONFIG")
    for words in ("unknown key colour", "fixed.wheels is not an option of oscillator cycle", "axes.fs: a log range",
                  "'perod' is not a number oscillator cycle prints", "5 problems"):
        assert words in err, (words, err)
    assert not (tmp_path / "s.zarr").exists()
    config.write_text(OSCILLATOR.replace("[0.4, 0.5, 0.6]", "[0.4, 11.0]").replace("start = 0.1", "start = -0.1"))
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr")]) == 2
    err = capsys.readouterr().err
    assert "axes.belt_speed = -0.1" in err and "axes.fs = 11" in err and "--fs" in err
    config.write_text('command = "brake map"\noutputs = ["x"]\n[axes]\nfriction = [0.1]\n')
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr")]) == 2
    assert "command must be one of: " in capsys.readouterr().err


@pytest.fixture
def oscillator_store(tmp_path):
    config = _write(tmp_path, OSCILLATOR)
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr"), "--scheduler", "synchronous"]) == 0
    return config, tmp_path / "s.zarr"


def test_a_store_of_another_sweep_is_refused(oscillator_store, capsys):
    config, store = oscillator_store
    config.write_text(OSCILLATOR.replace("normal_force = 2.0", "normal_force = 3.0"))
    assert run(["sweep", str(config), "--out", str(store), "--scheduler", "synchronous"]) == 2
    assert "a sweep store of the same computation" in capsys.readouterr().err
    assert run(["sweep", str(config), "--out", str(store), "--scheduler", "synchronous", "--overwrite"]) == 0
    assert float(_open(store)["stick_time"][0, 0]) == pytest.approx(2 * 0.1 * 3.0 / 0.1)


def test_failing_points_are_stored_with_their_message_on_a_local_cluster(tmp_path, capsys):
    """fs = fd: no stick phase, no limit cycle at those points; the others are computed, the
    failures logged and stored, and the sweep ends with exit code 1 saying how many."""
    config = _write(tmp_path, OSCILLATOR.replace("[0.4, 0.5, 0.6]", "[0.3, 0.5]"))
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr"), "--workers", "2"]) == 1
    err = capsys.readouterr().err
    assert "Dask dashboard: http://127.0.0.1:" in err and "4 of 8 points failed" in err
    ds = _open(tmp_path / "s.zarr")
    assert ds["done"].values.tolist() == [[0, 1]] * 4
    assert "no finite limit cycle" in ds.attrs["failed"]


@pytest.mark.slow
def test_a_sweep_killed_with_sigkill_resumes_without_recomputing(tmp_path):
    """The whole job killed (the process group, workers included, as a batch system does): the
    rerun starts from the points stored, and ends with every point right."""
    # 300 points, the store polled every 0.1 s: on a loaded machine 90 points finished between two polls
    config = _write(tmp_path, OSCILLATOR.replace("num = 4", "num = 100"))
    store = tmp_path / "s.zarr"
    cmd = [sys.executable, "-m", "stickslip", "sweep", str(config), "--out", str(store), "--workers", "2"]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    stored = 0
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and stored < 10:
            time.sleep(0.1)
            try:
                stored = int(_open(store)["done"].sum())
            except Exception:  # noqa: BLE001 - not written yet
                stored = 0
    finally:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
    assert 10 <= stored < 300, stored
    before = _open(store)
    done = before["done"].values.astype(bool)
    out = subprocess.run(cmd + ["--json"], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    import json

    assert json.loads(out.stdout)["computed_now"] <= 300 - done.sum()  # nothing stored computed again
    after = _open(store)
    assert after["done"].all()
    np.testing.assert_array_equal(after["stick_time"].values[done], before["stick_time"].values[done])
    V, fs = np.meshgrid(after["belt_speed"].values, after["fs"].values, indexing="ij")
    np.testing.assert_allclose(after["stick_time"].values, 2 * (fs - 0.3) * 2.0 / V, rtol=1e-9)


def test_the_configs_of_the_docs_are_valid(tmp_path):
    """The first sweep config of docs/sweeps-on-a-cluster.md is read as written."""
    import re

    from stickslip.cli import app
    from stickslip.cli.study import read_study

    text = (Path(__file__).resolve().parents[1] / "docs" / "sweeps-on-a-cluster.md").read_text()
    first = re.findall(r"```toml\n(.*?)```", text, re.S)[0]
    study = read_study(_write(tmp_path, first), app)
    assert study.points == 4 * 3 * 5 * 8 and list(study.outputs) == ["period", "stick_time", "amplitude"]


def test_an_entry_of_a_list_is_an_output(tmp_path):
    """``modes[0].growth_rate``: the most unstable mode of each CEA (a consistency check with
    the command's own output for the same friction)."""
    import json

    for name in ("block.toml", "mesh.py"):
        (tmp_path / name).write_bytes((EXAMPLES / "block_on_belt" / name).read_bytes())
    subprocess.run([sys.executable, "mesh.py", "block.msh", "0.005"], cwd=tmp_path, check=True)
    config = _write(tmp_path, 'command = "fem cea"\nconfig = "block.toml"\noutputs = ["unstable", '
                    '"modes[0].growth_rate", "modes[1].frequency"]\n[axes]\nfriction = [0.2, 0.6]\n')
    assert run(["sweep", str(config), "--out", str(tmp_path / "c.zarr"), "--scheduler", "synchronous"]) == 0
    ds = _open(tmp_path / "c.zarr")
    out = subprocess.run([sys.executable, "-m", "stickslip", "fem", "cea", str(tmp_path / "block.toml"), "--set",
                          "friction=0.6", "--json"], capture_output=True, text=True, check=True)
    data = json.loads(out.stdout)
    assert float(ds["modes_0_growth_rate"][1]) == pytest.approx(data["modes"][0]["growth_rate"], rel=1e-9)
    assert float(ds["modes_1_frequency"][1]) == pytest.approx(data["modes"][1]["frequency"], rel=1e-9)
    assert int(ds["unstable"][1]) == data["unstable"] and ds["modes_0_growth_rate"].attrs["units"] == "1/s"


def test_review_cases_a_flag_a_bool_dotted_keys_and_a_scheduler_that_is_not_there(tmp_path, capsys):
    """A bool for a number (it was dropped: the default computed instead), a number for a
    flag, and an address where no scheduler answers: refused before any store is made; an
    unquoted dotted key is read as the key it writes."""
    config = _write(tmp_path, 'command = "halfspace direct"\noutputs = ["c"]\n[fixed]\nnu = false\nv = 3.514e-3\n'
                    'v_star = 0.001\n[axes]\nT = [9.52e-4]\njson = [1.0]\n')
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr")]) == 2
    err = capsys.readouterr().err
    assert "fixed.nu = False: a number, not true or false" in err and "axes.json is not an option" in err
    config.write_text('command = "halfspace direct"\noutputs = ["c"]\n[fixed]\nv = 3.514e-3\nv_star = 0.001\n'
                      '[axes]\nT = [9.52e-4]\n')
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr"), "--scheduler", "tcp://127.0.0.1:9"]) == 2
    assert "none answered" in capsys.readouterr().err and not (tmp_path / "s.zarr").exists()
    from stickslip.cli import app
    from stickslip.cli.study import read_study

    for name in ("block.toml", "mesh.py"):
        (tmp_path / name).write_bytes((EXAMPLES / "block_on_belt" / name).read_bytes())
    subprocess.run([sys.executable, "mesh.py", "block.msh", "0.01"], cwd=tmp_path, check=True)
    study = read_study(_write(tmp_path, 'command = "fem steady"\nconfig = "block.toml"\noutputs = ["normal_force"]\n'
                              '[axes]\ncontact.friction = [0.2, 0.4]\n', "dotted.toml"), app)
    assert study.keys == {"contact_friction": "config:contact.friction"}


def test_a_failing_point_on_the_local_pool_is_stored_and_the_others_computed(tmp_path, capsys):
    """With --scheduler synchronous too (not only on a cluster), one point without a limit cycle
    does not stop the sweep; changing the mesh file of a fem config is another sweep."""
    config = _write(tmp_path, OSCILLATOR.replace("[0.4, 0.5, 0.6]", "[0.3, 0.5]"))
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr"), "--scheduler", "synchronous"]) == 1
    err = capsys.readouterr().err
    assert "4 of 8 points failed" in err and "(belt_speed = 0.1, fs = 0.3) failed" in err
    assert _open(tmp_path / "s.zarr")["done"].values.tolist() == [[0, 1]] * 4


def test_the_fem_cea_sweep_takes_a_scheduler(tmp_path, capsys):
    """`fem cea --sweep` on the block with --scheduler (synchronous here: the local cluster is
    tested with run_sweep); an address where nothing answers is refused in one line."""
    import json

    for name in ("block.toml", "mesh.py"):
        (tmp_path / name).write_bytes((EXAMPLES / "block_on_belt" / name).read_bytes())
    subprocess.run([sys.executable, "mesh.py", "block.msh", "0.01"], cwd=tmp_path, check=True)
    base = ["fem", "cea", str(tmp_path / "block.toml"), "--sweep", "friction=0.2:0.6:3", "--json"]
    assert run(base + ["--store", str(tmp_path / "c.zarr"), "--scheduler", "synchronous"]) == 0
    assert json.loads(capsys.readouterr().out)["sweep_points"] == 3
    assert run(base + ["--store", str(tmp_path / "d.zarr"), "--scheduler", "tcp://127.0.0.1:9"]) == 2
    assert "--scheduler" in capsys.readouterr().err


def test_the_oscillator_map_gives_what_a_sweep_of_the_cycle_command_gives(oscillator_store, tmp_path):
    """A ready-made study and the generic sweep over the same grid: at every stick-slip point of
    the map, the cycle's period, stick time and amplitude are those of `oscillator cycle`."""
    _, store = oscillator_store
    assert run(["oscillator", "map", "--out", str(tmp_path / "m.zarr"), "--mass", "1", "--stiffness", "1",
                "--normal-force", "2", "--fd", "0.3", "--x", "belt_speed=0.1:0.4:4", "--y", "fs=0.4:0.6:3",
                "--scheduler", "synchronous"]) == 0
    preset, generic = _open(tmp_path / "m.zarr"), _open(store)
    sticks = np.isin(preset["regime"].values, (1, 2))
    assert sticks.sum() >= 6 and preset["regime"].dims == generic["period"].dims
    for name in ("period", "stick_time", "amplitude"):
        np.testing.assert_allclose(preset[name].values[sticks], generic[name].values[sticks], rtol=1e-12)
        assert preset[name].attrs["units"] == generic[name].attrs["units"]


def test_two_swept_config_numbers_that_break_their_rule_together_are_refused_before_any_point(tmp_path, capsys):
    """static_friction >= friction at every point of the grid: [0.2, 0.5] x [0.6, 0.3] breaks it only at
    (0.5, 0.3), which the config's check (one axis varied at a time, the others at their first: (0.2, 0.6),
    (0.5, 0.6), (0.2, 0.3)) does not see; the sweep ran and stored the point as failed."""
    (tmp_path / "block.toml").write_bytes((EXAMPLES / "block_on_belt" / "block.toml").read_bytes())
    (tmp_path / "block.msh").write_text("not a mesh: its problem is said with the grid's\n")
    config = _write(tmp_path, """
command = "fem steady"
config = "block.toml"
outputs = ["friction_force"]
[axes]
friction = [0.2, 0.5]
static_friction = [0.6, 0.3]
""")
    assert run(["sweep", str(config), "--out", str(tmp_path / "s.zarr"), "--scheduler", "synchronous"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err, err
    assert "axes.contact.static_friction = 0.3 with axes.contact.friction = 0.5" in err, err
    assert "1 of 4 combinations" in err and "block.msh" in err and "2 problems" in err, err
    assert not (tmp_path / "s.zarr").exists()

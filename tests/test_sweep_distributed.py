"""Sweeps on dask.distributed (issue 25): a real scheduler and worker processes on loopback.

* A local cluster of two processes computes every point, each stored as it finishes; a point
  that raises is left not done with its message in the store (``failed``) and does not stop
  the sweep, which ends by saying how many failed (`NoSolutionError`); a second run computes
  only what is not done (each point's calls are counted in files the point function writes);
  a point computed later no longer counts as failed.
* Interrupted mid-sweep (the progress callback raising, as Ctrl-C would), the store keeps what
  had finished, and the resume computes nothing already stored.
* A worker killed (SIGKILL) while it computes a point loses that point: the scheduler gives
  it to another worker and every point ends done; the killed point ran twice, every other point
  at most twice (a result the dead worker had finished but not yet handed over is computed
  again: the sweep fetches results as they finish, which makes that window short, not empty).
* An existing scheduler by its address; an address where none answers is refused, named.
"""

import os
import signal
import time
from pathlib import Path

import numpy as np
import pytest

from stickslip import cluster
from stickslip.errors import NoSolutionError, ParameterError
from stickslip.sweep import run_sweep

AXES = {"a": [0.0, 1.0, 2.0, 3.0], "b": [0.0, 1.0, 2.0]}

#: distributed leaves sockets of its schedulers to the garbage collector (ResourceWarning), which
#: pytest reports as unraisable exceptions; they are collected here, after each test of this module
pytestmark = pytest.mark.filterwarnings("ignore::ResourceWarning",
                                        "ignore::pytest.PytestUnraisableExceptionWarning")


@pytest.fixture(autouse=True)
def _collect_sockets():
    yield
    import gc
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        gc.collect()


def point(a, b, marks, slow=-1.0, bad=-1.0):
    """``y = 10 a + b``; a file per call in ``marks`` (named by the point and the worker's pid)."""
    Path(marks, f"{a:g}_{b:g}_{os.getpid()}_{time.monotonic_ns()}").write_text(str(os.getpid()))
    if a == bad and b == 1.0:
        raise ValueError("a bad point")
    time.sleep(3.0 if a == slow and b == 1.0 else 0.02)
    return {"y": 10 * a + b}


def _calls(marks: Path) -> dict:
    out = {}
    for f in marks.iterdir():
        a, b = f.name.split("_")[:2]
        out[(float(a), float(b))] = out.get((float(a), float(b)), 0) + 1
    return out


def _point(marks, **options):
    import functools

    return functools.partial(point, marks=str(marks), **options)


def test_a_local_cluster_streams_the_points_and_stores_a_failure_without_stopping(tmp_path):
    marks = tmp_path / "marks"
    marks.mkdir()
    seen = []
    with pytest.raises(NoSolutionError) as err:
        run_sweep(_point(marks, bad=2.0), AXES, tmp_path / "s.zarr", outputs={"y": "1"}, scheduler="distributed",
                  workers=2, batch=4, progress=lambda done, total: seen.append(done))
    assert "1 of 12 points failed" in str(err.value) and "ValueError: a bad point" in str(err.value)
    import xarray as xr

    ds = xr.open_zarr(tmp_path / "s.zarr", consolidated=False).load()
    a, b = np.meshgrid(AXES["a"], AXES["b"], indexing="ij")
    done = ds["done"].values.astype(bool)
    assert done.sum() == 11 and not done[2, 1]
    assert np.array_equal(ds["y"].values[done], (10 * a + b)[done]) and np.isnan(ds["y"].values[2, 1])
    assert '"2,1": "ValueError: a bad point"' in ds.attrs["failed"]
    assert seen[-1] == 11 and len(seen) >= 3  # stored in several goes, not at the end
    assert len({p.read_text() for p in marks.iterdir()}) == 2  # two worker processes
    before = _calls(marks)
    with pytest.raises(NoSolutionError):
        run_sweep(_point(marks, bad=2.0), AXES, tmp_path / "s.zarr", outputs={"y": "1"}, scheduler="distributed",
                  workers=2)
    after = _calls(marks)
    assert {k: after[k] - before.get(k, 0) for k in after if after[k] != before.get(k, 0)} == {(2.0, 1.0): 1}
    ds = run_sweep(_point(marks), AXES, tmp_path / "s.zarr", outputs={"y": "1"}, scheduler="synchronous")
    assert ds["done"].values.all() and ds.attrs["failed"] == "{}"  # computed at last: no longer failed


def test_an_interrupted_sweep_keeps_what_finished_and_resumes_computing_nothing_twice(tmp_path):
    marks = tmp_path / "marks"
    marks.mkdir()

    def stop(done, total):
        if done > 0:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_sweep(_point(marks), AXES, tmp_path / "s.zarr", outputs={"y": "1"}, scheduler="distributed", workers=2,
                  batch=2, progress=stop)
    first = _calls(marks)
    ds = run_sweep(_point(marks), AXES, tmp_path / "s.zarr", outputs={"y": "1"}, scheduler="synchronous")
    assert ds["done"].values.all()
    again = {k: n - first.get(k, 0) for k, n in _calls(marks).items()}
    import xarray as xr

    stored = [k for k in again if again[k] == 0]
    assert stored and all(v in (0, 1) for v in again.values())  # stored points not computed again
    del xr


@pytest.mark.slow  # a cluster started and a worker killed (5 s)
def test_a_worker_killed_mid_point_loses_only_that_point(tmp_path):
    marks = tmp_path / "marks"
    marks.mkdir()
    killed = []

    def kill(done, total):  # once the slow point has started, kill the worker computing it
        for f in marks.iterdir():
            if f.name.startswith("1_1_") and not killed:
                pid = int(f.read_text())
                os.kill(pid, signal.SIGKILL)
                killed.append(pid)

    ds = run_sweep(_point(marks, slow=1.0), AXES, tmp_path / "s.zarr", outputs={"y": "1"}, scheduler="distributed",
                   workers=2, batch=1, progress=kill)
    assert killed and ds["done"].values.all() and ds.attrs["failed"] == "{}"
    calls = _calls(marks)
    assert calls[(1.0, 1.0)] == 2 and all(n in (1, 2) for n in calls.values())
    assert sum(calls.values()) <= len(calls) + 2


def test_an_existing_scheduler_by_address_and_one_that_does_not_answer(tmp_path, monkeypatch):
    from distributed import LocalCluster

    marks = tmp_path / "marks"
    marks.mkdir()
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=":0") as local:
        ds = run_sweep(_point(marks), {"a": [0.0, 1.0], "b": [2.0]}, tmp_path / "s.zarr", outputs={"y": "1"},
                       scheduler=local.scheduler_address)
        assert np.array_equal(ds["y"].values.ravel(), [2.0, 12.0])
    monkeypatch.setattr(cluster, "CONNECT_SECONDS", 1.0)
    with pytest.raises(ParameterError) as err:
        run_sweep(_point(marks), {"a": [0.0]}, tmp_path / "t.zarr", outputs={"y": "1"}, scheduler="tcp://127.0.0.1:9")
    assert err.value.name == "scheduler" and "running Dask scheduler" in str(err.value)


def test_the_map_commands_take_a_scheduler(tmp_path, capsys):
    """`oscillator map --scheduler distributed` stores the same map as the local pool (and a store
    of one resumes with the other: where the points ran is not part of the results); a scheduler
    that is neither is refused in one line."""
    import json

    from stickslip.cli import run

    args = ["oscillator", "map", "--mass", "1", "--stiffness", "1", "--normal-force", "1", "--fs", "0.6", "--fd",
            "0.4", "--x", "belt_speed=0.1:1.2:3", "--y", "damping=0.01:0.5:2", "--json"]
    counts = []
    for name, extra in (("a", ["--scheduler", "distributed", "--workers", "2"]), ("b", ["--workers", "1"])):
        assert run(args + ["--out", str(tmp_path / f"{name}.zarr")] + extra) == 0
        counts.append(json.loads(capsys.readouterr().out)["counts"])
    assert counts[0] == counts[1] and sum(counts[0].values()) == 6
    assert run(args + ["--out", str(tmp_path / "a.zarr"), "--workers", "1"]) == 0  # resumed: nothing to compute
    capsys.readouterr()
    assert run(args + ["--out", str(tmp_path / "c.zarr"), "--scheduler", "mpi"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--scheduler = 'mpi'" in err and "tcp://HOST:PORT" in err

"""`integrate`: checkpoint and resume, result format, scaling similarity, bad input."""

import numpy as np
import pytest
import xarray as xr

from stickslip.brake import BrakeParams
from stickslip.brake.ring.integrate import InitialCondition, RingRun, integrate, perturbed_steady, transit_time
from stickslip.errors import ParameterError

CASE2 = BrakeParams.from_physical(50.0, 1e-4, 0.7)  # f = 0.7, delta = 0.001, Omega = 50 rad/s


class Stop(Exception):
    pass


def _same(a: RingRun, b: RingRun, parts=("series", "snapshots", "kernel")):
    for part in parts:
        da, db = getattr(a, part), getattr(b, part)
        assert da.keys() == db.keys()
        for key in da:
            assert np.array_equal(da[key], db[key]), (part, key)


def test_interrupted_run_resumes_bitwise_from_its_checkpoint(tmp_path):
    path = tmp_path / "ring.nc"
    kwargs = dict(transits=30, checkpoint=path, every=5 * transit_time(CASE2))
    reference = integrate(CASE2, 64, transits=30)
    seen = []

    def stop_half_way(t, t_end):
        seen.append(t)
        if t > 0.55 * t_end:
            raise Stop

    with pytest.raises(Stop):
        integrate(CASE2, 64, progress=stop_half_way, **kwargs)
    saved = RingRun.from_xarray(xr.load_dataset(path))
    assert not saved.complete and saved.samples_done == len(seen)  # saved at interruption: nothing lost
    resumed = integrate(CASE2, 64, progress=lambda t, te: seen.append(t), **kwargs)
    assert resumed.complete and np.all(np.diff(seen) > 0) and seen[-1] >= reference.t[-1]
    _same(resumed, reference)
    again = integrate(CASE2, 64, **kwargs)  # already complete: read back, nothing recomputed
    _same(again, reference)


def test_a_checkpoint_can_be_extended(tmp_path):
    path = tmp_path / "ring.nc"
    integrate(CASE2, 32, transits=10, checkpoint=path)
    longer = integrate(CASE2, 32, transits=20, checkpoint=path)
    direct = integrate(CASE2, 32, transits=20)
    _same(longer, direct, parts=("series", "kernel"))


def test_a_checkpoint_of_another_run_is_refused(tmp_path):
    path = tmp_path / "ring.nc"
    integrate(CASE2, 32, transits=2, checkpoint=path)
    for kwargs in (dict(beta2=0.9), dict(initial=perturbed_steady(CASE2, 32, seed=1))):
        with pytest.raises(ParameterError) as err:
            integrate(CASE2, 32, transits=2, checkpoint=path, **kwargs)
        assert err.value.name == "checkpoint"
    with pytest.raises(ParameterError):
        integrate(CASE2.replace(friction=0.5), 32, transits=2, checkpoint=path)


def test_result_dataset_has_units_and_round_trips(tmp_path):
    run = integrate(CASE2, 32, transits=6, snapshot_every=2.0, tail=1.0)
    ds = run.to_xarray()
    assert ds["U"].dims == ("snapshot", "node") and ds["fraction"].dims == ("sample", "kind")
    assert ds["t"].attrs["units"] == "1/Omega" and ds["P"].attrs["units"] == "E / M"
    assert list(ds["kind"].values) == ["stick", "slip", "reverse_slip", "separation"]
    assert ds.attrs["physical_omega"] == 50.0 and ds.attrs["complete"] == 1
    assert np.allclose(ds["fraction"].sum("kind"), 1.0)
    # snapshots: every 2 transits and densely in the last one
    tail = run.settings["tail_samples"]
    assert tail + 2 <= ds.sizes["snapshot"] <= tail + 3
    assert np.all(np.diff(ds["snap_t"].values[-tail:]) == pytest.approx(run.settings["chunk"] * run.scheme.dt))
    path = tmp_path / "run.nc"
    ds.to_netcdf(path)
    back = RingRun.from_xarray(xr.load_dataset(path))
    _same(back, run)
    assert back.params == run.params and back.params.omega == 50.0


def test_time_scaling_similarity():
    """Only ``kappa = delta / sqrt(gamma)`` matters (with xi, nu, f): doubling Omega and the
    mismatch gives the same run in transits, with the same energies and velocities."""
    p1, p2 = CASE2, BrakeParams.from_physical(100.0, 2e-4, 0.7)
    r1, r2 = (integrate(p, 64, transits=40, initial=perturbed_steady(p, 64, 0.3, mode=3)) for p in (p1, p2))
    assert r2.scheme.dt == pytest.approx(2 * r1.scheme.dt, rel=1e-12)  # time unit 1/Omega
    assert r1.fractions[:, 0].max() > 0.05  # stick-slip reached
    assert np.array_equal(r1.fractions, r2.fractions)
    assert r2.energy == pytest.approx(r1.energy, rel=1e-6)
    assert r2.Vd == pytest.approx(r1.Vd, rel=1e-6, abs=1e-9)


@pytest.mark.parametrize("kwargs, name", [
    (dict(), "t_end"), (dict(t_end=1.0, transits=1.0), "t_end"), (dict(t_end=-1.0), "t_end"),
    (dict(transits=0.0), "transits"), (dict(transits=1, samples_per_transit=2), "samples_per_transit"),
    (dict(transits=1, initial="noise"), "initial"), (dict(transits=1, nodes=4), "nodes"),
    (dict(transits=1, beta2=0.3), "beta2"), (dict(transits=1, every=0.0), "every"),
    (dict(transits=1, tail=-1.0), "tail")])
def test_integrate_rejects_bad_input(kwargs, name):
    with pytest.raises(ParameterError) as err:
        integrate(CASE2, **(dict(nodes=32) | kwargs))
    assert err.value.name == name


def test_initial_conditions():
    ini = perturbed_steady(CASE2, 32, amplitude=0.5, mode=4, noise=0.0)
    c = CASE2.coefficients()
    V_e = CASE2.delta * CASE2.friction * c.g / c.h
    assert ini.V == pytest.approx(V_e + 0.5 * CASE2.delta * np.cos(4 * 2 * np.pi * np.arange(32) / 32))
    assert np.all(ini.U == CASE2.delta) and np.all(ini.Ud == 0) and "mode 4" in ini.label
    with pytest.raises(ParameterError) as err:
        perturbed_steady(CASE2, 32, mode=17)
    assert err.value.name == "mode"
    with pytest.raises(ParameterError) as err:
        InitialCondition(np.zeros(8), np.zeros(7), np.zeros(8), np.zeros(8))
    assert err.value.name == "V"
    with pytest.raises(ParameterError) as err:
        integrate(CASE2, 16, transits=1, initial=perturbed_steady(CASE2, 32))
    assert err.value.name == "initial"

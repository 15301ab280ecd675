"""`integrate_fem`: checkpoint and resume, result format, the kappa similarity, classification, bad input."""

import numpy as np
import pytest
import xarray as xr

from stickslip.brake import BrakeParams
from stickslip.brake.fem import FemInitial, FemRun, FemScheme, classify_fem, integrate_fem, perturbed_steady
from stickslip.errors import ParameterError

from .helpers import case

CASE2 = case(1)
MESH = dict(n_theta=32, n_r=2)


class Stop(Exception):
    pass


def _same(a: FemRun, b: FemRun, parts=("series", "snapshots", "kernel")):
    for part in parts:
        da, db = getattr(a, part), getattr(b, part)
        assert da.keys() == db.keys()
        for key in da:
            assert np.array_equal(da[key], db[key]), (part, key)


def test_interrupted_run_resumes_bitwise_from_its_checkpoint(tmp_path):
    path = tmp_path / "fem.nc"
    T = FemScheme(CASE2, **MESH).transit_time
    kwargs = dict(transits=30, checkpoint=path, every=5 * T, **MESH)
    reference = integrate_fem(CASE2, transits=30, **MESH)
    seen = []

    def stop_half_way(t, t_end):
        seen.append(t)
        if t > 0.55 * t_end:
            raise Stop

    with pytest.raises(Stop):
        integrate_fem(CASE2, progress=stop_half_way, **kwargs)
    saved = FemRun.from_xarray(xr.load_dataset(path))
    assert not saved.complete and saved.samples_done == len(seen)  # saved at interruption: nothing lost
    resumed = integrate_fem(CASE2, progress=lambda t, te: seen.append(t), **kwargs)
    assert resumed.complete and np.all(np.diff(seen) > 0) and seen[-1] >= reference.t[-1]
    _same(resumed, reference)
    _same(integrate_fem(CASE2, **kwargs), reference)  # complete: read back, nothing recomputed


def test_a_checkpoint_can_be_extended_and_another_run_is_refused(tmp_path):
    path = tmp_path / "fem.nc"
    integrate_fem(CASE2, transits=10, checkpoint=path, **MESH)
    _same(integrate_fem(CASE2, transits=20, checkpoint=path, **MESH), integrate_fem(CASE2, transits=20, **MESH),
          parts=("series", "kernel"))
    s = FemScheme(CASE2, **MESH)
    for kwargs in (dict(beta2=0.5), dict(initial=perturbed_steady(s, seed=1)), dict(n_r=3, n_theta=32)):
        with pytest.raises(ParameterError) as err:
            integrate_fem(CASE2, transits=2, checkpoint=path, **(MESH | kwargs))
        assert err.value.name == "checkpoint"
    with pytest.raises(ParameterError):
        integrate_fem(CASE2.replace(friction=0.5), transits=2, checkpoint=path, **MESH)


def test_result_dataset_has_units_and_round_trips(tmp_path):
    run = integrate_fem(CASE2, transits=6, snapshot_every=2.0, tail=1.0, **MESH)
    ds = run.to_xarray()
    assert ds["U"].dims == ("snapshot", "node") and ds["fraction"].dims == ("sample", "kind")
    assert ds["t"].attrs["units"] == "1/Omega" and ds["P"].attrs["units"] == "E"
    assert ds.attrs["physical_omega"] == 50.0 and ds.attrs["complete"] == 1 and ds.attrs["n_r"] == 2
    assert np.allclose(ds["fraction"].sum("kind"), 1.0)
    tail = run.settings["tail_samples"]
    assert tail + 2 <= ds.sizes["snapshot"] <= tail + 3
    path = tmp_path / "run.nc"
    ds.to_netcdf(path)
    back = FemRun.from_xarray(xr.load_dataset(path))
    _same(back, run)
    assert back.params == run.params and back.params.omega == 50.0


def test_only_kappa_matters():
    """The FE problem depends on ``xi, nu, f`` and ``kappa = delta / sqrt(gamma)`` only: doubling
    Omega and d gives the same run in transits (displacements and energies scale, velocities not)."""
    p1, p2 = CASE2, BrakeParams.from_physical(100.0, 2e-4, 0.7)
    runs = [integrate_fem(p, 64, 4, transits=30, initial=perturbed_steady(FemScheme(p, 64, 4), 0.3, mode=3))
            for p in (p1, p2)]
    r1, r2 = runs
    assert r2.scheme.dt == pytest.approx(2 * r1.scheme.dt, rel=1e-12)
    assert r1.fractions[:, 0].max() > 0.05  # stick reached
    assert np.array_equal(r1.fractions, r2.fractions)
    assert r2.energy == pytest.approx(4 * r1.energy, rel=1e-6)
    assert r2.Vd == pytest.approx(r1.Vd, rel=1e-6, abs=1e-9)
    assert r2.P == pytest.approx(2 * r1.P, rel=1e-6, abs=1e-12)


def test_classification_of_a_saturated_run():
    run = integrate_fem(CASE2, 64, 4, transits=60)
    res = classify_fem(run)
    assert res.regime.startswith("stick-slip") and res.n_zones >= 1 and res.n_fft_P >= 1
    assert res.fractions["stick"] > 0.1 and res.c_over_cp < 0  # against the shaft
    assert res.p_mean_over_pe == pytest.approx(1.0, abs=0.05) and res.p_max_over_pe > 1.2
    assert res.to_xarray()["fraction"].sum() == pytest.approx(1.0) and run.to_dict()["complete"]
    d = res.to_dict()
    assert d["regime"] == res.regime and isinstance(d["n_zones"], int) and d["transits"] == pytest.approx(60, abs=0.1)
    with pytest.raises(ParameterError):
        classify_fem(integrate_fem(CASE2, transits=2, contact=False, **MESH))
    with pytest.raises(ParameterError):
        classify_fem("run")


@pytest.mark.parametrize("kwargs, name", [
    (dict(), "t_end"), (dict(t_end=1.0, transits=1.0), "t_end"), (dict(t_end=-1.0), "t_end"),
    (dict(transits=0.0), "transits"), (dict(transits=1, samples_per_transit=2), "samples_per_transit"),
    (dict(transits=1, initial="noise"), "initial"), (dict(transits=1, n_theta=20), "n_theta"),
    (dict(transits=1, n_r=0), "n_r"), (dict(transits=1, beta2=0.3), "beta2"), (dict(transits=1, courant=1.5), "courant"),
    (dict(transits=1, every=0.0), "every"), (dict(transits=1, tail=-1.0), "tail"),
    (dict(transits=1, progress=3), "progress"), (dict(transits=1, modes=0), "modes")])
def test_integrate_rejects_bad_input(kwargs, name):
    with pytest.raises(ParameterError) as err:
        integrate_fem(CASE2, **(MESH | kwargs))
    assert err.value.name == name


def test_initial_conditions():
    s = FemScheme(CASE2, **MESH)
    ini = perturbed_steady(s, amplitude=0.5, mode=4)
    dv = s.system.hoop(ini.u - s.steady.u)
    X = (2.25 / s.system.mesh.radii[:-1] - s.system.mesh.radii[:-1]) / 1.25
    assert dv == pytest.approx(0.5 * CASE2.delta * X[:, None] * np.cos(4 * s.theta), abs=1e-15)
    assert np.all(s.system.radial(ini.u) == s.system.radial(s.steady.u)) and "mode 4" in ini.label
    for kwargs, name in ((dict(mode=17), "mode"), (dict(amplitude=-1.0), "amplitude"), (dict(noise=-1), "noise")):
        with pytest.raises(ParameterError) as err:
            perturbed_steady(s, **kwargs)
        assert err.value.name == name
    with pytest.raises(ParameterError):
        FemInitial(np.zeros(8), np.zeros(7))
    with pytest.raises(ParameterError):
        perturbed_steady("scheme")

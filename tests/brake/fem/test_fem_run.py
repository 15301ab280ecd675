"""`integrate_fem`: the kappa similarity, classification, initial conditions, its own options.

The run books it shares with the ring are tested in tests/contact/test_runs.py."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams
from stickslip.brake.fem import FemInitial, FemScheme, classify_fem, integrate_fem, perturbed_steady
from stickslip.errors import ParameterError

from .helpers import case

CASE2 = case(1)
MESH = dict(n_theta=32, n_r=2)


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


@pytest.mark.parametrize("kwargs, name", [(dict(transits=1, n_theta=20), "n_theta"), (dict(transits=1, n_r=0), "n_r")])
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

"""`integrate` (the ring): the kappa similarity, its initial conditions, its own options.

The run books it shares with the FE model are tested in tests/contact/test_runs.py."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams
from stickslip.brake.ring.integrate import InitialCondition, integrate, perturbed_steady
from stickslip.errors import ParameterError

CASE2 = BrakeParams.from_physical(50.0, 1e-4, 0.7)  # f = 0.7, delta = 0.001, Omega = 50 rad/s


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


@pytest.mark.parametrize("kwargs, name", [(dict(transits=1, nodes=4), "nodes"), (dict(transits=1, nodes=9.5), "nodes")])
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


@pytest.mark.parametrize("params", [BrakeParams.from_physical(50.0, 1e-4, 0.7),
                                    BrakeParams(xi=3.0, nu=0.45, gamma=0.1, delta=0.01, friction=0.3)])
def test_a_transit_is_once_round_the_ring_at_the_p_wave_speed_of_the_dispersion_relation(params):
    """`transit_time`: 2 pi (the ring's length in units of R) over the speed of the faster wave
    of the free problem, omega(k)/k of its upper branch at large k (continuous symbols: the
    relative error is O(1/k^2), below 1e-8 at k = 1e5)."""
    from stickslip.brake.ring import RingScheme, transit_time
    k = 1e5
    speed = RingScheme(params, 64).frequencies(np.array([k]), discrete=False)[0, 1] / k
    assert transit_time(params) == pytest.approx(2 * np.pi / speed, rel=1e-8)

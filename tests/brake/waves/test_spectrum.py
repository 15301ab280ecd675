"""The stability of a travelling wave on the discrete ring (`wave_spectrum`, `relative_cycle`).

Checked against what the spectrum code does not compute: the continuous wave of the
multiple-shooting solver (the discrete wave's speed tends to it at second order in the node
spacing), central differences of whole runs of the ring (the multipliers of the node-shift map),
and the ring's own equations written here (the system's accelerations and normal forces).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from stickslip.brake import BrakeParams, travelling_wave
from stickslip.brake.waves import Scaling, ring_system, wave_spectra, wave_spectrum
from stickslip.errors import ParameterError
from stickslip.system import Flow, cell_symmetry, monodromy, relative_cycle, simulate

from ...system.test_floquet import return_map_moduli

#: Figure 5's wave at Omega = 100 rad/s: stick and slip, four waves around the ring.
PARAMS = BrakeParams.from_physical(100.0, 1e-4, 0.2)


@pytest.fixture(scope="module")
def wave():
    return travelling_wave(PARAMS, 4)


def test_the_ring_system_is_the_discretised_reduced_model():
    """Accelerations and normal forces of every node sliding, against [12] written here with
    centred differences (U = delta): V'' = a V_thth - h V + f P, P = g delta - D V_th."""
    N = 16
    system = ring_system(PARAMS, N)
    sc = Scaling(PARAMS)
    co = sc.coefficients
    rng = np.random.default_rng(1)
    V, dV = rng.normal(size=N), 0.1 * rng.normal(size=N)  # slip speeds 1 - dV > 0: every node slips forward
    dth = 2 * math.pi / N
    P = co.g * sc.delta - co.D * (np.roll(V, -1) - np.roll(V, 1)) / (2 * dth)
    expected = co.a * (np.roll(V, -1) - 2 * V + np.roll(V, 1)) / dth**2 - co.h * V + PARAMS.friction * P
    flow = Flow(system, tuple([1] * N))
    z = np.concatenate([V, dV, [1.0]])
    np.testing.assert_allclose(flow.acceleration(z), expected, rtol=1e-12, atol=1e-12 * np.abs(expected).max())
    normals = np.array([c.normal_row(N) @ z for c in system.contacts])
    np.testing.assert_allclose(normals, P, rtol=1e-12)


def test_the_discrete_wave_speed_tends_to_the_continuous_one_at_second_order(wave):
    """The time to move one node against dtheta/|c| of the multiple-shooting wave: the error
    falls at an observed order in [1.8, 2.2] (centred differences) and is below 1 % at 64 nodes."""
    ds = wave_spectra(wave, (32, 64))
    assert float(ds["speed_error"].sel(nodes=64)) < 1e-2
    assert 1.8 <= float(ds["observed_order"].sel(nodes=64)) <= 2.2


def _ring_wave(wave, N):
    """The ring of ``N`` nodes, its wave moving by one node (from the sampled shooting wave) and
    the node shift."""
    system = ring_system(PARAMS, N)
    r, c = Scaling(PARAMS).root_gamma, float(wave.x[0])
    prof = wave.evaluate(2 * math.pi * (np.arange(N) + 0.5) / N)
    shift = (np.arange(N) + (1 if c > 0 else -1)) % N
    cycle = relative_cycle(system, prof["V"] / r, -c * prof["dV"] / r, shift, contact=0, state=0,
                           horizon=2 * math.pi / wave.n / abs(c))
    return system, cycle, shift


def test_the_multipliers_are_those_of_the_node_shift_map_by_differences(wave):
    """The multipliers (monodromy over one node's time with the saltation matrices of every
    switch, simultaneous ones included, mapped back by the shift) against central differences
    of the map from one stick onset to the next node's: the largest ten moduli to 1e-6."""
    system, cycle, shift = _ring_wave(wave, 32)
    free = list(range(32)) + [32 + i for i, s in enumerate(cycle.states) if s != 0]  # free on the section
    fd = return_map_moduli(system, cycle, free, period=cycle.shift_time, back=np.concatenate([shift, 32 + shift]),
                           target=int(cell_symmetry(system, shift)[cycle.contact]))[::-1]
    ours = np.abs(cycle.multipliers)
    ours = np.delete(ours, np.argmin(np.abs(cycle.multipliers - 1.0)))
    np.testing.assert_allclose(ours[:10], fd[:10], atol=1e-6)
    assert not cycle.stable  # a perturbation grows: the leading pair is outside the unit circle


def test_a_wave_period_has_the_multipliers_of_the_node_shift_map_to_the_power_of_its_nodes(wave):
    """Over a whole wave period (N/n node shifts, every switch of the four waves happening at
    once at four nodes) the monodromy's multipliers are mu^(N/n) of the node-shift map's (in
    modulus): the simultaneous switches' saltations are all applied."""
    N, n = 32, 4
    sp = wave_spectrum(wave, N)
    system, cycle, _ = _ring_wave(wave, N)
    run = simulate(system, cycle.x0, cycle.v0, (N // n) * cycle.shift_time, samples=2, segments=True,
                   states=cycle.states)
    period_moduli = np.sort(np.abs(np.linalg.eigvals(monodromy(system, run))))[::-1]
    expected = np.sort(np.abs(sp.multipliers) ** (N // n))[::-1]
    np.testing.assert_allclose(period_moduli[:12], expected[:12], atol=1e-6)


def test_a_symmetry_the_system_does_not_have_is_refused():
    system = ring_system(PARAMS, 16)
    with pytest.raises(ParameterError, match="shift = .*permutation"):
        cell_symmetry(system, [0] * 16)
    assert list(cell_symmetry(system, (np.arange(16) + 1) % 16)) == list((np.arange(16) + 1) % 16)
    swap = np.arange(16)
    swap[[0, 5]] = [5, 0]
    with pytest.raises(ParameterError, match="shift = .*symmetry of the system"):
        cell_symmetry(system, swap)


def test_waves_the_ring_cannot_follow_are_refused(wave):
    with pytest.raises(ParameterError, match="nodes = 30.*multiple of the mode number n = 4"):
        wave_spectrum(wave, 30)
    with pytest.raises(ParameterError, match="nodes = 2048"):
        wave_spectrum(wave, 2048)
    sep = travelling_wave(BrakeParams.from_physical(100.0, 1e-5, 0.2), 8, regime="stick-slip-separation-reverse-slip")
    with pytest.raises(ParameterError, match="wave = .*permanent contact"):
        wave_spectrum(sep, 64)


def test_steady_sliding_of_the_ring_is_the_discrete_flutter_of_the_paper():
    """Steady sliding of the ring system (every node slipping): its eigenvalues against the
    roots of s^2 = -a (4/dth^2) sin^2(k dth/2) - h - i f D sin(k dth)/dth for each wave number k
    (the constraint's reaction loads the contacts and does not act on V)."""
    from stickslip.system import steady_sliding

    N = 16
    co, f = Scaling(PARAMS).coefficients, PARAMS.friction
    dth = 2 * math.pi / N
    k = np.arange(N)
    s2 = -co.a * 4 / dth**2 * np.sin(k * dth / 2) ** 2 - co.h - 1j * f * co.D * np.sin(k * dth) / dth
    roots = np.concatenate([np.sqrt(s2), -np.sqrt(s2)])
    eig = steady_sliding(ring_system(PARAMS, N)).eigenvalues
    assert eig.size == roots.size
    for r in roots:
        assert np.min(np.abs(eig - r)) < 1e-9 * np.abs(roots).max()
    assert eig.real.max() > 0  # steady sliding flutters, as the paper says

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
from stickslip.brake.waves import Scaling, ring_system, sampled_ring, wave_spectra, wave_spectrum
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
    for bad in (0, 2.5, 10**7):
        with pytest.raises(ParameterError, match=f"max_iter = {bad}"):
            wave_spectrum(wave, 64, max_iter=bad)
    with pytest.raises(ParameterError, match="separation = 'yes'"):
        ring_system(PARAMS, 16, separation="yes")
    from stickslip.brake.waves import moreau_difference
    for call, name in ((lambda: sampled_ring(None, 64), "wave = None"), (lambda: sampled_ring(wave, 0), "nodes = 0"),
                       (lambda: sampled_ring(wave, 30), "nodes = 30"),
                       (lambda: moreau_difference(wave, 30), "nodes = 30"),
                       (lambda: moreau_difference("w", 64), "wave = 'w'")):
        with pytest.raises(ParameterError, match=name):
            call()


def test_the_moreau_comparison_refuses_what_it_cannot_run(separating):
    from stickslip.brake.waves import moreau_difference
    for kwargs, name in (({"steps": (0,)}, "steps"), ({"steps": (10.5,)}, "steps"), ({"steps": "10"}, "steps"),
                         ({"fraction": -0.5}, "fraction"), ({"fraction": 0.0}, "fraction"),
                         ({"fraction": math.inf}, "fraction"), ({"fraction": True}, "fraction")):
        with pytest.raises(ParameterError, match=f"invalid {name} ="):
            moreau_difference(separating, 64, **kwargs)


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


# ---- waves that leave the shaft: the ring whose nodes may leave it too --------------------------------------------

#: Figure 11's branch (f = 0.7, Omega = 50 rad/s, four waves) at d = 1.2 um: stick, slip and separation.
SEPARATING = BrakeParams.from_physical(50.0, 1.2e-6, 0.7)


@pytest.fixture(scope="module")
def separating():
    from stickslip.brake import continue_waves
    branch = continue_waves(BrakeParams.from_physical(50.0, 1e-5, 0.7), 4, "delta", 1.2e-6 / 0.1, num=12,
                            spacing="log")
    wave = branch.waves[-1]
    assert wave.structure == "stick|slip|separation" and wave.params.delta == pytest.approx(1.2e-5)
    return wave


def test_the_separating_ring_is_the_discretised_reduced_model():
    """Accelerations and contact forces of the ring whose nodes may leave the shaft, against [12]
    written here (U = delta + u): nodes 0-5 open (no force), the others slipping forwards on the
    shaft, whose reaction P keeps them there: u'' = b u_thth + D V_th - g (u + delta) + P = 0,
    V'' = a V_thth - D u_th - h V + f P."""
    N = 16
    system = ring_system(PARAMS, N, separation=True)
    sc = Scaling(PARAMS)
    co = sc.coefficients
    rng = np.random.default_rng(2)
    u = np.where(np.arange(N) < 6, np.abs(rng.normal(size=N)) * sc.delta, 0.0)
    V, du, dV = rng.normal(size=N), np.where(np.arange(N) < 6, rng.normal(size=N), 0.0), 0.1 * rng.normal(size=N)
    dth = 2 * math.pi / N
    lap = lambda w: (np.roll(w, -1) - 2 * w + np.roll(w, 1)) / dth**2  # noqa: E731
    grad = lambda w: (np.roll(w, -1) - np.roll(w, 1)) / (2 * dth)  # noqa: E731
    free_u = co.b * lap(u) + co.D * grad(V) - co.g * (u + sc.delta)
    P = np.where(np.arange(N) < 6, 0.0, -free_u)
    expected = np.concatenate([np.where(np.arange(N) < 6, free_u, 0.0),
                               co.a * lap(V) - co.D * grad(u) - co.h * V + PARAMS.friction * P])
    flow = Flow(system, tuple([2] * 6 + [1] * (N - 6)))
    z = np.concatenate([u, V, du, dV, [1.0]])
    np.testing.assert_allclose(flow.acceleration(z), expected, rtol=1e-12, atol=1e-12 * np.abs(expected).max())
    np.testing.assert_allclose(flow.normal_rows @ z, P, rtol=1e-12, atol=1e-12 * np.abs(P).max())


def test_in_permanent_contact_the_separating_ring_has_the_eliminated_rings_spectrum(wave):
    """Consistency of two formulations of ours (the normal motion eliminated, U = delta, or held by
    rigid constraints): the same wave speed and multipliers for a wave that never separates."""
    N = 32
    sp = wave_spectrum(wave, N)
    system = ring_system(PARAMS, N, separation=True)
    r, c = Scaling(PARAMS).root_gamma, float(wave.x[0])
    prof = wave.evaluate(2 * math.pi * (np.arange(N) + 0.5) / N)
    shift = (np.arange(N) + (1 if c > 0 else -1)) % N
    cycle = relative_cycle(system, np.concatenate([np.zeros(N), prof["V"] / r]),
                           np.concatenate([np.zeros(N), -c * prof["dV"] / r]), np.concatenate([shift, N + shift]),
                           contact=0, state=0, horizon=2 * math.pi / wave.n / abs(c))
    assert cycle.shift_time == pytest.approx(sp.shift_time, rel=1e-10)
    # the normal displacements and velocities of nodes that never leave the shaft are off the constraints:
    # multipliers 1 (an offset that stays) of the constrained ring only; the others are the same
    full, elim = (m[(np.abs(m) > 1e-6) & (np.abs(np.abs(m) - 1.0) > 1e-6)] for m in (cycle.multipliers, sp.multipliers))
    np.testing.assert_allclose(np.abs(full[:12]), np.abs(elim[:12]), rtol=1e-8)
    assert np.sum(np.abs(np.abs(cycle.multipliers) - 1.0) < 1e-6) == 2 * N + 1


def test_a_separating_wave_has_a_discrete_wave_whose_multipliers_are_those_of_its_runs(separating):
    """On 64 nodes: the discrete wave leaves the shaft, moves one node in about dtheta/|c| (1 %),
    has the multiplier 1 of its own motion, and its node-shift monodromy (saltation matrices at
    lift-offs, plastic landings with their friction impulses, stick and slip) against central
    differences of whole runs along random directions that keep the contacts' constraints."""
    N = 64
    sp = wave_spectrum(separating, N)
    assert sp.separation and abs(sp.shift_time / sp.continuous_shift_time - 1.0) < 1e-2
    assert np.min(np.abs(sp.multipliers - 1.0)) < 1e-8
    system = ring_system(separating.params, N, separation=True)
    c = float(separating.x[0])
    x0, v0, off = sampled_ring(separating, N)
    assert off.any() and x0.size == 2 * N and np.all(x0[:N][~off] == 0.0)
    shift = (np.arange(N) + (1 if c > 0 else -1)) % N
    cycle = relative_cycle(system, x0, v0, np.concatenate([shift, N + shift]), contact=0, state=2,
                           horizon=2 * math.pi / separating.n / abs(c))
    assert np.any(cycle.event_state == 2) and np.any(cycle.event_state == 0)
    T = 2.5 * cycle.shift_time  # between events
    run = simulate(system, cycle.x0, cycle.v0, T, samples=2, segments=True, states=cycle.states)
    Phi = monodromy(system, run)
    n = system.dofs
    free = np.ones(2 * n, dtype=bool)  # on a closed contact u = u' = 0; a sticking one V' = 1; a node at its
    for j, s in enumerate(cycle.states):  # lift-off keeps u = u' = 0 (its gap cannot shrink)
        if s != 2 or cycle.x0[j] < 1e-9:
            free[[j, n + j]] = False
        if s == 0:
            free[n + N + j] = False
    rng = np.random.default_rng(3)
    z0 = np.concatenate([cycle.x0, cycle.v0])
    for _ in range(2):
        d = np.where(free, rng.normal(size=2 * n), 0.0) * 1e-8 * np.abs(z0).max()
        ends = [simulate(system, cycle.x0 + s * d[:n], cycle.v0 + s * d[n:], T, samples=2, states=cycle.states)
                for s in (1, -1)]
        fd = (np.concatenate([ends[0].x[-1], ends[0].v[-1]]) - np.concatenate([ends[1].x[-1], ends[1].v[-1]])) / 2
        assert np.abs(Phi @ d - fd).max() < 1e-6 * np.abs(fd).max()


def test_the_separating_ring_moves_as_the_independent_moreau_stepper_converges(separating):
    """The event-driven ring (lift-offs, plastic landings with friction impulses, stick and slip at
    every node) against `step_ring`, the Moreau stepper of `wave_persistence` (written apart: an
    impulse per step keeps U >= delta, Coulomb's impulse sticks or slides): over half a wave period
    on 64 nodes from the sampled wave, the difference falls at first order in the Moreau step."""
    from stickslip.brake.waves import moreau_difference
    errors = moreau_difference(separating, 64, (4000, 8000, 16000))
    ratios = errors[:-1] / errors[1:]
    assert errors[-1] < 1e-3 and np.all((ratios > 1.5) & (ratios < 2.7)), (errors, ratios)
    with pytest.raises(ParameterError, match="separates from the shaft"):
        moreau_difference(travelling_wave(PARAMS, 4), 64)

"""Monodromy matrices with saltation matrices, against finite differences of runs that have
each kind of switch; limit cycles against the 1-DOF oscillator and against the finite-
difference Jacobian of their own return map."""

import numpy as np
import pytest

from stickslip.friction import Coulomb
from stickslip.oscillator import Oscillator, limit_cycle as oscillator_cycle
from stickslip.system import limit_cycle, monodromy, simulate

from .test_simulate import one_dof, two_blocks


def end_state(run):
    return np.concatenate([run.x[-1], run.v[-1]])


def finite_differences(system, z0, t_end, eps=1e-6):
    n = system.dofs
    out = np.zeros((2 * n, 2 * n))
    for c in range(2 * n):
        d = np.zeros(2 * n)
        d[c] = eps
        plus = simulate(system, (z0 + d)[:n], (z0 + d)[n:], t_end, samples=2)
        minus = simulate(system, (z0 - d)[:n], (z0 - d)[n:], t_end, samples=2)
        out[:, c] = (end_state(plus) - end_state(minus)) / (2 * eps)
    return out


def return_map_moduli(system, cycle, free, eps=1e-6, *, period=None, target=None, back=None):
    """The moduli (sorted) of the eigenvalues of the cycle's return map to its section (its
    contact entering its state), differentiated by central differences in the coordinates
    ``free`` of the state (those that stay free on the section). For a wave moving by one cell:
    the return is contact ``target``'s, the state there mapped back by ``z[back]``, within a
    few ``period`` (the cell's time)."""
    n, z0 = system.dofs, np.concatenate([cycle.x0, cycle.v0])
    period = cycle.period if period is None else period
    target = cycle.contact if target is None else target
    back = np.arange(2 * n) if back is None else back

    def return_map(z):
        run = simulate(system, z[:n], z[n:], 3 * period, samples=2, segments=True, states=cycle.states)
        for seg, nxt in zip(run.segments, run.segments[1:]):
            if seg.after[target] == cycle.state != seg.states[target]:
                return nxt.z[:2 * n][back]
        raise AssertionError("no return")

    J = np.zeros((len(free), len(free)))
    for j, c in enumerate(free):
        d = np.zeros(2 * n)
        d[c] = eps
        J[:, j] = (return_map(z0 + d)[free] - return_map(z0 - d)[free]) / (2 * eps)
    return np.sort(np.abs(np.linalg.eigvals(J)))


def _switches(run) -> set:
    kinds = set()
    for seg in run.segments:
        for a, b in zip(seg.states, seg.after):
            if a != b:
                kinds.add("stick onset" if b == 0 else "release" if a == 0 else "reversal")
    return kinds


@pytest.mark.parametrize("case, kinds", [("stick and release", {"stick onset", "release"}),
                                         ("reversals", {"reversal"})])
def test_the_monodromy_is_the_derivative_of_the_run(case, kinds):
    """The product of the pieces' exponentials and the saltation matrices against central
    differences of whole runs (step 1e-6: their error about 1e-10)."""
    if case == "reversals":  # f_s = f_d, started far from equilibrium: every zero of a slip velocity reverses it
        system, z0, t_end = two_blocks(fs=0.4, fd=0.4), np.array([3.0, -2.0, 0.0, 0.0]), 6.0
    else:  # from a moment when both blocks slip, over a stick phase of each
        system = two_blocks()
        warm = simulate(system, [0.0, 0.0], [0.0, 0.0], 6.31, samples=2)
        z0, t_end = end_state(warm), 8.0
        assert np.all(warm.states[-1] != 0)
    run = simulate(system, z0[:2], z0[2:], t_end, samples=2, segments=True)
    assert _switches(run) == kinds
    M = monodromy(system, run)
    FD = finite_differences(system, z0, t_end)
    assert np.abs(M - FD).max() < 1e-6 * max(1.0, np.abs(M).max())
    assert np.abs(M - np.eye(4)).max() > 0.1  # not a trivial product


@pytest.mark.parametrize("c", [0.0, 0.05])
def test_the_cycle_of_one_contact_is_the_oscillators(c):
    osc = Oscillator(1.0, 1.0, 2.0, 0.2, Coulomb(0.5, 0.3), damping=c)
    ref = oscillator_cycle(osc)
    cycle = limit_cycle(one_dof(c=c), [0.0], [0.0], transient=40.0)
    assert cycle.period == pytest.approx(ref.period, rel=1e-10)
    ours = np.sort(np.abs(cycle.multipliers))
    theirs = np.sort(np.abs(np.asarray(ref.floquet_multipliers, dtype=complex)))
    np.testing.assert_allclose(ours, theirs, atol=1e-9)


def test_a_two_contact_cycle_closes_and_its_multipliers_are_those_of_its_return_map():
    """The cycle of the 2-block chain: it returns to its start after one period; one multiplier
    is the flow's own 1; the others are the eigenvalues of the return map to the section
    (contact 1 sticking), differentiated by finite differences on the section."""
    system = two_blocks()
    cycle = limit_cycle(system, [0.0, 0.0], [0.0, 0.0], transient=60.0)
    again = simulate(system, cycle.x0, cycle.v0, cycle.period, samples=2)
    np.testing.assert_allclose(end_state(again), np.concatenate([cycle.x0, cycle.v0]), atol=1e-8)
    assert np.min(np.abs(cycle.multipliers - 1.0)) < 1e-8
    # the section: contact 1 sticking (v_1 = V_1 = 0.1); its coordinates x_1, x_2, v_1 of block 1
    assert (cycle.contact, cycle.state) == (1, 0)
    poincare = return_map_moduli(system, cycle, [0, 1, 2])
    others = np.delete(cycle.multipliers, np.argmin(np.abs(cycle.multipliers - 1.0)))
    np.testing.assert_allclose(np.sort(np.abs(others)), poincare, atol=1e-6)
    assert cycle.stable == (poincare.max() < 1)


@pytest.mark.parametrize("scale", [1e-8, 1e4])
def test_a_cycle_scaled_by_its_forces_and_speeds_is_the_scaled_cycle(scale):
    # normal forces and belt speeds times s: displacements and velocities times s, the same period and
    # multipliers (homogeneity of Coulomb friction). Convergence is relative to the orbit's size: a
    # cycle 1e-8 times smaller is found as accurately as the reference (it was 5e-4 off with an absolute tol)
    from stickslip.system import Contact, System
    ref = limit_cycle(two_blocks())
    base = two_blocks()
    small = System(base.mass, base.stiffness, [Contact(c.direction, c.normal_force * scale, c.friction,
                                                       c.surface_speed * scale) for c in base.contacts],
                   damping=base.damping)
    cycle = limit_cycle(small)
    assert cycle.period == pytest.approx(ref.period, rel=1e-9)
    assert np.abs(cycle.x0 / scale - ref.x0).max() <= 1e-8 * np.abs(ref.x0).max()
    assert np.abs(cycle.v0 / scale - ref.v0).max() <= 1e-8 * np.abs(ref.v0).max()
    assert np.abs(np.abs(cycle.multipliers[:3]) - np.abs(ref.multipliers[:3])).max() < 1e-8


def test_the_saltation_matrix_maps_the_field_before_onto_the_field_after_and_keeps_the_surface():
    """The defining properties of ``S = I + (f+ - f-) n^T / (n . f-)`` (the saltation matrix of a transversal crossing):
    ``S f- = f+`` (a start moved along the flow before the crossing arrives moved along the flow after
    it), and ``S t = t`` for every ``t`` in the switching surface (``n . t = 0``): the first fails for
    the transpose, the second for a wrong denominator. Random fields, a random normal."""
    from stickslip.system.floquet import saltation
    rng = np.random.default_rng(7)
    for _ in range(5):
        f_minus, f_plus, normal = rng.normal(size=(3, 6))
        S = saltation(f_minus, f_plus, normal)
        np.testing.assert_allclose(S @ f_minus, f_plus, rtol=1e-12, atol=1e-12)
        tangent = rng.normal(size=6)
        tangent -= normal * (normal @ tangent) / (normal @ normal)
        np.testing.assert_allclose(S @ tangent, tangent, rtol=1e-12, atol=1e-12)

"""Unilateral contact and Coulomb friction at every node and every step, and the discrete
energy balance (the work of the reactions), in a run where all four node states occur."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams
from stickslip.brake.ring import InitialCondition, RingScheme, integrate, perturbed_steady
from stickslip.contact import SEPARATION, SLIP_NEG, SLIP_POS, STICK

from .test_scheme import start

# coefficients of order 1; delta / sqrt(gamma) = 0.03 is small enough for separation
PARAMS = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.03, friction=0.7)


@pytest.fixture(scope="module")
def run():
    ini = perturbed_steady(PARAMS, 64, amplitude=1.0, mode=3, noise=0.1)
    out = integrate(PARAMS, 64, transits=20, initial=ini, samples_per_transit=128, snapshot_every=1 / 128)
    assert out.settings["chunk"] == 1 and out.state.shape[0] == out.energy.size  # every step recorded
    return out


def test_all_four_states_occur(run):
    counts = np.bincount(run.state.ravel(), minlength=4) / run.state.size
    assert np.all(counts > 0.01), counts


def test_contact_conditions_at_every_node_and_step(run):
    """``P >= 0``, ``U >= delta`` and ``P (U - delta) = 0`` at the constrained time ``t_{m+1}``."""
    delta = PARAMS.delta
    P, U_next, state = run.P[:-1], run.U[1:], run.state[:-1]
    assert P.min() >= 0.0
    assert U_next.min() >= delta * (1 - 1e-14)
    assert np.all(U_next[P > 0] == delta)  # complementarity, exactly
    assert np.all((P == 0) == (state == SEPARATION))
    assert np.all(run.Q[run.state == SEPARATION] == 0.0)


def test_coulomb_law_at_every_node_and_step(run):
    """``|Q| <= f P``; stick: ``V_dot = 1``; slip: ``Q = f P sign(1 - V_dot)`` ([12], [17]-[19])."""
    f, P, Q, slip, state = PARAMS.friction, run.P, run.Q, 1.0 - run.Vd, run.state
    fP = f * P
    assert np.all(np.abs(Q) <= fP * (1 + 1e-12))
    stick = state == STICK
    assert np.abs(slip[stick]).max() < 1e-9
    for code, sign in ((SLIP_POS, 1.0), (SLIP_NEG, -1.0)):
        sel = state == code
        assert Q[sel] == pytest.approx(sign * fP[sel], rel=1e-12)
        assert np.all(sign * slip[sel] > -1e-9)
    # Q (1 - V_dot) - f P |1 - V_dot| = 0 wherever there is contact
    contact = state != SEPARATION
    residual = Q[contact] * slip[contact] - fP[contact] * np.abs(slip[contact])
    assert np.abs(residual).max() < 1e-9 * fP.max()


def test_discrete_energy_balance_is_the_work_of_the_reactions(run):
    """Central differences: ``E_{m+1/2} - E_{m-1/2} = dtheta sum (r_m - r_e) . (u_{m+1} - u_{m-1})/2``
    for the energy of the deviation from steady sliding (``r_e`` its reactions)."""
    s = run.scheme
    c = s.coefficients
    Pe, Qe = c.g * PARAMS.delta, PARAMS.friction * c.g * PARAMS.delta
    du_U = s.dt * (run.Ud[1:] + run.Ud[:-1])  # u_{m+1} - u_{m-1}
    du_V = s.dt * (run.Vd[1:] + run.Vd[:-1])
    work = 0.5 * s.dtheta * np.sum((run.P[1:] - Pe) * du_U + (run.Q[1:] - Qe) * du_V, axis=1)
    dE = np.diff(run.energy)
    scale = np.abs(run.energy).max()
    assert np.abs(dE - work).max() < 1e-10 * scale
    assert np.abs(dE).max() > 1e-4 * scale  # the energy does change: friction works


def test_contact_off_means_no_reactions():
    ini = perturbed_steady(PARAMS, 32, amplitude=5.0, mode=2)
    out = integrate(PARAMS, 32, transits=3, initial=ini, contact=False, samples_per_transit=8)
    assert np.all(out.P == 0) and np.all(out.Q == 0) and out.U.min() < PARAMS.delta  # penetrates freely


def test_convergence_in_dt_is_first_order_through_stick_and_separation_events():
    """Non-smooth regime (stick, slip, reverse slip and separation all occur before ``t = 3``):
    the self-convergence of ``V`` at a fixed time is first order in ``dt`` (the switching
    events are located to within a step), against second order in the smooth linear regime
    (`test_ring_scheme.test_observed_order_in_time`)."""
    N, t_end = 64, 3.0
    theta = 2 * np.pi * np.arange(N) / N
    c = PARAMS.coefficients()
    V = PARAMS.delta * (PARAMS.friction * c.g / c.h + 10 * np.cos(3 * theta) + 3 * np.sin(5 * theta))
    ini = InitialCondition(np.full(N, PARAMS.delta), V, np.zeros(N), np.zeros(N))
    finals, seen = [], np.zeros(4)
    for M in (1000, 2000, 4000, 8000):
        scheme = RingScheme(PARAMS, N, 0.5, t_end / (M * RingScheme(PARAMS, N, 0.5, 1.0).dt_max))
        k = start(scheme, ini, True)
        for _ in range(10):
            seen += np.bincount(scheme.advance(k, M // 10).state, minlength=4)
        finals.append(scheme.fields(k.u)[1].copy())
    assert np.all(seen > 0)
    e = [np.abs(finals[i] - finals[i + 1]).max() for i in range(3)]
    orders = np.log2(np.array(e[:-1]) / e[1:])
    assert e[0] > e[1] > e[2] and 0.8 < orders.mean() < 1.5, orders

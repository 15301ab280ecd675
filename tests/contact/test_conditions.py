"""Unilateral contact and Coulomb friction at every contact node and step, and the discrete
energy balance (the work of the reactions), for both models of the shared explicit scheme,
in runs where all four node states occur."""

import numpy as np
import pytest

from stickslip.contact import SEPARATION, SLIP_NEG, SLIP_POS, STICK

from .models import MODELS, ORDER_ONE


def _every_step(model, beta2=0.5, transits=20):
    s = model.scheme(ORDER_ONE, beta2=beta2)
    spt = int(np.ceil(s.steps_per_transit))
    run = model.run(ORDER_ONE, transits, initial=model.perturbed(s, amplitude=1.0, mode=3, noise=0.1), beta2=beta2,
                    samples_per_transit=spt, snapshot_every=1.0 / spt)
    assert run.settings["chunk"] == 1 and run.state.shape[0] == run.energy.size  # every step recorded
    return run


@pytest.fixture(scope="module", params=[(m, b) for m in MODELS for b in (0.5, 0.9)],
                ids=lambda p: f"{p[0].name}-beta2={p[1]}")
def run(request):
    return _every_step(*request.param)


@pytest.mark.parametrize("model", MODELS, ids=lambda m: m.name)
def test_all_four_states_occur_with_central_differences(model):
    run = _every_step(model)
    counts = np.bincount(run.state.ravel(), minlength=4) / run.state.size
    assert np.all(counts > 0.01), counts


def test_contact_conditions_at_every_node_and_step(run):
    """``P >= 0``, ``U >= delta`` and ``P (U - delta) = 0`` at the constrained time ``t_{m+1}``."""
    delta = ORDER_ONE.delta
    P, U_next, state = run.P[:-1], run.U[1:], run.state[:-1]
    assert P.min() >= 0.0
    assert U_next.min() >= delta * (1 - 1e-14)
    assert np.all(U_next[P > 0] == delta)  # complementarity, exactly
    assert np.all((P == 0) == (state == SEPARATION)) and np.all(run.Q[run.state == SEPARATION] == 0.0)
    assert run.gap.min() >= 0.0 and np.all(run.P * run.gap == 0.0) and np.array_equal(run.gap[:-1], U_next - delta)


def test_coulomb_law_at_every_node_and_step(run):
    """``|Q| <= f P``; stick: ``V_dot = 1``; slip: ``Q = f P sign(1 - V_dot)`` ([17]-[19])."""
    f, P, Q, slip, state = ORDER_ONE.friction, run.P, run.Q, 1.0 - run.Vd, run.state
    fP = f * P
    assert np.all(np.abs(Q) <= fP * (1 + 1e-12))
    stick = state == STICK
    if stick.any():
        assert np.abs(slip[stick]).max() < 1e-9
    for code, sign in ((SLIP_POS, 1.0), (SLIP_NEG, -1.0)):
        sel = state == code
        assert Q[sel] == pytest.approx(sign * fP[sel], rel=1e-12)
        assert np.all(sign * slip[sel] > -1e-9)
    contact = state != SEPARATION  # Q (1 - V_dot) - f P |1 - V_dot| = 0 wherever there is contact
    residual = Q[contact] * slip[contact] - fP[contact] * np.abs(slip[contact])
    assert np.abs(residual).max() < 1e-9 * fP.max()


@pytest.mark.parametrize("model", MODELS, ids=lambda m: m.name)
def test_discrete_energy_balance_is_the_work_of_the_reactions(model):
    """Central differences: ``E_{m+1/2} - E_{m-1/2} = (r_m - r_e) . M (u_{m+1} - u_{m-1}) / 2`` for the
    energy of the deviation from steady sliding (``r_e`` its reactions per unit mass)."""
    run = _every_step(model)
    s = run.scheme
    normal, _ = s.contact_dofs
    weight = np.broadcast_to(s.mass, s.sparse_operator.shape[:1])[normal] / run.FORMAT.traction_scale(s)
    _, r_n, r_t = s.steady_reference()
    scale = run.FORMAT.traction_scale(s)
    dE = np.diff(run.energy)[:-1]  # E_{m+1/2} - E_{m-1/2} for m = 1 .. M-2
    work = np.sum(weight * ((run.P[1:-1] - scale * r_n) * (run.U[2:] - run.U[:-2]) / 2
                            + (run.Q[1:-1] - scale * r_t) * (run.V[2:] - run.V[:-2]) / 2), axis=1)
    assert np.abs(dE - work).max() < 1e-10 * np.abs(run.energy).max()
    assert np.abs(work).max() > 1e-3 * np.abs(run.energy).max()  # the reactions do work

"""Unilateral contact and Coulomb friction at every contact node and step, and the discrete
energy: conserved by central differences without contact, decaying at the rate of the
amplification matrix with beta2 > 1/2, and changed by exactly the work of the reactions."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams
from stickslip.brake.fem import FemInitial, FemScheme, fourier_block, integrate_fem, perturbed_steady
from stickslip.contact import SEPARATION, SLIP_NEG, SLIP_POS, STICK
from stickslip.contact import amplification_matrix

# order-one coefficients; kappa = delta / sqrt(gamma) = 0.03 is small enough for separation
PARAMS = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.03, friction=0.7)
MESH = (32, 2)


def _every_step(beta2, transits=20):
    s = FemScheme(PARAMS, *MESH, beta2)
    ini = perturbed_steady(s, amplitude=1.0, mode=3, noise=0.1)
    spt = int(np.ceil(s.steps_per_transit))
    run = integrate_fem(PARAMS, *MESH, transits=transits, initial=ini, beta2=beta2, samples_per_transit=spt,
                        snapshot_every=1.0 / spt)
    assert run.settings["chunk"] == 1 and run.state.shape[0] == run.energy.size  # every step recorded
    return run


@pytest.fixture(scope="module", params=[0.5, 0.9])
def run(request):
    return _every_step(request.param)


def test_all_four_states_occur_with_central_differences():
    counts = np.bincount(_every_step(0.5).state.ravel(), minlength=4) / (611 * 32)
    assert np.all(counts > 0.01), counts


def test_contact_conditions_at_every_node_and_step(run):
    """``lambda_n >= 0``, gap ``u_r - delta >= 0``, ``lambda_n (u_r - delta) = 0`` at ``t_{m+1}``."""
    delta = PARAMS.delta
    P, U_next, state = run.P[:-1], run.U[1:], run.state[:-1]
    assert P.min() >= 0.0
    assert U_next.min() >= delta * (1 - 1e-14)
    assert np.all(U_next[P > 0] == delta)  # complementarity, exactly
    assert np.all((P == 0) == (state == SEPARATION)) and np.all(run.Q[run.state == SEPARATION] == 0.0)
    assert run.gap.min() >= 0.0 and np.all(run.P * run.gap == 0.0) and np.array_equal(run.gap[:-1], U_next - delta)


def test_coulomb_law_at_every_node_and_step(run):
    """``|q| <= f p``; stick: the node moves with the shaft (``w = 1``); slip: ``q = f p sign(1 - w)``."""
    f, P, Q, slip, state = PARAMS.friction, run.P, run.Q, 1.0 - run.Vd, run.state
    fP = f * P
    assert np.all(np.abs(Q) <= fP * (1 + 1e-12))
    stick = state == STICK
    assert stick.any() == (run.scheme.beta2 == 0.5)
    if stick.any():
        assert np.abs(slip[stick]).max() < 1e-9
    for code, sign in ((SLIP_POS, 1.0), (SLIP_NEG, -1.0)):
        sel = state == code
        assert Q[sel] == pytest.approx(sign * fP[sel], rel=1e-12)
        assert np.all(sign * slip[sel] > -1e-9)
    contact = state != SEPARATION
    residual = Q[contact] * slip[contact] - fP[contact] * np.abs(slip[contact])
    assert np.abs(residual).max() < 1e-9 * fP.max()


def test_discrete_energy_balance_is_the_work_of_the_reactions():
    """Central differences: ``E_{m+1/2} - E_{m-1/2} = (lambda_m - lambda_e) . (u_{m+1} - u_{m-1}) / 2``
    (energy of the deviation from FE steady sliding, ``lambda_e`` its reactions)."""
    run = _every_step(0.5)
    h, st = run.scheme.system.mesh.h_theta, run.scheme.steady
    dE = np.diff(run.energy)[:-1]  # E_{m+1/2} - E_{m-1/2} for m = 1 .. M-2
    work = h * np.sum((run.P[1:-1] - st.pressure) * (run.U[2:] - run.U[:-2]) / 2
                      + (run.Q[1:-1] - st.reaction_t / h) * (run.V[2:] - run.V[:-2]) / 2, axis=1)
    assert np.abs(dE - work).max() < 1e-10 * np.abs(run.energy).max()
    assert np.abs(work).max() > 1e-3 * np.abs(run.energy).max()  # the reactions do work


def test_free_problem_conserves_the_scheme_energy():
    """No contact, central differences: ``w^T M w/2 + u_m^T K u_{m+1}/2`` constant to round-off."""
    s = FemScheme(PARAMS, *MESH, 0.5)
    rng = np.random.default_rng(3)
    ini = FemInitial(rng.standard_normal(s.system.n_free), np.zeros(s.system.n_free), "noise")
    run = integrate_fem(PARAMS, *MESH, transits=20, initial=ini, beta2=0.5, contact=False, samples_per_transit=8)
    E = run.energy
    assert E.min() > 0 and np.abs(E / E[0] - 1).max() < 1e-12


@pytest.mark.parametrize("beta2", [0.6, 0.9])
def test_free_mode_decays_at_the_rate_of_the_amplification_matrix(beta2):
    """A free eigenmode (n = 3, lowest branch): energy ratio after M steps = ``|z|^{2M}`` (in log,
    to 1 %: the scheme energy of a damped scheme also oscillates within a period)."""
    s = FemScheme(PARAMS, *MESH, beta2)
    N, n_r = MESH
    m = s.system.mass[:: 2 * N].repeat(2)
    w2, vec = np.linalg.eigh(fourier_block(s.system, 3) / np.sqrt(np.outer(m, m)))
    shape = (vec[:, 0] / np.sqrt(m)).reshape(n_r, 2)
    field = np.real(shape[:, :, None] * np.exp(3j * s.theta))  # (n_r, comp, theta)
    ini = FemInitial(s.system.from_fields(field[:, 0], field[:, 1]), np.zeros(s.system.n_free), "mode 3")
    run = integrate_fem(PARAMS, *MESH, transits=5, initial=ini, beta2=beta2, contact=False, samples_per_transit=8)
    z = np.abs(np.linalg.eigvals(amplification_matrix(w2[0] / PARAMS.gamma * s.dt**2, beta2))).max()
    steps = (run.t[-1] - run.t[0]) / s.dt
    assert np.log(run.energy[-1] / run.energy[0]) == pytest.approx(2 * steps * np.log(z), rel=0.01)
    assert run.energy[-1] < 0.9 * run.energy[0]

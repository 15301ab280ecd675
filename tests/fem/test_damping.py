"""Rayleigh damping in the explicit scheme: a cantilever released in its first mode decays at
the rate ``(alpha + beta omega^2) / 2`` of a proportionally damped mode, and the step the
scheme takes with damping is stable for the most damped (highest) mode.

Thresholds, set before the runs: the rate within 3e-2 at Courant 0.9 (the damping acts on the
velocity of the previous step: first order in ``omega dt``, about 0.02 here) and the error at
least 1.5 times smaller at Courant 0.45."""

import numpy as np
import pytest
import scipy.linalg as la
from scipy.optimize import curve_fit

from stickslip.contact import amplification_matrix
from stickslip.fem import Material, RigidFlat, assemble, body_from_meshio, contact_frames
from stickslip.fem.scheme import BodyScheme, ContactProblem

from .meshes import rectangle

E, NU, RHO = 2.1e11, 0.3, 7850.0


#: the quadratic beam (its highest mode sets a step four times shorter) in the slow set
@pytest.fixture(scope="module", params=[pytest.param(1, id="quad"), pytest.param(2, id="quad9", marks=pytest.mark.slow)])
def beam(request, tmp_path_factory):
    mesh = rectangle(tmp_path_factory.mktemp("c") / "c.msh", 0.04, 0.004, 0.002, quads=True, order=request.param)
    body = body_from_meshio(mesh, "beam")
    undamped = assemble(body, Material(E, NU, RHO))
    free = np.setdiff1d(np.arange(undamped.n_dofs), undamped.dofs(body.nodes("left")))
    K, m = undamped.K.toarray()[np.ix_(free, free)], undamped.mass[free]
    lam, vec = la.eigh(K, np.diag(m), subset_by_index=[0, 0])
    shape = np.zeros(undamped.n_dofs)
    shape[free] = vec[:, 0] / np.abs(vec[:, 0]).max()
    return body, float(np.sqrt(lam[0])), shape


def _rate(beam, zeta, courant):
    body, omega, shape = beam
    alpha, beta = zeta * omega, zeta / omega  # each half of the first mode's damping ratio zeta
    system = assemble(body, Material(E, NU, RHO, alpha=alpha, beta=beta))
    frames = contact_frames(body, "bottom", RigidFlat((0.0, -1.0), (0.0, 1.0), (0.0, 0.0)), tolerance=1e3)
    scheme = BodyScheme(ContactProblem(system, frames, 0.0, ("left",)), 0.5, courant)
    to_scheme = scheme.rotation.T
    u0 = 1e-6 * (to_scheme @ shape)[scheme.free]
    state = scheme.initial_state(u0, np.zeros_like(u0), contact=False)
    weights = scheme.mass * u0 / (u0 @ (scheme.mass * u0))  # the modal coordinate q = phi^T M u
    period = 2 * np.pi / omega
    chunk = max(1, int(period / 40 / scheme.dt))
    t, q = [0.0], [1.0]
    while t[-1] < 6 * period:
        scheme.advance(state, chunk, contact=False)
        t.append(t[-1] + chunk * scheme.dt)
        q.append(float(weights @ state.u))
    t, q = np.array(t), np.array(q)

    def decay(t, a, s, w, p):
        return a * np.exp(-s * t) * np.cos(w * t + p)

    (a, s, w, p), _ = curve_fit(decay, t, q, p0=(1.0, zeta * omega, omega, 0.0))
    return s, zeta * omega  # measured, exact (alpha + beta omega^2) / 2


def test_a_damped_mode_decays_at_the_rayleigh_rate_with_first_order_error(beam):
    measured, exact = _rate(beam, 0.02, 0.9)
    finer, _ = _rate(beam, 0.02, 0.45)
    coarse_error, fine_error = abs(measured / exact - 1), abs(finer / exact - 1)
    assert coarse_error < 3e-2 and fine_error < coarse_error / 1.5


@pytest.mark.parametrize("alpha, beta", [(0.0, 2e-7), (1e5, 0.0), (3e4, 5e-8)])
def test_the_damped_stable_step_is_stable_for_the_highest_mode(beam, alpha, beta):
    body, _, _ = beam
    system = assemble(body, Material(E, NU, RHO, alpha=alpha, beta=beta))
    frames = contact_frames(body, "bottom", RigidFlat((0.0, -1.0), (0.0, 1.0), (0.0, 0.0)), tolerance=1e3)
    for beta2 in (0.5, 0.9):
        s = BodyScheme(ContactProblem(system, frames, 0.0, ("left",)), beta2, 1.0)
        w, c = s.omega_max, alpha + beta * s.omega_max**2
        undamped = np.sqrt(2 / beta2) / w
        assert s.dt_max < undamped  # damping costs step
        radius = np.abs(np.linalg.eigvals(amplification_matrix((w * s.dt_max) ** 2, beta2, c * s.dt_max))).max()
        beyond = np.abs(np.linalg.eigvals(amplification_matrix((w * 1.01 * s.dt_max) ** 2, beta2,
                                                                c * 1.01 * s.dt_max))).max()
        assert radius <= 1 + 1e-9 < beyond
        # and the kernel at that step: white noise (all modes) does not grow over 3000 steps
        u0 = np.random.default_rng(0).standard_normal(s.free.size) * 1e-9
        state = s.initial_state(u0, np.zeros_like(u0), contact=False)
        s.advance(state, 3000, contact=False)
        assert np.abs(state.u).max() < 10 * np.abs(u0).max()

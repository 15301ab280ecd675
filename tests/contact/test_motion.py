"""Independent contact checks: the reactions recomputed from the recorded motion.

For the ring and the FE annulus, a run through stick, slip and separation is traced step by
step (`stickslip.contact.energy.trace`); `stickslip.contact.verify` recomputes the reactions
from the displacements alone through the equations of motion ``M a + K u = C^T lambda``,
with ``M`` and ``K`` built here, independently of the kernel and of the models' own
assembly (numpy centred differences for the ring; scikit-fem called directly for the
annulus). Those reactions must vanish off the contact dofs, equal the kernel's, and obey
Signorini's and Coulomb's laws. A wrong multiplier factor, sign, mass or stiffness in the
kernel or the models breaks one of these.
"""

import numpy as np
import pytest
import scipy.sparse as sp
from skfem import Basis, BilinearForm, ElementQuad1, ElementVector, MeshQuad, asm
from skfem.helpers import dot
from skfem.models.elasticity import lame_parameters, linear_elasticity

from stickslip.contact import SEPARATION, SLIP_NEG, SLIP_POS, STICK
from stickslip.contact.energy import trace
from stickslip.contact.verify import contact_law_residuals, implied_reactions

from .models import FEM, ORDER_ONE, RING

FRICTION = ORDER_ONE.friction


def ring_matrices(scheme):
    """``(M, K)`` of the ring: mass ``dtheta`` per dof, ``K`` from the centred differences of [12]."""
    c, d, N = scheme.coefficients, scheme.dtheta, scheme.nodes
    eye = np.eye(N)
    L = (np.roll(eye, 1, axis=1) - 2 * eye + np.roll(eye, -1, axis=1)) / d**2
    G = (np.roll(eye, 1, axis=1) - np.roll(eye, -1, axis=1)) / (2 * d)
    A = np.zeros((2 * N, 2 * N))  # -M^{-1} K on dofs (U_0, V_0, U_1, ...)
    A[0::2, 0::2], A[0::2, 1::2] = c.b * L - c.g * eye, c.D * G
    A[1::2, 0::2], A[1::2, 1::2] = -c.D * G, c.a * L - c.h * eye
    return np.full(2 * N, d), -d * A


@BilinearForm
def _mass(u, v, w):
    return dot(u, v)


def annulus_matrices(scheme):
    """``(M, K)`` of the annulus on the free dofs, in polar frames, assembled here with scikit-fem."""
    p, N, nr = scheme.params, scheme.n_theta, scheme.n_r
    r, th = np.linspace(1.0, p.xi, nr + 1), 2 * np.pi * np.arange(N) / N
    R, T = np.meshgrid(r, th, indexing="ij")
    i, j = (a.ravel() for a in np.meshgrid(np.arange(nr), np.arange(N), indexing="ij"))
    quads = np.vstack([i * N + j, (i + 1) * N + j, (i + 1) * N + (j + 1) % N, i * N + (j + 1) % N])
    mesh = MeshQuad(np.vstack([(R * np.cos(T)).ravel(), (R * np.sin(T)).ravel()]), quads)
    basis = Basis(mesh, ElementVector(ElementQuad1()))
    K = asm(linear_elasticity(*lame_parameters(1.0, p.nu)), basis)
    lumped = np.asarray(asm(_mass, basis).sum(axis=1)).ravel()
    dx, dy = basis.nodal_dofs
    c, s = np.cos(T.ravel()), np.sin(T.ravel())
    nodes = np.arange(T.size)
    # polar dof 2k (radial), 2k + 1 (hoop) of node k
    rot = sp.csr_matrix((np.concatenate([c, s, -s, c]), (np.concatenate([dx, dy, dx, dy]),
                         np.concatenate([2 * nodes, 2 * nodes, 2 * nodes + 1, 2 * nodes + 1]))))
    free = np.arange(2 * nr * N)  # the outer ring of nodes (i = nr) is clamped
    K_pol = (rot.T @ K @ rot).tocsr()[free][:, free]
    mass = np.empty(2 * T.size)
    mass[0::2], mass[1::2] = lumped[dx], lumped[dy]
    return p.gamma * mass[free], K_pol



#: (model, beta2, mesh, amplitude of the mode-3 start): beta2 = 0.9 damps coarse meshes into steady sliding
CASES = [(RING, 0.5, dict(nodes=32), 1.0), (RING, 0.9, dict(nodes=128), 3.0),
         (FEM, 0.5, dict(n_theta=32, n_r=2), 1.0), (FEM, 0.9, dict(n_theta=64, n_r=2), 30.0)]


@pytest.fixture(scope="module", params=CASES, ids=lambda p: f"{p[0].name}-beta2={p[1]}")
def traced(request):
    model, beta2, mesh, amplitude = request.param
    s = model.scheme(ORDER_ONE, beta2=beta2, **mesh)
    ini = model.perturbed(s, amplitude=amplitude, mode=3, noise=0.1)
    u0, v0 = (s.dofs(ini.U, ini.V), s.dofs(ini.Ud, ini.Vd)) if model is RING else (ini.u, ini.v)
    tr = trace(s, s.initial_state(u0, v0), int(12 * s.steps_per_transit))
    M, K = ring_matrices(s) if model is RING else annulus_matrices(s)
    r, steps = implied_reactions(tr, M, K)
    return tr, r, steps, contact_law_residuals(tr, r, steps, FRICTION)


def test_the_run_meets_every_state(traced):
    tr, _, steps, res = traced
    counts = np.bincount(tr.state[steps].ravel(), minlength=4)
    assert counts[STICK] > 0 and counts[SLIP_POS] > 0 and counts[SEPARATION] > 0
    assert res["stick_count"] > 0 and res["slip_count"] > 0


def test_implied_reactions_vanish_off_the_contact_and_equal_the_kernels(traced):
    *_, res = traced
    assert res["off_contact"] <= 1e-8 and res["kernel"] <= 1e-8, res


def test_signorini_and_coulomb_hold_for_the_implied_reactions(traced):
    """``r_n >= 0``, gap ``>= 0`` at ``t_{m+1}``, ``r_n gap = 0``, ``|r_t| <= f r_n``; a node sticks
    (moves with the surface) where ``|r_t| < f r_n`` and slips against ``r_t`` where ``|r_t| = f r_n``."""
    *_, res = traced
    for key in ("negative_pressure", "coulomb", "complementarity"):
        assert res[key] <= 1e-8, (key, res)
    assert res["penetration"] <= 1e-12 and res["stick_motion"] <= 1e-9 and res["slip_direction"] == 0.0, res


def test_the_kernels_states_agree_with_the_implied_reactions(traced):
    tr, r, steps, _ = traced
    normal, tangent = tr.scheme.contact_dofs
    tol = 1e-8 * np.abs(tr.lam_n[steps]).max()
    r_n, r_t, codes = r[:, normal], r[:, tangent], tr.state[steps]
    assert np.all((codes == SEPARATION) == (r_n <= tol))
    inside = np.abs(r_t) < FRICTION * r_n - tol
    assert np.all(codes[inside] == STICK)
    assert np.all(np.isin(codes[(r_n > tol) & ~inside & (codes != STICK)], (SLIP_POS, SLIP_NEG)))

"""Explicit beta2 scheme [22] with forward-increment Lagrange multipliers [21], [23] on the FE mesh.

Semi-discrete problem ([21]): ``gamma M u_tt + K u = C^T lambda`` with the lumped (diagonal)
mass ``M``, the stiffness ``K`` of `mesh.assemble` and reactions ``lambda`` on the contact
dofs only (polar frames: ``lambda_n`` on the radial dof, ``lambda_t`` on the hoop dof of each
node at ``r = 1``). One step, exactly as the ring scheme (`brake.ring_scheme`, see
``docs/theory/brake-fem.md``), with ``A_m = -(gamma M)^{-1} K u_m`` (one sparse matvec):

    predictor:  v*_m = v_{m-1} + dt ((1 - beta2) a_{m-1} + beta2 A_m),
                u*_{m+1} = u_m + dt v*_m + dt^2/2 A_m,
    contact:    r_n = max(0, (delta - u*_r) / (c dt^2)),            c = beta2 + 1/2,
                r_t = clip((u_theta,m + dt - u*_theta) / (c dt^2), -f r_n, f r_n),
    corrector:  u_{m+1} = u* + c dt^2 r,  a_m = A_m + r,  v_m = v*_m + beta2 dt r,

``r = lambda / (gamma m_c)`` the reaction per unit mass (``m_c`` the contact node's lumped
mass). The mass is diagonal and each constraint acts on one dof, so the multipliers are
exact node by node ([23] with a diagonal ``C M^{-1} C^T``): the normal one holds
``u_r = delta`` where it is positive, the tangential one makes a sticking node move with
the shaft (``u_theta,m+1 - u_theta,m = dt``, surface speed ``R Omega`` = 1) and its projection
on ``[-f r_n, f r_n]`` solves the discrete Coulomb law (slip opposing ``1 - w``).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np
from numba import njit

from ... import validation as check
from ...errors import ParameterError
from ..reduced.coefficients import ReducedCoefficients, elastic_moduli
from ..reduced.params import BrakeParams
from ..ring.scheme import SEPARATION, SLIP_NEG, SLIP_POS, STATE_NAMES, STICK
from .mesh import FemSystem, annulus_mesh, assemble
from .modes import max_frequency
from .static import FemSteady, steady_state

__all__ = ["FemScheme", "advance", "bare", "stencil_apply", "scheme_energy", "STICK", "SLIP_POS", "SLIP_NEG", "SEPARATION",
           "STATE_NAMES"]


@njit(cache=True)
def stencil_apply(C, u, out):
    """``out = -K u`` for the block-circulant ``K`` of stencil ``C[i, di + 1, dj + 1, c, c']``
    (`mesh.FemSystem.stencil`, here divided by the masses): a sparse matvec that reads the
    matrix from ``n_r x 36`` numbers instead of ``nnz`` (same matrix as ``FemSystem.K``)."""
    n_r = C.shape[0]
    N = out.shape[0] // (2 * n_r)
    for k in range(out.shape[0]):
        out[k] = 0.0
    for i in range(n_r):
        base = 2 * i * N
        for di in range(-1, 2):
            i2 = i + di
            if i2 < 0 or i2 >= n_r:
                continue
            b2 = 2 * i2 * N
            for dj in range(-1, 2):
                c00, c01 = C[i, di + 1, dj + 1, 0, 0], C[i, di + 1, dj + 1, 0, 1]
                c10, c11 = C[i, di + 1, dj + 1, 1, 0], C[i, di + 1, dj + 1, 1, 1]
                jlo = 1 if dj == -1 else 0
                jhi = N - 1 if dj == 1 else N
                off = b2 + 2 * dj
                for j in range(jlo, jhi):
                    ur, ut = u[off + 2 * j], u[off + 2 * j + 1]
                    out[base + 2 * j] -= c00 * ur + c01 * ut
                    out[base + 2 * j + 1] -= c10 * ur + c11 * ut
                if dj != 0:  # periodic wrap
                    j, j2 = (0, N - 1) if dj == -1 else (N - 1, 0)
                    ur, ut = u[b2 + 2 * j2], u[b2 + 2 * j2 + 1]
                    out[base + 2 * j] -= c00 * ur + c01 * ut
                    out[base + 2 * j + 1] -= c10 * ur + c11 * ut


@njit(cache=True)
def advance(u, v, a, lam_n, lam_t, state, work, nsteps, dt, C, delta, f, beta2, contact):
    """Advance ``nsteps`` steps in place (compiled).

    On entry ``u = u_m``, ``v = v_{m-1}``, ``a = a_{m-1}`` (free dofs); on exit the same for
    ``m + nsteps``. ``C`` is the stencil of ``(gamma M)^{-1} K`` (`FemScheme.operator`).
    ``lam_n, lam_t, state`` (one per contact node, ``nc = lam_n.size``, dofs ``2j, 2j+1``)
    receive the reactions per unit mass and the node states of the last step, ``work`` its
    ``u_m`` (for energies and snapshots).
    """
    n, nc = u.shape[0], lam_n.shape[0]
    cdt2 = (beta2 + 0.5) * dt * dt
    on = 1.0 if contact else 0.0
    A = np.empty(n)
    ut_old = np.empty(nc)
    for step in range(nsteps):
        stencil_apply(C, u, A)
        if step == nsteps - 1:
            work[:] = u
        for j in range(nc):
            ut_old[j] = u[2 * j + 1]
        for k in range(n):
            vs = v[k] + dt * ((1.0 - beta2) * a[k] + beta2 * A[k])
            v[k] = vs
            u[k] += dt * vs + 0.5 * dt * dt * A[k]
            a[k] = A[k]
        for j in range(nc):  # branch-free, so that the loop vectorises
            r, t = 2 * j, 2 * j + 1
            p = on * max((delta - u[r]) / cdt2, 0.0)
            trial = (ut_old[j] + dt - u[t]) / cdt2
            lim = f * p
            q = min(max(trial, -lim), lim)
            touch = p > 0.0
            state[j] = SEPARATION * (1 - touch) + touch * (SLIP_POS * (trial > lim) + SLIP_NEG * (trial < -lim))
            lam_n[j], lam_t[j] = p, q
            a[r] += p
            a[t] += q
            v[r] += beta2 * dt * p
            v[t] += beta2 * dt * q
            u[r] = delta if touch else u[r]
            u[t] += cdt2 * q


@njit(cache=True)
def bare(u, v, a, nsteps, dt, C, beta2):
    """The same update without contact (compiled): matvec + predictor."""
    n = u.shape[0]
    A = np.empty(n)
    for _ in range(nsteps):
        stencil_apply(C, u, A)
        for k in range(n):
            v[k] += dt * ((1.0 - beta2) * a[k] + beta2 * A[k])
            u[k] += dt * v[k] + 0.5 * dt * dt * A[k]
            a[k] = A[k]


def scheme_energy(scheme, u0, u1, ref=None):
    """``(kinetic, elastic)`` at ``t_{m+1/2}``: ``w^T M w / 2`` and ``(u_m - u_e)^T K (u_{m+1} - u_e)/2``
    (``w = (u_{m+1} - u_m)/dt``, ``M`` the physical mass ``gamma * mass``, ``u_e = ref``).
    Their sum is conserved by central differences without contact; with contact its change
    over a step is the work ``(r_m - r_e) . (u_{m+1} - u_{m-1}) / 2`` of the reactions."""
    w = (u1 - u0) / scheme.dt
    x0, x1 = (u0, u1) if ref is None else (u0 - ref, u1 - ref)
    Kx1 = np.empty_like(x1)
    stencil_apply(scheme.operator, x1, Kx1)  # -(gamma M)^{-1} K x1
    mass = scheme.mass
    return 0.5 * float(np.dot(mass * w, w)), -0.5 * float(np.dot(x0, mass * Kx1))


@lru_cache(maxsize=8)
def _system(n_theta: int, n_r: int, xi: float, nu: float) -> FemSystem:
    """Assembled systems are shared by the schemes of one mesh and material (they are not mutated)."""
    return assemble(annulus_mesh(n_theta, n_r, xi), nu)


@dataclass(frozen=True, eq=False)
class FemScheme:
    """The FE discretisation of [10] on an ``n_theta x n_r`` mesh and its explicit time step.

    Parameters
    ----------
    params : BrakeParams
        Dimensionless parameters (``xi``, ``nu`` set the mesh and the material).
    n_theta, n_r : int
        Mesh (`annulus_mesh`): nodes around (a multiple of 8, >= 16) and layers across.
    beta2 : float
        ``gamma`` of the explicit Newmark scheme [22], in [1/2, 1]: 1/2 is central
        differences; the paper uses 0.9 (numerical damping of high frequencies).
    courant : float
        ``dt / dt_max`` in (0, 1], ``dt_max = sqrt(2 / beta2) / omega_max`` (``omega_max``
        the largest free frequency of the mesh: the CFL limit set by the P-wave speed).
    """

    params: BrakeParams
    n_theta: int = 256
    n_r: int = 16
    beta2: float = 0.9
    courant: float = 0.9

    def __post_init__(self):
        if not isinstance(self.params, BrakeParams):
            raise ParameterError("params", self.params, "a stickslip.brake.BrakeParams")
        annulus_mesh(self.n_theta, self.n_r, self.params.xi)  # validates n_theta, n_r
        object.__setattr__(self, "n_theta", int(self.n_theta))
        object.__setattr__(self, "n_r", int(self.n_r))
        object.__setattr__(self, "beta2", check.in_range("beta2", self.beta2, 0.5, 1.0))
        object.__setattr__(self, "courant", check.in_range("courant", self.courant, 0.0, 1.0, lo_open=True))

    @cached_property
    def system(self) -> FemSystem:
        return _system(self.n_theta, self.n_r, self.params.xi, self.params.nu)

    @cached_property
    def steady(self) -> FemSteady:
        return steady_state(self.params, self.system)

    @cached_property
    def operator(self) -> np.ndarray:
        """Stencil of ``(gamma M)^{-1} K`` for `advance` (row layer ``i`` divided by its mass)."""
        m = self.params.gamma * self.system.mass[::2 * self.n_theta]
        return np.ascontiguousarray(self.system.stencil / m[:, None, None, None, None])

    @property
    def mass(self) -> np.ndarray:
        """Physical lumped mass ``gamma M`` of the free dofs."""
        return self.params.gamma * self.system.mass

    @property
    def nodes(self) -> int:
        return self.n_theta

    @property
    def theta(self) -> np.ndarray:
        return self.system.mesh.theta

    @property
    def dtheta(self) -> float:
        return 2.0 * np.pi / self.n_theta

    @cached_property
    def coefficients(self) -> ReducedCoefficients:
        """Reduced-model coefficients [13] (for speeds in units of its ``sqrt(a)``)."""
        return self.params.coefficients()

    @property
    def p_wave_speed(self) -> float:
        """``c_p / (R Omega) = sqrt(ã / gamma)``: angular speed of a P-wave along ``r = R``."""
        return float(np.sqrt(float(elastic_moduli(self.params.nu)[0]) / self.params.gamma))

    @cached_property
    def omega_max(self) -> float:
        return max_frequency(self.system) / np.sqrt(self.params.gamma)

    @cached_property
    def dt_max(self) -> float:
        return float(np.sqrt(2.0 / self.beta2) / self.omega_max)

    @property
    def dt(self) -> float:
        return self.courant * self.dt_max

    @property
    def transit_time(self) -> float:
        """``2 pi / (c_p / (R Omega))``: a P-wave once around the contact circle (paper time)."""
        return 2.0 * np.pi / self.p_wave_speed

    @property
    def steps_per_transit(self) -> float:
        return self.transit_time / self.dt

    @property
    def order(self) -> int:
        return 2 if self.beta2 == 0.5 else 1

    def key(self) -> dict:
        return {"n_theta": self.n_theta, "n_r": self.n_r, "beta2": self.beta2, "courant": self.courant}

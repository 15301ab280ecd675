"""The explicit-scheme interface shared by every contact model (ring, FE annulus, general FE).

`ExplicitScheme` is the contract a model's discretisation meets to use the shared
kernel (`stickslip.contact.kernel`), the run books (`stickslip.contact.runs`) and the
classification (`stickslip.contact.classify`). A model writes a frozen dataclass with the
fields ``params``, ``beta2`` and ``courant``, sets ``PARAMS`` (the type of ``params``),
calls `ExplicitScheme.validate_common` in ``__post_init__``, and defines:

* ``omega_max``: the highest free angular frequency of the discrete problem (no contact);
* ``transit_time``: the time a P-wave takes to run once along the contact line;
* ``theta``: the positions of the contact nodes along the closed contact line [rad];
* ``mass``: the lumped mass per dof (a number or an array), for the energies;
* ``contact_dofs``: the normal and tangential dof of every contact node (two int arrays);
* ``surface``: the rigid surface per contact node, ``(gap0, speed)``: ``u_n >= gap0``
  and its tangential speed;
* the operator ``M^{-1} K``: either ``stencil`` (structured rings of nodes, see
  `kernel.stencil_apply`: the fast path) or ``operator_matrix()`` (a scipy sparse matrix:
  the general path);
* ``steady_reference()``: steady sliding ``u_e`` and its reactions per unit mass
  ``(r_n, r_t)`` per contact node (the start of a run and the zero of its energy).

What it gets: the time step and its CFL limit, the order, the numerical damping
of a free mode, the starting state of a run, the step itself and the scheme's energies.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass
from functools import cached_property
from typing import ClassVar

import numpy as np
import scipy.sparse as sp

from ..quantities import COMMON as Q
from ..errors import ParameterError
from .kernel import COULOMB, advance, block2_apply, csr_apply, stencil_apply

__all__ = ["ExplicitScheme", "StepState", "StepOutput", "amplification_matrix", "discrete_rates", "stencil_matrix"]


def amplification_matrix(w2, beta2, cdt=0.0) -> np.ndarray:
    """One step of the scheme for ``x'' = -lambda x - c x'``, ``w2 = lambda dt^2`` (complex
    allowed), ``cdt = c dt`` (the damping acts on ``v_{m-1}``, as in the kernel):
    ``(u_m, v_{m-1} dt, a_{m-1} dt^2) -> (u_{m+1}, v_m dt, a_m dt^2)``."""
    beta2, cdt = Q.check("beta2", beta2), Q.check("cdt", cdt)
    am = np.array([-w2, -cdt, 0.0], dtype=complex)
    vm = np.array([0.0, 1.0, 1.0 - beta2]) + beta2 * am
    um = np.array([1.0, 0.0, 0.0]) + vm + 0.5 * am
    return np.array([um, vm, am])


def discrete_rates(lam, dt: float, beta2: float) -> np.ndarray:
    """``log(z)/dt`` of the amplification factor ``z`` of largest modulus, for ``x'' = -lambda x``.

    The fully discrete counterpart of ``s = sqrt(-lambda)`` (vectorised over ``lam``).
    """
    dt, beta2 = Q.check("dt", dt), Q.check("beta2", beta2)
    lam = np.asarray(lam, dtype=complex)
    out = np.empty(lam.shape, dtype=complex)
    for idx, value in np.ndenumerate(lam):
        z = np.linalg.eigvals(amplification_matrix(value * dt**2, beta2))
        out[idx] = np.log(z[np.argmax(np.abs(z))]) / dt
    return out


_NO_STENCIL = np.zeros((0, 3, 3, 2, 2))
_NO_LOAD = np.zeros(0)


def stencil_matrix(C: np.ndarray, n_theta: int) -> sp.csr_matrix:
    """The sparse matrix of the stencil ``C[i, di + 1, dj + 1, c, c']`` on ``n_r = len(C)`` rings of
    ``n_theta`` nodes (`kernel.stencil_apply` applies minus it without forming it)."""
    n_theta = Q.check("n_theta", n_theta)
    n_r = C.shape[0]
    i, di, dj, c, c2 = (a.ravel() for a in np.meshgrid(*map(np.arange, C.shape), indexing="ij"))
    val = C.ravel()
    ok = (val != 0.0) & (i + di - 1 >= 0) & (i + di - 1 < n_r)
    i, di, dj, c, c2, val = i[ok], di[ok] - 1, dj[ok] - 1, c[ok], c2[ok], val[ok]
    j = np.arange(n_theta)
    rows = 2 * (i[:, None] * n_theta + j) + c[:, None]
    cols = 2 * ((i + di)[:, None] * n_theta + (j + dj[:, None]) % n_theta) + c2[:, None]
    n = 2 * n_r * n_theta
    K = sp.csr_matrix((np.repeat(val, n_theta), (rows.ravel(), cols.ravel())), shape=(n, n))
    K.sort_indices()
    return K


@dataclass(eq=False)
class StepState:
    """The scheme's state between steps: ``u = u_m``, ``v = v_{m-1}``, ``a = a_{m-1}`` (updated in place)."""

    u: np.ndarray
    v: np.ndarray
    a: np.ndarray

    def copy(self) -> "StepState":
        return StepState(self.u.copy(), self.v.copy(), self.a.copy())


@dataclass(eq=False)
class StepOutput:
    """What the last step of `ExplicitScheme.advance` leaves: ``u_prev`` (its ``u_m``), the
    reactions per unit mass ``lam_n, lam_t`` and the ``state`` code of every contact node."""

    u_prev: np.ndarray
    lam_n: np.ndarray
    lam_t: np.ndarray
    state: np.ndarray


class ExplicitScheme(ABC):
    """Explicit beta2 scheme [22] with forward-increment multipliers [23] (see the module docstring)."""

    PARAMS: ClassVar[type] = object
    params: object
    beta2: float
    courant: float

    def validate_common(self) -> None:
        """Check ``params`` (a ``PARAMS``) and normalise ``beta2`` in [1/2, 1] and ``courant`` in (0, 1]."""
        if not isinstance(self.params, self.PARAMS):
            raise ParameterError("params", self.params, f"a {self.PARAMS.__name__}")
        object.__setattr__(self, "beta2", Q.check("beta2", self.beta2))
        object.__setattr__(self, "courant", Q.check("courant", self.courant))

    # --- what a model defines -----------------------------------------------------------
    @property
    @abstractmethod
    def omega_max(self) -> float:
        """Highest free angular frequency of the discrete problem."""

    @property
    @abstractmethod
    def transit_time(self) -> float:
        """Time for a P-wave to run once along the contact line."""

    @property
    @abstractmethod
    def theta(self) -> np.ndarray:
        """Positions of the contact nodes along the closed contact line [rad]."""

    @property
    @abstractmethod
    def mass(self):
        """Lumped mass per dof (number or array)."""

    @property
    @abstractmethod
    def contact_dofs(self) -> tuple[np.ndarray, np.ndarray]:
        """``(normal, tangent)``: the two dofs of every contact node (int64 arrays)."""

    @property
    @abstractmethod
    def surface(self) -> tuple[np.ndarray, np.ndarray]:
        """``(gap0, speed)`` per contact node: the rigid surface is at ``u_n = gap0`` and moves at ``speed``."""

    @abstractmethod
    def steady_reference(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Steady sliding: ``u_e`` and the reactions per unit mass ``(r_n, r_t)`` per contact node."""

    @property
    def closed_line(self) -> bool:
        """Whether the contact line closes on itself (a ring, a bore) — the classification then
        looks for travelling waves around it; on an open line (a pad, a block) it does not."""
        return True

    @property
    def static_friction(self) -> float:
        """Static coefficient ``f_s >= f`` (a node sticks while its holding reaction is within
        ``f_s r_n``); by default ``params.friction``: plain Coulomb."""
        return float(self.params.friction)

    @property
    def kinetic_law(self) -> tuple[float, int, float]:
        """The kinetic coefficient and how it depends on the slip speed — ``(f, kind, parameter)``
        of `kernel.kinetic_coefficient` (default ``(params.friction, COULOMB, 0)``: a constant)."""
        return (float(self.params.friction), COULOMB, 0.0)

    @property
    def pressure_scaling(self) -> tuple[float, np.ndarray]:
        """A friction coefficient that depends on the contact pressure — ``(n, s)``, the exponent of
        ``(P / P_ref)^(-n)`` and, per contact node, ``P / P_ref`` per unit of the kernel's normal
        reaction (default ``(0, [])``: none)."""
        return (0.0, np.zeros(0))

    @property
    def kernel_law(self) -> np.ndarray:
        """The kernel's ``law`` array: ``[kind, parameter, n, s_0, s_1, ...]`` (`kinetic_law`,
        `pressure_scaling`)."""
        _, kind, parameter = self.kinetic_law
        n, scale = self.pressure_scaling
        return np.concatenate([[float(kind), float(parameter), float(n)], np.asarray(scale, dtype=float)])

    @property
    def damping(self) -> tuple[float, float]:
        """Rayleigh damping ``(alpha, beta)``, ``C = alpha M + beta K`` (default none)."""
        return (0.0, 0.0)

    @property
    def load(self) -> np.ndarray | None:
        """A constant external load per unit mass on every dof (added to ``-M^{-1} K u``), or None."""
        return None

    # --- the operator: a stencil (fast path) or a sparse matrix (general path) ----------
    @property
    def stencil(self) -> np.ndarray | None:
        """Stencil of ``M^{-1} K`` on structured rings of nodes (`kernel.stencil_apply`), or None."""
        return None

    def operator_matrix(self):
        """``M^{-1} K`` as a scipy sparse matrix (by default, from the stencil)."""
        if self.stencil is None:
            raise NotImplementedError(f"{type(self).__name__} defines neither stencil nor operator_matrix()")
        return stencil_matrix(self.stencil, self.nodes)

    def apply(self, u: np.ndarray, out: np.ndarray | None = None, sparse: bool = False) -> np.ndarray:
        """``-M^{-1} K u`` (the internal accelerations); ``sparse=True`` forces the general path."""
        u = np.ascontiguousarray(u, dtype=float)
        out = np.empty_like(u) if out is None else out
        if self.stencil is not None and not sparse:
            stencil_apply(self.stencil, u, out)
        else:
            indptr, indices, data, block = self.kernel_operator
            (block2_apply if block == 2 else csr_apply)(indptr, indices, data, u, out)
        return out

    # --- what every scheme gets ---------------------------------------------------------
    @cached_property
    def sparse_operator(self):
        """`operator_matrix` in CSR form with sorted int64 indices (for the compiled kernels)."""
        A = self.operator_matrix().tocsr()
        A.sort_indices()
        return type(A)((A.data.astype(float), A.indices.astype(np.int64), A.indptr.astype(np.int64)),
                       shape=A.shape)

    @cached_property
    def kernel_operator(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
        """``(indptr, indices, data, block)``: `sparse_operator` as the compiled kernels read it.

        In 2 x 2 blocks (``block = 2``, `kernel.block2_apply`) when the dofs pair up by node
        (``2 i + c``) and the blocks store at most a quarter more entries than the matrix has;
        in CSR (``block = 1``) otherwise. Blocks read one column index per four entries: on 2-D
        meshes the product takes 0.7 of scipy's CSR ``K @ u`` (``benchmarks/fem_general.py``).
        """
        A = self.sparse_operator
        if A.shape[0] % 2 == 0 and A.nnz > 0:
            B = A.tobsr(blocksize=(2, 2))
            B.sort_indices()
            if 4 * B.indices.size <= 1.25 * A.nnz:
                return (B.indptr.astype(np.int64), B.indices.astype(np.int64),
                        np.ascontiguousarray(B.data, dtype=float).reshape(-1), 2)
        return A.indptr, A.indices, A.data, 1

    @cached_property
    def dt_max(self) -> float:
        """CFL limit ``sqrt(2/beta2) / omega_max`` of the free discrete problem; with damping,
        the largest step at which the highest mode (damped by ``alpha + beta omega_max^2``)
        does not grow (bisection on the spectral radius of `amplification_matrix`)."""
        undamped = float(np.sqrt(2.0 / self.beta2) / self.omega_max)
        alpha, beta = self.damping
        if alpha == 0.0 and beta == 0.0:
            return undamped
        w, c = self.omega_max, alpha + beta * self.omega_max**2

        def stable(dt):
            return np.abs(np.linalg.eigvals(amplification_matrix((w * dt) ** 2, self.beta2, c * dt))).max() <= 1 + 1e-12

        lo, hi = 0.0, undamped
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if stable(mid) else (lo, mid)
        return lo

    @property
    def dt(self) -> float:
        return self.courant * self.dt_max

    @property
    def steps_per_transit(self) -> float:
        return self.transit_time / self.dt

    @property
    def order(self) -> int:
        """Order of accuracy in time — 2 for central differences (``beta2 = 1/2``), 1 otherwise."""
        return 2 if self.beta2 == 0.5 else 1

    @property
    def nodes(self) -> int:
        """Number of contact nodes."""
        return int(self.theta.size)

    @property
    def dtheta(self) -> float:
        return 2.0 * np.pi / self.nodes

    @property
    def speed_scales(self) -> dict:
        """Named reference speeds [rad per unit time] — a classification reports ``c`` over each."""
        return {}

    def step_factor(self, omega) -> np.ndarray:
        """Spectral radius per step of the scheme for a free mode of frequency ``omega``."""
        out = [np.abs(np.linalg.eigvals(amplification_matrix((w * self.dt) ** 2, self.beta2))).max()
               for w in np.ravel(omega)]
        return np.reshape(out, np.shape(omega))

    def energies(self, u0: np.ndarray, u1: np.ndarray, ref: np.ndarray | None = None) -> tuple[float, float]:
        """``(kinetic, elastic)`` at ``t_{m+1/2}``: ``w^T M w / 2`` and ``(u_m - u_e)^T K (u_{m+1} - u_e) / 2``.

        ``w = (u_{m+1} - u_m)/dt``, ``u_e = ref`` (default 0). Their sum is conserved by central
        differences without contact; with contact its change over a step is the work
        ``(r_m - r_e) . M (u_{m+1} - u_{m-1}) / 2`` of the reactions.
        """
        w = (u1 - u0) / self.dt
        x0, x1 = (u0, u1) if ref is None else (u0 - ref, u1 - ref)
        mass = self.mass
        # sums without BLAS: its threads, idle between two samples, spin against the kernel's on a
        # loaded machine (1.3 s of a 2.1-s kernel's run with another job on the cores)
        return 0.5 * float(np.einsum("i,i", mass * w, w)), -0.5 * float(np.einsum("i,i", x0, mass * self.apply(x1)))

    def gaps(self, u: np.ndarray) -> np.ndarray:
        """The normal gap of every contact node at displacement ``u``: ``u_n - gap0``."""
        return u[self.contact_dofs[0]] - self.surface[0]

    def touching(self, u: np.ndarray) -> np.ndarray:
        """Which contact nodes touch at displacement ``u`` (``u_n <= gap0``)."""
        return self.gaps(u) <= 0.0

    def contact_work(self, lam_n: np.ndarray, lam_t: np.ndarray, du: np.ndarray):
        """``(surface work, friction dissipation, normal work)`` of the reactions per unit mass
        ``lam_n, lam_t`` (one row per step) over the displacements ``du = (u_{m+1} - u_{m-1}) / 2``:
        ``r_t`` times the surface's displacement ``s dt``, against the slip ``du_t - s dt``, and
        ``r_n`` times ``du_n`` (`stickslip.contact.energy`)."""
        (normal, tangent), (_, speed) = self.contact_dofs, self.surface
        mass = np.broadcast_to(np.asarray(self.mass, dtype=float), du.shape[-1:])
        m_n, m_t = mass[normal], mass[tangent]
        slip = du[..., tangent] - speed * self.dt
        return (np.sum(m_t * lam_t * speed * self.dt, axis=-1), -np.sum(m_t * lam_t * slip, axis=-1),
                np.sum(m_n * lam_n * du[..., normal], axis=-1))

    def initial_state(self, u0: np.ndarray, v0: np.ndarray, contact: bool = True) -> StepState:
        """``u_0, v_{-1}, a_{-1}`` such that the first step starts from displacement ``u0`` and velocity ``v0``.

        ``a_{-1}`` is the internal acceleration at ``u0`` (with the load) plus the steady reactions at the
        contact nodes touching the surface, and ``v_{-1} = v0 - dt a_{-1}``: exact for the free
        problem and for unperturbed steady sliding.
        """
        u0, v0 = (np.array(x, dtype=float) for x in (u0, v0))
        if u0.shape != v0.shape or u0.shape != self.sparse_operator.shape[:1]:
            raise ParameterError("initial", f"arrays of shape {u0.shape}, {v0.shape}",
                                 f"two arrays of shape {self.sparse_operator.shape[:1]}")
        alpha, beta = self.damping
        a = self.apply(u0 + beta * v0) - alpha * v0
        if self.load is not None:
            a += self.load
        if contact:
            a += self.steady_reactions(u0)
        return StepState(u0, v0 - self.dt * a, a)

    def steady_reactions(self, u: np.ndarray) -> np.ndarray:
        """The steady reactions per unit mass on every dof, at the contact nodes that touch at ``u``."""
        (normal, tangent), (_, r_n, r_t) = self.contact_dofs, self.steady_reference()
        out, touching = np.zeros_like(u), self.touching(u)
        out[normal] += touching * r_n
        out[tangent] += touching * r_t
        return out

    def new_output(self) -> StepOutput:
        n = self.nodes
        return StepOutput(np.zeros(self.sparse_operator.shape[0]), np.zeros(n), np.zeros(n), np.zeros(n, np.int8))

    def advance(self, state: StepState, nsteps: int = 1, contact: bool = True, out: StepOutput | None = None, *,
                sparse: bool = False) -> StepOutput:
        """Advance ``state`` by ``nsteps`` steps in place; return what the last step leaves.

        ``contact=False`` switches contact and friction off; ``sparse=True`` takes the general
        sparse-matrix path even where the scheme has a stencil (the same operator).
        """
        nsteps = Q.check("nsteps", nsteps)
        out = self.new_output() if out is None else out
        (normal, tangent), (gap0, speed) = self.contact_dofs, self.surface
        indptr, indices, data, block = self.kernel_operator
        C = self.stencil if self.stencil is not None and not sparse else _NO_STENCIL
        f, kind, parameter = self.kinetic_law
        load = _NO_LOAD if self.load is None else np.ascontiguousarray(self.load, dtype=float)
        advance(C, indptr, indices, data, block, load, np.array(self.damping, dtype=float), state.u, state.v, state.a, normal, tangent, gap0, speed, nsteps,
                self.dt, self.beta2, f, self.static_friction, bool(contact), out.lam_n, out.lam_t,
                out.state, out.u_prev, self.kernel_law)
        return out

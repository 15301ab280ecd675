"""Step-by-step traces of an explicit contact run and their discrete energy books.

The scheme of `kernel` satisfies, at every step and for any ``beta2`` (``docs/theory/contact.md``),

    M (u_{m+1} - 2 u_m + u_{m-1}) / dt^2 + K u_m = M r_m + (beta2 - 1/2) M (a_m - a_{m-1}),

so with ``E_{m+1/2} = w^T M w / 2 + u_m^T K u_{m+1} / 2`` (``w = (u_{m+1} - u_m)/dt``) and
``du = (u_{m+1} - u_{m-1}) / 2``:

    E_{m+1/2} - E_{m-1/2} = r_m . M du  +  (beta2 - 1/2) (a_m - a_{m-1}) . M du.

The first term is the work of the contact reactions, which splits into the work of the
moving surface (``r_t`` times its displacement ``s dt``), minus the frictional dissipation
(``r_t`` against the slip ``du_t - s dt``), plus the work of the normal reactions (nonzero
only where contact begins or ends); the second is the numerical dissipation of ``beta2 >
1/2`` (zero for central differences). `EnergyBooks` holds every term per step; their sum
closes to round-off, which the tests check at ``beta2 = 1/2`` and ``0.9``.

A `Trace` records every step (the whole dof vector): it is meant for verification on
small problems, not for production runs (which keep the books of `runs`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..quantities import COMMON as Q
from .scheme import ExplicitScheme, StepState

__all__ = ["Trace", "trace", "EnergyBooks", "energy_books"]


@dataclass(frozen=True, eq=False)
class Trace:
    """Every step of a run: ``u[m]`` for ``m = 0 .. M`` and, for ``m = 0 .. M-1``, the
    acceleration ``a[m]`` (reactions included), the reactions per unit mass ``lam_n[m]``,
    ``lam_t[m]`` and the node states ``state[m]`` of step ``m``; ``a_start`` is ``a_{-1}``."""

    scheme: ExplicitScheme
    u: np.ndarray
    a: np.ndarray
    a_start: np.ndarray
    lam_n: np.ndarray
    lam_t: np.ndarray
    state: np.ndarray
    contact: bool
    lam_b: np.ndarray | None = None  # across the sliding direction, between solids (its output's lam_b)

    @property
    def steps(self) -> int:
        return self.a.shape[0]

    @property
    def t(self) -> np.ndarray:
        """Times ``t_m`` of ``u[m]``."""
        return self.scheme.dt * np.arange(self.u.shape[0])


def trace(scheme: ExplicitScheme, state: StepState, nsteps: int, contact: bool = True) -> Trace:
    """Advance a copy of ``state`` by ``nsteps`` single steps and record each of them."""
    nsteps = Q.check("nsteps", nsteps)
    k = state.copy()
    n, nc = k.u.size, scheme.nodes
    u, a = np.empty((nsteps + 1, n)), np.empty((nsteps, n))
    lam_n, lam_t, codes = np.empty((nsteps, nc)), np.empty((nsteps, nc)), np.empty((nsteps, nc), np.int8)
    out = scheme.new_output()
    lam_b = np.empty((nsteps, nc)) if getattr(out, "lam_b", None) is not None else None
    u[0], a_start = k.u, k.a.copy()
    for m in range(nsteps):
        scheme.advance(k, 1, contact, out)
        u[m + 1], a[m], lam_n[m], lam_t[m], codes[m] = k.u, k.a, out.lam_n, out.lam_t, out.state
        if lam_b is not None:
            lam_b[m] = out.lam_b
    return Trace(scheme, u, a, a_start, lam_n, lam_t, codes, bool(contact), lam_b)


@dataclass(frozen=True, eq=False)
class EnergyBooks:
    """The terms of the discrete energy balance for steps ``m = 1 .. M-1`` (arrays of ``M - 1``).

    ``energy[i]`` is ``E_{m+1/2}`` for ``m = i .. `` (``M`` values, ``E_{1/2} .. E_{M-1/2}``);
    ``kinetic``, ``strain`` its parts. Per step: ``surface_work`` (work of the moving
    surface on the contact nodes), ``friction_dissipation`` (>= 0 where friction opposes
    the slip), ``normal_work`` (of the normal reactions), ``numerical`` (of ``beta2 > 1/2``).
    `residual` is what the balance leaves.
    """

    energy: np.ndarray
    kinetic: np.ndarray
    strain: np.ndarray
    surface_work: np.ndarray
    friction_dissipation: np.ndarray
    normal_work: np.ndarray
    numerical: np.ndarray

    @property
    def residual(self) -> np.ndarray:
        """``E_{m+1/2} - E_{m-1/2} - (surface work - friction dissipation + normal work + numerical)``."""
        return np.diff(self.energy) - (self.surface_work - self.friction_dissipation + self.normal_work
                                       + self.numerical)


def energy_books(tr: Trace) -> EnergyBooks:
    """The energy balance of a trace (see the module docstring)."""
    s = tr.scheme
    dt, beta2 = s.dt, s.beta2
    mass = np.broadcast_to(np.asarray(s.mass, dtype=float), tr.u.shape[1:])
    w = np.diff(tr.u, axis=0) / dt                                          # w_{m+1/2}, m = 0 .. M-1
    kinetic = 0.5 * np.einsum("mi,i,mi->m", w, mass, w)
    Ku = -mass * np.array([s.apply(x) for x in tr.u[:-1]])                  # K u_m
    strain = 0.5 * np.einsum("mi,mi->m", Ku, tr.u[1:])
    du = 0.5 * (tr.u[2:] - tr.u[:-2])                                       # m = 1 .. M-1
    a_prev = np.vstack([tr.a_start[None], tr.a[:-1]])
    numerical = (beta2 - 0.5) * np.einsum("mi,i,mi->m", (tr.a - a_prev)[1:], mass, du)
    across = {} if tr.lam_b is None else {"lam_b": tr.lam_b[1:]}  # the friction across the sliding, between solids
    surface, friction, normal = s.contact_work(tr.lam_n[1:], tr.lam_t[1:], du, **across)
    return EnergyBooks(energy=kinetic + strain, kinetic=kinetic, strain=strain, surface_work=surface,
                       friction_dissipation=friction, normal_work=normal, numerical=numerical)

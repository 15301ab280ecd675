"""Steady sliding of a system and its linear stability.

With every surface moving (``V_i != 0``) the structure can rest while each contact slips at
``v_r = V_i``: the position solves ``K x = f + sum_i w_i N_i sign(V_i) mu_i(|V_i|)``. Small
motions about it obey ``M y'' + C_eff y' + K y = 0`` with

    C_eff = C + sum_i N_i mu_i'(|V_i|) w_i w_i^T

(a friction law falling with slip speed, ``mu' < 0``, feeds energy in: negative damping), and
steady sliding is stable when every eigenvalue of that linear flow has a negative real part.
A unilateral contact (normal force ``N(x) = N_0 - k_n n . x``) adds ``k_n n n^T`` and, through its
friction, ``sign(V) mu k_n w n^T`` to the stiffness: a matrix no longer symmetric, whose modes
may coalesce and flutter (mode-coupling instability, Hoffmann et al. 2002); with a law of the slip
speed, ``N(x) mu'(|V|) w w^T`` at the resting position to the damping.

A rigid contact (``n . x >= 0``, Coulomb) is closed in steady sliding: its reaction ``P`` acts along
``b = n + s mu w`` (the normal and its friction), so the position and reactions solve
``K x - B P = f``, ``N^T x = 0`` (``N``, ``B``: the contacts' ``n`` and ``b`` as columns; every
``P > 0``, else the contact would open). Small motions keep ``N^T y = 0``: the reactions follow
from ``N^T y'' = 0``, ``p = H^-1 N^T M^-1 (C_eff y' + K_eff y)`` with ``H = N^T M^-1 B``, which must
be a P-matrix (every principal minor positive: a unique reaction for every load; else friction
makes the contact's reaction ill-posed, the Painleve paradox), and the flow on ``y = Z q``
(``Z`` an orthonormal basis of the motions that keep the contacts closed) is
``q'' = -Z^T L (K_eff Z q + C_eff Z q')``, ``L = M^-1 - M^-1 B H^-1 N^T M^-1``: ``2 (n - m)``
eigenvalues for ``m`` rigid contacts.
"""

from __future__ import annotations

from dataclasses import dataclass

import itertools

import numpy as np
import lazy_loader as lazy
from scipy.linalg import null_space

from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..results import Result
from .model import System

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["SteadySliding", "steady_sliding"]


@dataclass(frozen=True, eq=False, repr=False)
class SteadySliding(Result):
    """The resting position ``x`` under sliding contacts, each contact's ``friction_force``,
    the effective damping matrix and the ``eigenvalues`` of the linearised flow (by decreasing
    real part)."""

    x: np.ndarray
    friction_force: np.ndarray
    effective_damping: np.ndarray
    eigenvalues: np.ndarray
    MODEL = "system"

    @property
    def marginal(self) -> bool:
        """The largest real part is zero to round-off (``1e3 eps`` of the largest eigenvalue): an
        undamped structure under Coulomb contacts, a damping that friction cancels exactly. Linear
        stability does not decide then."""
        scale = float(np.abs(self.eigenvalues).max()) if self.eigenvalues.size else 0.0
        return bool(abs(self.growth_rate) <= 1e3 * np.finfo(float).eps * scale)

    @property
    def stable(self) -> bool:
        """Every eigenvalue with a negative real part, beyond round-off (False when `marginal`)."""
        return bool(np.all(self.eigenvalues.real < 0)) and not self.marginal

    @property
    def growth_rate(self) -> float:
        """The largest real part of the eigenvalues (1/s) — positive when steady sliding is unstable."""
        return float(self.eigenvalues.real.max())

    def to_dict(self) -> dict:
        return {"stable": self.stable, "marginal": self.marginal, "growth_rate": self.growth_rate, "x": self.x.tolist(),
                "friction_force": self.friction_force.tolist(),
                "eigenvalue_real": self.eigenvalues.real.tolist(), "eigenvalue_imag": self.eigenvalues.imag.tolist()}

    def to_xarray(self) -> xr.Dataset:
        """Units and meanings from the declarations (`stickslip.cf.finish`)."""
        ds = xr.Dataset(
            {"x": ("dof", self.x), "friction_force": ("contact", self.friction_force),
             "eigenvalue_real": ("mode", self.eigenvalues.real), "eigenvalue_imag": ("mode", self.eigenvalues.imag)},
            coords={"dof": np.arange(self.x.size), "contact": np.arange(self.friction_force.size),
                    "mode": np.arange(self.eigenvalues.size)},
            attrs={"stable": int(self.stable), "marginal": int(self.marginal), "growth_rate": self.growth_rate})
        return finish(ds, "system with frictional contacts: steady sliding and its linear stability", "system")


def steady_sliding(system: System) -> SteadySliding:
    """Steady sliding of ``system`` (every contact's surface moving) and its linear stability."""
    if not isinstance(system, System):
        raise ParameterError("system", system, "a stickslip.system.System")
    system.unforced("steady sliding")
    for i, c in enumerate(system.contacts):
        if not hasattr(c.friction, "kinetic"):
            raise ParameterError(f"contacts[{i}].friction", type(c.friction).__name__, "a law of the slip speed; "
                                 "steady sliding with rate-and-state laws: stickslip.system.rate_state_steady")
    n = system.dofs
    forces = np.empty(len(system.contacts))
    c_eff = system.damping.copy()
    k_eff = system.stiffness.copy()
    load = system.force.copy()
    for i, c in enumerate(system.contacts):
        speed = abs(c.surface_speed)
        if speed == 0.0:
            raise ParameterError(f"contacts[{i}].surface_speed", c.surface_speed,
                                 "nonzero for steady sliding (a contact on a surface at rest sticks)")
        if speed >= c.friction.max_speed:
            raise ParameterError(f"contacts[{i}].surface_speed", c.surface_speed,
                                 f"below the speed {c.friction.max_speed:g} where its friction law ends")
        mu, sign = float(c.friction.kinetic(speed)), float(np.sign(c.surface_speed))
        if c.rigid:  # its reaction: the constraint's (below)
            continue
        if c.unilateral:  # N(x) = N0 - k_n n.x pushes along n; the friction s mu N(x) along w (Coulomb)
            k_n, nv, w = c.normal_stiffness, c.normal_direction, c.direction
            push = 1.0 if c.pushes else 0.0  # without: the reaction of an eliminated constraint
            k_eff += push * k_n * np.outer(nv, nv) + sign * mu * k_n * np.outer(w, nv)
            load += (push * nv + sign * mu * w) * c.normal_force
            continue
        forces[i] = c.normal_force * sign * mu
        load += c.direction * forces[i]
        slope = float(c.friction.slope(speed))  # d mu / d v_r at v_r = |V|; mu is even in v_r
        c_eff += c.normal_force * slope * np.outer(c.direction, c.direction)
    rigid = [i for i, c in enumerate(system.contacts) if c.rigid]
    N, B = _directions(system, rigid)
    x, reactions = _position(k_eff, load, N, B)
    for i, c in enumerate(system.contacts):
        if c.unilateral and not c.rigid:
            normal = float(c.normal_row(n)[:n] @ x + c.normal_force)
            if normal <= 0.0:
                raise NoSolutionError(f"contact {i} is open at the resting position (its normal force would be "
                                      f"{normal:.6g} N): no steady sliding on it")
            forces[i] = np.sign(c.surface_speed) * float(c.friction.kinetic(abs(c.surface_speed))) * normal
            slope = float(c.friction.slope(abs(c.surface_speed)))  # a law of the slip speed: N(x) mu' in the damping
            c_eff += normal * slope * np.outer(c.direction, c.direction)
    for i, p in zip(rigid, reactions):
        if not p > 0.0:
            raise NoSolutionError(f"contact {i} (rigid) would pull on its surface at the resting position (its "
                                  f"reaction would be {p:.6g} N): it opens; no steady sliding with it closed")
        c = system.contacts[i]
        forces[i] = np.sign(c.surface_speed) * float(c.friction.kinetic(abs(c.surface_speed))) * p
    flow = _constrained(system, rigid, N, B, k_eff, c_eff)
    eig = np.linalg.eigvals(flow)
    eig = eig[np.lexsort((-eig.imag, -eig.real))]
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(eig))):
        raise NoSolutionError("steady sliding overflows: the loads or the stiffness are out of scale")
    return SteadySliding(x, forces, c_eff, eig)


def _directions(system: System, rigid: list[int]) -> tuple[np.ndarray, np.ndarray]:
    """``N`` and ``B``: the rigid contacts' normals and their reactions' directions ``n + s mu w``."""
    cs = [system.contacts[i] for i in rigid]
    N = np.array([c.normal_direction for c in cs]).T.reshape(system.dofs, len(cs))
    B = N + np.array([np.sign(c.surface_speed) * float(c.friction.kinetic(abs(c.surface_speed))) * c.direction
                      for c in cs]).T.reshape(N.shape)
    return N, B


def _position(k_eff: np.ndarray, load: np.ndarray, N: np.ndarray, B: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The resting position and the rigid contacts' reactions: ``K x - B P = f``, ``N^T x = 0``."""
    n, m = N.shape
    scale = float(np.abs(k_eff).max()) or 1.0  # the reactions' columns on the stiffness's scale
    A = np.block([[k_eff, -scale * B], [scale * N.T, np.zeros((m, m))]])
    sv = np.linalg.svd(A, compute_uv=False)
    if sv[-1] <= 1e-13 * sv[0]:
        cond = f"condition number {sv[0] / sv[-1]:.3g}" if sv[-1] > 0 else "exactly singular"
        held = " and the rigid contacts' constraints (dependent normals?)" if m else ""
        raise NoSolutionError(f"the stiffness matrix (with the contacts' springs{held}) is singular to working "
                              f"accuracy ({cond} > 1e13): no resting position under sliding contacts can be computed "
                              "(a free body, a mechanism, or stiffnesses 13 decades apart)")
    sol = np.linalg.solve(A, np.concatenate([load, np.zeros(m)]))
    return sol[:n], scale * sol[n:]


#: Rigid contacts up to which `_constrained` checks every principal minor of ``H`` (beyond: a
#: sufficient condition, ``H + H^T`` positive definite).
MINORS_UP_TO = 12


def _constrained(system: System, rigid: list[int], N: np.ndarray, B: np.ndarray, k_eff: np.ndarray,
                 c_eff: np.ndarray) -> np.ndarray:
    """The linearised flow on the motions that keep the rigid contacts closed (the module; ``N``, ``B``:
    `_directions`)."""
    n, Minv = system.dofs, system.inverse_mass
    if not rigid:
        return np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ k_eff, -Minv @ c_eff]])
    H = N.T @ Minv @ B
    m = len(rigid)
    if m <= MINORS_UP_TO:
        bad = next((k for r in range(1, m + 1) for k in itertools.combinations(range(m), r)
                    if not np.linalg.det(H[np.ix_(k, k)]) > 1e-12 * np.abs(H).max() ** r), None)
    else:
        bad = None if np.linalg.eigvalsh(H + H.T).min() > 1e-12 * np.abs(H).max() else tuple(range(m))
    if bad is not None and m <= MINORS_UP_TO:
        named = ", ".join(str(rigid[k]) for k in bad)
        raise NoSolutionError(f"the reactions of the rigid contacts {named} are not determined by the motion "
                              "(N^T M^-1 (n + s mu w) is not a P-matrix: friction pulls the contact into its surface "
                              "faster than the normal pushes it out, the Painleve paradox): no steady sliding")
    if bad is not None:
        raise NoSolutionError(f"that the reactions of the {m} rigid contacts are determined by the motion could not "
                              f"be confirmed (N^T M^-1 (n + s mu w) + its transpose is not positive definite, and "
                              f"its principal minors are checked up to {MINORS_UP_TO} contacts only): no steady "
                              "sliding computed")
    if m >= n:
        raise NoSolutionError(f"the {m} rigid contacts hold every one of the {n} degrees of freedom: no motion is "
                              "left whose stability steady sliding would have")
    L = Minv - Minv @ B @ np.linalg.solve(H, N.T @ Minv)
    Z = null_space(N.T)
    k = n - m
    return np.block([[np.zeros((k, k)), np.eye(k)], [-Z.T @ L @ k_eff @ Z, -Z.T @ L @ c_eff @ Z]])

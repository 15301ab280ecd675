"""Steady sliding of a system and its linear stability.

With every surface moving (``V_i != 0``) the structure can rest while each contact slips at
``v_r = V_i``: the position solves ``K x = f + sum_i w_i N_i sign(V_i) mu_i(|V_i|)``. Small
motions about it obey ``M y'' + C_eff y' + K y = 0`` with

    C_eff = C + sum_i N_i mu_i'(|V_i|) w_i w_i^T

(a friction law falling with slip speed, ``mu' < 0``, feeds energy in: negative damping), and
steady sliding is stable when every eigenvalue of that linear flow has a negative real part.
A unilateral contact (normal force ``N(x) = N_0 - k_n n . x``) adds ``k_n n n^T`` and, through its
friction, ``sign(V) mu k_n w n^T`` to the stiffness: a matrix no longer symmetric, whose modes
may coalesce and flutter (mode-coupling instability, Hoffmann et al. 2002).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..results import Result
from .model import System

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
        """The largest real part of the eigenvalues (1/s): positive when steady sliding is unstable."""
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
        if c.rigid:
            raise ParameterError(f"contacts[{i}].rigid", True, "false for steady sliding in this version (a rigid "
                                 "contact's motion: simulate, limit_cycle)")
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
    sv = np.linalg.svd(k_eff, compute_uv=False)
    if sv[-1] <= 1e-13 * sv[0]:
        cond = f"condition number {sv[0] / sv[-1]:.3g}" if sv[-1] > 0 else "exactly singular"
        raise NoSolutionError(f"the stiffness matrix (with the contacts' springs) is singular to working accuracy "
                              f"({cond} > 1e13): no resting position under sliding contacts can be computed (a free "
                              "body, a mechanism, or stiffnesses 13 decades apart)")
    x = np.linalg.solve(k_eff, load)
    for i, c in enumerate(system.contacts):
        if c.unilateral:
            normal = float(c.normal_row(n)[:n] @ x + c.normal_force)
            if normal <= 0.0:
                raise NoSolutionError(f"contact {i} is open at the resting position (its normal force would be "
                                      f"{normal:.6g} N): no steady sliding on it")
            forces[i] = np.sign(c.surface_speed) * float(c.friction.kinetic(abs(c.surface_speed))) * normal
    Minv = system.inverse_mass
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ k_eff, -Minv @ c_eff]])
    eig = np.linalg.eigvals(A)
    eig = eig[np.lexsort((-eig.imag, -eig.real))]
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(eig))):
        raise NoSolutionError("steady sliding overflows: the loads or the stiffness are out of scale")
    return SteadySliding(x, forces, c_eff, eig)

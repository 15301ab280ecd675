"""Contact reactions recomputed from the motion, and the contact laws checked on them.

The kernel's node states satisfy Signorini's and Coulomb's laws by construction, so
checking them proves nothing. Here the reactions are recomputed from a `Trace` (every
step's displacements) through the scheme's relation between displacements and
accelerations,

    (u_{m+1} - 2 u_m + u_{m-1}) / dt^2 = (beta2 + 1/2) a_m + (1/2 - beta2) a_{m-1},

and the equations of motion ``M a_m + K u_m = C^T lambda_m``, with ``M`` and ``K`` supplied
by the caller (assembled independently of the kernel: the tests build their own, the
report uses each model's sparse matrices rather than its stencil). The recursion for
``a_m`` starts from zero and forgets its start at the rate ``(beta2 - 1/2)/(beta2 + 1/2)``
per step, so the first ``settle`` steps are dropped. The recomputed reactions must
vanish off the contact dofs, equal the kernel's, and obey the contact laws.
"""

from __future__ import annotations

import numpy as np

from ..quantities import COMMON as Q
from .energy import Trace

__all__ = ["implied_reactions", "contact_law_residuals"]


def implied_reactions(tr: Trace, mass, stiffness, settle: int = 40) -> tuple[np.ndarray, slice]:
    """Reactions per unit mass on every dof, from the motion, for steps ``settle + 1 .. M-1``.

    Parameters
    ----------
    tr : Trace
        From `stickslip.contact.energy.trace`.
    mass : number or array
        Lumped mass per dof.
    stiffness : matrix
        ``K`` on the same dofs (sparse or dense).
    settle : int
        Steps dropped at the start (>= 0).

    Returns the array ``r[step, dof]`` and the slice of the trace's steps it covers.
    """
    settle = Q.check("settle", settle)
    s = tr.scheme
    dt, b2 = s.dt, s.beta2
    mass = np.broadcast_to(np.asarray(mass, dtype=float), tr.u.shape[1:])
    d2 = (tr.u[2:] - 2 * tr.u[1:-1] + tr.u[:-2]) / dt**2  # steps m = 1 .. M-1
    a = np.empty_like(d2)
    prev = np.zeros(tr.u.shape[1])
    for m in range(d2.shape[0]):
        a[m] = prev = (d2[m] - (0.5 - b2) * prev) / (b2 + 0.5)
    force = mass * a + np.asarray((stiffness @ tr.u[1:-1].T)).T
    k = int(settle)
    return (force / mass)[k:], slice(k + 1, tr.steps)


def contact_law_residuals(tr: Trace, r: np.ndarray, steps: slice, friction: float) -> dict:
    """How far the recomputed reactions ``r`` (from `implied_reactions`) are from the laws.

    All relative to the largest normal reaction (or to the largest gap, for gaps), so that
    0 is exact: ``off_contact`` (largest reaction on a dof without contact), ``kernel`` (largest
    difference from the kernel's reactions), ``negative_pressure`` (``max(-r_n)``),
    ``penetration`` (``max(-gap)`` at ``t_{m+1}``), ``complementarity`` (``max |r_n gap|``),
    ``coulomb`` (``max(|r_t| - f r_n)``), ``stick_motion`` (largest slip speed where
    ``|r_t| < f r_n``, relative to the surface speed), ``slip_direction`` (largest share of
    friction at the limit not opposing the slip), with the counts of sticking and slipping
    node-steps.
    """
    s = tr.scheme
    (normal, tangent), (gap0, speed) = s.contact_dofs, s.surface
    scale = max(float(np.abs(tr.lam_n[steps]).max()), 1e-300)
    m = np.arange(tr.steps)[steps]
    gap = tr.u[m + 1][:, normal] - gap0
    gap_scale = max(float(np.abs(gap).max()), float(np.abs(gap0).max()), 1e-300)
    slip = speed - (tr.u[m + 1][:, tangent] - tr.u[m][:, tangent]) / s.dt  # surface minus node speed
    r_n, r_t = r[:, normal], r[:, tangent]
    tol = 1e-8 * scale
    stick = np.abs(r_t) < friction * r_n - tol
    limit = (np.abs(r_t) >= friction * r_n - tol) & (r_n > tol) & (np.abs(slip) > 1e-9 * max(np.abs(speed).max(), 1))
    free = np.setdiff1d(np.arange(r.shape[1]), np.concatenate([normal, tangent]))
    return {"off_contact": float(np.abs(r[:, free]).max() / scale) if free.size else 0.0,
            "kernel": float(max(np.abs(r_n - tr.lam_n[steps]).max(), np.abs(r_t - tr.lam_t[steps]).max()) / scale),
            "negative_pressure": float(max(0.0, -r_n.min()) / scale),
            "penetration": float(max(0.0, -gap.min()) / gap_scale),
            "complementarity": float(np.abs(r_n * gap).max() / (scale * gap_scale)),
            "coulomb": float(max(0.0, (np.abs(r_t) - friction * r_n).max()) / scale),
            "stick_motion": float(np.abs(slip[stick]).max() / max(np.abs(speed).max(), 1e-300)) if stick.any() else 0.0,
            "slip_direction": float(np.mean(np.sign(r_t[limit]) != np.sign(slip[limit]))) if limit.any() else 0.0,
            "stick_count": int(stick.sum()), "slip_count": int(limit.sum())}

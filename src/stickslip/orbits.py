"""Periodic orbits of smooth autonomous equations ``y' = f(y)``: shooting with Newton's method.

The orbit through ``y0`` with period ``T`` solves ``phi_T(y0) = y0``, with a phase condition that
fixes where on the orbit ``y0`` lies: ``(y0 - y_r) . f(y_r) = 0``, the plane through the previous
iterate ``y_r`` across the flow. The derivative of ``phi_T`` is the monodromy ``Phi(T)``, by
central differences of whole runs (Radau IIA; the variational equations, integrated with the
orbit, cost a Jacobian per evaluation and were 30 to 200 times slower on a rate-and-state block).
Each Newton step solves

    [ Phi - I    f(phi_T(y0)) ] [ dy ]     [ phi_T(y0) - y0        ]
    [ f(y_r)^T        0       ] [ dT ] = - [ (y0 - y_r) . f(y_r)   ]

The multipliers are the eigenvalues of ``Phi(T)``; one of them is 1, the flow's own. Everything
is done in scaled variables ``(y - y0) / scale`` (the caller's typical size of each variable: its
variation over the orbit), so that the tolerances (absolute in them) mean the same for every
variable: the runs' error about ``rtol``, the monodromy's about ``rtol / step``. Used by the
rate-and-state systems (`stickslip.system.rate_state_cycle`).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from .errors import NoSolutionError, ParameterError

__all__ = ["flow_map", "monodromy", "periodic_orbit"]


def flow_map(rhs, jac, y0: np.ndarray, T: float, rtol: float, atol: float | np.ndarray) -> np.ndarray:
    """``phi_T(y0)`` of ``y' = rhs(t, y)`` (Jacobian ``jac(t, y)``), by Radau IIA; a `NoSolutionError`
    where the integration fails."""
    try:
        sol = solve_ivp(rhs, (0.0, T), y0, method="Radau", rtol=rtol, atol=atol, jac=jac)
    except ParameterError:  # the model's own (a law out of its range)
        raise
    except ValueError:  # scipy refuses a Jacobian or a step that is not finite: the flow overflowed
        raise NoSolutionError(f"the flow over {T:.6g} s could not be integrated (its numbers left the range of "
                              "floats)") from None
    if sol.status != 0 or not np.all(np.isfinite(sol.y[:, -1])):
        raise NoSolutionError(f"the flow over {T:.6g} s could not be integrated (Radau: {sol.message})")
    return sol.y[:, -1]


def monodromy(rhs, jac, y0: np.ndarray, T: float, rtol: float, atol, step: float) -> np.ndarray:
    """``d phi_T / d y0`` by central differences of whole runs, ``step`` apart in each variable."""
    n = y0.size
    out = np.empty((n, n))
    for j in range(n):
        d = np.zeros(n)
        d[j] = step
        out[:, j] = (flow_map(rhs, jac, y0 + d, T, rtol, atol) - flow_map(rhs, jac, y0 - d, T, rtol, atol)) / (2 * step)
    return out


def periodic_orbit(rhs, jac, y0, period: float, scale, *, rtol: float = 1e-9, tol: float = 1e-7,
                   max_iter: int = 30, step: float = 1e-4, flow=None) -> tuple[np.ndarray, float, np.ndarray]:
    """``(y0, T, multipliers)``: the periodic orbit of ``y' = rhs(t, y)`` near ``y0`` with period near
    ``period``, by Newton's method (see the module) until the return misses the start by at most
    ``tol`` in the scaled variables ``y / scale``; multipliers by decreasing modulus. A
    `NoSolutionError` saying what was tried when Newton's method does not converge. ``flow(y, T)``, if
    given, maps a state over ``T`` in place of Radau on ``rhs`` (a flow with switches: ``rhs`` then
    gives the vector field at the start and at the end, off the switches)."""
    s = np.asarray(scale, dtype=float)
    c = np.asarray(y0, dtype=float).copy()  # the variables measured from the start: all of order one or less
    u = np.zeros_like(c)
    T = float(period)

    def f(t, v):
        return rhs(t, c + v * s) / s

    def J(t, v):
        return jac(t, c + v * s) * s[None, :] / s[:, None]

    def phi(v, T):
        return flow_map(f, J, v, T, rtol, rtol) if flow is None else (flow(c + v * s, T) - c) / s

    def derivative(v, T):
        if flow is None:
            return monodromy(f, J, v, T, rtol, rtol, step)
        out = np.empty((v.size, v.size))
        for j in range(v.size):
            d = np.zeros(v.size)
            d[j] = step
            out[:, j] = (phi(v + d, T) - phi(v - d, T)) / (2 * step)
        return out

    miss, n = np.inf, c.size
    for it in range(max_iter):
        end = phi(u, T)
        residual = end - u
        miss = float(np.abs(residual).max())
        Phi = derivative(u, T)
        if miss <= tol:
            mult = np.linalg.eigvals(Phi)
            return c + u * s, T, mult[np.argsort(-np.abs(mult))]
        A = np.zeros((n + 1, n + 1))
        A[:n, :n] = Phi - np.eye(n)
        A[:n, n] = f(0.0, end)
        A[n, :n] = f(0.0, u)
        delta = np.linalg.lstsq(A, -np.concatenate([residual, [0.0]]), rcond=None)[0]
        limit = 0.5 / max(float(np.abs(delta[:n]).max()), 1e-300)  # at most half the orbit's size in one step
        damp = min(1.0, limit, 0.5 * T / max(abs(delta[n]), 1e-300))
        u, T = u + damp * delta[:n], T + damp * delta[n]
        if not (T > 0 and np.all(np.isfinite(u))):
            break
    raise NoSolutionError(f"Newton's method on the periodic orbit did not converge in {max_iter} iterations from a "
                          f"period of {period:.6g} s (the return missed the start by {miss:.3g} of the orbit's size): "
                          "no periodic orbit near this start (a longer transient, or another start)")

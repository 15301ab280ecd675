"""One piece of a slider's load history (a constant load velocity) integrated with the kernels of
`stickslip.rsf.kernel`.

LSODA (scipy's ``odeint``: Adams while the equations are mild, BDF once they stiffen) with the
equations and their Jacobian: interpreted while the process's interpreted work stays within its
allowance (`stickslip.jit`: a short run pays no numba start-up), else compiled. LSODA's error test
passes a step whose error is NaN, so a step that leaves the range of the numbers stops it (the
equations' rates not finite); the piece is then solved again by Radau IIA (scipy's ``solve_ivp``,
which shortens such a step), with the compiled kernels: slower, as robust as the slider was before
it had compiled equations.
"""

from __future__ import annotations

import warnings

import numpy as np
from scipy.integrate import ODEintWarning, odeint, solve_ivp

from ..errors import NoSolutionError
from .kernel import KERNELS, MASS

__all__ = ["solve_piece", "MAX_CALLS", "CALL_COST"]

#: The most evaluations of the equations per piece of a history (some 250 stick-slip cycles).
MAX_CALLS = 1_000_000
#: An interpreted evaluation of the equations or the Jacobian with LSODA's call (estimated microseconds).
CALL_COST = 10.0


class _Stop(Exception):
    """Raised out of an integrator's call: ``args = (why, t)``."""


def solve_piece(p: np.ndarray, y: np.ndarray, at: np.ndarray, rtol: float) -> tuple[np.ndarray, int]:
    """The states at the times ``at`` (the first, the start ``y``; increasing) and the steps taken,
    for the parameters ``p`` (`stickslip.rsf.kernel.pack`) at relative tolerance ``rtol``."""
    calls = [0]
    allowance = KERNELS.left / CALL_COST
    tried = []
    if allowance >= 1.0:
        try:
            return _lsoda(KERNELS.interpreted, p, y, at, rtol, calls, allowance)
        except _Stop as stop:
            tried.append(stop.args)
        finally:
            KERNELS.charge(KERNELS.interpreted, CALL_COST * calls[0])
    if not tried or tried[-1][0] == "allowance":
        try:
            return _lsoda(KERNELS.compiled, p, y, at, rtol, calls, MAX_CALLS)
        except _Stop as stop:
            tried.append(stop.args)
    if tried[-1][0] != "calls":
        try:
            return _radau(p, y, at, rtol, calls)
        except _Stop as stop:
            tried.append(stop.args)
    why, t = tried[-1]
    if why == "calls":
        raise NoSolutionError(f"more than {MAX_CALLS:.0e} evaluations of the equations by t = {t:.6g} s of a piece "
                              f"from {at[0]:.6g} to {at[-1]:.6g} s: a shorter t_end, or a looser rtol")
    hint = " (quasi-static: a slip rate running away, which inertia would bound?)" if p[MASS] == 0.0 else ""
    raise NoSolutionError(f"the slider's integration failed at t = {t:.6g} s ({why}): the slip rate or the state left "
                          f"the range of the numbers, or its time scale fell below the spacing of the times{hint}")


def _evaluations(kernels, p, size, calls, limit):
    """``(f, df)`` counting their calls, stopping at ``limit`` and at rates that are not finite
    (Python's math raises where IEEE arithmetic gives inf)."""
    rate, jac = np.empty(size), np.empty((size, size))

    def f(t, z):
        calls[0] += 1
        if calls[0] > limit:
            raise _Stop("calls" if limit == MAX_CALLS else "allowance", t)
        try:
            kernels.rhs(z, p, rate)
        except (ArithmeticError, ValueError):
            rate[:] = np.nan
        return rate

    def df(t, z):
        calls[0] += 1
        try:
            kernels.jacobian(z, p, jac)
        except (ArithmeticError, ValueError):
            jac[:] = np.nan
        return jac

    return f, df


def _lsoda(kernels, p, y, at, rtol, calls, limit):
    f, df = _evaluations(kernels, p, y.size, calls, limit)

    def guarded(t, z):
        rate = f(t, z)
        if not np.all(np.isfinite(rate)):
            raise _Stop("a rate beyond the numbers", t)
        return rate

    with np.errstate(over="ignore", invalid="ignore", divide="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore", ODEintWarning)  # its failure is read from its output
        ys, info = odeint(guarded, y, at, Dfun=df, tfirst=True, rtol=rtol, atol=rtol * np.maximum(1.0, np.abs(y)),
                          mxstep=MAX_CALLS, full_output=True, printmessg=False, tcrit=at[-1:])
    if info["message"] != "Integration successful." or not np.all(np.isfinite(ys)):
        raise _Stop(info["message"].rstrip("."), float(np.max(info["tcur"], initial=at[0])))
    return ys, int(info["nst"][-1])


def _radau(p, y, at, rtol, calls):
    f, df = _evaluations(KERNELS.compiled, p, y.size, calls, MAX_CALLS)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        try:
            sol = solve_ivp(lambda t, z: f(t, z).copy(), (at[0], at[-1]), y, method="Radau", rtol=rtol,
                            atol=rtol * np.maximum(1.0, np.abs(y)), jac=lambda t, z: df(t, z).copy(), dense_output=True)
        except ValueError as err:  # scipy refuses a Jacobian or a step that overflowed
            raise _Stop(str(err), at[0]) from None
        if sol.status != 0 or not np.all(np.isfinite(sol.y[:, -1])):
            raise _Stop(sol.message.rstrip("."), float(sol.t[-1]))
        ys = sol.sol(at).T
    ys[0], ys[-1] = y, sol.y[:, -1]
    return ys, sol.t.size - 1

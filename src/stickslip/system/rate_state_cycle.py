"""Limit cycles of systems with rate-and-state contacts, and their Floquet multipliers.

The motion is smooth (no contact sticks), so a cycle is a periodic orbit of the equations in
``y = (x, x', psi)``: found by shooting with Newton's method, its monodromy from the
variational equations (`stickslip.orbits`). The start: the motion from a perturbed steady
sliding (or a given start) after a transient, the period between its last two upward crossings
of contact 0's slip rate through its surface speed. An unstable cycle (beyond a subcritical Hopf
point) is found too when the start is near it; from a transient, a motion settles only on a
stable one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy

from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..orbits import periodic_orbit
from ..quantities import COMMON, SYSTEM as Q
from ..results import Result
from .floquet import without_own
from .model import System
from .rate_state import (LONGEST, METHODS, RateStateEquations, RateStateRun, rate_state_simulate, rate_state_steady,
                         slowest_state_time)
from .rate_state_modes import first_mode

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["RateStateCycle", "rate_state_cycle", "orbit_maps", "orbit_size", "psi_lists", "run_states"]

#: Samples per period of the linear oscillation in the transient (where the period is read).
SAMPLES_PER_PERIOD = 200
#: A swing of the slip rate smaller by this fraction than a period before: the motion still decays (0.1 %
#: took the wandering sampled heights of sharp slip bursts for a decay).
DECAY = 1e-2


@dataclass(frozen=True, eq=False, repr=False)
class RateStateCycle(Result):
    """A limit cycle of a system integrated between its switches (rate-and-state contacts, or laws not
    affine in the slip speed): its ``period``, the state ``x0``, ``v0``, ``psi0`` (one array per
    rate-and-state contact; empty without one) where contact 0's slip rate crosses its surface speed
    upward, the ``multipliers`` (by decreasing modulus; one is the flow's own 1), each contact's
    smallest and largest slip rate over the cycle (``slip_rate_min``, ``slip_rate_max``) and the
    half peak-to-peak ``amplitude`` of each degree of freedom."""

    period: float
    x0: np.ndarray
    v0: np.ndarray
    psi0: tuple
    multipliers: np.ndarray
    slip_rate_min: np.ndarray
    slip_rate_max: np.ndarray
    amplitude: np.ndarray
    MODEL = "system"

    @property
    def stable(self) -> bool:
        """Every multiplier but the flow's own inside the unit circle."""
        return bool(np.all(np.abs(without_own(self.multipliers)) < 1.0))

    def to_dict(self) -> dict:
        return {"period": self.period, "stable": self.stable, "multipliers_abs": np.abs(self.multipliers).tolist(),
                "amplitude": self.amplitude.tolist(), "slip_rate_min": self.slip_rate_min.tolist(),
                "slip_rate_max": self.slip_rate_max.tolist(), "x0": self.x0.tolist(), "v0": self.v0.tolist(),
                "psi0": [p.tolist() for p in self.psi0]}

    def to_xarray(self) -> xr.Dataset:
        """Units and meanings from the declarations (`stickslip.cf.finish`)."""
        m = self.multipliers
        ds = xr.Dataset(
            {"multiplier_real": ("multiplier", m.real), "multiplier_imag": ("multiplier", m.imag),
             "x0": ("dof", self.x0), "v0": ("dof", self.v0), "amplitude": ("dof", self.amplitude),
             "slip_rate_min": ("contact", self.slip_rate_min), "slip_rate_max": ("contact", self.slip_rate_max)},
            coords={"dof": np.arange(self.x0.size), "contact": np.arange(self.slip_rate_min.size)},
            attrs={"period": self.period, "stable": int(self.stable)})
        return finish(ds, "system with rate-and-state contacts: limit cycle and its Floquet multipliers", "system")


def run_states(eq: RateStateEquations, run: RateStateRun) -> np.ndarray:
    """The samples of ``run`` as rows of ``y = (x, x', psi)``."""
    psi = [run.psi[:, i, :law.states] for i, law in enumerate(eq.laws) if eq.rsf[i]]
    return np.hstack([run.x, run.v, *psi])


def _swing(run: RateStateRun, rsf: bool, a: int, b: int) -> float:
    """Contact 0's swing of slip rate from sample ``a`` to ``b``: in its logarithm for a rate-and-state
    contact, else in m/s (it may stick: zero)."""
    rate = run.slip_rate[a:b, 0]
    return float(np.ptp(np.log(rate)) if rsf else np.ptp(rate))


def _crossings(run: RateStateRun, V: float) -> np.ndarray:
    """Sample indices after which contact 0's slip rate crosses ``V`` upward (log scale)."""
    r = np.log(np.maximum(run.slip_rate[:, 0], 1e-300) / V) if V > 0 else run.slip_rate[:, 0] - V
    return np.nonzero((r[:-1] < 0) & (r[1:] >= 0))[0]


def orbit_size(span: np.ndarray) -> np.ndarray:
    """Each variable's range over the rows ``span`` of an orbit (at least 1e-9 of its size): Newton's scale."""
    return np.maximum(np.ptp(span, axis=0), 1e-9 * np.maximum(np.abs(span).max(axis=0), 1e-300))


def psi_lists(eq: RateStateEquations, y: np.ndarray) -> list:
    """The state variables in ``y``, one array per rate-and-state contact (a run's ``psi0``)."""
    return [eq.psi(y, i).copy() for i in range(len(eq.laws)) if eq.rsf[i]]


def orbit_maps(system: System, eq: RateStateEquations, rtol: float, method: str = "auto"):
    """``(field, flow)`` for `stickslip.orbits.periodic_orbit`: the smooth equations (flow None: Radau on
    them) or, with contacts that stick, runs with their switches and the field in the state's mode."""
    if all(eq.rsf):
        return eq.guarded, None
    n = eq.n

    def flow(y, T):
        run = rate_state_simulate(system, y[:n], y[n:2 * n], T, psi0=psi_lists(eq, y), samples=2, rtol=rtol,
                                  method=method)
        return run_states(eq, run)[-1]

    def field(t, y):
        first_mode(eq, y)
        return eq.guarded(t, y)
    return field, flow


def rate_state_cycle(system: System, x0=None, v0=None, *, psi0=None, transient: float | None = None,
                     rtol: float = 1e-9, tol: float = 1e-7, max_iter: int = 30,
                     method: str = "auto") -> RateStateCycle:
    """The limit cycle the motion from ``(x0, v0, psi0)`` (default: steady sliding with contact 0's
    first state variable raised by 0.01) settles on after ``transient`` seconds (default: the time
    for steady sliding's leading growth rate to multiply it by 1000, and 20 periods), solved by
    Newton's method to ``tol`` (of each variable's range over the cycle; the runs by
    `rate_state_simulate` at ``rtol`` with its ``method``, the monodromy by central differences:
    multipliers to about ``1e4 rtol``)."""
    if not isinstance(method, str) or method not in METHODS:
        raise ParameterError("method", method, "one of " + ", ".join(METHODS))
    eq = RateStateEquations(system)
    system.unforced("a limit cycle")
    rtol, tol, max_iter = Q.check("rtol", rtol), COMMON["tol"].check(tol, "tol"), Q.check("max_iter", max_iter)
    steady = rate_state_steady(system)
    lead = steady.eigenvalues[0]
    if abs(lead.imag) == 0.0:
        raise NoSolutionError("steady sliding's leading eigenvalue is real: no oscillation to follow to a cycle")
    linear = 2.0 * math.pi / abs(lead.imag)
    scale = slowest_state_time(eq)
    if transient is None:  # the perturbation's growth to the cycle's size, then 20 periods to settle
        transient = min(math.log(1e3) / max(lead.real, 1e-300) + 20.0 * linear, 0.9 * LONGEST * scale,
                        Q["transient"].range.hi)
    transient = Q.check("transient", transient)
    if x0 is None and v0 is None and psi0 is None:
        if steady.psi:
            psi0 = [p.copy() for p in steady.psi]
            psi0[0][0] += 0.01
        else:  # no state variable: contact 0's slip rate raised by 1 % of its surface speed
            w = system.contacts[0].direction
            x0, v0 = steady.x, -0.01 * float(eq.V[0]) * w / float(w @ w)
    samples = int(min(2e5, max(2001, SAMPLES_PER_PERIOD * transient / linear)))
    try:
        run = rate_state_simulate(system, x0, v0, transient, psi0=psi0, samples=samples, rtol=rtol, method=method)
    except ParameterError as err:
        if err.name != "t_end":
            raise
        raise ParameterError("transient", transient, err.allowed, also=err.also) from None
    V0 = float(eq.V[0])
    up = _crossings(run, abs(V0))
    if up.size < 5:
        raise NoSolutionError("fewer than five upward crossings of contact 0's slip rate through its surface speed "
                              f"in the transient of {transient:.6g} s: the motion settled (steady sliding is stable, "
                              "or the cycle is far from this start), no cycle to follow")
    Y = run_states(eq, run)
    swing = np.array([_swing(run, eq.rsf[0], a + 1, b + 2) for a, b in zip(up[-5:-1], up[-4:])])
    if np.all(swing[1:] < (1.0 - DECAY) * swing[:-1]):  # shrinking period after period (four swings)
        raise NoSolutionError(f"the oscillation still decays at the end of the transient of {transient:.6g} s (contact "
                              f"0's slip rate swings {swing[-1]:.3g} in its logarithm, {swing[0]:.3g} "
                              f"{swing.size - 1} periods before): toward steady sliding, no cycle to settle on (a "
                              "longer transient if it is still settling)")
    last = Y[up[-1] + 1]
    period = float(run.t[up[-1] + 1] - run.t[up[-2] + 1])
    span = Y[up[-2] + 1:up[-1] + 2]
    size = orbit_size(span)
    if np.all(np.ptp(span[:, :eq.n], axis=0) <= 1e-9 * np.maximum(np.abs(span[:, :eq.n]).max(axis=0), 1e-300)):
        raise NoSolutionError("the motion settled to steady sliding in the transient: no cycle to follow")
    n = eq.n
    field, flow = orbit_maps(system, eq, rtol, method)
    y0, period, mult = periodic_orbit(field, eq.guarded_jacobian, last, period, size, rtol=rtol, tol=tol,
                                      max_iter=max_iter, flow=flow)
    if np.all(np.abs(mult - 1.0) > 1e-3) or np.max(np.abs((y0 - last) / size)) > 1e3:
        raise NoSolutionError("Newton's method left the cycle for steady sliding (no multiplier is the flow's own 1): "
                              "no cycle near the motion after the transient")
    one = rate_state_simulate(system, y0[:n], y0[n:2 * n], period, psi0=psi_lists(eq, y0), samples=2001, rtol=rtol,
                              method=method)
    return RateStateCycle(period, y0[:n].copy(), y0[n:2 * n].copy(), tuple(psi_lists(eq, y0)), mult,
                          one.slip_rate.min(axis=0), one.slip_rate.max(axis=0), 0.5 * np.ptp(one.x, axis=0))

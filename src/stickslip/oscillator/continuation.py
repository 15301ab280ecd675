"""Pseudo-arclength continuation of limit cycles in one parameter (default: belt speed).

Unknowns ``u = (x_s, p)``: the cycle's point on the section ``v = 0`` and the
parameter. A branch is a curve of ``G(x_s, p) = P(x_s; p) - x_s = 0``; arclength
parametrisation lets it turn at folds. ``G_x = P'(x_s) - 1`` comes from the monodromy,
``G_p`` from a finite difference. Along the branch we watch for

* grazing: the cycle stops (or starts) touching the stick segment, located by
  bisection; the branch ends there, since at a grazing-sliding fold two branches meet
  at a corner that arclength continuation cannot turn;
* stability changes (the non-trivial Floquet multiplier crossing the unit circle);
* the Hopf point, where the cycle shrinks onto the equilibrium and the branch ends.
"""

from __future__ import annotations

from typing import ClassVar

import math
from dataclasses import dataclass, field

import numpy as np
import lazy_loader as lazy

from ..results import Result
from ..cf import finish
from .. import validation as check
from ..quantities import OSCILLATOR as Q, lookup
from ..errors import NoSolutionError, ParameterError
from .cycle import LimitCycle, characterise, limit_cycle, return_map, solve_section
from .model import Oscillator
from .simulate import Engine, params_attrs

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["Branch", "continue_cycle"]


@dataclass(repr=False)
class Branch(Result):
    """Limit cycles along a parameter; ``events`` lists grazing and stability changes."""

    MODEL: ClassVar[str] = "oscillator"

    parameter: str
    values: np.ndarray
    cycles: list[LimitCycle]
    end_reason: str
    events: list[dict] = field(default_factory=list)

    def to_xarray(self) -> xr.Dataset:
        c = self.cycles
        mult = np.array([cy.nontrivial_multiplier for cy in c], complex)
        col = lambda name: np.array([getattr(cy, name) for cy in c], float)
        ds = xr.Dataset(
            {
                "parameter_value": ("point", self.values, {"long_name": f"value of {self.parameter}",
                                                           "units": (lookup(self.parameter, "oscillator") or ("1",))[0]}),
                "period": ("point", col("period"), {"units": "s"}),
                "amplitude": ("point", col("amplitude"), {"units": "m"}),
                "x_min": ("point", col("x_min"), {"units": "m"}),
                "x_max": ("point", col("x_max"), {"units": "m"}),
                "v_min": ("point", col("v_min"), {"units": "m/s"}),
                "v_max": ("point", col("v_max"), {"units": "m/s"}),
                "stick_time": ("point", col("stick_time"), {"units": "s"}),
                "slip_time": ("point", col("slip_time"), {"units": "s"}),
                "reverse_slip_time": ("point", col("reverse_slip_time"), {"units": "s"}),
                "multiplier_re": ("point", mult.real, {"long_name": "non-trivial Floquet multiplier, real part"}),
                "multiplier_im": ("point", mult.imag),
                "stable": ("point", np.array([cy.stable for cy in c], "i1")),
                "touches_stick": ("point", np.array([cy.touches_stick for cy in c], "i1")),
            },
            coords={"point": ("point", np.arange(len(c)), {"long_name": "point number along the branch"})},
            attrs={"continuation_parameter": self.parameter, "end_reason": self.end_reason,
                   "events": "; ".join(", ".join(f"{k} {v}" for k, v in e.items()) for e in self.events)},
        )
        return finish(ds, f"periodic orbits of the friction oscillator continued in {self.parameter}", "oscillator",
                      params=params_attrs(c[0].oscillator))

    def to_dict(self) -> dict:
        return {"parameter": self.parameter, "end_reason": self.end_reason, "events": self.events,
                "points": [{self.parameter: float(p), **cy.to_dict()} for p, cy in zip(self.values, self.cycles)]}


class _Problem:
    """``G(u)`` in scaled variables ``u = (x_s / Lx, p / Lp)``."""

    def __init__(self, osc: Oscillator, parameter: str, method: str, rtol: float):
        self.osc, self.parameter, self.method, self.rtol = osc, parameter, method, rtol
        self.Lx = osc.friction.static * osc.normal_force / osc.stiffness or abs(osc.equilibrium) or 1.0
        self.Lp = abs(osc.parameter(parameter))
        self.engine = self._engine  # overridable in tests

    def set_range(self, stop: float):
        """Scale the parameter by the length of the continuation interval."""
        self.Lp = abs(stop - self.osc.parameter(self.parameter))

    def oscillator(self, u) -> Oscillator:
        return self.osc.with_parameter(self.parameter, u[1] * self.Lp)

    def _engine(self, u) -> Engine:
        return Engine(self.oscillator(u), self.method, self.rtol, variational=True)

    def residual(self, u):
        """``G``, ``dG/du`` and the return map at ``u``."""
        engine = self.engine(u)
        rm = return_map(engine, u[0] * self.Lx)
        g = (rm.x_next - rm.x) / self.Lx
        h = 1e-7 * max(1.0, abs(u[1]))
        rm_p = return_map(self.engine((u[0], u[1] + h)), u[0] * self.Lx)
        g_p = ((rm_p.x_next - rm_p.x) / self.Lx - g) / h
        return g, np.array([rm.derivative - 1.0, g_p]), engine, rm

    def amplitude(self, u) -> float:
        return abs(self.oscillator(u).equilibrium - u[0] * self.Lx) / self.Lx


def _correct(problem: _Problem, u_pred, tangent, tol, max_iter=12):
    """Newton on ``[G(u) = 0, tangent . (u - u_pred) = 0]``."""
    u = np.array(u_pred, float)
    previous = math.inf
    for it in range(max_iter):
        try:
            g, dg, engine, rm = problem.residual(u)
        except (NoSolutionError, ParameterError):  # no cycle, or an iterate past the valid range
            return None
        if it >= 3 and abs(g) > 0.5 * previous:  # not converging: let the caller shrink the step
            return None
        previous = abs(g)
        jac = np.array([dg, tangent])
        rhs = -np.array([g, tangent @ (u - u_pred)])
        try:
            du = np.linalg.solve(jac, rhs)
        except np.linalg.LinAlgError:
            return None
        u = u + du
        if abs(g) < tol and np.linalg.norm(du) < 1e3 * tol:
            return u, it + 1
    return None


def continue_cycle(osc: Oscillator, stop: float, *, parameter: str = "belt_speed", step: float = 0.02,
                   max_step: float = 0.1, min_step: float = 1e-5, max_points: int = 300,
                   x0: float | None = None, v0: float | None = None, method: str = "auto",
                   rtol: float = 1e-12, tol: float = 1e-10) -> Branch:
    """Continue the limit cycle found from ``(x0, v0)`` at the oscillator's parameter value.

    Parameters
    ----------
    osc : Oscillator
        Starting point; its value of ``parameter`` is the first point of the branch.
    stop : float
        Continue towards this parameter value. The branch ends when the parameter
        leaves the interval between start and stop, at a Hopf point (amplitude -> 0),
        at a grazing point (the cycle starts or stops touching the stick segment: the
        branch has a corner there, so the other side is a separate branch, see
        `continue_from_hopf`), where no cycle can be found, or after ``max_points``.
    parameter : str
        Any name of `Oscillator.parameter_names` (``belt_speed``, ``damping``, ``tau``...).
    step, max_step, min_step : float
        Arclength steps in scaled units (parameter relative to its start value,
        section coordinate relative to ``f_s N / k``).
    """
    check.instance("osc", osc, Oscillator, "a stickslip.oscillator.Oscillator")
    start = osc.parameter(parameter)
    stop = Q.check("stop", stop)
    if stop == start:
        raise ParameterError("stop", stop, f"different from the start value {start:g}")
    try:  # the branch may run up to stop: it must be a valid value of the parameter
        osc.with_parameter(parameter, stop)
    except ParameterError as err:
        raise ParameterError("stop", stop, f"a valid {parameter}, {err.allowed}", also=err.also) from None
    min_step = Q.check("min_step", min_step)
    step = check.at_least("step", Q.check("initial_step", step, "step"), min_step, "min_step")
    max_step = check.at_least("max_step", Q.check("max_step", max_step), step, "step")
    Q.check("max_points", max_points)
    problem = _Problem(osc, parameter, method, rtol)
    problem.set_range(stop)
    lo, hi = sorted((start / problem.Lp, stop / problem.Lp))

    first = limit_cycle(osc, x0, v0, method=method, rtol=rtol)
    u = np.array([first.section_x / problem.Lx, start / problem.Lp])
    g, dg, _, _ = problem.residual(u)
    direction = math.copysign(1.0, stop - start)
    tangent = np.array([-dg[1] / dg[0] if abs(dg[0]) > 1e-12 else 0.0, 1.0]) * direction
    tangent /= np.linalg.norm(tangent)

    values, cycles, events = [start], [first], []
    end_reason, ds = f"reached max_points = {max_points}", step
    while len(cycles) < max_points:
        result = _correct(problem, u + ds * tangent, tangent, tol)
        if result is None or not (lo - 1e-12 <= result[0][1] <= hi + 1e-12):
            if result is not None:  # stepped past the end: land exactly on it
                end_reason = f"reached {parameter} = {stop:g}"
                p_end = stop / problem.Lp
                if abs(tangent[1]) > 1e-12 and abs(u[1] - p_end) > 1e-12:
                    guess = u + tangent * (p_end - u[1]) / tangent[1]
                    landed = _correct(problem, guess, np.array([0.0, 1.0]), tol)
                    if landed is not None:
                        engine = problem.engine(landed[0])
                        values.append(stop)
                        cycles.append(characterise(engine, return_map(engine, landed[0][0] * problem.Lx)))
                break
            ds *= 0.5
            if ds >= min_step:
                continue
            end_reason = "no cycle beyond this point (corrector failed at the minimum step)"
            # a branch ending at a corner (grazing-sliding fold): locate it
            p_end = _locate_grazing(problem, u, u + step * tangent, tol)
            if math.isfinite(p_end):
                touching = cycles[-1].touches_stick
                events.append({"kind": "grazing", parameter: p_end, "touches_stick_after": not touching})
                end_reason = (f"branch ends at {parameter} = {p_end:.10g}: " + (
                    "beyond it the orbit leaving the stick segment no longer returns to v = V (grazing); "
                    f"stick time at the last branch point {cycles[-1].stick_time:.6g} s" if touching else
                    "the slip cycle grazes the stick segment (max velocity = V) and the branch turns at a corner"))
            break
        u_new, iterations = result
        try:
            engine = problem.engine(u_new)
            cycle = characterise(engine, return_map(engine, u_new[0] * problem.Lx))
        except NoSolutionError as exc:
            end_reason = str(exc)
            break
        if problem.amplitude(u_new) < min(1e-3, problem.amplitude(u)):
            events.append({"kind": "hopf", parameter: float(u_new[1] * problem.Lp)})
            end_reason = "the cycle shrinks onto the equilibrium (Hopf point)"
            values.append(u_new[1] * problem.Lp), cycles.append(cycle)
            break
        previous = cycles[-1]
        if cycle.touches_stick != previous.touches_stick:
            p_graze = _locate_grazing(problem, u, u_new, tol)
            events.append({"kind": "grazing", parameter: p_graze, "between": [values[-1], float(u_new[1] * problem.Lp)],
                           "touches_stick_after": cycle.touches_stick})
            end_reason = (f"grazing at {parameter} = {p_graze:.10g}: the cycle "
                          f"{'starts' if cycle.touches_stick else 'stops'} touching the stick segment")
            break
        if cycle.stable != previous.stable:
            events.append({"kind": "stability change", "between": [values[-1], float(u_new[1] * problem.Lp)],
                           "stable_after": cycle.stable})
        tangent_new = (u_new - u) / np.linalg.norm(u_new - u)
        tangent, u = tangent_new, u_new
        values.append(u[1] * problem.Lp), cycles.append(cycle)
        ds = min(max_step, ds * (1.5 if iterations <= 3 else 1.0))
    return Branch(parameter, np.asarray(values, float), cycles, end_reason, events)


def _locate_grazing(problem: _Problem, ua, ub, tol, iterations: int = 40) -> float:
    """Parameter where the stick phase appears or vanishes, between ``ua`` and ``ub``.

    Bisection in the parameter; at each trial value the cycle is re-solved at fixed
    parameter by Newton from the side-``a`` cycle, extrapolated along the branch, and
    classified by whether it touches the stick segment.
    """
    def solve(u_guess):
        engine = problem.engine(u_guess)
        rm = solve_section(engine, u_guess[0] * problem.Lx, tol=tol, max_iter=15)
        touches = any(s.mode == 0 and s.duration > 0 for s in rm.trajectory.segments)
        return np.array([rm.x / problem.Lx, u_guess[1]]), touches

    def classify(a, p):
        try:
            return solve(np.array([a[0] + slope * (p - a[1]), p]))
        except NoSolutionError:
            return np.array([math.nan, p]), None
        except ParameterError:  # past the parameter's valid range: no grazing there
            return np.array([math.nan, p]), OUTSIDE

    OUTSIDE = "outside"
    _, side_a = solve(ua)
    a = np.array(ua, float)
    slope = (ub[0] - ua[0]) / (ub[1] - ua[1]) if ub[1] != ua[1] else 0.0
    # march from a at fixed parameter until the classification flips: the point ub
    # may have jumped across a corner onto the other branch, so it is not trusted
    width, b = (ub[1] - ua[1]) / 4, None
    for _ in range(16):
        u_try, side = classify(a, a[1] + width)
        if side is OUTSIDE:
            return math.nan
        if side != side_a:
            b = u_try
            break
        slope = (u_try[0] - a[0]) / (u_try[1] - a[1])
        a = u_try
    if b is None:
        return math.nan
    for _ in range(iterations):
        p_mid = 0.5 * (a[1] + b[1])
        u_mid, side = classify(a, p_mid)
        if side == side_a:
            slope = (u_mid[0] - a[0]) / (u_mid[1] - a[1]) if u_mid[1] != a[1] else slope
            a = u_mid
        else:
            b = u_mid
        if abs(b[1] - a[1]) < 1e-10 * max(1.0, abs(a[1])):
            break
    return float(0.5 * (a[1] + b[1]) * problem.Lp)


def continue_from_hopf(osc: Oscillator, hopf, stop: float, *, offset: float = 1e-3, **options) -> Branch:
    """Continue the small cycle born at a Hopf point (see `stability.hopf_points`).

    The first cycle is sought at ``p = p_H (1 + offset)`` on the side where it exists
    (``d1 d3 < 0``), starting Newton from the averaged amplitude
    ``A^2 = -4 d1 / (3 d3 w^2)``.
    """
    from .stability import damping_coefficients

    from .stability import HopfPoint

    if not isinstance(osc, Oscillator):
        raise ParameterError("osc", osc, "an Oscillator")
    if not isinstance(hopf, HopfPoint):
        raise ParameterError("hopf", hopf, "a HopfPoint (see hopf_points)")
    offset = Q.check("offset", offset)
    for sign in (1.0, -1.0):
        p = hopf.value * (1 + sign * offset)
        at = osc.with_parameter(hopf.parameter, p)
        d1, d3 = damping_coefficients(at)
        if d1 * d3 < 0:
            break
    else:
        raise NoSolutionError("no small cycle near this Hopf point (degenerate: d3 = 0)")
    amplitude = math.sqrt(-4 * d1 / (3 * d3 * at.omega**2))
    return continue_cycle(at, stop, parameter=hopf.parameter, x0=at.equilibrium - amplitude, v0=0.0, **options)

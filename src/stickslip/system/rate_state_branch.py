"""Limit cycles of systems with rate-and-state contacts followed along a parameter.

`continue_rate_state(build, start, stop)` finds the cycle of ``build(start)`` as `rate_state_cycle`
does (from a transient) and follows it over ``points`` equally spaced values to ``stop``: at each
value Newton's method on the periodic orbit (`stickslip.orbits.periodic_orbit`) from the orbit
and period before, the variables scaled by the orbit's range before; where Newton's method fails
on a stable cycle, the motion from the orbit before is let settle (`SETTLE` periods) and Newton's
method starts from there (`rate_state_cycle`). A step neither converges on is halved, down to
``2^-HALVINGS`` of the step between two values (the branch then holds those values too). The
branch ends where no cycle is found that way, Newton's method failing or going onto steady sliding
(an amplitude below `SHRUNK` of the first one's, or no multiplier the flow's own 1): a Hopf point,
where the cycle shrinks onto steady sliding, or a fold of cycles. A change of stability is
recorded between the two values where it happens. `stickslip.system.continue_system` sends such
systems here.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from ..errors import NoSolutionError, ParameterError
from ..orbits import periodic_orbit
from .branch import SystemBranch
from .floquet import inside, without_own
from .model import System
from .rate_state import RateStateEquations, integrated, rate_state_simulate
from .rate_state_cycle import orbit_maps, orbit_size, psi_lists, rate_state_cycle, run_states

__all__ = ["continue_rate_state", "SHRUNK"]

#: A cycle whose largest amplitude is below this fraction of the first one's has shrunk onto steady sliding.
SHRUNK = 1e-4
#: Halvings of a step between two values before the branch is said to end there.
HALVINGS = 5
#: Periods of the cycle before over which the motion settles on a stable cycle where Newton's method failed.
SETTLE = 30
#: Samples of one period from which an orbit's ranges (its scale, its amplitude) are taken.
ORBIT_SAMPLES = 2001


def _orbit(system: System, eq: RateStateEquations, y: np.ndarray, period: float, rtol: float):
    """``(amplitude of each dof, range of each variable, each contact's largest slip rate)`` of the
    orbit from ``y`` over ``period``."""
    n = eq.n
    run = rate_state_simulate(system, y[:n], y[n:2 * n], period, psi0=psi_lists(eq, y), samples=ORBIT_SAMPLES,
                              rtol=rtol)
    return 0.5 * np.ptp(run.x, axis=0), orbit_size(run_states(eq, run)), run.slip_rate.max(axis=0)


def _settled(system: System, eq: RateStateEquations, prev: tuple, rtol: float, tol: float):
    """`rate_state_cycle` of ``system`` from the orbit ``prev`` of the value before, after a transient of
    `SETTLE` of its periods: ``(y, period, multipliers, amplitude, size)``, Nones if it finds none."""
    n, y = eq.n, prev[2]
    try:
        cycle = rate_state_cycle(system, y[:n], y[n:2 * n], psi0=psi_lists(eq, y), transient=SETTLE * prev[1],
                                 rtol=rtol, tol=tol)
    except (NoSolutionError, ParameterError):
        return None, None, None, None, None
    y = np.concatenate([cycle.x0, cycle.v0, *cycle.psi0])
    amp, size, _ = _orbit(system, eq, y, cycle.period, rtol)
    return y, cycle.period, cycle.multipliers, amp, size


def continue_rate_state(build: Callable[[float], System], start: float, stop: float, *, points: int = 41,
                        x0=None, v0=None, psi0=None, transient: float | None = None, tol: float = 1e-7,
                        parameter: str = "parameter", rtol: float = 1e-9, progress=None):
    """The `SystemBranch` of the limit cycles of ``build(p)`` (rate-and-state contacts at every
    contact) for ``points`` values from ``start`` to ``stop`` (see the module); the cycle at ``start``
    the one the motion from ``(x0, v0, psi0)`` settles on after ``transient`` (`rate_state_cycle`).
    Its rows hold no contact states or event sequences (the motion is smooth); ``psi0`` holds each
    cycle's state variables."""
    first = build(start)
    eq = RateStateEquations(first)
    cycle = rate_state_cycle(first, x0, v0, psi0=psi0, transient=transient, rtol=rtol, tol=tol)
    y = np.concatenate([cycle.x0, cycle.v0, *cycle.psi0])
    amp, size, _ = _orbit(first, eq, y, cycle.period, rtol)
    rows = [(start, cycle.period, y, without_own(cycle.multipliers), amp)]
    events, stopped = [], f"reached stop = {stop:g}"
    values = list(np.linspace(start, stop, points)[1:])
    targets, halvings = list(values), 0  # (halvings of the step to the next of the values)
    tick = progress or (lambda done, total: None)
    tick(1, points)
    while targets:
        prev, p = rows[-1], float(targets[0])
        try:
            system = build(p)
            if not integrated(system) or RateStateEquations(system).rsf != eq.rsf:
                raise ParameterError("contacts", p, "the same laws at every contact all along the branch")
            eq = RateStateEquations(system)
            field, flow = orbit_maps(system, eq, rtol)
            y, period, mult = periodic_orbit(field, eq.guarded_jacobian, prev[2], prev[1], size, rtol=rtol,
                                             tol=tol, flow=flow)
            amp, new_size, _ = _orbit(system, eq, y, period, rtol)
        except ParameterError as err:
            events.append({"change": "refused", "value": p, "before": "", "after": ""})
            stopped = f"stopped before {parameter} = {p:.10g}: {err}"
            break
        except NoSolutionError:
            y = None
        if y is not None and (np.abs(mult - 1.0).min() > 1e-3 or amp.max() < SHRUNK * rows[0][4].max()):
            y = None  # Newton's method went onto steady sliding (an orbit of any period)
        if y is None and inside(prev[3][:1]):  # a stable cycle: let the motion from the one before settle on it
            y, period, mult, amp, new_size = _settled(system, eq, prev, rtol, tol)
            if y is not None and amp.max() < SHRUNK * rows[0][4].max():
                y = None
        if y is None:
            if halvings < HALVINGS:  # a step too long for Newton's method: half of it first
                targets.insert(0, 0.5 * (prev[0] + p))
                halvings += 1
                continue
            events.append({"change": "cycle lost", "value": p, "before": "", "after": ""})
            stopped = (f"no cycle beyond {parameter} = {prev[0]:.10g}: at {p:.10g} ({HALVINGS} halvings of the step "
                       "on) Newton's method finds none or goes onto steady sliding (a Hopf point, where the cycle "
                       "shrinks onto steady sliding, or a fold of cycles)")
            break
        mult = without_own(mult)
        if inside(mult[:1]) != inside(prev[3][:1]):
            was = inside(prev[3][:1])
            events.append({"change": "stability", "value": p, "before": "stable" if was else "unstable",
                           "after": "unstable" if was else "stable",
                           "crossing": f"between {prev[0]:.10g} and {p:.10g}"})
        rows.append((p, period, y, mult, amp))
        size = new_size
        if targets.pop(0) in values:  # one of the values reached: its steps may be halved anew
            halvings = 0
            tick(points - len(targets), points)
    n = first.dofs
    width = max(1, min(8, min(r[3].size for r in rows)))
    mult = np.array([np.abs(r[3][:width]) for r in rows])
    return SystemBranch(parameter, np.array([r[0] for r in rows]), np.array([r[1] for r in rows]),
                        np.array([r[2][:n] for r in rows]), np.array([r[2][n:2 * n] for r in rows]),
                        tuple(() for _ in rows), mult, np.array([inside(r[3][:1]) for r in rows]),
                        tuple("" for _ in rows), tuple(events), stopped, np.array([r[4] for r in rows]),
                        psi0=np.array([r[2][2 * n:] for r in rows]))

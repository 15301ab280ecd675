"""Limit cycles of a system followed along a parameter, with the changes of their events.

`continue_system(build, start, stop)` finds the cycle of ``build(start)`` (a `System` for a
parameter value) and follows it over ``points`` values to ``stop``, each found by Newton's
method on the return map from the cycle before (`return_fixed_point`). Along the branch it
records the period, the multipliers and the cycle's sequence of contact events (which contact
enters which state, in order over a period). Where that sequence changes between two values —
a stick phase born or gone, a slip reversal appearing: a grazing of a switching line — the
value is located by bisection, as is the value beyond which no cycle is found (a cycle lost at
a grazing fold, where it meets a switching line tangentially); the branch ends there. A change
of stability (the largest multiplier but the flow's own crossing the unit circle) is located by
bisection too, with how it crosses: at +1, at -1 (a period doubling), or as a complex pair.

A system with a periodic force (`Harmonic`) has no limit cycle but a periodic response
(`forced_response`): the same branch follows it, found at each value by Newton's method on the
stroboscopic map over ``periods`` forcing periods, its multipliers all of them (no flow's own):
with the frequency of a harmonic as the parameter, a frequency response curve, with the
amplitude of each degree of freedom along it; with ``harmonic.frequency``, every harmonic's
frequency scaled together (the lowest is the parameter, the others keep their ratios to it: the
engine orders of a rotating machine).

`file_parameter(data, key)` makes ``build`` from a system's TOML table and one of its numbers
named as the file writes it (``contact[0].surface_speed``, ``stiffness[0][1]``, ``force[1]``,
``harmonic[0].frequency``, ``harmonic[0].cos[1]``; ``harmonic.frequency``: all harmonics together).
"""

from __future__ import annotations

import copy
import re
from typing import Callable

import numpy as np

from ..errors import NoSolutionError, ParameterError
from ..quantities import SYSTEM as Q
from .branch import AMPLITUDE_SAMPLES, SystemBranch, parameter_units
from .config import as_file_keys, system_from_dict
from .floquet import inside, limit_cycle, monodromy, return_fixed_point, without_own
from .flow import Flow
from .forced import extent, forced_response, forcing_period, stroboscopic_fixed_point, stroboscopic_multipliers
from .model import System
from .rate_state import integrated
from .rate_state_branch import continue_rate_state
from .simulate import longest_run

__all__ = ["SystemBranch", "continue_system", "file_parameter", "parameter_units"]

#: Bisection steps locating an event along the branch (2^-40 of the step between two values).
BISECTIONS = 40
#: The section of a forced system's branch: ``(FORCED, periods)`` in place of a cycle's (contact, state).
FORCED = "forcing periods"


def file_parameter(data: dict, key: str) -> tuple[Callable[[float], System], float]:
    """``(build, value)``: the system of the TOML table ``data`` with its number ``key`` set to a
    value, and that number's value in ``data``. A `ParameterError` naming ``parameter`` if the
    key names no number of the table."""
    if key == "harmonic.frequency":
        return _base_frequency(data)
    match = re.fullmatch(r"(contact)\[(\d+)\]\.(\w+)|(mass|stiffness|damping)\[(\d+)\]\[(\d+)\]|(force)\[(\d+)\]"
                         r"|(harmonic)\[(\d+)\]\.(frequency|cos|sin)(?:\[(\d+)\])?",
                         key) if isinstance(key, str) else None
    if match is None or (match[9] and (match[11] == "frequency") != (match[12] is None)):
        raise ParameterError("parameter", key, "a number of the file: contact[i].surface_speed (or normal_force, fs, "
                             "fd, tau, normal_stiffness), stiffness[i][j] (mass, damping), force[i], "
                             "harmonic[i].frequency, harmonic[i].cos[j] (sin), harmonic.frequency (all together)")
    path = ([match[1], int(match[2]), match[3]] if match[1] else
            [match[4], int(match[5]), int(match[6])] if match[4] else [match[7], int(match[8])] if match[7] else
            [match[9], int(match[10]), match[11]] + ([] if match[12] is None else [int(match[12])]))
    try:
        value = _holder(data, path)[path[-1]]
    except (KeyError, IndexError, TypeError):
        raise ParameterError("parameter", key, "a number the file gives (this one is not in it)") from None
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParameterError("parameter", key, f"a number of the file (it holds {value!r})")

    def build(p: float) -> System:
        table = copy.deepcopy(data)
        _holder(table, path)[path[-1]] = float(p)
        try:
            return system_from_dict(table)
        except ParameterError as err:
            raise as_file_keys(err) from None
    return build, float(value)


def _base_frequency(data: dict) -> tuple[Callable[[float], System], float]:
    """`file_parameter` for ``harmonic.frequency``: the lowest frequency, the others scaled with it."""
    if not isinstance(data, dict) or not isinstance(data.get("harmonic"), list) or not data["harmonic"]:
        raise ParameterError("parameter", "harmonic.frequency", "the frequency of a file's [[harmonic]] tables (each "
                             "with a frequency)")
    try:  # every frequency checked as the file gives it, under its own key
        freqs = [h.frequency for h in system_from_dict(data).harmonics]
    except ParameterError as err:
        raise as_file_keys(err) from None
    low = min(freqs)

    def build(p: float) -> System:
        table = copy.deepcopy(data)
        for t, f in zip(table["harmonic"], freqs):
            t["frequency"] = float(p) * (f / low)
        try:
            return system_from_dict(table)
        except ParameterError as err:
            raise as_file_keys(err) from None
    return build, low


def _holder(table, path: list):
    """The table or list that holds the number at ``path`` (its last step) in ``table``."""
    for step in path[:-1]:
        table = table[step]
    return table


_NAMES = {-1: "reverse", 0: "stick", 1: "slip", 2: "open"}


def _sequence(segments: tuple) -> str:
    out = []
    for seg in segments:
        out += [f"{i}:{_NAMES[b]}" for i, (a, b) in enumerate(zip(seg.states, seg.after)) if seg.rows and a != b]
    return " ".join(out)


def _solve(build, p, start, horizon, tol):
    """The cycle of ``build(p)`` from ``start`` = (z, states, signature): ``(period, z, states,
    sequence, multipliers)``; NoSolutionError or ParameterError if none near. A signature
    ``(FORCED, periods)``: the periodic response over that many forcing periods (``horizon`` unused)."""
    system = build(p)
    z, states, signature = start
    with Flow.shared(system):  # its returns, Newton steps and monodromy meet the same contact states
        if signature[0] == FORCED:
            period = signature[1] * forcing_period(system)
            n = system.dofs
            y, states, run = stroboscopic_fixed_point(system, z[:2 * n], states, period, tol, 50, newton_after=0,
                                                      near=1.0)
            z, segments = np.concatenate([y, [1.0]]), run.segments
            mult = stroboscopic_multipliers(system, run, states)
        else:
            period, z, states, segments = return_fixed_point(system, z, states, signature, horizon, tol, 50,
                                                             newton_after=0)
            mult = without_own(np.linalg.eigvals(monodromy(system, segments)))
    return period, z, states, _sequence(segments), mult[np.argsort(-np.abs(mult))]


def continue_system(build: Callable[[float], System], start: float, stop: float, *, points: int = 41, x0=None,
                    v0=None, transient: float | None = None, tol: float | None = None, parameter: str = "parameter",
                    periods: int = 1, psi0=None, progress: Callable[[int, int], None] | None = None) -> SystemBranch:
    """Follow the limit cycle of ``build(start)`` (the one the motion from ``x0``, ``v0`` settles on
    after ``transient`` seconds, default 100, as `limit_cycle` finds it) over ``points`` equally
    spaced values to ``stop`` (see the module), each to ``tol`` (default 1e-10). ``parameter`` names
    the parameter in messages and results. A system with a periodic force: its periodic response
    over ``periods`` forcing periods (`forced_response`). A system with rate-and-state contacts: its
    smooth cycles (`stickslip.system.rate_state_branch`; ``psi0`` their states at the start, the
    transient and ``tol`` by default as `rate_state_cycle` has them). ``progress(done, points)``, if
    given, is called as each value is done (a status line's time left on a long branch)."""
    if not callable(build):
        raise ParameterError("build", build, "a function of the parameter's value returning a System")
    start, stop = Q.check("parameter_value", start, "start"), Q.check("parameter_value", stop, "stop")
    if stop == start:
        raise ParameterError("stop", stop, f"different from the start value {start:g}")
    points = Q.check("points", points)
    if tol is not None:
        tol = Q.check("tol", tol)
    first = build(start)
    try:  # a value the branch may reach must make a valid system: refused before the work
        build(stop)
    except ParameterError as err:
        raise ParameterError("stop", stop, f"a value {parameter} can take ({err.name}: {err.allowed})") from None
    if not isinstance(first, System):
        raise ParameterError("build", build, "a function of the parameter's value returning a System")
    if integrated(first):
        if periods != 1:
            raise ParameterError("periods", periods, "1 for a system with rate-and-state contacts (its cycles are "
                                 "unforced)")
        return continue_rate_state(build, start, stop, points=points, x0=x0, v0=v0, psi0=psi0, transient=transient,
                                   tol=1e-7 if tol is None else tol, parameter=parameter, progress=progress)
    if psi0 is not None:
        raise ParameterError("psi0", psi0, "left out: it is the state of rate-and-state contacts, and this system "
                             "has none")
    transient, tol = 100.0 if transient is None else transient, 1e-10 if tol is None else tol
    n, forced = first.dofs, bool(first.harmonics)
    periods = Q.check("periods", periods)
    if periods != 1 and not forced:
        raise ParameterError("periods", periods, "1: it counts forcing periods, and this system has no harmonic force")
    if forced:
        cycle = forced_response(first, x0, v0, periods=periods, transient=transient, tol=tol, samples=2)
        section = (FORCED, cycle.periods)
    else:
        cycle = limit_cycle(first, x0, v0, transient=transient, tol=tol)
        section = (cycle.contact, cycle.state)
    state = (np.concatenate([cycle.x0, cycle.v0, [1.0]]), cycle.states, section)
    here = _solve(build, start, state, 3.0 * cycle.period, tol)
    values = np.linspace(start, stop, points)
    rows, events, stopped = [(start, *here)], [], f"reached stop = {stop:g}"
    tick = progress or (lambda done, total: None)
    tick(1, points)
    for p in values[1:]:
        prev = rows[-1]
        guess = (prev[2], prev[3], state[2])
        refused = _refused(build, p, section)
        if refused:
            events.append({"change": "refused", "value": float(p), "before": prev[4], "after": ""})
            stopped = f"stopped before {parameter} = {p:.10g}: {refused}"
            break
        try:
            now = _solve(build, p, guess, 3.0 * prev[1], tol)
        except (NoSolutionError, ParameterError):
            now = None
        if now is None:  # a step too long for Newton, or the cycle is lost before p: where?
            value, near = _bisect(build, prev, p, state[2], tol, lambda r: r is not None)
            try:  # from the last cycle found, next to p
                now = _solve(build, p, near, 3.0 * prev[1], tol)
            except (NoSolutionError, ParameterError):
                now = None
        if now is None:
            events.append({"change": "cycle lost", "value": value, "before": prev[4], "after": ""})
            which = repr(prev[4]) if prev[4] else "without contact events"
            stopped = (f"no cycle beyond {parameter} = {value:.10g} (the cycle {which} meets a switching line: a "
                       "grazing fold, or the motion leaves for another attractor)")
            break
        if now[3] != prev[4]:
            value = _bisect(build, prev, p, state[2], tol, lambda r: r is not None and r[3] == prev[4])[0]
            events.append({"change": "event sequence", "value": value, "before": prev[4], "after": now[3]})
        if inside(now[4][:1]) != inside(prev[5][:1]):
            was = inside(prev[5][:1])
            value, near = _bisect(build, prev, p, state[2], tol,
                                  lambda r: r is not None and r[3] == prev[4] and inside(r[4][:1]) == was)
            try:
                crossing = _crossing(_solve(build, value, near, 3.0 * prev[1], tol)[4][0])
            except (NoSolutionError, ParameterError) as err:  # at the change itself (a grazing, a stick's limit)
                crossing = f"not found: no orbit at the change itself ({err})"
            events.append({"change": "stability", "value": value, "before": "stable" if was else "unstable",
                           "after": "unstable" if was else "stable", "crossing": crossing})
        rows.append((p, *now))
        tick(len(rows), points)
    width = max(1, min(8, 2 * n - (0 if forced else 1)))
    mult = np.full((len(rows), width), np.nan)
    for i, r in enumerate(rows):
        mult[i, :min(width, r[5].size)] = np.abs(r[5][:width])
    stable = np.array([inside(r[5][:1]) for r in rows])
    amplitude = np.array([_amplitude(build(r[0]), r[2][:2 * n], r[3], r[1]) for r in rows])
    return SystemBranch(parameter, np.array([r[0] for r in rows]), np.array([r[1] for r in rows]),
                        np.array([r[2][:n] for r in rows]), np.array([r[2][n:2 * n] for r in rows]),
                        tuple(r[3] for r in rows), mult, stable,
                        tuple(r[4] for r in rows), tuple(events), stopped, amplitude, forced)


def _amplitude(system: System, y: np.ndarray, states: tuple, period: float) -> np.ndarray:
    """Half the peak-to-peak displacement of each degree of freedom over one period from ``y``."""
    low, high, _ = extent(system, y, states, period, AMPLITUDE_SAMPLES)
    return 0.5 * (high - low)


def _refused(build, p: float, section: tuple) -> str:
    """Why the system at ``p`` cannot be followed ('' if it can): its `ParameterError` (a value it
    cannot take, a force that is not periodic, a forcing period longer than a run can be)."""
    try:
        system = build(p)
        if section[0] == FORCED:
            T, longest = section[1] * forcing_period(system), longest_run(system)[0]
            if T > longest:
                raise ParameterError("harmonics", [h.frequency for h in system.harmonics],
                                     f"a forcing period whose {section[1]} period(s) a run can span (here {T:.6g} s, "
                                     f"longer than {longest:.6g} s)")
    except ParameterError as err:
        return str(err)
    return ""


def _crossing(mu: complex) -> str:
    """How the multiplier ``mu`` crosses the unit circle: at +1 (a fold or pitchfork of cycles), at -1
    (a period doubling), or as a complex pair (a torus)."""
    if abs(mu.imag) > 1e-6 * abs(mu):
        return f"complex pair at angle {np.angle(mu):.4g} rad (a torus)"
    return "at -1 (period doubling)" if mu.real < 0 else "at +1 (a fold or pitchfork of cycles)"


def _bisect(build, prev, bad, signature, tol, good) -> tuple:
    """The value between ``prev[0]`` (where ``good(cycle)``) and ``bad`` (where not) at which the
    cycle followed from ``prev`` stops being good, to `BISECTIONS` halvings, and the start of the
    last good cycle found (for `_solve`)."""
    lo, hi, start = prev[0], bad, (prev[2], prev[3], signature)
    for _ in range(BISECTIONS):
        mid = 0.5 * (lo + hi)
        try:
            found = _solve(build, mid, start, 3.0 * prev[1], tol)
        except (NoSolutionError, ParameterError):
            found = None
        if good(found):
            lo, start = mid, (found[1], found[2], signature)
        else:
            hi = mid
    return 0.5 * (lo + hi), start

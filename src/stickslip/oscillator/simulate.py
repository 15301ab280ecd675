"""Event-driven simulation of the friction oscillator with exact stick/slip switching.

The trajectory is a chain of segments, each in one mode. Slip segments use the
closed-form flow for affine laws (no step-size error; compiled event loop in
`kernel`) and DOP853 with event location otherwise; stick segments are exact
(``x = x0 + V t``). At ``v = V`` the next mode is chosen by Filippov's rule
(`Oscillator.mode_at_switch`): stick if the needed force is within ``f_s N``,
otherwise slip on in the direction the spring pulls, which gives reverse slip when the
mass overtakes the belt. Starting a segment exactly on a switching line never counts
as a crossing, so there is no chattering at the switch.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Callable, ClassVar

import numpy as np
import lazy_loader as lazy

from ..results import Result
from ..cf import finish
from ..quantities import OSCILLATOR as Q
from ..errors import NoSolutionError, ParameterError
from ..validation import finite
from .kernel import KERNELS, SEGMENT_COST
from .flows import AffineSlip, CompiledSlip, NumericSlip, StepPieces, compiled_failure
from .model import Mode, Oscillator

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["Segment", "Trajectory", "simulate", "Engine"]

#: The longest simulation accepted, in natural periods ``2 pi sqrt(m/k)`` (refused up front, not left to hang).
MAX_PERIODS = 1e7
#: The slip flows `simulate` and `Engine` take (see `Engine`).
METHODS = ("auto", "closed-form", "numeric", "python")

_STATUS = {0: "reached t_end", 1: "reached the Poincare section", -2: "stopped after max_events segments",
           -3: "Zeno: more than 100 consecutive vanishing segments"}


@dataclass(frozen=True)
class Segment:
    """One stretch of the trajectory in a single mode, ``t0 <= t <= t1``."""

    mode: Mode
    t0: float
    t1: float
    x0: float
    v0: float
    x1: float
    v1: float
    evaluate: Callable | None = field(repr=False, compare=False)

    @property
    def duration(self) -> float:
        return self.t1 - self.t0

    def sample(self, t):
        """State at global times ``t`` inside the segment."""
        t = np.asarray(t, dtype=float)
        if self.mode == Mode.STICK:
            return self.x0 + self.v0 * (t - self.t0), np.full(t.shape, self.v0)
        x, v = self.evaluate(t - self.t0)
        return np.reshape(x, t.shape), np.reshape(v, t.shape)


class Trajectory(Result):
    """Result of `simulate`: segment ``i`` has mode ``modes[i]`` and runs from
    ``(t[i], x[i], v[i])`` to ``(t[i+1], x[i+1], v[i+1])``.

    ``status`` is 0 when ``t_end`` was reached, 1 when the run stopped on the Poincare
    section, and negative on failure (``message`` says why).
    """

    MODEL: ClassVar[str] = "oscillator"

    def __init__(self, oscillator, modes, t, x, v, status, message, evaluators, jacobians=None, speed_ranges=None):
        self.oscillator = oscillator
        #: Numeric flows: ``(lowest, highest)`` velocity of each segment, found on the way (the
        #: velocity's extrema located to round-off); None for the closed form.
        self.speed_ranges = speed_ranges
        self.modes, self.t, self.x, self.v = np.asarray(modes, np.int8), np.asarray(t), np.asarray(x), np.asarray(v)
        self.status, self.message = status, message
        self._evaluators = evaluators  # mode -> flow (closed form) or index -> evaluator (numeric)
        self._jacobians = jacobians

    @property
    def t_end(self) -> float:
        return float(self.t[-1])

    @cached_property
    def segments(self) -> list[Segment]:
        out = []
        for i, mode in enumerate(self.modes):
            ev = self._evaluators.get(("segment", i))
            if ev is None and mode != 0:
                flow, x0, v0 = self._evaluators[int(mode)], float(self.x[i]), float(self.v[i])
                ev = (lambda f, a, b: (lambda t: f._state(t, a, b)))(flow, x0, v0)
            out.append(Segment(Mode(int(mode)), float(self.t[i]), float(self.t[i + 1]), float(self.x[i]),
                               float(self.v[i]), float(self.x[i + 1]), float(self.v[i + 1]), ev))
        return out

    def durations(self, mode: Mode) -> np.ndarray:
        """Durations of the segments in ``mode``."""
        return np.diff(self.t)[self.modes == int(mode)]

    @property
    def events(self) -> list[tuple[float, float, float, Mode, Mode]]:
        """Switches as ``(t, x, v, mode_before, mode_after)``."""
        idx = np.nonzero(self.modes[1:] != self.modes[:-1])[0] + 1
        return [(float(self.t[i]), float(self.x[i]), float(self.v[i]), Mode(int(self.modes[i - 1])),
                 Mode(int(self.modes[i]))) for i in idx]

    @cached_property
    def monodromy(self) -> np.ndarray:
        """``d(x, v)(t_end) / d(x, v)(0)``: flow Jacobians times saltation matrices."""
        osc, segs = self.oscillator, self.segments
        mono = np.eye(2)
        for i, seg in enumerate(segs):
            if seg.mode != Mode.STICK:
                jac = (self._jacobians[i] if self._jacobians is not None
                       else self._evaluators[int(seg.mode)].jacobian(seg.duration))
                mono = jac @ mono
            if i + 1 < len(segs) and segs[i + 1].mode != seg.mode:
                mono = _saltation(osc, seg.x1, seg.v1, seg.mode, segs[i + 1].mode) @ mono
        return mono

    def to_dict(self) -> dict:
        """Status, end state and the time spent in each contact mode (JSON-ready)."""
        time = {name: float(self.durations(Mode(code)).sum()) for name, code in (("stick_time", 0), ("slip_time", 1),
                                                                                ("reverse_slip_time", -1))}
        return {"status": self.status, "message": self.message, "t_end": self.t_end, "x_end": float(self.x[-1]),
                "v_end": float(self.v[-1]), **time, "segments": int(self.modes.size), "switches": len(self.events)}

    def sample(self, num: int = 2001):
        """Uniform samples plus every switching instant: ``t, x, v, mode`` arrays."""
        Q.check("samples", num, "num")
        grid = np.linspace(0.0, self.t_end, num)
        ts, xs, vs, ms = [], [], [], []
        for seg in self.segments:
            inside = grid[(grid > seg.t0) & (grid < seg.t1)]
            t = np.concatenate(([seg.t0], inside, [seg.t1]))
            x, v = seg.sample(t)
            ts.append(t), xs.append(x), vs.append(v), ms.append(np.full(t.size, int(seg.mode)))
        return tuple(np.concatenate(a) for a in (ts, xs, vs, ms))

    def to_xarray(self, num: int = 2001) -> xr.Dataset:
        """Sampled trajectory and switching events as an `xarray.Dataset`.

        ``t`` is a uniform grid of ``num`` times plus every switching instant, each time once:
        a switching instant belongs to the segment it starts (``mode`` there is the new mode).
        """
        t, x, v, mode = self.sample(Q.check("samples", num))
        first = np.append(np.diff(t) > 0, True)  # of equal times keep the last: the start of the next segment
        t, x, v, mode = t[first], x[first], v[first], mode[first]
        ev = self.events
        flags = {k: v for k, v in MODE_ATTRS.items() if k != "long_name"}
        ds = xr.Dataset(
            {
                "x": ("t", x, {"units": "m", "long_name": "displacement"}),
                "v": ("t", v, {"units": "m/s", "long_name": "velocity"}),
                "mode": ("t", mode.astype("i1"), {"long_name": "contact mode", **flags}),
                "event_time": ("event", np.array([e[0] for e in ev], float), {"units": "s"}),
                "event_x": ("event", np.array([e[1] for e in ev], float), {"units": "m"}),
                "event_from": ("event", np.array([int(e[3]) for e in ev], "i1"),
                               {"long_name": "contact mode before the switch", **flags}),
                "event_to": ("event", np.array([int(e[4]) for e in ev], "i1"),
                             {"long_name": "contact mode after the switch", **flags}),
            },
            coords={"t": ("t", t, {"units": "s", "long_name": "time",
                                   "comment": f"{num} uniform samples plus the switching instants"}),
                    "event": ("event", np.arange(len(ev)), {"long_name": "switch number"})},
            attrs={"status": self.status, "message": self.message},
        )
        return finish(ds, "trajectory of the friction oscillator", "oscillator", params=params_attrs(self.oscillator))


#: CF attributes of a variable of contact modes (`stickslip.oscillator.Mode` codes).
MODE_ATTRS = {"long_name": "contact mode", "flag_values": np.array([-1, 0, 1], np.int8),
              "flag_meanings": "reverse_slip stick slip"}


def params_attrs(osc: Oscillator) -> dict:
    """The oscillator's parameters as netCDF attributes (units in the names)."""
    law = osc.friction
    attrs = {"mass_kg": osc.mass, "stiffness_N_per_m": osc.stiffness, "normal_force_N": osc.normal_force,
             "belt_speed_m_per_s": osc.belt_speed, "damping_N_s_per_m": osc.damping,
             "friction_law": type(law).__name__}
    for name in ("fs", "fd", "tau", "vs"):
        if hasattr(law, name):
            attrs[f"friction_{name}"] = float(getattr(law, name))
    return attrs


def _saltation(osc: Oscillator, x, v, before: Mode, after: Mode) -> np.ndarray:
    """``I + (f+ - f-) grad_h^T / (grad_h . f-)`` at a switch from ``before`` to ``after``.

    Leaving stick the switching surface is ``x = x_hi`` (``grad_h = (1, 0)``); otherwise
    it is ``v = V`` (``grad_h = (0, 1)``). Entering stick gives ``diag(1, 0)``.
    """
    grad_h = np.array([1.0, 0.0]) if before == Mode.STICK else np.array([0.0, 1.0])
    f_minus, f_plus = osc.vector_field(x, v, before), osc.vector_field(x, v, after)
    denom = float(grad_h @ f_minus)
    if denom == 0.0:
        return np.full((2, 2), np.nan)  # grazing: the switch is not transversal
    return np.eye(2) + np.outer(f_plus - f_minus, grad_h) / denom


class Engine:
    """Runs segments for one oscillator; reused by simulation, cycles and continuation.

    ``method`` is ``"auto"`` (closed form when the law is affine), ``"closed-form"``,
    ``"numeric"`` (DOP853 with tolerance ``rtol``, compiled with the law where numba can
    compile it: `CompiledSlip`) or ``"python"`` (the same DOP853, scipy's, in Python:
    `NumericSlip`, the reference of the compiled one). ``variational=True`` integrates the
    variational equations along numeric segments (for `Trajectory.monodromy`).
    """

    def __init__(self, osc: Oscillator, method: str = "auto", rtol: float = 1e-12, variational=False):
        if not isinstance(osc, Oscillator):
            raise ParameterError("osc", osc if isinstance(osc, (int, float, str, type(None))) else type(osc).__name__,
                                 "a stickslip.oscillator.Oscillator")
        if method not in METHODS:
            raise ParameterError("method", method, "one of " + ", ".join(METHODS))
        if method == "closed-form" and osc.friction.affine is None:
            raise ParameterError("method", method, "'numeric' or 'auto' for a law that is not affine")
        self.closed = method in ("auto", "closed-form") and osc.friction.affine is not None
        self.osc, self.variational = osc, variational
        law = None
        if not (self.closed or method == "python"):
            from .. import lawkernel  # compiles the law's callbacks: only for laws that are not affine

            law = lawkernel.compiled(osc.friction)
        self.compiled, self._law, self._rtol = law is not None, law, rtol

        def flow(m):
            if self.closed:
                return AffineSlip(osc, m)
            if law is not None:
                return CompiledSlip(osc, m, law, rtol=rtol, variational=variational)
            return NumericSlip(osc, m, rtol=rtol, variational=variational)
        self.flows = {m: flow(m) for m in (Mode.SLIP_POS, Mode.SLIP_NEG)}

    def run(self, x0, v0, t_end, *, section: float | None = None, max_events: int = 10**7) -> Trajectory:
        """Integrate from ``(x0, v0)`` to ``t_end`` or to the first upward crossing of
        ``v = section`` (a Poincare section), whichever comes first.

        Parameters
        ----------
        x0, v0 : float
            The starting displacement [m] and velocity [m/s].
        t_end : float
            The time the run ends at [s], > 0 (earlier at the section).
        section : float, optional
            A velocity [m/s]: the run stops where ``v`` crosses it upward.
        max_events : int
            Safety bound on the number of segments.

        Returns
        -------
        Trajectory
            Check ``status``: negative means the run stopped early (``message`` says why).
        """
        x0, v0, t_end = Q.check("x0", x0), Q.check("v0", v0), Q.check("t_end", t_end)
        section = None if section is None else finite("section", section)
        max_events = Q.check("max_events", max_events)
        if self.closed:
            return self._run_closed(x0, v0, t_end, section, max_events)
        if self.compiled:
            return self._run_compiled(x0, v0, t_end, section, max_events)
        return self._run_numeric(x0, v0, t_end, section, max_events)

    def _run_compiled(self, x0, v0, t_end, section, max_events):
        """`_run_numeric`'s loop in one compiled call (`slipkernel.run`)."""
        from . import slipkernel  # laws that are not affine: the compiled flows load with their first run

        osc, (mu, slope, numbers) = self.osc, self._law
        allowed = Q["fd"].range
        lo, hi = osc.stick_limits
        numbers = np.array(numbers, dtype=float)
        out = slipkernel.run(mu, slope, numbers, np.array([osc.mass, osc.stiffness, osc.damping, osc.normal_force,
                                                           osc.belt_speed, allowed.lo, allowed.hi, lo, hi, osc.omega]),
                             x0, v0, int(osc.initial_mode(x0, v0)), float(t_end),
                             0.0 if section is None else float(section), section is not None, bool(self.variational),
                             self._rtol, 1e-14, int(max_events), float(osc.friction.max_speed))
        status, value, modes, t, x, v, jac, ranges, first, starts, states, slopes, ends = out
        if status == 2:  # a coefficient out of range, or none (the user's function raised): the Python path says why
            Engine(osc, "python", self._rtol, self.variational).run(x0, v0, t_end, section=section,
                                                                      max_events=max_events)
        if status in (2, 3):
            compiled_failure(slipkernel.BAD_LAW if status == 2 else slipkernel.STEP_TOO_SMALL, value)
        evaluators = {("segment", i): StepPieces(mu, slope, numbers, self.flows[Mode(int(m))].p,
                                                       starts[first[i]:first[i + 1]], states[first[i]:first[i + 1]],
                                                       slopes[first[i]:first[i + 1]], ends[i], (x[i + 1], v[i + 1]))
                      for i, m in enumerate(modes) if m != 0}
        return Trajectory(osc, modes, t, x, v, status, _STATUS.get(status) or _validity_message(osc), evaluators,
                          jac if self.variational else None, [tuple(r) for r in ranges])

    def _run_closed(self, x0, v0, t_end, section, max_events):
        osc = self.osc
        mu0, mu1 = osc.friction.affine
        p = np.array([osc.mass, osc.stiffness, osc.damping, osc.normal_force, osc.belt_speed, mu0, mu1,
                      osc.friction.static])
        # segments allocated for: a first guess, grown four-fold while a run needs more (a guess from
        # t_end * omega took 1e7 segments, 6 GB, for a 5e-12 kg block whose cycle has a handful)
        limit = int(min(max_events, 4096, 64 + 4 * max(1.0, t_end * osc.omega)))
        while True:
            kernels = KERNELS.choose(limit * SEGMENT_COST)  # a short job runs interpreted (`stickslip.jit`)
            modes, t, x, v, n, status = kernels.run_affine(p, x0, v0, int(osc.initial_mode(x0, v0)), float(t_end),
                                                           limit, 0.0 if section is None else float(section),
                                                           section is not None)
            KERNELS.charge(kernels, n * SEGMENT_COST)
            if status != -2 or limit >= max_events:
                break
            limit = min(max_events, 4 * limit)  # more segments than guessed: run again
        message = _STATUS.get(status) or _validity_message(osc)
        evaluators = {int(m): f for m, f in self.flows.items()}
        return Trajectory(osc, modes, t, x, v, status, message, evaluators)

    def _run_numeric(self, x0, v0, t_end, section, max_events):
        osc, V = self.osc, self.osc.belt_speed
        x_hi = osc.stick_limits[1]
        mode = osc.initial_mode(x0, v0)
        clock = _Clock()
        t, x, v = 0.0, x0, v0
        modes, ts, xs, vs, evaluators, jacs, ranges = [], [t], [x], [v], {}, [], []
        status = 0
        tiny_in_a_row = 0
        while t < t_end:
            if len(modes) >= max_events:
                status = -2
                break
            modes.append(int(mode))
            if mode == Mode.STICK:
                dt = max(0.0, (x_hi - x) / V)
                hit = clock.peek(dt) <= t_end
                if not hit:
                    dt = t_end - t
                t, x, v = clock.add(dt), (x_hi if hit else x + V * dt), V
                ts.append(t), xs.append(x), vs.append(v), jacs.append(None), ranges.append((V, V))
                if not hit:
                    break
                mode = Mode.SLIP_POS
                continue
            flow = self.flows[mode]
            levels = [(V, 1 if mode == Mode.SLIP_POS else -1)]
            if section is not None and mode == Mode.SLIP_POS:
                levels.append((section, 1))
            dt, hit = flow.first_crossing(x, v, t_end - t, levels)
            x1, v1 = flow.end()
            if hit is not None:
                v1 = levels[hit][0]  # snap onto the line that was crossed
            evaluators[("segment", len(modes) - 1)] = flow.evaluator()
            jacs.append(flow.jacobian() if self.variational else None)
            t, x, v = clock.add(dt), x1, v1
            ts.append(t), xs.append(x), vs.append(v)
            extremes = flow.speed_extremes()
            ranges.append((float(np.min(extremes)), float(np.max(extremes))))
            speed = float(np.max(np.abs(V - extremes)))
            if speed > osc.friction.max_speed * (1 + 1e-12):
                status = -1
                break
            tiny_in_a_row = tiny_in_a_row + 1 if dt < 1e-12 / osc.omega else 0
            if tiny_in_a_row > 100:
                status = -3
                break
            if hit is None:
                break
            if hit == 1:
                status = 1
                break
            mode = osc.mode_at_switch(x)
        message = _STATUS.get(status) or _validity_message(osc)
        return Trajectory(osc, modes, ts, xs, vs, status, message, evaluators,
                          jacs if self.variational else None, ranges)


def _validity_message(osc: Oscillator) -> str:
    return (f"the slip speed left the friction law's range of validity |v_r| < {osc.friction.max_speed:.6g} "
            "(the coefficient would turn negative)")


class _Clock:
    """Time as a compensated (Neumaier) sum of segment durations: no drift over 10^4 cycles."""

    def __init__(self):
        self.t, self._c = 0.0, 0.0

    def peek(self, dt: float) -> float:
        return self.t + (dt + self._c)

    def add(self, dt: float) -> float:
        s = self.t + dt
        self._c += (self.t - s) + dt if abs(self.t) >= abs(dt) else (dt - s) + self.t
        self.t = s
        return s + self._c


def simulate(osc: Oscillator, t_end: float, x0: float | None = None, v0: float = 0.0, *,
             method: str = "auto", rtol: float = 1e-12, max_events: int = 10**7) -> Trajectory:
    """Simulate the oscillator from ``(x0, v0)`` over ``[0, t_end]``.

    Parameters
    ----------
    osc : Oscillator
    t_end : float
        Final time [s], > 0.
    x0, v0 : float
        Initial displacement [m] (default: the steady-sliding equilibrium) and velocity [m/s].
    method : {"auto", "closed-form", "numeric", "python"}
        Slip flow: closed form (affine laws only) or DOP853 event location (compiled with the
        law where numba can compile it; ``"python"``: scipy's, the reference).
    rtol : float
        Relative tolerance of the numeric flow, in (0, 1e-3].
    max_events : int
        Safety bound on the number of segments.

    Returns
    -------
    Trajectory
        Check ``status``: negative means the run stopped early (``message`` says why).
    """
    if not isinstance(osc, Oscillator):
        raise ParameterError("osc", osc if isinstance(osc, (int, float, str, type(None))) else type(osc).__name__, "a stickslip.oscillator.Oscillator")
    t_end = Q.check("t_end", t_end)
    longest = MAX_PERIODS * 2 * np.pi / osc.omega
    if t_end > longest:
        raise ParameterError("t_end", t_end, f"<= {longest:.4g} s ({MAX_PERIODS:.0e} natural periods "
                             "2 pi sqrt(m/k); simulate in pieces from the last state for more)",
                             also=("mass", "stiffness"))
    x0, v0 = osc.start(osc.equilibrium if x0 is None else x0, v0)
    rtol = Q.check("rtol", rtol)
    Q.check("max_events", max_events)
    return Engine(osc, method, rtol).run(x0, v0, t_end, max_events=max_events)

"""Limit cycles of the friction oscillator: shooting on a Poincare section.

The section is ``Sigma = {v = 0, v increasing}``: every periodic orbit encircles the
steady-sliding equilibrium ``(x_e, 0)`` and crosses it once per period, at its leftmost
point. The return map ``P`` is computed with the event-driven engine; its derivative
comes from the monodromy matrix, built from the flows' Jacobians and the saltation
matrices at every switch. Sticking collapses a direction, so a stick-slip cycle has
Floquet multipliers exactly ``{1, 0}`` and ``P`` is locally constant.
"""

from __future__ import annotations

from typing import ClassVar

import math
from dataclasses import dataclass, field

import numpy as np
import lazy_loader as lazy
import scipy  # scipy.optimize loads on first use

from ..results import Result
from ..cf import finish
from ..quantities import OSCILLATOR as Q
from ..errors import NoSolutionError
from .model import Mode, Oscillator
from .simulate import Engine, Trajectory
from .. import validation as check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["LimitCycle", "return_map", "limit_cycle", "return_horizon"]


def return_horizon(osc: Oscillator) -> float:
    """Time within which an orbit must come back to the section."""
    x_lo, x_hi = osc.stick_limits
    return 200 * 2 * math.pi / osc.omega + 4 * (x_hi - x_lo) / osc.belt_speed


@dataclass(frozen=True)
class ReturnMap:
    """One application of the return map from ``(x, 0)``."""

    x: float
    x_next: float
    derivative: float
    trajectory: Trajectory


def return_map(engine: Engine, x: float) -> ReturnMap:
    """``P(x)`` and ``P'(x)`` on the section ``v = 0`` (upward)."""
    check.instance("engine", engine, Engine, "a stickslip.oscillator.Engine")
    x = Q.check("x0", x, "x")  # a start on the section
    traj = engine.run(x, 0.0, return_horizon(engine.osc), section=0.0)
    if traj.status != 1:
        reason = traj.message if traj.status < 0 else "the orbit settles without returning"
        raise NoSolutionError(f"no return to the section v = 0 from x = {x:.6g}: {reason}")
    derivative = math.nan
    if engine.closed or engine.variational:
        # v = 0 at both ends, so projecting along the flow leaves d x_next / d x = M[0, 0]
        derivative = float(traj.monodromy[0, 0])
    return ReturnMap(x, float(traj.x[-1]), derivative, traj)


@dataclass(frozen=True, repr=False)
class LimitCycle(Result):
    """A periodic orbit and its characteristics (SI units).

    ``floquet_multipliers`` are the eigenvalues of the monodromy matrix (with saltation
    matrices); one of them is 1 (the flow direction). They are NaN for a cycle that
    touches a switching line tangentially (grazing), where no monodromy matrix exists.
    """

    MODEL: ClassVar[str] = "oscillator"

    oscillator: Oscillator
    section_x: float
    period: float
    stick_time: float
    slip_time: float
    reverse_slip_time: float
    x_min: float
    x_max: float
    v_min: float
    v_max: float
    floquet_multipliers: np.ndarray
    trajectory: Trajectory = field(repr=False)

    @property
    def amplitude(self) -> float:
        """Half the peak-to-peak displacement."""
        return 0.5 * (self.x_max - self.x_min)

    @property
    def touches_stick(self) -> bool:
        return self.stick_time > 0.0

    @property
    def nontrivial_multiplier(self) -> complex:
        """The multiplier that is not the trivial 1 (the flow direction)."""
        mults = self.floquet_multipliers
        return complex(mults[np.argmax(np.abs(mults - 1.0))])

    @property
    def stable(self) -> bool:
        return abs(self.nontrivial_multiplier) < 1.0

    def to_dict(self) -> dict:
        """JSON-ready summary; complex multipliers become ``[re, im]`` pairs."""
        mults = [float(m.real) if m.imag == 0 else [float(m.real), float(m.imag)] for m in self.floquet_multipliers]
        return {"period": self.period, "stick_time": self.stick_time, "slip_time": self.slip_time,
                "reverse_slip_time": self.reverse_slip_time, "x_min": self.x_min, "x_max": self.x_max,
                "v_min": self.v_min, "v_max": self.v_max, "amplitude": self.amplitude,
                "floquet_multipliers": mults, "stable": self.stable, "touches_stick": self.touches_stick,
                "equilibrium": self.oscillator.equilibrium}

    def to_xarray(self, num: int = 2001) -> xr.Dataset:
        ds = self.trajectory.to_xarray(num)
        summary = {k: v for k, v in self.to_dict().items() if k != "floquet_multipliers"}
        ds.attrs.update({k: (int(v) if isinstance(v, bool) else v) for k, v in summary.items()})
        mult = np.asarray(self.floquet_multipliers, complex)
        ds["floquet_multiplier"] = ("multiplier", mult.real, {"units": "1", "long_name": "Floquet multiplier (real part)"})
        ds["floquet_multiplier_imag"] = ("multiplier", mult.imag,
                                         {"units": "1", "long_name": "Floquet multiplier (imaginary part)"})
        ds.coords["multiplier"] = ("multiplier", np.arange(mult.size), {"long_name": "multiplier number"})
        ds.attrs["title"] = "limit cycle of the friction oscillator"
        return finish(ds, ds.attrs["title"], "oscillator")


def _x_max(engine: Engine, traj: Trajectory) -> float:
    """Largest displacement: x where v crosses 0 downward (exact, per segment)."""
    best = traj.segments[0].x0
    for seg in traj.segments:
        best = max(best, seg.x0, seg.x1)
        if seg.mode == Mode.SLIP_POS:
            flow = engine.flows[Mode.SLIP_POS]
            dt, hit = flow.first_crossing(seg.x0, seg.v0, seg.duration, [(0.0, -1)])
            if hit is not None:
                best = max(best, float(np.ravel(flow.evaluator()(dt))[0]))
    return best


def _v_extreme(engine: Engine, traj: Trajectory, sign: int) -> float:
    """Largest (``sign=+1``) or smallest (``-1``) velocity: from the segments' ranges where the
    numeric flows found them or the closed form gives them (exact), else sampled, then refined."""
    ranges = traj.speed_ranges
    if (ranges is None or len(ranges) != len(traj.modes)) and engine.closed:
        ranges = [(seg.v0, seg.v0) if seg.mode == Mode.STICK
                  else engine.flows[seg.mode].velocity_range(seg.x0, seg.v0, seg.duration) for seg in traj.segments]
    if ranges is not None and len(ranges) == len(traj.modes):
        return float(max(r[1] for r in ranges) if sign > 0 else min(r[0] for r in ranges))
    t, _, v, _ = traj.sample(4001)
    i = int(np.argmax(sign * v))
    seg = next(s for s in traj.segments if s.t0 <= t[i] <= s.t1)
    if seg.mode == Mode.STICK:
        return float(v[i])
    res = scipy.optimize.minimize_scalar(lambda s: -sign * float(seg.sample(np.array([s]))[1][0]), bounds=(seg.t0, seg.t1),
                          method="bounded", options={"xatol": 1e-12 * max(1.0, seg.t1)})
    return float(sign * max(-res.fun, sign * v[i]))


def characterise(engine: Engine, rm: ReturnMap) -> LimitCycle:
    """Cycle quantities from one period of the orbit through ``(rm.x, 0)``."""
    traj = rm.trajectory
    durations = {m: float(np.sum(traj.durations(m))) for m in Mode}
    mono = traj.monodromy
    # a cycle that grazes a switching line has no monodromy matrix (the switch is not transversal)
    mults = np.linalg.eigvals(mono) if np.all(np.isfinite(mono)) else np.full(2, np.nan)
    mults = np.where(np.abs(mults.imag) < 1e-12, mults.real, mults)
    return LimitCycle(
        oscillator=engine.osc, section_x=rm.x, period=traj.t_end, stick_time=durations[Mode.STICK],
        slip_time=durations[Mode.SLIP_POS] + durations[Mode.SLIP_NEG],
        reverse_slip_time=durations[Mode.SLIP_NEG], x_min=rm.x, x_max=_x_max(engine, traj),
        v_min=_v_extreme(engine, traj, -1), v_max=_v_extreme(engine, traj, +1), floquet_multipliers=np.sort_complex(mults),
        trajectory=traj)


def solve_section(engine: Engine, x: float, *, tol: float = 1e-12, max_iter: int = 100) -> ReturnMap:
    """Fixed point of the return map: Newton's method, accepted only while it reduces the
    residual; otherwise one step of map iteration (which follows the attractor)."""
    osc = engine.osc
    scale = max(abs(osc.equilibrium), osc.friction.static * osc.normal_force / osc.stiffness,
                osc.belt_speed / osc.omega)

    def near_equilibrium(x):
        return abs(x - osc.equilibrium) < 1e-9 * scale

    stable = bool(np.all(osc.equilibrium_eigenvalues().real < 0))

    rm = return_map(engine, x)
    for _ in range(max_iter):
        residual = rm.x_next - x
        if abs(residual) <= tol * scale:
            return rm
        slope = rm.derivative - 1.0
        step = -residual / slope if math.isfinite(slope) and abs(slope) > 1e-8 else residual
        if abs(step) > 0.5 * scale:  # keep Newton from leaping across the phase plane
            step = math.copysign(0.5 * scale, step)
        trial = None
        if not near_equilibrium(x + step):
            try:
                trial = return_map(engine, x + step)
            except NoSolutionError:
                trial = None
        if trial is not None and abs(trial.x_next - trial.x) < abs(residual):
            x, rm = x + step, trial
        else:  # Newton jumped between regimes (e.g. stick-slip and pure slip): iterate the map
            x = rm.x_next
            if near_equilibrium(x) or (abs(x - osc.equilibrium) < 1e-3 * scale and stable):
                break  # map iteration cannot converge to an unstable cycle: it decays onto steady sliding
            rm = return_map(engine, x)
        if near_equilibrium(x):
            break
    if abs(x - osc.equilibrium) < 1e-3 * scale:
        raise NoSolutionError("the orbit converges to the steady-sliding equilibrium: no limit cycle there")
    raise NoSolutionError(f"shooting did not converge in {max_iter} iterations (last x = {x:.6g})")


def limit_cycle(osc: Oscillator, x0: float | None = None, v0: float | None = None, *,
                method: str = "auto", rtol: float = 1e-12, tol: float = 1e-12) -> LimitCycle:
    """Find the limit cycle reached from ``(x0, v0)`` and its Floquet multipliers.

    Parameters
    ----------
    osc : Oscillator
    x0, v0 : float, optional
        Starting state. Default: the end of the stick segment ``(x_hi, V)``, which lies
        on every stick-slip cycle. A start on the section (``v0 = 0``, ``x0 < x_e``)
        is the first Newton iterate, which also finds unstable cycles.
    method : {"auto", "closed-form", "numeric", "python"}
        As `simulate`'s.
    rtol : float
        Tolerance of the numeric flow.
    tol : float
        Tolerance on the fixed point of the return map, relative to the stick length.

    Raises
    ------
    NoSolutionError
        If the orbit settles on the equilibrium or shooting fails.
    """
    check.instance("osc", osc, Oscillator, "a stickslip.oscillator.Oscillator")
    x0, v0 = osc.start(osc.stick_limits[1] if x0 is None else x0, osc.belt_speed if v0 is None else v0)
    rtol = Q.check("rtol", rtol)
    tol = Q.check("tol", tol)
    engine = Engine(osc, method, rtol, variational=True)
    if v0 == 0.0 and x0 < osc.equilibrium:  # already on the section: shoot from here
        start = x0
    else:
        first = engine.run(x0, v0, return_horizon(osc), section=0.0)
        if first.status != 1:
            raise NoSolutionError(f"the orbit from ({x0:.6g}, {v0:.6g}) does not reach the section v = 0: "
                                  f"{first.message}")
        start = first.segments[-1].x1
    rm = solve_section(engine, start, tol=tol)
    return characterise(engine, rm)

"""Continuation of travelling-wave families in the mismatch, the shaft speed or friction.

Along a family the zone sequence is kept and each point is a multiple-shooting solve
(`boundsco`) started from a secant prediction. A zone sequence ends in one of two
ways (paper, Figure 11):

* **death** of a zone: its length goes to 0 (its two switching points coalesce), e.g.
  the slip zone right of the separation zone when the mismatch gets small;
* **birth** of a zone: an inequality of [17]-[20] is violated inside a zone, e.g. the
  pressure touches 0 inside a slip zone (a separation zone is born), or the slip
  velocity touches 0 (a stick or reverse-slip zone is born).

Either way the current sequence stops passing the checks. The event is located by
bisection on the parameter (the last value where the old sequence still passes), and the
family is continued in the new regime, found by the stick-exit return map near the last
wave speed. Because the internal problem depends on ``delta`` and ``gamma`` only through
``delta/sqrt(gamma)`` (`zones.Scaling`), continuing in ``delta`` or in ``Omega``
follows the same internal family; only the conversion of ``c`` and amplitudes differs.
"""

from __future__ import annotations

from typing import ClassVar

import math
from collections import Counter
from dataclasses import dataclass, field

import numpy as np
import lazy_loader as lazy

from ...results import Result
from ...cf import finish
from ...quantities import BRAKE as Q
from ...errors import NoSolutionError, ParameterError
from ..reduced.params import BrakeParams, PhysicalParams
from .zones import KINDS, Scaling
from .solve import TravellingWave, find_waves, solve_layout, travelling_wave

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["WaveEvent", "WaveBranch", "continue_waves", "PARAMETERS"]

PARAMETERS = ("delta", "gamma", "omega", "friction")


def with_parameter(params: BrakeParams, name: str, value: float) -> BrakeParams:
    """``params`` with one parameter changed (physical parameters kept when known)."""
    phys = params.physical
    if name == "omega":
        if phys is None:
            raise ParameterError("parameter", name, "'omega' only for parameters built from physical values")
        return PhysicalParams(**{**_fields(phys), "omega": value}).dimensionless()
    if phys is not None and name in ("delta", "friction"):
        key, val = ("mismatch", value * phys.inner_radius) if name == "delta" else ("friction", value)
        return PhysicalParams(**{**_fields(phys), key: val}).dimensionless()
    return params.replace(**{name: value})


def _fields(phys):
    return {k: getattr(phys, k) for k in phys.__dataclass_fields__}


def _value(params: BrakeParams, name: str) -> float:
    return params.omega if name == "omega" else getattr(params, name)


@dataclass(frozen=True, repr=False)
class WaveEvent(Result):
    """A change of zone sequence along a family, located at ``parameter``."""

    MODEL: ClassVar[str] = "brake"

    parameter: float
    kind: str  # "birth", "death" or "change"
    zones: tuple  # kinds of the zones born / dead
    before: str
    after: str
    cause: str  # the check that failed for the old sequence beyond the event

    def to_dict(self) -> dict:
        return {"parameter": float(self.parameter), "kind": self.kind, "zones": list(self.zones),
                "before": self.before, "after": self.after, "cause": self.cause}


@dataclass(frozen=True, repr=False)
class WaveBranch(Result):
    """A family of waves of ``n`` modes along one parameter."""

    MODEL: ClassVar[str] = "brake"

    parameter: str
    n: int
    values: np.ndarray
    waves: tuple
    events: tuple
    stopped: str = ""
    params: BrakeParams = field(default=None, repr=False)

    def to_dict(self) -> dict:
        return {"parameter": self.parameter, "n": self.n, "values": [float(v) for v in self.values],
                "c": [float(w.c) for w in self.waves], "structure": [w.structure for w in self.waves],
                "events": [e.to_dict() for e in self.events], "stopped": self.stopped}

    def to_xarray(self) -> xr.Dataset:
        """Per point: ``c``, regime, zone boundaries (padded), zone lengths per kind, extrema."""
        m = max(len(w.zones) for w in self.waves)
        pad = lambda rows: np.array([r + [np.nan] * (m - len(r)) for r in rows])  # noqa: E731
        starts = pad([[z.start for z in w.zones] for w in self.waves])
        ends = pad([[z.end for z in w.zones] for w in self.waves])
        kinds = np.array([[z.kind for z in w.zones] + [""] * (m - len(w.zones)) for w in self.waves])
        length = {k: [sum(z.length for z in w.zones if z.kind == k) for w in self.waves] for k in KINDS}
        prof = [w.evaluate(np.linspace(0, w.period, 1001)) for w in self.waves]
        delta = np.array([w.params.delta for w in self.waves])
        rad = {"units": "rad"}
        padded = {**rad, "comment": "NaN past the last zone of a point (points have different numbers of zones)"}
        ds = xr.Dataset(
            {"c": ("point", [w.c for w in self.waves], {"long_name": "wave speed (theta per unit Omega t)"}),
             "c_internal": ("point", [w.x[0] for w in self.waves], {"long_name": "c sqrt(gamma)"}),
             "structure": ("point", [w.structure for w in self.waves]),
             "regime": ("point", [w.regime for w in self.waves]),
             "zone_start": (("point", "zone"), starts, padded), "zone_end": (("point", "zone"), ends, padded),
             "zone_kind": (("point", "zone"), kinds),
             **{f"length_{k.replace('-', '_')}": ("point", length[k], {**rad, "long_name": f"total {k} length"})
                for k in KINDS},
             "U_max": ("point", [p["U"].max() for p in prof], {"units": "R"}),
             "gap_max": ("point", [p["U"].max() for p in prof] - delta, {"units": "R",
                                                                         "long_name": "max U - delta"}),
             "V_amplitude": ("point", [0.5 * np.ptp(p["V"]) for p in prof], {"units": "R"}),
             "P_max": ("point", [p["P"].max() for p in prof], {"units": "E/M"}),
             "residual": ("point", [w.residual for w in self.waves])},
            coords={"point": ("point", np.arange(len(self.waves)), {"long_name": "point number along the branch"}),
                    self.parameter: ("point", np.asarray(self.values, float)),
                    "delta_internal": ("point", [Scaling(w.params).delta for w in self.waves],
                                       {"long_name": "delta/sqrt(gamma)"})})
        ds.attrs.update({"parameter": self.parameter, "n": self.n, "stopped": self.stopped,
                         "events": "; ".join(f"{e.kind} of {'+'.join(e.zones)} at {self.parameter} = "
                                             f"{e.parameter:.8g} ({e.before} -> {e.after}, {e.cause})"
                                             for e in self.events)})
        ds["regime"].attrs["long_name"] = "regime of the wave"
        ds["structure"].attrs["long_name"] = "zone structure of one period"
        return finish(ds, f"travelling waves continued in {self.parameter}", "brake",
                      params=self.waves[0].params.to_attrs() if self.waves else None)


def _diff(before: TravellingWave, after: TravellingWave):
    a, b = Counter(z.kind for z in before.zones), Counter(z.kind for z in after.zones)
    born, dead = list((b - a).elements()), list((a - b).elements())
    if born and not dead:
        return "birth", tuple(born)
    if dead and not born:
        return "death", tuple(dead)
    return "change", tuple(dead + born)


def _locate(params, name, n, wave, p_good, p_bad, tol):
    """Last parameter value where ``wave``'s zone sequence still passes, by bisection."""
    good, bad_wave = wave, None
    for _ in range(60):
        if abs(p_bad - p_good) <= tol * max(abs(p_good), abs(p_bad)):
            break
        mid = 0.5 * (p_good + p_bad)
        trial = solve_layout(with_parameter(params, name, mid), n, good.layout, good.x)
        if trial.valid and trial.residual < 1e-8:
            p_good, good = mid, trial
        else:
            p_bad, bad_wave = mid, trial
    if bad_wave is None:
        bad_wave = solve_layout(with_parameter(params, name, p_bad), n, good.layout, good.x)
    failing = [k for k, v in bad_wave.margins.items() if v < 0]
    cause = ", ".join(failing) if bad_wave.residual < 1e-8 else "no solution of the old sequence"
    return p_good, good, cause


def _switch(params, name, n, last, p):
    """The wave at ``p`` (just beyond an event) continuing ``last`` (return-map scan).

    ``T(c)`` is continuous in ``c`` and in the parameter, so the new wave speed is close
    to the old one: scan windows of growing width around it (in units of the distance
    to the sonic speed) and keep the closest root.
    """
    at_p = with_parameter(params, name, p)
    c_old = last.x[0] / Scaling(at_p).root_gamma  # same internal speed, new units
    sonic = math.sqrt(at_p.coefficients().a)
    gap = abs(c_old) - sonic
    for width in (0.01, 0.05, 0.2):
        lo = math.copysign(max(abs(c_old) - width * gap, sonic * (1 + 1e-6)), c_old)
        hi = math.copysign(abs(c_old) + width * gap, c_old)
        waves = find_waves(at_p, n, c_range=(lo, hi), num=24)
        if waves:
            return min(waves, key=lambda w: abs(w.c - c_old))
    return None


def continue_waves(params: BrakeParams, modes: int, parameter: str = "delta", stop: float | None = None,
                   num: int = 50, wave: TravellingWave | None = None, regime: str | None = None,
                   spacing: str = "linear", tol: float = 1e-9) -> WaveBranch:
    """Follow a wave family from ``params`` to ``parameter = stop``.

    Parameters
    ----------
    params : BrakeParams
        Start point.
    modes : int
        Number of waves ``n`` around the ring.
    parameter : {"delta", "gamma", "omega", "friction"}
        The continued parameter (``omega`` in rad/s needs physical parameters).
    stop : float
        End value of the parameter.
    num : int
        Number of points (start and stop included).
    wave : TravellingWave, optional
        The start wave (default: `travelling_wave(params, modes, regime)`).
    spacing : {"linear", "log"}
        Spacing of the parameter values.
    tol : float
        Relative accuracy of the located events.

    Returns
    -------
    WaveBranch
        The waves, the parameter values reached, and the events (zone births and deaths).
    """
    if parameter not in PARAMETERS:
        raise ParameterError("parameter", parameter, f"one of {PARAMETERS}")
    if stop is None:
        raise ParameterError("stop", stop, "the end value of the continued parameter")
    num, tol = Q.check("points", num), Q.check("tol", tol)
    if num < 2:
        raise ParameterError("points", num, "an integer >= 2")
    if spacing not in ("linear", "log"):
        raise ParameterError("spacing", spacing, "'linear' or 'log'")
    start = _value(params, parameter)
    if not math.isfinite(start):
        raise ParameterError("parameter", parameter, "'omega' only for parameters built from physical values")
    try:  # the branch runs up to stop: it must be a valid value of the parameter
        with_parameter(params, parameter, stop)
    except ParameterError as err:
        raise ParameterError("stop", stop, f"a valid {parameter}: {err.name} {err.allowed}", also=err.also) from None
    if parameter == "delta" and not stop > 0:
        raise ParameterError("stop", stop, "> 0 (a wave needs contact: delta > 0)")
    if spacing == "log":
        if start <= 0 or stop <= 0:
            raise ParameterError("spacing", spacing, "'linear' when the parameter range reaches 0")
        values = np.geomspace(start, stop, num)
    else:
        values = np.linspace(start, stop, num)
    if wave is not None and (wave.params != params or wave.n != modes):
        raise ParameterError("wave", wave, f"a wave of {modes} modes at the start parameters")
    current = wave if wave is not None else travelling_wave(params, modes, regime=regime)
    if not current.valid:
        raise NoSolutionError("the start wave does not pass its checks")
    waves, reached, events, history = [current], [values[0]], [], [(values[0], current.x)]
    stopped = ""
    for p in values[1:]:
        p_from, q = reached[-1], p
        grid_step = p - p_from
        min_step = 1e-3 * abs(p - p_from)
        while True:
            trial = solve_layout(with_parameter(params, parameter, q), modes, current.layout,
                                 _predict(history, current, q))
            if trial.valid and trial.residual < 1e-8:  # accepted: go on to the grid point
                current, p_from = trial, q
                history.append((q, current.x))
                if q == p:
                    break
                q = p
                continue
            if abs(q - p_from) > min_step:  # smaller step before calling it an event
                q = p_from + 0.5 * (q - p_from)
                continue
            p_event, last, cause = _locate(params, parameter, modes, current, p_from, q, tol)
            for frac in (0.01, 0.05, 0.25):  # a little beyond the event (new zones start tiny)
                p_after = p_event + frac * grid_step
                if (p_after - p) * grid_step > 0:
                    p_after = p
                new = _switch(params, parameter, modes, last, p_after)
                if new is not None:
                    break
            if new is None or len(events) > 4 * num:
                short = min(last.zones, key=lambda z: z.length)
                why = (f"; its {short.kind} zone shrinks to nothing ({short.length / last.period:.1e} of the "
                       f"period){' (waves without stick are not followed)' if short.kind == 'stick' else ''}"
                       if short.length < 1e-3 * last.period else "")
                stopped = (f"the {last.structure} family ends at {parameter} = {p_event:.8g} ({cause}){why}; "
                           f"no wave continues it (return-map scan around c = {last.c:.6g})")
                break
            kind, zones = _diff(last, new)
            events.append(WaveEvent(p_event, kind, zones, last.structure, new.structure, cause))
            current, history, p_from, q = new, [(p_after, new.x)], p_after, p
        if stopped:
            break
        waves.append(current)
        reached.append(p)
    return WaveBranch(parameter, int(modes), np.asarray(reached), tuple(waves), tuple(events), stopped, params)


def _predict(history, current, p):
    """Secant prediction of the unknowns (same zone sequence only)."""
    if len(history) >= 2:
        (p0, x0), (p1, x1) = history[-2], history[-1]
        if p1 != p0:
            return x1 + (x1 - x0) * (p - p1) / (p1 - p0)
    return current.x

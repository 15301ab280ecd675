"""Multiple shooting with switching points as unknowns (the BOUNDSCO formulation).

A wave is a cyclic sequence of zones over one period ``2 pi/n`` (``phi`` order, zone 0
starting at ``phi = 0``: the phase condition). Each zone is mapped to unit length; the
unknowns are

    x = (c, L_0 .. L_{m-1}, reduced start state of every zone),

where the reduced start state is ``V`` for stick (``U = delta``, ``U' = 0``, ``V' = -1/c``),
``(V, V')`` for slip and reverse slip (``U = delta``, ``U' = 0``), and ``(U, U', V, V')``
for separation. The state at the end of a zone is the exact closed form
(`ZoneFlows.flow`), so no numerical integration enters. The equations are, at each
switching point (read in time order: ``phi`` increases with time iff ``c < 0``):

* contact -> contact: ``V`` and ``V'`` continuous; leaving stick: ``Q = s f P`` (the
  traction reaches the friction limit); slip <-> reverse slip: ``1 + c V' = 0``;
  entering stick: ``1 + c V' = 0`` (it is the continuity of ``V'``);
* lift-off (contact -> separation): ``U = delta``, ``U' = 0``, ``V, V'`` continuous and
  ``P = 0`` on the contact side;
* landing (separation -> contact): ``U = delta`` and ``V`` continuous; ``U'`` jumps to 0
  with the normal impulse ``Pi = (c^2 - b)[U']`` (``phi`` order), and if the contact
  zone slips, ``(c^2 - a)[V'] = s f Pi``; landing in stick fixes ``V' = -1/c``;

and ``sum L_k = 2 pi/n``. This is square for every admissible sequence. Lift-off from
stick is possible only if ``P = g delta + D/c = 0`` in the whole stick zone, so a
stick -> separation switch is degenerate: the reduced model has no stick-separation
wave (the solve then fails verification).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import root

from ...errors import ParameterError
from .zones import CONTACT, KINDS, REVERSE, SEPARATION, SLIP, STICK, ZoneFlows, slip_sign

__all__ = ["Layout", "residual", "solve", "verify", "layout_from_orbit", "CHECK_TOLERANCE"]

_SIZES = {STICK: 1, SLIP: 2, REVERSE: 2, SEPARATION: 4}
#: Inequalities are accepted down to this (relative) margin.
CHECK_TOLERANCE = 1e-8


@dataclass(frozen=True)
class Layout:
    """Zone kinds in ``phi`` order (zone 0 starts at ``phi = 0``) and the time direction."""

    kinds: tuple
    direction: int  # +1: time runs with phi (c < 0); -1: against it (c > 0)
    #: switching points (index ``i``: between zones ``i`` and ``i + 1``) that are landings
    #: whose friction impulse stops the sliding (``1 + c V' = 0`` after the impact) and
    #: are followed by slip at once because ``|h V| > f P`` there
    stopped: tuple = ()

    def __post_init__(self):
        kinds = tuple(self.kinds)
        object.__setattr__(self, "kinds", kinds)
        object.__setattr__(self, "stopped", tuple(sorted(int(i) % len(kinds) for i in self.stopped)))
        if len(kinds) < 2 or any(k not in KINDS for k in kinds):
            raise ParameterError("zones", kinds, f"at least two zone kinds among {KINDS}")
        for k1, k2 in zip(kinds, kinds[1:] + kinds[:1]):
            if k1 == k2:
                raise ParameterError("zones", kinds, "a cyclic sequence with no two equal neighbours")
        if self.direction not in (1, -1):
            raise ParameterError("direction", self.direction, "+1 or -1")

    @property
    def size(self) -> int:
        return 1 + len(self.kinds) + sum(_SIZES[k] for k in self.kinds)

    def pack(self, c, lengths, states) -> np.ndarray:
        """Unknown vector from ``c``, zone lengths and full start states."""
        parts = [[c], list(lengths)]
        for k, y in zip(self.kinds, states):
            parts.append({STICK: [y[2]], SLIP: [y[2], y[3]], REVERSE: [y[2], y[3]],
                          SEPARATION: list(y)}[k])
        return np.array([v for p in parts for v in p], dtype=float)

    def unpack(self, x, delta):
        """``(c, lengths, start states)`` from the unknown vector."""
        m = len(self.kinds)
        c, lengths, i = x[0], x[1:1 + m], 1 + m
        states = []
        for k in self.kinds:
            if k == STICK:
                states.append(np.array([delta, 0.0, x[i], -1.0 / c]))
            elif k == SEPARATION:
                states.append(np.array(x[i:i + 4]))
            else:
                states.append(np.array([delta, 0.0, x[i], x[i + 1]]))
            i += _SIZES[k]
        return c, lengths, states

    def rotate(self, k: int) -> "Layout":
        """The same wave with the phase condition at the start of zone ``k``."""
        return Layout(self.kinds[k:] + self.kinds[:k], self.direction, tuple(i - k for i in self.stopped))


def _boundary(fl: ZoneFlows, direction, k1, y1, k2, y2, stopped=False):
    """Equations at the switch from zone ``k1`` (end state ``y1``) to ``k2`` (start ``y2``)."""
    early, late = (k1, k2) if direction > 0 else (k2, k1)
    y_early, y_late = (y1, y2) if direction > 0 else (y2, y1)
    if early in CONTACT and late in CONTACT:
        res = [y2[2] - y1[2], y2[3] - y1[3]]
        if early == STICK:  # leaving stick: the traction reaches the friction limit
            res.append(fl.traction(STICK, y_early) - slip_sign(late) * fl.f * fl.pressure(STICK, y_early))
        elif late != STICK:  # slip <-> reverse slip through zero slip velocity
            res.append(fl.slip_velocity(y_early))
        return res
    if late == SEPARATION:  # lift-off
        if early == SEPARATION:
            raise ParameterError("zones", (k1, k2), "no two separation zones in a row")
        return [y_late[0] - fl.delta, y_late[1], y2[2] - y1[2], y2[3] - y1[3], fl.pressure(early, y_early)]
    res = [y_early[0] - fl.delta, y2[2] - y1[2]]  # landing (impact)
    if late != STICK:
        if stopped:  # the impulse stops the sliding; slip resumes at once
            res.append(fl.slip_velocity(y_late))
        else:
            Pi, Q_Pi = fl.impulses(y1, y2)
            res.append(Q_Pi - slip_sign(late) * fl.f * Pi)
    return res


def residual(x, layout: Layout, coef, friction, delta, period) -> np.ndarray:
    """The BOUNDSCO equations (see module doc) at the unknown vector ``x``."""
    c, lengths, starts = layout.unpack(x, delta)
    try:
        with np.errstate(all="ignore"):
            fl = ZoneFlows(coef, friction, delta, c)
            ends = [fl.flow(k, y, np.array(L)) for k, y, L in zip(layout.kinds, starts, lengths)]
            res = []
            m = len(layout.kinds)
            for i in range(m):
                j = (i + 1) % m
                res.extend(_boundary(fl, layout.direction, layout.kinds[i], ends[i], layout.kinds[j], starts[j],
                                 i in layout.stopped))
            res.append(sum(lengths) - period)
            res = np.asarray(res, dtype=float)
    except (np.linalg.LinAlgError, ZeroDivisionError, FloatingPointError):
        res = np.full(layout.size, np.nan)
    if not np.all(np.isfinite(res)):  # the solver wandered off (c^2 = a, overflow): push it back
        res = np.full(layout.size, 1e12)
    return res


def solve(layout: Layout, x0, coef, friction, delta, period, tol=1e-11):
    """Newton-type solve (MINPACK hybrd, then Levenberg-Marquardt). Returns ``(x, max|F|)``."""
    fun = lambda x: residual(x, layout, coef, friction, delta, period)  # noqa: E731
    best = np.asarray(x0, float)
    with np.errstate(all="ignore"):
        f0 = fun(best)
        best_norm = float(np.max(np.abs(f0))) if np.all(np.isfinite(f0)) else math.inf
        for method, opts in (("hybr", {"xtol": 1e-14}), ("lm", {"xtol": 1e-14, "ftol": 1e-14})):
            sol = root(fun, best, method=method, options=opts)
            fx = fun(sol.x)
            norm = float(np.max(np.abs(fx))) if np.all(np.isfinite(fx)) else math.inf
            if norm < best_norm:
                best, best_norm = sol.x, norm
            if best_norm < tol:
                break
    return best, best_norm


def zone_samples(layout: Layout, x, coef, friction, delta, num=401):
    """Exact states on ``num`` points of every zone: list of ``(kind, s, Y)`` and flows."""
    c, lengths, starts = layout.unpack(x, delta)
    fl = ZoneFlows(coef, friction, delta, c)
    out = []
    for k, y, L in zip(layout.kinds, starts, lengths):
        s = np.linspace(0.0, L, num)
        out.append((k, s, fl.flow(k, y, s)))
    return out, fl


def verify(layout: Layout, x, coef, friction, delta, num=401) -> dict:
    """Worst relative margin of every inequality of [17]-[20] on a fine grid.

    A margin ``>= -CHECK_TOLERANCE`` passes. Interior points only (the switching
    conditions hold with equality at the ends). Keys: ``length`` (``L_k / period``),
    ``supersonic`` (``(c^2 - a)/a``), ``pressure`` (contact zones, ``P / max P``),
    ``stick_friction`` (``(f P - |Q|)/(f max P)``), ``slip_direction`` (``s w``: the slip
    velocity over the shaft speed), ``separation_gap`` (``(U - delta)/max|U - delta|``),
    ``impact_impulse`` (``sign Pi``), ``impact_friction`` (landing in stick:
    ``(f Pi - |Q_Pi|)/(f Pi)``; landing in slip: ``s w`` on both sides).
    """
    samples, fl = zone_samples(layout, x, coef, friction, delta, num)
    c, lengths, starts = layout.unpack(x, delta)
    period = float(np.sum(lengths))
    P_ref = max((float(np.max(np.abs(fl.pressure(k, Y)))) for k, _, Y in samples if k in CONTACT), default=1.0)
    margins = {"length": float(np.min(lengths)) / period, "supersonic": (c * c - fl.a) / fl.a}
    worst = {}

    def put(name, value):
        worst[name] = min(worst.get(name, math.inf), float(value))

    for k, s, Y in samples:
        inner = Y[1:-1]
        if inner.shape[0] == 0:
            continue
        if k in CONTACT:
            P = fl.pressure(k, inner)
            put("pressure", np.min(P) / P_ref)
        if k == STICK:
            put("stick_friction", np.min(fl.f * P - np.abs(fl.traction(k, inner))) / (fl.f * P_ref))
        elif k in (SLIP, REVERSE):
            put("slip_direction", np.min(slip_sign(k) * fl.slip_velocity(inner)))
        else:
            gap = inner[:, 0] - fl.delta
            put("separation_gap", np.min(gap) / max(float(np.max(np.abs(gap))), 1e-300))
    m = len(layout.kinds)
    for i in range(m):
        j = (i + 1) % m
        k1, k2 = layout.kinds[i], layout.kinds[j]
        if SEPARATION not in (k1, k2):
            continue
        early, late = (k1, k2) if layout.direction > 0 else (k2, k1)
        if early != SEPARATION:
            continue  # lift-off: no impulse
        y1, y2 = samples[i][2][-1], starts[j]
        Pi, Q_Pi = fl.impulses(y1, y2)
        put("impact_impulse", math.copysign(1.0, Pi) if Pi != 0 else 0.0)
        if late == STICK or i in layout.stopped:  # the impulse stops the sliding
            put("impact_friction", (fl.f * Pi - abs(Q_Pi)) / max(fl.f * abs(Pi), 1e-300))
        else:  # sliding impact: the slip keeps its direction through the impact
            sgn = slip_sign(late)
            put("impact_friction", min(sgn * fl.slip_velocity(y1), sgn * fl.slip_velocity(y2)))
        if i in layout.stopped:  # slip resumes at once: |h V| > f P, in the direction of h V
            P_st = fl.stick_pressure()
            put("slip_onset", (slip_sign(late) * fl.h * y2[2] - fl.f * P_st) / (fl.f * P_st))
    margins.update(worst)
    return margins


def passed(margins: dict, tol: float = CHECK_TOLERANCE) -> bool:
    return all(v >= -tol for v in margins.values()) and margins["length"] > 0 and margins["supersonic"] > 0


def layout_from_orbit(orbit):
    """``(Layout, x)`` from a closed stick-exit orbit (time order -> ``phi`` order)."""
    zones = []
    for z in orbit.zones:  # merge a grazing touch (same kind twice in a row)
        if zones and zones[-1][0] == z[0]:
            k, L, y0, _ = zones[-1]
            zones[-1] = (k, L + z[1], y0, z[3])
        else:
            zones.append(tuple(z))
    direction = -int(math.copysign(1, orbit.c))
    stick, excursion = zones[-1], zones[:-1]
    if direction > 0:
        seq = [(stick[0], stick[1], stick[2])] + [(k, L, y0) for k, L, y0, _ in excursion]
    else:  # phi runs against time: reverse the order, zones start at their time-end
        seq = [(stick[0], stick[1], stick[3])] + [(k, L, y1) for k, L, _, y1 in reversed(excursion)]
    stopped = []
    for t in range(1, len(zones) - 1):  # time-order zone t starts right after a landing?
        k, _, y0, _ = zones[t]
        if zones[t - 1][0] == SEPARATION and k in (SLIP, REVERSE) and y0[3] == -1.0 / orbit.c:
            stopped.append(t if direction > 0 else len(zones) - 1 - t)  # boundary index in phi order
    layout = Layout(tuple(k for k, _, _ in seq), direction, tuple(stopped))
    return layout, layout.pack(orbit.c, [L for _, L, _ in seq], [y for _, _, y in seq])

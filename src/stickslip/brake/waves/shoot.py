"""The stick-exit return map: every travelling wave with a stick zone, one speed at a time.

In a stick zone [17] the pressure ``P = g delta + D/c`` is constant and ``Q = h V`` grows
at the rate ``h`` per unit time (``V_t = 1``). A material point therefore always leaves
stick at the same state, ``Q = +f P``:

    y_exit(c) = (delta, 0, f P_stick / h, -1/c).

From there the zone logic is deterministic in time order (for ``c^2 > a``): positive slip
until the slip velocity returns to 0 (then stick if ``|h V| < f P``, else slip in the
direction of ``h V``: overshoot into reverse slip) or the pressure reaches 0 (lift-off);
free flight until ``U = delta`` again (impact: ``U'`` jumps to 0, with a friction impulse
that stops the sliding if it can, else keeps its direction). The orbit closes at the
first return to stick, so for each ``c`` there is at most one wave containing stick, of
period ``T(c)`` (one stick zone per period), and the waves of ``n`` modes are the roots of

    T(c) = 2 pi / n.

This turns the search into a one-dimensional root-finding problem, and it classifies the
regime for free. Time order runs with ``phi`` when ``c < 0`` and against it when ``c > 0``
(``phi = theta - c t``). Events are found on a fine grid of the exact zone solution
(step ``<= 0.2/|largest eigenvalue|``) and refined with `scipy.optimize.brentq`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ...quantities import BRAKE as Q

from .zones import REVERSE, SEPARATION, SLIP, STICK, ZoneFlows, slip_sign

__all__ = ["Orbit", "stick_exit_orbit"]

_CHUNK = 256
# the first samples of a zone are geometric, to see short zones and early events
_FIRST = np.concatenate([np.geomspace(1e-7, 1.0, 15)[:-1], np.arange(1, _CHUNK + 1)])


@dataclass
class Orbit:
    """The orbit from the stick exit to the next stick entry, in time order.

    ``zones`` lists ``(kind, length, y_start, y_end)`` in time order, the closing stick
    zone last; ``period`` is the sum of the lengths (in ``phi``). ``status`` is ``"closed"``
    or the reason the orbit is not a wave.
    """

    c: float
    status: str
    zones: list = field(default_factory=list)

    @property
    def closed(self) -> bool:
        return self.status == "closed"

    @property
    def period(self) -> float:
        return float(sum(z[1] for z in self.zones)) if self.closed else math.inf

    @property
    def structure(self) -> tuple:
        return tuple(z[0] for z in self.zones)


def _first_event(flows: ZoneFlows, kind: str, y0, direction: float, funcs, on_surface, horizon: float):
    """First ``s`` in (0, horizon] where one of ``funcs`` (positive inside the zone) turns <= 0.

    ``s`` is measured in time order; ``phi = phi0 + direction * s``. ``on_surface[i]`` says
    that ``funcs[i]`` vanishes at the start (the zone begins on that switching surface):
    then only its values for ``s > 0`` count, and they must start positive. Sign changes
    on the sampling grid are refined by `brentq`; so are shallow dips between samples
    (small local minima of the samples are refined by a bounded minimisation), which
    catches grazing events. Returns ``(s, index)``, ``(-1, index)`` if the zone is left
    at once (inconsistent), or ``None`` (no event within the horizon, or a blow-up).
    """
    rate = flows.max_rate(kind)
    step = min(0.05, 0.2 / rate) if rate > 0 else 0.05
    start = np.array([float(fn(y0)) for fn in funcs])
    surface = np.asarray(on_surface, bool)
    if np.any(~surface & (start <= 0.0)):
        return -1.0, int(np.argmin(np.where(surface, np.inf, start)))
    carry_v, carry_s, first = start[:, None], np.array([0.0]), True
    while carry_s[-1] < horizon:
        grid = carry_s[-1] + step * (_FIRST if first else np.arange(1, _CHUNK + 1))
        vals = np.array([fn(flows.flow(kind, y0, direction * grid)) for fn in funcs])
        if not np.all(np.isfinite(vals)):
            return None  # the zone solution blows up before any event
        allv, alls = np.concatenate([carry_v, vals], axis=1), np.concatenate([carry_s, grid])
        trusted = np.full(len(funcs), carry_v.shape[1])  # first sample index that counts
        if first:
            trusted[:] = 0
            for i in np.flatnonzero(surface):  # skip the samples lost in rounding
                big = np.flatnonzero(np.abs(vals[i]) > 1e-9 * np.max(np.abs(vals[i])))
                if big.size == 0 or vals[i, big[0]] <= 0.0:
                    return -1.0, int(i)
                trusted[i] = 1 + big[0]
        hits = []
        for i, fn in enumerate(funcs):
            hit = _event_in(flows, kind, y0, direction, fn, allv[i], alls, trusted[i])
            if hit is not None:
                hits.append((hit, i))
        if hits:
            return min(hits)
        carry_v, carry_s, first = allv[:, -2:], alls[-2:], False
    return None


def _event_in(flows, kind, y0, direction, fn, v, s, k0):
    """Earliest root of ``fn`` on the samples ``v`` (at ``s``) from index ``k0`` on."""
    g = lambda t: float(fn(flows.flow(kind, y0, np.array(direction * t))))  # noqa: E731
    idx = np.arange(max(k0, 0), len(v))
    neg = np.flatnonzero(v[idx] <= 0.0)
    stop = idx[neg[0]] if neg.size else len(v)
    scale = np.max(np.abs(v[idx])) if idx.size else 0.0
    for k in range(max(k0, 1), min(stop, len(v) - 1)):  # hidden dips before the first sign change
        if v[k] <= v[k - 1] and v[k] <= v[k + 1] and v[k] < 0.05 * scale:
            res = minimize_scalar(g, bounds=(s[k - 1], s[k + 1]), method="bounded",
                                  options={"xatol": 1e-14 * max(1.0, s[k + 1])})
            if res.fun <= 0.0:
                return brentq(g, s[k - 1], res.x, xtol=1e-15, rtol=4 * np.finfo(float).eps, maxiter=200)
    if neg.size and stop > 0:
        return brentq(g, s[stop - 1], s[stop], xtol=1e-15, rtol=4 * np.finfo(float).eps, maxiter=200)
    return None


def stick_exit_orbit(flows: ZoneFlows, horizon: float, max_zones: int = 12) -> Orbit:
    """Follow the zone logic from the stick exit until the next stick (see module doc).

    Parameters
    ----------
    flows : ZoneFlows
        Zone solutions for one wave speed ``c`` (internal units), ``c^2 > a``.
    horizon : float
        Give up when the orbit gets longer than this (in ``phi``).
    max_zones : int
        Give up after this many zones.
    """
    horizon, max_zones = Q.check("horizon", horizon), Q.check("max_zones", max_zones)
    c, f, h = flows.c, flows.f, flows.h
    orbit = Orbit(c, "closed")
    if flows.ca <= 0.0:
        orbit.status = "subsonic: c^2 <= a (no stick->slip transition is consistent)"
        return orbit
    P_st = flows.stick_pressure()
    if P_st <= 0.0:
        orbit.status = "no stick: the stick pressure g delta + D/c is not positive"
        return orbit
    direction = -math.copysign(1.0, c)  # d phi / d(time order)
    V_top = f * P_st / h
    y = np.array([flows.delta, 0.0, V_top, -1.0 / c])
    kind, total, w_surface = SLIP, 0.0, True
    for _ in range(max_zones):
        if kind == SEPARATION:
            funcs, surface = [lambda Y: Y[..., 0] - flows.delta], [True]
        else:
            s = slip_sign(kind)
            funcs = [lambda Y, s=s: s * flows.slip_velocity(Y), lambda Y, k=kind: flows.pressure(k, Y)]
            surface = [w_surface, False]
        event = _first_event(flows, kind, y, direction, funcs, surface, horizon - total)
        if event is None:
            orbit.status = "too long: no return to stick within the horizon"
            return orbit
        length, which = event
        if length < 0:
            if kind != SEPARATION and which == 1:
                orbit.status = ("bounce: P <= 0 right after an impact (a zero-length contact, not a zone "
                                "sequence handled here)")
            else:
                orbit.status = f"{kind} zone left at once (inconsistent switching)"
            return orbit
        y_end = flows.flow(kind, y, np.array(direction * length))
        orbit.zones.append((kind, length, y, y_end))
        total += length
        if kind == SEPARATION:  # impact: U' -> 0, friction impulse
            kind, y = _landing(flows, y_end, direction, P_st)
            if kind is None:
                orbit.status = y
                return orbit
            w_surface = bool(flows.slip_velocity(y) == 0.0 or y[3] == -1.0 / c)  # stopped by the impact
        elif which == 1:  # pressure reached 0: lift-off with U = delta, U' = 0
            kind, y = SEPARATION, y_end.copy()
        else:  # slip velocity reached 0
            kind, y = _after_zero_slip(flows, y_end, P_st)
            w_surface = True
        if kind == STICK:
            stick_len = (V_top - y[2]) * abs(c)
            y_end = y.copy()
            y_end[2] = V_top
            orbit.zones.append((STICK, stick_len, y, y_end))
            return orbit
    orbit.status = f"more than {max_zones} zones without returning to stick"
    return orbit


def _after_zero_slip(flows: ZoneFlows, y, P_st):
    """Zone after the slip velocity reaches 0: stick if ``|h V| < f P``, else overshoot."""
    y = y.copy()
    y[3] = -1.0 / flows.c
    Q_stick = flows.h * y[2]
    if abs(Q_stick) < flows.f * P_st:
        return STICK, y
    return (SLIP if Q_stick > 0 else REVERSE), y


def _landing(flows: ZoneFlows, y, direction, P_st):
    """Impact at ``U = delta``: ``U'`` jumps to 0; returns ``(kind, state)`` or ``(None, why)``.

    In ``phi`` order the jumps obey ``(c^2 - b)[U'] = Pi >= 0`` and ``(c^2 - a)[V'] = Q_Pi``
    with ``|Q_Pi| <= f Pi``; in time order ``[X]_t = direction [X]_phi``.
    """
    Pi = -direction * flows.cb * y[1]
    if Pi < 0.0:
        return None, "impact would need a tensile impulse (Pi < 0)"
    after = y.copy()
    after[1] = 0.0
    Q_needed = direction * flows.ca * (-1.0 / flows.c - y[3])  # impulse that stops sliding
    if abs(Q_needed) <= flows.f * Pi:
        return _after_zero_slip(flows, after, P_st)
    s = math.copysign(1.0, flows.slip_velocity(y))
    after[3] = y[3] + direction * s * flows.f * Pi / flows.ca
    return (SLIP if s > 0 else REVERSE), after

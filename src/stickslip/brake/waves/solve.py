"""Travelling stick-slip(-separation) waves of the brake-like system (paper eqs. [14]-[20]).

A wave ``U(phi), V(phi)``, ``phi = theta - c t``, periodic with period ``2 pi/n``, made of
stick [17], slip [18], reverse slip [19] and separation [20] zones. Inside each zone the
equations [15] are linear with constant coefficients and solved in closed form
(`zones`); the wave is the solution of the multiple-shooting system with the
switching points as unknowns (`boundsco`, the BOUNDSCO formulation of the paper).

Initial guesses come from the stick-exit return map (`shoot`): every zone sequence
that contains stick is determined by ``c`` alone, and the waves of ``n`` modes are the
roots of ``T(c) = 2 pi/n``. A scan of ``c`` brackets them; each root is then polished by
multiple shooting and every inequality of [17]-[20] is verified on a fine grid.

Units: the paper's dimensionless ones (``t = Omega t̄``, lengths over ``R``, ``P, Q``
divided by the modal mass as in [12]). ``c`` is in radians of ``theta`` per unit ``t``;
the angular phase speed in rad/s is ``c Omega``.
"""

from __future__ import annotations

import math
from numbers import Integral

import numpy as np
from scipy.optimize import brentq

from ...quantities import BRAKE as Q
from ...errors import NoSolutionError, ParameterError
from ..reduced.params import BrakeParams
from .boundsco import Layout, layout_from_orbit, residual, solve, verify
from .result import REGIMES, TravellingWave, Zone, regime_name
from .shoot import stick_exit_orbit
from .zones import REVERSE, SEPARATION, SLIP, STICK, Scaling, ZoneFlows

__all__ = ["Zone", "TravellingWave", "travelling_wave", "find_waves", "solve_layout", "REGIMES", "regime_name",
           "STICK", "SLIP", "REVERSE", "SEPARATION"]


# --- construction ----------------------------------------------------------------------
def _check(params, modes) -> int:
    if not isinstance(params, BrakeParams):
        raise ParameterError("params", params, "a stickslip.brake.BrakeParams")
    if isinstance(modes, bool) or not isinstance(modes, Integral) or modes < 1:
        raise ParameterError("modes", modes, "an integer >= 1 (number of waves around the ring)")
    if params.friction <= 0.0:
        raise ParameterError("friction", params.friction, "> 0 (no stick zone without friction)")
    return int(modes)


def _wave(params, n, layout, x) -> TravellingWave:
    sc = Scaling(params)
    coef, f, delta = sc.coefficients, params.friction, sc.delta
    period = 2.0 * math.pi / n
    res = float(np.max(np.abs(residual(x, layout, coef, f, delta, period))))
    margins = verify(layout, x, coef, f, delta)
    c_hat, lengths, _ = layout.unpack(x, delta)
    edges = np.concatenate([[0.0], np.cumsum(lengths)])
    zones = tuple(Zone(k, float(a), float(b)) for k, a, b in zip(layout.kinds, edges[:-1], edges[1:]))
    return TravellingWave(params, n, float(sc.speed(c_hat)), zones, res, margins, layout, np.asarray(x, float))


def solve_layout(params: BrakeParams, modes: int, layout: Layout, x0) -> TravellingWave:
    """Multiple-shooting solve for a given zone sequence from the internal guess ``x0``."""
    n = _check(params, modes)
    sc = Scaling(params)
    x, _ = solve(layout, x0, sc.coefficients, params.friction, sc.delta, 2.0 * math.pi / n)
    return _wave(params, n, layout, x)


def _speed_grid(coef, c_range, num):
    if c_range is not None:
        lo, hi = (float(v) for v in c_range)
        if not (math.isfinite(lo) and math.isfinite(hi)) or lo == hi or lo * hi <= 0:
            raise ParameterError("c_range", c_range, "two distinct internal speeds of the same sign")
        return np.geomspace(lo, hi, num)
    sign = math.copysign(1.0, coef.D) if coef.D != 0 else -1.0
    return sign * math.sqrt(coef.a) * (1.0 + np.geomspace(1e-3, 10.0, num))


def _period_function(coef, f, delta, period):
    horizon = 3.0 * period

    def F(c):
        orbit = stick_exit_orbit(ZoneFlows(coef, f, delta, c), horizon)
        if orbit.closed:
            return orbit.period - period, orbit
        if orbit.status.startswith("too long"):
            return horizon - period, orbit
        return math.nan, orbit
    return F


class _Undefined(Exception):
    pass


def _roots(F, speeds, period):
    """Speeds where ``T(c) = period``: sign changes on the grid, refined by brentq."""
    vals = [F(c) for c in speeds]
    out = []
    for (c1, (F1, o1)), (c2, (F2, _)) in zip(zip(speeds, vals), zip(speeds[1:], vals[1:])):
        if not (np.isfinite(F1) and np.isfinite(F2)) or F1 * F2 > 0:
            continue

        def g(c):
            v = F(c)[0]
            if not np.isfinite(v):
                raise _Undefined
            return v
        try:
            c = brentq(g, c1, c2, xtol=1e-15, rtol=4 * np.finfo(float).eps, maxiter=200)
        except _Undefined:
            continue
        value, orbit = F(c)
        if orbit.closed and abs(value) < 1e-8 * period:
            out.append(orbit)
    return out, vals


def find_waves(params: BrakeParams, modes: int, c_range=None, num: int = 150) -> list[TravellingWave]:
    """All verified waves of ``modes`` waves around the ring found on a scan of ``c``.

    Parameters
    ----------
    params : BrakeParams
        ``friction > 0``.
    modes : int
        ``n >= 1``: the wave has period ``2 pi/n`` in ``phi``.
    c_range : (float, float), optional
        Scanned wave speeds in the paper's units (same sign). Default: ``sign(D)`` (the
        direction of the flutter wave) and ``|c| sqrt(gamma)/sqrt(a gamma) - 1`` from
        ``1e-3`` to ``10`` (waves with stick need ``c^2 > a``).
    num : int
        Number of scanned speeds (geometric spacing).

    Returns
    -------
    list of TravellingWave
        Sorted by decreasing ``|c|``; only waves that pass every check.
    """
    n = _check(params, modes)
    sc = Scaling(params)
    coef, f, delta = sc.coefficients, params.friction, sc.delta
    period = 2.0 * math.pi / n
    num = Q.check("num", num)
    speeds = _speed_grid(coef, None if c_range is None else sc.internal_speed(np.asarray(c_range)), num)
    orbits, _ = _roots(_period_function(coef, f, delta, period), speeds, period)
    waves = []
    for orbit in orbits:
        layout, x0 = layout_from_orbit(orbit)
        x, _ = solve(layout, x0, coef, f, delta, period)
        wave = _wave(params, n, layout, x)
        if wave.valid:
            waves.append(wave)
    return sorted(waves, key=lambda w: -abs(w.c))


def _from_guess(params, n, guess) -> TravellingWave:
    if isinstance(guess, TravellingWave):
        return solve_layout(params, n, guess.layout, guess.x)
    c = float(guess)
    lo, hi = sorted((0.8 * c, 1.25 * c), key=abs)
    waves = find_waves(params, n, c_range=(lo, hi), num=40)
    if not waves:
        raise NoSolutionError(f"no wave with {n} modes for c within [{lo:.6g}, {hi:.6g}] (guess {c:.6g})")
    return min(waves, key=lambda w: abs(w.c - c))


def travelling_wave(params: BrakeParams, modes: int, regime: str | None = None, guess=None,
                    c_range=None, num: int = 150) -> TravellingWave:
    """A travelling wave with ``modes`` waves around the ring (paper eqs. [14]-[20]).

    Parameters
    ----------
    params : BrakeParams
        Dimensionless parameters (``friction > 0``).
    modes : int
        Number of waves ``n`` around the ring (period ``2 pi/n``).
    regime : str, optional
        One of `REGIMES` values (e.g. ``"stick-slip"``); by default any.
    guess : TravellingWave or float, optional
        A nearby wave (its zone sequence and unknowns start the multiple shooting) or a
        wave speed ``c`` (the scan is restricted to ``[0.8 c, 1.25 c]``).
    c_range, num
        Scan of the wave speed, as in `find_waves`.

    Returns
    -------
    TravellingWave
        When several waves qualify, the one with the largest ``|c|`` (the principal family
        of the scan, farthest from the sonic speed ``sqrt(a)``).

    Raises
    ------
    NoSolutionError
        No verified wave; the message says what was scanned and which regimes exist.
    """
    n = _check(params, modes)
    if regime is not None and regime not in REGIMES.values():
        raise ParameterError("regime", regime, f"one of {sorted(REGIMES.values())}")
    if guess is not None:
        wave = _from_guess(params, n, guess)
        if wave.valid and (regime is None or wave.regime == regime):
            return wave
        failed = [k for k, v in wave.margins.items() if v < 0]
        raise NoSolutionError(f"multiple shooting from the guess gave a {wave.regime} solution with residual "
                              f"{wave.residual:.2e} that violates {failed or 'nothing'}; requested regime "
                              f"{regime or 'any'}")
    waves = find_waves(params, n, c_range=c_range, num=num)
    chosen = [w for w in waves if regime is None or w.regime == regime]
    if chosen:
        return chosen[0]
    sc = Scaling(params)
    a = sc.coefficients.a / params.gamma
    tried = (f"scanned {num} wave speeds " + (f"in {tuple(c_range)}" if c_range is not None else
             f"with sonic ratio |c|/sqrt(a) from 1.001 to 11 (sqrt(a) = {math.sqrt(a):.6g})") +
             " with the stick-exit return map, polished by multiple shooting and verified on a grid")
    found = sorted({w.regime for w in waves})
    why = ("; the reduced model has no stick-separation wave (lift-off from stick needs P = 0 in the "
           "whole stick zone)" if regime == "stick-separation" else "")
    raise NoSolutionError(f"no {regime or 'travelling'} wave with {n} modes at {params.to_dict()}: {tried}; "
                          f"regimes found for this n: {found or 'none'}{why}")

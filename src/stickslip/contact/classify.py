"""Automatic classification of the limit regime of a contact run (paper [14], [17]-[20]).

Works on any run of the books of `stickslip.contact.runs`. Per node and step the scheme knows its state: stick [17], positive slip [18], reverse
slip [19] or separation [20]. Over the densely sampled tail of a run, `classify` gives

* the zone fractions (time averages) and the regime name, the present zones joined in the
  order stick, slip, separation, reverse-slip (e.g. ``stick-slip-separation``);
* the mode number ``n``: the number of stick zones along the contact line in the frame of the
  wave (the stick masks of the snapshots shifted back by ``c t`` and averaged; a zone is a
  run of at least ``min_run`` nodes occupied at least half as often as the most occupied
  node; contact zones if nothing sticks), and ``n_fft``, the dominant Fourier mode of ``V``;
* the wave speed ``c`` in the paper's convention ``phi = theta - c t`` (a pattern
  ``X(theta - c t)`` moves by ``+c dt``): the shift between consecutive snapshots that
  maximises their periodic cross-correlation (sub-node by a parabola through the peak),
  accumulated and fitted against time;
* a stationarity test: a travelling wave satisfies ``X(theta, t + s) = X(theta - c s, t)``.
  The residual is the largest RMS misfit of ``U`` and ``V`` (relative to their RMS
  deviation from the mean) over all pairs of tail snapshots, the shift done by linear
  interpolation, and the state mismatch the largest fraction of nodes whose state differs
  from the shifted earlier state (shift rounded to a node).

On an open contact line (a pad, a block: `ExplicitScheme.closed_line` false) nothing travels
around the line: ``c = 0`` (left out of ``to_dict``), zones are counted without wrapping around its ends, and the
stationarity test compares the snapshots unshifted (a steady state, not a wave); ``line``
says which analysis was done.
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass, field

import numpy as np
import lazy_loader as lazy

from ..results import Result
from ..quantities import COMMON as Q
from ..cf import finish
from ..errors import ParameterError
from .states import SEPARATION, STATE_NAMES, STICK, count_zones, regime_code, regime_name
from .. import validation as check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["RegimeResult", "classify", "pattern_shift", "pattern_speed"]


def pattern_shift(x1: np.ndarray, x2: np.ndarray, max_shift: float = np.pi) -> float:
    """Shift ``s`` (radians, ``|s| <= max_shift``) with ``x2(theta) ~ x1(theta - s)``."""
    x1, x2 = check.finite_array("x1", x1, 1), check.finite_array("x2", x2, 1)
    if x1.size != x2.size:
        raise ParameterError("x2", f"{x2.size} values", f"as many values as x1 ({x1.size})")
    max_shift = Q.check("max_shift", max_shift)
    N = x1.size
    a, b = x1 - x1.mean(), x2 - x2.mean()
    corr = np.real(np.fft.ifft(np.conj(np.fft.fft(a)) * np.fft.fft(b)))  # corr[k] = sum a[j] b[j + k]
    lag = (np.arange(N) + N // 2) % N - N // 2
    allowed = np.abs(lag) * 2 * np.pi / N <= max_shift + 1e-12
    i = int(np.flatnonzero(allowed)[np.argmax(corr[allowed])])
    c0, cm, cp = corr[i], corr[i - 1], corr[(i + 1) % N]
    den = cm - 2 * c0 + cp
    frac = 0.5 * (cm - cp) / den if den < 0 else 0.0
    return float((lag[i] + np.clip(frac, -0.5, 0.5)) * 2 * np.pi / N)


def _shift(x, s, theta):
    """``x(theta - s)`` by periodic linear interpolation."""
    return np.interp((theta - s) % (2 * np.pi), theta, x, period=2 * np.pi)


@dataclass(frozen=True, repr=False)
class RegimeResult(Result):
    """Limit regime of a run: zones, mode number, wave speed, stationarity.

    ``relative_speeds`` holds ``c`` over each reference speed of the scheme
    (`ExplicitScheme.speed_scales`), read as attributes ``c_over_<name>`` (for the ring,
    ``c_over_sqrt_a``: ``c`` over the reduced model's P-wave speed ``sqrt(a)``).
    """

    MODEL: ClassVar[str] = "brake"

    regime: str
    fractions: dict
    n: int
    n_fft: int
    c: float
    stationary: bool
    residual: float
    state_mismatch: float
    window: tuple
    snapshots: int
    params: dict
    relative_speeds: dict = field(default_factory=dict)
    line: str = "closed"

    def __getattr__(self, name):
        speeds = self.__dict__.get("relative_speeds", {})
        if name.startswith("c_over_") and name[len("c_over_"):] in speeds:
            return speeds[name[len("c_over_"):]]
        raise AttributeError(name)

    def to_dict(self) -> dict:
        out = {k: getattr(self, k) for k in ("regime", "n", "n_fft")}
        if self.line == "closed":  # nothing travels around an open line: it has no pattern speed
            out["c"] = self.c
            out.update({f"c_over_{k}": v for k, v in self.relative_speeds.items()})
        out.update({k: getattr(self, k) for k in ("stationary", "residual", "state_mismatch", "snapshots", "line")})
        out.update({"fractions": dict(self.fractions), "window": list(self.window), "params": dict(self.params)})
        return {k: (float(v) if isinstance(v, np.floating) else v) for k, v in out.items()}

    def to_xarray(self) -> xr.Dataset:
        """The state fractions over ``kind``; the rest as attributes (numbers), with the
        regime's code (`stickslip.contact.states.REGIME_CODES`)."""
        d = self.to_dict()
        frac = d.pop("fractions")
        ds = xr.Dataset({"fraction": ("kind", list(frac.values()),
                                      {"units": "1", "long_name": "fraction of the contact nodes in each state"})},
                        coords={"kind": ("kind", list(frac), {"long_name": "contact state"})})
        return finish(ds, "limit regime of a contact run", "brake",
                      params={**d, "regime_code": regime_code(self.regime),
                              "speed_units": "c: rad per unit Omega t; c_over_*: units of the reference speed"})


def classify(run, transits: float | None = None, min_fraction: float = 0.01, min_run: int = 2,
             tol: float = 0.1) -> RegimeResult:
    """Classify the last ``transits`` (default: the run's dense tail) of a contact run.

    Parameters
    ----------
    run : RunRecord
        A run of `stickslip.contact.runs` (a `RingRun`, a `FemRun`) with at least 3
        snapshots in the window.
    transits : float, optional
        Window length in wave transits; default the ``tail`` of the run.
    min_fraction : float
        A zone kind is present if its time-averaged node fraction is >= this, in [0, 1).
    min_run : int
        Stick zones shorter than this (nodes) are not counted in ``n``.
    tol : float
        Stationarity threshold on the relative residual (and on the state mismatch).
    """
    from .runs import RunRecord

    if not isinstance(run, RunRecord):
        raise ParameterError("run", run, "a run (a RunRecord: RingRun, FemRun, BodyRun)")
    s = run.scheme
    min_fraction = Q.check("min_fraction", min_fraction)
    min_run, tol = Q.check("min_run", min_run), Q.check("stationarity_tol", tol, "tol")
    if transits is None:
        span = run.settings["tail_samples"] * run.settings["chunk"] * s.dt
    else:
        span = Q.check("transits", transits) * s.transit_time
    t1 = run.t_end
    snap_t = np.asarray(run.snapshots.get("snap_t", []))
    sel = np.flatnonzero(snap_t >= t1 - span - 1e-12 * t1)
    if sel.size < 3:
        raise ParameterError("transits", transits if transits is not None else run.transits,
                             f"long enough for 3 snapshots in the analysis window (it holds {sel.size}: run longer)")
    ser = run.t >= snap_t[sel[0]]
    fr = dict(zip(STATE_NAMES, (float(x) for x in run.series["fractions"][ser].mean(axis=0))))
    regime = regime_name([k for k, v in fr.items() if v >= min_fraction])
    state, U, V, ts = (run.snapshots[k][sel] for k in ("state", "U", "V", "snap_t"))
    power = np.mean(np.abs(run.series["modes_V"][ser]) ** 2, axis=0)
    n_fft = int(np.argmax(power[1:]) + 1)
    closed = bool(s.closed_line)
    c = pattern_speed(V, ts, n_fft) if closed else 0.0
    n = 0
    for mask, kind in ((state == STICK, "stick"), (state != SEPARATION, "slip")):
        if fr[kind] >= min_fraction and n == 0:
            n = count_zones(_wave_frame(mask, c * (ts - ts[0]), s.dtheta), min_run, periodic=closed)
    n = n_fft if n == 0 else n
    residual, mismatch = _stationarity(s.theta, U, V, state, ts, c)
    return RegimeResult(regime, fr, n, n_fft, c, bool(residual < tol and mismatch < tol), residual, mismatch,
                        (float(ts[0]), float(ts[-1])), int(sel.size), s.params.to_dict(),
                        {k: c / v for k, v in s.speed_scales.items()}, "closed" if closed else "open")


def pattern_speed(X: np.ndarray, ts: np.ndarray, n: int) -> float:
    """Speed of the pattern of the snapshots ``X[i]`` (rows at times ``ts``): shifts of at
    most ``pi / n`` between consecutive snapshots, accumulated and fitted against time."""
    n = Q.check("n", n)
    steps = [pattern_shift(X[i], X[i + 1], np.pi / n) for i in range(len(ts) - 1)]
    return float(np.polyfit(ts, np.concatenate([[0.0], np.cumsum(steps)]), 1)[0])


def _wave_frame(masks, shifts, dtheta):
    """Nodes where the mask holds in at least half of the snapshots seen in the wave frame
    (snapshot ``i`` moved back by ``shifts[i]``), relative to the most occupied node."""
    occupancy = np.mean([np.roll(m, -int(np.round(d / dtheta))) for m, d in zip(masks, shifts)], axis=0)
    return occupancy >= 0.5 * occupancy.max() if occupancy.max() > 0 else occupancy > 0


def _stationarity(theta, U, V, state, ts, c):
    """Largest RMS misfit of ``X(t_j)`` and ``X(t_i)`` shifted by ``c (t_j - t_i)``, relative to
    the RMS of ``X - mean`` (X = U, V), and the largest fraction of mismatched node states."""
    res, mism = 0.0, 0.0
    dev = [X - X.mean(axis=1, keepdims=True) for X in (U, V)]
    scale = [max(float(np.sqrt(np.mean(X**2))), 1e-300) for X in dev]
    for i in range(len(ts)):
        for j in range(i + 1, len(ts)):
            d = c * (ts[j] - ts[i])
            for X, sc in zip(dev, scale):
                res = max(res, float(np.sqrt(np.mean((X[j] - _shift(X[i], d, theta)) ** 2))) / sc)
            k = int(np.round(d / (theta[1] - theta[0])))
            mism = max(mism, float(np.mean(np.roll(state[i], k) != state[j])))
    return res, mism

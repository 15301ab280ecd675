"""Rate-and-state parameters from a laboratory record: a velocity-step or slide-hold-slide history
of the friction coefficient, fitted by the quasi-static spring-slider (`stickslip.rsf.slide`).

A record (`read_record`: a CSV with the columns ``time`` [s], ``friction`` and ``load_velocity``
[m/s], time strictly increasing, the load velocity held between its changes) is the friction of a
slider pulled at the load-point velocities of the record. `fit_record` finds ``a``, ``b``, ``D_c``
(and ``b2``, ``D_c2`` with two state variables) and the stiffness of the machine and sample per
unit normal stress, ``k / sigma`` [1/m], and ``f0``, by nonlinear least squares (scipy's
trust-region ``least_squares``, on the logarithms of all but ``f0``, so each stays positive), with
``V_0`` the record's first load velocity (steady sliding at it before the record). The model's
friction is interpolated onto the record's times (cubic, from 4 samples per record sample). It
starts from the parameters the record's first step shows (`_guess`), and from ``D_c`` ten times
smaller or larger if that start ends on a wall (the slider overflowing) or a bound.

Uncertainties: the standard errors of the linearised problem at the optimum, ``s^2 (J^T J)^-1`` with
``s^2`` the residuals' variance (``n - p`` degrees of freedom), carried to each parameter from its
logarithm (``sigma_p = p sigma_ln p``). They say how well the record pins the parameters if the model
is right and the noise white; a record the model does not fit has a large ``rms_residual``.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass

import numpy as np

from ..errors import NoSolutionError, ParameterError
from ..quantities import RSF as Q
from ..results import Result
from ..validation import regular_input

__all__ = ["Record", "read_record", "record_from_arrays", "fit_record", "RsfFit"]

#: Columns of a record (CSV header names).
COLUMNS = ("time", "friction", "load_velocity")
#: Rows of a record, at most.
MAX_ROWS = 1_000_000
#: The slider's tolerance while fitting (its error, 1e-7 of the friction, far below a record's noise).
RTOL = 1e-7


@dataclass(frozen=True, eq=False)
class Record:
    """A laboratory record: ``t`` [s] from 0, the ``friction`` and the ``load_velocity`` [m/s] at each."""

    t: np.ndarray
    friction: np.ndarray
    load_velocity: np.ndarray
    source: str = "record"

    @property
    def history(self) -> tuple[np.ndarray, np.ndarray]:
        """``(times, velocities)``: where the load velocity takes each new value (the first at 0)."""
        change = np.concatenate([[0], np.flatnonzero(np.diff(self.load_velocity) != 0.0) + 1])
        return self.t[change], self.load_velocity[change]


def record_from_arrays(t, friction, load_velocity, source: str = "record") -> Record:
    """A `Record` from three arrays (checked: finite, as long as each other, time strictly increasing;
    shifted to start at 0)."""
    arrays = []
    for name, value in (("time", t), ("friction", friction), ("load_velocity", load_velocity)):
        try:
            a = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            raise ParameterError(name, f"<{type(value).__name__}>", "an array of numbers") from None
        if a.ndim != 1 or not np.all(np.isfinite(a)):
            raise ParameterError(name, f"{source}: {a.size} values", "one column of finite numbers")
        arrays.append(a)
    t, mu, v = arrays
    if not (t.size == mu.size == v.size) or not 10 <= t.size <= MAX_ROWS:
        raise ParameterError("time", f"{source}: {t.size} rows", f"10 to {MAX_ROWS} rows, as many of each column")
    if np.any(np.diff(t) <= 0.0):
        k = int(np.flatnonzero(np.diff(t) <= 0.0)[0])
        raise ParameterError("time", f"{source}: {t[k + 1]:g} s after {t[k]:g} s (row {k + 2})",
                             "strictly increasing times")
    if np.any(v < 0.0) or v[0] <= 0.0:
        raise ParameterError("load_velocity", f"{source}: {v.min():g} m/s" if np.any(v < 0) else f"{v[0]:g} m/s first",
                             "load velocities >= 0 [m/s], the first > 0 (steady sliding at it before the record)")
    return Record(t - t[0], mu, v, source)


def read_record(record) -> Record:
    """A `Record` from the CSV file ``record`` (a path) with the header columns ``time``, ``friction``,
    ``load_velocity``."""
    path = regular_input("record", record, "a CSV record with the columns time, friction, load_velocity")
    try:
        with open(path, newline="") as fh:
            rows = list(csv.reader(fh))
    except (OSError, UnicodeDecodeError) as err:
        raise ParameterError("record", str(path), f"a readable CSV text file ({err.__class__.__name__})") from None
    if not rows:
        raise ParameterError("record", str(path), "a CSV file with a header row: time, friction, load_velocity")
    header = [h.strip() for h in rows[0]]
    missing = [c for c in COLUMNS if c not in header]
    if missing:
        raise ParameterError("record", str(path), f"the columns {', '.join(COLUMNS)} in its header (missing: "
                             f"{', '.join(missing)}; it has {', '.join(header) or 'none'})")
    if len(rows) - 1 > MAX_ROWS:
        raise ParameterError("record", str(path), f"at most {MAX_ROWS} rows")
    index = [header.index(c) for c in COLUMNS]
    try:
        data = np.array([[float(row[i]) for i in index] for row in rows[1:] if row], dtype=float)
    except (ValueError, IndexError):
        raise ParameterError("record", str(path), "numbers in every row of the columns time, friction, "
                             "load_velocity") from None
    if data.ndim != 2 or len(data) < 10:
        raise ParameterError("record", str(path), "at least 10 rows of data")
    return record_from_arrays(data[:, 0], data[:, 1], data[:, 2], path.name)


@dataclass(frozen=True, eq=False, repr=False)
class RsfFit(Result):
    """The fitted parameters, their standard errors, the residuals' RMS and the model's friction at
    the record's times."""

    names: tuple
    values: np.ndarray
    errors: np.ndarray
    rms_residual: float
    v_ref: float
    evolution: str
    model: np.ndarray
    record: Record
    MODEL = "rsf"

    def __getitem__(self, name: str) -> float:
        return float(self.values[self.names.index(name)])

    def error(self, name: str) -> float:
        return float(self.errors[self.names.index(name)])

    def to_dict(self) -> dict:
        out = {}
        for name, value, error in zip(self.names, self.values, self.errors):
            out[name] = float(value)
            out[f"{name}_error"] = float(error)
        return {**out, "rms_residual": self.rms_residual, "v_ref": self.v_ref,
                "evolution": self.evolution, "rows": int(self.record.t.size)}


def _model(record: Record, x: np.ndarray, states: int, evolution: str, v_ref: float) -> np.ndarray:
    """The slider's friction at the record's times for ``x = (f0, ln a, ln b, ln D_c, ln k/sigma[, ln b2,
    ln D_c2])``."""
    from scipy.interpolate import CubicSpline

    from .law import RateState
    from .slider import SpringSlider, slide

    p = np.exp(x[1:])
    law = RateState(p[0], p[1], p[2], f0=x[0], v_ref=v_ref, evolution=evolution,
                    **({"b2": p[4], "dc2": p[5]} if states == 2 else {}))
    slider = SpringSlider(law, 1.0, p[3])  # per unit normal stress: the stiffness is k / sigma [1/m]
    times, velocities = record.history
    t_end = float(record.t[-1])
    run = slide(slider, velocities, t_end, times=times, samples=min(4 * record.t.size + 1, 200_001), rtol=RTOL)
    return CubicSpline(run.t, run.friction)(record.t)


def _guess(record: Record, states: int) -> list[np.ndarray]:
    """Starts ``(f0, ln a, ln b, ln D_c, ln k/sigma[, ln b2, ln D_c2])``, the likeliest first: ``f0`` the
    mean friction before the first change; ``k / sigma`` from the friction's rise just after it
    (``dmu/dt = (k / sigma) (V_new - V_old)`` while the slip rate has not yet changed); ``a`` from the
    peak's jump and ``a - b`` from the friction's change by the end of that velocity, each over
    ``ln(V_new / V_old)``; ``D_c`` the slip at the new velocity while the friction falls from the peak
    a third of the way back (then a tenth and ten times that)."""
    times, velocities = record.history
    t, mu = record.t, record.friction
    before = t < times[1]
    f0 = float(np.mean(mu[before]))
    travel = float(np.sum(np.diff(np.append(times, t[-1])) * velocities))
    k, a, b, dc = 1.0 / max(travel, 1e-300), 0.01, 0.01, travel / 30.0
    v0, v1 = velocities[0], velocities[1]
    end = times[2] if len(times) > 2 else t[-1]
    during = np.flatnonzero((t >= times[1]) & (t < end))
    if v1 > 0 and during.size >= 6:
        first = during[:6]
        slope = np.polyfit(t[first], mu[first], 1)[0]
        k = abs(slope / (v1 - v0)) or k
        ratio = math.log(v1 / v0)
        peak = during[np.argmax(mu[during] * np.sign(ratio))]
        a = max(abs(mu[peak] - f0) / abs(ratio), 1e-4)
        b = max(a - (mu[during[-1]] - f0) / ratio, 1e-4)
        after = during[during > peak]
        fallen = after[np.abs(mu[after] - mu[peak]) >= abs(mu[peak] - mu[during[-1]]) / 3.0]
        if fallen.size:
            dc = max(v1 * (t[fallen[0]] - t[peak]), 1e-12)
    return [np.concatenate([[f0], np.log([a, b, d, k] + ([0.5 * b, 10 * d] if states == 2 else []))])
            for d in (dc, dc / 10.0, dc * 10.0)]


def fit_record(record: Record, states: int = 1, evolution: str = "aging") -> RsfFit:
    """``f0``, ``a``, ``b``, ``dc`` (and ``b2``, ``dc2`` with ``states = 2``) and ``stiffness_per_stress``
    (``k / sigma``, 1/m) of ``record`` (see the module docstring), from a few starts (the best kept)."""
    from scipy.optimize import least_squares

    if not isinstance(record, Record):
        raise ParameterError("record", record, "a Record (read_record, record_from_arrays)")
    if isinstance(states, bool) or states not in (1, 2):
        raise ParameterError("states", states, "1 or 2 state variables")
    Q.check("evolution", evolution)
    times, velocities = record.history
    if len(times) < 2:
        raise ParameterError("record", record.source, "a load velocity that changes at least once (a velocity step "
                             "or a hold): a constant one says nothing of a, b or D_c")
    v_ref = float(velocities[0])

    def residual(x):
        try:
            return _model(record, x, states, evolution, v_ref) - record.friction
        except (ParameterError, NoSolutionError):
            return np.full(record.t.size, 1e3)  # outside the laws' ranges or overflowing: a wall

    best = None
    for x0 in _guess(record, states):  # the likeliest start first; the others only if it ends on a wall or a bound
        try:
            sol = least_squares(residual, x0, method="trf", diff_step=1e-6, max_nfev=60 * x0.size)
        except (ValueError, FloatingPointError):
            continue
        if best is None or sol.cost < best.cost:
            best = sol
        if np.max(np.abs(sol.fun)) < 1e3 and np.all(np.exp(sol.x[1:]) > 1e-6):
            break
    if best is None or not np.isfinite(best.cost) or np.max(np.abs(best.fun)) >= 1e3:
        raise NoSolutionError(f"no fit of {record.source}: the slider leaves the laws' ranges from every start")
    names = ("f0", "a", "b", "dc", "stiffness_per_stress") + (("b2", "dc2") if states == 2 else ())
    n, m = record.t.size, best.x.size
    s2 = 2.0 * best.cost / max(n - m, 1)
    values = np.concatenate([best.x[:1], np.exp(best.x[1:])])
    try:
        sd = np.sqrt(np.clip(np.diag(s2 * np.linalg.inv(best.jac.T @ best.jac)), 0.0, None))
        errors = np.concatenate([sd[:1], values[1:] * sd[1:]])  # from the logarithms: sigma_p = p sigma_ln p
    except np.linalg.LinAlgError:
        errors = np.full(m, math.inf)
    model = best.fun + record.friction
    return RsfFit(names, values, errors, float(math.sqrt(2.0 * best.cost / n)), v_ref, evolution, model, record)

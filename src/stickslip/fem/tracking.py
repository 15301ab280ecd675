"""Sweeps of the complex eigenvalue analysis over one number of a config, with every mode
tracked from point to point by its shape.

`cea_sweep(config, key, values, store)` runs the CEA of ``config`` with ``key`` (a number of
the config: ``contact.friction``, ``material[1].young``, ``surface.omega``, ...) set to each
of ``values``, through the package's resumable sweep (`stickslip.sweep.run_sweep`: Dask,
in parallel, checkpointed in a Zarr ``store``). Each point keeps its eigenvalues in the band
and a sketch of each mode shape (the shape on the body's free dofs, folded into
``SKETCH`` rows with random signs: inner products kept to some 5 %, a few kB per mode
whatever the mesh).

`track` links the modes of neighbouring points by the modal assurance criterion of their
shapes, ``MAC(a, b) = |a^H b|^2 / (|a|^2 |b|^2)``: one to one, the pairing of largest total MAC
(`scipy.optimize.linear_sum_assignment`), a link only where ``MAC >= MIN_MAC``; a mode left
over starts a branch, a branch left over ends. Tracking by shape, not by frequency, follows
modes through crossings and veerings.

Along each branch the critical value, where the mode first turns unstable (growth rate above
``NEUTRAL |s|``) or stable, is located between the two points by bisection, each step a new
CEA whose mode is the one of largest MAC with the branch, until the bracket is within ``tol``
of the swept value's step; its ``partner`` is the branch nearest in frequency (within
``COUPLING`` of it) whose growth rate goes the other way over the same bracket: the mode it
coalesces with (mode coupling), or -1.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import dask
import numpy as np
import lazy_loader as lazy
from scipy.optimize import linear_sum_assignment

from ..cf import finish
from ..errors import ParameterError
from ..quantities import FEM as Q
from ..sweep import run_sweep, worker_pool
from .cea import NEUTRAL, complex_eigenvalues, count_sketch, linearised
from .config import load_config, read_toml, resolve_key
from .scheme import BodyScheme, ContactProblem

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["cea_sweep", "track", "Tracked", "MIN_MAC", "SKETCH"]

#: Rows of the sketch of a mode shape.
SKETCH = 256
#: The least MAC of a link between the modes of neighbouring points.
MIN_MAC = 0.4
#: A partner's frequency within this (relative) of the branch's at its onset.
COUPLING = 0.05
#: The most modes kept per point.
MAX_MODES = 200


def _solve(config, key, value, modes_kept):
    """``(s, sketches)`` of the CEA of ``config`` with ``key = value``: eigenvalues and the
    sketched shapes on the free dofs (unit length), at most ``modes_kept``."""
    cfg = load_config(config, {key: value})
    problem = cfg.problem()
    modes = complex_eigenvalues(problem, cfg.band, cfg.count, mode_shapes=True, complete_below=cfg.complete_below,
                                **cfg.cea_options)
    if isinstance(problem, ContactProblem):  # the kept dofs among the scheme's free ones
        n, kept = BodyScheme(problem).free.size, linearised(problem, **cfg.cea_options)[3]
    else:  # a pair: its free dofs, ahead of the contact multipliers (whose number varies)
        n = problem.linearised()[3].size
        kept = np.arange(n)
    sketch = count_sketch(n, SKETCH)
    out = np.zeros((min(len(modes.s), modes_kept), SKETCH), dtype=complex)
    for k in range(out.shape[0]):
        full = np.zeros(n, dtype=complex)
        full[kept] = modes.shapes[:kept.size, k]
        out[k] = sketch(full)
    return modes.s[:out.shape[0]], out


def _point(config: str, key: str, modes_kept: int, value: float) -> dict:
    """One point of the sweep as `run_sweep` stores it (NaN-padded to ``modes_kept``)."""
    s, x = _solve(config, key, value, modes_kept)
    pad = lambda a, size: np.concatenate([a, np.full(size - a.size, np.nan)])  # noqa: E731
    return {"modes": float(len(s)), "s_real": pad(s.real, modes_kept), "s_imag": pad(s.imag, modes_kept),
            "sketch_real": pad(x.real.ravel(), modes_kept * SKETCH),
            "sketch_imag": pad(x.imag.ravel(), modes_kept * SKETCH)}


def mac(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The MAC of every row of ``a`` with every row of ``b``."""
    dot = np.abs(np.conj(a) @ b.T) ** 2
    return dot / np.outer(np.sum(np.abs(a) ** 2, axis=1), np.sum(np.abs(b) ** 2, axis=1))


def track(s_points: list, sketches: list, min_mac: float = MIN_MAC) -> tuple[np.ndarray, np.ndarray]:
    """Branches through the points: ``(s, where)``, ``s[b, p]`` the eigenvalue of branch ``b`` at
    point ``p`` (NaN where it has none) and ``where[b, p]`` its position among the point's modes
    (-1)."""
    branches: list[dict] = []
    last: list[int] = []  # the branches with a mode at the previous point
    for p, (s, x) in enumerate(zip(s_points, sketches)):
        taken, now = set(), []
        if last and len(s):
            score = mac(np.array([branches[b]["x"] for b in last]), x)
            rows, cols = linear_sum_assignment(-score)
            for r, c in zip(rows, cols):
                if score[r, c] >= min_mac:
                    b = branches[last[r]]
                    b["s"][p], b["at"][p], b["x"] = s[c], c, x[c]
                    taken.add(int(c))
                    now.append(last[r])
        for c in range(len(s)):
            if c not in taken:
                # NaN in both parts where the branch has no mode (nan + 0j stored a frequency of 0 Hz there)
                b = {"s": np.full(len(s_points), complex(np.nan, np.nan)), "at": np.full(len(s_points), -1), "x": x[c]}
                b["s"][p], b["at"][p] = s[c], c
                branches.append(b)
                now.append(len(branches) - 1)
        last = now
    if not branches:
        return np.zeros((0, len(s_points)), complex), np.zeros((0, len(s_points)), int)
    return np.array([b["s"] for b in branches]), np.array([b["at"] for b in branches])


def _unstable(s) -> np.ndarray:
    return s.real > NEUTRAL * np.abs(s)


@dataclass(frozen=True, eq=False)
class Tracked:
    """Tracked branches of a CEA sweep: ``s[branch, point]`` over ``values`` of ``key``, each
    branch's ``critical`` value (the first where its growth rate changes sign, NaN if it does
    not), the frequency there [Hz], its ``partner`` (-1: none) and ``turn``: +1 if it turns
    unstable as the value grows, -1 if it turns stable, 0 without a critical value."""

    key: str
    values: np.ndarray
    s: np.ndarray
    critical: np.ndarray
    critical_frequency: np.ndarray
    partner: np.ndarray
    turn: np.ndarray
    tolerance: float
    band: tuple

    def to_xarray(self) -> xr.Dataset:
        name = self.key.split(".")[-1]
        units = Q[name].units if name in Q else "1"
        value = ("value", self.values, {"units": units, "long_name": f"swept value of {self.key}"})
        missing = "NaN where the branch has no mode at this value (it starts later or ended)"
        data = {"growth_rate": (("branch", "value"), self.s.real, {"comment": missing}),
                "frequency": (("branch", "value"), self.s.imag / (2 * math.pi), {"comment": missing}),
                "growing": (("branch", "value"), _unstable(self.s).astype(np.int8),
                            {"comment": "0 where the branch has no mode at this value"}),
                "critical": ("branch", self.critical, {"units": units, "long_name": f"{self.key} where the branch's "
                                                   "growth rate changes sign (NaN: it does not)"}),
                "critical_frequency": ("branch", self.critical_frequency),
                "partner": ("branch", self.partner.astype(np.int32)),
                "turn": ("branch", self.turn.astype(np.int8))}
        ds = xr.Dataset(data, coords={"value": value, "branch": ("branch", np.arange(len(self.s)))})
        return finish(ds, f"CEA sweep over {self.key} with tracked modes", "fem",
                      params={"swept_key": self.key, "onset_tolerance": self.tolerance,
                              "band_lo": self.band[0], "band_hi": self.band[1], "min_mac": MIN_MAC})


def cea_sweep(config, key: str, values, store, *, tol: float = 1e-2, workers: int | None = None,
              progress=None, overwrite: bool = False, scheduler="processes") -> Tracked:
    """The CEA of ``config`` at each of ``values`` of ``key``, tracked (see the module docstring);
    ``store`` is the sweep's Zarr checkpoint (resumed if it holds this sweep). ``key`` as
    `stickslip.fem.config.resolve_key` takes it (``friction`` for ``contact.friction``)."""
    values = [float(v) for v in values]
    if len(values) < 2 or np.any(np.diff(values) <= 0):
        raise ParameterError("values", values, "at least two increasing values")
    tol = Q.check("onset_tolerance", tol, "tol")
    key = resolve_key(read_toml(config), key)
    first = load_config(config, {key: values[0]})  # the key and the first value checked before any work
    load_config(config, {key: values[-1]})
    kept = min(MAX_MODES, 16 * first.count)
    func = functools.partial(_point, str(config), key, kept)
    outputs = {"modes": "1", "s_real": ("1/s", kept), "s_imag": ("1/s", kept),
               "sketch_real": ("1", kept * SKETCH), "sketch_imag": ("1", kept * SKETCH)}
    ds = run_sweep(func, {"value": values}, store, outputs=outputs, workers=workers, progress=progress,
                   overwrite=overwrite, scheduler=scheduler, attrs={"config": str(config), "swept_key": key},
                   title=f"CEA sweep over {key}", model="fem")
    s_points, sketches = [], []
    for p in range(len(values)):
        m = int(ds["modes"].values[p])
        s_points.append(ds["s_real"].values[p, :m] + 1j * ds["s_imag"].values[p, :m])
        sketches.append((ds["sketch_real"].values[p, :m * SKETCH] + 1j * ds["sketch_imag"].values[p, :m * SKETCH])
                        .reshape(m, SKETCH))
    s, _ = track(s_points, sketches)
    if scheduler == "processes" and workers == 1:
        scheduler = "synchronous"
    critical, freq, partner, turn = _onsets(config, key, np.array(values), s, s_points, sketches, tol, kept,
                                            scheduler, workers)
    return Tracked(key, np.array(values), s, critical, freq, partner, turn, tol, tuple(first.band))


def _onsets(config, key, values, s, s_points, sketches, tol, kept, scheduler="synchronous", workers=None):
    """Each branch's first onset of instability, by bisection between the points (see the module
    docstring), its frequency and partner. The bisections of all branches advance together, a
    round at a time: the CEAs of a round run in parallel on ``scheduler`` (`worker_pool`), and a
    value shared by several branches (partners turn in the same bracket) is solved once."""
    nb = len(s)
    onset, freq, partner, turn = np.full(nb, np.nan), np.full(nb, np.nan), np.full(nb, -1), np.zeros(nb, int)
    jobs = {}  # branch -> [p, lo, hi, at, shape, target state]
    for b in range(nb):
        up = _unstable(s[b])
        known = ~np.isnan(s[b])
        for p in range(len(values) - 1):
            if known[p] and known[p + 1] and up[p] != up[p + 1]:
                shape = sketches[p + 1][int(np.argmin(np.abs(s_points[p + 1] - s[b, p + 1])))]
                jobs[b] = [p, values[p], values[p + 1], s[b, p + 1], shape, up[p + 1]]
                break
    solved = {}
    with worker_pool(scheduler, workers) as evaluate:
        while True:
            active = [b for b, (p, lo, hi, *_) in jobs.items() if hi - lo > tol * (values[p + 1] - values[p])]
            mids = sorted({0.5 * (jobs[b][1] + jobs[b][2]) for b in active} - set(solved))
            if not active:
                break
            for value, result in zip(mids, evaluate([dask.delayed(_solve)(config, key, v, kept) for v in mids])):
                solved[value] = result
            for b in active:
                job = jobs[b]
                mid = 0.5 * (job[1] + job[2])
                z, x = solved[mid]
                if not len(z):
                    job[1] = job[2] = mid  # no mode at all there: the bracket stops
                    continue
                k = int(np.argmax(mac(job[4][None, :], x)[0]))
                if _unstable(z[k : k + 1])[0] == job[5]:
                    job[2], job[3], job[4] = mid, z[k], x[k]
                else:
                    job[1] = mid
    for b, (p, lo, hi, at, _, target) in jobs.items():
        onset[b], freq[b], turn[b] = 0.5 * (lo + hi), at.imag / (2 * math.pi), 1 if target else -1
        rising = bool(target)  # the partner's growth rate goes the other way
        falling = [c for c in range(nb) if c != b and not np.isnan(s[c, p])
                   and not np.isnan(s[c, p + 1]) and (s[c, p + 1].real < s[c, p].real) == rising
                   and abs(s[c, p + 1].imag - s[b, p + 1].imag) <= COUPLING * abs(s[b, p + 1].imag)]
        if falling:
            partner[b] = min(falling, key=lambda c: abs(s[c, p + 1].imag - s[b, p + 1].imag))
    return onset, freq, partner, turn

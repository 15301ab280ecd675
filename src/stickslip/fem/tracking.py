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
``NEUTRAL |s|``) or stable, is located between the two points by multisection
(`stickslip.fem.critical`: rounds of new CEAs on the sweep's workers, each CEA's mode the one
of largest MAC with the branch) until the bracket is within ``tol`` of the swept value's step;
every CEA of the search is kept in the sweep's store as it finishes (group `SEARCH`), and a
resumed search reuses them. Its ``partner`` is the branch nearest in frequency (within
``COUPLING`` of it) whose growth rate goes the other way over the same bracket: the mode it
coalesces with (mode coupling), or -1.
"""

from __future__ import annotations

import functools
import logging
import math
import os
from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy
from scipy.optimize import linear_sum_assignment

from ..cf import finish
from ..errors import ParameterError
from ..quantities import FEM as Q
from ..files import exclusive
from ..sweep import run_sweep, worker_pool
from ..sweep.offgrid import OffGrid
from .cea import complex_eigenvalues, count_sketch, linearised
from .critical import COUPLING, mac, search, stored_solve, unpack, unstable  # noqa: F401 - COUPLING: its home
from .config import load_config, read_toml, resolve_key
from .scheme import BodyScheme, ContactProblem

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

log = logging.getLogger("stickslip.fem")

__all__ = ["cea_sweep", "solve_point", "track", "Tracked", "MIN_MAC", "SKETCH", "SEARCH", "MAX_MODES"]

#: Rows of the sketch of a mode shape.
SKETCH = 256
#: The least MAC of a link between the modes of neighbouring points.
MIN_MAC = 0.4
#: The group of the sweep's store that keeps the CEAs of the critical values' search.
SEARCH = "critical_search"
#: The most modes kept per point.
MAX_MODES = 200


def solve_point(config, overrides: dict, modes_kept: int, key: str | None = None, value: float | None = None):
    """``(s, sketches)`` of the CEA of ``config`` with its numbers ``overrides`` (and ``key = value``):
    eigenvalues and the sketched shapes on the free dofs (unit length), at most ``modes_kept``."""
    cfg = load_config(config, {**overrides, **({} if key is None else {key: value})})
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
    s, x = solve_point(config, {key: value}, modes_kept)
    pad = lambda a, size: np.concatenate([a, np.full(size - a.size, np.nan)])  # noqa: E731
    return {"modes": float(len(s)), "s_real": pad(s.real, modes_kept), "s_imag": pad(s.imag, modes_kept),
            "sketch_real": pad(x.real.ravel(), modes_kept * SKETCH),
            "sketch_imag": pad(x.imag.ravel(), modes_kept * SKETCH)}


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
                "growing": (("branch", "value"), unstable(self.s).astype(np.int8),
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
              progress=None, overwrite: bool = False, scheduler="processes", multisection: bool = True) -> Tracked:
    """The CEA of ``config`` at each of ``values`` of ``key``, tracked (see the module docstring);
    ``store`` is the sweep's Zarr checkpoint (resumed if it holds this sweep, with the CEAs of the
    critical values' search). ``key`` as `stickslip.fem.config.resolve_key` takes it (``friction``
    for ``contact.friction``). ``multisection=False`` searches the critical values by bisection
    (one CEA per bracket a round, whatever the workers: the search before issue 44)."""
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
    width = 1 if scheduler == "synchronous" or not multisection else workers or os.cpu_count() or 1
    with exclusive(store, "store"):  # the search's CEAs go to the sweep's store, checked by run_sweep
        keep = OffGrid(store, SEARCH)
        stored = {v: unpack(arrays) for v, arrays in keep.load().items()}
        solve = functools.partial(stored_solve, functools.partial(solve_point, str(config), {}, kept, key), keep)
        with worker_pool(scheduler, workers) as evaluate:
            found = search(values, s, s_points, sketches, tol, solve, evaluate, width, stored)
    if found.rounds:
        log.info("critical values of %d branch(es): %d round(s) of %d CEA(s) computed, %d reused from %s",
                 int(np.sum(found.turn != 0)), found.rounds, found.computed, found.reused, store)
    return Tracked(key, np.array(values), s, found.onset, found.frequency, found.partner, found.turn, tol,
                   tuple(first.band))

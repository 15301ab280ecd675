"""Stability maps over two parameters: the friction coefficient and one more number of a config
(the piston's pressure, the disc's speed, a lining's modulus, ...).

`stability_map(config, key, values, frictions, store)` runs, for each of ``values`` of ``key``, the
CEA of ``config`` at each of ``frictions``, through the package's resumable sweep
(`stickslip.sweep.run_sweep`: Dask, one row of the map a point, checkpointed in a Zarr ``store``):

* with ``[cea] reduced_modes``: one reduction basis per row (`stickslip.fem.reduced.modal_basis`)
  and the reduced friction sweep on it (`reduced_sweep`);
* without: the full CEA at each friction (`stickslip.fem.tracking.solve_point`).

Either way the modes are tracked along the row by their shapes and each branch's critical friction
found by multisection (`stickslip.fem.critical.search`) to ``tol`` of the friction step; the row's
``onset`` is the least critical friction at which a branch turns unstable.

Each grid point keeps the largest growth rate [1/s] of the band's modes, that mode's frequency [Hz]
and how many modes grow. What the second parameter can change is the model's: with Coulomb friction
and linear elasticity, the CEA depends on the pressure only through the contact's active set and a
pressure law, and on the speed only through the sliding direction, a friction law of the speed and
(plane bodies) the turning disc's gyroscopic terms.
"""

from __future__ import annotations

import functools
import math

import numpy as np

import lazy_loader as lazy

from ..cf import finish
from ..errors import ParameterError
from ..quantities import FEM as Q
from ..sweep import run_sweep
from .config import load_config, read_toml, resolve_key
from .critical import search, unstable
from .tracking import MAX_MODES, solve_point, track

xr = lazy.load("xarray")

__all__ = ["stability_map", "MAX_FRICTIONS"]

#: The most frictions of a row.
MAX_FRICTIONS = 1000


def _row(config: str, key: str, frictions: tuple, tol: float, value: float) -> dict:
    """One row of the map: the CEA at each friction with ``key = value``, its modes tracked and each
    branch's critical friction found by multisection."""
    import dask

    cfg = load_config(config, {key: value})
    if cfg.reduced is not None:
        from .reduced import config_basis, reduced_sweep

        tracked = reduced_sweep(config_basis(cfg, cfg.problem()), frictions, band=cfg.band, tol=tol)
        columns, critical, turn, at = ([tracked.s[:, p] for p in range(len(frictions))], tracked.critical,
                                       tracked.turn, tracked.critical_frequency)
    else:
        solve = functools.partial(solve_point, config, {key: value}, min(MAX_MODES, 16 * cfg.count),
                                  "contact.friction")
        points = [solve(f) for f in frictions]
        s, _ = track([p[0] for p in points], [p[1] for p in points])
        found = search(frictions, s, [p[0] for p in points], [p[1] for p in points], tol, solve,
                       lambda calls: dask.compute(*calls, scheduler="synchronous"))
        columns, critical, turn, at = [p[0] for p in points], found.onset, found.turn, found.frequency
    growth, frequency, count = np.full(len(frictions), np.nan), np.full(len(frictions), np.nan), np.zeros(len(frictions))
    for p, s in enumerate(columns):
        s = s[np.isfinite(s)]
        if s.size:
            k = int(np.argmax(s.real))
            growth[p], frequency[p], count[p] = s.real[k], s.imag[k] / (2 * math.pi), np.sum(unstable(s))
    up = np.flatnonzero((turn == 1) & np.isfinite(critical))
    first = up[np.argmin(critical[up])] if up.size else None
    return {"max_growth_rate": growth, "most_unstable_frequency": frequency, "unstable_modes": count,
            "onset": math.nan if first is None else float(critical[first]),
            "onset_frequency": math.nan if first is None else float(at[first])}


def stability_map(config, key: str, values, frictions, store, *, tol: float = 1e-2, workers: int | None = None,
                  progress=None, overwrite: bool = False, scheduler="processes"):
    """The stability map of ``config`` over ``values`` of ``key`` and ``frictions`` (see the module
    docstring) as an `xarray.Dataset` on ``(value, friction)``: ``max_growth_rate`` [1/s],
    ``most_unstable_frequency`` [Hz], ``unstable_modes``, and per value the ``onset`` friction and its
    frequency (NaN: stable over the frictions), found to ``tol`` of the friction step. ``key`` as
    `stickslip.fem.config.resolve_key` takes it (``pressure`` for ``load[0].pressure``); not the friction
    itself."""
    key = resolve_key(read_toml(config), key)
    tol = Q.check("onset_tolerance", tol, "tol")
    if key == "contact.friction":
        raise ParameterError("key", key, "a number of the config other than contact.friction (the map's other axis "
                             "is the friction)")
    try:
        values = [float(v) for v in values]
        frictions = tuple(float(f) for f in frictions)
    except (TypeError, ValueError):
        raise ParameterError("values", values, "numbers (values of the key, and frictions)") from None
    for name, seq in (("values", values), ("frictions", frictions)):
        if len(seq) < 2 or np.any(np.diff(seq) <= 0):
            raise ParameterError(name, list(seq)[:8], "at least two increasing numbers")
    if len(frictions) > MAX_FRICTIONS:
        raise ParameterError("frictions", f"{len(frictions)} values", f"at most {MAX_FRICTIONS} frictions")
    for f in (frictions[0], frictions[-1]):  # the ends checked before any work (the config's ranges)
        for v in (values[0], values[-1]):
            load_config(config, {key: v, "contact.friction": f})
    reduced = load_config(config).reduced is not None
    n = len(frictions)
    outputs = {"max_growth_rate": ("1/s", n), "most_unstable_frequency": ("Hz", n), "unstable_modes": ("1", n),
               "onset": "1", "onset_frequency": "Hz"}
    ds = run_sweep(functools.partial(_row, str(config), key, frictions, tol), {"value": values}, store, outputs=outputs,
                   workers=workers, progress=progress, overwrite=overwrite, scheduler=scheduler,
                   attrs={"config": str(config), "swept_key": key, "frictions": list(frictions), "tol": tol},
                   title=f"stability map over contact.friction and {key}", model="fem")
    friction = ("friction", np.array(frictions), {"units": "1", "long_name": "Coulomb friction coefficient"})
    grid = ("value", "friction")
    out = xr.Dataset({"max_growth_rate": (grid, ds["max_growth_rate"].values),
                      "most_unstable_frequency": (grid, ds["most_unstable_frequency"].values),
                      "unstable_modes": (grid, ds["unstable_modes"].values),
                      "onset": ("value", ds["onset"].values), "onset_frequency": ("value", ds["onset_frequency"].values)},
                     coords={"value": ("value", np.array(values), {"long_name": f"value of {key}",
                                                                   "units": _units(key)}), "friction": friction})
    method = ("reduced CEA (stickslip.fem.reduced.reduced_sweep)" if reduced else "full CEA") + \
        f": modes tracked by MAC, each branch's critical friction by multisection to {tol:g} of the friction step"
    return finish(out, f"stability map over contact.friction and {key}", "fem",
                  params={"swept_key": key, "onset_method": method, "reduced": int(reduced)})


def _units(key: str) -> str:
    """The units of a config key's last part, as declared (``1`` if not)."""
    name = key.split(".")[-1]
    return Q[name].units if name in Q else "1"

"""What the figures of ring runs (limit regimes, initial conditions) share: one run summarised
(classification over its last transits, energy per transit, the node states of the tail),
summaries stacked into data variables.

Budgets are in wave transits ``2 pi / sqrt(a)``; runs start from steady sliding plus noise
or a seeded mode (`stickslip.brake.perturbed_steady`).
"""

from __future__ import annotations

import numpy as np

from ...brake import classify, separation_number
from ...contact import STATE_NAMES

__all__ = ["PHI", "SNAPS", "PADDED", "summary", "pad_rows", "stack", "all_true"]

#: Why a padded energy history holds NaN.
PADDED = "NaN past a run's last record (a grid's whole steps may end a run a transit short of another's)"

#: Node patterns kept for plotting: nodes resampled to PHI, the last SNAPS snapshots.
PHI, SNAPS = 256, 60


def summary(run, window=2.0) -> dict:
    res = classify(run, transits=window)
    s, tr = run.scheme, run.t / run.scheme.transit_time
    edges = np.arange(0, int(np.floor(tr[-1])) + 1)
    energy = np.array([run.energy[(tr >= a) & (tr < a + 1)].mean() for a in edges[:-1]])
    tail = run.snap_t >= run.t_end - window * s.transit_time
    idx = (np.arange(PHI) * s.nodes) // PHI
    q = len(energy) // 4
    return {"regime": res.regime, "n": res.n, "n_fft": res.n_fft, "c_over_sqrt_a": res.c_over_sqrt_a,
            "c": res.c, "stationary": res.stationary, "residual": res.residual,
            "fraction": [res.fractions[k] for k in STATE_NAMES], "energy": energy,
            "energy_late": energy[-q:].mean(), "energy_spread": abs(energy[-q:].mean() - energy[-2 * q:-q].mean()),
            "state": run.state[tail][-SNAPS:, idx], "kappa": s.params.delta / np.sqrt(s.params.gamma),
            "S": separation_number(s.params), "D": s.coefficients.D}


def pad_rows(rows) -> np.ndarray:
    """Rows of unequal length as a 2-D array padded with NaN (the variable's comment: `PADDED`)."""
    out = np.full((len(rows), max(len(r) for r in rows)), np.nan)
    for i, r in enumerate(rows):
        out[i, :len(r)] = r
    return out


def stack(summaries, shape, dims, prefix=""):
    """Data variables from nested summaries (a flat list in C order over ``shape``)."""
    out = {}
    for key, unit in (("regime", None), ("n", "1"), ("n_fft", "1"), ("c_over_sqrt_a", "1"), ("stationary", None),
                      ("residual", "1"), ("energy_late", "E R^2 / M"), ("energy_spread", "E R^2 / M"),
                      ("kappa", "1"), ("S", "1"), ("D", "1")):
        arr = np.array([sm[key] for sm in summaries]).reshape(shape)
        attrs = {"units": unit} if unit else {}
        if key == "c_over_sqrt_a":
            attrs["comment"] = "NaN where the run settles on no travelling wave (no speed to measure)"
        out[prefix + key] = (dims, arr.astype(str) if key == "regime" else arr, attrs)
    frac = np.array([sm["fraction"] for sm in summaries]).reshape(shape + (len(STATE_NAMES),))
    out[prefix + "fraction"] = (dims + ("kind",), frac, {"units": "1", "long_name": "time-averaged node fraction"})
    return out


def all_true(values) -> bool:
    return bool(np.all(np.asarray(values)))

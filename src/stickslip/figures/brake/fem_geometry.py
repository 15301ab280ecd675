"""Section 3.1 with finite elements: the geometry question.

The paper gives no geometry for its FE runs, and its mode numbers depend on the mesh,
on the scheme's damping ``beta2`` and on the start. For each of the three cases, unseeded
runs (`stickslip.brake.fem.campaign.geometry`) over the ring's thickness ``xi = R*/R``
(1.25 to 3, inner radius 0.1 m, the radial spacing of the 256 x 16 mesh at ``xi = 1.5``)
and ``beta2`` (0.6 to 0.9, the range the paper says converges at the same rate) give the
most frequent outcome; does any ``(xi, beta2)`` give the paper's three regimes and mode
numbers at once?
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake.fem.campaign import budget_of, geometry, geometry_mesh
from ...contact import REGIME_CODES
from .. import Check, FigureSpec
from . import campaign_data
from .paper import CASES, PAPER_REGIMES

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["compute", "check", "plot", "inputs", "most_frequent", "describe"]

_NAMES = {v: k for k, v in REGIME_CODES.items()}
_SHORT = {"stick-slip": "SS", "stick-slip-separation": "SSS", "stick-separation": "SSep", "slip": "S",
          "stick-slip-reverse-slip": "SSR", "stick-slip-separation-reverse-slip": "SSSR", "none": "-", "other": "?"}


def compute(quick: bool = False, cache: Path | None = None, data_dir: Path | None = None) -> xr.Dataset:
    ds, source = campaign_data.find("geometry", data_dir)
    small = ds is None
    if small:
        with campaign_data.small_store(cache) as store:
            ds = geometry(store, CASES, xis=(1.5, 2.5), beta2s=(0.6, 0.9), seeds=2, n_theta=128,
                          budget={"max_transits": 150.0 if quick else 250.0})
        source = f"the small version (xi 1.5, 2.5; beta2 0.6, 0.9; 2 runs each; 128 nodes around): {source}"
    ds = ds.drop_vars("done", errors="ignore")
    ds.attrs.update({"data_source": source, "small": int(small)})
    return ds


def inputs(data_dir: Path | None) -> str:
    return campaign_data.inputs("geometry", data_dir)


def describe(ds: xr.Dataset) -> str:
    """What was computed, from the dataset itself (its grid, mesh and budget)."""
    n_theta, budget = int(ds.attrs.get("n_theta", 256)), budget_of(ds.attrs)
    xis = ", ".join(f"{x:g}" for x in ds["xi"].values)
    meshes = ", ".join(f"{a} × {b}" for a, b in (geometry_mesh(float(x), n_theta) for x in ds["xi"].values))
    return (f"{ds.sizes['seed']} unseeded runs (white noise 1e-3 δ) per cell, of the three cases over ξ = {xis} "
            f"(R = 0.1 m; meshes {meshes}: the radial spacing of 256 × 16 at ξ = 1.5) and β2 = "
            + ", ".join(f"{b:g}" for b in ds["beta2"].values) + f", each to stationarity or {budget['max_transits']:g} "
            "transits as in brake-fem-statistics; the most frequent (regime, number of stick zones) over the runs of "
            "each cell.")


def most_frequent(ds: xr.Dataset) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Most frequent (regime code, n_zones) over the seeds, and its share, per (case, xi, beta2)."""
    shape = (ds.sizes["case"], ds.sizes["xi"], ds.sizes["beta2"])
    code, n, share = np.zeros(shape, int), np.zeros(shape, int), np.zeros(shape)
    for idx in np.ndindex(shape):
        sel = ds.isel(case=idx[0], xi=idx[1], beta2=idx[2])
        pairs = list(zip(sel["regime"].values.astype(int), sel["n_zones"].values.astype(int)))
        best = max(set(pairs), key=lambda p: (pairs.count(p), -p[1]))
        code[idx], n[idx], share[idx] = best[0], best[1], pairs.count(best) / len(pairs)
    return code, n, share


def check(ds: xr.Dataset) -> list[Check]:
    code, n, share = most_frequent(ds)
    paper = np.array([[REGIME_CODES[r], m] for r, m in PAPER_REGIMES])
    hit = np.all((code == paper[:, 0, None, None]) & (n == paper[:, 1, None, None]), axis=0)
    per_case = [int(np.sum((code[c] == paper[c, 0]) & (n[c] == paper[c, 1]))) for c in range(len(PAPER_REGIMES))]
    where = [f"(xi {ds['xi'].values[i]:g}, beta2 {ds['beta2'].values[j]:g})" for i, j in zip(*np.nonzero(hit))]
    cells = ds.sizes["xi"] * ds.sizes["beta2"]
    return [
        Check("every run ended in a classified window", bool(np.all(ds["regime"].values >= 0)
                                                             and np.all(np.isfinite(ds["n_zones"].values))),
              f"{int(ds['regime'].size)} runs", "regime and mode number for every run",
              f"data: {ds.attrs.get('data_source', 'not recorded')}"),
        Check("some ring thickness xi and damping beta2 give the paper's three regimes and mode numbers at once "
              "(most frequent outcome of the unseeded runs)", bool(hit.any()),
              ", ".join(where) if where else "none", "at least one (xi, beta2)",
              "cells where each case alone matches: " + ", ".join(f"case {c + 1}: {k} of {cells}"
                                                                 for c, k in enumerate(per_case)), claim=True),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Per case, the most frequent mode number over (xi, beta2), labelled with the regime."""
    code, n, share = most_frequent(ds)
    fig, axes = plotting.new_figure(fig, ds.sizes["case"], size=(3.8, 3.8))
    xi, b2 = ds["xi"].values, ds["beta2"].values
    for c, ax in enumerate(axes):
        top = max(12, int(n.max()))
        im = ax.imshow(n[c].T, origin="lower", aspect="auto", cmap="viridis", vmin=0, vmax=top)
        for i in range(xi.size):
            for j in range(b2.size):
                regime = _NAMES.get(int(code[c, i, j]), "other")
                ax.text(i, j, f"{n[c, i, j]} {_SHORT.get(regime, '?')}\n{share[c, i, j]:.0%}", ha="center",
                        va="center", fontsize=8, color="k" if n[c, i, j] > 0.6 * top else "w")
        regime, modes = PAPER_REGIMES[c]
        f, d, om = CASES[c]
        ax.set(xticks=range(xi.size), xticklabels=[f"{x:g}" for x in xi], yticks=range(b2.size),
               yticklabels=[f"{b:g}" for b in b2], xlabel="ξ = R*/R [1]", ylabel="β2 [1]",
               title=f"case {c + 1} (f = {f:g}): paper {modes} modes, {_SHORT[regime]}")
        ax.title.set_fontsize(9)
        fig.colorbar(im, ax=ax, label="most frequent mode number [1]")
    fig.suptitle(plotting.wrap("Cells: most frequent number of stick zones and regime (SS stick-slip, SSS "
                               "stick-slip-separation, SSep stick-separation), % = share of the runs; "
                               f"data: {ds.attrs.get('data_source', 'not recorded')[:80]}", 130), fontsize=9)
    return fig


FIGURE = FigureSpec(
    key="brake-fem-geometry", title="Section 3.1 — FE mode numbers over the ring's thickness and the scheme's damping",
    model="brake-like system, finite elements",
    claim="(The paper gives no geometry, and states that β2 between 0.6 and 0.9 converges at the same rate.) Is there "
          "a ring thickness ξ = R*/R and a β2 for which the three cases give the paper's regimes and mode numbers?",
    method="Unseeded runs (white noise 1e-3 δ) of the three cases over ξ = 1.25, 1.5, 2, 3 (R = 0.1 m) and β2 = 0.6, "
           "0.75, 0.9 on 256 × round(32 (ξ − 1)) meshes, each to stationarity or 300 transits as in "
           "brake-fem-statistics; the most frequent (regime, number of stick zones) over the runs of each cell.",
)

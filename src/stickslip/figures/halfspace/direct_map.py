"""Beyond the paper: the direct problem (the wave from its loading) over the loading plane."""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...halfspace import direct_map, inverse_problem, radok
from ...halfspace.direct import cbar_grid
from .. import Check, FigureSpec
from .common import FIGURE14, checks

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = True) -> xr.Dataset:
    """Direct problem over the loading plane ``(v/v*, T/v*)``, both systems (nu = 0.3, mu = 0.5)."""
    p = FIGURE14
    n = 40 if quick else 200
    vr = np.geomspace(1.05, 50.0, n)
    tr = np.geomspace(1e-2, 1e3, n)
    maps = [direct_map(vr, tr, nu=p["nu"], mu=p["mu"], system=s, n_grid=1001 if quick else 4001) for s in ("printed", "text")]
    ds = xr.concat(maps, dim=xr.DataArray(["printed", "text"], dims="system", name="system"))
    rd = radok(cbar_grid(20001), p["nu"], p["mu"])
    ratio = rd.K / rd.K_minus_one
    ds.attrs.update({"v_ratio_band_lo": float(ratio.min()), "v_ratio_band_hi": float(ratio.max()),
                     "quick": int(quick), "nu": p["nu"], "mu": p["mu"]})
    return ds


def check(ds: xr.Dataset) -> list[Check]:
    pr = ds.sel(system="printed")
    has = pr.n_solutions.values > 0
    vr = np.broadcast_to(pr.v_ratio.values[:, None], has.shape)
    lo, hi = ds.attrs["v_ratio_band_lo"], ds.attrs["v_ratio_band_hi"]
    inside = (vr > lo) & (vr < hi)
    out = [("printed: at most one wave per loading", int(ds.n_solutions.sel(system="printed").max()) <= 1,
            int(ds.n_solutions.sel(system="printed").max()), "<= 1", "K(c) is monotone"),
           ("printed: a wave exists iff v/v* lies in the band K/(K-1)", bool(np.array_equal(has, inside)),
            float(np.mean(has == inside)), "1", f"band ({lo:.4g}, {hi:.4g})")]
    c = pr.c.sel(solution=0).values
    b = pr.b.sel(solution=0).values
    ok = np.isfinite(c)
    if ok.any():
        idx = np.argwhere(ok)[:: max(1, ok.sum() // 20)]
        err = 0.0
        for i, j in idx:
            sol = inverse_problem(b[i, j], c[i, j], 1.0, nu=ds.attrs["nu"], mu=ds.attrs["mu"])
            err = max(err, abs(float(sol.v) / pr.v_ratio.values[i] - 1), abs(float(sol.T) / pr.T_ratio.values[j] - 1))
        out.append(("printed: inverse problem reproduces the loading", err < 1e-8, err, "< 1e-8", "round trip at sampled points"))
    return checks(out)


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:

    fig, axes = plotting.new_figure(fig, 2, size=(5.5, 4.2))
    for ax, system in zip(axes, ("printed", "text")):
        d = ds.sel(system=system, solution=0)
        m = ax.pcolormesh(d.T_ratio.values, d.v_ratio.values, d.c.values, shading="auto")
        fig.colorbar(m, ax=ax, label="wave speed c / c2 [1] (blank: no wave)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("T / v* [1]")
        ax.set_ylabel("v / v* [1]")
        ax.set_title(f"direct problem, {system}: max {int(ds.n_solutions.sel(system=system).max())} wave(s)")
    return fig


FIGURE = FigureSpec(
    key="halfspace-direct-map", cost=10, title="Beyond the paper — the direct problem over the loading plane",
    model="rigid body on an elastic half-space",
    claim="(The paper could not solve it: Newton fails.) Given the loading (T, v, v*), find the wave (c̄, b).",
    method="b eliminated by the second equation, every sign change in c̄ bracketed on a grid and refined by Brent; "
           "the map over (v/v*, T/v*) counts solutions; inverse → direct round trips.",
    errata=("H4",),
)

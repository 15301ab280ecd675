"""Beyond the paper: a regime map of the Stribeck oscillator over belt speed and damping."""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...oscillator import continue_cycle
from ...oscillator.regimes import REGIMES, regime_map
from .. import Check, FigureSpec
from .common import osc_attrs, osc_from_attrs
from .bifurcation import STRIBECK

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

DAMPING_CHECK = 0.05


def compute(quick: bool, cache: Path | None = None) -> xr.Dataset:
    speeds = np.linspace(0.05, 1.5, 16 if quick else 40)
    dampings = np.linspace(0.01, 0.3, 10 if quick else 24)
    with tempfile.TemporaryDirectory() as tmp:
        store = Path(cache or tmp) / "oscillator-regimes.zarr"
        ds = regime_map(STRIBECK, {"belt_speed": speeds, "damping": dampings}, store, batch=64)
    c_check = float(dampings[np.argmin(np.abs(dampings - DAMPING_CHECK))])  # a grid value
    branch = continue_cycle(STRIBECK.replace(damping=c_check), 2.0, step=0.05, max_step=0.1)
    graze = [e["belt_speed"] for e in branch.events if e["kind"] == "grazing"]
    ds["grazing_at_check_damping"] = ((), graze[0] if graze else math.nan, {"units": "m/s"})
    ds["check_damping"] = ((), c_check, {"units": "N s/m"})
    ds.attrs.update(osc_attrs(STRIBECK))
    return ds


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    from matplotlib.colors import ListedColormap

    fig, (ax,) = plotting.new_figure(fig, size=(10.0, 5.2))
    colours = ["#9ecae1", "#fdae6b", "#e6550d", "#74c476", "#bbbbbb"]
    v, c = ds.belt_speed.values, ds.damping.values
    ax.pcolormesh(v, c, ds.regime.values.T, cmap=ListedColormap(colours), vmin=-0.5, vmax=4.5, shading="nearest")
    osc = osc_from_attrs(ds.attrs)
    law, N = osc.friction, osc.normal_force
    cs = np.linspace(c.min(), c.max(), 200)
    vh = law.vs * np.log(N * (law.fs - law.fd) / (cs * law.vs))
    inside = (vh >= v.min()) & (vh <= v.max())  # the analytic curve where the map is
    ax.plot(np.where(inside, vh, np.nan), cs, "k--", lw=1.2, label="Hopf: c + N μ'(V) = 0")
    ax.plot(float(ds.grazing_at_check_damping), float(ds.check_damping), "k*", ms=10, label="grazing (continuation)")
    shown = set(np.unique(ds.regime.values[np.isfinite(ds.regime.values)]).astype(int)) | {0, 1, 2, 3}
    for code, colour in enumerate(colours):
        if code in shown:
            ax.plot([], [], "s", color=colour, ms=10, label=REGIMES[code])
    ax.set_xlim(v.min(), v.max()), ax.set_ylim(c.min(), c.max())
    ax.set_xlabel("belt speed V [m/s]"), ax.set_ylabel("damping c [N s/m]")
    ax.set_title("Stribeck oscillator: long-time behaviour")
    plotting.legend_beside(ax)
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    osc = osc_from_attrs(ds.attrs)
    law, N = osc.friction, osc.normal_force
    v, c = ds.belt_speed.values, ds.damping.values
    dv = v[1] - v[0]
    stable = ds.equilibrium_stable.values.astype(bool)
    worst = 0.0
    for j, cj in enumerate(c):  # the stability boundary of steady sliding along each damping
        vh = law.vs * math.log(N * (law.fs - law.fd) / (cj * law.vs))
        if v[0] < vh < v[-1]:
            first_stable = v[np.argmax(stable[:, j])]
            worst = max(worst, abs(first_stable - vh) / dv)
    j = int(np.argmin(np.abs(c - float(ds.check_damping))))
    has_cycle = np.isfinite(ds.amplitude.values[:, j]) & (ds.regime.values[:, j] > 0)
    last = v[np.nonzero(has_cycle)[0].max()]
    vg = float(ds.grazing_at_check_damping)
    regimes = ds.regime.values
    return [
        Check("stability boundary of steady sliding = Hopf curve V_H(c) = v_s ln(N(f_s - f_d)/(c v_s))",
              worst <= 1.0, f"max offset {worst:.2f} grid steps", "<= 1 grid step"),
        Check(f"stick-slip region ends at the grazing point of the continuation (c = {c[j]:.3g})",
              bool(0 <= vg - last <= dv * 1.0001), f"last grid point with a cycle V = {last:.4g}",
              f"within one step below V_g = {vg:.6g}"),
        Check("a bistable band exists (steady sliding and stick-slip both stable)", bool(np.any(regimes == 2)),
              f"{int(np.sum(regimes == 2))} of {regimes.size} points", "> 0"),
        Check("every point classified (no 'none found')", bool(np.all(regimes != 4) and np.all(ds.done.values)),
              f"{int(np.sum(regimes == 4))} unclassified", "0"),
    ]


FIGURE = FigureSpec(
    key="oscillator-regimes", cost=9, title="Beyond the paper — regime map of the Stribeck oscillator",
    model="1-DOF friction oscillator, Stribeck law with viscous damping",
    claim="(Not in the paper.) Where in (V, c) steady sliding, stick-slip, or both are the long-time behaviour.",
    method="A resumable Dask sweep (Zarr store) over a (V, c) grid: linear stability of steady sliding, and shooting "
           "from the end of the stick segment, through which every stick-slip cycle passes; the Hopf curve in "
           "closed form and the grazing point from the continuation as references.",
)

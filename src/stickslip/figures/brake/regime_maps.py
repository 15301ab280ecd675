"""Beyond the paper: regime maps of the brake-like system over friction and mismatch."""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake.maps import REGIME_CODES, ring_regime_map, wave_regime_map
from .. import Check, FigureSpec

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

OMEGA, MODES = 50.0, 4
COLOURS = ["#ffffff", "#fdae6b", "#fd8d3c", "#6baed6", "#3182bd", "#31a354", "#cccccc", "#888888"]


def compute(quick: bool, cache: Path | None = None) -> xr.Dataset:
    frictions = np.linspace(0.1, 2.0, 8 if quick else 16)
    mismatches = np.logspace(-7, -4, 6 if quick else 12)
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(cache or tmp)
        waves = wave_regime_map(frictions, mismatches, root / "waves.zarr", omega=OMEGA, modes=MODES)
        ring = ring_regime_map(frictions, mismatches, root / "ring.zarr", omega=OMEGA,
                               transits=100.0 if quick else 150.0)
    ds = xr.merge([waves.drop_vars("done"), ring.drop_vars("done")], combine_attrs="drop")
    for name in ("wave_regime", "ring_regime"):  # merge drops variable attributes too: the codes' flags back
        ds[name].attrs = dict(waves[name].attrs if name in waves else ring[name].attrs)
    ds["c_over_sqrt_a"].attrs = {**waves["c_over_sqrt_a"].attrs, "comment": "NaN where no travelling wave is found"}
    ds.attrs.update({"omega": OMEGA, "modes": MODES, "nodes": ring.attrs["nodes"],
                     "transits": ring.attrs["transits"]})
    return ds


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    from matplotlib.colors import ListedColormap

    fig, axes = plotting.new_figure(fig, 2, size=(5.6, 4.6))
    cmap = ListedColormap(COLOURS)
    for ax, name, title in ((axes[0], "wave_regime", f"principal travelling wave, n = {ds.attrs['modes']}"),
                            (axes[1], "ring_regime", "limit regime of the ring integration")):
        ax.pcolormesh(ds.mismatch * 1e6, ds.friction, ds[name], cmap=cmap, vmin=-0.5, vmax=7.5, shading="nearest")
        ax.set(xscale="log", xlabel="mismatch d [µm]", ylabel="friction coefficient f [1]", title=title)
        ax.title.set_fontsize(10)
    for name, code in REGIME_CODES.items():
        axes[1].plot([], [], "s", color=COLOURS[code], ms=9, label=name if name != "none" else "no wave found")
    plotting.legend_beside(axes[1], title="regime (both maps)", title_fontsize=8)
    fig.suptitle(f"Steel ring R = 0.1 m, R* = 0.15 m, Ω = {ds.attrs['omega']:g} rad/s", fontsize=10)
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    w, r = ds.wave_regime.values, ds.ring_regime.values
    sep_codes = [REGIME_CODES["stick-slip-separation"], REGIME_CODES["stick-slip-separation-reverse-slip"]]
    separation_w, separation_r = np.isin(w, sep_codes), np.isin(r, sep_codes)
    found = w > 0
    agree = float(np.mean(separation_w[found] == separation_r[found]))
    f, d = ds.friction.values, ds.mismatch.values
    high_pressure = (f <= 0.7)[:, None] & (d >= d[-2])[None, :]
    small_mismatch = (f >= 0.5)[:, None] & (d <= d[1])[None, :]
    return [
        Check("stick-slip where the pressure is high and the friction small (paper §3.1)",
              bool(np.all(w[high_pressure] == REGIME_CODES["stick-slip"]) and
                   np.all(r[high_pressure] == REGIME_CODES["stick-slip"])),
              f"waves {sorted(int(v) for v in set(w[high_pressure]))}, ring {sorted(int(v) for v in set(r[high_pressure]))}",
              "code 1 (stick-slip) in both maps", "f <= 0.7 and the two largest mismatches"),
        Check("separation where the mismatch is small and the friction large enough (paper §3.1)",
              bool(np.all(separation_w[small_mismatch & found]) and np.all(separation_r[small_mismatch])),
              f"{int(separation_r[small_mismatch].sum())}/{int(small_mismatch.sum())} ring points with separation",
              "all", "f >= 0.5 and the two smallest mismatches"),
        Check("the shooting solver and the time integration agree on separation", agree >= 0.75,
              f"{agree:.0%} of the points where a wave exists", ">= 75 %",
              "the ring may settle on another wave than the principal one, or on no stationary wave"),
        Check("no stick-separation wave anywhere in the reduced model (erratum W5)",
              bool(np.all(w != REGIME_CODES["stick-separation"]) and np.all(r != REGIME_CODES["stick-separation"])),
              f"{int(np.sum(w == 5) + np.sum(r == 5))} points", "0",
              "the paper's Figure 8 (FE, f = 2) has no counterpart in [12]"),
    ]


FIGURE = FigureSpec(
    key="brake-regime-maps", cost=133, title="Beyond the paper — regime maps over friction and mismatch",
    model="brake-like system, reduced model: shooting and time integration",
    claim="'The stick-slip regime occurs if the normal contact pressure is high enough or for a small coefficient of "
          "friction ... the stick-slip-separation wave may be obtained when the mismatch is small enough or when the "
          "friction is high enough' (§3.1, from FE runs).",
    method="Two resumable Dask sweeps over (f, d) at Ω = 50 rad/s on the steel ring: the regime of the principal "
           "4-mode travelling wave (multiple shooting), and the limit regime of the ring integration from perturbed "
           "steady sliding (128 nodes, central differences); the paper's qualitative statements tested on both.",
    errata=("W5",),
)

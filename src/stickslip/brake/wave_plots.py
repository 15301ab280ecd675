"""Plots of Figures 5, 6, 11 and 12 (travelling waves); they read datasets only.

The datasets come from `wave_figures` (``figN_data``); zones are coloured by kind.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

__all__ = ["plot_fig5", "plot_fig6", "plot_fig11", "plot_fig12", "COLOURS"]

COLOURS = {"stick": "tab:green", "slip": "tab:blue", "reverse-slip": "tab:red", "separation": "tab:orange"}


def _by_zone(ax, x, y, zone, kinds):
    for i, kind in enumerate(kinds):
        if not kind:
            continue
        sel = zone == i
        ax.plot(np.where(sel, x, np.nan), np.where(sel, y, np.nan), color=COLOURS[kind], lw=1.4)


def _legend(ax):
    from matplotlib.lines import Line2D
    ax.legend([Line2D([], [], color=c) for c in COLOURS.values()], list(COLOURS), fontsize=7, loc="best")


def _phase_plot(ds, path, pairs, title):
    from .. import plotting
    fig, axes = plotting.figure(ncols=len(pairs), size=(5.6, 4.6))
    for ax, (xk, yk, xl, yl) in zip(axes, pairs):
        for i in ds["case"].values:
            c = ds.sel(case=i)
            kinds = [str(k) for k in c["zone_kind"].values]
            x, y = c[xk].values, c[yk].values
            if xk != "phi":  # closed orbit; jumps (impacts) show as dashed chords
                ax.plot(np.append(x, x[0]), np.append(y, y[0]), color="0.6", lw=0.7, ls="--")
            _by_zone(ax, x, y, c["zone"].values, kinds)
            if "omega" in c.coords and len(ds["case"]) > 1:
                k = int(np.argmax(x))
                ax.annotate(f"Ω = {float(c.omega):g}", (x[k], y[k]), fontsize=7)
        ax.set(xlabel=xl, ylabel=yl)
        ax.ticklabel_format(style="sci", scilimits=(-3, 3))
        _legend(ax)
    fig.suptitle(title, fontsize=10)
    plotting.save(fig, path)


def plot_fig5(ds: xr.Dataset, path) -> None:
    _phase_plot(ds, path, [("V", "dV", "V (units of R)", "V' = dV/dφ")],
                f"Fig. 5: stick-slip waves, n = {ds.attrs['modes']}, f = {ds.attrs['friction']}, several Ω")


def plot_fig6(ds: xr.Dataset, path) -> None:
    _phase_plot(ds, path, [("U", "dU", "U (units of R)", "U' = dU/dφ"), ("V", "dV", "V (units of R)", "V'")],
                f"Fig. 6: stick-slip-separation waves, n = {ds.attrs['modes']}, f = {ds.attrs['friction']}")


def plot_fig12(ds: xr.Dataset, path) -> None:
    _phase_plot(ds, path, [("V", "dV", "V (units of R)", "V' = dV/dφ"), ("phi", "slip_velocity", "φ", "1 − V̇")],
                f"Fig. 12: mode-{ds.attrs['modes']} wave with reverse slip (1 − V̇ < 0: overshoot)")


def plot_fig11(ds: xr.Dataset, path) -> None:
    from .. import plotting
    fig, (ax1, ax2) = plotting.figure(ncols=2, size=(6.0, 4.6))
    phi = ds["profile_phi"].values
    for k, i in enumerate(ds["profile_point"].values):
        ax1.plot(phi, ds["profile_U"].values[k] / float(ds["delta"][i]) - 1.0,
                 label=f"d = {float(ds['mismatch'][i]) * 1e6:.3g} µm ({ds['structure'].values[i]})", lw=1)
    ax1.set(xlabel="φ", ylabel="U/δ − 1 (gap over mismatch)", title="radial displacement")
    ax1.legend(fontsize=6)
    d = ds["mismatch"].values * 1e6
    for z in ds["zone"].values:
        kinds = ds["zone_kind"].values[:, z]
        for kind, colour in COLOURS.items():
            sel = kinds == kind
            ax2.plot(np.where(sel, d, np.nan), np.where(sel, ds["zone_start"].values[:, z], np.nan), ".",
                     color=colour, ms=3)
    for e in ds["event_parameter"].values:
        ax2.axvline(e * 0.1 * 1e6, color="grey", lw=0.6, ls=":")
    ax2.set(xscale="log", xlabel="mismatch d [µm]", ylabel="zone start φ", title="switching points (start of zone)")
    _legend(ax2)
    plotting.save(fig, path)

"""Plots of result datasets, for the figures of the paper and for the command line.

Every plot function reads an `xarray.Dataset` (a result's ``to_xarray()`` or a figure's
data), draws on a `matplotlib.figure.Figure` it is given or creates, and returns it.
Nothing here imports `matplotlib.pyplot` or switches the backend, so a Jupyter user keeps
theirs; `save` writes a figure to a file.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

__all__ = ["new_figure", "save", "modal_line", "oscillator_phase", "state_image", "state_legend", "zone_legend",
           "plot_cycle", "plot_trajectory", "plot_branch", "plot_oscillator_map", "plot_interface_fields",
           "MODE_COLOURS", "STATE_COLOURS", "ZONE_COLOURS"]

MODE_COLOURS = {-1: "tab:red", 0: "tab:green", 1: "tab:blue"}
MODE_LABELS = {-1: "reverse slip", 0: "stick", 1: "slip"}
#: Colours of the contact-node states, in the order of `stickslip.contact.STATE_NAMES`.
STATE_COLOURS = ("#1b9e77", "#d95f02", "#7570b3", "#e7e7e7")
#: Colours of the zones of a travelling wave.
ZONE_COLOURS = {"stick": "tab:green", "slip": "tab:blue", "reverse-slip": "tab:red", "separation": "tab:orange"}


def new_figure(fig: Figure | None = None, ncols: int = 1, nrows: int = 1, size=(6.4, 4.8)):
    """``(fig, axes)``: ``ncols x nrows`` axes (a flat list) on ``fig``, or on a new `Figure`
    of ``size`` per panel (inches)."""
    if fig is None:
        fig = Figure(figsize=(size[0] * ncols, size[1] * nrows))
    axes = fig.subplots(nrows, ncols, squeeze=False)
    return fig, list(axes.ravel())


def save(fig: Figure, path, dpi: int = 120) -> None:
    """Lay out and write ``fig`` (the format from the suffix of ``path``)."""
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)


def modal_line(ax, x, y, mode, lw=1.2, alpha=1.0):
    """A curve coloured by contact mode (stick, slip, reverse slip)."""
    x, y, mode = np.asarray(x), np.asarray(y), np.asarray(mode)
    ok = np.isfinite(x) & np.isfinite(y)
    x, y, mode = x[ok], y[ok], mode[ok]
    if x.size == 0:
        return
    cuts = np.nonzero(np.diff(mode))[0] + 1
    for seg in np.split(np.arange(x.size), cuts):
        if seg.size == 0:
            continue
        idx = np.arange(max(seg[0] - 1, 0), seg[-1] + 1)
        ax.plot(x[idx], y[idx], color=MODE_COLOURS.get(int(mode[seg[0]]), "k"), lw=lw, alpha=alpha)


def oscillator_phase(ax, ds, title: str | None = None) -> None:
    """Phase portrait ``(x, v)`` of a simulated or periodic trajectory dataset."""
    modal_line(ax, ds["x"].values, ds["v"].values, ds["mode"].values)
    ax.axhline(ds.attrs.get("belt_speed_m_per_s", np.nan), color="0.6", lw=0.6, ls=":")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("dx/dt [m/s]")
    handles = [Line2D([], [], color=c, label=MODE_LABELS[m]) for m, c in MODE_COLOURS.items()]
    ax.legend(handles=handles, loc="lower right", fontsize=8)
    if title:
        ax.set_title(title)


def state_image(ax, state, title: str = "", extent=(0, 2 * np.pi, 0, 2)):
    """Contact-node states (rows: times, columns: nodes along the contact line) as an image."""
    from matplotlib.colors import ListedColormap

    im = ax.imshow(state, aspect="auto", origin="lower", cmap=ListedColormap(STATE_COLOURS), vmin=-0.5, vmax=3.5,
                   interpolation="nearest", extent=extent)
    if title:
        ax.set_title(title, fontsize=8)
    ax.set_xticks([0, np.pi, 2 * np.pi], ["0", "π", "2π"])
    return im


def state_legend(ax, **kwargs) -> None:
    """A legend of the four contact-node states."""
    from matplotlib.patches import Patch

    names = ("stick", "slip", "reverse slip", "separation")
    ax.legend(handles=[Patch(color=c, label=n) for c, n in zip(STATE_COLOURS, names)], **{"fontsize": 7, **kwargs})


def zone_legend(ax, **kwargs) -> None:
    """A legend of the zone kinds of a travelling wave."""
    ax.legend([Line2D([], [], color=c) for c in ZONE_COLOURS.values()], list(ZONE_COLOURS),
              **{"fontsize": 7, "loc": "best", **kwargs})


def plot_cycle(ds, fig: Figure | None = None) -> Figure:
    """A limit cycle (`LimitCycle.to_xarray`): phase portrait and ``x(t)``."""
    fig, (ax1, ax2) = new_figure(fig, 2, size=(5.5, 4.2))
    oscillator_phase(ax1, ds, "limit cycle")
    ax2.plot(ds["t"], ds["x"], lw=1)
    ax2.set(xlabel="t [s]", ylabel="x [m]")
    return fig


def plot_trajectory(ds, fig: Figure | None = None) -> Figure:
    """A simulated trajectory (`Trajectory.to_xarray`): phase portrait and ``x(t)`` by contact mode."""
    fig, (ax1, ax2) = new_figure(fig, 2, size=(5.5, 4.2))
    oscillator_phase(ax1, ds, "phase portrait")
    modal_line(ax2, ds["t"].values, ds["x"].values, ds["mode"].values)
    ax2.set(xlabel="t [s]", ylabel="x [m]")
    return fig


def plot_branch(ds, fig: Figure | None = None) -> Figure:
    """A branch of limit cycles (`Branch.to_xarray`): amplitude and period, stable or not."""
    fig, axes = new_figure(fig, 2, size=(5.5, 4.2))
    p = ds["parameter_value"].values
    stable = ds["stable"].values.astype(bool)
    for ax, name in zip(axes, ("amplitude", "period")):
        ax.plot(p, ds[name], color="0.7", lw=0.8)
        ax.plot(p[stable], ds[name].values[stable], "o", ms=3, label="stable")
        ax.plot(p[~stable], ds[name].values[~stable], "x", ms=3, label="unstable")
        ax.set(xlabel=str(ds.attrs.get("continuation_parameter", "parameter")), ylabel=f"{name} [{ds[name].attrs['units']}]")
        ax.legend()
    return fig


def plot_oscillator_map(ds, regimes: dict, fig: Figure | None = None) -> Figure:
    """A regime map of the oscillator over its two sweep axes (``regime`` codes named by ``regimes``)."""
    fig, (ax,) = new_figure(fig)
    names = [d for d in ds["regime"].dims]
    mesh = ax.pcolormesh(ds[names[0]], ds[names[1]], ds["regime"].values.T, shading="nearest", vmin=0, vmax=4)
    fig.colorbar(mesh, ax=ax, label="; ".join(f"{k} {v}" for k, v in regimes.items()))
    ax.set(xlabel=names[0], ylabel=names[1])
    return fig


def plot_interface_fields(ds, fig: Figure | None = None) -> Figure:
    """The interface fields of a half-space wave (``StickSlipWave.fields(...).to_xarray()``)."""
    fig = Figure(figsize=(8, 8)) if fig is None else fig
    axes = fig.subplots(3, 1, sharex=True)
    x = ds.x.values
    order = np.argsort(x)
    stick = ds.zone.values[order] == 0
    for ax, names, label in ((axes[0], ("Sigma_yy", "Sigma_xy"), "stress / G"), (axes[1], ("u_xx",), "u_x,x"),
                             (axes[2], ("slip_velocity", "material_velocity"), "velocity / c2")):
        for name in names:
            ax.plot(x[order], ds[name].values[order], lw=1, label=name)
        finite = np.concatenate([ds[n].values[np.isfinite(ds[n].values)] for n in names])
        lo, hi = np.percentile(finite, [1, 99])
        pad = 0.3 * (hi - lo + 1e-30)
        ax.set_ylim(lo - pad, hi + pad)
        ax.set_ylabel(label)
        ax.legend(fontsize=8, loc="lower right")
        ax.fill_between(x[order], 0, 1, where=stick, transform=ax.get_xaxis_transform(), color="0.9", lw=0)
    axes[-1].set_xlabel("x / a  (grey: stick)")
    a = ds.attrs
    axes[0].set_title(f"c = {a.get('c', float('nan')):.3g}, b = {a.get('b', float('nan')):.4g}, "
                      f"v = {a.get('v', float('nan')):.3g}, T = {a.get('T', float('nan')):.3g}")
    return fig

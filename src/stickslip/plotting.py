"""Matplotlib helpers (headless). Plotting reads datasets; it never runs a solver."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

MODE_COLOURS = {-1: "tab:red", 0: "tab:green", 1: "tab:blue"}
MODE_LABELS = {-1: "reverse slip", 0: "stick", 1: "slip"}


def figure(ncols: int = 1, nrows: int = 1, size=(6.4, 4.8)):
    fig, axes = plt.subplots(nrows, ncols, figsize=(size[0] * ncols, size[1] * nrows), squeeze=False)
    return fig, axes.ravel()


def save(fig, path) -> None:
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def modal_line(ax, x, y, mode, lw=1.2, alpha=1.0, label_modes=True):
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
        lo = max(seg[0] - 1, 0)
        idx = np.arange(lo, seg[-1] + 1)
        m = int(mode[seg[0]])
        ax.plot(x[idx], y[idx], color=MODE_COLOURS.get(m, "k"), lw=lw, alpha=alpha)


def oscillator_phase(ax, ds, title: str | None = None) -> None:
    """Phase portrait ``(x, v)`` of a simulated or periodic trajectory dataset."""
    modal_line(ax, ds["x"].values, ds["v"].values, ds["mode"].values)
    ax.axhline(ds.attrs.get("belt_speed_m_per_s", np.nan), color="0.6", lw=0.6, ls=":")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("dx/dt [m/s]")
    handles = [plt.Line2D([], [], color=c, label=MODE_LABELS[m]) for m, c in MODE_COLOURS.items()]
    ax.legend(handles=handles, loc="lower right", fontsize=8)
    if title:
        ax.set_title(title)

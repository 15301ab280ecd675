"""Figure 10 (section 3.1, FE): the contact pressure of the runs of Figure 9 (zero in separation)."""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from .. import Check, FigureSpec
from .fem_cases import METHOD, runs_text, spacetime_panels

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def check(ds) -> list[Check]:
    """Case 2 (f = 0.7), contact pressure: it vanishes where the ring separates; its mean stays p_e."""
    return [
        Check("the pressure recomputed from the motion is >= 0 and vanishes where the ring separates",
              bool(ds["negative_pressure"].max() <= 1e-8 and ds["complementarity"].max() <= 1e-8),
              f"max(-p) {float(ds['negative_pressure'].max()):.1e}, max |p gap| {float(ds['complementarity'].max()):.1e}",
              "<= 1e-8 (relative)", "p from M a + K u = Cᵀλ over the traced steps, not from the kernel's states"),
        Check("the mean contact pressure stays at the steady p_e (the mean load is set by the mismatch)",
              bool(np.all(np.abs(ds["p_mean_over_pe"].values - 1.0) < 0.05)), runs_text(ds, "p_mean_over_pe", "{:.3f}"),
              "1 +- 0.05", "largest p / p_e over the last transits (no paper value): "
              + runs_text(ds, "p_max_over_pe", "{:.2f}")),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Figure 10: contact pressure ``p / p_e`` vs ``theta`` (space-time and successive profiles)."""
    fig, bottom = spacetime_panels(ds, fig, "P", "contact pressure p / p_e [1]", "viridis")
    for i, ax in enumerate(bottom):
        r = ds.isel(run=i)
        for k in (0, r.sizes["snapshot"] // 4, r.sizes["snapshot"] - 1):
            ax.plot(r["theta"], r["P"].isel(snapshot=k), lw=0.8, label=f"t = {float(r['snap_t'][k]):.2f}")
        ax.axhline(1.0, color="k", lw=0.4)
        ax.set(xlabel="θ [rad]", ylabel="contact pressure p / p_e [1]", xticks=[0, np.pi, 2 * np.pi],
               xticklabels=["0", "π", "2π"])
        plotting.legend_above(ax, title="profiles at t [transits]", title_fontsize=8)
    a = ds.attrs
    fig.suptitle(plotting.wrap(f"Figure 10: contact pressure, f = {a['friction']:g}, δ = {a['delta']:g}, "
                               f"Ω = {a['omega']:g} rad/s (p_e = {a['p_e']:.3g} E); {a['mesh']}", 110), fontsize=9)
    return fig


FIGURE = FigureSpec(
    key="fig10", title="Figure 10 — FE: contact pressure of the stick-slip-separation wave",
    model="brake-like system, finite elements",
    claim="The normal contact pressure of the stick-slip-separation wave (zero in the separation zones).",
    method=METHOD + " Same runs as Figure 9.",
    data_from="fig9",
)

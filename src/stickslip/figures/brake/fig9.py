"""Figure 9 (section 3.1, FE): case 2, ``f = 0.7``: a stick-slip-separation wave with 8 modes (radial displacement)."""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from .. import Check, FigureSpec
from .fem_cases import METHOD, case_data, common_checks, runs_text, seeded_check, spacetime_panels, waterfall

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = False) -> xr.Dataset:
    """Case 2 (``f = 0.7``), for Figures 9 and 10: from noise and from a seeded mode 8."""
    return case_data(1, (None, 8), quick)


def check(ds) -> list[Check]:
    """Case 2 (f = 0.7), radial displacement. The paper's claim (stick-slip-separation, 8 modes) from
    unseeded starts: brake-fem-statistics."""
    seeded = ds.sel(run="mode 8")
    return common_checks(ds) + [
        seeded_check(ds, 8, "stick-slip-separation", "Figure 9", f"dominant pressure mode {float(seeded['n_fft_P']):g}; "
                     f"time per run: {runs_text(ds, 'seconds', '{:.0f} s')}"),
        Check("the radial displacement pattern propagates (Figure 9)",
              bool(np.all(np.abs(ds["c_P_over_cp"].values) > 0.05)), runs_text(ds, "c_P_over_cp", "{:.3f}"),
              "|c| > 0.05 c_p/R in every run", "speed of the pressure pattern; separation pulses ride on it"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Figure 9: radial displacement ``u_r(R)/d - 1`` vs ``theta`` and ``t`` (propagation)."""
    fig, bottom = spacetime_panels(ds, fig, "U", "u_r(R)/d − 1 [1] (> 0: separated)", "magma")
    for i, ax in enumerate(bottom):
        waterfall(ax, ds, i, "U", 4, max(float(ds["U"].isel(run=i).max()), 1e-12), "u_r(R)/d − 1")
    a = ds.attrs
    fig.suptitle(plotting.wrap(f"Figure 9: f = {a['friction']:g}, δ = {a['delta']:g}, Ω = {a['omega']:g} rad/s; "
                               f"{a['mesh']}; paper: {a['paper_regime']}, {a['paper_modes']} modes", 110), fontsize=9)
    return fig


FIGURE = FigureSpec(
    key="fig9", cost=171, title="Figure 9 — FE: stick-slip-separation wave with 8 modes, radial displacement",
    model="brake-like system, finite elements",
    claim="For Ω = 50 rad/s, δ = 0.001 and f = 0.7 a stick-slip-separation wave with 8 modes; the radial "
          "displacement shows the propagation.",
    method=METHOD, errata=("B5",),
)

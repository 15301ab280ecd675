"""Figure 7 (section 3.1, FE): case 1, ``f = 0.2``: a stick-slip wave with 4 modes?"""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from .. import Check, FigureSpec
from .fem_cases import METHOD, case_data, case_plot, common_checks, seeded_check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = False) -> xr.Dataset:
    """Case 1 (``f = 0.2``): from noise and from a seeded mode 4."""
    return case_data(0, (None, 4), quick)


def check(ds) -> list[Check]:
    """Case 1 (f = 0.2). The paper's claim (stick-slip, 4 modes) from unseeded starts: brake-fem-statistics."""
    seeded = ds.sel(run="mode 4")
    c_lin = float(ds["flutter_speed"].sel(mode=4))
    return common_checks(ds) + [
        seeded_check(ds, 4, "stick-slip", "Figure 7"),
        Check("the 4-mode wave runs in the direction of the linear flutter wave of mode 4 (lowest branch)",
              bool(np.sign(float(seeded["c_over_cp"])) == np.sign(c_lin) != 0),
              f"c = {float(seeded['c_over_cp']):.3f} c_p/R", f"sign of -Im s(4)/4 = {c_lin:.3f} c_p/R",
              "linear stability of FE steady sliding (fem_growth_rates), an independent computation"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Figure 7: stick-slip waves of case 1 (node states, hoop velocity and pressure)."""
    return case_plot(ds, fig, "Vd", "hoop velocity / RΩ")


FIGURE = FigureSpec(
    key="fig7", cost=190, title="Figure 7 — FE: stick-slip wave with 4 modes (f = 0.2, δ = 0.004, Ω = 1 rad/s)",
    model="brake-like system, finite elements",
    claim="For f = 0.2, δ = 0.004 and Ω = 1 rad/s the limit cycle is a stick-slip wave with 4 modes.",
    method=METHOD, errata=("B5",),
)

"""Figure 7 (section 3.1, FE): case 1, ``f = 0.2``: a stick-slip wave with 4 modes?"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from .. import Check, FigureSpec
from .fem_cases import METHOD, case_data, case_plot, common_checks, runs_text


def compute(quick: bool = False) -> xr.Dataset:
    """Case 1 (``f = 0.2``): from noise and from a seeded mode 4."""
    return case_data(0, (None, 4), quick)


def check(ds) -> list[Check]:
    """Case 1 (f = 0.2): stick-slip wave with 4 modes."""
    reg, nz = ds["regime"].values, ds["n_zones"].values
    seeded = ds.sel(run="mode 4")
    return common_checks(ds) + [
        Check("stick-slip (no separation) from every initial condition, as the paper's FE",
              bool(np.all(reg == "stick-slip")), runs_text(ds, "regime"), "stick-slip", claim=True),
        Check("the 4-mode stick-slip wave of Figure 7 is a limit regime (stationary travelling wave)",
              bool(int(seeded["n_zones"]) == 4 and bool(seeded["stationary"])),
              f"seeded mode 4: {int(seeded['n_zones'])} stick zones, stationary {bool(seeded['stationary'])}, "
              f"c = {float(seeded['c_over_cp']):.3f} c_p/R", "4 stick zones, stationary",
              f"time per run: {runs_text(ds, 'seconds', '{:.0f} s')}", claim=True),
        Check("the limit regime depends on the initial condition (paper, section 3.1)", bool(len(set(nz)) > 1),
              f"stick zones {runs_text(ds, 'n_zones')}", "different mode numbers",
              "noise selects the fastest-growing discrete mode of the mesh", claim=True),
        Check("the 4-mode wave runs against the shaft, as the linear flutter wave of the lowest branch",
              bool(float(seeded["c_over_cp"]) < 0), f"c / (c_p/R): {runs_text(ds, 'c_over_cp', '{:.3f}')}",
              "c < 0 for the 4-mode wave", "other waves may run either way (higher radial branches)"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Figure 7: stick-slip waves of case 1 (node states, hoop velocity and pressure)."""
    return case_plot(ds, fig, "Vd", "hoop velocity / RΩ")


FIGURE = FigureSpec(
    key="fig7", title="Figure 7 — FE: stick-slip wave with 4 modes (f = 0.2, δ = 0.004, Ω = 1 rad/s)",
    model="brake-like system, finite elements",
    claim="For f = 0.2, δ = 0.004 and Ω = 1 rad/s the limit cycle is a stick-slip wave with 4 modes.",
    method=METHOD, errata=("B5",),
)

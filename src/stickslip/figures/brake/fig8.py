"""Figure 8 (section 3.1, FE): case 3, ``f = 2``: a stick-separation wave with 2 modes?"""

from __future__ import annotations

import lazy_loader as lazy
from matplotlib.figure import Figure

from .. import Check, FigureSpec
from .fem_cases import METHOD, case_data, case_plot, common_checks, seeded_check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = False) -> xr.Dataset:
    """Case 3 (``f = 2``): from noise and from a seeded mode 2."""
    return case_data(2, (None, 2), quick)


def check(ds) -> list[Check]:
    """Case 3 (f = 2); f > 1 makes steady sliding ill-posed. The paper's claim (stick-separation, 2 modes)
    from unseeded starts: brake-fem-statistics."""
    N = ds.sizes["theta"]
    hs = ds.attrs["halfspace_rate_per_transit_per_mode"]
    ns = [N // 16, N // 8]
    per_n = [float(ds["growth"].sel(mode=n)) / n for n in ns]
    return common_checks(ds) + [
        seeded_check(ds, 2, "stick-separation", "Figure 8"),
        Check("f = 2 > 1: steady sliding is ill-posed (growth proportional to the wavenumber)",
              bool(hs > 0 and all(0.85 < g / hs < 1.2 for g in per_n)),
              f"FE growth / n at n = {ns[0]}, {ns[1]}: {per_n[0]:.3f}, {per_n[1]:.3f} per transit; half-space slip "
              f"wave {hs:.3f} per transit per mode", "ratios in (0.85, 1.2)",
              f"fastest discrete mode n = {int(ds['growth_discrete'].idxmax())} of {N // 2}: the mesh and the "
              "numerical damping select the wavelength, so the mode number is not mesh-converged"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Figure 8: stick-separation of case 3 (node states, radial displacement and pressure)."""
    return case_plot(ds, fig, "U", "u_r / d - 1")


FIGURE = FigureSpec(
    key="fig8", cost=162, title="Figure 8 — FE: stick-separation wave with 2 modes (f = 2, δ = 0.004, Ω = 80 rad/s)",
    model="brake-like system, finite elements",
    claim="For a very high friction (f > 1.5), a high angular velocity and a small mismatch, a stick-separation wave; "
          "with 2 modes for f = 2, δ = 0.004, Ω = 80 rad/s.",
    method=METHOD + " For f > 1 steady sliding is ill-posed (half-space slip waves grow at every wavelength), "
                    "so the wavelength is set by the mesh and β2: this is measured and reported.",
    errata=("B5", "W5"),
)

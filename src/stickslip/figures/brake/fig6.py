"""Figure 6: stick-slip-separation travelling waves for several shaft speeds, ``(U, U')`` and ``(V, V')``."""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from .. import Check, FigureSpec
from .paper import FIG6
from .wave_cases import METHOD, common_checks, phase_plot, waves_dataset

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = False) -> xr.Dataset:
    """Stick-slip-separation waves (``n = 4``) for several shaft speeds: ``(U, U')`` and ``(V, V')``."""
    return waves_dataset(FIG6, "stick-slip-separation", quick)


def check(ds: xr.Dataset) -> list[Check]:
    return common_checks(ds, "Fig. 6") + [
        Check("Fig. 6: U' jumps back to 0 at the end of separation (impact), energy lost > 0",
              bool(np.all(ds["n_impacts"] >= 1) and np.all(ds["impact_dissipation"] > 0)),
              f"impacts per period {ds['n_impacts'].values.tolist()}, impact dissipation / shaft work "
              f"{np.round(ds['impact_dissipation'].values / ds['shaft_work'].values, 4).tolist()}", "> 0"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    return phase_plot(ds, fig, [("U", "dU", "U [R]", "U' = dU/dφ [R/rad]"),
                                ("V", "dV", "V [R]", "V' = dV/dφ [R/rad]")],
                      f"Fig. 6: stick-slip-separation waves, n = {ds.attrs['modes']}, f = {ds.attrs['friction']}")


FIGURE = FigureSpec(
    key="fig6", title="Figure 6 — stick-slip-separation waves in the (U, U') plane",
    model="brake-like system, reduced model, travelling waves",
    claim="Stick-slip-separation waves exist; phase diagrams in the plane of the normal displacement and velocity "
          "(the caption repeats Figure 5's, see W3).",
    method=METHOD + " Here f = 0.7, d = 1 µm, n = 4, several Ω; the landing impact (W2) is part of the wave.",
    errata=("W2", "W3"),
)

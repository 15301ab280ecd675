"""Figure 5: stick-slip travelling waves for several shaft speeds, phase plane ``(V, V')``."""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from .. import Check, FigureSpec
from .paper import FIG5
from .wave_cases import METHOD, common_checks, phase_plot, waves_dataset

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = False) -> xr.Dataset:
    """Stick-slip waves (``n = 4``) for several shaft speeds: phase diagrams ``(V, V')``."""
    return waves_dataset(FIG5, "stick-slip", quick)


def check(ds: xr.Dataset) -> list[Check]:
    cw = ds["c"].values * ds["omega"].values
    amp = np.abs(ds["dV"]).max("sample").values / ds["omega"].values
    return common_checks(ds, "Fig. 5") + [
        Check("Fig. 5: self-similar in Omega: c Omega and max|V'|/Omega do not depend on Omega",
              bool(np.ptp(cw) < 1e-8 * abs(cw[0]) and np.ptp(amp) < 1e-8 * amp[0]),
              f"c Omega = {cw[0]:.8g} rad/s (spread {np.ptp(cw):.1e}), max|V'|/Omega spread {np.ptp(amp) / amp[0]:.1e}",
              "spread < 1e-8", "stick-slip waves depend on delta/sqrt(gamma) only through V_e"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    return phase_plot(ds, fig, [("V", "dV", "V [R]", "V' = dV/dφ [R/rad]")],
                      f"Fig. 5: stick-slip waves, n = {ds.attrs['modes']}, f = {ds.attrs['friction']}, several Ω")


FIGURE = FigureSpec(
    key="fig5", title="Figure 5 — phase diagrams (V, V') of stick-slip waves for several Ω",
    model="brake-like system, reduced model, travelling waves",
    claim="Stick-slip travelling waves exist; their phase diagrams (V, V') for different angular velocities Ω "
          "(the text says 'different normal contact pressure', see W4).",
    method=METHOD + " Here f = 0.2, d = 0.1 mm, n = 4, several Ω.",
    errata=("W1", "W4"),
)

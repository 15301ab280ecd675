"""Figure 12: a travelling wave of mode 8 with reverse slip (overshoot)."""

from __future__ import annotations

import xarray as xr
from matplotlib.figure import Figure

from .. import Check, FigureSpec
from .paper import FIG12
from .wave_cases import METHOD, common_checks, phase_plot, waves_dataset


def compute(quick: bool = False) -> xr.Dataset:
    """A mode-8 wave with reverse slip (overshoot): phase plane ``(V, V')``."""
    return waves_dataset(FIG12, "stick-slip-separation-reverse-slip", quick, samples=(1000, 4000))


def check(ds: xr.Dataset) -> list[Check]:
    w = ds["slip_velocity"].values
    return common_checks(ds, "Fig. 12") + [
        Check("Fig. 12: mode-8 wave with reverse slip (overshoot: V_t > 1 somewhere)",
              bool(int(ds.attrs["modes"]) == 8 and "reverse-slip" in str(ds["structure"].values[0]) and w.min() < 0),
              f"{ds['structure'].values[0]}, min(1 - V_t) = {w.min():.4g}", "n = 8, reverse-slip zone, min < 0"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    return phase_plot(ds, fig, [("V", "dV", "V (units of R)", "V' = dV/dφ"), ("phi", "slip_velocity", "φ", "1 − V̇")],
                      f"Fig. 12: mode-{ds.attrs['modes']} wave with reverse slip (1 − V̇ < 0: overshoot)")


FIGURE = FigureSpec(
    key="fig12", title="Figure 12 — mode-8 travelling wave with reverse slip (overshooting)",
    model="brake-like system, reduced model, travelling waves",
    claim="A traveling wave in mode 8 with reverse slip (overshooting), computed by multiple shooting.",
    method=METHOD + " Here f = 0.2, d = 10 µm, Ω = 100 rad/s, n = 8.",
)

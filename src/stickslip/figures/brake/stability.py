"""Figure data, plot and checks for the flutter of steady sliding (growth rate vs ``n``).

Not a figure of the paper: the paper only states that steady sliding is unstable
(section 3, citing Moirot 1998). The figure shows the growth rate of each mode for the
three regimes of section 3.1, on the default steel ring (``R = 0.1 m``, ``R* = 0.15 m``),
and the sign of the coupling ``D`` (which drives the flutter) against ``xi``.
"""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake import BrakeParams, coupling, growth_rate_limit, growth_rates, neutral_radius_ratio, shape_integrals
from ...brake.reduced import elastic_moduli, grid_growth_rates
from .. import Check, FigureSpec
from .paper import CASES, GEOMETRY

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

POISSON = (0.2, 0.3, 0.4, 0.45)


def compute(quick: bool = False) -> xr.Dataset:
    """Growth rates for the three regimes of section 3.1 and the coupling ``D`` vs ``xi``."""
    modes = np.arange(1, 13 if quick else 41)
    params = [BrakeParams.from_physical(om, d, f) for f, d, om in CASES]
    res = [growth_rates(p, modes) for p in params]
    n_grid = modes[modes <= (6 if quick else 12)]
    grid = [grid_growth_rates(p, n_grid, nodes=2 * int(n_grid[-1]) + 3) for p in params]
    xi = 1.0 + np.logspace(-2, 1, 60 if quick else 200)
    _, _, C1, C2 = shape_integrals(xi)
    scale = np.array([sum(m * C for m, C in zip(elastic_moduli(nu), (C1, C2))) for nu in POISSON])
    case = np.arange(len(CASES))
    omega = np.array([p.omega for p in params])
    ds = xr.Dataset(
        {"growth_rate": (("case", "n"), np.array([r.growth_rate for r in res]),
                         {"units": "1", "long_name": "Re s (time Omega t)"}),
         "frequency": (("case", "n"), np.array([r.frequency for r in res]), {"units": "1"}),
         "growth_rate_si": (("case", "n"), omega[:, None] * np.array([r.growth_rate for r in res]),
                            {"units": "1/s", "long_name": "Omega Re s"}),
         "growth_rate_grid": (("case", "n_grid"), np.array(grid),
                              {"units": "1", "long_name": "Re s from the penalised theta-grid operator"}),
         "growth_rate_limit": ("case", [growth_rate_limit(p) for p in params], {"units": "1"}),
         "D": ("case", [r.coefficients.D for r in res], {"units": "1"}),
         "coupling": (("nu", "xi"), np.array([coupling(xi, nu) for nu in POISSON]),
                      {"units": "1", "long_name": "gamma B D = a~ C1 - b~ C2"}),
         "coupling_normalised": (("nu", "xi"), np.array([coupling(xi, nu) for nu in POISSON]) / scale,
                                 {"units": "1", "long_name": "(a~ C1 - b~ C2) / (a~ C1 + b~ C2)"}),
         "xi_neutral": ("nu", [neutral_radius_ratio(nu) or np.nan for nu in POISSON],
                        {"long_name": "xi where D = 0", "comment": "NaN for a Poisson ratio without such a xi"})},
        coords={"case": case, "n": modes, "n_grid": n_grid, "xi": xi, "nu": list(POISSON),
                "friction": ("case", [p.friction for p in params]), "delta": ("case", [p.delta for p in params]),
                "omega": ("case", omega, {"units": "rad/s"}), "gamma": ("case", [p.gamma for p in params])})
    ds.attrs.update({"xi_case": params[0].xi, "nu_case": params[0].nu, "quick": int(quick),
                     "geometry": GEOMETRY})
    return ds


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Growth rate [1/s] vs ``n`` per regime, and ``gamma B D`` vs ``xi`` per ``nu``."""
    fig, (ax1, ax2) = plotting.new_figure(fig, 2, size=(5.5, 4.2))
    for i in ds["case"].values:
        c = ds.sel(case=i)
        label = f"f = {float(c.friction):g}, δ = {float(c.delta):g}, Ω = {float(c.omega):g} rad/s"
        line, = ax1.plot(ds["n"], c["growth_rate_si"], "o-", ms=3, label=label)
        ax1.axhline(float(c.omega * c.growth_rate_limit), color=line.get_color(), ls="--", lw=0.8)
        ax1.plot(ds["n_grid"], c.omega * c["growth_rate_grid"], "x", color="k", ms=5)
    ax1.set(xlabel="mode number n [1]", ylabel="growth rate Ω Re s [1/s]", yscale="log",
            title="flutter of steady sliding (x: θ-grid operator, --: n → ∞)")
    ax1.legend(fontsize=8)
    for nu in ds["nu"].values:
        line, = ax2.plot(ds["xi"], ds["coupling_normalised"].sel(nu=nu), label=f"ν = {nu:g}")
        x_star = float(ds["xi_neutral"].sel(nu=nu))
        if np.isfinite(x_star):
            ax2.axvline(x_star, color=line.get_color(), ls=":", lw=0.8)
    ax2.axhline(0.0, color="k", lw=0.6)
    ax2.axvline(ds.attrs["xi_case"], color="grey", ls="--", lw=0.8)
    ax2.set(xscale="log", xlabel="ξ = R*/R [1]", ylabel="(ã C1 − b̃ C2) / (ã C1 + b̃ C2) [1]",
            title="sign of the coupling D (no flutter where D = 0)")
    ax2.legend(fontsize=8)
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    """The paper's claim (steady sliding unstable) and the consistency of the analysis."""
    rate, lim = ds["growth_rate"], ds["growth_rate_limit"]
    grid = ds["growth_rate"].sel(n=ds["n_grid"].values).values
    err = float(np.max(np.abs(ds["growth_rate_grid"].values - grid) / grid))
    monotone = bool(np.all(np.diff(rate.values, axis=1) > 0) and np.all(rate < lim))
    nu_with_root = [float(nu) for nu, x in zip(ds["nu"].values, ds["xi_neutral"].values) if np.isfinite(x)]
    signs = np.sign(ds["coupling"].values)
    changes = [int(np.sum(np.diff(s) != 0)) for s in signs]
    return [
        Check("steady sliding is unstable (flutter) for every mode n >= 1", bool(rate.min() > 0),
              f"min Re s = {float(rate.min()):.4g}", "> 0",
              "all points slipping, contact kept; s^2 + a n^2 + h + i n f D = 0"),
        Check("growth rate increases with n, below f|D|/(2 sqrt a)", monotone,
              f"Re s(n_max)/limit = {float((rate.isel(n=-1) / lim).min()):.4f}", "< 1, increasing",
              "the reduced model selects no wavelength at the linear level"),
        Check("closed form agrees with the penalised theta-grid operator", err < 1e-4,
              f"max relative difference {err:.2e}", "< 1e-4", "independent route: eigenvalues on a theta-grid"),
        Check("D changes sign only for nu > 1/4 (once)", all(
              (c == 1) == (nu > 0.25) and c <= 1 for c, nu in zip(changes, ds["nu"].values)),
              f"sign changes {changes} for nu = {[float(v) for v in ds['nu'].values]}", "1 if nu > 1/4 else 0",
              f"xi* exists for nu = {nu_with_root}"),
    ]


FIGURE = FigureSpec(
    key="brake-stability", title="Section 3 — flutter instability of steady sliding (reduced model)",
    model="brake-like system, reduced model [12]-[13]",
    claim="The steady sliding solution [11] of the annulus on the rotating shaft is unstable (Moirot 1998, "
          "Moirot et al. 2002), which gives rise to stick, slip and separation zones.",
    method="Linearisation of the corrected reduced model about [16] with all points slipping: per Fourier mode n, "
           "s² + a n² + h + i n f D = 0 (dimensionless time Ωt). Growth rates for the three regimes of §3.1 on a steel "
           "ring R = 0.1 m, R* = 0.15 m; cross-checked against the eigenvalues of the penalised operator on a θ-grid; "
           "the sign of the coupling D against ξ for several ν.",
    errata=("B1", "B3"),
)

"""Section 3.1 with finite elements: limit regimes over the ring's thickness and the shaft speed."""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake import BrakeParams
from ...brake.fem import classify_fem, integrate_fem
from ...contact import STATE_NAMES
from .. import Check, FigureSpec

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = False) -> xr.Dataset:
    """Regimes over ``xi`` and ``Omega`` (``f = 0.7``, ``d = 0.1 mm``, ``R = 0.1 m``), from noise.

    Only ``xi`` and ``kappa = d sqrt(E/rho) / (R^2 Omega)`` matter (with ``nu``, ``f``), so
    ``Omega`` stands for ``kappa``. Mesh ``256 x 32 (xi - 1)`` (the same radial spacing).
    """
    xis, omegas, T = ((1.5, 2.0), (50.0, 800.0), 150) if quick else ((1.25, 1.5, 2.0), (12.5, 50.0, 200.0, 800.0), 300)
    rows = []
    for xi in xis:
        nr = max(1, int(round(32 * (xi - 1.0))))
        for om in omegas:
            p = BrakeParams.from_physical(om, 1e-4, 0.7, outer_radius=0.1 * xi)
            run = integrate_fem(p, 256, nr, transits=T)
            res = classify_fem(run)
            rows.append((res.regime, res.n_zones, res.n_fft_P, res.c_over_cp, res.stationary,
                         [res.fractions[k] for k in STATE_NAMES], p.delta / np.sqrt(p.gamma)))
    shape = (len(xis), len(omegas))
    col = lambda i: np.array([r[i] for r in rows]).reshape(shape)  # noqa: E731
    data = {"regime": (("xi", "omega"), col(0).astype(str)), "n_zones": (("xi", "omega"), col(1)),
            "n_fft_P": (("xi", "omega"), col(2)), "c_over_cp": (("xi", "omega"), col(3)),
            "stationary": (("xi", "omega"), col(4)), "kappa": (("xi", "omega"), col(6)),
            "fraction": (("xi", "omega", "kind"), np.array([r[5] for r in rows]).reshape(shape + (4,)))}
    return xr.Dataset(data, coords={"xi": list(xis), "omega": ("omega", list(omegas), {"units": "rad/s"}),
                                    "kind": list(STATE_NAMES)},
                      attrs={"friction": 0.7, "mismatch_m": 1e-4, "transits": T, "n_theta": 256, "beta2": 0.9,
                             "quick": int(bool(quick)), "initial": "FE steady sliding + 1e-3 delta white noise"})


def check(ds) -> list[Check]:
    """Regimes over xi and Omega (f = 0.7, d = 0.1 mm)."""
    sep = ds["fraction"].sel(kind="separation")
    stick = ds["fraction"].sel(kind="stick")
    grows = bool(np.all(sep.isel(omega=-1).values > sep.isel(omega=0).values + 0.01))
    return [
        Check("stick zones in every run (steady sliding unstable for every xi and Omega)",
              bool(stick.min() > 0.005), f"min stick fraction {float(stick.min()):.3f}", "> 0.005"),
        Check("separation grows as kappa = d sqrt(E/rho)/(R^2 Omega) decreases (paper: small mismatch, "
              "high speed)", grows, f"separation fraction {np.round(sep.values, 3).tolist()} (rows xi "
              f"{ds['xi'].values.tolist()}, columns Omega {ds['omega'].values.tolist()} rad/s)",
              "at every xi, larger at the largest Omega than at the smallest, by more than 0.01",
              "regimes: " + "; ".join(f"xi={x:g}: " + ", ".join(str(r) for r in ds['regime'].sel(xi=x).values)
                                      for x in ds["xi"].values), claim=True),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Regime names and zone fractions over ``xi`` and ``Omega``."""
    fig, (ax,) = plotting.new_figure(fig, size=(9, 3 + 0.8 * ds.sizes["xi"]))
    sep = ds["fraction"].sel(kind="separation").values
    top = max(0.3, float(sep.max()))
    im = ax.imshow(sep, origin="lower", cmap="Greys", vmin=0, vmax=top, aspect="auto")
    for i, xi in enumerate(ds["xi"].values):
        for j, om in enumerate(ds["omega"].values):
            c = ds.sel(xi=xi, omega=om)
            ax.text(j, i, f"{str(c['regime'].values)}\n{int(c['n_zones'])} zones, κ = {float(c['kappa']):.2g}",
                    ha="center", va="center", fontsize=7.5, color="w" if sep[i, j] > 0.45 * top else "k")
    ax.set(xticks=range(ds.sizes["omega"]), xticklabels=[f"{o:g}" for o in ds["omega"].values],
           yticks=range(ds.sizes["xi"]), yticklabels=[f"{x:g}" for x in ds["xi"].values], xlabel="Ω [rad/s]",
           ylabel="ξ = R*/R [1]",
           title=f"FE regimes, f = 0.7, d = 0.1 mm, R = 0.1 m ({ds.attrs['transits']} transits, "
                 "grey: separation fraction)")
    ax.title.set_fontsize(11)
    fig.colorbar(im, ax=ax, label="separation fraction of the nodes [1]")
    return fig


FIGURE = FigureSpec(
    key="brake-fem-regimes", cost=132, title="Section 3.1 — FE regimes over geometry and shaft speed",
    model="brake-like system, finite elements",
    claim="(Asked by the specification: the paper gives no geometry.) How the limit regime moves when the ring's "
          "thickness ξ = R*/R and the shaft speed Ω change.",
    method="FE runs from noise (f = 0.7, d = 0.1 mm) over ξ and Ω, which enter only through ξ and "
           "κ = d sqrt(E/ρ)/(R² Ω); classification of each limit regime.",
)

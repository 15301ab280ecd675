"""Section 3.1: the limit regime depends on the initial condition (reduced model on the ring).

Two perturbations of the same steady state (``f = 0.7``, ``delta = 0.001``, ``Omega = 50``
rad/s, the paper's ``beta2 = 0.9``), seeded with mode 2 or mode 3 plus white noise, on
several grids; each run classified over its last transits.
"""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake import BrakeParams, integrate, perturbed_steady
from ...contact import STATE_ATTRS, STATE_NAMES
from .. import Check, FigureSpec
from .paper import CASES
from .ring_runs import PADDED, PHI, SNAPS, all_true, pad_rows, stack, summary

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

#: Initial conditions of `initial_condition_data`: (label, seeded mode); amplitude 0.1 delta + 1e-3 noise.
SEEDS = (("mode 2", 2), ("mode 3", 3))


def compute(quick: bool = False) -> xr.Dataset:
    """Case 2 of section 3.1 (``f = 0.7``, ``delta = 0.001``, ``Omega = 50`` rad/s), paper's scheme
    ``beta2 = 0.9``: steady sliding perturbed by ``0.1 delta cos(n theta)`` (``n = 2`` or 3) plus
    white noise ``1e-3 delta`` (so no symmetry is imposed), on several grids."""
    f, d, om = CASES[1]
    p = BrakeParams.from_physical(om, d, f)
    grids, T = ((128, 192), 400) if quick else ((128, 192, 256), 800)
    runs = [summary(integrate(p, N, transits=T, beta2=0.9, initial=perturbed_steady(p, N, 0.1, mode, noise=1e-3)))
            for N in grids for _, mode in SEEDS]
    shape, dims = (len(grids), len(SEEDS)), ("grid", "seed")
    data = stack(runs, shape, dims)
    data["energy"] = (dims + ("transit",), pad_rows([r["energy"] for r in runs]).reshape(shape + (-1,)),
                      {"units": "E R^2 / M", "long_name": "energy of the deviation from steady sliding",
                       "comment": PADDED})
    data["state"] = (dims + ("snapshot", "phi"), np.array([r["state"] for r in runs]).reshape(shape + (SNAPS, PHI)),
                     {"long_name": "node state over the last 2 transits", **STATE_ATTRS})
    coords = {"grid": list(grids), "seed": [s for s, _ in SEEDS], "seed_mode": ("seed", [m for _, m in SEEDS]),
              "kind": list(STATE_NAMES), "transit": np.arange(data["energy"][1].shape[-1])}
    return xr.Dataset(data, coords=coords, attrs={
        "quick": int(quick), "transits": T, "beta2": 0.9, "friction": f, "delta": p.delta, "omega": om,
        "gamma": p.gamma, "initial": "steady sliding + 0.1 delta cos(n theta) + 1e-3 delta white noise (seed 0)"})


def check(ds: xr.Dataset) -> list[Check]:
    """Two perturbations, two limit regimes, on every grid."""
    n, E, spread = ds["n_fft"].values, ds["energy_late"].values, ds["energy_spread"].values
    differs = (n[:, 0] != n[:, 1]) & (np.abs(E[:, 0] - E[:, 1]) > 10 * spread.max(axis=1))
    return [
        Check("the limit regime depends on the initial condition (same parameters)", all_true(differs),
              f"dominant mode {n.tolist()}, late energy {np.round(E, 4).tolist()}", "different on every grid",
              "paper section 3.1: 'the limit regime may be different for two different initial conditions'"),
        Check("each limit regime is statistically steady (energy of the last two quarters)",
              bool(np.all(spread <= 0.01 * np.abs(E))), f"max relative change {float(np.max(spread / np.abs(E))):.2e}",
              "<= 1e-2", "a limit regime, not a transient"),
        Check("each seed selects the same regime on every grid", all_true(n == n[:1]),
              f"dominant mode per grid {n.tolist()}", "the same in every row", "robust to the mesh"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Energy histories (whole runs on a log scale; the second half, where the limit regimes
    are told apart, on a linear one) and the final node states of the two seeds on the finest grid."""
    from matplotlib.lines import Line2D

    nseed = ds.sizes["seed"]
    fig, axes = plotting.new_figure(fig, max(nseed, 2), 2, size=(5.4, 4.2))
    styles = ["-", "--", ":", "-."]
    transit = ds["transit"].values
    late = transit >= transit[-1] / 2
    for g, N in enumerate(ds["grid"].values):
        for k, seed in enumerate(ds["seed"].values):
            energy = ds["energy"].sel(grid=N, seed=seed).values
            style = {"color": f"C{k}", "lw": 0.8, "ls": styles[g % 4]}
            axes[0].semilogy(transit, energy, **style)
            axes[1].plot(transit[late], energy[late], **style)
    a = ds.attrs
    axes[0].set(xlabel="t [transits]", ylabel="energy of the deviation [E R²/M]",
                title=f"whole runs: f = {a['friction']:g}, δ = {a['delta']:g}, Ω = {a['omega']:g} rad/s, β2 = 0.9")
    axes[1].set(xlabel="t [transits]", ylabel="energy of the deviation [E R²/M]",
                title="second half of the runs (linear scale)")
    for ax in axes[:2]:
        ax.title.set_fontsize(9)
    handles = [Line2D([], [], color=f"C{k}", label=f"seeded {seed}") for k, seed in enumerate(ds["seed"].values)]
    handles += [Line2D([], [], color="k", lw=0.8, ls=styles[g % 4], label=f"N = {N}")
                for g, N in enumerate(ds["grid"].values)]
    plotting.legend_beside(axes[1], handles=handles)
    last = ds.isel(grid=-1)
    for k, seed in enumerate(ds["seed"].values):
        c = last.sel(seed=seed)
        ax = axes[len(axes) // 2 + k]
        plotting.state_image(ax, c["state"].values,
                             f"seeded {seed}, N = {int(last.grid)}: {str(c['regime'].values)},\ndominant n = "
                             f"{int(c['n_fft'])}, c/√a = {float(c['c_over_sqrt_a']):.2f}")
        ax.set(xlabel="θ [rad]", ylabel="t [transits], last 2")
    plotting.state_legend(axes[len(axes) // 2 + nseed - 1])
    for ax in axes[2:len(axes) // 2] + axes[len(axes) // 2 + nseed:]:
        ax.set_visible(False)
    return fig


FIGURE = FigureSpec(
    key="brake-initial-condition", cost=16, title="Section 3.1 — the limit regime depends on the initial condition",
    model="brake-like system, reduced model [12] by the method of lines",
    claim="It has been found that the limit regime may be different for two different initial conditions.",
    method="The same parameters (f = 0.7, δ = 0.001, Ω = 50 rad/s, β2 = 0.9) started from steady sliding plus a mode-2 "
           "or a mode-3 perturbation; each run classified over its last transits and checked for statistical "
           "steadiness.",
)

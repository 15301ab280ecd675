"""Section 3.1 with the reduced model: limit regimes of the ring by time integration.

The three regimes of the paper's section 3.1 (FE results there) run with the reduced
model on the default steel ring, with the paper's damped scheme (``beta2 = 0.9``) and with
central differences (``beta2 = 1/2``); the wavelength selection by the scheme's numerical
damping (fully discrete growth rates); and a sweep over ``xi`` and ``Omega``, which enter
the reduced model only through ``xi`` and ``kappa = delta / sqrt(gamma)`` (separation
number ``S = g delta sqrt(a) / |D|``).
"""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake import BrakeParams, RingScheme, growth_rates, integrate, perturbed_steady
from ...contact import STATE_ATTRS, STATE_NAMES
from .. import Check, FigureSpec
from .paper import CASES, PAPER_REGIMES
from .ring_runs import PADDED, PHI, SNAPS, all_true, pad_rows, stack, summary

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = False) -> xr.Dataset:
    """Limit regimes of the section 3.1 cases, wavelength selection, and a (xi, Omega) sweep."""
    settings = [(0.9, 256, 300), (0.5, 256, 300)] if quick else [(0.9, 512, 600), (0.5, 512, 600)]
    runs = []
    for f, d, om in CASES:
        p = BrakeParams.from_physical(om, d, f)
        for beta2, N, T in settings:
            runs.append(summary(integrate(p, N, transits=T, beta2=beta2, initial=perturbed_steady(p, N))))
    energy = pad_rows([r["energy"] for r in runs])
    T_max = energy.shape[1]
    shape, dims = (len(CASES), len(settings)), ("case", "setting")
    data = stack(runs, shape, dims)
    data["energy"] = (dims + ("transit",), energy.reshape(shape + (T_max,)),
                      {"units": "E R^2 / M", "long_name": "energy of the deviation from steady sliding",
                       "comment": PADDED})
    data["state"] = (dims + ("snapshot", "phi"), np.array([r["state"] for r in runs]).reshape(shape + (SNAPS, PHI)),
                     {"long_name": "node state over the last 2 transits", **STATE_ATTRS})
    # wavelength selection: fully discrete growth of steady sliding per transit
    n, grids = np.arange(1, 17), np.array([128, 256, 512, 1024])
    growth, cont = [], []
    for f, d, om in CASES:
        p = BrakeParams.from_physical(om, d, f)
        growth.append([[RingScheme(p, N, b2).growth_rates(n).real * RingScheme(p, N, b2).transit_time
                        for N in grids] for b2 in (0.9, 0.5)])
        cont.append(growth_rates(p, n).growth_rate * RingScheme(p).transit_time)
    data["growth"] = (("case", "beta2", "grid", "mode"), np.array(growth),
                      {"units": "1 / transit", "long_name": "fully discrete Re s of steady sliding"})
    data["growth_continuous"] = (("case", "mode"), np.array(cont), {"units": "1 / transit"})
    # sweep: xi x Omega at f = 0.7, d = 0.1 mm (only xi and kappa = delta/sqrt(gamma) matter)
    xis, omegas = ((1.5, 3.0), (50.0, 3200.0)) if quick else ((1.5, 2.0, 3.0), (12.5, 50.0, 200.0, 800.0, 3200.0))
    T_sweep = 200 if quick else 400
    sweep = []
    for xi in xis:
        for om in omegas:
            p = BrakeParams.from_physical(om, 1e-4, 0.7, outer_radius=0.1 * xi)
            sweep.append(summary(integrate(p, 128, transits=T_sweep, beta2=0.9, initial=perturbed_steady(p, 128))))
    data.update(stack(sweep, (len(xis), len(omegas)), ("xi", "omega"), prefix="sweep_"))
    coords = {"case": np.arange(len(CASES)), "setting": np.arange(len(settings)),
              "beta2_setting": ("setting", [s[0] for s in settings]), "nodes": ("setting", [s[1] for s in settings]),
              "transits": ("setting", [s[2] for s in settings]), "kind": list(STATE_NAMES),
              "friction": ("case", [c[0] for c in CASES]), "delta": ("case", [c[1] / 0.1 for c in CASES]),
              "omega_case": ("case", [c[2] for c in CASES], {"units": "rad/s"}),
              "paper_regime": ("case", [r for r, _ in PAPER_REGIMES]),
              "paper_modes": ("case", [m for _, m in PAPER_REGIMES]),
              "beta2": [0.9, 0.5], "grid": grids, "mode": n, "xi": list(xis),
              "omega": ("omega", list(omegas), {"units": "rad/s"}), "transit": np.arange(T_max)}
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update({"quick": int(quick), "sweep_transits": T_sweep, "sweep_nodes": 128, "sweep_beta2": 0.9,
                     "geometry": "steel ring R = 0.1 m, R* = 0.15 m (sweep: R* = xi R), E = 2.1e11 Pa, "
                                 "rho = 7850 kg/m^3, nu = 0.3; sweep at f = 0.7, d = 0.1 mm",
                     "initial": "steady sliding + white noise 1e-3 delta (seed 0)"})
    return ds


def check(ds: xr.Dataset) -> list[Check]:
    """What the reduced model gives for section 3.1, checked against linear theory and the paper."""
    stick = ds["fraction"].sel(kind="stick")
    sep, S = ds["sweep_fraction"].sel(kind="separation"), ds["sweep_S"]
    c1 = ds["regime"].isel(case=0).values
    sign = np.sign(ds["c_over_sqrt_a"].values) == np.sign(ds["D"].values)
    ssign = np.sign(ds["sweep_c_over_sqrt_a"].values) == np.sign(ds["sweep_D"].values)
    selected = ds["growth"].sel(beta2=0.9).isel(case=1).idxmax("mode").values
    damped = ds["growth"].sel(beta2=0.9, grid=128).isel(case=0)
    found = [f"case {i + 1}: {r} (n = {n}) / {pr} ({pm})" for i, (r, n, pr, pm) in enumerate(zip(
        ds["regime"].isel(setting=0).values, ds["n_fft"].isel(setting=0).values, ds["paper_regime"].values,
        ds["paper_modes"].values))]
    return [
        Check("steady sliding gives way to stick zones in every run (flutter saturated by stick)",
              bool(stick.min() > 0.005), f"min stick fraction {float(stick.min()):.3f}", "> 0.005",
              "section 3: steady sliding is unstable; zones of stick and/or separation appear"),
        Check("the waves travel in the direction of the linear flutter wave (sign of D)",
              all_true(sign) and all_true(ssign[ds["sweep_fraction"].sel(kind="stick").values > 0.005]),
              f"c/sqrt(a) in [{float(ds['c_over_sqrt_a'].min()):.3f}, {float(ds['c_over_sqrt_a'].max()):.3f}]",
              "sign(c) = sign(D) < 0", "against the shaft for xi = 1.5, nu = 0.3"),
        Check("case 1 (f = 0.2, delta = 0.004, Omega = 1 rad/s): stick-slip, no separation, as the FE",
              all_true(c1 == "stick-slip"), f"{c1.tolist()}", "stick-slip with both schemes",
              "mode number differs: " + "; ".join(found[:1])),
        Check("separation needs a small separation number S = g delta sqrt(a)/|D|",
              all_true(sep.values[S.values > 5] == 0) and all_true(sep.values[S.values < 0.5] > 0.01),
              f"separation fraction {np.round(sep.values, 3).tolist()} at S {np.round(S.values, 2).tolist()}",
              "0 for S > 5, > 0.01 for S < 0.5",
              "paper: separation for small mismatch or high speed/friction; " + "; ".join(found[1:])),
        Check("beta2 = 0.9 damps short waves: the discrete growth rate peaks at a mode growing with N",
              bool(np.all(np.diff(selected) >= 0) and selected[-1] > selected[0]),
              f"most unstable n = {selected.tolist()} for N = {ds['grid'].values.tolist()}",
              "non-decreasing in N (continuous model: Re s increases with n)",
              "case 2; the mode number of a damped-scheme simulation is partly a property of the mesh"),
        Check("beta2 = 0.9 on 128 nodes makes steady sliding of case 1 stable, which it is not",
              bool(damped.max() < 0 and ds["growth_continuous"].isel(case=0).min() > 0),
              f"max discrete Re s = {float(damped.max()):.3f} per transit", "< 0 (continuous: > 0 for all n)",
              "numerical damping (beta2 - 1/2) w^2 dt / 2 exceeds the flutter growth on coarse meshes"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Node states (space-time) per case and scheme, energies, growth selection, and the sweep."""
    from matplotlib.lines import Line2D

    ncase, nset = ds.sizes["case"], ds.sizes["setting"]
    fig = Figure(figsize=(11.5, 3.2 * nset + 7.4)) if fig is None else fig
    grid = fig.add_gridspec(nset + 2, 2 * ncase, height_ratios=[1.0] * nset + [1.1, 1.1])
    first_row, first_col = [], []
    for j in range(nset):
        for i in range(ncase):
            ax = fig.add_subplot(grid[j, 2 * i:2 * i + 2], sharex=first_row[i] if j else None,
                                 sharey=first_col[j] if i else None)
            first_row += [ax] if j == 0 else []
            first_col += [ax] if i == 0 else []
            c = ds.isel(case=i, setting=j)
            plotting.state_image(ax, c["state"].values,
                                 f"case {i + 1}: f = {float(c.friction):g}, δ = {float(c.delta):g}, "
                                 f"Ω = {float(c.omega_case):g} rad/s\n"
                                 f"β2 = {float(c.beta2_setting):g}, N = {int(c.nodes)}: "
                                 f"{str(c['regime'].values)}, n = {int(c['n_fft'])}\nc/√a = "
                                 f"{float(c['c_over_sqrt_a']):.2f}; FE: {str(c.paper_regime.values)}, "
                                 f"{int(c.paper_modes)} modes")
            ax.tick_params(labelbottom=j == nset - 1, labelleft=i == 0)
            if j == nset - 1:
                ax.set_xlabel("θ [rad]")
            if i == 0:
                ax.set_ylabel("t [transits], last 2")
            if j == 0 and i == ncase - 1:
                plotting.state_legend(ax)
    styles = ["-", "--", ":", "-."]
    ax = fig.add_subplot(grid[nset, :ncase])
    for i in range(ncase):
        for j in range(nset):
            ax.semilogy(ds["transit"], ds["energy"].isel(case=i, setting=j), lw=0.8, ls=styles[j % 4], color=f"C{i}")
    ax.set(xlabel="t [transits]", ylabel="energy of the deviation [E R²/M]")
    handles = [Line2D([], [], color=f"C{i}", label=f"case {i + 1}") for i in range(ncase)]
    handles += [Line2D([], [], color="k", lw=0.8, ls=styles[j % 4], label=f"β2 = {float(ds.beta2_setting[j]):g}")
                for j in range(nset)]
    plotting.legend_above(ax, handles=handles, ncol=3, title="growth and saturation", title_fontsize=9)
    ax = fig.add_subplot(grid[nset, ncase:])
    for k, b2 in enumerate(ds["beta2"].values):
        for g, N in enumerate(ds["grid"].values):
            ax.plot(ds["mode"], ds["growth"].isel(case=1).sel(beta2=b2, grid=N), ls="-" if k == 0 else ":",
                    color=f"C{g}")
            if k == 0:
                ax.plot(ds["mode"], ds["growth"].isel(case=0).sel(beta2=b2, grid=N), ls="-.", color=f"C{g}", lw=0.7)
    ax.plot(ds["mode"], ds["growth_continuous"].isel(case=1), "k-", lw=2)
    ax.plot(ds["mode"], ds["growth_continuous"].isel(case=0), "k-.", lw=1)
    ax.axhline(0, color="k", lw=0.5)
    ax.set_yscale("symlog", linthresh=1.0)
    ax.set(xlabel="mode number n [1]", ylabel="Re s [1/transit] (symlog)")
    ax.set_title("fully discrete growth of steady sliding", fontsize=10)
    handles = [Line2D([], [], color=f"C{g}", label=f"N = {N}") for g, N in enumerate(ds["grid"].values)]
    handles += [Line2D([], [], color="k", lw=2, label="continuous model"),
                Line2D([], [], color="0.4", ls="-", label="case 2, β2 = 0.9"),
                Line2D([], [], color="0.4", ls=":", label="case 2, β2 = 0.5"),
                Line2D([], [], color="0.4", ls="-.", lw=0.7, label="case 1, β2 = 0.9")]
    plotting.legend_beside(ax, handles=handles)
    ax = fig.add_subplot(grid[nset + 1, :])
    sep, stick = ds["sweep_fraction"].sel(kind="separation"), ds["sweep_fraction"].sel(kind="stick")
    markers = {"stick-slip": "o", "stick-slip-separation": "^", "stick-separation": "s",
               "stick-slip-reverse-slip": "v", "stick-slip-separation-reverse-slip": "D"}
    met = []
    for x, xi in enumerate(ds["xi"].values):
        S = ds["sweep_S"].sel(xi=xi).values
        order = np.argsort(S)
        ax.plot(S[order], sep.sel(xi=xi).values[order], "-", color=f"C{x}")
        ax.plot(S[order], stick.sel(xi=xi).values[order], "--", color=f"C{x}")
        for s_, f_, r in zip(S, sep.sel(xi=xi).values, ds["sweep_regime"].sel(xi=xi).values):
            r = str(r)
            met += [r] if r not in met else []
            ax.plot(s_, f_, markers.get(r, "X"), color=f"C{x}", ms=7, mec="k", mew=0.6)
    ax.set_xscale("log")
    om = ds["omega"].values
    ax.set(xlabel="separation number S = g δ √a / |D| [1]", ylabel="node fraction [1]",
           title=f"sweep over ξ and Ω = {om.min():g} to {om.max():g} rad/s: f = 0.7, d = 0.1 mm, β2 = 0.9, "
                 f"N = {ds.attrs['sweep_nodes']}")
    handles = [Line2D([], [], color=f"C{x}", label=f"ξ = {xi:g}") for x, xi in enumerate(ds["xi"].values)]
    handles += [Line2D([], [], color="k", ls="-", label="separation fraction"),
                Line2D([], [], color="k", ls="--", label="stick fraction")]
    handles += [Line2D([], [], ls="none", marker=markers.get(r, "X"), color="w", mec="k", ms=7, label=r) for r in met]
    plotting.legend_beside(ax, handles=handles, title="marker: regime", title_fontsize=8)
    return fig


FIGURE = FigureSpec(
    key="brake-ring-regimes", cost=48, title="Section 3.1 — limit regimes of the ring (reduced model, time integration)",
    model="brake-like system, reduced model [12] by the method of lines",
    claim="Direct time integration reaches limit regimes: for f = 0.2, δ = 0.004, Ω = 1 rad/s a stick-slip wave with "
          "4 modes; for f = 0.7, δ = 0.001, Ω = 50 rad/s a stick-slip-separation wave with 8 modes; for f = 2, "
          "δ = 0.004, Ω = 80 rad/s a stick-separation wave with 2 modes (FE results in the paper, Figures 7-10).",
    method="The corrected reduced model [12] on N nodes (second-order differences), explicit β2-scheme [22] with "
           "forward-increment Lagrange multipliers [23] node by node, on a steel ring R = 0.1 m, R* = 0.15 m (the paper "
           "gives no geometry), with the paper's β2 = 0.9 and with central differences (β2 = 1/2); automatic "
           "classification of the last transits (zones, mode number, wave speed, stationarity); wavelength selection "
           "by the scheme's discrete growth rates; a sweep over ξ and Ω. The paper's regimes are FE results: the "
           "report states where the reduced model agrees and where it does not.",
    errata=("B3",),
)

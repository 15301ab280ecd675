"""What the FE figures of section 3.1 (7-10) share: the runs of one case as a dataset, the
checks every case passes, and the panels of their plots (which read only the dataset).

Each case is run on the default steel ring (``R = 0.1 m``, ``R* = 0.15 m``,
``E = 2.1e11 Pa``, ``rho = 7850 kg/m^3``, ``nu = 0.3``; the paper gives no geometry for this
section) from FE steady sliding perturbed by white noise ``1e-3 delta`` and from a seeded
mode (``0.1 delta cos n theta`` plus the same noise), with the paper's scheme
``beta2 = 0.9``. Budgets are in P-wave transits ``2 pi R / c_p``. The cases (`paper.CASES`):

* Figure 7: ``f = 0.2, delta = 0.004, Omega = 1 rad/s`` (paper: stick-slip, 4 modes);
* Figure 8: ``f = 2, delta = 0.004, Omega = 80 rad/s`` (paper: stick-separation, 2 modes);
* Figures 9 and 10: ``f = 0.7, delta = 0.001, Omega = 50 rad/s`` (paper:
  stick-slip-separation, 8 modes; Figure 9 its radial displacement, Figure 10 its contact
  pressure: one run set).
"""

from __future__ import annotations

import time

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake import BrakeParams
from ...brake.fem import FemScheme, classify_fem, fem_growth_rates, integrate_fem, perturbed_steady, slip_wave_rate
from ...contact import SEPARATION, STATE_ATTRS, STATE_NAMES, StepState, count_zones
from ...contact.energy import trace
from ...contact.verify import contact_law_residuals, implied_reactions
from ...errors import ParameterError
from .. import Check
from .paper import CASES, GEOMETRY, PAPER_REGIMES

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["METHOD", "MESHES", "case_data", "common_checks", "seeded_check", "runs_text", "separation_zones", "case_plot", "title",
           "spacetime", "waterfall", "spacetime_panels"]

METHOD = ("Plane-strain annulus meshed with bilinear quadrilaterals (scikit-fem assembly, lumped mass, outer radius "
          "clamped), explicit β2-scheme [22] with β2 = 0.9 as in the paper and forward-increment Lagrange "
          "multipliers [23] solved exactly node by node (erratum B5); steel ring R = 0.1 m, R* = 0.15 m (the paper "
          "gives no geometry); runs from FE steady sliding (checked against Lamé) perturbed by noise and by a seeded "
          "mode, budgeted in P-wave transits; the contact laws checked on reactions recomputed from the motion "
          "(M a + K u = Cᵀλ with the assembled sparse K) over 200 steps at the end of every run; the limit regime "
          "classified on the contact nodes. Mesh 512 × 32, 400 transits (quick: 256 × 16, 300). The paper's "
          "regime and mode-number claims are settled by the statistics of unseeded runs (brake-fem-statistics); "
          "here the runs seeded with a mode show whether that wave is a limit regime.")

#: (n_theta, n_r, transits per run) of the quick and full modes.
MESHES = {True: (256, 16, 300), False: (512, 32, 400)}


_SNAPS = 64  # tail snapshots kept (2 transits at 32 per transit)


_SCALARS = ("n", "n_fft", "n_zones", "n_fft_P", "c_over_cp", "c_P_over_cp", "stationary", "residual",
            "energy_mean", "energy_cv", "p_max_over_pe", "p_mean_over_pe")


_RESIDUALS = ("off_contact", "kernel", "negative_pressure", "penetration", "complementarity", "coulomb",
              "stick_motion", "slip_direction", "stick_count", "slip_count")
#: Steps traced at the end of every run for the check of the contact laws.
TRACE_STEPS = 200


def _params(case: int) -> BrakeParams:
    f, d, om = CASES[case]
    return BrakeParams.from_physical(om, d, f)


def _one_run(p, N, nr, T, seed):
    s = FemScheme(p, N, nr, 0.9)
    ini = perturbed_steady(s) if seed is None else perturbed_steady(s, 0.1, seed, noise=1e-3)
    t0 = time.perf_counter()
    run = integrate_fem(p, N, nr, transits=T, initial=ini)
    seconds = time.perf_counter() - t0
    res, resid = classify_fem(run), _law_residuals(run)
    tr = run.t / s.transit_time
    per = [(tr >= k) & (tr < k + 1) for k in range(int(np.floor(tr[-1])))]
    pe = s.steady.pressure.mean()
    return {"regime": res.regime, **{k: getattr(res, k) for k in _SCALARS}, **{k: resid[k] for k in _RESIDUALS},
            "fraction": [res.fractions[k] for k in STATE_NAMES], "seconds": seconds,
            "energy": np.array([run.energy[m].mean() for m in per]),
            "fraction_history": np.array([run.fractions[m].mean(axis=0) for m in per]),
            "U": run.U[-_SNAPS:] / p.delta - 1.0, "Vd": run.Vd[-_SNAPS:], "P": run.P[-_SNAPS:] / pe,
            "state": run.state[-_SNAPS:], "snap_t": run.snap_t[-_SNAPS:] / s.transit_time}


def _law_residuals(run) -> dict:
    """Contact-law residuals of reactions recomputed from `TRACE_STEPS` traced steps after the run."""
    s, k = run.scheme, run.kernel
    tr = trace(s, StepState(k["u"].copy(), k["v"].copy(), k["a"].copy()), TRACE_STEPS)
    r, steps = implied_reactions(tr, s.mass, s.system.K)
    return contact_law_residuals(tr, r, steps, s.params.friction)


def case_data(case: int, seeds=(None,), quick: bool = False, mesh: tuple | None = None) -> xr.Dataset:
    """Runs of section 3.1 case ``case`` (0, 1, 2) from noise (``None``) and seeded modes.

    ``mesh = (n_theta, n_r, transits)`` overrides `MESHES` (quick: 256 x 16, 300 transits;
    full: 512 x 32, 400 transits per run).
    """
    if case not in (0, 1, 2):
        raise ParameterError("case", case, "0, 1 or 2 (section 3.1 cases)")
    N, nr, T = MESHES[bool(quick)] if mesh is None else mesh
    p = _params(case)
    s = FemScheme(p, N, nr, 0.9)
    runs = [_one_run(p, N, nr, T, seed) for seed in seeds]
    dims = ("run",)
    data = {"regime": (dims, np.array([r["regime"] for r in runs]))}
    for key in _SCALARS + _RESIDUALS + ("seconds",):
        data[key] = (dims, np.array([r[key] for r in runs]))
    data["fraction"] = (dims + ("kind",), np.array([r["fraction"] for r in runs]), {"units": "1"})
    nt = min(len(r["energy"]) for r in runs)
    data["energy"] = (dims + ("transit",), np.array([r["energy"][:nt] for r in runs]),
                      {"units": "E R^2", "long_name": "energy of the deviation from steady sliding, per transit"})
    data["fraction_history"] = (dims + ("transit", "kind"), np.array([r["fraction_history"][:nt] for r in runs]))
    for key, units in (("U", "delta"), ("Vd", "R Omega"), ("P", "p_e"), ("state", None), ("snap_t", "transits")):
        arr = np.array([r[key] for r in runs])
        data[key] = (dims + ("snapshot",) + (("theta",) if arr.ndim == 3 else ()), arr,
                     {"units": units} if units else dict(STATE_ATTRS))
    data["U"][2]["long_name"] = "u_r(R)/d - 1 (radial displacement beyond the mismatch)"
    g = fem_growth_rates(p, s.system, np.arange(1, N // 2 + 1))
    data["growth"] = ("mode", g.growth_rate * s.transit_time, {"units": "1/transit", "long_name": "FE flutter"})
    data["growth_discrete"] = ("mode", g.discrete(s.dt, 0.9).real.max(axis=1) * s.transit_time,
                               {"units": "1/transit", "long_name": "fully discrete (beta2 = 0.9)"})
    data["flutter_speed"] = ("mode", -g.lowest.imag / g.n / s.p_wave_speed,
                             {"units": "c_p/R", "long_name": "phase speed -Im s / n of the lowest flutter branch"})
    errors = s.steady.errors()
    rho = slip_wave_rate(p.friction, p.nu)
    cs_over_cp = float(np.sqrt((1 - 2 * p.nu) / (2 * (1 - p.nu))))
    coords = {"run": ["noise" if sd is None else f"mode {sd}" for sd in seeds],
              "seed_mode": ("run", [0 if sd is None else sd for sd in seeds]), "kind": list(STATE_NAMES),
              "theta": s.theta, "transit": np.arange(nt), "mode": g.n}
    attrs = {"case": case + 1, "friction": p.friction, "delta": p.delta, "omega": p.omega, "gamma": p.gamma,
             "kappa": p.delta / np.sqrt(p.gamma), "n_theta": N, "n_r": nr, "transits": T, "beta2": 0.9,
             "mesh": s.system.mesh.describe(), "dt": s.dt, "steps_per_transit": s.steps_per_transit,
             "p_e": errors["p_e"], "lame_error_u": errors["u"], "lame_error_v": errors["v"],
             "lame_error_p": errors["p"], "paper_regime": PAPER_REGIMES[case][0], "paper_modes": PAPER_REGIMES[case][1],
             "halfspace_rate_per_transit_per_mode": float(2 * np.pi * rho.real * cs_over_cp) if rho == rho else 0.0,
             "quick": int(bool(quick)), "geometry": GEOMETRY, "initial": "FE steady sliding + 1e-3 delta white noise (seed 0), "
             "or + 0.1 delta cos(n theta) + 1e-3 delta noise"}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def runs_text(ds, key, fmt="{}"):
    return ", ".join(f"{r}: {fmt.format(v)}" for r, v in zip(ds["run"].values, ds[key].values))


def separation_zones(ds) -> np.ndarray:
    """Median number of separation zones per snapshot, per run."""
    return np.array([np.median([count_zones(s == SEPARATION, 1) for s in st]) for st in ds["state"].values])


def common_checks(ds) -> list[Check]:
    """Lamé agreement, the contact laws on reactions recomputed from the motion, instability of steady sliding."""
    lame = max(ds.attrs["lame_error_u"], ds.attrs["lame_error_v"], ds.attrs["lame_error_p"])
    worst = {k: float(ds[k].max()) for k in _RESIDUALS[:8]}
    stick = ds["fraction"].sel(kind="stick")
    return [
        Check("FE steady sliding on this mesh matches the Lamé solution (eq. [11] corrected)", lame < 1e-3,
              f"max relative error u {ds.attrs['lame_error_u']:.2e}, v {ds.attrs['lame_error_v']:.2e}, "
              f"p {ds.attrs['lame_error_p']:.2e} (p_e = {ds.attrs['p_e']:.4g} E)", "< 1e-3 (order 2 in the mesh)",
              f"mesh {ds.attrs['mesh']}"),
        Check("the reactions the equations of motion need are the kernel's, and obey Signorini and Coulomb",
              all(worst[k] <= 1e-8 for k in ("off_contact", "kernel", "negative_pressure", "complementarity", "coulomb"))
              and worst["penetration"] <= 1e-12 and worst["stick_motion"] <= 1e-9 and worst["slip_direction"] == 0
              and bool(ds["stick_count"].min() > 0) and bool(ds["slip_count"].min() > 0),
              ", ".join(f"{k} {v:.1e}" for k, v in worst.items()) + f"; stick node-steps {int(ds['stick_count'].min())}+,"
              f" slip {int(ds['slip_count'].min())}+", "<= 1e-8 (relative to max lambda_n), gap >= 0, stick and slip met",
              f"reactions from M a + K u over {TRACE_STEPS} traced steps after each run (a from the displacements, "
              "K the assembled sparse matrix, not the kernel's stencil)"),
        Check("steady sliding is unstable: stick zones appear in every run", bool(stick.min() > 0.005),
              ", ".join(f"{r}: stick {float(v):.3f}" for r, v in zip(ds["run"].values, stick.values)), "> 0.005",
              f"flutter: fastest discrete mode n = {int(ds['growth_discrete'].idxmax())} "
              f"({float(ds['growth_discrete'].max()):.2f} per transit, beta2 = 0.9)"),
    ]


def seeded_check(ds, mode: int, regime: str, figure: str, detail: str = "") -> Check:
    """The run seeded with ``cos(mode theta)`` ends, stationary, in ``regime`` with ``mode`` stick
    zones: the paper's wave is a limit regime (a seeded run, labelled so; the claim from
    unseeded starts is brake-fem-statistics')."""
    r = ds.sel(run=f"mode {mode}")
    ok = str(r["regime"].values) == regime and float(r["n_zones"]) == mode and bool(r["stationary"])
    return Check(f"seeded start (cos {mode}θ): the {mode}-mode {regime} wave of {figure} is a limit regime (stationary)",
                 bool(ok), f"seeded mode {mode}: {r['regime'].values}, {float(r['n_zones']):g} stick zones, stationary "
                 f"{bool(r['stationary'])}, c = {float(r['c_over_cp']):.3f} c_p/R; slip "
                 f"{float(r['fraction'].sel(kind='slip')):.3f}, reverse slip "
                 f"{float(r['fraction'].sel(kind='reverse_slip')):.3f}, separation "
                 f"{float(r['fraction'].sel(kind='separation')):.3f}",
                 f"{regime}, {mode} stick zones, stationary", detail or f"time per run: {runs_text(ds, 'seconds', '{:.0f} s')}",
                 claim=True)


def title(ds, i):
    r = ds.isel(run=i)
    return (f"{str(r['run'].values)}: {str(r['regime'].values)}, {int(r['n_zones'])} zones, "
            f"c = {float(r['c_over_cp']):.2f} c_p/R")


def case_plot(ds, fig, profile, label) -> Figure:
    """A column per run: node states (last 2 transits) over the profiles of ``profile`` and the
    pressure at the last snapshot; below, the energies and the growth rates of steady sliding."""
    nrun = ds.sizes["run"]
    fig = Figure(figsize=(max(5.5 * nrun, 9.0), 11.0)) if fig is None else fig
    grid = fig.add_gridspec(3, 2 * nrun)
    th = ds["theta"].values
    for i in range(nrun):
        ax = fig.add_subplot(grid[0, 2 * i:2 * i + 2])
        plotting.state_image(ax, ds["state"].isel(run=i).values, title(ds, i))
        ax.set(xlabel="θ [rad]", ylabel="t [transits], last 2 of the run")
        if i == nrun - 1:
            plotting.state_legend(ax)
        ax = fig.add_subplot(grid[1, 2 * i:2 * i + 2])
        ax.plot(th, ds[profile].isel(run=i, snapshot=-1), lw=0.9, label=label)
        ax.plot(th, ds["P"].isel(run=i, snapshot=-1), lw=0.9, label="p / p_e")
        ax.axhline(1.0, color="k", lw=0.4)
        ax.set(xlabel="θ [rad] (last snapshot)", ylabel=f"{label}, p / p_e [1]", xticks=[0, np.pi, 2 * np.pi],
               xticklabels=["0", "π", "2π"])
        plotting.legend_above(ax)
    ax = fig.add_subplot(grid[2, :nrun])
    for i in range(nrun):
        ax.semilogy(ds["transit"], ds["energy"].isel(run=i), lw=0.8, label=str(ds["run"].values[i]))
    ax.set(xlabel="t [transits]", ylabel="energy of the deviation [E R²]")
    plotting.legend_above(ax, title="growth and saturation, per run", title_fontsize=9)
    ax = fig.add_subplot(grid[2, nrun:])
    growth, discrete = ds["growth"].values, ds["growth_discrete"].values
    lo = min(-1.0, float(np.nanmin(growth)), float(np.nanmin(discrete)))
    hi = 1.2 * max(float(np.nanmax(growth)), float(np.nanmax(discrete)))
    ax.plot(ds["mode"], growth, label="FE semi-discrete")
    ax.plot(ds["mode"], discrete, label="FE discrete, β2 = 0.9")
    hs = ds.attrs["halfspace_rate_per_transit_per_mode"]
    if hs > 0:  # a straight line: drawn up to the top of the axes
        line = hs * ds["mode"].values
        ax.plot(ds["mode"], np.where(line <= hi, line, np.nan), "k:", label="half-space slip wave")
    ax.axhline(0, color="k", lw=0.5)
    ax.set(xlabel="mode number n [1]", ylabel="growth rate Re s [1/transit]", ylim=(lo, hi))
    plotting.legend_above(ax, title="flutter of steady sliding (Re s: max over the branches)", title_fontsize=9)
    a = ds.attrs
    fig.suptitle(plotting.wrap(f"case {a['case']}: f = {a['friction']:g}, δ = {a['delta']:g}, Ω = {a['omega']:g} "
                               f"rad/s (κ = {a['kappa']:.3g}); paper: {a['paper_regime']}, {a['paper_modes']} modes; "
                               f"{a['mesh']}, β2 = 0.9, {a['transits']} transits per run", 120), fontsize=9)
    return fig


def spacetime(ax, ds, i, key, label, cmap):
    r = ds.isel(run=i)
    im = ax.imshow(r[key].values, aspect="auto", origin="lower", cmap=cmap, interpolation="nearest",
                   extent=(0, 2 * np.pi, float(r["snap_t"][0]), float(r["snap_t"][-1])))
    ax.set(xlabel="θ [rad]", ylabel="t [transits]", xticks=[0, np.pi, 2 * np.pi], xticklabels=["0", "π", "2π"])
    ax.set_title(title(ds, i), fontsize=8)
    return im


def waterfall(ax, ds, i, key, step, scale, label=""):
    """Successive profiles of ``key`` (every ``step``-th snapshot) divided by ``scale`` and lifted to
    their time: the y axis is the time of each profile's baseline."""
    r = ds.isel(run=i)
    snaps = list(range(0, r.sizes["snapshot"], step))
    times = r["snap_t"].values[snaps]
    lift = np.median(np.diff(times)) if len(times) > 1 else 1.0
    for snap, t in zip(snaps, times):
        ax.plot(r["theta"], t + lift * r[key].isel(snapshot=snap) / scale, lw=0.7, color="C0")
    ax.set(xlabel="θ [rad]", ylabel="t [transits] (baseline of each profile)", xticks=[0, np.pi, 2 * np.pi],
           xticklabels=["0", "π", "2π"])
    ax.set_title(f"successive profiles of {label or key}\n(one baseline spacing = {scale:.3g})", fontsize=8)


def spacetime_panels(ds, fig, key, label, cmap):
    """A column per run: ``key`` over ``theta`` and time on top (with a colour bar); returns the
    figure and the empty bottom axes, one per run."""
    nrun = ds.sizes["run"]
    fig = Figure(figsize=(max(5.0 * nrun, 6.0), 9)) if fig is None else fig
    axes = fig.subplots(2, nrun, squeeze=False)
    for i in range(nrun):
        fig.colorbar(spacetime(axes[0, i], ds, i, key, label, cmap), ax=axes[0, i], label=label)
    return fig, list(axes[1])

"""Figure data, plots and checks for the time integration of the reduced model on the ring.

`regimes_data`: the three regimes of the paper's section 3.1 (FE results there) run with
the reduced model on the default steel ring, with the paper's damped scheme
(``beta2 = 0.9``) and with central differences (``beta2 = 1/2``); the wavelength selection
by the scheme's numerical damping (fully discrete growth rates); and a sweep over
``xi`` and ``Omega``, which enter the reduced model only through ``xi`` and
``kappa = delta / sqrt(gamma)`` (separation number ``S = g delta sqrt(a) / |D|``).
`initial_condition_data`: two perturbations of the same steady state reaching two
different limit regimes. Budgets are in wave transits ``2 pi / sqrt(a)``.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..figures import Check
from .reduced.params import BrakeParams
from .ring.integrate import integrate, perturbed_steady
from .ring import classify
from .ring_plots import plot_initial_condition, plot_regimes
from ..contact import STATE_NAMES
from .ring import RingScheme
from .reduced.flutter import growth_rates

__all__ = ["CASES", "PAPER_REGIMES", "regimes_data", "initial_condition_data", "plot_regimes",
           "plot_initial_condition", "check_regimes", "check_initial_condition", "separation_number"]

#: (friction f, mismatch d [m], Omega [rad/s]) of section 3.1 on R = 0.1 m (delta = d/R).
CASES = ((0.2, 4e-4, 1.0), (0.7, 1e-4, 50.0), (2.0, 4e-4, 80.0))
#: What the paper's FE gave for CASES (regime, number of modes).
PAPER_REGIMES = (("stick-slip", 4), ("stick-slip-separation", 8), ("stick-separation", 2))
_PHI, _SNAPS = 256, 60  # node patterns for plotting: resampled nodes, last snapshots


def separation_number(params: BrakeParams) -> float:
    """``S = g delta sqrt(a) / |D|``: contact is lost where ``D V' > g delta``, and a stick-slip
    wave has ``|V'| ~ 1/sqrt(a)`` (velocities of the order of the shaft speed), so separation
    needs ``S`` of order one or less. ``S = kappa * (gamma g) sqrt(gamma a) / (gamma |D|)``."""
    c = params.coefficients()
    return float(c.g * params.delta * np.sqrt(c.a) / abs(c.D))


def _summary(run, window=2.0) -> dict:
    res = classify(run, transits=window)
    s, tr = run.scheme, run.t / run.scheme.transit_time
    edges = np.arange(0, int(np.floor(tr[-1])) + 1)
    energy = np.array([run.energy[(tr >= a) & (tr < a + 1)].mean() for a in edges[:-1]])
    tail = run.snap_t >= run.t_end - window * s.transit_time
    idx = (np.arange(_PHI) * s.nodes) // _PHI
    q = len(energy) // 4
    return {"regime": res.regime, "n": res.n, "n_fft": res.n_fft, "c_over_sqrt_a": res.c_over_sqrt_a,
            "c": res.c, "stationary": res.stationary, "residual": res.residual,
            "fraction": [res.fractions[k] for k in STATE_NAMES], "energy": energy,
            "energy_late": energy[-q:].mean(), "energy_spread": abs(energy[-q:].mean() - energy[-2 * q:-q].mean()),
            "state": run.state[tail][-_SNAPS:, idx], "kappa": s.params.delta / np.sqrt(s.params.gamma),
            "S": separation_number(s.params), "D": s.coefficients.D}


def _pad(rows) -> np.ndarray:
    """Rows of unequal length as a 2-D array padded with NaN."""
    out = np.full((len(rows), max(len(r) for r in rows)), np.nan)
    for i, r in enumerate(rows):
        out[i, :len(r)] = r
    return out


def _stack(summaries, shape, dims, prefix=""):
    """Data variables from nested summaries (a flat list in C order over ``shape``)."""
    out = {}
    for key, unit in (("regime", None), ("n", "1"), ("n_fft", "1"), ("c_over_sqrt_a", "1"), ("stationary", None),
                      ("residual", "1"), ("energy_late", "E R^2 / M"), ("energy_spread", "E R^2 / M"),
                      ("kappa", "1"), ("S", "1"), ("D", "1")):
        arr = np.array([sm[key] for sm in summaries]).reshape(shape)
        out[prefix + key] = (dims, arr.astype(str) if key == "regime" else arr, {"units": unit} if unit else {})
    frac = np.array([sm["fraction"] for sm in summaries]).reshape(shape + (len(STATE_NAMES),))
    out[prefix + "fraction"] = (dims + ("kind",), frac, {"units": "1", "long_name": "time-averaged node fraction"})
    return out


def regimes_data(quick: bool = False) -> xr.Dataset:
    """Limit regimes of the section 3.1 cases, wavelength selection, and a (xi, Omega) sweep."""
    settings = [(0.9, 256, 300), (0.5, 256, 300)] if quick else [(0.9, 512, 600), (0.5, 512, 600)]
    runs = []
    for f, d, om in CASES:
        p = BrakeParams.from_physical(om, d, f)
        for beta2, N, T in settings:
            runs.append(_summary(integrate(p, N, transits=T, beta2=beta2, initial=perturbed_steady(p, N))))
    energy = _pad([r["energy"] for r in runs])
    T_max = energy.shape[1]
    shape, dims = (len(CASES), len(settings)), ("case", "setting")
    data = _stack(runs, shape, dims)
    data["energy"] = (dims + ("transit",), energy.reshape(shape + (T_max,)),
                      {"units": "E R^2 / M", "long_name": "energy of the deviation from steady sliding"})
    data["state"] = (dims + ("snapshot", "phi"), np.array([r["state"] for r in runs]).reshape(shape + (_SNAPS, _PHI)),
                     {"long_name": "node state over the last 2 transits", "flag_meanings": " ".join(STATE_NAMES)})
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
            sweep.append(_summary(integrate(p, 128, transits=T_sweep, beta2=0.9, initial=perturbed_steady(p, 128))))
    data.update(_stack(sweep, (len(xis), len(omegas)), ("xi", "omega"), prefix="sweep_"))
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


#: Initial conditions of `initial_condition_data`: (label, seeded mode); amplitude 0.1 delta + 1e-3 noise.
SEEDS = (("mode 2", 2), ("mode 3", 3))


def initial_condition_data(quick: bool = False) -> xr.Dataset:
    """Case 2 of section 3.1 (``f = 0.7``, ``delta = 0.001``, ``Omega = 50`` rad/s), paper's scheme
    ``beta2 = 0.9``: steady sliding perturbed by ``0.1 delta cos(n theta)`` (``n = 2`` or 3) plus
    white noise ``1e-3 delta`` (so no symmetry is imposed), on several grids."""
    f, d, om = CASES[1]
    p = BrakeParams.from_physical(om, d, f)
    grids, T = ((128, 192), 400) if quick else ((128, 192, 256), 800)
    runs = [_summary(integrate(p, N, transits=T, beta2=0.9, initial=perturbed_steady(p, N, 0.1, mode, noise=1e-3)))
            for N in grids for _, mode in SEEDS]
    shape, dims = (len(grids), len(SEEDS)), ("grid", "seed")
    data = _stack(runs, shape, dims)
    data["energy"] = (dims + ("transit",), _pad([r["energy"] for r in runs]).reshape(shape + (-1,)),
                      {"units": "E R^2 / M", "long_name": "energy of the deviation from steady sliding"})
    data["state"] = (dims + ("snapshot", "phi"), np.array([r["state"] for r in runs]).reshape(shape + (_SNAPS, _PHI)),
                     {"long_name": "node state over the last 2 transits", "flag_meanings": " ".join(STATE_NAMES)})
    coords = {"grid": list(grids), "seed": [s for s, _ in SEEDS], "seed_mode": ("seed", [m for _, m in SEEDS]),
              "kind": list(STATE_NAMES), "transit": np.arange(data["energy"][1].shape[-1])}
    return xr.Dataset(data, coords=coords, attrs={
        "quick": int(quick), "transits": T, "beta2": 0.9, "friction": f, "delta": p.delta, "omega": om,
        "gamma": p.gamma, "initial": "steady sliding + 0.1 delta cos(n theta) + 1e-3 delta white noise (seed 0)"})


def _all(values) -> bool:
    return bool(np.all(np.asarray(values)))


def check_regimes(ds: xr.Dataset) -> list[Check]:
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
              _all(sign) and _all(ssign[ds["sweep_fraction"].sel(kind="stick").values > 0.005]),
              f"c/sqrt(a) in [{float(ds['c_over_sqrt_a'].min()):.3f}, {float(ds['c_over_sqrt_a'].max()):.3f}]",
              "sign(c) = sign(D) < 0", "against the shaft for xi = 1.5, nu = 0.3"),
        Check("case 1 (f = 0.2, delta = 0.004, Omega = 1 rad/s): stick-slip, no separation, as the FE",
              _all(c1 == "stick-slip"), f"{c1.tolist()}", "stick-slip with both schemes",
              "mode number differs: " + "; ".join(found[:1])),
        Check("separation needs a small separation number S = g delta sqrt(a)/|D|",
              _all(sep.values[S.values > 5] == 0) and _all(sep.values[S.values < 0.5] > 0.01),
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


def check_initial_condition(ds: xr.Dataset) -> list[Check]:
    """Two perturbations, two limit regimes, on every grid."""
    n, E, spread = ds["n_fft"].values, ds["energy_late"].values, ds["energy_spread"].values
    differs = (n[:, 0] != n[:, 1]) & (np.abs(E[:, 0] - E[:, 1]) > 10 * spread.max(axis=1))
    return [
        Check("the limit regime depends on the initial condition (same parameters)", _all(differs),
              f"dominant mode {n.tolist()}, late energy {np.round(E, 4).tolist()}", "different on every grid",
              "paper section 3.1: 'the limit regime may be different for two different initial conditions'"),
        Check("each limit regime is statistically steady (energy of the last two quarters)",
              bool(np.all(spread <= 0.01 * np.abs(E))), f"max relative change {float(np.max(spread / np.abs(E))):.2e}",
              "<= 1e-2", "a limit regime, not a transient"),
        Check("each seed selects the same regime on every grid", _all(n == n[:1]),
              f"dominant mode per grid {n.tolist()}", "the same in every row", "robust to the mesh"),
    ]

"""Figure data of the FE runs of section 3.1 (Figures 7-10) and a regime map.

One dataset per run set; plots (`fem.plots`) and checks (`fem.figure_checks`) read only the
dataset. Each case is run on the default steel ring (``R = 0.1 m``, ``R* = 0.15 m``,
``E = 2.1e11 Pa``, ``rho = 7850 kg/m^3``, ``nu = 0.3``; the paper gives no geometry for this
section) from FE steady sliding perturbed by white noise ``1e-3 delta`` and from a seeded
mode (``0.1 delta cos n theta`` plus the same noise), with the paper's scheme
``beta2 = 0.9``. Budgets are in P-wave transits ``2 pi R / c_p``.

* `fig7_data`: ``f = 0.2, delta = 0.004, Omega = 1 rad/s`` (paper: stick-slip, 4 modes);
* `fig8_data`: ``f = 2, delta = 0.004, Omega = 80 rad/s`` (paper: stick-separation, 2 modes);
* `fig9_data`: ``f = 0.7, delta = 0.001, Omega = 50 rad/s`` (paper: stick-slip-separation,
  8 modes; Figure 9 its radial displacement, Figure 10 its contact pressure: one run set);
* `regime_map_data`: ``f = 0.7``, ``d = 0.1 mm``, regimes over ``xi = R*/R`` and ``Omega``.
"""

from __future__ import annotations

import time

import numpy as np
import xarray as xr

from ...errors import ParameterError
from ..reduced.params import BrakeParams
from ..ring_figures import CASES, PAPER_REGIMES
from ...contact import STATE_NAMES
from .classify import classify_fem, contact_residuals
from .figure_checks import check_fig7, check_fig8, check_fig9, check_fig10, check_regime_map
from .halfspace import slip_wave_rate
from .modes import fem_growth_rates
from .plots import plot_fig7, plot_fig8, plot_fig9, plot_fig10, plot_regime_map
from .run import integrate_fem, perturbed_steady
from .scheme import FemScheme

__all__ = ["fig7_data", "fig8_data", "fig9_data", "regime_map_data", "case_data", "MESHES", "plot_fig7",
           "plot_fig8", "plot_fig9", "plot_fig10", "plot_regime_map", "check_fig7", "check_fig8", "check_fig9",
           "check_fig10", "check_regime_map"]

#: (n_theta, n_r, transits per run) of the quick and full modes.
MESHES = {True: (256, 16, 300), False: (512, 32, 400)}
_SNAPS = 64  # tail snapshots kept (2 transits at 32 per transit)
_SCALARS = ("n", "n_fft", "n_zones", "n_fft_P", "c_over_cp", "c_P_over_cp", "stationary", "residual",
            "energy_mean", "energy_cv", "p_max_over_pe", "p_mean_over_pe")
_RESIDUALS = ("P_min", "gap_min", "complementarity", "coulomb", "stick_speed", "slip_law", "slip_direction")


def _params(case: int) -> BrakeParams:
    f, d, om = CASES[case]
    return BrakeParams.from_physical(om, d, f)


def _one_run(p, N, nr, T, seed):
    s = FemScheme(p, N, nr, 0.9)
    ini = perturbed_steady(s) if seed is None else perturbed_steady(s, 0.1, seed, noise=1e-3)
    t0 = time.perf_counter()
    run = integrate_fem(p, N, nr, transits=T, initial=ini)
    seconds = time.perf_counter() - t0
    res, resid = classify_fem(run), contact_residuals(run)
    tr = run.t / s.transit_time
    per = [(tr >= k) & (tr < k + 1) for k in range(int(np.floor(tr[-1])))]
    pe = s.steady.pressure.mean()
    return {"regime": res.regime, **{k: getattr(res, k) for k in _SCALARS}, **{k: resid[k] for k in _RESIDUALS},
            "fraction": [res.fractions[k] for k in STATE_NAMES], "seconds": seconds,
            "energy": np.array([run.energy[m].mean() for m in per]),
            "fraction_history": np.array([run.fractions[m].mean(axis=0) for m in per]),
            "U": run.U[-_SNAPS:] / p.delta - 1.0, "Vd": run.Vd[-_SNAPS:], "P": run.P[-_SNAPS:] / pe,
            "state": run.state[-_SNAPS:], "snap_t": run.snap_t[-_SNAPS:] / s.transit_time}


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
                     {"units": units} if units else {"flag_meanings": " ".join(STATE_NAMES)})
    data["U"][2]["long_name"] = "u_r(R)/d - 1 (radial displacement beyond the mismatch)"
    g = fem_growth_rates(p, s.system, np.arange(1, N // 2 + 1))
    data["growth"] = ("mode", g.growth_rate * s.transit_time, {"units": "1/transit", "long_name": "FE flutter"})
    data["growth_discrete"] = ("mode", g.discrete(s.dt, 0.9).real.max(axis=1) * s.transit_time,
                               {"units": "1/transit", "long_name": "fully discrete (beta2 = 0.9)"})
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
             "quick": int(bool(quick)), "geometry": "steel ring R = 0.1 m, R* = 0.15 m, E = 2.1e11 Pa, "
             "rho = 7850 kg/m^3, nu = 0.3", "initial": "FE steady sliding + 1e-3 delta white noise (seed 0), "
             "or + 0.1 delta cos(n theta) + 1e-3 delta noise"}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def fig7_data(quick: bool = False) -> xr.Dataset:
    """Case 1 (``f = 0.2``): from noise and from a seeded mode 4."""
    return case_data(0, (None, 4), quick)


def fig8_data(quick: bool = False) -> xr.Dataset:
    """Case 3 (``f = 2``): from noise and from a seeded mode 2."""
    return case_data(2, (None, 2), quick)


def fig9_data(quick: bool = False) -> xr.Dataset:
    """Case 2 (``f = 0.7``), for Figures 9 and 10: from noise and from seeded modes 8 and 4."""
    return case_data(1, (None, 8, 4), quick)


def regime_map_data(quick: bool = False) -> xr.Dataset:
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

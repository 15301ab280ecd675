"""Checks of the FE figures (7-10, regime map): what each figure verifies, measured in its dataset.

Every case dataset is checked for (i) the static Lamé agreement of FE steady sliding on the
run's mesh, (ii) the contact and Coulomb residuals at every recorded node and step, (iii)
the instability of steady sliding, and then for the paper's claim (regime name, number of
modes), with the measured numbers in the `Check` whatever the verdict.
"""

from __future__ import annotations

import numpy as np

from ...figures import Check
from ...contact import count_zones
from ...contact import SEPARATION

__all__ = ["check_fig7", "check_fig8", "check_fig9", "check_fig10", "check_regime_map", "common_checks"]


def _runs(ds, key, fmt="{}"):
    return ", ".join(f"{r}: {fmt.format(v)}" for r, v in zip(ds["run"].values, ds[key].values))


def _sep_zones(ds) -> np.ndarray:
    """Median number of separation zones per snapshot, per run."""
    return np.array([np.median([count_zones(s == SEPARATION, 1) for s in st]) for st in ds["state"].values])


def common_checks(ds) -> list[Check]:
    """Lamé agreement, contact residuals, instability of steady sliding."""
    lame = max(ds.attrs["lame_error_u"], ds.attrs["lame_error_v"], ds.attrs["lame_error_p"])
    bad = {k: max(0.0, float(v)) for k, v in (
        ("p < 0", -ds["P_min"].min()), ("gap < 0", -ds["gap_min"].min()),
        ("p gap", ds["complementarity"].max()), ("|q| - f p", ds["coulomb"].max()),
        ("stick |1 - w|", ds["stick_speed"].max()), ("slip |q - f p sign(1 - w)|", ds["slip_law"].max()),
        ("friction along the slip", -ds["slip_direction"].min()))}
    stick = ds["fraction"].sel(kind="stick")
    return [
        Check("FE steady sliding on this mesh matches the Lamé solution (eq. [11] corrected)", lame < 1e-3,
              f"max relative error u {ds.attrs['lame_error_u']:.2e}, v {ds.attrs['lame_error_v']:.2e}, "
              f"p {ds.attrs['lame_error_p']:.2e} (p_e = {ds.attrs['p_e']:.4g} E)", "< 1e-3 (order 2 in the mesh)",
              f"mesh {ds.attrs['mesh']}"),
        Check("contact and Coulomb's law hold at every recorded node and step", all(v <= 1e-9 for v in bad.values()),
              ", ".join(f"{k}: {v:.1e}" for k, v in bad.items()), "all violations <= 1e-9 (relative to p_e, d, 1)",
              "lambda_n >= 0, gap >= 0, lambda_n gap = 0, |q| <= f p, stick: w = 1, slip: q = f p sign(1 - w)"),
        Check("steady sliding is unstable: stick zones appear in every run", bool(stick.min() > 0.005),
              ", ".join(f"{r}: stick {float(v):.3f}" for r, v in zip(ds["run"].values, stick.values)), "> 0.005",
              f"flutter: fastest discrete mode n = {int(ds['growth_discrete'].idxmax())} "
              f"({float(ds['growth_discrete'].max()):.2f} per transit, beta2 = 0.9)"),
    ]


def check_fig7(ds) -> list[Check]:
    """Case 1 (f = 0.2): stick-slip wave with 4 modes."""
    reg, nz = ds["regime"].values, ds["n_zones"].values
    seeded = ds.sel(run="mode 4")
    return common_checks(ds) + [
        Check("stick-slip (no separation) from every initial condition, as the paper's FE",
              bool(np.all(reg == "stick-slip")), _runs(ds, "regime"), "stick-slip", claim=True),
        Check("the 4-mode stick-slip wave of Figure 7 is a limit regime (stationary travelling wave)",
              bool(int(seeded["n_zones"]) == 4 and bool(seeded["stationary"])),
              f"seeded mode 4: {int(seeded['n_zones'])} stick zones, stationary {bool(seeded['stationary'])}, "
              f"c = {float(seeded['c_over_cp']):.3f} c_p/R", "4 stick zones, stationary",
              f"time per run: {_runs(ds, 'seconds', '{:.0f} s')}", claim=True),
        Check("the limit regime depends on the initial condition (paper, section 3.1)", bool(len(set(nz)) > 1),
              f"stick zones {_runs(ds, 'n_zones')}", "different mode numbers",
              "noise selects the fastest-growing discrete mode of the mesh", claim=True),
        Check("the 4-mode wave runs against the shaft, as the linear flutter wave of the lowest branch",
              bool(float(seeded["c_over_cp"]) < 0), f"c / (c_p/R): {_runs(ds, 'c_over_cp', '{:.3f}')}",
              "c < 0 for the 4-mode wave", "other waves may run either way (higher radial branches)"),
    ]


def check_fig8(ds) -> list[Check]:
    """Case 3 (f = 2): stick-separation wave with 2 modes; f > 1 makes steady sliding ill-posed."""
    fr = ds["fraction"]
    sep = _sep_zones(ds)
    N = ds.sizes["theta"]
    hs = ds.attrs["halfspace_rate_per_transit_per_mode"]
    ns = [N // 16, N // 8]
    per_n = [float(ds["growth"].sel(mode=n)) / n for n in ns]
    return common_checks(ds) + [
        Check("stick-separation is reached: almost no slip (< 1 % of the nodes), separation present (paper)",
              bool(np.any((fr.sel(kind="slip") < 0.01) & (fr.sel(kind="separation") > 0.01))),
              ", ".join(f"{r}: {g} (slip {float(a):.3f}, separation {float(b):.3f})" for r, g, a, b in zip(
                  ds["run"].values, ds["regime"].values, fr.sel(kind="slip").values,
                  fr.sel(kind="separation").values)), "slip < 0.01, separation > 0.01 in some run",
              "the limit regime depends on the initial condition", claim=True),
        Check("2 modes (paper: two separation pulses around the ring)", bool(np.any(sep == 2)),
              "median separation zones per snapshot: " + ", ".join(f"{r}: {v:g}" for r, v in
                                                                     zip(ds["run"].values, sep)), "2", claim=True),
        Check("f = 2 > 1: steady sliding is ill-posed (growth proportional to the wavenumber)",
              bool(hs > 0 and all(0.85 < g / hs < 1.2 for g in per_n)),
              f"FE growth / n at n = {ns[0]}, {ns[1]}: {per_n[0]:.3f}, {per_n[1]:.3f} per transit; half-space slip "
              f"wave {hs:.3f} per transit per mode", "ratios in (0.85, 1.2)",
              f"fastest discrete mode n = {int(ds['growth_discrete'].idxmax())} of {N // 2}: the mesh and the "
              "numerical damping select the wavelength, so the mode number is not mesh-converged"),
    ]


def check_fig9(ds) -> list[Check]:
    """Case 2 (f = 0.7), radial displacement: stick-slip-separation wave with 8 modes, propagating."""
    reg = ds["regime"].values
    return common_checks(ds) + [
        Check("stick-slip-separation from every initial condition (paper)",
              bool(np.all(reg == "stick-slip-separation")), _runs(ds, "regime"), "stick-slip-separation", claim=True),
        Check("8 modes (paper)", bool(np.any(ds["n_zones"].values == 8)),
              f"stick zones per snapshot (median): {_runs(ds, 'n_zones')}; dominant pressure mode: "
              f"{_runs(ds, 'n_fft_P')}", "8 in some run", f"time per run: {_runs(ds, 'seconds', '{:.0f} s')}", claim=True),
        Check("the radial displacement pattern propagates (Figure 9)",
              bool(np.all(np.abs(ds["c_P_over_cp"].values) > 0.05)), _runs(ds, "c_P_over_cp", "{:.3f}"),
              "|c| > 0.05 c_p/R", "speed of the pressure pattern; separation pulses ride on it"),
    ]


def check_fig10(ds) -> list[Check]:
    """Case 2 (f = 0.7), contact pressure: zero in separation zones, mean p_e."""
    P, st = ds["P"].values, ds["state"].values
    sep = st == SEPARATION
    return [
        Check("the contact pressure vanishes exactly in the separation zones and is positive elsewhere",
              bool(np.all(P[sep] == 0.0) and np.all(P[~sep] > 0.0) and sep.any()),
              f"{int(sep.sum())} separated node-snapshots, max p there {float(P[sep].max()) if sep.any() else 0:.1e}; "
              f"min p in contact {float(P[~sep].min()):.2e} p_e", "0 and > 0"),
        Check("the mean contact pressure stays at the steady p_e (the mean load is set by the mismatch)",
              bool(np.all(np.abs(ds["p_mean_over_pe"].values - 1.0) < 0.05)), _runs(ds, "p_mean_over_pe", "{:.3f}"),
              "1 +- 0.05", "largest p / p_e over the last transits (no paper value): "
              + _runs(ds, "p_max_over_pe", "{:.2f}")),
    ]


def check_regime_map(ds) -> list[Check]:
    """Regimes over xi and Omega (f = 0.7, d = 0.1 mm)."""
    sep = ds["fraction"].sel(kind="separation")
    stick = ds["fraction"].sel(kind="stick")
    grows = bool(np.all(sep.isel(omega=-1).values >= sep.isel(omega=0).values))
    return [
        Check("stick zones in every run (steady sliding unstable for every xi and Omega)",
              bool(stick.min() > 0.005), f"min stick fraction {float(stick.min()):.3f}", "> 0.005"),
        Check("separation grows as kappa = d sqrt(E/rho)/(R^2 Omega) decreases (paper: small mismatch, "
              "high speed)", grows, f"separation fraction {np.round(sep.values, 3).tolist()} (rows xi "
              f"{ds['xi'].values.tolist()}, columns Omega {ds['omega'].values.tolist()} rad/s)",
              "largest Omega >= smallest Omega, every xi",
              "regimes: " + "; ".join(f"xi={x:g}: " + ", ".join(str(r) for r in ds['regime'].sel(xi=x).values)
                                      for x in ds["xi"].values)),
    ]

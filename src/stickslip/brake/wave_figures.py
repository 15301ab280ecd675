"""Figures 5, 6, 11 and 12 of the paper: travelling waves of the reduced model.

The paper prints no parameters for these figures (except mode 8 for Figure 12). Defaults:
the steel ring of `PhysicalParams` (``R = 0.1 m``, ``R* = 0.15 m``, ``E = 2.1e11 Pa``,
``rho = 7850 kg/m^3``, ``nu = 0.3``). The waves depend on ``delta`` and ``Omega`` only
through ``delta/sqrt(gamma) = d/(R^2 Omega sqrt(rho/E))`` (`wave_zones.Scaling`); the
regimes of the principal family of ``n`` modes are set by that number. The cases below
were chosen from the event maps of `continue_waves` (see ``docs/theory/brake-waves.md``):

* Figure 5, stick-slip: ``f = 0.2``, ``d = 0.1 mm``, ``n = 4``, ``Omega = 50..200 rad/s``
  (``delta/sqrt(gamma)`` from 1.03 to 0.26; reverse slip appears below 0.143);
* Figure 6, stick-slip-separation: ``f = 0.7``, ``d = 1 um``, ``n = 4``,
  ``Omega = 40..100 rad/s`` (``delta/sqrt(gamma)`` from 0.013 to 0.005, below the death
  of reverse slip at 0.0170);
* Figure 11: ``f = 0.7``, ``n = 4``, ``Omega = 50 rad/s``, ``d`` from 10 um down to
  0.25 um (continuation in the mismatch);
* Figure 12: ``f = 0.2``, ``d = 10 um``, ``Omega = 100 rad/s``, ``n = 8``: a
  stick-slip-separation-reverse-slip wave.

Each ``figN_data(quick)`` returns a Dataset; ``plot_figN(ds, path)`` draws it and
``check_figN(ds)`` returns the `Check` list of what the figure verifies.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..figures import Check
from .reduced.params import BrakeParams
from .waves.checks import energy_balance, integrate_wave
from .waves.continuation import continue_waves
from .waves.shoot import stick_exit_orbit
from .waves.zones import Scaling, ZoneFlows
from .wave_plots import plot_fig5, plot_fig6, plot_fig11, plot_fig12
from .waves.solve import travelling_wave

__all__ = ["fig5_data", "fig6_data", "fig11_data", "fig12_data", "plot_fig5", "plot_fig6", "plot_fig11",
           "plot_fig12", "check_fig5", "check_fig6", "check_fig11", "check_fig12", "FIG5", "FIG6", "FIG11",
           "FIG12"]

FIG5 = {"friction": 0.2, "mismatch": 1e-4, "modes": 4, "omegas": (50.0, 100.0, 150.0, 200.0)}
FIG6 = {"friction": 0.7, "mismatch": 1e-6, "modes": 4, "omegas": (40.0, 60.0, 80.0, 100.0)}
FIG11 = {"friction": 0.7, "omega": 50.0, "modes": 4, "mismatch": (1e-5, 2.5e-7)}
FIG12 = {"friction": 0.2, "mismatch": 1e-5, "omega": 100.0, "modes": 8}

_PROFILE = ("U", "dU", "V", "dV", "P", "Q", "slip_velocity", "zone")


def _diagnostics(wave) -> dict:
    """Scalars stored per case: verification margins, independent checks."""
    sc = Scaling(wave.params)
    orbit = stick_exit_orbit(ZoneFlows(sc.coefficients, wave.params.friction, sc.delta, wave.x[0]),
                             3 * wave.period)
    integ, energy = integrate_wave(wave), energy_balance(wave)
    return {"c": wave.c, "c_si": wave.wave_speed_si, "c_internal": wave.x[0],
            "delta_internal": sc.delta, "sonic_ratio": abs(wave.c) / np.sqrt(wave.params.coefficients().a),
            "D_sign": float(np.sign(wave.params.coefficients().D)),
            "residual": wave.residual, "min_margin": min(wave.margins.values()),
            "return_map_mismatch": abs(orbit.period - wave.period) / wave.period,
            "ivp_profile_error": integ["profile_error"], "ivp_switching": integ["switching"],
            "ivp_periodicity": integ["periodicity"], "energy_residual": energy["residual"],
            "ring_work": energy["ring_work"], "shaft_work": energy["shaft_work"],
            "impact_dissipation": energy["impacts"], "sliding_dissipation": energy["sliding"],
            "stick_fraction": sum(z.length for z in wave.zones if z.kind == "stick") / wave.period,
            "separation_fraction": sum(z.length for z in wave.zones if z.kind == "separation") / wave.period,
            "reverse_fraction": sum(z.length for z in wave.zones if z.kind == "reverse-slip") / wave.period,
            "slip_fraction": sum(z.length for z in wave.zones if z.kind == "slip") / wave.period,
            "n_impacts": len(wave.impacts())}


def _cases(waves, labels, label_name, num) -> xr.Dataset:
    m = max(len(w.zones) for w in waves)
    diag = [_diagnostics(w) for w in waves]
    data = {}
    for key in diag[0]:
        data[key] = ("case", [d[key] for d in diag])
    phis = np.array([np.linspace(0.0, w.period, num) for w in waves])
    profs = [w.evaluate(p) for w, p in zip(waves, phis)]
    units = {"U": "R", "dU": "R/rad", "V": "R", "dV": "R/rad", "P": "E/M", "Q": "E/M", "slip_velocity": "1",
             "zone": "1"}
    for k in _PROFILE:
        data[k] = (("case", "sample"), np.array([p[k] for p in profs]), {"units": units[k]})
    data["phi"] = (("case", "sample"), phis, {"units": "rad", "long_name": "phi = theta - c t"})
    pad = lambda rows, fill: [r + [fill] * (m - len(r)) for r in rows]  # noqa: E731
    data["zone_kind"] = (("case", "zone"), pad([[z.kind for z in w.zones] for w in waves], ""))
    data["zone_start"] = (("case", "zone"), pad([[z.start for z in w.zones] for w in waves], np.nan))
    data["zone_end"] = (("case", "zone"), pad([[z.end for z in w.zones] for w in waves], np.nan))
    data["regime"] = ("case", [w.regime for w in waves])
    data["structure"] = ("case", [w.structure for w in waves])
    data["delta"] = ("case", [w.params.delta for w in waves])
    data["gamma"] = ("case", [w.params.gamma for w in waves])
    data["V_e"] = ("case", [w.params.friction * w.params.delta * w.params.coefficients().g
                            / w.params.coefficients().h for w in waves], {"units": "R"})
    ds = xr.Dataset(data, coords={"case": np.arange(len(waves)), label_name: ("case", list(labels))})
    p = waves[0].params
    ds.attrs.update({"friction": p.friction, "xi": p.xi, "nu": p.nu, "modes": waves[0].n,
                     "geometry": "steel ring R = 0.1 m, R* = 0.15 m, E = 2.1e11 Pa, rho = 7850 kg/m^3, nu = 0.3"})
    return ds


def _waves_over_omega(cfg, regime, quick):
    omegas = cfg["omegas"][::2] if quick else cfg["omegas"]
    waves = [travelling_wave(BrakeParams.from_physical(om, cfg["mismatch"], cfg["friction"]), cfg["modes"],
                             regime=regime) for om in omegas]
    return waves, omegas


def fig5_data(quick: bool = False) -> xr.Dataset:
    """Stick-slip waves (``n = 4``) for several shaft speeds: phase diagrams ``(V, V')``."""
    waves, omegas = _waves_over_omega(FIG5, "stick-slip", quick)
    ds = _cases(waves, omegas, "omega", 400 if quick else 1500)
    ds["omega"].attrs["units"] = "rad/s"
    ds.attrs["mismatch"] = FIG5["mismatch"]
    return ds


def fig6_data(quick: bool = False) -> xr.Dataset:
    """Stick-slip-separation waves (``n = 4``) for several shaft speeds: ``(U, U')`` and ``(V, V')``."""
    waves, omegas = _waves_over_omega(FIG6, "stick-slip-separation", quick)
    ds = _cases(waves, omegas, "omega", 400 if quick else 1500)
    ds["omega"].attrs["units"] = "rad/s"
    ds.attrs["mismatch"] = FIG6["mismatch"]
    return ds


def fig12_data(quick: bool = False) -> xr.Dataset:
    """A mode-8 wave with reverse slip (overshoot): phase plane ``(V, V')``."""
    p = BrakeParams.from_physical(FIG12["omega"], FIG12["mismatch"], FIG12["friction"])
    wave = travelling_wave(p, FIG12["modes"], regime="stick-slip-separation-reverse-slip")
    ds = _cases([wave], [FIG12["omega"]], "omega", 1000 if quick else 4000)
    ds.attrs["mismatch"] = FIG12["mismatch"]
    return ds


def fig11_data(quick: bool = False) -> xr.Dataset:
    """Continuation in the mismatch ``d``: ``U(phi)`` at several ``d`` and the switching points."""
    d0, d1 = FIG11["mismatch"]
    R = 0.1
    p0 = BrakeParams.from_physical(FIG11["omega"], d0, FIG11["friction"])
    branch = continue_waves(p0, FIG11["modes"], "delta", d1 / R, num=25 if quick else 60, spacing="log")
    ds = branch.to_xarray()
    ds = ds.assign_coords(mismatch=("point", ds["delta"].values * R, {"units": "m"}))
    # profiles at a few points, one per zone sequence met, plus the two ends
    seqs = [str(s) for s in ds["structure"].values]
    pick = sorted({0, len(seqs) - 1} | {seqs.index(s) for s in seqs} |
                  {len(seqs) - 1 - seqs[::-1].index(s) for s in seqs})
    num = 400 if quick else 1200
    profs = [branch.waves[i].evaluate(np.linspace(0.0, branch.waves[i].period, num)) for i in pick]
    ds["profile_point"] = ("profile", pick)
    ds["profile_U"] = (("profile", "sample"), np.array([q["U"] for q in profs]), {"units": "R"})
    ds["profile_zone"] = (("profile", "sample"), np.array([q["zone"] for q in profs]))
    ds["profile_phi"] = ("sample", np.linspace(0.0, branch.waves[0].period, num), {"units": "rad"})
    ds["event_parameter"] = ("event", [e.parameter for e in branch.events])
    ds["event_kind"] = ("event", [e.kind for e in branch.events])
    ds["event_zones"] = ("event", ["+".join(e.zones) for e in branch.events])
    ds["event_after"] = ("event", [e.after for e in branch.events])
    ds["event_before"] = ("event", [e.before for e in branch.events])
    ds["event_cause"] = ("event", [e.cause for e in branch.events])
    # independent direct solves at three points of the branch
    idx = [len(seqs) // 4, len(seqs) // 2, (3 * len(seqs)) // 4]
    direct = []
    for i in idx:
        w = branch.waves[i]
        cands = [v for v in [travelling_wave(w.params, w.n, guess=w.c)] if v.structure == w.structure]
        direct.append(cands[0].c if cands else np.nan)
    ds["direct_point"] = ("check", idx)
    ds["direct_c"] = ("check", direct)
    ds["sonic_speed"] = ("point", [np.sqrt(w.params.coefficients().a) for w in branch.waves])
    ds.attrs.update({"friction": FIG11["friction"], "omega": FIG11["omega"], "modes": FIG11["modes"],
                     "stopped": branch.stopped, "min_margin": min(min(w.margins.values()) for w in branch.waves),
                     "max_residual": max(w.residual for w in branch.waves)})
    return ds


# --- checks --------------------------------------------------------------------------------
def _common(ds, label) -> list[Check]:
    def worst(key):
        return float(np.max(np.abs(ds[key].values)))
    return [
        Check(f"{label}: multiple-shooting residual", worst("residual") < 1e-9, f"{worst('residual'):.2e}",
              "< 1e-9", "continuity, jump and switching conditions, periodicity"),
        Check(f"{label}: inequalities of [17]-[20] on a 401-point grid per zone", float(ds["min_margin"].min()) > -1e-8,
              f"min margin {float(ds['min_margin'].min()):.2e}", ">= -1e-8",
              "P > 0 in contact, |Q| < fP in stick, slip direction, U > delta in separation, impulses"),
        Check(f"{label}: closed forms agree with solve_ivp (DOP853) across the zones",
              worst("ivp_profile_error") < 1e-6 and worst("ivp_switching") < 1e-8 and worst("ivp_periodicity") < 1e-8,
              f"profile {worst('ivp_profile_error'):.1e}, switching {worst('ivp_switching'):.1e}, "
              f"periodicity {worst('ivp_periodicity'):.1e}", "< 1e-6, 1e-8, 1e-8",
              "time-order integration with the impact law applied at landings"),
        Check(f"{label}: energy balance over a period", worst("energy_residual") < 1e-9 and worst("ring_work") < 1e-9,
              f"|shaft - sliding - impacts|/shaft {worst('energy_residual'):.1e}, ring work {worst('ring_work'):.1e}",
              "< 1e-9", "net work of the contact forces on the ring vanishes; shaft work = dissipation"),
        Check(f"{label}: stick-exit return map gives the same wave", worst("return_map_mismatch") < 1e-8,
              f"|T(c) - 2pi/n| n/2pi = {worst('return_map_mismatch'):.1e}", "< 1e-8",
              "independent route: event-driven closed-form orbit from the stick exit"),
        Check(f"{label}: waves run in the direction of sign(D), faster than sqrt(a)",
              bool(np.all(np.sign(ds["c"].values) == ds["D_sign"].values) and np.all(ds["sonic_ratio"] > 1)),
              f"sign(c) = {np.sign(ds['c'].values).tolist()}, |c|/sqrt(a) in "
              f"[{float(ds['sonic_ratio'].min()):.4f}, {float(ds['sonic_ratio'].max()):.4f}]",
              "sign(D), > 1", "as the flutter waves of steady sliding"),
    ]


def check_fig5(ds: xr.Dataset) -> list[Check]:
    regimes = sorted(set(str(r) for r in ds["regime"].values))
    cw = ds["c"].values * ds["omega"].values
    amp = np.abs(ds["dV"]).max("sample").values / ds["omega"].values
    return _common(ds, "Fig. 5") + [
        Check("Fig. 5: every wave is a stick-slip wave", regimes == ["stick-slip"], str(regimes), "['stick-slip']"),
        Check("Fig. 5: self-similar in Omega: c Omega and max|V'|/Omega do not depend on Omega",
              bool(np.ptp(cw) < 1e-8 * abs(cw[0]) and np.ptp(amp) < 1e-8 * amp[0]),
              f"c Omega = {cw[0]:.8g} rad/s (spread {np.ptp(cw):.1e}), max|V'|/Omega spread {np.ptp(amp) / amp[0]:.1e}",
              "spread < 1e-8", "stick-slip waves depend on delta/sqrt(gamma) only through V_e"),
    ]


def check_fig6(ds: xr.Dataset) -> list[Check]:
    regimes = sorted(set(str(r) for r in ds["regime"].values))
    return _common(ds, "Fig. 6") + [
        Check("Fig. 6: every wave is a stick-slip-separation wave", regimes == ["stick-slip-separation"],
              str(regimes), "['stick-slip-separation']"),
        Check("Fig. 6: U' jumps back to 0 at the end of separation (impact), energy lost > 0",
              bool(np.all(ds["n_impacts"] >= 1) and np.all(ds["impact_dissipation"] > 0)),
              f"impacts per period {ds['n_impacts'].values.tolist()}, impact dissipation / shaft work "
              f"{np.round(ds['impact_dissipation'].values / ds['shaft_work'].values, 4).tolist()}", "> 0"),
    ]


def check_fig12(ds: xr.Dataset) -> list[Check]:
    w = ds["slip_velocity"].values
    return _common(ds, "Fig. 12") + [
        Check("Fig. 12: mode-8 wave with reverse slip (overshoot: V_t > 1 somewhere)",
              bool(int(ds.attrs["modes"]) == 8 and "reverse-slip" in str(ds["structure"].values[0]) and w.min() < 0),
              f"{ds['structure'].values[0]}, min(1 - V_t) = {w.min():.4g}", "n = 8, reverse-slip zone, min < 0"),
    ]


def check_fig11(ds: xr.Dataset) -> list[Check]:
    kinds = [str(k) for k in ds["event_kind"].values]
    after = [str(a) for a in ds["event_after"].values]
    before = [str(b) for b in ds["event_before"].values]
    zones = [str(z) for z in ds["event_zones"].values]
    born_sep = any(k == "birth" and "separation" in z for k, z in zip(kinds, zones))
    # death of the slip zone right of the separation zone (switching points coalesce)
    slip_dies = [i for i, (k, z, b) in enumerate(zip(kinds, zones, before))
                 if k == "death" and z == "slip" and "separation|slip" in b]
    sss = "stick|slip|separation" in [str(s) for s in ds["structure"].values]
    direct = ds["direct_c"].values
    c_branch = ds["c"].values[ds["direct_point"].values]
    ok_direct = bool(np.all(np.abs(direct - c_branch) <= 1e-8 * np.abs(c_branch)))
    lengths = ds["zone_end"] - ds["zone_start"]
    return [
        Check("Fig. 11: separation is born when the pressure touches 0 inside a slip zone",
              born_sep, "; ".join(f"{k} of {z} at delta = {p:.5g}" for k, z, p in
                                  zip(kinds, zones, ds["event_parameter"].values)), "a birth of separation"),
        Check("Fig. 11: the slip zone right of separation vanishes as d decreases (switching points coalesce)",
              bool(slip_dies), f"{[before[i] + ' -> ' + after[i] for i in slip_dies]}", "a death of that slip zone"),
        Check("Fig. 11: one ends in the stick-slip-separation state", sss,
              f"last structures {sorted(set(str(s) for s in ds['structure'].values[-3:]))}", "stick|slip|separation"),
        Check("Fig. 11: continuation agrees with direct solves", ok_direct,
              f"max |c_direct - c_branch|/|c| = {float(np.nanmax(np.abs(direct - c_branch) / np.abs(c_branch))):.1e}",
              "<= 1e-8", "return-map scan + multiple shooting at three points of the branch"),
        Check("Fig. 11: every point passes the checks", float(ds.attrs["min_margin"]) > -1e-8
              and float(ds.attrs["max_residual"]) < 1e-8 and float(lengths.min()) > 0,
              f"min margin {float(ds.attrs['min_margin']):.1e}, max residual {float(ds.attrs['max_residual']):.1e}",
              ">= -1e-8, < 1e-8"),
    ]

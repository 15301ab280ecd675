"""What the travelling-wave figures (5, 6, 12) share: the diagnostics of each wave, its
profile as a dataset, the checks every wave passes, and the phase-plane plot.

Each wave is verified by its shooting residual, every inequality of [17]-[20] on a fine
grid, re-integration of the zones with `solve_ivp`, the energy balance over a period and
the stick-exit return map (an independent route to the same wave).
"""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake import BrakeParams, travelling_wave
from ...brake.waves import Scaling, ZoneFlows, energy_balance, integrate_wave, stick_exit_orbit
from .. import Check
from .paper import GEOMETRY

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["METHOD", "diagnostics", "cases_dataset", "waves_dataset", "common_checks", "phase_plot", "by_zone"]

METHOD = ("Multiple shooting with the switching points as unknowns (BOUNDSCO formulation), exact closed forms "
          "inside each zone of the corrected [15], the wave speed found by scanning the period map T(c) = 2π/n; "
          "every inequality of [17]-[20] verified on a fine grid, the zones re-integrated with solve_ivp, the "
          "energy balance over a period (shaft work = sliding + impact dissipation) closed. Steel ring R = 0.1 m, "
          "R* = 0.15 m (the paper gives no parameters; values in stickslip.figures.brake.paper).")

_PROFILE = ("U", "dU", "V", "dV", "P", "Q", "slip_velocity", "zone")


def diagnostics(wave) -> dict:
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


def cases_dataset(waves, labels, label_name, num) -> xr.Dataset:
    m = max(len(w.zones) for w in waves)
    diag = [diagnostics(w) for w in waves]
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
    padded = {"units": "rad", "comment": "NaN past the last zone of a case (cases have different numbers of zones)"}
    data["zone_start"] = (("case", "zone"), pad([[z.start for z in w.zones] for w in waves], np.nan), padded)
    data["zone_end"] = (("case", "zone"), pad([[z.end for z in w.zones] for w in waves], np.nan), padded)
    data["regime"] = ("case", [w.regime for w in waves])
    data["structure"] = ("case", [w.structure for w in waves])
    data["delta"] = ("case", [w.params.delta for w in waves])
    data["gamma"] = ("case", [w.params.gamma for w in waves])
    data["V_e"] = ("case", [w.params.friction * w.params.delta * w.params.coefficients().g
                            / w.params.coefficients().h for w in waves], {"units": "R"})
    ds = xr.Dataset(data, coords={"case": np.arange(len(waves)), label_name: ("case", list(labels))})
    p = waves[0].params
    ds.attrs.update({"friction": p.friction, "xi": p.xi, "nu": p.nu, "modes": waves[0].n,
                     "geometry": GEOMETRY})
    return ds


def waves_dataset(cfg: dict, regime: str, quick: bool, samples=(400, 1500)) -> xr.Dataset:
    """The waves of ``cfg`` (`paper`), one per shaft speed of ``cfg["omegas"]`` (every other one if
    ``quick``) or at ``cfg["omega"]``, in the given regime, as a dataset of ``samples`` points per wave."""
    omegas = tuple(cfg["omegas"][::2] if quick else cfg["omegas"]) if "omegas" in cfg else (cfg["omega"],)
    waves = [travelling_wave(BrakeParams.from_physical(om, cfg["mismatch"], cfg["friction"]), cfg["modes"],
                             regime=regime) for om in omegas]
    ds = cases_dataset(waves, omegas, "omega", samples[0] if quick else samples[1])
    ds["omega"].attrs["units"] = "rad/s"
    ds.attrs["mismatch"] = cfg["mismatch"]
    return ds


# --- checks --------------------------------------------------------------------------------
def common_checks(ds, label) -> list[Check]:
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
    ]


def by_zone(ax, x, y, zone, kinds):
    for i, kind in enumerate(kinds):
        if not kind:
            continue
        sel = zone == i
        ax.plot(np.where(sel, x, np.nan), np.where(sel, y, np.nan), color=plotting.ZONE_COLOURS[kind], lw=1.4)


def phase_plot(ds, fig, pairs, title) -> Figure:
    """Phase planes ``pairs = [(x, y, x label, y label), ...]`` of every case, coloured by zone;
    with several shaft speeds each orbit is labelled with its Ω just above its top (orbits nest)."""
    from matplotlib.lines import Line2D

    fig, axes = plotting.new_figure(fig, len(pairs), size=(4.9, 4.6) if len(pairs) > 1 else (7.0, 5.2))
    shown, chords = set(), False
    for ax, (xk, yk, xl, yl) in zip(axes, pairs):
        labelled = "omega" in ds.coords and len(ds["case"]) > 1 and xk != "phi"
        orbits, labels = [], []
        for i in ds["case"].values:
            c = ds.sel(case=i)
            kinds = [str(k) for k in c["zone_kind"].values]
            x, y = c[xk].values, c[yk].values
            if xk != "phi":  # closed orbit; jumps (impacts) show as dashed chords
                ax.plot(np.append(x, x[0]), np.append(y, y[0]), color="0.6", lw=0.7, ls="--")
                jumps = np.hypot(np.diff(x) / np.ptp(x), np.diff(y) / np.ptp(y))
                chords |= bool(np.nanmax(jumps) > 0.02 or np.hypot((x[-1] - x[0]) / np.ptp(x),
                                                                   (y[-1] - y[0]) / np.ptp(y)) > 0.02)
            by_zone(ax, x, y, c["zone"].values, kinds)
            shown |= {kinds[int(z)] for z in np.unique(c["zone"].values) if 0 <= int(z) < len(kinds)}
            orbits.append((x, y))
            labels.append(f"Ω = {float(c.omega):g}")
        ax.set(xlabel=xl, ylabel=yl)
        if labelled:  # each orbit labelled beside it, off every curve (orbits nest)
            ax.margins(x=0.1, y=0.12)
            plotting.label_curves(ax, orbits, labels)
        ax.ticklabel_format(style="sci", scilimits=(-3, 3))
    handles = [Line2D([], [], color=plotting.ZONE_COLOURS[k], lw=1.4, label=k) for k in plotting.ZONE_COLOURS
               if k in shown]
    if chords:
        handles.append(Line2D([], [], color="0.6", lw=0.7, ls="--", label="jump (impact)\nor closing chord"))
    plotting.legend_beside(axes[-1], handles=handles, title="zone", title_fontsize=8)
    fig.suptitle(title + (" (Ω in rad/s)" if "omega" in ds.coords and len(ds["case"]) > 1 else ""), fontsize=10)
    return fig

"""Beyond the paper: limit cycles of the oscillator continued in the belt speed V."""

from __future__ import annotations

import math

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...friction import Coulomb, Stribeck
from ...oscillator import (Oscillator, continue_cycle, continue_from_hopf, hopf_points, simulate)
from ...oscillator.stability import damping_coefficients
from .. import Check, FigureSpec, close_check
from .common import osc_attrs, osc_from_attrs

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

STRIBECK = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.05,
                      friction=Stribeck(fs=0.6, fd=0.4, vs=0.1), damping=0.05)
DAMPED_COULOMB = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.05,
                            friction=Coulomb(fs=0.6, fd=0.4), damping=0.05)
COULOMB = DAMPED_COULOMB.replace(damping=0.0)
V_MAX = 2.0


def _branch_vars(branch, name):
    ds = branch.to_xarray().rename({"point": f"{name}_point"})
    return {f"{name}_{k}": v for k, v in ds.data_vars.items()}


def _returns_to_stick_baseline(osc: Oscillator) -> bool:
    """Independent test with plain solve_ivp: does the slip arc leaving the stick segment
    come back up to v = V? Its first velocity maximum is located as an event on the
    acceleration (a crossing of v = V itself can be missed between two steps)."""
    from scipy.integrate import solve_ivp

    m, k, c, N, V = osc.mass, osc.stiffness, osc.damping, osc.normal_force, osc.belt_speed
    fd = osc.friction.fd
    rhs = lambda t, y: [y[1], (fd * N - c * y[1] - k * y[0]) / m]
    peak = lambda t, y: rhs(t, y)[1]
    peak.terminal, peak.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 100.0), [osc.stick_limits[1], V], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=peak)
    return bool(sol.t_events[0].size and sol.y_events[0][0][1] >= V)


def _end_by_bisection(osc: Oscillator, lo: float, hi: float) -> float:
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _returns_to_stick_baseline(osc.replace(belt_speed=mid)) else (lo, mid)
    return 0.5 * (lo + hi)


def compute(quick: bool) -> xr.Dataset:
    opts = dict(step=0.02, max_step=0.08 if quick else 0.04)
    stick_slip = continue_cycle(STRIBECK, V_MAX, **opts)
    hopf = hopf_points(STRIBECK, "belt_speed", 0.01, V_MAX)[0]
    slip = continue_from_hopf(STRIBECK, hopf, V_MAX, **opts)
    damped = continue_cycle(DAMPED_COULOMB, V_MAX, **opts)
    coulomb = continue_cycle(COULOMB, 1.0, step=0.05, max_step=0.2)
    graze_ss = next(e["belt_speed"] for e in stick_slip.events if e["kind"] == "grazing")
    graze_slip = next(e["belt_speed"] for e in slip.events if e["kind"] == "grazing")
    damped_end = next(e["belt_speed"] for e in damped.events if e["kind"] == "grazing")
    v_mid = 0.5 * (hopf.value + graze_ss)
    mid = STRIBECK.replace(belt_speed=v_mid)
    # bistability at v_mid: a small disturbance of steady sliding decays, the stick-slip cycle persists
    near = simulate(mid, 200.0, mid.equilibrium - 0.05, 0.0)
    far = simulate(mid, 200.0, mid.stick_limits[1], v_mid)
    ds = xr.Dataset({
        **_branch_vars(stick_slip, "ss"), **_branch_vars(slip, "slip"), **_branch_vars(damped, "dc"),
        **_branch_vars(coulomb, "c0"),
        "hopf_speed": ((), hopf.value, {"units": "m/s"}), "hopf_d3": ((), hopf.d3),
        "grazing_from_stick_slip": ((), graze_ss, {"units": "m/s"}),
        "grazing_from_slip": ((), graze_slip, {"units": "m/s"}),
        "damped_coulomb_end": ((), damped_end, {"units": "m/s"}),
        "damped_coulomb_end_baseline": ((), _end_by_bisection(DAMPED_COULOMB, 0.05, 2 * damped_end), {"units": "m/s"}),
        "bistable_speed": ((), v_mid, {"units": "m/s"}),
        "near_final_amplitude": ((), float(np.max(np.abs(near.sample(4001)[1][-400:] - mid.equilibrium)))),
        "far_final_stick_segments": ((), int(np.sum(far.modes[-6:] == 0))),
    }, attrs=osc_attrs(STRIBECK))
    return ds


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    from matplotlib.lines import Line2D

    fig, axes = plotting.new_figure(fig, 2, 1, size=(5.4, 4.6))
    for ax, name, unit in ((axes[0], "amplitude", "m"), (axes[1], "period", "s")):
        for key, label, colour in (("ss", "Stribeck, stick-slip", "tab:blue"), ("slip", "Stribeck, pure slip", "tab:red"),
                                   ("dc", "Coulomb, c > 0", "tab:green"), ("c0", "Coulomb, c = 0", "0.5")):
            p, y = ds[f"{key}_parameter_value"].values, ds[f"{key}_{name}"].values
            stable = ds[f"{key}_stable"].values.astype(bool)
            ax.plot(p, y, color=colour, lw=1.5 if stable.all() else 1.0, ls="-" if stable.all() else "--",
                    label=label + ("" if stable.all() else " (unstable)"))
        ax.axvline(float(ds.hopf_speed), color="k", lw=0.6, ls=":")
        ax.axvline(float(ds.grazing_from_stick_slip), color="tab:purple", lw=0.6, ls=":")
        ax.set_xlabel("belt speed V [m/s]"), ax.set_ylabel(f"{name} [{unit}]")
    handles, _ = axes[0].get_legend_handles_labels()
    handles += [Line2D([], [], color="k", lw=0.6, ls=":", label="Hopf point (subcritical)"),
                Line2D([], [], color="tab:purple", lw=0.6, ls=":", label="grazing of the stick-slip branch")]
    plotting.legend_beside(axes[1], handles=handles)
    fig.suptitle("Limit cycles vs belt speed: stick-slip branch, grazing, subcritical Hopf", fontsize=11)
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    osc = osc_from_attrs(ds.attrs)
    N, c, fs, fd, vs = osc.normal_force, osc.damping, osc.friction.fs, osc.friction.fd, osc.friction.vs
    v_h = vs * math.log(N * (fs - fd) / (c * vs))
    first = osc.replace(belt_speed=float(ds.slip_parameter_value[0]))
    d1, d3 = damping_coefficients(first)
    a_avg = math.sqrt(-4 * d1 / (3 * d3 * first.omega**2))
    a0 = float(ds.slip_amplitude[0])
    v = ds.c0_parameter_value.values
    r = np.hypot((fs - fd) * N / osc.stiffness, v / osc.omega)
    c0_err = float(np.max(np.abs(ds.c0_amplitude.values - r)))
    ss_mult = np.abs(ds.ss_multiplier_re.values)
    slip_mult = ds.slip_multiplier_re.values
    return [
        close_check("Hopf speed: c + N μ'(V) = 0, V_H = v_s ln(N(f_s - f_d)/(c v_s))", float(ds.hopf_speed), v_h,
                    rtol=1e-10),
        Check("Hopf is subcritical (d3 = N μ'''/6 < 0) and its cycle unstable (multiplier > 1)",
              bool(float(ds.hopf_d3) < 0 and np.all(slip_mult > 1)), f"d3 = {float(ds.hopf_d3):.4g}, "
              f"min multiplier {slip_mult.min():.6f}", "d3 < 0, all > 1"),
        close_check("small cycle amplitude vs averaging A² = -4 d1 / (3 d3 w²) near the Hopf point", a0, a_avg,
                    rtol=2e-2, detail=f"at V = {float(ds.slip_parameter_value[0]):.6g}"),
        close_check("stick-slip branch and Hopf branch end at the same grazing point",
                    float(ds.grazing_from_slip), float(ds.grazing_from_stick_slip), rtol=1e-6,
                    detail="two independent continuations meeting at a corner"),
        Check("stick-slip cycles are superstable (multiplier 0)", bool(np.all(ss_mult < 1e-9)),
              f"max |λ| = {ss_mult.max():.1e}", "< 1e-9"),
        close_check("Coulomb c = 0: amplitude = sqrt(((f_s-f_d)N/k)² + (V/w)²) along the branch", c0_err, 0.0,
                    atol=1e-12, detail=f"{v.size} points, V in [{v.min():.3g}, {v.max():.3g}]"),
        close_check("damped Coulomb branch end vs bisection with plain solve_ivp (event on the velocity peak)",
                    float(ds.damped_coulomb_end), float(ds.damped_coulomb_end_baseline), rtol=1e-6),
        Check("bistability between Hopf and grazing: small disturbance decays, stick-slip persists",
              bool(float(ds.near_final_amplitude) < 1e-3 and int(ds.far_final_stick_segments) >= 2),
              f"final amplitude {float(ds.near_final_amplitude):.1e}, stick segments {int(ds.far_final_stick_segments)}",
              f"< 1e-3 and >= 2 at V = {float(ds.bistable_speed):.4g}"),
    ]


FIGURE = FigureSpec(
    key="oscillator-bifurcation", cost=14, title="Beyond the paper — limit cycles vs belt speed",
    model="1-DOF friction oscillator, Stribeck and Coulomb with damping",
    claim="(Not in the paper.) The stick-slip cycle of a falling friction law persists up to a belt speed where "
          "it grazes the stick segment; steady sliding loses stability at a Hopf point where c + N μ'(V) = 0.",
    method="Pseudo-arclength continuation in V of the fixed point of the return map on v = 0 (Stribeck law "
           "f_s = 0.6, f_d = 0.4, v_s = 0.1, c = 0.05; Coulomb with c = 0.05 and c = 0); a second branch started "
           "at the Hopf point from the averaged amplitude; grazing located by bisection; event-driven simulations "
           "for bistability; a plain solve_ivp bisection for the end of the damped Coulomb branch.",
)

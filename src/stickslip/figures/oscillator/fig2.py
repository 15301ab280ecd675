"""Figure 2: phase diagram of the Coulomb friction oscillator (static > kinetic)."""

from __future__ import annotations

import math

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...friction import Coulomb
from ...oscillator import Oscillator, limit_cycle
from ...oscillator.baseline import solve_ivp_switches
from ...oscillator.simulate import MODE_ATTRS
from .. import Check, FigureSpec, close_check
from .common import PADDED, orbits, osc_attrs, osc_from_attrs, section_after

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

OSC = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2, friction=Coulomb(fs=0.6, fd=0.4))
# inside the equilibrium set S; between S and the cycle; outside; far outside (reverse slip); right side
STARTS = [(0.5, 0.0), (0.4, -0.25), (-0.5, 0.0), (-1.5, 0.0), (1.2, 0.0)]


def compute(quick: bool) -> xr.Dataset:
    cycle = limit_cycle(OSC)
    t_end = 4 * cycle.period
    o = orbits(OSC, STARTS, t_end, 600 if quick else 2000)
    cyc = cycle.trajectory.to_xarray(400 if quick else 1500)
    # independent check: plain solve_ivp with events, period from successive stick entries
    sw = solve_ivp_switches(OSC, *STARTS[2], 12 * cycle.period, rtol=1e-11)
    sticks = [s[0] for s in sw if s[3] == 0]
    # the orbit inside S: energy about x_e along the sampled orbit
    w2, xe = OSC.stiffness / OSC.mass, OSC.friction.fd * OSC.normal_force / OSC.stiffness
    e = 0.5 * o["v"][0] ** 2 + 0.5 * w2 * (o["x"][0] - xe) ** 2
    energy = np.nanmax(e) - np.nanmin(e)
    return xr.Dataset(
        {
            "orbit_x": (("start", "sample"), o["x"], {"units": "m", "comment": PADDED}),
            "orbit_v": (("start", "sample"), o["v"], {"units": "m/s", "comment": PADDED}),
            "orbit_mode": (("start", "sample"), o["mode"], {**MODE_ATTRS, "long_name": "contact mode on the orbit"}),
            "start_x": ("start", np.array([s[0] for s in STARTS]), {"units": "m"}),
            "start_v": ("start", np.array([s[1] for s in STARTS]), {"units": "m/s"}),
            "section_after_transient": ("start", np.array([section_after(OSC, x, v, 3 * cycle.period)
                                                          for x, v in STARTS]), {"units": "m"}),
            "x": ("t", cyc["x"].values, {"units": "m"}), "v": ("t", cyc["v"].values, {"units": "m/s"}),
            "mode": ("t", cyc["mode"].values, MODE_ATTRS),
            "period": ((), cycle.period, {"units": "s"}), "stick_time": ((), cycle.stick_time, {"units": "s"}),
            "slip_time": ((), cycle.slip_time, {"units": "s"}),
            "x_min": ((), cycle.x_min, {"units": "m"}), "x_max": ((), cycle.x_max, {"units": "m"}),
            "section_x": ((), cycle.section_x, {"units": "m"}),
            "multipliers": ("k", np.sort(np.real(cycle.floquet_multipliers))),
            "solve_ivp_period": ((), (sticks[-1] - sticks[1]) / (len(sticks) - 2), {"units": "s"}),
            "inside_energy_variation": ((), energy, {"units": "J/kg"}),
            "inside_reaches_stick": ((), int(np.any(o["mode"][0] == 0))),
        },
        coords={"t": ("t", cyc["t"].values, {"units": "s"})},
        attrs=osc_attrs(OSC),
    )


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    osc = osc_from_attrs(ds.attrs)
    fig, (ax,) = plotting.new_figure(fig, size=(9.5, 5.5))
    for i in range(ds.sizes["start"]):
        plotting.modal_line(ax, ds.orbit_x[i], ds.orbit_v[i], ds.orbit_mode[i], lw=0.8, alpha=0.7)
        ax.plot(ds.start_x[i], ds.start_v[i], "ko", ms=3, label="initial states" if i == 0 else None)
    ax.plot(ds.x, ds.v, color="k", lw=2.2, label="limit cycle")
    x_lo, x_hi = osc.stick_limits
    V = osc.belt_speed
    ax.plot([x_lo, x_hi], [V, V], color="tab:green", lw=4, alpha=0.5, label="stick segment [-x_a, x_a]")
    xe, w = osc.equilibrium, osc.omega
    th = np.linspace(0, 2 * np.pi, 200)
    ax.fill(xe + V / w * np.cos(th), V * np.sin(th), color="tab:orange", alpha=0.2, label="equilibrium set S")
    ax.plot([xe, -xe], [0, 0], "k+", ms=10, label="ellipse centres ±x_e")
    ax.set_xlabel("x [m]"), ax.set_ylabel("dx/dt [m/s]")
    ax.set_title("Fig. 2 — Coulomb oscillator (f_s = 0.6, f_d = 0.4): stick-slip limit cycle")
    handles, labels = ax.get_legend_handles_labels()
    modes = plotting.mode_handles((1, -1))  # the orbits' colours (stick: on the stick segment)
    plotting.legend_beside(ax, handles=handles + modes, labels=labels + [h.get_label() for h in modes],
                           title="orbits from the initial states", title_fontsize=8)
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    osc = osc_from_attrs(ds.attrs)
    k, N, V = osc.stiffness, osc.normal_force, osc.belt_speed
    fs, fd, w = osc.friction.fs, osc.friction.fd, osc.omega
    x_a, x_e = fs * N / k, fd * N / k
    dta = 2 * (fs - fd) * N / (k * V)
    dtg = (2 * math.pi - 2 * math.atan(dta * w / 2)) / w
    printed = 2 * math.pi * math.atan(dta * w / 2) / w
    r = math.hypot(x_a - x_e, V / w)
    mult = sorted(float(v) for v in ds.multipliers.values)
    joined = np.abs(ds.section_after_transient.values[1:] - float(ds.section_x))
    return [
        close_check("stick time = 2 (f_s - f_d) N / (k V)", float(ds.stick_time), dta, rtol=1e-12),
        close_check("slip time = (2π - 2 arctan(Δt_a w/2)) / w (corrected, E1)", float(ds.slip_time), dtg, rtol=1e-12),
        Check("printed slip time 2π arctan(Δt_a w/2)/w disagrees with the simulation (E1)",
              bool(abs(printed - float(ds.slip_time)) > 1e-3 * dtg), f"{printed:.6g}",
              f"simulated {float(ds.slip_time):.6g}", f"relative error {abs(printed / float(ds.slip_time) - 1):.1%}: "
              "printed formula rejected"),
        close_check("x_max = x_e + sqrt((x_a - x_e)^2 + (V/w)^2)", float(ds.x_max), x_e + r, rtol=1e-12),
        close_check("x_min = x_e - sqrt((x_a - x_e)^2 + (V/w)^2)", float(ds.x_min), x_e - r, rtol=1e-12),
        Check("Floquet multipliers {0, 1} (saltation matrices)", bool(abs(mult[0]) < 1e-12 and abs(mult[1] - 1) < 1e-12),
              f"{mult[0]:.2e}, {mult[1]:.15f}", "0, 1 within 1e-12"),
        close_check("period vs plain solve_ivp (rtol 1e-11, independent code)", float(ds.solve_ivp_period),
                    float(ds.period), rtol=1e-8),
        Check("orbits outside S join the cycle exactly (finite-time capture by sticking)",
              bool(np.all(joined < 1e-12)), f"max |Δx| = {joined.max():.2e}", "< 1e-12 after 3 periods"),
        Check("orbit inside S never sticks and keeps its ellipse (energy about x_e conserved)",
              bool(int(ds.inside_reaches_stick) == 0 and float(ds.inside_energy_variation) < 1e-12),
              f"energy variation {float(ds.inside_energy_variation):.1e}", "no stick, < 1e-12"),
    ]


FIGURE = FigureSpec(
    key="fig2", title="Figure 2 — phase diagram of the stick-slip regime", model="1-DOF friction oscillator, Coulomb",
    claim="Slip trajectories are ellipses centred at ±x_e = ±f_d N/k; the stick set is the segment "
          "[(-x_a, V), (x_a, V)], x_a = f_s N/k; initial conditions in a domain S keep a stable equilibrium "
          "(closed slip ellipses), all others reach an attracting limit cycle made of a stick phase "
          "Δt_a = 2(f_s - f_d)N/(kV) and a slip phase Δt_g.",
    method="Event-driven simulation with closed-form slip segments and exact switching (m = k = N = 1, V = 0.2, "
           "f_s = 0.6, f_d = 0.4) from five initial conditions (one inside S, one with reverse slip); the limit cycle "
           "by shooting on the section v = 0 with saltation-matrix Floquet multipliers; an independent solve_ivp "
           "integration for the period.",
    errata=("E1",),
)

"""Figure 3: the oscillator with a kinetic coefficient falling linearly with slip speed."""

from __future__ import annotations

import math

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...friction import LinearWeakening, UserLaw
from ...oscillator import Engine, Oscillator, equilibrium_stability, limit_cycle
from ...oscillator.baseline import solve_ivp_switches
from ...oscillator.simulate import MODE_ATTRS
from .. import Check, FigureSpec, close_check
from .common import PADDED, orbits, osc_attrs, osc_from_attrs, section_after

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

# f_s = f_d as in eq. [7]; tau V = 0.1 << 1
OSC = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2,
                 friction=LinearWeakening(fs=0.4, fd=0.4, tau=0.5))
STARTS = [(0.37, 0.0), (0.36, -0.1), (-0.7, 0.0), (1.0, 0.0)]


def _spiral(osc: Oscillator, x0: float, turns: int = 3):
    """Successive v = 0 crossings of the slip spiral, from an independent DOP853 flow of the
    law given as a plain callable (no closed form involved)."""
    law = osc.friction
    numeric = osc.replace(friction=UserLaw(lambda v: law.fd * (1 - law.tau * abs(v)), law.fs))
    engine = Engine(numeric, method="numeric")
    flow = engine.flows[1]
    xs, x, v = [], x0, 0.0
    for _ in range(2 * turns):
        dt, hit = flow.first_crossing(x, v, 100.0, [(0.0, 0)])
        x, v = (float(a) for a in np.ravel(flow.evaluator()(dt)))
        xs.append(x)
        v = 0.0
    return np.array(xs)


def compute(quick: bool) -> xr.Dataset:
    cycle = limit_cycle(OSC)
    o = orbits(OSC, STARTS, 6 * cycle.period, 800 if quick else 2500)
    cyc = cycle.trajectory.to_xarray(400 if quick else 1500)
    st = equilibrium_stability(OSC)
    sw = solve_ivp_switches(OSC, *STARTS[2], 15 * cycle.period, rtol=1e-11)
    sticks = [s[0] for s in sw if s[3] == 0]
    return xr.Dataset(
        {
            "orbit_x": (("start", "sample"), o["x"], {"units": "m", "comment": PADDED}),
            "orbit_v": (("start", "sample"), o["v"], {"units": "m/s", "comment": PADDED}),
            "orbit_mode": (("start", "sample"), o["mode"], {**MODE_ATTRS, "long_name": "contact mode on the orbit"}),
            "start_x": ("start", np.array([s[0] for s in STARTS]), {"units": "m"}),
            "start_v": ("start", np.array([s[1] for s in STARTS]), {"units": "m/s"}),
            "section_after_transient": ("start", np.array([section_after(OSC, x, v, 8 * cycle.period)
                                                          for x, v in STARTS]), {"units": "m"}),
            "x": ("t", cyc["x"].values, {"units": "m"}), "v": ("t", cyc["v"].values, {"units": "m/s"}),
            "mode": ("t", cyc["mode"].values, MODE_ATTRS),
            "period": ((), cycle.period, {"units": "s"}), "stick_time": ((), cycle.stick_time, {"units": "s"}),
            "section_x": ((), cycle.section_x, {"units": "m"}),
            "multipliers": ("k", np.sort(np.real(cycle.floquet_multipliers))),
            "eigen_re": ("k", st.eigenvalues.real, {"units": "1/s"}),
            "eigen_im": ("k", st.eigenvalues.imag, {"units": "1/s"}),
            "spiral_crossings": ("crossing", _spiral(OSC, STARTS[0][0]), {"units": "m"}),
            "solve_ivp_period": ((), (sticks[-1] - sticks[1]) / (len(sticks) - 2), {"units": "s"}),
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
    ax.plot([x_lo, x_hi], [osc.belt_speed] * 2, color="tab:green", lw=4, alpha=0.5, label="stick segment")
    ax.plot([osc.equilibrium], [0], "r*", ms=10, label="unstable equilibrium x_e+")
    ax.set_xlabel("x [m]"), ax.set_ylabel("dx/dt [m/s]")
    ax.set_title("Fig. 3 — f = f_d (1 - τ|v_r|): flutter of the equilibrium, attracting stick-slip cycle")
    handles, labels = ax.get_legend_handles_labels()
    modes = plotting.mode_handles((1, -1))  # the orbits' colours (stick: on the stick segment)
    plotting.legend_beside(ax, handles=handles + modes, labels=labels + [h.get_label() for h in modes],
                           title="orbits from the initial states", title_fontsize=8)
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    osc = osc_from_attrs(ds.attrs)
    m, k, N, V = osc.mass, osc.stiffness, osc.normal_force, osc.belt_speed
    fd, tau = osc.friction.fd, osc.friction.tau
    growth = fd * tau * N / (2 * m)
    xs = ds.spiral_crossings.values
    centre = (xs[2] * xs[0] - xs[1] ** 2) / (xs[2] - 2 * xs[1] + xs[0])  # exact for a linear spiral
    ratio = (xs[2] - centre) / (xs[0] - centre)
    wd = math.sqrt(k / m - growth**2)
    joined = np.abs(ds.section_after_transient.values - float(ds.section_x))
    mult = sorted(float(v) for v in ds.multipliers.values)
    return [
        close_check("equilibrium eigenvalues: Re λ = +f_d τ N / (2m) (negative damping, flutter)",
                    float(ds.eigen_re.max()), growth, rtol=1e-12),
        Check("equilibrium is an unstable focus (complex pair)", bool(np.all(ds.eigen_im.values != 0)),
              f"Im λ = ±{abs(float(ds.eigen_im[0])):.6g}", "non-zero"),
        close_check("spiral centre x_e+ = f_d (1 - τV) N / k (fitted from an independent DOP853 orbit)",
                    centre, fd * (1 - tau * V) * N / k, rtol=1e-9),
        close_check("spiral growth per turn = exp(2π σ / ω_d), σ = f_d τ N / 2m", ratio,
                    math.exp(2 * math.pi * growth / wd), rtol=1e-9),
        Check("every start (inside and outside) reaches the same cycle", bool(np.all(joined < 1e-12)),
              f"max |Δx| = {joined.max():.2e}", "< 1e-12 after 8 periods"),
        Check("Floquet multipliers {0, 1}", bool(abs(mult[0]) < 1e-12 and abs(mult[1] - 1) < 1e-12),
              f"{mult[0]:.2e}, {mult[1]:.15f}", "0, 1 within 1e-12"),
        close_check("period vs plain solve_ivp (independent code)", float(ds.solve_ivp_period),
                    float(ds.period), rtol=1e-8),
    ]


FIGURE = FigureSpec(
    key="fig3", title="Figure 3 — phase diagram with velocity-weakening friction", model="1-DOF friction oscillator, linear weakening",
    claim="With f = f_d(1 - τ v_r) the slip trajectories are divergent spirals centred at x_e+ = f_d(1 - τV)N/k; "
          "the unique equilibrium is unstable by flutter (Hopf), the law acting as a negative damping "
          "m ẍ - f_d τ N ẋ + k x = f_d(1 - τV)N; a limit cycle attracts every initial condition.",
    method="Closed-form event-driven simulation (m = k = N = 1, V = 0.2, f_s = f_d = 0.4, τ = 0.5) from four starts "
           "(two near the equilibrium, two outside the cycle); eigenvalues of the linearisation; the spiral's centre "
           "and growth fitted from an independent DOP853 integration of the law given as a callable; shooting and "
           "Floquet multipliers; a plain solve_ivp period.",
    errata=("E2", "E3"),
)

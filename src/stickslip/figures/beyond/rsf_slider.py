"""Beyond the paper: the rate-and-state spring-slider (slide-hold-slide; critical stiffness)."""

from __future__ import annotations

import math

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...rsf import RateState, SpringSlider, linear_stability, slide
from .. import Check, FigureSpec, close_check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

A, B, DC, SIGMA, F0, V0 = 0.01, 0.015, 1e-5, 1e7, 0.6, 1e-6
LAWS = ("aging", "slip", "prz")
TIMES, SPEEDS = [0.0, 20.0, 60.0, 100.0], [1e-6, 1e-5, 0.0, 1e-6]  # a step up, a hold, sliding again
K = 5.0 * SIGMA * (B - A) / DC  # the PRZ and slip laws run away at a tenfold step below about 3 k_c


def compute(quick: bool) -> xr.Dataset:
    samples = 801 if quick else 3201
    friction = []
    for law in LAWS:
        slider = SpringSlider(RateState(A, B, DC, f0=F0, v_ref=V0, evolution=law), SIGMA, K)
        friction.append(slide(slider, SPEEDS, 160.0, times=TIMES, samples=samples).friction)
    t = np.linspace(0.0, 160.0, samples)
    eta = np.logspace(-3, 1, 9 if quick else 17)  # the inertia m V^2 / (sigma a Dc)
    mass = eta * SIGMA * A * DC / V0**2
    kc, omega = [], []
    for m in mass:
        s = linear_stability(SpringSlider(RateState(A, B, DC, f0=F0, v_ref=V0), SIGMA, K, mass=m), V0)
        kc.append(s.critical_stiffness)
        omega.append(s.hopf_frequency)
    return xr.Dataset(
        {"friction": (("law", "t"), np.array(friction), {"units": "1", "long_name": "friction coefficient"}),
         "critical_stiffness": ("eta", np.array(kc), {"units": "Pa/m", "long_name": "critical stiffness"}),
         "hopf_frequency": ("eta", np.array(omega), {"units": "rad/s", "long_name": "Hopf frequency"})},
        coords={"law": ("law", list(LAWS), {"long_name": "evolution law of the state"}), "t": ("t", t, {"units": "s", "long_name": "time"}),
                "eta": ("eta", eta, {"units": "1", "long_name": "inertia m V^2 / (sigma a D_c)"})},
        attrs={"a": A, "b": B, "dc": DC, "normal_stress": SIGMA, "f0": F0, "v_ref": V0, "stiffness": K})


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    fig, (ax, bx) = plotting.new_figure(fig, ncols=2, size=(5.6, 4.4))
    for law in ds.law.values:
        ax.plot(ds.t, ds.friction.sel(law=law), lw=1.2, label=f"{law} law")
    for edge in TIMES[1:]:
        ax.axvline(edge, color="0.6", lw=0.6, ls=":")
    ax.set_xlabel("time [s]"), ax.set_ylabel("friction coefficient [1]")
    ax.set_title("slide (1 µm/s), step to 10 µm/s, hold, slide", fontsize=10)
    ax.legend(fontsize=8, loc="lower left")
    kc0 = SIGMA * (B - A) / DC
    bx.loglog(ds.eta, ds.critical_stiffness / kc0, "o", ms=4, label="computed (linearised slider)")
    eta = np.logspace(-3, 1, 100)
    bx.loglog(eta, 1 + eta, "k-", lw=0.8, label="closed form 1 + m V²/(σ a D_c)")
    bx.set_xlabel("inertia m V²/(σ a D_c) [1]"), bx.set_ylabel("k_c / (σ (b - a)/D_c) [1]")
    bx.set_title("critical stiffness with inertia", fontsize=10)
    bx.legend(fontsize=8, loc="upper left")
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    kc0 = SIGMA * (B - A) / DC
    expected = kc0 * (1 + ds.eta.values)
    worst_kc = float(np.max(np.abs(ds.critical_stiffness.values / expected - 1)))
    omega = V0 / DC * math.sqrt((B - A) / A)
    worst_w = float(np.max(np.abs(ds.hopf_frequency.values / omega - 1)))
    aging = ds.friction.sel(law="aging").values
    t = ds.t.values
    steady = F0 + (A - B) * math.log(1e-6 / V0)
    peak = float(aging[t > 100.0].max())
    return [
        close_check("steady friction before the step = f0 + (a - b) ln(V/V0)", float(aging[t < 19.0].mean()),
                    steady, atol=1e-9),
        Check("k_c = σ(b - a)/D_c (1 + m V²/(σ a D_c)) over 4 decades of inertia", bool(worst_kc < 1e-8),
              f"worst relative difference {worst_kc:.1e}", "< 1e-8"),
        Check("Hopf frequency (V/D_c) sqrt((b - a)/a) with and without inertia", bool(worst_w < 1e-8),
              f"worst relative difference {worst_w:.1e}", "< 1e-8"),
        Check("the aging law heals during the hold: a peak above steady friction on reloading", bool(peak > steady),
              f"peak {peak:.6f}", f"> {steady:.6f}"),
    ]


FIGURE = FigureSpec(
    key="beyond-rsf", title="Beyond the paper — the rate-and-state spring-slider",
    model="rate-and-state spring-slider (beyond the paper)",
    claim="(Not a claim of the paper.) Rate-and-state friction (Dieterich aging, Ruina slip, Perrin-Rice-Zheng): "
          "steady sliding of a spring-slider loses stability below k_c = σ(b - a)/D_c (1 + m V²/(σ a D_c)) "
          "(Ruina 1983; Rice & Ruina 1983) with an oscillation of frequency (V/D_c) sqrt((b - a)/a).",
    method="stickslip.rsf: the quasi-static slider (a = 0.01, b = 0.015, D_c = 10 µm, σ = 10 MPa, k = 5 k_c) under "
           "a slide-hold-slide history, Radau IIA in (ln V, ln θ); k_c by Brent's method on the eigenvalues of the "
           "slider linearised by complex steps, compared with the closed form.",
)

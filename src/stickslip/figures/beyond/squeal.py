"""Beyond the paper: the mode-coupling model of brake squeal (Hoffmann et al. 2002) as a system
with a unilateral frictional contact: flutter of steady sliding, the limit cycle beyond it."""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...friction import Coulomb
from ...system import Contact, System, limit_cycle, simulate, steady_sliding
from .. import Check, FigureSpec, close_check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

K11, K12, K22, KH, N0, V = 1.1, -0.3, 0.5, 0.5, 1.0, 0.5
MU_CYCLE, DAMPING = 0.7, 0.01


def squeal(mu: float, damping: float = 0.0) -> System:
    pad = Contact([1.0, 0.0], N0, Coulomb(1.2 * mu, mu), V, normal_direction=[0.0, 1.0], normal_stiffness=KH)
    return System(np.eye(2), [[K11, K12], [K12, K22]], [pad], damping=damping * np.eye(2))


def compute(quick: bool) -> xr.Dataset:
    mu = np.linspace(0.3, 0.9, 61 if quick else 241)
    growth = np.array([steady_sliding(squeal(m)).growth_rate for m in mu])
    damped = np.array([steady_sliding(squeal(m, DAMPING)).growth_rate for m in mu])
    lo, hi = 0.3, 0.9  # the undamped threshold by bisection on the computed growth rate
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if steady_sliding(squeal(mid)).growth_rate < 1e-9 else (lo, mid)
    system = squeal(MU_CYCLE, DAMPING)
    cycle = limit_cycle(system, [0.5, 0.1], [0.0, 0.0], transient=300.0)
    orbit = simulate(system, cycle.x0, cycle.v0, cycle.period, samples=400 if quick else 1200, states=cycle.states)
    closing = float(np.abs(np.concatenate([orbit.x[-1] - cycle.x0, orbit.v[-1] - cycle.v0])).max())
    return xr.Dataset(
        {"growth_rate": ("mu", growth, {"units": "1/s", "long_name": "growth rate of steady sliding, undamped"}),
         "growth_rate_damped": ("mu", damped, {"units": "1/s", "long_name": "growth rate, damping 0.01"}),
         "x": ("t", orbit.x[:, 0], {"units": "m", "long_name": "tangential displacement"}),
         "y": ("t", orbit.x[:, 1], {"units": "m", "long_name": "normal displacement (away from the belt)"}),
         "contact_state": ("t", orbit.states[:, 0].astype(np.int8), {"long_name": "contact state",
                                                                      "flag_values": np.array([-1, 0, 1, 2], np.int8),
                                                                      "flag_meanings": "reverse_slip stick slip open"}),
         "multiplier_abs": ("multiplier", np.abs(cycle.multipliers),
                            {"units": "1", "long_name": "moduli of the cycle's Floquet multipliers"}),
         "mu_critical": ((), 0.5 * (lo + hi), {"units": "1", "long_name": "flutter threshold by bisection"}),
         "period": ((), cycle.period, {"units": "s", "long_name": "period of the limit cycle"}),
         "closing_error": ((), closing, {"units": "1", "long_name": "largest change of the state over one period"}),
         "opens": ((), int(2 in set(cycle.event_state.tolist())),
                   {"units": "1", "long_name": "1 if the contact opens on the cycle"})},
        coords={"mu": ("mu", mu, {"units": "1", "long_name": "friction coefficient"}),
                "t": ("t", orbit.t, {"units": "s", "long_name": "time"})},
        attrs={"k11": K11, "k12": K12, "k22": K22, "k_h": KH, "preload": N0, "belt_speed": V})


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    fig, (ax, bx) = plotting.new_figure(fig, ncols=2, size=(5.6, 4.4))
    ax.plot(ds.mu, ds.growth_rate, lw=1.2, label="undamped")
    ax.plot(ds.mu, ds.growth_rate_damped, lw=1.2, ls="--", label=f"damping {DAMPING} N s/m")
    ax.axvline(float(ds.mu_critical), color="k", lw=0.8, ls=":", label="closed-form μ_c (undamped)")
    ax.set_xlabel("friction coefficient μ [1]"), ax.set_ylabel("growth rate of steady sliding [1/s]")
    ax.set_title("flutter: two modes coalesce", fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    closed = ds.contact_state.values != 2
    bx.plot(np.where(closed, ds.x, np.nan), np.where(closed, ds.y, np.nan), color="tab:blue", lw=1.4,
            label="contact closed (slipping)")
    bx.plot(np.where(~closed, ds.x, np.nan), np.where(~closed, ds.y, np.nan), color="tab:red", lw=1.4,
            label="contact open")
    bx.axhline(N0 / KH, color="0.5", lw=0.8, ls=":", label="contact spring unloaded (N = 0)")
    bx.set_xlabel("tangential displacement x [m]"), bx.set_ylabel("normal displacement y [m]")
    bx.set_title(f"limit cycle at μ = {MU_CYCLE} (period {float(ds.period):.3f} s)", fontsize=10)
    plotting.legend_beside(bx)
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    mu_c = (-(K11 - K22 - KH) ** 2 / (4 * K12) - K12) / KH
    others = np.sort(ds.multiplier_abs.values)
    unit = float(np.min(np.abs(ds.multiplier_abs.values - 1.0)))
    return [
        close_check("flutter threshold μ_c = (-(k11 - k22 - k_H)²/(4 k12) - k12)/k_H", float(ds.mu_critical), mu_c,
                    rtol=1e-6),
        Check("the cycle closes after one period", bool(float(ds.closing_error) < 1e-8),
              f"{float(ds.closing_error):.1e}", "< 1e-8"),
        Check("one Floquet multiplier is the flow's own 1", bool(unit < 1e-8), f"|m - 1| = {unit:.1e}", "< 1e-8"),
        Check("the cycle is stable (the other multipliers inside the unit circle)",
              bool(np.sum(others < 1 - 1e-6) == others.size - 1), ", ".join(f"{m:.4f}" for m in others), "< 1"),
        Check("the contact opens and closes once a period", bool(int(ds.opens) == 1), str(int(ds.opens)), "1"),
    ]


FIGURE = FigureSpec(
    key="beyond-squeal", title="Beyond the paper — mode-coupling brake squeal (Hoffmann model)",
    model="structure with a unilateral frictional contact (beyond the paper)",
    claim="(Not a claim of the paper.) Friction couples the tangential and normal modes of a pad pressed on a "
          "moving belt: steady sliding flutters above a critical friction coefficient (Hoffmann et al. 2002), and "
          "the vibration grows until the contact opens: a limit cycle that slips, lifts off and lands once a period.",
    method="stickslip.system: a mass with a tangential and a normal degree of freedom, coupled springs, a contact "
           "spring k_H (normal force N = N0 - k_H y while positive), Coulomb friction; the eigenvalues of steady "
           "sliding over μ, μ_c by bisection against its closed form; the cycle by Newton's method on the return "
           "map with saltation-matrix Floquet multipliers.",
)

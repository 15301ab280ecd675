"""Beyond the paper (its open problem): are the travelling waves stable? The Floquet multipliers
of the discrete ring's wave (`stickslip.brake.waves.wave_spectrum`), their convergence with
the nodes, the Moreau runs' evidence beside them, and the stability along Figure 11's branch,
the waves that leave the shaft included (the ring whose nodes may leave it too)."""

from __future__ import annotations

import math
import time

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake import BrakeParams, continue_waves, travelling_wave
from ...brake.waves import moreau_difference, wave_persistence, wave_spectrum
from ...errors import NoSolutionError
from .. import Check, FigureSpec
from .paper import FIG5, FIG11

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

#: The waves of the convergence table: Figure 5's at Omega = 100 rad/s, Figure 11's first, and one
#: of Figure 11's branch that leaves the shaft (stick, slip, separation).
WAVES = (("Figure 5, Ω = 100 rad/s", 100.0, FIG5["mismatch"], FIG5["friction"], FIG5["modes"]),
         ("Figure 11, d = 10 µm", FIG11["omega"], FIG11["mismatch"][0], FIG11["friction"], FIG11["modes"]),
         ("Figure 11's branch, d = 1.2 µm (separates)", FIG11["omega"], 1.2e-6, FIG11["friction"], FIG11["modes"]))
#: The separating wave's row of the table: its ring has 2N degrees of freedom (the normal motion) and a
#: flow (2N-square matrices) per contact state met; at 512 nodes a run takes about 20 minutes and 2.5 GB,
#: beyond a report's budget: it stops at 256 (NaN beyond; benchmarks/wave_spectrum.py --separating).
SEPARATING, SEPARATING_NODES = 2, 256
BEYOND = f"NaN for the separating wave beyond {SEPARATING_NODES} nodes (not computed: 20 minutes and 2.5 GB at 512)"
#: Points of Figure 11's branch whose stability is computed (64 and 128 nodes each; log-spaced: every
#: other of the 25 it had, whose 21 separating waves' spectra took most of the figure's time).
BRANCH_POINTS = 13
#: Moreau steps over half a wave period against which the event-driven separating ring is set.
MOREAU_STEPS = (4000, 8000, 16000)
R = 0.1  # the ring's inner radius [m] (paper.GEOMETRY)


#: Returns of the node-shift map a branch point's discrete wave is looked for in (iterations and Newton
#: steps): the waves found take 4 to 20; one marginal separating wave (d = 4.6 um, 128 nodes) took 51 Newton
#: steps stalled near a grazing contact, 54 s of the figure's 270, before its last two converged.
BRANCH_RETURNS = 30


def _growth(wave, nodes: int) -> float:
    try:
        return wave_spectrum(wave, nodes, max_iter=BRANCH_RETURNS).growth_per_period
    except NoSolutionError:  # no discrete wave near the continuous one (the figure says how many)
        return math.nan


def compute(quick: bool = False) -> xr.Dataset:
    nodes = (64, 128, 256) if quick else (64, 128, 256, 512)
    growth, err, secs, moreau, persists, period, separation = [], [], [], [], [], [], []
    spectrum = None
    for i, (_, omega, d, f, n) in enumerate(WAVES):
        wave = travelling_wave(BrakeParams.from_physical(omega, d, f), n)
        row_g, row_e, row_t = [], [], []
        for k in nodes:
            if i == SEPARATING and k > SEPARATING_NODES:
                row_g.append(math.nan), row_e.append(math.nan), row_t.append(math.nan)
                continue
            start = time.perf_counter()
            sp = wave_spectrum(wave, k)
            row_t.append(time.perf_counter() - start)
            row_g.append(sp.growth_per_period)
            row_e.append(abs(sp.shift_time / sp.continuous_shift_time - 1.0))
            if spectrum is None and k == 128:
                spectrum = sp.multipliers
        growth.append(row_g), err.append(row_e), secs.append(row_t)
        run = wave_persistence(wave, nodes=256, periods=30)  # the Moreau stepper's evidence
        wave_period = (2 * np.pi / wave.n) / abs(float(wave.x[0]))  # internal time
        moreau.append(run.growth_rate * wave_period)
        separation.append(run.separation_of_runs)
        persists.append(int(run.persists))
        period.append(wave_period)
        if i == SEPARATING:
            refinement = moreau_difference(wave, 64, MOREAU_STEPS)
    p0 = BrakeParams.from_physical(FIG11["omega"], FIG11["mismatch"][0], FIG11["friction"])
    branch = continue_waves(p0, FIG11["modes"], "delta", FIG11["mismatch"][1] / R, num=BRANCH_POINTS, spacing="log")
    delta, structure, along = [], [], []
    for w in branch.waves:
        delta.append(w.params.delta)
        structure.append(w.structure)
        along.append([_growth(w, k) for k in (64, 128)])
    return xr.Dataset(
        {"growth_per_period": (("wave", "nodes"), np.array(growth),
                               {"units": "1", "long_name": "ln of a perturbation's growth over a wave period",
                                "comment": BEYOND}),
         "speed_error": (("wave", "nodes"), np.array(err),
                         {"units": "1", "long_name": "discrete against continuous wave speed, relative",
                          "comment": BEYOND}),
         "seconds": (("wave", "nodes"), np.array(secs), {"units": "s", "long_name": "time of the computation", "comment": BEYOND}),
         "moreau_growth_per_period": ("wave", np.array(moreau), {"units": "1", "long_name": "the same from the "
                                                                 "Moreau runs (wave and perturbed wave, 256 nodes)"}),
         "moreau_persists": ("wave", np.array(persists, dtype=np.int8), {"units": "1", "long_name": "1 if the "
                                                                        "Moreau run stays within 5 % of the wave"}),
         "moreau_separation": (("wave", "moreau_period"), np.array(separation),
                               {"units": "1", "long_name": "perturbed - unperturbed Moreau run / initial perturbation"}),
         "moreau_refinement": ("moreau_steps", refinement,
                               {"units": "1", "long_name": "event-driven separating ring - Moreau run, half a "
                                                           "period, 64 nodes, relative"}),
         "wave_period": ("wave", np.array(period), {"units": "1", "long_name": "wave period, internal time"}),
         "multiplier_real": ("multiplier", spectrum.real, {"units": "1", "long_name": "node-shift multipliers "
                                                           "(real part), first wave, 128 nodes"}),
         "multiplier_imag": ("multiplier", spectrum.imag, {"units": "1", "long_name": "(imaginary part)"}),
         "branch_growth": (("point", "branch_nodes"), np.array(along),
                           {"units": "1", "long_name": "growth over a wave period along Figure 11's branch",
                            "comment": "NaN where no discrete wave was found near the continuous one within "
                                       f"{BRANCH_RETURNS} returns of the map"}),
         "branch_structure": ("point", np.array(structure, dtype=str), {"long_name": "zones of the wave"})},
        coords={"wave": ("wave", np.array([w[0] for w in WAVES], dtype=str), {"long_name": "wave"}),
                "moreau_period": ("moreau_period", np.arange(len(separation[0])),
                                  {"units": "1", "long_name": "time in wave periods"}),
                "moreau_steps": ("moreau_steps", np.array(MOREAU_STEPS), {"units": "1",
                                                                          "long_name": "Moreau steps"}),
                "nodes": ("nodes", np.array(nodes), {"units": "1", "long_name": "ring nodes"}),
                "multiplier": ("multiplier", np.arange(spectrum.size), {"units": "1", "long_name": "multiplier"}),
                "point": ("point", np.arange(len(delta)), {"units": "1", "long_name": "branch point"}),
                "mismatch": ("point", np.array(delta) * R, {"units": "m", "long_name": "mismatch d"}),
                "branch_nodes": ("branch_nodes", np.array([64, 128]), {"units": "1", "long_name": "ring nodes"})})


def _finite(row) -> np.ndarray:
    row = np.asarray(row, dtype=float)
    return row[np.isfinite(row)]


def stability_changes(ds: xr.Dataset) -> list[float]:
    """The mismatches [m] between two neighbouring points of the branch where the growth at the most
    nodes changes sign (geometric means of the two; points without a discrete wave skipped)."""
    g, d = ds.branch_growth.values[:, -1], ds.mismatch.values
    done = np.flatnonzero(np.isfinite(g))
    return [float(np.sqrt(d[a] * d[b])) for a, b in zip(done[:-1], done[1:]) if (g[a] > 0) != (g[b] > 0)]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    fig, (ax, bx, cx, dx) = plotting.new_figure(fig, ncols=2, nrows=2, size=(5.4, 4.0))
    colors = ("tab:blue", "tab:red", "tab:green")
    for i, name in enumerate(ds.wave.values):
        ax.plot(ds.nodes, ds.growth_per_period[i], "o-", color=colors[i], lw=1.2, label=name)
    ax.axhline(0.0, color="k", lw=0.6)
    ax.set_xscale("log", base=2)
    ax.set_xlabel("ring nodes N [1]"), ax.set_ylabel("ln(growth) per wave period [1]")
    ax.set_title("leading multiplier against the nodes", fontsize=10)
    plotting.legend_beside(ax)
    m = ds.multiplier_real.values + 1j * ds.multiplier_imag.values
    near = np.abs(m) > 0.5  # the rest are 0: the sticking nodes' velocities
    bx.plot(np.angle(m[near]), np.abs(m[near]) - 1.0, ".", ms=4, color=colors[0], label="multipliers μ")
    bx.axhline(0.0, color="k", lw=0.6, label="unit circle")
    bx.set_xlabel("arg μ [rad]"), bx.set_ylabel("|μ| - 1 [1]")
    bx.set_title("node-shift map, first wave, 128 nodes", fontsize=10)
    plotting.legend_beside(bx)
    sep = np.array(["separation" in s for s in ds.branch_structure.values])
    for j, k in enumerate(ds.branch_nodes.values):
        line, = cx.plot(ds.mismatch * 1e6, ds.branch_growth[:, j], "-", lw=1.0, label=f"{k} nodes")
        cx.plot(ds.mismatch[~sep] * 1e6, ds.branch_growth[~sep, j], "o", ms=3, color=line.get_color())
        cx.plot(ds.mismatch[sep] * 1e6, ds.branch_growth[sep, j], "o", ms=3, mfc="white", color=line.get_color())
    cx.plot([], [], "o", ms=3, mfc="white", color="0.4", label="separates")
    for k, d in enumerate(stability_changes(ds)):
        cx.axvline(d * 1e6, color="k", ls=":", lw=0.8, label="sign change" if k == 0 else None)
    cx.axhline(0.0, color="k", lw=0.6)
    cx.set_xscale("log")
    cx.set_xlabel("mismatch d [µm]"), cx.set_ylabel("ln(growth) per wave period [1]")
    cx.set_title("Figure 11's branch (> 0: unstable)", fontsize=10)
    plotting.legend_beside(cx)
    periods = ds.moreau_period.values
    for i, name in enumerate(ds.wave.values):
        dx.semilogy(periods, ds.moreau_separation[i], color=colors[i], lw=1.0, label=f"{name}: Moreau run")
        g = float(_finite(ds.growth_per_period[i])[-1])
        dx.semilogy(periods, np.exp(g * periods), color=colors[i], ls="--", lw=1.0,
                    label=f"exp({g:.3f} t/T): multiplier")
    dx.set_xlabel("time t/T [wave periods]"), dx.set_ylabel("perturbation / initial [1]")
    dx.set_title("a perturbed run of the ring (Moreau)", fontsize=10)
    plotting.legend_beside(dx)
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    out = []
    for i, name in enumerate(ds.wave.values):
        if "separates" in str(name):  # the motion itself, against the Moreau stepper refined (its spectrum: described)
            r = ds.moreau_refinement.values
            ratios = r[:-1] / r[1:]
            out.append(Check(f"{name}: the event-driven ring leaving and landing on the shaft moves as the Moreau "
                             "stepper (independent) converges", bool(r[-1] < 1e-3 and np.all((ratios > 1.5) &
                                                                                               (ratios < 2.7))),
                             ", ".join(f"{v:.2g}" for v in r), "halving with the step (first order), < 1e-3"))
            continue
        e = ds.speed_error[i].values
        out.append(Check(f"{name}: the discrete wave's speed tends to the continuous one",
                         bool(e[-1] < 1e-3 and e[-1] < e[-2]), ", ".join(f"{v:.2g}" for v in e),
                         "< 1e-3 at the most nodes, falling"))
        g = ds.growth_per_period[i].values
        steps = np.abs(np.diff(g))
        out.append(Check(f"{name}: the leading multiplier converges (each doubling of N changes it less)",
                         bool(np.all(steps[1:] < steps[:-1])), ", ".join(f"{s:.2g}" for s in steps), "decreasing"))
        mo = float(ds.moreau_growth_per_period[i])
        ratio = mo / g[-1]
        out.append(Check(f"{name}: the Moreau runs (an independent stepper) see the same instability",
                         bool(g[-1] > 0 and 0.5 <= ratio <= 2.0), f"{mo:.3g} against {g[-1]:.3g}",
                         "both > 0, ratio in [0.5, 2]"))
    return out


def describe(ds: xr.Dataset) -> str:
    parts = []
    for i, name in enumerate(ds.wave.values):
        g = ds.growth_per_period[i].values
        done = np.isfinite(g)
        k = ds.nodes.values[done]
        parts.append(f"{name}: a perturbation grows by a factor {np.exp(g[done][-1]):.3f} per wave period at "
                     f"{int(k[-1])} nodes ({', '.join(f'{v:.4f}' for v in g[done])} for N = "
                     f"{', '.join(str(int(v)) for v in k)}); the Moreau runs give "
                     f"{float(ds.moreau_growth_per_period[i]):.4f}")
    g = _finite(ds.growth_per_period[SEPARATING])
    settles = g.size > 2 and bool(np.all(np.diff(np.abs(np.diff(g))) < 0))  # each doubling changes it less
    rate = "its rate settling" if settles else "its rate not settling over these N: not converged"
    errors = ", ".join(f"{v:.2g}" for v in _finite(ds.speed_error[SEPARATING]))
    parts.append(f"the separating wave is unstable at every N computed ({rate}; speed error {errors}, first order)"
                 if np.all(g > 0) else "the separating wave's multipliers change sign with N: its stability is not "
                 "settled")
    gap = [float(_finite(ds.growth_per_period[i])[-1] - ds.moreau_growth_per_period[i]) for i in range(SEPARATING)]
    parts.append(f"the Moreau runs (CFL 0.25) grow slower than the multipliers say by {min(gap):.3f} to "
                 f"{max(gap):.3f} per period on the waves in contact (their numerical damping)")
    b = ds.branch_growth.values[:, -1]
    changes = stability_changes(ds)
    both = np.all(np.isfinite(ds.branch_growth.values), axis=1)
    differ = ds.mismatch.values[both & ((ds.branch_growth.values[:, 0] > 0) != (b > 0))]
    parts.append(f"along Figure 11's branch the stability changes {len(changes)} times at 128 nodes"
                 + (f" (near d = {', '.join(f'{v * 1e6:.2f}' for v in changes)} µm)" if changes else "")
                 + (f"; 64 and 128 nodes disagree on the sign at d = {', '.join(f'{v * 1e6:.2f}' for v in differ)} "
                    "µm: marginal waves there, not settled" if differ.size else ""))
    sep = np.array(["separation" in s for s in ds.branch_structure.values])
    for label, sel in (("in permanent contact", ~sep), ("separating", sep)):
        v = b[sel][np.isfinite(b[sel])]
        if sel.any():
            parts.append(f"along Figure 11's branch, of {int(sel.sum())} waves {label} {v.size} have a discrete wave "
                         f"at 128 nodes within {BRANCH_RETURNS} returns of the map, {int((v > 0).sum())} unstable (ln growth per period "
                         + (f"{v.min():.3f} to {v.max():.3f})" if v.size else "-)"))
    return "; ".join(parts) + "."


FIGURE = FigureSpec(
    key="wave-stability", cost=150, title="Beyond the paper — the stability of the travelling waves",
    model="reduced brake model (ring), travelling waves",
    claim="(The paper's open problem, not a claim of it.) The stick-slip waves of Figures 5 and 11 in permanent "
          "contact are unstable: on the discrete ring their node-shift map has multipliers outside the unit circle, "
          "and the leading one converges as the ring is refined. A wave of Figure 11's branch that leaves the shaft "
          "is weakly unstable at every N computed (its rate not shown to converge).",
    method="stickslip.brake.waves.wave_spectrum: the ring of N nodes (centred differences) in contact, each node a "
           "frictional contact of a stickslip.system.System whose normal force is the reaction of U = δ; the wave "
           "a relative periodic orbit (it moves by one node in τ ≈ Δθ/|c|), found by Newton's method from the "
           "sampled shooting wave; the multipliers of the node-shift map with saltation matrices at every node's "
           "switch; N = 64 to 256 (512 in the full run). Beside it the growth fitted to a perturbed Moreau run "
           "(wave_persistence, 256 nodes). A wave that separates: the ring whose nodes may leave the shaft "
           "(ring_system(separation=True): the normal motion as degrees of freedom, each contact a rigid unilateral "
           "constraint with plastic landings and their friction impulses), the section a node's lift-off, N = 64 to "
           "256; its motion set against the Moreau stepper refined (64 nodes, half a period).",
)

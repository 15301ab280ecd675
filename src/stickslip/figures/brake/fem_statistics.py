"""Section 3.1 with finite elements: the limit regimes from unseeded starts, by statistics.

The paper reports, for each of three cases, one limit regime with a mode number (Figures
7-10). Each case is run here from many independent random perturbations of steady sliding
on two meshes (`stickslip.brake.fem.campaign`: each run driven to a stationary travelling
wave or to its budget of transits, its mode number counted as the number of stick zones
around the ring). A claim counts as reproduced when, on **each** of the two meshes, at least
a quarter of the unseeded runs end in the paper's regime with the paper's mode number (a
threshold fixed before the campaign was run). The data come from the campaign
(`campaign_data`), or from a small version on the coarse mesh alone, which cannot settle a
claim.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake.fem.campaign import budget_of, statistics
from ...contact import REGIME_CODES
from .. import Check, FigureSpec
from . import campaign_data
from .campaign_data import outcome_counts
from .paper import CASES, PAPER_REGIMES

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["THRESHOLD", "compute", "check", "plot", "inputs", "describe"]

#: Fraction of unseeded runs, on each mesh, that must reach the paper's regime and mode number.
THRESHOLD = 0.25
_SMALL = {True: 4, False: 6}  # seeds per case of the small version (quick, full)


def compute(quick: bool = False, cache: Path | None = None, data_dir: Path | None = None) -> xr.Dataset:
    """The statistics dataset over ``(case, mesh, seed)`` (see the module docstring)."""
    ds, source = campaign_data.find("statistics", data_dir)
    small = ds is None
    if small:
        with campaign_data.small_store(cache) as store:
            ds = statistics(store, CASES, meshes=((256, 16),), seeds=_SMALL[bool(quick)],
                            budgets=({"max_transits": 300.0},))
        source = f"the small version ({_SMALL[bool(quick)]} runs per case on 256 x 16 only): {source}"
    ds = ds.drop_vars("done", errors="ignore")
    ds.attrs.update({"data_source": source, "small": int(small), "threshold": THRESHOLD})
    return ds


def inputs(data_dir: Path | None) -> str:
    return campaign_data.inputs("statistics", data_dir)


def describe(ds: xr.Dataset) -> str:
    """What was computed, from the dataset itself (its meshes, budgets and runs): the report's
    text describes the data the figure shows, the small version included."""
    meshes = _meshes(ds)
    runs = [f"{a} × {b} ({budget_of(ds.attrs, m)['min_transits']:g} to {budget_of(ds.attrs, m)['max_transits']:g} "
            "transits)" for m, (a, b) in enumerate(meshes)]
    chunk = budget_of(ds.attrs, 0)["chunk"]
    return (f"{ds.sizes['seed']} runs per case from FE steady sliding plus white noise (1e-3 δ, one seed per run, "
            f"nothing seeded), β2 = {float(ds.attrs.get('beta2', 0.9)):g}, on " + " and ".join(runs) + ", each "
            f"integrated in chunks of {chunk:g} P-wave transits and stopped once its last 2 transits form a stationary "
            "travelling wave (relative misfit and state mismatch of the shifted snapshots < 0.1). The outcome: the "
            "regime of those transits and the mode number counted as the median number of stick zones around the "
            f"ring. A claim is reproduced when >= {THRESHOLD:.0%} of the runs on each of two meshes reach the paper's "
            "regime and mode" + ("." if len(meshes) >= 2 else "; with one mesh here, no claim can be settled.")
            + " The full campaign is `stickslip brake campaign` (resumable, about an hour on 2 cores).")


def _meshes(ds) -> list:
    return [(int(a), int(b)) for a, b in zip(np.atleast_1d(ds.attrs["mesh_n_theta"]),
                                             np.atleast_1d(ds.attrs["mesh_n_r"]))]


def _paper_fraction(ds, case: int, mesh: int, modes: bool = True) -> float:
    """Fraction of the runs of ``case`` on ``mesh`` that end in the paper's regime (and, with
    ``modes``, with the paper's mode number)."""
    regime, n = PAPER_REGIMES[case]
    sel = ds.isel(case=case, mesh=mesh)
    hit = sel["regime"].values == REGIME_CODES[regime]
    if modes:
        hit = hit & (sel["n_zones"].values == n)
    return float(np.mean(hit))


def check(ds: xr.Dataset) -> list[Check]:
    meshes = _meshes(ds)
    mesh_names = [f"{a} x {b}" for a, b in meshes]
    settled = len(meshes) >= 2  # one mesh cannot settle a claim
    out = [Check("every run ended in a classified window (regime and mode number defined)",
                 bool(np.all(ds["regime"].values >= 0) and np.all(np.isfinite(ds["n_zones"].values))
                      and np.all(np.abs(ds[["stick", "slip", "reverse_slip", "separation"]].to_array().sum("variable")
                                        - 1.0) < 1e-9)),
                 f"{int(ds['regime'].size)} runs", "regime, mode number and fractions summing to 1 for every run",
                 f"data: {ds.attrs.get('data_source', 'not recorded')}")]
    for case, (regime, modes) in enumerate(PAPER_REGIMES):
        fractions = [_paper_fraction(ds, case, m) for m in range(len(meshes))]
        stationary = [float(ds["stationary"].isel(case=case, mesh=m).mean()) for m in range(len(meshes))]
        detail = "; ".join(f"{name}: " + ", ".join(f"{r} {n} x{k}" + (f" ({s} stationary)" if s else "")
                                                   for (r, n), (k, s) in outcome_counts(ds, case, m).items())
                           for m, name in enumerate(mesh_names))
        out.append(Check(
            f"Figure {7 if case == 0 else (9 if case == 1 else 8)} (case {case + 1}): {regime} with {modes} modes from "
            "unseeded starts, on both meshes",
            bool(settled and all(f >= THRESHOLD for f in fractions)),
            ", ".join(f"{name}: {f:.0%} of {ds.sizes['seed']} runs (stationary: {s:.0%})"
                      for name, f, s in zip(mesh_names, fractions, stationary)),
            f">= {THRESHOLD:.0%} on each of two meshes" + ("" if settled else " (not settled: one mesh only)"),
            detail, claim=True))
    regimes = [[_paper_fraction(ds, c, m, modes=False) for m in range(len(meshes))] for c in range(ds.sizes["case"])]
    out.append(Check(
        "the paper's regime types from unseeded starts (any mode number): stick-slip (f = 0.2), "
        "stick-slip-separation (f = 0.7), stick-separation (f = 2), on both meshes",
        bool(settled and all(f >= THRESHOLD for row in regimes for f in row)),
        "; ".join(f"case {c + 1}: " + ", ".join(f"{name} {f:.0%}" for name, f in zip(mesh_names, row))
                  for c, row in enumerate(regimes)),
        f">= {THRESHOLD:.0%} of the runs of each case on each mesh" + ("" if settled else " (not settled: one mesh)"),
        "the same threshold as for regime and mode number together", claim=True))
    outcomes = [len([k for k, (_, s) in outcome_counts(ds, c, m).items() if s]) for c in range(ds.sizes["case"])
                for m in range(len(meshes))]
    out.append(Check("the limit regime depends on the initial condition (paper, section 3.1): unseeded starts of "
                     "one case reach different stationary regimes or mode numbers", bool(max(outcomes) > 1),
                     f"distinct stationary outcomes per case and mesh: {outcomes}", "> 1 for some case and mesh",
                     "random white-noise perturbations, nothing seeded", claim=True))
    if len(meshes) >= 2:
        tops = [[next(iter(outcome_counts(ds, c, m))) for m in range(len(meshes))] for c in range(ds.sizes["case"])]
        out.append(Check("the most frequent outcome of each case does not change with the mesh",
                         all(t[0] == t[-1] for t in tops),
                         "; ".join(f"case {c + 1}: " + " / ".join(f"{r} {n}" for r, n in t) for c, t in enumerate(tops)),
                         f"the same on {mesh_names[0]} and {mesh_names[-1]}", "mesh convergence of the answer",
                         claim=True))
    return out


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Per case, the number of runs ending in each (regime, mode number), per mesh; hatched: not stationary."""
    from matplotlib.patches import Patch

    meshes = _meshes(ds)
    keys = [[] for _ in range(ds.sizes["case"])]
    for case in range(ds.sizes["case"]):
        for m in range(len(meshes)):
            keys[case] += [k for k in outcome_counts(ds, case, m) if k not in keys[case]]
    rows = [0.9 + 0.32 * max(len(k), 1) * max(len(meshes), 1) ** 0.5 for k in keys]
    if fig is None:
        fig = Figure(figsize=(9.0, sum(rows) + 0.8))
    axes = list(fig.subplots(ds.sizes["case"], 1, squeeze=False, height_ratios=rows)[:, 0])
    height = 0.8 / len(meshes)
    for case, ax in enumerate(axes):
        for m, (a, b) in enumerate(meshes):
            counts = outcome_counts(ds, case, m)
            y = np.arange(len(keys[case])) + (m - (len(meshes) - 1) / 2) * height
            runs = np.array([counts.get(k, (0, 0))[0] for k in keys[case]])
            stat = np.array([counts.get(k, (0, 0))[1] for k in keys[case]])
            ax.barh(y, stat, height, color=f"C{m}", label=f"{a} x {b}")
            ax.barh(y, runs - stat, height, left=stat, color=f"C{m}", alpha=0.4, hatch="//", edgecolor="w")
        regime, modes = PAPER_REGIMES[case]
        ax.set_yticks(np.arange(len(keys[case])), [f"{r}, {n} modes" for r, n in keys[case]], fontsize=8)
        ax.invert_yaxis()
        f, d, om = CASES[case]
        ax.set(xlabel="number of runs [1]", ylabel="limit regime",
               title=f"case {case + 1}: f = {f:g}, d = {d * 1e3:g} mm, Ω = {om:g} rad/s; "
                     f"paper: {regime}, {modes} modes")
        ax.title.set_fontsize(9)
    handles, labels = axes[0].get_legend_handles_labels()
    handles.append(Patch(facecolor="0.75", hatch="//", edgecolor="w", label="not stationary (pale, hatched)"))
    plotting.legend_beside(axes[0], handles=handles, title="mesh", title_fontsize=8)
    fig.suptitle(plotting.wrap(f"Limit regimes from unseeded starts ({ds.sizes['seed']} runs per case and mesh); "
                               f"data: {ds.attrs.get('data_source', 'not recorded')[:90]}", 110), fontsize=9)
    return fig


FIGURE = FigureSpec(
    key="brake-fem-statistics", title="Section 3.1 — FE limit regimes from unseeded starts (statistics)",
    model="brake-like system, finite elements",
    claim="Figures 7-10: for the three cases of section 3.1 the limit regime is a stick-slip wave with 4 modes "
          "(f = 0.2), a stick-slip-separation wave with 8 modes (f = 0.7) and a stick-separation wave with 2 modes "
          "(f = 2); the limit regime may depend on the initial condition.",
    method="Runs from FE steady sliding plus white noise (1e-3 δ, one seed per run, nothing seeded), β2 = 0.9, on "
           "256 × 16 and 512 × 32 (the report's meshes), each integrated in chunks of 50 P-wave transits from 100 up "
           "to 300 (256 × 16) or 400 (512 × 32) transits and stopped once its last 2 transits form a stationary "
           "travelling wave (relative misfit and state mismatch of the shifted snapshots < 0.1). The outcome: the "
           "regime of those transits and the mode number counted as the median number of stick zones around the "
           "ring. A claim is reproduced when >= 25 % of the runs on each mesh reach the paper's regime and mode. "
           "The campaign is `stickslip brake campaign` (resumable, about an hour on 2 cores).",
)

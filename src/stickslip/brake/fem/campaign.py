"""Statistics of the FE annulus's limit regimes from unseeded starts (paper section 3.1).

The paper reports one limit regime per case, from one (unstated) start. Here each case is
run from many independent random perturbations of FE steady sliding (white noise of
amplitude ``1e-3 delta``, one seed per run), on several meshes, and each run is driven to a
stated stationarity criterion:

* the run is integrated in chunks of ``chunk`` P-wave transits, from ``min_transits`` up to
  ``max_transits``; after each chunk its last ``window`` transits are classified
  (`classify_fem`), and the run stops as soon as they form a stationary travelling wave
  (relative misfit and state mismatch of the shifted snapshots below 0.1);
* the outcome is the regime of that window and its **mode number counted as the median
  number of stick zones around the ring per snapshot** (``n_zones``: the same count for
  stick-slip, stick-slip-separation and stick-separation), with whether it was stationary.

Two sweeps, both resumable (`stickslip.sweep.run_sweep`, one Zarr store each, and a
checkpoint per run so that a killed run resumes where it stopped):

* `statistics`: over ``(case, mesh, seed)`` at ``beta2 = 0.9`` and the paper's geometry;
* `geometry`: over ``(case, xi, beta2, seed)`` on ``256 x round(32 (xi - 1))`` meshes (the
  radial spacing of the 256 x 16 mesh at ``xi = 1.5``), the paper's open question of the
  ring's thickness and of the scheme's damping.

Cases are given as ``(friction, mismatch [m], Omega [rad/s])`` on the steel ring of
`PhysicalParams` with inner radius 0.1 m.
"""

from __future__ import annotations

import functools
import inspect
import math
import shutil
import time
from pathlib import Path

import numpy as np

from ... import validation as check
from ...quantities import BRAKE as Q
from ...contact import REGIME_CODES, regime_code
from ...contact.runs import held_transits
from ...errors import ParameterError
from ...sweep import run_sweep
from ..reduced import BrakeParams
from .classify import classify_fem
from .run import integrate_fem, perturbed_steady
from .scheme import FemScheme

__all__ = ["OUTCOMES", "limit_regime", "statistics", "geometry", "geometry_mesh", "budget_of", "CANARY_RUNS",
           "CANARY_FIELDS", "CANARY_RTOL", "canary", "canary_changes"]

#: What each run records (name -> units).
OUTCOMES = {"regime": REGIME_CODES, "n_zones": "1", "n_fft": "1", "stationary": "1", "residual": "1", "transits": "1",
            "stick": "1", "slip": "1", "reverse_slip": "1", "separation": "1", "c_over_cp": "1", "seconds": "s"}


def limit_regime(params: BrakeParams, n_theta: int, n_r: int, seed: int, *, beta2: float = 0.9,
                 amplitude: float = 1e-3, chunk: float = 50.0, min_transits: float = 100.0,
                 max_transits: float = 400.0, window: float = 2.0, checkpoint=None) -> dict:
    """Run from FE steady sliding plus white noise (``seed``) to stationarity or ``max_transits``.

    Returns the outcomes of `OUTCOMES` (``regime`` as a code of
    `stickslip.contact.REGIME_CODES`). With ``checkpoint`` (a netCDF path) the run resumes
    from it; it is left in place.
    """
    chunk, min_transits = Q.check("chunk", chunk), Q.check("min_transits", min_transits)
    max_transits = check.at_least("max_transits", Q.check("max_transits", max_transits), min_transits, "min_transits")
    scheme = FemScheme(params, n_theta, n_r, beta2)
    initial = perturbed_steady(scheme, amplitude, seed=int(seed))
    start, T = time.perf_counter(), min_transits
    held = held_transits(checkpoint) if checkpoint is not None else None
    if held is not None and held > min_transits:  # a killed run resumes at the length it had reached
        T = min(max_transits, min_transits + chunk * math.ceil((held - min_transits) / chunk))
    while True:
        run = integrate_fem(params, n_theta, n_r, transits=T, initial=initial, beta2=beta2, tail=window,
                            checkpoint=checkpoint)
        res = classify_fem(run)
        if res.stationary or T >= max_transits:
            break
        T = min(T + chunk, max_transits)
    return {"regime": float(regime_code(res.regime)), "n_zones": float(res.n_zones), "n_fft": float(res.n_fft),
            "stationary": float(res.stationary), "residual": float(res.residual), "transits": float(run.transits),
            **{k: float(res.fractions[k]) for k in ("stick", "slip", "reverse_slip", "separation")},
            "c_over_cp": float(res.c_over_cp), "seconds": time.perf_counter() - start}


def _checkpointed(runs_dir, name: str, params, n_theta: int, n_r: int, seed, **options) -> dict:
    """`limit_regime` with a checkpoint ``<runs_dir>/<name>.nc``, removed once the run is done."""
    folder = Path(runs_dir)
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{name}.nc"
    out = limit_regime(params, n_theta, n_r, int(seed), checkpoint=path, **options)
    path.unlink(missing_ok=True)
    return out


def _statistics_point(cases, meshes, budget, runs_dir, case, mesh, seed) -> dict:
    f, d, om = cases[int(case)]
    return _checkpointed(runs_dir, f"case{int(case)}-mesh{int(mesh)}-seed{int(seed)}",
                         BrakeParams.from_physical(om, d, f), *meshes[int(mesh)], seed, **budget[int(mesh)])


def _check_cases(cases) -> tuple:
    try:
        cases = tuple((float(f), float(d), float(om)) for f, d, om in cases)
    except (TypeError, ValueError):
        raise ParameterError("cases", cases, "a list of (friction, mismatch [m], Omega [rad/s])") from None
    for f, d, om in cases:
        BrakeParams.from_physical(om, d, f)  # validates
    if not cases:
        raise ParameterError("cases", cases, "at least one case")
    return cases


def statistics(store, cases, meshes=((256, 16), (512, 32)), seeds: int = 16, *,
               budgets=({"max_transits": 300.0}, {"max_transits": 400.0}), **options):
    """Limit regimes of each case from ``seeds`` unseeded starts on each mesh (resumable).

    ``meshes`` are ``(n_theta, n_r)``; ``budgets`` the keyword arguments of `limit_regime`
    per mesh; ``options`` go to `run_sweep` (``workers``, ``progress``, ``scheduler``).
    Returns the dataset over ``(case, mesh, seed)``.
    """
    cases = _check_cases(cases)
    meshes = tuple((Q.check("n_theta", a), Q.check("n_r", b)) for a, b in meshes)
    seeds = Q.check("seeds", seeds)
    if len(budgets) != len(meshes):
        raise ParameterError("budgets", budgets, f"one dict per mesh ({len(meshes)})")
    store = Path(store)
    func = functools.partial(_statistics_point, cases, meshes, tuple(dict(b) for b in budgets),
                             str(store.with_suffix(".runs")))
    attrs = {"mesh_n_theta": [m[0] for m in meshes], "mesh_n_r": [m[1] for m in meshes], **_case_attrs(cases),
             **{f"mesh{m}_{k}": float(v) for m, b in enumerate(budgets) for k, v in sorted(dict(b).items())},
             "beta2": 0.9, "mode_number": "median number of stick zones per snapshot (n_zones)",
             "initial": "FE steady sliding + 1e-3 delta white noise (one seed per run)"}
    options.setdefault("batch", max(1, options.get("workers") or 2))
    _fresh_runs(store, options)
    return run_sweep(func, {"case": list(range(len(cases))), "mesh": list(range(len(meshes))),
                            "seed": list(range(seeds))}, store, outputs=OUTCOMES, attrs=attrs,
                     title="FE limit regimes from unseeded starts, per case and mesh", model="brake", **options)


def geometry_mesh(xi: float, n_theta: int = 256) -> tuple[int, int]:
    """``(n_theta, n_r)`` with the radial spacing of ``256 x 16`` at ``xi = 1.5``."""
    return n_theta, max(2, int(round(32 * (Q.check("xi", xi) - 1.0))))


def _geometry_point(cases, n_theta, budget, runs_dir, case, xi, beta2, seed) -> dict:
    f, d, om = cases[int(case)]
    return _checkpointed(runs_dir, f"case{int(case)}-xi{xi:g}-beta2{beta2:g}-seed{int(seed)}",
                         BrakeParams.from_physical(om, d, f, outer_radius=0.1 * xi), *geometry_mesh(xi, n_theta),
                         seed, beta2=beta2, **budget)


def geometry(store, cases, xis=(1.25, 1.5, 2.0, 3.0), beta2s=(0.6, 0.75, 0.9), seeds: int = 4, *,
             n_theta: int = 256, budget=None, **options):
    """Limit regimes of each case over the ring's thickness ``xi`` and ``beta2`` (resumable)."""
    cases = _check_cases(cases)
    xis = [Q.check("xi", x) for x in xis]
    beta2s = [Q.check("beta2", b) for b in beta2s]
    seeds, n_theta = Q.check("seeds", seeds), Q.check("n_theta", n_theta)
    budget = dict(budget or {"max_transits": 300.0})
    store = Path(store)
    func = functools.partial(_geometry_point, cases, n_theta, budget, str(store.with_suffix(".runs")))
    attrs = {"n_theta": n_theta, "budget": budget, **_case_attrs(cases),
             "mesh": "n_theta x round(32 (xi - 1)) (the radial spacing of 256 x 16 at xi = 1.5)",
             "mode_number": "median number of stick zones per snapshot (n_zones)",
             "initial": "FE steady sliding + 1e-3 delta white noise (one seed per run)"}
    options.setdefault("batch", max(1, options.get("workers") or 2))
    _fresh_runs(store, options)
    return run_sweep(func, {"case": list(range(len(cases))), "xi": xis, "beta2": beta2s,
                            "seed": list(range(seeds))}, store, outputs=OUTCOMES, attrs=attrs,
                     title="FE limit regimes over the radius ratio and beta2", model="brake", **options)


def _fresh_runs(store: Path, options: dict) -> None:
    """With ``overwrite``, the runs' checkpoints go with the store (`run_sweep` replaces it)."""
    if options.get("overwrite"):
        shutil.rmtree(store.with_suffix(".runs"), ignore_errors=True)


def budget_of(attrs, mesh: int | None = None) -> dict:
    """The budget of `limit_regime` (``chunk``, ``min_transits``, ``max_transits``, ...) a
    campaign's runs had, from its attributes (``mesh{m}_<key>`` of `statistics`, ``budget_<key>``
    of `geometry`), the defaults filled in."""
    defaults = {k: p.default for k, p in inspect.signature(limit_regime).parameters.items()
                if p.kind is p.KEYWORD_ONLY and isinstance(p.default, float)}
    prefix = "budget_" if mesh is None else f"mesh{mesh}_"
    given = attrs.get("budget") if mesh is None and isinstance(attrs.get("budget"), dict) else {}
    return {k: float(given.get(k, attrs.get(prefix + k, v))) for k, v in defaults.items()}


def _case_attrs(cases) -> dict:
    return {"case_friction": [c[0] for c in cases], "case_mismatch": [c[1] for c in cases],
            "case_omega": [c[2] for c in cases]}


#: The canary of a stored campaign: short seeded runs of its cases, ``(case, xi, beta2)`` on
#: `geometry_mesh` (``xi = 1.5``: the statistics' coarse mesh, 256 x 16), each `CANARY_TRANSITS`
#: P-wave transits from `perturbed_steady` with seed 0. Their numbers (`canary`) are stored
#: with the campaign when it is exported; the present code reproduces them to `CANARY_RTOL` if its
#: numbers are the campaign's (`canary_changes` says which run moved and by how much).
CANARY_RUNS = ((0, 1.5, 0.9), (1, 1.5, 0.9), (2, 1.5, 0.9), (2, 2.0, 0.6))
CANARY_TRANSITS = 1.0
#: Relative tolerance of a canary number, set before the canary was stored (2026-11-28): a
#: relative change of 1e-15 in every displacement at the start (a library's last bit)
#: (three random such changes) moved the numbers by 3e-11 at most over one transit, the state counts not at all.
CANARY_RTOL = 1e-8
#: name -> meaning of the numbers of a canary run, at its end (units of the paper: R, R Omega, E).
CANARY_FIELDS = {"deviation": "|u - u_e|, the displacement's deviation from FE steady sliding (all free dofs)",
                 "velocity": "|v|, the velocity of every free dof",
                 "pressure": "sum of the contact nodes' pressures P", "shear": "sum of their friction shears Q",
                 "energy": "energy of the deviation from FE steady sliding, summed over the run's samples",
                 "stick": "contact nodes sticking", "slip": "contact nodes slipping",
                 "reverse_slip": "contact nodes slipping backwards", "separation": "contact nodes separated"}


def canary(cases, runs=CANARY_RUNS, transits: float = CANARY_TRANSITS) -> dict[str, list[float]]:
    """The numbers of `CANARY_FIELDS` for each canary run (``runs``: ``(case, xi, beta2)``) of
    ``cases`` (``(friction, mismatch [m], Omega [rad/s])``, as `statistics` takes them)."""
    cases = _check_cases(cases)
    out: dict[str, list[float]] = {name: [] for name in CANARY_FIELDS}
    for case, xi, beta2 in runs:
        f, d, om = cases[int(case)]
        params = BrakeParams.from_physical(om, d, f, outer_radius=0.1 * xi)
        n_theta, n_r = geometry_mesh(xi)
        initial = perturbed_steady(FemScheme(params, n_theta, n_r, beta2), 1e-3, seed=0)
        run = integrate_fem(params, n_theta, n_r, transits=transits, initial=initial, beta2=beta2,
                            tail=min(transits, 2.0))
        state = np.asarray(run.state[-1], dtype=int)
        numbers = {"deviation": np.linalg.norm(run.kernel["u"] - run.kernel["ref"]),
                   "velocity": np.linalg.norm(run.kernel["v"]), "pressure": np.sum(run.P[-1]),
                   "shear": np.sum(run.Q[-1]), "energy": np.sum(run.energy),
                   **dict(zip(("stick", "slip", "reverse_slip", "separation"), np.bincount(state, minlength=4)))}
        for name in CANARY_FIELDS:
            out[name].append(float(numbers[name]))
    return out


def canary_changes(stored: dict, fresh: dict, runs=CANARY_RUNS, cases=None, rtol: float = CANARY_RTOL) -> list[str]:
    """What moved between a stored canary and a fresh one: one line per run and number beyond
    ``rtol`` (relative to the stored number), naming the run; empty when nothing moved."""
    changes = []
    for name in CANARY_FIELDS:
        old, new = np.asarray(stored.get(name, []), float), np.asarray(fresh[name], float)
        if old.shape != new.shape:
            return [f"the stored canary has {old.size} runs of {name}, the present one {new.size}"]
        for k, (a, b) in enumerate(zip(old, new)):
            if not abs(b - a) <= rtol * abs(a):
                case, xi, beta2 = runs[k]
                what = f"case {int(case) + 1}" + ("" if cases is None else
                                                   " (f = {:g}, d = {:g} m, Omega = {:g} rad/s)".format(*cases[int(case)]))
                n_theta, n_r = geometry_mesh(xi)
                changes.append(f"{what} on {n_theta} x {n_r} (xi {xi:g}, beta2 {beta2:g}): {name} {a:.10g} -> {b:.10g} "
                               f"(relative {abs(b - a) / abs(a) if a else float('inf'):.2g}, tolerance {rtol:g})")
    return changes

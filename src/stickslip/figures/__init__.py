"""The paper's figures for `stickslip reproduce`: one module per figure, one registry.

A figure module (``figures/<model>/<figure>.py``) holds everything about its figure:

* ``compute(quick: bool) -> xarray.Dataset``: all the numbers the figure needs (no
  plotting); it may take a ``cache`` folder to resume a sweep point by point, and the
  report's ``data_dir`` to find data computed outside `reproduce` (then it also defines
  ``inputs(data_dir) -> str``, a fingerprint of those data);
* ``check(ds) -> list[Check]``: the paper's claim and the verification of the computation,
  measured in the dataset alone;
* ``plot(ds, fig=None) -> matplotlib.figure.Figure``: draws the dataset on ``fig`` (or a new
  figure) and returns it, without pyplot or a change of backend;
* ``FIGURE = FigureSpec(...)``: its key, title, claim and method for the report (the
  registry adds the module's ``compute``, ``check`` and ``plot``).

`FIGURES` below lists the modules in the paper's order: it is the registry. Computing
apart from plotting lets `reproduce` checkpoint each dataset to netCDF and resume a
killed run without recomputing it. To add a figure: write the module, add it to
`FIGURES`.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass, field, replace
from typing import Callable

import lazy_loader as lazy

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["Check", "FigureSpec", "close_check", "registry", "FIGURES"]

#: The figure modules (relative to this package), in the order of the report.
FIGURES = ("oscillator.fig2", "oscillator.fig3", "oscillator.bifurcation", "oscillator.regimes",
           "brake.stability", "brake.fig5", "brake.fig6", "brake.fig11", "brake.fig12", "brake.waves_vs_ring",
           "brake.wave_stability",
           "brake.ring_regimes", "brake.initial_condition", "brake.regime_maps", "brake.fig7", "brake.fig8",
           "brake.fig9", "brake.fig10", "brake.fem_statistics", "brake.fem_geometry", "brake.fem_regimes",
           "halfspace.fig14", "halfspace.inverse_map",
           "halfspace.direct_map", "beyond.rsf_slider", "beyond.squeal", "beyond.flutter", "beyond.adams",
           "beyond.regimes", "beyond.wave_in_time")


@dataclass(frozen=True)
class Check:
    """One verified statement: what was expected, what was measured, and the verdict.

    ``claim=True`` marks a claim of the paper that our computation may legitimately not
    reproduce (a scientific finding, reported as "not reproduced"); other checks verify
    the computation itself, and a failure there is a failure of the run.
    """

    name: str
    passed: bool
    measured: str
    expected: str
    detail: str = ""
    claim: bool = False


@dataclass(frozen=True)
class FigureSpec:
    """A reproducible figure: the paper's claim and how it is computed, plotted and checked."""

    key: str
    title: str
    model: str
    claim: str
    method: str
    errata: tuple[str, ...] = field(default_factory=tuple)
    data_from: str | None = None  # reuse the dataset (and checkpoint) of another figure
    compute: Callable[[bool], xr.Dataset] | None = None
    plot: Callable | None = None
    check: Callable[[xr.Dataset], list[Check]] | None = None
    inputs: Callable | None = None  # inputs(data_dir) -> str: fingerprint of data from outside the package
    describe: Callable[[xr.Dataset], str] | None = None  # what was computed, for the data actually used
    #: seconds its full computation took on the 2-core machine (2026-11-28, a fresh clone): the order
    #: in which a first run starts the figures (later runs use their own records)
    cost: float = 0.0


def _spec(name: str) -> FigureSpec:
    module = importlib.import_module(f"{__name__}.{name}")
    return replace(module.FIGURE, compute=getattr(module, "compute", None), plot=module.plot, check=module.check,
                   inputs=getattr(module, "inputs", None), describe=getattr(module, "describe", None))


def registry() -> dict[str, FigureSpec]:
    """All figures by key, in the order of `FIGURES`."""
    specs = [_spec(name) for name in FIGURES]
    return {spec.key: spec for spec in specs}


def close_check(name: str, measured: float, expected: float, rtol: float = 0.0, atol: float = 0.0,
                detail: str = "") -> Check:
    """A `Check` that ``|measured - expected| <= atol + rtol |expected|``."""
    err = abs(measured - expected)
    bound = atol + rtol * abs(expected)
    return Check(name, bool(err <= bound), f"{measured:.12g}", f"{expected:.12g} (tolerance {bound:.2g})",
                 detail or f"|difference| = {err:.3g}")

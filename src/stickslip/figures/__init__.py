"""Registry of the paper's figures for `stickslip reproduce`.

Each figure module defines three functions and registers them:

* ``compute(quick: bool) -> xarray.Dataset``: all numbers the figure needs (no plotting);
* ``plot(ds, path)``: draws the PNG from the dataset alone;
* ``check(ds) -> list[Check]``: tests the paper's claim against the computed numbers.

Computation is separated from plotting so that `reproduce` can checkpoint each
dataset to netCDF and resume a killed run without recomputing it.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass, field
from typing import Callable

import xarray as xr

__all__ = ["Check", "FigureSpec", "register", "registry"]

_MODULES = ["fig2", "fig3", "oscillator_bifurcation", "oscillator_regimes", "brake_stability", "brake_waves", "brake_ring", "brake_regimes", "brake_fem", "halfspace"]
_REGISTRY: dict[str, "FigureSpec"] = {}


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
    """A reproducible figure: the paper's claim and how it is computed and checked."""

    key: str
    title: str
    model: str
    claim: str
    method: str
    compute: Callable[[bool], xr.Dataset] | None
    plot: Callable[[xr.Dataset, object], None]
    check: Callable[[xr.Dataset], list[Check]]
    errata: tuple[str, ...] = field(default_factory=tuple)
    data_from: str | None = None  # reuse the dataset (and checkpoint) of another figure


def register(spec: FigureSpec) -> FigureSpec:
    _REGISTRY[spec.key] = spec
    return spec


def registry() -> dict[str, FigureSpec]:
    """All registered figures, in the paper's order."""
    for name in _MODULES:
        importlib.import_module(f"{__name__}.{name}")
    return dict(_REGISTRY)


def close_check(name: str, measured: float, expected: float, rtol: float = 0.0, atol: float = 0.0,
                detail: str = "") -> Check:
    """A `Check` that ``|measured - expected| <= atol + rtol |expected|``."""
    err = abs(measured - expected)
    bound = atol + rtol * abs(expected)
    return Check(name, bool(err <= bound), f"{measured:.12g}", f"{expected:.12g} (tolerance {bound:.2g})",
                 detail or f"|difference| = {err:.3g}")

"""Stability of steady sliding and its Hopf (flutter) points.

About the equilibrium ``k x_e = N mu(V)`` the oscillator reads, with ``y = x'``,

    m x'' + k (x - x_e) = -(d1 y + d2 y^2 + d3 y^3) + ...,
    d1 = c + N mu'(V),  d2 = -N mu''(V)/2,  d3 = N mu'''(V)/6.

``d1 < 0`` is the paper's negative damping (``-f_d tau N`` for the linear law). At
``d1 = 0`` the eigenvalues are ``+-i w``: a Hopf point. The first Lyapunov coefficient
of this Lienard system is ``-3 d3 / (8 m)`` (the quadratic term does not enter), so the
bifurcation is subcritical when ``d3 < 0`` (as for the Stribeck law). Averaging gives
the small cycle's amplitude ``A^2 = -4 d1 / (3 d3 w^2)``.
"""

from __future__ import annotations

from typing import ClassVar

import math
from dataclasses import dataclass

import numpy as np
import scipy  # scipy.optimize loads on first use

from ..results import Result
from ..errors import ParameterError
from ..quantities import OSCILLATOR as Q, lookup
from .model import Oscillator
from .. import validation as check

__all__ = ["EquilibriumStability", "HopfPoint", "equilibrium_stability", "hopf_points", "damping_coefficients"]


def damping_coefficients(osc: Oscillator, h: float | None = None) -> tuple[float, float]:
    """``(d1, d3)`` of the expansion above; ``mu'''`` by central differences of the slope."""
    V, N = osc.belt_speed, osc.normal_force
    h = 1e-3 * V if h is None else h
    slope = osc.friction.slope
    d1 = osc.damping + N * float(slope(V))
    mid = float(slope(V))
    mu3 = ((float(slope(V + h)) - mid) / h - (mid - float(slope(V - h))) / h) / h  # h**2 may leave range
    return d1, N * mu3 / 6.0


@dataclass(frozen=True, repr=False)
class EquilibriumStability(Result):
    """Linear stability of steady sliding (the mass at rest, the belt slipping under it)."""

    MODEL: ClassVar[str] = "oscillator"

    x_e: float
    eigenvalues: np.ndarray
    effective_damping: float

    @property
    def stable(self) -> bool:
        return bool(np.all(self.eigenvalues.real < 0))

    @property
    def kind(self) -> str:
        re, im = self.eigenvalues.real, self.eigenvalues.imag
        if np.all(re == 0):
            return "centre"
        if np.any(im != 0):
            return "stable focus" if np.all(re < 0) else "unstable focus"
        return "stable node" if np.all(re < 0) else "unstable node"

    def to_dict(self) -> dict:
        return {"x_e": self.x_e, "effective_damping": self.effective_damping, "stable": self.stable,
                "kind": self.kind, "eigenvalues": [[float(e.real), float(e.imag)] for e in self.eigenvalues]}


def equilibrium_stability(osc: Oscillator) -> EquilibriumStability:
    """Equilibrium position, eigenvalues and effective damping ``c + N mu'(V)``."""
    check.instance("osc", osc, Oscillator, "a stickslip.oscillator.Oscillator")
    return EquilibriumStability(osc.equilibrium, np.sort_complex(osc.equilibrium_eigenvalues()),
                                osc.effective_damping)


@dataclass(frozen=True, repr=False)
class HopfPoint(Result):
    """A parameter value where the effective damping vanishes."""

    MODEL: ClassVar[str] = "oscillator"

    parameter: str
    value: float
    frequency: float
    d3: float

    @property
    def criticality(self) -> str:
        if self.d3 == 0 or not math.isfinite(self.d3):
            return "degenerate"
        return "subcritical" if self.d3 < 0 else "supercritical"

    def to_dict(self) -> dict:
        return {"parameter": self.parameter, "value": self.value, "frequency": self.frequency,
                "d3": self.d3, "criticality": self.criticality}

    def to_xarray(self):
        """The Hopf point's numbers, ``value`` in the units of its parameter."""
        ds = Result.to_xarray(self)
        ds["value"].attrs.update(units=(lookup(self.parameter, "oscillator") or ("1",))[0],
                                 long_name=f"{self.parameter} at the Hopf point")
        return ds


def hopf_points(osc: Oscillator, parameter: str, lo: float, hi: float, num: int = 400) -> list[HopfPoint]:
    """All Hopf points for ``parameter`` in ``[lo, hi]``: sign changes of ``d1``, refined by Brent.

    For the linear-weakening law ``d1 = c - f_d tau N`` does not depend on ``V``; its
    Hopf point is in the damping, ``c_H = f_d tau N`` (or in ``tau``, ``N``).
    """
    check.instance("osc", osc, Oscillator, "a stickslip.oscillator.Oscillator")
    osc.parameter(parameter)
    lo, hi = Q.check("lo", lo), Q.check("hi", hi)
    if not lo < hi:
        raise ParameterError("hi", hi, f"> lo = {lo:g}", also=("lo",))
    for name, end in (("lo", lo), ("hi", hi)):  # the scan stays where the parameter is valid
        try:
            osc.with_parameter(parameter, end)
        except ParameterError as err:
            raise ParameterError(name, end, f"a valid {parameter}, {err.allowed}") from None
    num = Q.check("num", num)

    def d1(p):
        return osc.with_parameter(parameter, p).effective_damping

    grid = np.linspace(lo, hi, num + 1)
    values = [d1(p) for p in grid]
    points = []
    for a, b, fa, fb in zip(grid[:-1], grid[1:], values[:-1], values[1:]):
        if fa == 0 or fa * fb < 0:
            p = a if fa == 0 else scipy.optimize.brentq(d1, a, b, xtol=1e-14 * max(1.0, abs(b)), rtol=1e-15)
            at = osc.with_parameter(parameter, p)
            points.append(HopfPoint(parameter, p, at.omega, damping_coefficients(at)[1]))
    return points

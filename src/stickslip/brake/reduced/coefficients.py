"""Coefficients of the reduced model (paper eqs. [12]-[13]).

With ``u = X(r) U(theta, t)``, ``v = X(r) V(theta, t)`` and
``X(r) = (xi^2/r - r)/(xi^2 - 1)`` (the static Lamé profile, ``X(1) = 1``,
``X(xi) = 0``), the virtual-work equation restricted to these fields gives (the
second derivatives of the printed [12] are swapped; see ``docs/errata_brake_draft.md``)

    U_tt - b U'' - D V' + g U = P,
    V_tt - a V'' + D U' + h V = Q,          (' = d/dtheta)

    a = ã A/(gamma B),  b = b̃ A/(gamma B),  g = (2ã + 2(xi^2-1) b̃)/(gamma B),
    h = 2 xi^2 b̃/(gamma B),  D = (ã C1 - b̃ C2)/(gamma B) = (a C1 - b C2)/A,

    ã = (1-nu)/((1+nu)(1-2nu)) = (lambda + 2 mu)/E,   b̃ = 1/(2(1+nu)) = mu/E,
    A = (xi^2-1) int X^2/r dr,  B = (xi^2-1) int X^2 r dr,  C1 = (xi^2-1)(1/2 - int X^2/r dr),
    C2 = (xi^2-1)(3/2 + int X^2/r dr)   (integrals over 1 < r < xi),

which are the printed closed forms of [13]. ``P`` and ``Q`` are the contact pressure and
shear (``p = -sigma_rr(1)``, ``q = -sigma_rtheta(1)``, in units of ``E``) divided by the
modal mass ``M = gamma int X^2 r dr = gamma B/(xi^2 - 1)``: ``p = M P``, ``q = M Q``.
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy
from scipy.optimize import brentq

from ...results import Result
from ...cf import finish
from ...quantities import BRAKE as Q
from ... import validation as check
from ...errors import ParameterError

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["ReducedCoefficients", "coefficients", "shape_integrals", "coupling", "neutral_radius_ratio"]


def shape_integrals(xi):
    """``(A, B, C1, C2)`` of [13] (vectorised over ``xi > 1``; all positive)."""
    xi = check.finite_array("xi", xi)
    if (xi <= 1.0).any() or (xi > 1e150).any():  # beyond, xi^2 overflows
        raise ParameterError("xi", xi.tolist() if xi.size <= 8 else f"{xi.size} values", "in (1, 1e150] (outer over "
                             "inner radius)")
    xi = np.asarray(xi, dtype=float)
    e = xi**2 - 1.0
    ell = (1.0 + e) * np.log1p(e) / e  # = 2 xi^2 ln(xi) / (xi^2 - 1)
    A = -ell + (1.0 + xi**2) / 2.0
    B = xi**2 * ell / 2.0 + (1.0 - 3.0 * xi**2) / 4.0
    return A, B, ell - 1.0, -ell - 1.0 + 2.0 * xi**2


def elastic_moduli(nu):
    """``(ã, b̃) = ((lambda + 2 mu)/E, mu/E)``."""
    nu = check.finite_array("nu", nu)
    if ((nu <= -1.0) | (nu >= 0.5)).any():
        raise ParameterError("nu", nu.tolist() if nu.size <= 8 else f"{nu.size} values", "in (-1, 0.5) (Poisson's ratio)")
    nu = np.asarray(nu, dtype=float)
    return (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)), 1.0 / (2.0 * (1.0 + nu))


def coupling(xi, nu):
    """``gamma B D = ã C1 - b̃ C2``: the sign and size of the U-V coupling, free of ``gamma``."""
    xi, nu = check.finite_array("xi", xi), check.finite_array("nu", nu)
    _, _, C1, C2 = shape_integrals(xi)
    at, bt = elastic_moduli(nu)
    return at * C1 - bt * C2


@dataclass(frozen=True, repr=False)
class ReducedCoefficients(Result):
    """Coefficients of the reduced equations [12] (corrected) for given ``(xi, nu, gamma)``."""

    MODEL: ClassVar[str] = "brake"

    xi: float
    nu: float
    gamma: float
    a: float
    b: float
    g: float
    h: float
    D: float
    A: float
    B: float
    C1: float
    C2: float

    @property
    def modal_mass(self) -> float:
        """``M = gamma B / (xi^2 - 1)``: contact pressure ``p = M P`` (units of ``E``)."""
        return self.gamma * self.B / (self.xi**2 - 1.0)

    def to_dict(self) -> dict:
        return {k: float(getattr(self, k)) for k in ("a", "b", "g", "h", "D", "A", "B", "C1", "C2")}

    def to_xarray(self) -> xr.Dataset:
        data = {k: ((), v, {"units": "1", "long_name": f"coefficient {k} of eq. [13]"})
                for k, v in self.to_dict().items()}
        ds = xr.Dataset(data, attrs={"xi": self.xi, "nu": self.nu, "gamma": self.gamma,
                                     "modal_mass": self.modal_mass, "source": "paper eq. [13]"})
        return finish(ds, "coefficients of the reduced model", "brake")


def coefficients(xi: float, nu: float, gamma: float) -> ReducedCoefficients:
    """The coefficients ``a, b, g, h, D, A, B, C1, C2`` of eq. [13].

    Parameters
    ----------
    xi : float
        Radius ratio ``R*/R`` > 1.
    nu : float
        Poisson's ratio in [0, 0.5).
    gamma : float
        ``rho R^2 Omega^2 / E`` > 0.
    """
    xi, nu, gamma = Q.check("xi", xi), Q.check("nu", nu), Q.check("gamma", gamma)
    A, B, C1, C2 = (float(v) for v in shape_integrals(xi))
    at, bt = (float(v) for v in elastic_moduli(nu))
    gB = gamma * B
    return ReducedCoefficients(xi, nu, gamma, a=at * A / gB, b=bt * A / gB,
                               g=(2.0 * at + 2.0 * (xi**2 - 1.0) * bt) / gB, h=2.0 * xi**2 * bt / gB,
                               D=(at * C1 - bt * C2) / gB, A=A, B=B, C1=C1, C2=C2)


def neutral_radius_ratio(nu: float) -> float | None:
    """The radius ratio ``xi*`` where ``D = 0`` (no flutter), or None if there is none.

    ``C2/C1`` grows from 3 (at ``xi -> 1``) to infinity, and ``D = 0`` where it equals
    ``ã/b̃ = 2(1-nu)/(1-2nu)``. So ``xi*`` exists iff ``nu > 1/4``; then ``D > 0`` for
    ``1 < xi < xi*`` and ``D < 0`` beyond. For ``nu <= 1/4``, ``D < 0`` for every ``xi``.
    """
    nu = Q.check("nu", nu)
    if nu <= 0.25:
        return None
    f = lambda x: float(coupling(x, nu))  # noqa: E731
    lo, hi = 1.0 + 1e-6, 2.0
    while f(hi) > 0.0:
        lo, hi = hi, 2.0 * hi
    if f(lo) <= 0.0:  # nu so close to 1/4 that xi* is within 1e-6 of 1
        return lo
    return brentq(f, lo, hi, xtol=1e-14, rtol=1e-13)

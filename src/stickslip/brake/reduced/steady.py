"""Steady sliding of the annulus on the shaft (paper eqs. [11] and [16]).

All points slip forward (``1 - v_t = 1 > 0``), so ``q = f p`` everywhere, and nothing
depends on ``theta`` or ``t``: the steady state is the static plane-strain Lamé solution
of the annulus ``1 < r < xi`` clamped at ``r = xi``, with ``u(1) = delta`` imposed by
the shaft and a uniform shear traction ``q = f p`` on ``r = 1``:

    u_e = delta X(r),   v_e = V_e X(r),   X(r) = (xi^2/r - r)/(xi^2 - 1),
    p_e = -sigma_rr(1) = delta (xi^2 + 1/(1 - 2 nu)) / ((1 + nu)(xi^2 - 1)) > 0,
    q_e = -sigma_rtheta(1) = f p_e,
    V_e = v_e(1) = f delta (1 + 1/(xi^2 (1 - 2 nu))) = f delta g/h.

(The printed [11] has ``mu`` for ``nu`` and ``1/(1 - xi^2)`` for ``1/(xi^2 - 1)``, which
makes ``p_e < 0``.) Stresses are in units of ``E`` and lengths in units of ``R``.
Because ``X`` is the exact static profile, the reduced model [12] has the same steady
state, [16]: ``U_e = delta``, ``V_e = delta f g/h``, ``P_e = g delta``, ``Q_e = f P_e``,
with ``p_e = M P_e`` (``M`` the modal mass of `ReducedCoefficients`).
"""

from __future__ import annotations

from typing import ClassVar

import math
from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy

from ...results import Result
from ...cf import finish
from ...quantities import BRAKE as Q
from .coefficients import coefficients, elastic_moduli

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["SteadySliding", "steady_sliding"]


@dataclass(frozen=True, repr=False)
class SteadySliding(Result):
    """The steady-sliding state: Lamé fields [11] and reduced-model values [16]."""

    MODEL: ClassVar[str] = "brake"

    xi: float
    nu: float
    delta: float
    friction: float
    p_e: float
    q_e: float
    U_e: float
    V_e: float
    gamma: float | None = None
    P_e: float = math.nan
    Q_e: float = math.nan

    def shape(self, r):
        """``X(r) = (xi^2/r - r)/(xi^2 - 1)``."""
        r = np.asarray(r, dtype=float)
        return (self.xi**2 / r - r) / (self.xi**2 - 1.0)

    def u(self, r):
        """Radial displacement ``u_e(r)`` (units of ``R``)."""
        return self.delta * self.shape(r)

    def v(self, r):
        """Tangential displacement ``v_e(r)`` (units of ``R``)."""
        return self.V_e * self.shape(r)

    def stress(self, r):
        """``(sigma_rr, sigma_thth, sigma_rth, sigma_zz)`` at radius ``r`` (units of ``E``)."""
        r = np.asarray(r, dtype=float)
        at, bt = (float(x) for x in elastic_moduli(self.nu))
        lam = at - 2.0 * bt
        k = self.xi**2 - 1.0
        dX, X_r = -(self.xi**2 / r**2 + 1.0) / k, (self.xi**2 / r**2 - 1.0) / k  # X', X/r
        e_rr, e_tt = self.delta * dX, self.delta * X_r
        s_rth = bt * self.V_e * (dX - X_r)
        return at * e_rr + lam * e_tt, lam * e_rr + at * e_tt, s_rth, lam * (e_rr + e_tt)

    def to_dict(self) -> dict:
        out = {"p_e": self.p_e, "q_e": self.q_e, "U_e": self.U_e, "V_e": self.V_e}
        if self.gamma is not None:
            out.update(P_e=self.P_e, Q_e=self.Q_e)
        return out

    def to_xarray(self, num: int = 101) -> xr.Dataset:
        """Radial profiles of displacements and stresses, scalars in ``attrs``."""
        r = np.linspace(1.0, self.xi, Q.check("points", num, "num"))
        s_rr, s_tt, s_rt, s_zz = self.stress(r)
        unit_l, unit_s = {"units": "R"}, {"units": "E"}
        ds = xr.Dataset(
            {"u": ("r", self.u(r), {**unit_l, "long_name": "radial displacement u_e"}),
             "v": ("r", self.v(r), {**unit_l, "long_name": "tangential displacement v_e"}),
             "sigma_rr": ("r", s_rr, unit_s), "sigma_thth": ("r", s_tt, unit_s),
             "sigma_rth": ("r", s_rt, unit_s), "sigma_zz": ("r", s_zz, unit_s)},
            coords={"r": ("r", r, {"units": "R", "long_name": "radius"})})
        ds.attrs.update({"xi": self.xi, "nu": self.nu, "delta": self.delta, "friction": self.friction,
                         **{k: float(v) for k, v in self.to_dict().items()},
                         "source": "paper eqs. [11] and [16], corrected"})
        if self.gamma is not None:
            ds.attrs["gamma"] = self.gamma
        for name, long_name in (("sigma_rr", "radial stress"), ("sigma_thth", "hoop stress"),
                                ("sigma_rth", "shear stress"), ("sigma_zz", "axial stress")):
            ds[name].attrs["long_name"] = long_name
        return finish(ds, "steady sliding of the annulus (closed form)", "brake")


def steady_sliding(xi: float, nu: float, delta: float, friction: float,
                   gamma: float | None = None) -> SteadySliding:
    """Steady sliding, eqs. [11] and [16] (corrected).

    Parameters
    ----------
    xi, nu, delta, friction : float
        ``xi > 1``, ``0 <= nu < 0.5``, ``delta >= 0``, ``f >= 0``.
    gamma : float, optional
        ``rho R^2 Omega^2/E > 0``; if given, the reduced pressures ``P_e, Q_e`` of [16]
        are filled in (``p_e, q_e, U_e, V_e`` do not depend on it).
    """
    xi, nu = Q.check("xi", xi), Q.check("nu", nu)
    delta, f = Q.check("delta", delta), Q.check("friction", friction)
    p_e = delta * (xi**2 + 1.0 / (1.0 - 2.0 * nu)) / ((1.0 + nu) * (xi**2 - 1.0))
    V_e = f * delta * (1.0 + 1.0 / (xi**2 * (1.0 - 2.0 * nu)))
    extra = {}
    if gamma is not None:
        c = coefficients(xi, nu, gamma)
        extra = {"gamma": c.gamma, "P_e": c.g * delta, "Q_e": f * c.g * delta}
    return SteadySliding(xi, nu, delta, f, p_e=p_e, q_e=f * p_e, U_e=delta, V_e=V_e, **extra)

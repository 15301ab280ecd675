"""Remote loading of the half-space (eqs [24]-[26], [40]).

The half-space is loaded by remote stresses ``tau*_yy < 0`` (compression) and
``tau*_xy = -mu* tau*_yy > 0`` with ``0 <= mu* < mu``. In plane strain with
``tau*_xx = 0`` (and ``sigma_zz = nu tau*_yy``) the remote strain is

    eps*_xx = -nu (1 + nu) tau*_yy / E > 0                      [25]

(plane stress would give ``-nu tau*_yy / E``), and the paper defines

    V* = -c eps*_xx = c nu (1 + nu) tau*_yy / E > 0             [26]

(``c < 0``). The driving traction of the slip condition [40] is

    T* = -tau*_xy - mu tau*_yy = (mu - mu*)(-tau*_yy) > 0.

Scaled (``E = 2 G (1 + nu)``): ``v* = V*/c2 = cbar nu (tau*_yy/G) / 2`` and
``T = T*/G = (mu - mu*)(-tau*_yy/G)``. So for given ``(cbar, v*)``, [26] fixes
``tau*_yy/G = 2 v*/(cbar nu)`` and then ``T``: this is how the paper's Figure 14 fixes
``b`` from ``cbar`` (see `stickslip.halfspace.b_for_loading`).
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass

from ..results import Result
from ..quantities import HALFSPACE as Q
from ..errors import ParameterError

__all__ = ["remote_strain", "v_star_from_stress", "stress_from_v_star", "driving_traction",
           "stresses_from_T", "Loading", "loading_from_wave"]


def _tau_yy(tau_yy) -> float:
    t = Q.check("tau_yy", tau_yy)
    return t


def _mu_pair(mu, mu_star) -> tuple[float, float]:
    mu = Q.check("mu", mu)
    mu_star = Q.check("mu_star", mu_star)
    if mu_star >= mu:
        raise ParameterError("mu_star", mu_star, f"< mu = {mu:g} (apparent friction below the local one)")
    return mu, mu_star


def remote_strain(tau_yy, young, nu, *, plane: str = "strain") -> float:
    """``eps*_xx`` under ``tau*_yy`` alone: [25] in plane strain, ``-nu tau/E`` in plane stress."""
    t = _tau_yy(tau_yy)
    E = Q.check("young", young)
    nu = Q.check("nu", nu)
    return (-nu * (1.0 + nu) if Q.check("plane", plane) == "strain" else -nu) * t / E


def v_star_from_stress(cbar, tau_yy_over_G, nu) -> float:
    """``v* = V*/c2 = cbar nu (tau*_yy/G)/2`` ([26] scaled); > 0 for ``cbar, tau < 0``."""
    c = Q.check("cbar", cbar, "c")
    return c * Q.check("nu", nu) * _tau_yy(tau_yy_over_G) / 2.0


def stress_from_v_star(cbar, v_star, nu) -> float:
    """``tau*_yy/G = 2 v*/(cbar nu)``: [26] solved for the remote normal stress (``nu > 0``)."""
    c = Q.check("cbar", cbar, "c")
    vs = Q.check("v_star", v_star)
    nu = Q.check("nu", nu)
    if nu == 0.0:
        raise ParameterError("nu", nu, "> 0 here: with nu = 0, [26] gives V* = 0 for every tau*_yy")
    return 2.0 * vs / (c * nu)


def driving_traction(tau_yy, tau_xy, mu) -> float:
    """``T* = -tau*_xy - mu tau*_yy`` ([40]); any consistent unit (or scaled by ``G``)."""
    mu = Q.check("mu", mu)
    return -Q.check("tau_xy", tau_xy) - mu * _tau_yy(tau_yy)


def stresses_from_T(T, mu, mu_star) -> tuple[float, float]:
    """``(tau*_yy, tau*_xy)`` (same scaling as ``T``) from ``T = (mu - mu*)(-tau*_yy)``
    and ``tau*_xy = -mu* tau*_yy``."""
    T = Q.check("T", T)
    mu, mu_star = _mu_pair(mu, mu_star)
    tau_yy = -T / (mu - mu_star)
    return tau_yy, -mu_star * tau_yy


@dataclass(frozen=True, repr=False)
class Loading(Result):
    """Scaled loading of a wave: ``T = T*/G``, ``v* = V*/c2``, remote stresses over ``G``."""

    MODEL: ClassVar[str] = "halfspace"

    cbar: float
    nu: float
    mu: float
    mu_star: float
    tau_yy: float
    tau_xy: float
    T: float
    v_star: float

    def to_dict(self) -> dict:
        return dict(self.__dict__)


def loading_from_wave(cbar, v_star, *, nu, mu, mu_star) -> Loading:
    """The loading implied by a wave speed and ``v*`` through [26] (as for Figure 14).

    ``tau*_yy/G = 2 v*/(cbar nu)``, ``tau*_xy = -mu* tau*_yy``,
    ``T = (mu - mu*)(-tau*_yy/G)``.
    """
    mu, mu_star = _mu_pair(mu, mu_star)
    tau_yy = stress_from_v_star(cbar, v_star, nu)
    tau_xy = -mu_star * tau_yy
    T = driving_traction(tau_yy, tau_xy, mu)
    return Loading(cbar=float(cbar), nu=float(nu), mu=mu, mu_star=mu_star, tau_yy=tau_yy,
                   tau_xy=tau_xy, T=T, v_star=float(v_star))

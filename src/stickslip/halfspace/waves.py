"""Wave speeds and the Radok coefficients of a steady subsonic wave (paper section 4.1).

Plane strain, isotropic, homogeneous half-space. In the frame ``x = X - c t`` moving
with the wave the Radok variables are ``z_k = x + i beta_k y`` with (paper, after [26])

    beta1 = sqrt(1 - c^2/c1^2),   beta2 = sqrt(1 - c^2/c2^2),

and the interface quantities of section 4.2 are

    gamma1 = beta1 (1 - beta2^2),   gamma2 = 1 + beta2^2 - 2 beta1 beta2,
    tan(pi alpha) = mu gamma2 / gamma1,   0 < alpha < 1/2.

``alpha`` is never defined in the paper (it prints "tan(alpha pi) = 0"); it is the
exponent of the Riemann-Hilbert problem [41]: ``g = -exp(2 i pi alpha)`` in [42].
Everything is in the paper's scaling: speeds in units of ``c2``, ``cbar = c/c2``.
"""

from __future__ import annotations

from typing import ClassVar

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..results import Result
from ..quantities import HALFSPACE as Q
from .arrays import cbar_array

__all__ = ["Material", "wave_speed_ratio", "rayleigh_speed_ratio", "rayleigh_function", "Radok", "radok"]


def wave_speed_ratio(nu) -> float:
    """``c1/c2 = sqrt(2 (1 - nu) / (1 - 2 nu))`` in plane strain (``0 <= nu < 1/2``)."""
    nu = Q.check("nu", nu)
    return math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu))


def rayleigh_function(xi, c1bar):
    """Rayleigh's function ``(2 - xi^2)^2 - 4 sqrt(1 - xi^2) sqrt(1 - xi^2/c1bar^2)``."""
    return (2.0 - xi**2) ** 2 - 4.0 * np.sqrt(1.0 - xi**2) * np.sqrt(1.0 - xi**2 / c1bar**2)


def rayleigh_speed_ratio(nu) -> float:
    """``c_R / c2``: the root in (0, 1) of Rayleigh's equation (plane strain).

    Rayleigh's function divided by ``xi^2`` is negative near 0 and equals 1 at
    ``xi = 1``, with a single root in between; it is bracketed in (0.5, 1).
    """
    c1bar = wave_speed_ratio(nu)
    return brentq(lambda xi: rayleigh_function(xi, c1bar) / xi**2, 0.5, 1.0, xtol=1e-15, rtol=1e-15)


@dataclass(frozen=True, repr=False)
class Material(Result):
    """Isotropic elastic material, SI units.

    Parameters
    ----------
    young : float
        Young's modulus ``E`` [Pa] > 0.
    poisson : float
        Poisson's ratio ``nu`` in [0, 0.5).
    density : float
        Mass density ``rho`` [kg/m^3] > 0.
    """

    MODEL: ClassVar[str] = "halfspace"

    young: float = 2.1e11
    poisson: float = 0.3
    density: float = 7850.0

    def __post_init__(self):
        object.__setattr__(self, "young", Q.check("young", self.young))
        object.__setattr__(self, "poisson", Q.check("poisson", self.poisson))
        object.__setattr__(self, "density", Q.check("density", self.density))

    @property
    def shear_modulus(self) -> float:
        """``G = E / (2 (1 + nu))`` [Pa]."""
        return self.young / (2.0 * (1.0 + self.poisson))

    @property
    def lame_lambda(self) -> float:
        """Lame's ``lambda = E nu / ((1 + nu)(1 - 2 nu))`` [Pa]."""
        nu = self.poisson
        return self.young * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))

    @property
    def c1(self) -> float:
        """Longitudinal wave speed ``sqrt((lambda + 2G)/rho)`` [m/s]."""
        return math.sqrt((self.lame_lambda + 2.0 * self.shear_modulus) / self.density)

    @property
    def c2(self) -> float:
        """Shear wave speed ``sqrt(G/rho)`` [m/s]."""
        return math.sqrt(self.shear_modulus / self.density)

    @property
    def c1_over_c2(self) -> float:
        return wave_speed_ratio(self.poisson)

    @property
    def rayleigh_speed(self) -> float:
        """Rayleigh wave speed ``c_R`` [m/s]."""
        return rayleigh_speed_ratio(self.poisson) * self.c2

    def to_dict(self) -> dict:
        return {"young": self.young, "poisson": self.poisson, "density": self.density,
                "shear_modulus": self.shear_modulus, "c1": self.c1, "c2": self.c2,
                "c1_over_c2": self.c1_over_c2, "rayleigh_speed": self.rayleigh_speed}


def _x_over_sin_minus_one(x):
    """``x / sin(x) - 1`` without cancellation for small ``x`` (``0 < x < pi/2``)."""
    x = np.asarray(x, dtype=float)
    small = x < 1e-2
    xs = np.where(small, 1.0, x)
    series = x**2 / 6.0 + 7.0 * x**4 / 360.0 + 31.0 * x**6 / 15120.0
    return np.where(small, series, xs / np.sin(xs) - 1.0)


@dataclass(frozen=True, eq=False)
class Radok:
    """Radok coefficients of a wave with scaled speed ``cbar`` (arrays, broadcast).

    Attributes
    ----------
    beta1, beta2 : ndarray
        ``sqrt(1 - cbar^2/c1bar^2)``, ``sqrt(1 - cbar^2)``.
    gamma1, gamma2 : ndarray
        ``beta1 (1 - beta2^2)`` and ``1 + beta2^2 - 2 beta1 beta2`` (section 4.2).
    one_minus_b1b2 : ndarray
        ``1 - beta1 beta2`` (eq. [34]).
    alpha, lam : ndarray
        ``tan(pi alpha) = mu gamma2/gamma1`` and ``lam = 1/2 - alpha``: the interface
        fields behave like ``|x - b|^(-lam)`` at the slip->stick point.
    gamma_mod : ndarray
        ``|gamma1 + i mu gamma2| = gamma1 cos(pi alpha) + mu gamma2 sin(pi alpha)``
        (the factor of [50], [53], [55]).
    K : ndarray
        ``pi (1/2 - alpha) / cos(pi alpha) = pi lam / sin(pi lam)`` (in [52], [54]); > 1.
    K_minus_one : ndarray
        ``K - 1`` computed without cancellation.
    """

    cbar: np.ndarray
    nu: float
    mu: float
    c1bar: float
    beta1: np.ndarray
    beta2: np.ndarray
    gamma1: np.ndarray
    gamma2: np.ndarray
    one_minus_b1b2: np.ndarray
    alpha: np.ndarray
    lam: np.ndarray
    gamma_mod: np.ndarray
    K: np.ndarray
    K_minus_one: np.ndarray


def radok(cbar, nu, mu) -> Radok:
    """Radok coefficients for scaled wave speed(s) ``cbar = c/c2`` in (-1, 0).

    Written in cancellation-free forms, valid down to ``cbar -> 0``:
    ``1 - beta2^2 = cbar^2``, ``gamma2 = (beta1 - beta2)^2 + cbar^2/c1bar^2`` and
    ``1 - beta1 beta2 = (1 - beta1^2 beta2^2)/(1 + beta1 beta2)``.

    Parameters
    ----------
    cbar : array_like
        ``c/c2``, every entry in (-1, 0).
    nu : float
        Poisson's ratio in [0, 0.5).
    mu : float
        Local friction coefficient > 0.
    """
    c = cbar_array(cbar)
    nu = Q.check("nu", nu)
    mu = Q.check("mu", mu)
    c1bar = wave_speed_ratio(nu)
    c2sq, r = c * c, 1.0 / c1bar**2
    beta1 = np.sqrt(1.0 - c2sq * r)
    beta2 = np.sqrt(1.0 - c2sq)
    gamma1 = beta1 * c2sq
    b1_minus_b2 = c2sq * (1.0 - r) / (beta1 + beta2)
    gamma2 = b1_minus_b2**2 + c2sq * r
    one_minus_b1b2 = c2sq * (1.0 + r - c2sq * r) / (1.0 + beta1 * beta2)
    lam = np.arctan2(gamma1, mu * gamma2) / np.pi
    alpha = 0.5 - lam
    K_minus_one = _x_over_sin_minus_one(np.pi * lam)
    return Radok(cbar=c, nu=nu, mu=mu, c1bar=c1bar, beta1=beta1, beta2=beta2, gamma1=gamma1,
                 gamma2=gamma2, one_minus_b1b2=one_minus_b1b2, alpha=alpha, lam=lam,
                 gamma_mod=np.hypot(gamma1, mu * gamma2), K=1.0 + K_minus_one, K_minus_one=K_minus_one)

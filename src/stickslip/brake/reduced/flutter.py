"""Linear stability of steady sliding in the reduced model (flutter of [12]).

Perturb the steady state [16] with contact kept (``P > 0``) and every point slipping
forward (``1 - V_t > 0``). Then ``U = delta`` is imposed, ``P`` is the reaction given
by the U-equation, and the friction ``Q = f P`` drives the V-equation:

    P = g delta - D V'                      (U-equation with U = delta),
    V_tt - a V'' + f D V' + h V = f g delta (V-equation with Q = f P).

For ``V = V_e + e^{i n theta + s t}`` this is one quadratic per mode ``n``,

    s^2 + a n^2 + h + i n f D = 0,      s = +- sqrt(-(a n^2 + h) - i n f D).

The term ``i n f D`` is a non-symmetric (circulatory) stiffness: a tangential strain
``V'`` changes the pressure through ``D``, the pressure changes the friction force,
which feeds ``V`` back a quarter period out of phase. Whenever ``f D != 0`` one root has

    Re s = n f |D| / sqrt(2 (sqrt(K^2 + n^2 f^2 D^2) + K)) > 0,   K = a n^2 + h,

for every ``n >= 1``: steady sliding is unstable by flutter. ``Re s`` increases with
``n`` toward ``f |D| / (2 sqrt(a))``; the unstable wave ``e^{i(n theta + Im(s) t)}``
travels at angular speed ``-Im(s)/n``, against the shaft when ``D < 0``. All rates are
in the paper's time ``t = Omega t̄``; since ``a, h, D`` scale as ``1/gamma``,
``s sqrt(gamma)`` and the rate in 1/s, ``Omega Re s``, do not depend on ``Omega``.
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass
from numbers import Integral

import numpy as np
import lazy_loader as lazy

from ...results import Result
from ...cf import finish
from ...quantities import BRAKE as Q
from ...errors import ParameterError
from .coefficients import ReducedCoefficients
from .params import BrakeParams
from ... import validation as check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["ModeGrowth", "GrowthRates", "growth_rates", "most_unstable_mode", "growth_rate_limit",
           "unstable_root", "mode_numbers", "grid_growth_rates",
           "separation_number"]


def unstable_root(K, eps):
    """Root ``s`` of ``s^2 + K + i eps = 0`` with the larger real part (``K > 0``).

    Computed without cancellation; for ``eps = 0`` the root ``+i sqrt(K)`` is returned.
    The other root is ``-s``.
    """
    K, eps = check.finite_array("K", K), check.finite_array("eps", eps)
    K, eps = np.asarray(K, dtype=float), np.asarray(eps, dtype=float)
    modulus = np.hypot(K, eps)
    beta = np.sqrt((modulus + K) / 2.0)  # |Im s|
    alpha = np.abs(eps) / (2.0 * beta)  # Re s >= 0
    return alpha - 1j * np.where(eps > 0, 1.0, -1.0) * beta


def mode_numbers(modes) -> np.ndarray:
    """Validated, sorted, distinct Fourier mode numbers (an integer >= 0 or a list of them)."""
    items = [modes] if isinstance(modes, Integral) else modes
    try:
        items = list(items)
    except TypeError:
        raise ParameterError("modes", modes, "an integer >= 0 or a list of them") from None
    if not items:
        raise ParameterError("modes", modes, "a non-empty list of integers >= 0")
    if len(items) > Q["modes"].range.hi:
        raise ParameterError("modes", f"{len(items)} modes", f"at most {Q['modes'].range.hi:g} modes")
    if any(isinstance(n, bool) or not isinstance(n, Integral) for n in items):
        raise ParameterError("modes", modes, "a non-empty list of integers >= 0")
    items = [Q["n"].check(n, "modes") for n in items]
    return np.unique(np.asarray(items, dtype=int))


def _check_params(params) -> BrakeParams:
    if not isinstance(params, BrakeParams):
        raise ParameterError("params", params, "a stickslip.brake.BrakeParams")
    if params.delta <= 0.0:
        raise ParameterError("delta", params.delta, "> 0 (steady sliding in contact needs a positive mismatch)",
                             also=("mismatch",))
    return params


@dataclass(frozen=True, repr=False)
class ModeGrowth(Result):
    """Growth rate ``Re s`` and frequency ``Im s`` of one mode (time ``t = Omega t̄``)."""

    MODEL: ClassVar[str] = "brake"

    n: int
    growth_rate: float
    frequency: float

    @property
    def wave_speed(self) -> float:
        """Angular phase speed ``-Im(s)/n`` of the unstable wave (``nan`` for ``n = 0``)."""
        return -self.frequency / self.n if self.n else float("nan")

    def to_dict(self) -> dict:
        return {"n": self.n, "growth_rate": self.growth_rate, "frequency": self.frequency}


@dataclass(frozen=True, repr=False)
class GrowthRates(Result):
    """Complex growth rates ``s(n)`` (the root with larger real part) of steady sliding."""

    MODEL: ClassVar[str] = "brake"

    params: BrakeParams
    coefficients: ReducedCoefficients
    n: np.ndarray
    s: np.ndarray

    @property
    def growth_rate(self) -> np.ndarray:
        return self.s.real

    @property
    def frequency(self) -> np.ndarray:
        return self.s.imag

    @property
    def limit(self) -> float:
        """``sup_n Re s = f |D| / (2 sqrt(a))``."""
        return growth_rate_limit(self.params)

    @property
    def modes(self) -> list[ModeGrowth]:
        return [ModeGrowth(int(n), float(s.real), float(s.imag)) for n, s in zip(self.n, self.s)]

    @property
    def most_unstable(self) -> ModeGrowth:
        """The mode with the largest growth rate (the smallest such ``n`` on ties)."""
        return self.modes[int(np.argmax(self.growth_rate))]

    @property
    def unstable(self) -> bool:
        return bool(np.any(self.growth_rate > 0.0))

    def to_dict(self) -> dict:
        return {"modes": [m.to_dict() for m in self.modes], "most_unstable": self.most_unstable.n,
                "growth_rate_limit": self.limit, "D": self.coefficients.D, "unstable": self.unstable}

    def to_xarray(self) -> xr.Dataset:
        ds = xr.Dataset(
            {"growth_rate": ("n", self.growth_rate, {"units": "1", "long_name": "Re s (time Omega t)"}),
             "frequency": ("n", self.frequency, {"units": "1", "long_name": "Im s (time Omega t)"})},
            coords={"n": ("n", self.n, {"long_name": "number of waves around the ring"})})
        omega = self.params.omega
        if np.isfinite(omega):
            ds["growth_rate_si"] = ("n", omega * self.growth_rate, {"units": "1/s", "long_name": "Omega Re s"})
            ds["frequency_si"] = ("n", omega * self.frequency, {"units": "rad/s", "long_name": "Omega Im s"})
        ds.attrs.update({"D": self.coefficients.D, "growth_rate_limit": self.limit,
                         "source": "linearised eq. [12] (corrected), all points slipping"})
        return finish(ds, "growth rates of steady sliding, reduced model", "brake", params=self.params.to_attrs())


def growth_rates(params: BrakeParams, modes=range(1, 21)) -> GrowthRates:
    """Complex growth rates of the modes ``e^{i n theta + s t}`` of steady sliding.

    Parameters
    ----------
    params : BrakeParams
        Dimensionless parameters, with ``delta > 0`` (contact).
    modes : int or iterable of int
        Mode numbers ``n >= 0`` (sorted, duplicates dropped).

    Returns
    -------
    GrowthRates
        ``s(n)`` with ``Re s >= 0`` (the other root is ``-s``).
    """
    params, n = _check_params(params), mode_numbers(modes)
    c = params.coefficients()
    s = unstable_root(c.a * n**2 + c.h, n * params.friction * c.D)
    return GrowthRates(params, c, n, np.asarray(s, dtype=complex))


def most_unstable_mode(params: BrakeParams, modes=range(1, 21)) -> ModeGrowth:
    """The mode of ``modes`` with the largest growth rate.

    ``Re s`` increases with ``n`` in the reduced model, so this is the largest ``n``
    whenever ``f D != 0``: the reduced model selects no wavelength at the linear level.
    """
    return growth_rates(params, modes).most_unstable


def growth_rate_limit(params: BrakeParams) -> float:
    """``sup_n Re s(n) = f |D| / (2 sqrt(a))``, reached as ``n -> infinity``."""
    c = _check_params(params).coefficients()
    return float(params.friction * abs(c.D) / (2.0 * np.sqrt(c.a)))


def grid_growth_rates(params: BrakeParams, modes, nodes: int = 33, penalty: float = 1e6) -> np.ndarray:
    """Independent route: eigenvalues of [12] linearised on a theta-grid.

    Fourier-spectral derivatives on ``nodes`` (odd) points, contact by a penalty
    ``P = -penalty g U`` (``U = delta`` is not imposed), ``Q = f P``. Each eigenvector is
    assigned the mode ``|n|`` that dominates its V-part; fast penalty modes are dropped.
    Returns the largest real part per requested mode. Solved at ``gamma = 1`` and scaled
    by ``1/sqrt(gamma)`` (every coefficient is proportional to ``1/gamma``) for conditioning.
    """
    modes = mode_numbers(modes)
    nodes, penalty = Q.check("nodes", nodes), Q.check("penalty", penalty)
    if nodes % 2 == 0 or nodes <= 2 * modes.max():
        raise ParameterError("nodes", nodes, f"odd and > 2 max(modes) = {2 * modes.max()}")
    c, f = params.replace(gamma=1.0).coefficients(), params.friction
    k = np.fft.fftfreq(nodes, 1.0 / nodes)
    F = np.fft.fft(np.eye(nodes), axis=0)
    d1, d2 = (np.real(np.fft.ifft(m[:, None] * F, axis=0)) for m in (1j * k, -k**2))
    eye, kappa = np.eye(nodes), penalty * c.g
    K = np.block([[c.b * d2 - (c.g + kappa) * eye, c.D * d1],
                  [-c.D * d1 - f * kappa * eye, c.a * d2 - c.h * eye]])
    zero = np.zeros_like(K)
    lam, vec = np.linalg.eig(np.block([[zero, np.eye(2 * nodes)], [K, zero]]))
    slow = np.abs(lam) < 0.1 * np.sqrt(kappa)
    dominant = np.abs(k[np.argmax(np.abs(np.fft.fft(vec[nodes:2 * nodes], axis=0)), axis=0)])
    return np.array([lam[slow & (dominant == n)].real.max() for n in modes]) / np.sqrt(params.gamma)


def separation_number(params: BrakeParams) -> float:
    """``S = g delta sqrt(a) / |D|``: contact is lost where ``D V' > g delta``, and a stick-slip
    wave has ``|V'| ~ 1/sqrt(a)`` (velocities of the order of the shaft speed), so separation
    needs ``S`` of order one or less. ``S = kappa * (gamma g) sqrt(gamma a) / (gamma |D|)``."""
    check.instance("params", params, BrakeParams, "a stickslip.brake.BrakeParams")
    c = params.coefficients()
    return float(c.g * params.delta * np.sqrt(c.a) / abs(c.D))

"""Rate-and-state friction: the friction coefficient and the evolution of its state.

    mu = f_0 + a ln(V / V_0) + sum_i b_i ln(V_0 theta_i / D_c,i)

or, regularised near zero slip rate (Rice & Ben-Zion 1996, Lapusta et al. 2000),

    mu = a asinh( V / (2 V_0) exp(Psi / a) ),   Psi = f_0 + sum_i b_i ln(V_0 theta_i / D_c,i),

which is the first form to within exp(-2 Psi/a) once V >> V_0 exp(-Psi/a). Each state
variable evolves by one of

    aging (Dieterich):      theta' = 1 - V theta / D_c
    slip (Ruina):           theta' = -(V theta / D_c) ln(V theta / D_c)
    prz (Perrin-Rice-Zheng): theta' = 1 - (V theta / (2 D_c))^2

so that steady sliding at V has ``theta = D_c / V`` (``2 D_c / V`` for prz) and, for the first
two, ``mu_ss = f_0 + (a - b) ln(V / V_0)``. The model works with ``psi_i = ln(V_0 theta_i / D_c,i)``
and ``ln V`` (the rates span tens of decades); every function here accepts complex arguments
(the slider's Jacobian is taken by complex steps).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ParameterError
from ..quantities import RSF as Q
from .kernel import LARGE_LOG

__all__ = ["RateState"]



@dataclass(frozen=True)
class RateState:
    """A rate-and-state law: ``a``, ``b``, ``dc`` (and ``b2``, ``dc2`` for a second state
    variable), ``f0`` at the reference rate ``v_ref``, the ``evolution`` law, ``regularized``."""

    a: float
    b: float
    dc: float
    f0: float = 0.6
    v_ref: float = 1e-6
    evolution: str = "aging"
    b2: float = 0.0
    dc2: float | None = None
    regularized: bool = False

    def __post_init__(self):
        for name in ("a", "b", "dc", "f0", "v_ref", "b2"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        Q.check("evolution", self.evolution)
        if self.b2 > 0.0 and self.dc2 is None:
            raise ParameterError("b2", self.b2, "0 unless dc2, the second state variable's slip distance, is given",
                                 also=("dc2",))
        if self.dc2 is not None:
            object.__setattr__(self, "dc2", Q.check("dc2", self.dc2))
        if not isinstance(self.regularized, bool):
            raise ParameterError("regularized", self.regularized, "True or False")

    @property
    def states(self) -> int:
        """How many state variables."""
        return 1 if self.dc2 is None else 2

    @property
    def b_values(self) -> np.ndarray:
        return np.array([self.b] if self.dc2 is None else [self.b, self.b2])

    @property
    def dc_values(self) -> np.ndarray:
        return np.array([self.dc] if self.dc2 is None else [self.dc, self.dc2])

    def theta(self, psi) -> np.ndarray:
        """The state variables ``theta_i`` (s) of ``psi_i``."""
        return self.dc_values * np.exp(np.real(psi)) / self.v_ref

    def steady_psi(self, v: float) -> np.ndarray:
        """``psi`` of steady sliding at slip rate ``v``."""
        shift = math.log(2.0) if self.evolution == "prz" else 0.0
        return np.full(self.states, math.log(self.v_ref / v) + shift)

    def friction(self, log_v, psi):
        """``(mu, d mu / d ln V, d mu / d Psi)`` at ``ln V`` and ``psi``."""
        big_psi = self.f0 + self.b_values @ psi
        if not self.regularized:
            return self.f0 + self.a * (log_v - math.log(self.v_ref)) + self.b_values @ psi, self.a, 1.0
        log_z = log_v - math.log(2.0 * self.v_ref) + big_psi / self.a
        if np.ndim(log_z):  # many states at once (a run's samples)
            big = np.real(log_z) > LARGE_LOG
            mu = self.a * np.where(big, log_z + math.log(2.0), np.arcsinh(np.exp(np.where(big, 0.0, log_z))))
        elif np.real(log_z) > LARGE_LOG:
            mu = self.a * (log_z + math.log(2.0))
        else:
            mu = self.a * np.arcsinh(np.exp(log_z))
        slope = self.a / np.sqrt(1.0 + np.exp(-2.0 * log_z))
        return mu, slope, slope / self.a

    def state_rate(self, log_v, psi):
        """``d psi_i / dt`` (1/s)."""
        v = np.exp(log_v)
        dc = self.dc_values
        if self.evolution == "aging":
            return self.v_ref / dc * np.exp(-psi) - v / dc
        if self.evolution == "slip":
            return -(v / dc) * (psi + log_v - math.log(self.v_ref))
        return self.v_ref / dc * np.exp(-psi) - v * v * np.exp(psi) / (4.0 * dc * self.v_ref)

    def steady_friction(self, v: float) -> float:
        """The friction coefficient of steady sliding at slip rate ``v``."""
        mu, _, _ = self.friction(math.log(v), self.steady_psi(v))
        return float(np.real(mu))

"""The paper's stick-slip waves (section 4, `stickslip.halfspace.StickSlipWave`) in time: a wave's
interface fields, in physical units on a periodic in-plane grid, as the state a run starts from and as
the exact solution it is compared with (`WaveOnGrid`).

**From the paper's frame to the run's.** The paper's elastic body is the lower half-plane, the rigid
body above it moves at ``V`` and the body's material far away at ``V*``; its fields travel as
functions of ``x - c t`` (``-c_2 < c < 0``), lengths in units of the stick length ``a``, stresses of
``G``, speeds of ``c_2``. A run's half-space lies above a rigid body at rest (`stickslip.sbim.inplane`).
Reflected (``y -> -y``: ``sigma_xy`` changes sign, ``sigma_yy`` does not) and seen from the rigid body,
the wave's fields at a node ``x`` at time ``t`` are, with ``xi = (x + dx / 2 - c t) / a`` (each node
half a cell from the pattern's start, so no node sits on a transition at ``t = 0``)::

    V_x = -c_2 (V - U_dot)(xi),   sigma_xy = -G Sigma_xy(xi),   sigma_yy = G Sigma_yy(xi),   V_y = 0.

On the slip zone the paper's condition ``Sigma_xy = -mu Sigma_yy`` is then Coulomb's law sliding
backwards (``V_x < 0``) at the coefficient ``mu``: the wave is a solution of a run with
``CoulombFriction(mu, mu)`` wherever its pressure stays compressive, its slip rate stays negative on
the slip zone and its stick zone's traction within ``mu`` times its pressure (the wave's
``tensile_zone`` and ``stick_violation`` say where not).

**Its loading and past.** The remote stresses are the run's uniform load, the shear load raised by
the radiation of the wave's mean slip rate ``W`` (``tau_0 = -G tau*_xy + (G / c_2) W``: the whole body
has slid at ``W`` for ever); the rates before ``t = 0`` are the travelling pattern's, and the slip at
``t = 0`` their sum over the scheme's past steps (each mode a geometric sum, ``dt V_k q / (1 - q)``
with ``q = exp(i k c dt)``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ParameterError
from ..halfspace import StickSlipWave
from ..quantities.sbim import SBIM as Q
from .initial import InitialState
from .inplane import InplaneProblem
from .interface import LAWS, CoulombFriction

__all__ = ["WaveOnGrid"]


@dataclass(frozen=True, eq=False)
class WaveOnGrid:
    """A `StickSlipWave` on a half-space of ``shear_modulus`` [Pa] and ``shear_wave_speed`` [m/s] with
    a stick zone ``stick_length`` [m] long, over ``periods`` of its period in ``elements`` (module
    docstring)."""

    wave: StickSlipWave
    shear_modulus: float
    shear_wave_speed: float
    stick_length: float
    elements: int
    periods: int = 1

    def __post_init__(self):
        if not isinstance(self.wave, StickSlipWave):
            raise ParameterError("wave", self.wave, "a StickSlipWave (stickslip.halfspace)")
        if not math.isfinite(self.wave.tau_yy) or self.wave.tau_yy >= 0.0:
            raise ParameterError("tau_yy", self.wave.tau_yy, "a compressive remote normal stress over G (< 0): "
                                 "the wave's loading")
        for name in ("shear_modulus", "shear_wave_speed", "elements", "periods"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        object.__setattr__(self, "stick_length", Q.check("stick_length", self.stick_length))
        most = Q["length"].range.hi
        if self.length > most:
            top = most / (self.periods * self.wave.b)
            raise ParameterError("stick_length", self.stick_length, f"at most {top:.4g} m here: the grid's period, "
                                 f"periods x b x stick_length = {self.length:.4g} m, is at most {most:g} m",
                                 also=("periods",))

    @property
    def length(self) -> float:
        """The grid's period [m], ``periods`` of the wave's."""
        return self.periods * self.wave.b * self.stick_length

    @property
    def dx(self) -> float:
        return self.length / self.elements

    @property
    def x(self) -> np.ndarray:
        return np.arange(self.elements) * self.dx

    @property
    def speed(self) -> float:
        """The wave's speed ``c`` [m/s] (negative: towards ``-x``)."""
        return self.wave.cbar * self.shear_wave_speed

    def pattern(self, t: float) -> np.ndarray:
        """Each node's place in the wave's pattern at ``t`` [s]: ``xi`` in stick lengths, from 0 to ``b`` (the
        stick zone ``[0, 1)``, the slip zone ``[1, b)``, the slip-to-stick point at ``b = 0``)."""
        return np.mod((self.x + 0.5 * self.dx - self.speed * t) / self.stick_length, self.wave.b)

    def exact(self, t: float) -> dict:
        """The wave's slip rate [m/s], shear and normal tractions [Pa] at the nodes at ``t`` [s]."""
        f = self.wave.fields(self.pattern(t))
        return {"slip_rate": -self.shear_wave_speed * f.slip_velocity,
                "shear_stress": -self.shear_modulus * f.Sigma_xy,
                "normal_traction": self.shear_modulus * f.Sigma_yy}

    def load(self):
        """The uniform remote tractions [Pa], the shear raised by the radiation of the mean slip rate."""
        mean = float(np.mean(self.exact(0.0)["slip_rate"]))
        tau = -self.shear_modulus * self.wave.tau_xy + self.shear_modulus / self.shear_wave_speed * mean
        sigma = self.shear_modulus * self.wave.tau_yy
        return lambda x, t: (np.full(np.shape(x), tau), np.full(np.shape(x), sigma))

    def initial(self, beta: float = 0.3, perturbation: float = 0.0, mode: int = 1) -> InitialState:
        """The interface at ``t = 0`` for a scheme of step ``dt = beta dx / c_s``, its slip perturbed by
        ``perturbation`` [m] times ``cos(2 pi mode x / length)``."""
        dt = Q.check("beta", beta) * self.dx / self.shear_wave_speed
        perturbation, mode = Q.check("perturbation", perturbation), Q.check("mode", mode)
        rate = self.exact(0.0)["slip_rate"]
        k = 2.0 * math.pi * np.arange(self.elements // 2 + 1) / self.length
        q = np.exp(1j * k * self.speed * dt)
        vk = np.fft.rfft(rate)
        uk = np.zeros_like(vk)
        uk[1:] = dt * vk[1:] * q[1:] / (1.0 - q[1:])
        slip = np.fft.irfft(uk, self.elements) + perturbation * np.cos(2.0 * math.pi * mode * self.x / self.length)
        zero = np.zeros(self.elements)
        return InitialState(slip, zero, lambda t: (np.fft.irfft(vk * np.exp(-1j * k * self.speed * t), self.elements),
                                                  zero))

    def problem(self, law=None, beta: float = 0.3, history_periods: float = 16.0, perturbation: float = 0.0,
                mode: int = 1) -> InplaneProblem:
        """The run that starts from the wave: ``law`` by default ``CoulombFriction(mu, mu)``, the paper's."""
        law = CoulombFriction(self.wave.mu, self.wave.mu) if law is None else law
        if not isinstance(law, LAWS):
            raise ParameterError("law", law, "None (the paper's Coulomb friction) or an in-plane law")
        return InplaneProblem(self.shear_modulus, self.shear_wave_speed, self.wave.nu, self.length, self.elements,
                              self.load(), law, beta=beta, history_periods=history_periods,
                              initial=self.initial(beta, perturbation, mode))

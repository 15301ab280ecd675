"""One elastic half-space's surface in an in-plane run: its material (`Solid`) and, during a run, its
memory of rates mode by mode and the tractions it exerts (`Surface`).

An in-plane run has the upper half-space ``y > 0`` and, below it, a rigid body or a second half-space
``y < 0`` (two materials: Adams, 1995; Cochard and Rice, 2000). Each surface, moving by its own
displacements ``u`` and rates ``v``, exerts on the interface (`stickslip.sbim.inplane_kernels`)::

    upper:  sigma = G+ - Z+ v+,        lower:  sigma = G- + Z- v-,

``G`` the load and the static, coupling and memory terms of that surface and ``Z = (mu / c_s,
eta mu / c_s)`` its radiation damping, shear and normal. The lower half-space is the upper one
reflected ``y -> -y`` (``u_y``, ``sigma_xy`` and the coupling change sign). The tractions being one,
the interface sees the slip ``U = u+ - u-`` and the opening through::

    sigma = G - Z V,   G = (Z- G+ + Z+ G-) / (Z+ + Z-),   Z = Z+ Z- / (Z+ + Z-),

the rigid body's ``Z- -> infinity`` giving ``G = G+``, ``Z = Z+``. The law sets ``V`` and ``sigma``;
each side's rate follows, ``v+ = (G+ - sigma) / Z+``, ``v- = (sigma - G-) / Z-``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ParameterError
from ..quantities.sbim import SBIM as Q
from .history import History
from .inplane_kernels import inplane_step_weights, static_stiffness, wave_speed_ratio

__all__ = ["Solid", "Surface", "MAX_POISSON", "interface_damping"]

#: Largest Poisson's ratio in-plane (c_p / c_s = 7.1).
MAX_POISSON = 0.49


@dataclass(frozen=True)
class Solid:
    """An elastic half-space's material: ``shear_modulus`` [Pa], ``shear_wave_speed`` [m/s] and
    ``poisson`` (plane strain)."""

    shear_modulus: float
    shear_wave_speed: float
    poisson: float

    def __post_init__(self):
        for name in ("shear_modulus", "shear_wave_speed", "poisson"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        if self.poisson > MAX_POISSON:
            raise ParameterError("poisson", self.poisson, f"at most {MAX_POISSON} in-plane (the kernels' quadrature "
                                 "grows with c_p / c_s)")

    @property
    def eta(self) -> float:
        """``c_p / c_s``."""
        return wave_speed_ratio(self.poisson)

    @property
    def impedance(self) -> tuple[float, float]:
        """The radiation damping ``(mu / c_s, eta mu / c_s)`` [Pa s/m], shear and normal."""
        z = self.shear_modulus / self.shear_wave_speed
        return z, self.eta * z


def interface_damping(upper: Solid, lower: Solid | None) -> tuple[float, float]:
    """The interface's radiation damping, shear and normal [Pa s/m]: the upper solid's on a rigid body
    (``lower`` None), else the two solids' in series."""
    if lower is None:
        return upper.impedance
    return tuple(a * b / (a + b) for a, b in zip(upper.impedance, lower.impedance))


def history_windows(solid: Solid, k: np.ndarray, dt: float, history_periods: float) -> np.ndarray:
    """Each mode's kept steps: ``history_periods`` of its shear periods (none for the uniform mode)."""
    window = np.zeros(k.size, dtype=np.int64)
    if k.size > 1:
        T1 = k[1] * solid.shear_wave_speed * dt
        window[1:] = np.ceil(history_periods * 2.0 * math.pi / (T1 * np.arange(1, k.size)))
    return window


class Surface:
    """The surface of ``solid`` (``side`` +1 above the interface, -1 below) over a run of ``steps`` steps
    with ``pre`` steps of a past, on the modes ``k`` [1/m] with step ``dt`` [s]."""

    def __init__(self, solid: Solid, side: int, k: np.ndarray, dt: float, history_periods: float, steps: int,
                 pre: int = 0):
        self.solid, self.side = solid, side
        self.window = history_windows(solid, k, dt, history_periods)
        self.count = np.minimum(steps + pre, self.window)
        T1 = k[1] * solid.shear_wave_speed * dt if k.size > 1 else 0.0
        w11, w22, self.w12 = inplane_step_weights(solid.poisson, T1, dt, self.count, self.window)
        self.hx, self.hy = History(w11, self.count, steps), History(w22, self.count, steps)
        self.s11, self.s22, self.s12 = static_stiffness(solid.poisson)
        self.muk = solid.shear_modulus * k
        self.impedance = solid.impedance

    def tractions(self, step: int, Ux: np.ndarray, Uy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The static, coupling and memory terms of the tractions [Pa] at ``step`` (the history's), mode
        by mode, of the surface displaced by ``Ux``, ``Uy``."""
        s, muk, hx, hy = self.side, self.muk, self.hx, self.hy
        ux, uy = np.fft.rfft(Ux), np.fft.rfft(s * Uy if s < 0 else Uy)
        fx = muk * (hx.memory(step) - self.s11 * ux) + 1j * muk * (self.s12 * uy - hy.memory(step, self.w12))
        fy = muk * (hy.memory(step) - self.s22 * uy) - 1j * muk * (self.s12 * ux - hx.memory(step, self.w12))
        return (-fx if s < 0 else fx), fy

    def push(self, step: int, Vx: np.ndarray, Vy: np.ndarray) -> None:
        """Keep this surface's rates [m/s] of ``step``."""
        self.hx.push(step, np.fft.rfft(Vx))
        self.hy.push(step, np.fft.rfft(-Vy if self.side < 0 else Vy))

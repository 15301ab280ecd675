"""The in-plane interface laws: unilateral contact with a rigid body, friction proportional to the
pressure, and Prakash and Clifton's regularisation of the pressure the strength sees; one step of
each node (`interface_step`), used by `stickslip.sbim.inplane`.

**Contact.** A closed node whose normal drive ``G_y`` is compressive stays closed (``V_y = 0``,
``sigma_yy = G_y``); otherwise it opens or moves free (``sigma_yy = 0``), and a gap that would close
within the step closes exactly at its end (``V_y = -U_y / dt``, the impact's compression in
``sigma_yy``).

**Friction.** The shear strength is the coefficient times the pressure ``P``: a stuck node holds while
``|G_x|`` stays within the static strength, a moving node slides at ``V_x = (c_s / mu) sign(G_x)
(|G_x| - f P)`` with the kinetic (or slip-weakened) ``f`` and sticks again when ``|G_x| <= f P``; an
open node slides free. With `CoulombFriction` and `SlipWeakeningFriction` ``P = N = max(-sigma_yy, 0)``
at once: sliding at a coefficient above 1 is then ill-posed (`stickslip.sbim.flutter`).

**Prakash-Clifton.** `PrakashClifton` wraps either law, or rate-and-state friction
(`stickslip.sbim.RateStateFriction`, whose strength is then ``P mu(V, psi)``): ``P`` follows ``N`` over a
slip, ``P' = -(|V_x| + V*) / L (P - N)``, advanced exactly over each step with that step's ``N`` and
``V_x`` (`relaxed_pressure`); ``P`` starts at the first step's ``N`` (the interface pressed before the
run). It makes steady sliding well posed at any coefficient (`stickslip.sbim.flutter`), and rate-and-state
sliding between two materials (Rice, Lapusta and Ranjith 2001).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ParameterError
from ..quantities.sbim import SBIM as Q
from .antiplane import FreeSurface, law_parameters
from .ratestate import RateStateFriction
from .scales import weakening_lengths

__all__ = ["CoulombFriction", "SlipWeakeningFriction", "PrakashClifton", "interface_step", "relaxed_pressure",
           "LAWS", "slip_weakening_lengths", "law_parameters"]


def _coefficients(law) -> None:
    for name in ("static_friction", "kinetic_friction"):
        object.__setattr__(law, name, Q.check(name, getattr(law, name)))
    if law.kinetic_friction > law.static_friction:
        raise ParameterError("kinetic_friction", law.kinetic_friction, f"at most static_friction = "
                             f"{law.static_friction:g}", also=("static_friction",))


@dataclass(frozen=True)
class CoulombFriction:
    """Unilateral contact with static and kinetic friction coefficients."""

    static_friction: float
    kinetic_friction: float

    def __post_init__(self):
        _coefficients(self)

    def coefficient(self, slip: np.ndarray, sliding: np.ndarray) -> np.ndarray:
        return np.where(sliding, self.kinetic_friction, self.static_friction)

    def sliding_coefficients(self) -> np.ndarray:
        """The coefficients a node can slide with."""
        return np.array([self.kinetic_friction])


@dataclass(frozen=True)
class SlipWeakeningFriction:
    """Unilateral contact with a friction coefficient falling linearly with slip from ``static_friction``
    to ``kinetic_friction`` over ``weakening_slip`` [m]."""

    static_friction: float
    kinetic_friction: float
    weakening_slip: float

    def __post_init__(self):
        _coefficients(self)
        object.__setattr__(self, "weakening_slip", Q.check("weakening_slip", self.weakening_slip))

    def coefficient(self, slip: np.ndarray, sliding: np.ndarray) -> np.ndarray:
        fall = np.minimum(np.abs(slip) / self.weakening_slip, 1.0)
        return self.static_friction - (self.static_friction - self.kinetic_friction) * fall

    def sliding_coefficients(self) -> np.ndarray:
        """The coefficients a node can slide with (samples of the fall)."""
        return np.linspace(self.kinetic_friction, self.static_friction, 17)


@dataclass(frozen=True)
class PrakashClifton:
    """``friction`` (`CoulombFriction`, `SlipWeakeningFriction` or `stickslip.sbim.RateStateFriction`) with the
    pressure its strength sees following the contact pressure over ``relaxation_slip`` [m] of slip,
    ``relaxation_speed`` [m/s] added to the slip rate (module docstring)."""

    friction: object
    relaxation_slip: float
    relaxation_speed: float

    def __post_init__(self):
        if not isinstance(self.friction, (CoulombFriction, SlipWeakeningFriction, RateStateFriction)):
            raise ParameterError("friction", self.friction, "CoulombFriction(...), SlipWeakeningFriction(...) or "
                                 "RateStateFriction(...)")
        for name in ("relaxation_slip", "relaxation_speed"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))

    def coefficient(self, slip: np.ndarray, sliding: np.ndarray) -> np.ndarray:
        return self.friction.coefficient(slip, sliding)

    def sliding_coefficients(self) -> np.ndarray:
        return self.friction.sliding_coefficients()

    def parameters(self) -> dict:
        """Its law's numbers (`law_parameters`) and its own."""
        return {**law_parameters(self.friction), "relaxation_slip": self.relaxation_slip,
                "relaxation_speed": self.relaxation_speed}


#: The laws an in-plane run takes.
LAWS = (FreeSurface, CoulombFriction, SlipWeakeningFriction, PrakashClifton)


def interface_step(law, Gx, Gy, slip, gap, sliding, pressure, dt, rad):
    """One step of every node: ``(V_x, V_y, sigma_xy, sigma_yy, sliding, pressure)`` from the drives
    ``G``, the slip, the gap, which nodes slide and the pressure the strength sees (``None`` at the
    first step), ``rad`` the radiation dampings ``(mu / c_s, eta mu / c_s)`` (module docstring)."""
    rad_t, rad_n = rad
    if isinstance(law, FreeSurface):
        return Gx / rad_t, Gy / rad_n, np.zeros_like(Gx), np.zeros_like(Gy), sliding, pressure
    Vy = np.where((gap > 0.0) | (Gy > 0.0), Gy / rad_n, 0.0)
    Vy = np.maximum(Vy, -gap / dt)  # a gap closing within the step closes at its end
    syy = Gy - rad_n * Vy
    N = np.maximum(-syy, 0.0)
    P = N if pressure is None or not isinstance(law, PrakashClifton) else pressure
    held = np.abs(Gx) <= law.coefficient(slip, sliding) * P
    excess = np.abs(Gx) - law.coefficient(slip, np.ones(slip.shape, bool)) * P
    sliding = ~held & (excess > 0.0)
    Vx = np.where(sliding, np.sign(Gx) * excess / rad_t, 0.0)
    if isinstance(law, PrakashClifton):
        P = relaxed_pressure(law, P, N, Vx, dt)
    return Vx, Vy, Gx - rad_t * Vx, syy, sliding, P


def relaxed_pressure(law: PrakashClifton, seen: np.ndarray, pressure: np.ndarray, slip_rate: np.ndarray,
                     dt: float) -> np.ndarray:
    """The pressure the strength sees after ``dt``, relaxed from ``seen`` towards ``pressure`` at the slip rate
    (exactly, both held over the step)."""
    rate = (np.abs(slip_rate) + law.relaxation_speed) / law.relaxation_slip
    return pressure + (seen - pressure) * np.exp(-rate * dt)


def slip_weakening_lengths(law, shear_modulus: float, poisson: float, normal_stress: float) -> tuple[float, float]:
    """The nucleation half-length and the static cohesive zone [m] of a slip-weakening interface in mode II
    under the compressive ``normal_stress`` [Pa] (``mu* = mu / (1 - nu)``, strength drop ``(f_s - f_d)
    normal_stress``; `stickslip.sbim.scales`)."""
    if isinstance(law, PrakashClifton):
        law = law.friction
    if not isinstance(law, SlipWeakeningFriction):
        raise ParameterError("law", law, "a SlipWeakeningFriction (or one regularised by PrakashClifton)")
    mu, nu = Q.check("shear_modulus", shear_modulus), Q.check("poisson", poisson)
    drop = (law.static_friction - law.kinetic_friction) * Q.check("normal_stress", normal_stress)
    return weakening_lengths(mu / (1.0 - nu), law.weakening_slip, drop)

"""The one-degree-of-freedom friction oscillator (paper section 2, eq. [1]).

    m x'' + c x' + k x = F,   v_r = V - x',

a mass on a spring pressed with normal force ``N`` on a belt moving at speed ``V``.
Three modes: ``STICK`` (``x' = V``, ``|k x + c V| <= f_s N``), ``SLIP_POS``
(``v_r > 0``, ``F = +N mu(v_r)``) and ``SLIP_NEG`` (reverse slip, ``v_r < 0``,
``F = -N mu(v_r)``).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from enum import IntEnum
from numbers import Real

import numpy as np

from ..quantities import OSCILLATOR as Q
from ..errors import ParameterError
from ..friction import FrictionLaw


class Mode(IntEnum):
    """Contact state of the mass. ``int(mode)`` is the slip direction ``sign(v_r)``."""

    SLIP_NEG = -1
    STICK = 0
    SLIP_POS = 1


#: The steepest Stribeck drop ``(f_s - f_d) N / v_s`` accepted, over ``sqrt(k m)``: within it a cycle
#: takes seconds (1e6: 2 s with m = k = N = 1; 2e7: 40 s; 2e8: the integrator fails).
MAX_STRIBECK_STIFFNESS = 1e6
#: How far from steady sliding a start may be, in the oscillator's own scales (`Oscillator.start`).
MAX_START = 1e6
#: The largest damping ratio ``c / (2 sqrt(k m))`` (see `Oscillator`).
MAX_DAMPING_RATIO = 1e11


@dataclass(frozen=True)
class Oscillator:
    """Parameters of the friction oscillator, in SI units.

    Parameters
    ----------
    mass, stiffness, normal_force, belt_speed : float
        ``m`` [kg], ``k`` [N/m], ``N`` [N], ``V`` [m/s]; all > 0.
    friction : FrictionLaw
        The friction law (`stickslip.friction`).
    damping : float
        Viscous damping ``c`` [N s/m] >= 0, with a damping ratio ``c / (2 sqrt(k m))`` at most
        `MAX_DAMPING_RATIO` (1e11: the fast time of an overdamped slip, ``1/(2 zeta w)``, must
        stay above the event loop's resolution of ``1e-12/w``).
    """

    mass: float
    stiffness: float
    normal_force: float
    belt_speed: float
    friction: FrictionLaw
    damping: float = 0.0

    def __post_init__(self):
        for name in ("mass", "stiffness", "normal_force", "belt_speed", "damping"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        critical = 2.0 * math.sqrt(self.stiffness) * math.sqrt(self.mass)
        if self.damping > MAX_DAMPING_RATIO * critical:
            raise ParameterError("damping", self.damping, f"<= {MAX_DAMPING_RATIO * critical:.6g} (a damping ratio "
                                 f"c/(2 sqrt(k m)) <= {MAX_DAMPING_RATIO:g}: beyond it the fast time 1/(2 zeta w) "
                                 "is below the event loop's resolution of 1e-12/w)", also=("mass", "stiffness"))
        if not isinstance(self.friction, FrictionLaw):
            raise ParameterError("friction", self.friction, "a stickslip.friction.FrictionLaw")
        vs = getattr(self.friction, "vs", None)
        if vs is not None:  # the Stribeck law's drop, as a negative damping over the oscillator's own scale
            least = (self.friction.fs - self.friction.fd) * self.normal_force / (
                MAX_STRIBECK_STIFFNESS * math.sqrt(self.stiffness) * math.sqrt(self.mass))
            if vs < least:
                raise ParameterError("vs", vs, f">= {least:.4g} m/s here: the law's drop (f_s - f_d) N / v_s may be at "
                                     f"most {MAX_STRIBECK_STIFFNESS:g} sqrt(k m), or the slip transition is too fast "
                                     "for the integrator (vs = 1e-8 with m = k = N = 1 took 40 s; use coulomb there)",
                                     also=("fs", "fd", "normal_force", "mass", "stiffness"))

    def replace(self, **changes) -> "Oscillator":
        """A copy with some parameters changed (validated again)."""
        fields = dict(mass=self.mass, stiffness=self.stiffness, normal_force=self.normal_force,
                      belt_speed=self.belt_speed, friction=self.friction, damping=self.damping)
        fields.update(changes)
        return Oscillator(**fields)

    PARAMETERS = ("mass", "stiffness", "normal_force", "belt_speed", "damping")

    def parameter(self, name: str) -> float:
        """Value of a named parameter of the oscillator or of its friction law."""
        if not isinstance(name, str):
            raise ParameterError("parameter", name, "one of " + ", ".join(self.parameter_names()))
        if name in self.PARAMETERS:
            return getattr(self, name)
        if name in self.parameter_names():
            return getattr(self.friction, name)
        raise ParameterError("parameter", name, "one of " + ", ".join(self.parameter_names()))

    def parameter_names(self) -> list[str]:
        """The oscillator's parameters and the friction law's numeric ones (not its name)."""
        fields = getattr(self.friction, "__dataclass_fields__", {})
        law = [n for n in fields if n not in ("mu", "label", "step")
               and isinstance(getattr(self.friction, n), Real) and not isinstance(getattr(self.friction, n), bool)]
        return [*self.PARAMETERS, *law]

    def with_parameter(self, name: str, value: float) -> "Oscillator":
        """A copy with one parameter (of the oscillator or the law) changed."""
        self.parameter(name)  # validates the name
        if name in self.PARAMETERS:
            return self.replace(**{name: value})
        return self.replace(friction=dataclasses.replace(self.friction, **{name: value}))

    @property
    def omega(self) -> float:
        """Natural angular frequency ``w = sqrt(k/m)``."""
        return math.sqrt(self.stiffness / self.mass)

    def start(self, x0: float, v0: float) -> tuple[float, float]:
        """A starting state ``(x0, v0)`` within `MAX_START` of this oscillator's own scales: the
        displacement from steady sliding at most that many times ``L = max(f_s N / k, V / w, c V / k)``
        (``c V / k``: the stick segment's shift by the damping force), the velocity from the belt's at
        most that many times ``w L`` (farther starts are no friction problem: the spring alone carries
        them for a time beyond any event loop)."""
        x0, v0 = Q.check("x0", x0), Q.check("v0", v0)
        length = max(self.friction.static * self.normal_force / self.stiffness, self.belt_speed / self.omega,
                     abs(self.damping * self.belt_speed) / self.stiffness)
        scales = ("mass", "stiffness", "normal_force", "belt_speed", "fs", "damping")
        if abs(x0 - self.equilibrium) > MAX_START * length:
            raise ParameterError("x0", x0, f"within {MAX_START:g} x {length:.4g} m of steady sliding at "
                                 f"{self.equilibrium:.6g} m (the oscillator's length scale max(f_s N/k, V/w, c V/k))",
                                 also=scales)
        if abs(v0 - self.belt_speed) > MAX_START * self.omega * length:
            raise ParameterError("v0", v0, f"within {MAX_START:g} x {self.omega * length:.4g} m/s of the belt speed "
                                 f"{self.belt_speed:g} m/s (w times the oscillator's length scale)", also=scales)
        return x0, v0

    @property
    def stick_limits(self) -> tuple[float, float]:
        """``(x_lo, x_hi)``: sticking holds while ``|k x + c V| <= f_s N``.

        Without damping this is the paper's stick segment ``[-x_a, x_a]``,
        ``x_a = f_s N / k``.
        """
        fsn, cv = self.friction.static * self.normal_force, self.damping * self.belt_speed
        return ((-fsn - cv) / self.stiffness, (fsn - cv) / self.stiffness)

    def stick_force(self, x):
        """Friction force needed to keep the mass stuck at ``x``: ``k x + c V``."""
        return self.stiffness * x + self.damping * self.belt_speed

    def acceleration(self, x, v, mode: Mode):
        """``x''`` in a slip mode (``SLIP_POS`` or ``SLIP_NEG``)."""
        s = int(mode)
        v_r = self.belt_speed - v
        # on the mode's side of v_r = 0, as the flows take it: at a switch (v = V) a law that differs
        # there (a user's law of the signed v_r) gives the mode's own one-sided value
        friction = s * self.normal_force * self.friction.kinetic(s * np.maximum(np.abs(v_r), 1e-300))
        return (friction - self.damping * v - self.stiffness * x) / self.mass

    def vector_field(self, x, v, mode: Mode) -> np.ndarray:
        """Right-hand side ``(x', v')`` of the mode; ``(V, 0)`` while sticking."""
        if mode == Mode.STICK:
            return np.array([self.belt_speed, 0.0])
        return np.array([v, self.acceleration(x, v, mode)])

    def mode_at_switch(self, x: float) -> Mode:
        """Mode chosen on the switching line ``v = V`` (Filippov's convention)."""
        lo, hi = self.stick_limits
        if lo <= x <= hi:
            return Mode.STICK
        return Mode.SLIP_POS if x > hi else Mode.SLIP_NEG

    def initial_mode(self, x: float, v: float) -> Mode:
        """Mode of a state off or on the switching line."""
        if v < self.belt_speed:
            return Mode.SLIP_POS
        if v > self.belt_speed:
            return Mode.SLIP_NEG
        return self.mode_at_switch(x)

    # --- equilibrium and its stability -------------------------------------------
    @property
    def equilibrium(self) -> float:
        """Position of the steady-sliding equilibrium ``k x_e = N mu(V)``."""
        return self.normal_force * float(self.friction.kinetic(self.belt_speed)) / self.stiffness

    @property
    def effective_damping(self) -> float:
        """Damping of the linearisation about the equilibrium, ``c + N mu'(V)``.

        Negative for a falling law: the paper's ``m x'' - f_d tau N x' + k x = ...``.
        """
        return self.damping + self.normal_force * float(self.friction.slope(self.belt_speed))

    def equilibrium_eigenvalues(self) -> np.ndarray:
        """Eigenvalues of the linearisation about the equilibrium."""
        jac = np.array([[0.0, 1.0], [-self.stiffness / self.mass, -self.effective_damping / self.mass]])
        return np.linalg.eigvals(jac)

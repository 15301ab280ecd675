"""Parameters of the brake-like system (paper section 3, scaling above eq. [10]).

An elastic annulus (inner radius ``R``, outer radius ``R*``, Young's modulus ``E``,
Poisson's ratio ``nu``, density ``rho``) is fixed on its outer surface and pressed on a
rigid shaft of radius ``R + d`` turning at ``Omega``, with Coulomb friction ``f``.
The paper's dimensionless numbers are

    xi = R*/R,   gamma = rho R^2 Omega^2 / E,   delta = d/R,

with lengths scaled by ``R``, stresses by ``E`` and time by ``1/Omega`` (``t = Omega t̄``).
`BrakeParams` holds the dimensionless set; `PhysicalParams` the SI one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ...errors import ParameterError
from ...quantities import BRAKE as Q
from .coefficients import ReducedCoefficients, coefficients
from .steady import SteadySliding, steady_sliding

__all__ = ["BrakeParams", "PhysicalParams", "STEEL"]

#: Default material (the paper's section 4 values): Young [Pa], density [kg/m^3], Poisson.
STEEL = {"young": 2.1e11, "density": 7850.0, "poisson": 0.3}
#: The interference ``d/R`` is the hoop strain at the bore: linear (small-strain)
#: elasticity, the paper's model, does not hold beyond about 1 %.
MAX_STRAIN = 0.01
#: The range of the dimensionless ``gamma`` (declared in `stickslip.quantities.BRAKE`).
SCALE_RANGE = (Q["gamma"].range.lo, Q["gamma"].range.hi)
#: The largest Coulomb coefficient accepted (declared in `stickslip.quantities.BRAKE`).
MAX_FRICTION = Q["friction"].range.hi


def in_ratio(name: str, value: float, inner: float, inner_name: str = "inner_radius") -> float:
    """An outer radius whose ratio to ``inner`` is a valid radius ratio ``xi``."""
    xi = Q["xi"].range
    if not (xi.lo * inner <= value <= xi.hi * inner):
        raise ParameterError(name, value, f"in [{xi.lo:.4f}, {xi.hi:g}] x {inner_name} = {inner:g} m (the radius "
                             f"ratio xi: {Q['xi'].why})", also=(inner_name,))
    return value


def small_strain(name: str, mismatch: float, inner: float, inner_name: str = "inner_radius") -> float:
    """An interference ``d`` of at most `MAX_STRAIN` times the bore radius."""
    if mismatch > MAX_STRAIN * inner:
        raise ParameterError(name, mismatch, f"<= {MAX_STRAIN * inner:.6g} m ({MAX_STRAIN:g} x {inner_name}: the "
                             "interference is the hoop strain at the bore, and linear elasticity holds for small "
                             "strains only)", also=(inner_name,))
    return mismatch


@dataclass(frozen=True)
class PhysicalParams:
    """The brake-like system in SI units.

    Parameters
    ----------
    omega : float
        Shaft angular speed ``Omega`` [rad/s].
    mismatch : float
        Radial interference ``d`` [m] (shaft radius ``R + d``), at most `MAX_STRAIN` ``R``.
    friction : float
        Coulomb coefficient ``f``.
    inner_radius, outer_radius : float
        ``R`` and ``R*`` [m], ``R*/R`` a radius ratio ``xi``. Defaults 0.1 m and 0.15 m (``xi = 1.5``).
    young, density : float
        ``E`` [Pa] and ``rho`` [kg/m^3]. Defaults: steel.
    poisson : float
        ``nu``. Default 0.3.

    Every range is declared in `stickslip.quantities.BRAKE`; ``gamma = rho R^2 Omega^2 / E``
    must lie in the range of ``gamma``.
    """

    omega: float
    mismatch: float
    friction: float
    inner_radius: float = 0.1
    outer_radius: float = 0.15
    young: float = STEEL["young"]
    density: float = STEEL["density"]
    poisson: float = STEEL["poisson"]

    def __post_init__(self):
        for name in ("omega", "mismatch", "friction", "inner_radius", "outer_radius", "young", "density", "poisson"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        in_ratio("outer_radius", self.outer_radius, self.inner_radius)
        small_strain("mismatch", self.mismatch, self.inner_radius)
        gamma = Q["gamma"]
        if self.gamma not in gamma.range:
            scale = self.inner_radius * math.sqrt(self.density / self.young)
            lo, hi = math.sqrt(gamma.range.lo) / scale, math.sqrt(gamma.range.hi) / scale
            raise ParameterError("omega", self.omega, f"in [{lo:.3g}, {hi:.3g}] rad/s (gamma = rho R^2 Omega^2 / E "
                                 f"{gamma.range.text()}: {gamma.why})", also=("density", "young", "inner_radius"))

    @property
    def xi(self) -> float:
        return self.outer_radius / self.inner_radius

    @property
    def gamma(self) -> float:
        return self.density * self.inner_radius**2 * self.omega**2 / self.young

    @property
    def delta(self) -> float:
        return self.mismatch / self.inner_radius

    def dimensionless(self) -> "BrakeParams":
        """The paper's dimensionless parameters (remembering this physical set)."""
        return BrakeParams(self.xi, self.poisson, self.gamma, self.delta, self.friction, physical=self)


@dataclass(frozen=True)
class BrakeParams:
    """Dimensionless parameters of the brake-like system (paper, above eq. [10]).

    Parameters
    ----------
    xi : float
        Radius ratio ``R*/R``.
    nu : float
        Poisson's ratio.
    gamma : float
        Inertia number ``rho R^2 Omega^2 / E``.
    delta : float
        Mismatch ``d/R``. The model is linear: in these scaled units any ``delta`` is one
        problem rescaled; the small-strain bound is on the SI set.
    friction : float
        Coulomb coefficient ``f``.
    physical : PhysicalParams, optional
        The SI set these numbers come from, if any (for converting rates to 1/s).

    Every range is declared in `stickslip.quantities.BRAKE`.
    """

    xi: float
    nu: float
    gamma: float
    delta: float
    friction: float
    physical: PhysicalParams | None = field(default=None, compare=False, repr=False)

    def __post_init__(self):
        for name in ("xi", "nu", "gamma", "delta", "friction"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        if self.physical is not None and not isinstance(self.physical, PhysicalParams):
            raise ParameterError("physical", self.physical, "a PhysicalParams or None")

    @classmethod
    def from_physical(cls, omega: float, mismatch: float, friction: float, **material) -> "BrakeParams":
        """Build from SI values; ``material`` are the other `PhysicalParams` fields."""
        return PhysicalParams(omega, mismatch, friction, **material).dimensionless()

    def replace(self, **changes) -> "BrakeParams":
        """A copy with some dimensionless parameters changed (drops ``physical``)."""
        fields = dict(xi=self.xi, nu=self.nu, gamma=self.gamma, delta=self.delta, friction=self.friction)
        fields.update(changes)
        return BrakeParams(**fields)

    @property
    def omega(self) -> float:
        """Shaft speed [rad/s] if known, else ``nan`` (time unit is ``1/Omega``)."""
        return self.physical.omega if self.physical is not None else math.nan

    def to_dict(self) -> dict:
        out = {"xi": self.xi, "nu": self.nu, "gamma": self.gamma, "delta": self.delta, "friction": self.friction}
        if self.physical is not None:
            p = self.physical
            out["physical"] = {k: getattr(p, k) for k in p.__dataclass_fields__}
        return out

    def to_attrs(self) -> dict:
        """Flat attributes for a netCDF file (``physical_*`` for the SI set); see `from_attrs`."""
        out = {k: v for k, v in self.to_dict().items() if k != "physical"}
        if self.physical is not None:
            out.update({f"physical_{k}": v for k, v in self.to_dict()["physical"].items()})
        return out

    @classmethod
    def from_attrs(cls, attrs) -> "BrakeParams":
        """The parameters stored by `to_attrs` (other attributes are ignored)."""
        physical = {k[len("physical_"):]: float(v) for k, v in attrs.items() if k.startswith("physical_")}
        return cls(*(float(attrs[k]) for k in ("xi", "nu", "gamma", "delta", "friction")),
                   physical=PhysicalParams(**physical) if physical else None)

    def coefficients(self) -> ReducedCoefficients:
        """The reduced-model coefficients [13] (see `stickslip.brake.reduced.coefficients`)."""
        return coefficients(self.xi, self.nu, self.gamma)

    def steady(self) -> SteadySliding:
        """Steady sliding [11] and [16] (see `stickslip.brake.reduced.steady`)."""
        return steady_sliding(self.xi, self.nu, self.delta, self.friction, gamma=self.gamma)

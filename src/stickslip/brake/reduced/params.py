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

from ... import validation as check
from ...errors import ParameterError
from .coefficients import ReducedCoefficients, coefficients
from .steady import SteadySliding, steady_sliding

__all__ = ["BrakeParams", "PhysicalParams", "STEEL"]

#: Default material (the paper's section 4 values): Young [Pa], density [kg/m^3], Poisson.
STEEL = {"young": 2.1e11, "density": 7850.0, "poisson": 0.3}
#: The interference ``d/R`` is the hoop strain at the bore: linear (small-strain)
#: elasticity, the paper's model, does not hold beyond about 1 %.
MAX_STRAIN = 0.01
#: The range of the dimensionless ``gamma`` and ``delta``: the reduced coefficients scale
#: like ``1/gamma`` and the energies like ``gamma delta^2``; beyond these they leave the
#: range of double precision on the way.
SCALE_RANGE = (1e-100, 1e100)
#: The largest Coulomb coefficient accepted: measured ones stay below about 2 (clean
#: metals in vacuum); past 10 the model describes no contact there is.
MAX_FRICTION = 10.0


@dataclass(frozen=True)
class PhysicalParams:
    """The brake-like system in SI units.

    Parameters
    ----------
    omega : float
        Shaft angular speed ``Omega`` [rad/s] > 0.
    mismatch : float
        Radial interference ``d`` [m] >= 0 (shaft radius ``R + d``).
    friction : float
        Coulomb coefficient ``f`` >= 0.
    inner_radius, outer_radius : float
        ``R`` and ``R*`` [m], ``0 < R < R*``. Defaults 0.1 m and 0.15 m (``xi = 1.5``).
    young, density : float
        ``E`` [Pa] > 0 and ``rho`` [kg/m^3] > 0. Defaults: steel.
    poisson : float
        ``nu`` in [0, 0.5). Default 0.3.

    The interference is at most `MAX_STRAIN` ``R`` (small strain), the radius ratio in
    `stickslip.validation.RADIUS_RATIO`, and ``gamma`` in `SCALE_RANGE`.
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
        for name in ("omega", "inner_radius", "young", "density"):
            object.__setattr__(self, name, check.positive(name, getattr(self, name)))
        object.__setattr__(self, "mismatch", check.nonnegative("mismatch", self.mismatch))
        object.__setattr__(self, "friction", check.in_range("friction", self.friction, 0.0, MAX_FRICTION))
        outer = check.finite("outer_radius", self.outer_radius)
        if outer <= self.inner_radius:
            raise ParameterError("outer_radius", outer, f"> inner_radius = {self.inner_radius:g}",
                                 also=("inner_radius",))
        object.__setattr__(self, "outer_radius", outer)
        object.__setattr__(self, "poisson", check.poisson_ratio("poisson", self.poisson))
        lo, hi = check.RADIUS_RATIO
        if not lo * self.inner_radius <= outer <= hi * self.inner_radius:
            raise ParameterError("outer_radius", outer, f"in [{lo:.4f}, {hi:g}] x inner_radius "
                                 "(see the radius ratio xi)", also=("inner_radius",))
        if self.mismatch > MAX_STRAIN * self.inner_radius:
            raise ParameterError("mismatch", self.mismatch, f"<= {MAX_STRAIN * self.inner_radius:.6g} m "
                                 f"({MAX_STRAIN:g} inner_radius: the interference is the hoop strain at the bore, "
                                 "and linear elasticity holds for small strains only)", also=("inner_radius",))
        lo, hi = SCALE_RANGE
        speed = self.inner_radius * self.omega  # gamma = (rho / E) (R Omega)^2, without overflow on the way
        if not lo <= (self.density / self.young) * speed * speed <= hi:
            scale = self.inner_radius * math.sqrt(self.density / self.young)
            raise ParameterError("omega", self.omega, f"in [{math.sqrt(lo) / scale:.3g}, {math.sqrt(hi) / scale:.3g}] "
                                 f"rad/s (gamma = rho R^2 Omega^2 / E in [{lo:g}, {hi:g}])",
                                 also=("density", "young", "inner_radius"))

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
        Radius ratio ``R*/R`` in [1.0001, 1000] (`stickslip.validation.RADIUS_RATIO`).
    nu : float
        Poisson's ratio in [0, 0.5).
    gamma : float
        Inertia number ``rho R^2 Omega^2 / E`` in [1e-100, 1e100] (`SCALE_RANGE`).
    delta : float
        Mismatch ``d/R`` in [0, 1e100]. The model is linear: in these scaled units any
        ``delta`` is one problem rescaled; the small-strain bound is on the SI set.
    friction : float
        Coulomb coefficient ``f`` in [0, 10] (`MAX_FRICTION`).
    physical : PhysicalParams, optional
        The SI set these numbers come from, if any (for converting rates to 1/s).
    """

    xi: float
    nu: float
    gamma: float
    delta: float
    friction: float
    physical: PhysicalParams | None = field(default=None, compare=False, repr=False)

    def __post_init__(self):
        object.__setattr__(self, "xi", check.radius_ratio("xi", self.xi))
        object.__setattr__(self, "nu", check.poisson_ratio("nu", self.nu))
        lo, hi = SCALE_RANGE
        object.__setattr__(self, "gamma", check.in_range("gamma", self.gamma, lo, hi))
        object.__setattr__(self, "delta", check.nonnegative("delta", self.delta))
        if self.delta > hi:
            raise ParameterError("delta", self.delta, f"<= {hi:g}")
        object.__setattr__(self, "friction", check.in_range("friction", self.friction, 0.0, MAX_FRICTION))
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

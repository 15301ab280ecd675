"""Friction laws: small frozen objects, one formula each.

Convention (paper eq. [1]): the relative velocity is ``v_r = V - xdot`` (belt minus
body). While slipping, the friction force on the body is

    F = N * sign(v_r) * mu(v_r),   mu >= 0,

and while sticking (``v_r = 0``) the force adapts, with ``|F| <= f_s N``. Every law
exposes the static coefficient ``static`` (``f_s``), the kinetic coefficient
``kinetic(v_r)`` and its derivative ``slope(v_r)``. Laws that are affine in the slip
speed, ``mu = mu0 - mu1 |v_r|``, also expose ``affine = (mu0, mu1)``: the oscillator
then uses closed-form segments.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import Callable, ClassVar

import numpy as np

from . import validation as check
from .quantities import OSCILLATOR as Q
from .errors import MISSING, ParameterError

__all__ = ["FrictionLaw", "Coulomb", "LinearWeakening", "Stribeck", "UserLaw", "PressurePower", "law_names",
           "make_law"]

_REGISTRY: dict[str, type["FrictionLaw"]] = {}


class FrictionLaw(ABC):
    """Base class. Subclasses set ``name`` to register themselves for the CLI."""

    name: ClassVar[str] = ""
    static: float

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if cls.name:
            _REGISTRY[cls.name] = cls

    @abstractmethod
    def kinetic(self, v_r):
        """Kinetic coefficient ``mu(v_r) >= 0`` for slip velocity ``v_r != 0``."""

    @abstractmethod
    def slope(self, v_r):
        """Derivative ``d mu / d v_r``."""

    @property
    def affine(self) -> tuple[float, float] | None:
        """``(mu0, mu1)`` if ``mu(v_r) = mu0 - mu1 |v_r|``, else None."""
        return None

    @property
    def max_speed(self) -> float:
        """Largest slip speed ``|v_r|`` for which the law is valid (``inf`` if unbounded)."""
        return math.inf

    def force(self, v_r, normal_force):
        """Friction force on the body while slipping, ``N sign(v_r) mu(v_r)``."""
        return normal_force * np.sign(v_r) * self.kinetic(v_r)


def _check_pair(fs, fd):
    fd = Q.check("fd", fd)
    fs = check.at_least("fs", Q.check("fs", fs), fd, "fd")
    return fs, fd


@dataclass(frozen=True)
class Coulomb(FrictionLaw):
    """Coulomb friction, paper eqs. [2]-[6]: static ``fs`` >= kinetic ``fd``."""

    fs: float
    fd: float
    name: ClassVar[str] = "coulomb"

    def __post_init__(self):
        fs, fd = _check_pair(self.fs, self.fd)
        object.__setattr__(self, "fs", fs)
        object.__setattr__(self, "fd", fd)

    @property
    def static(self):
        return self.fs

    def kinetic(self, v_r):
        return self.fd + 0.0 * np.abs(v_r)

    def slope(self, v_r):
        return 0.0 * np.abs(v_r)

    @property
    def affine(self):
        return (self.fd, 0.0)


@dataclass(frozen=True)
class LinearWeakening(FrictionLaw):
    """Kinetic coefficient decreasing linearly with slip speed, eqs. [7]-[9].

    ``mu(v_r) = fd (1 - tau |v_r|)``; valid while ``tau |v_r| < 1``. Equation [9] as
    printed has the opposite sign of ``tau`` for reverse slip; the odd law used here is
    the one consistent with the paper's spiral centres (see docs/errata.md, E2).
    """

    fs: float
    fd: float
    tau: float
    name: ClassVar[str] = "linear-weakening"

    def __post_init__(self):
        fs, fd = _check_pair(self.fs, self.fd)
        object.__setattr__(self, "fs", fs)
        object.__setattr__(self, "fd", fd)
        object.__setattr__(self, "tau", Q.check("tau", self.tau))

    @property
    def static(self):
        return self.fs

    def kinetic(self, v_r):
        return self.fd * (1.0 - self.tau * np.abs(v_r))

    def slope(self, v_r):
        return -self.fd * self.tau * np.sign(v_r)

    @property
    def affine(self):
        return (self.fd, self.fd * self.tau)

    @property
    def max_speed(self):
        return math.inf if self.tau == 0 else 1.0 / self.tau


@dataclass(frozen=True)
class Stribeck(FrictionLaw):
    """Exponential Stribeck law ``mu = fd + (fs - fd) exp(-|v_r| / vs)``.

    Continuous at the stick limit (``mu(0+) = fs``); ``vs`` is the Stribeck speed.
    """

    fs: float
    fd: float
    vs: float
    name: ClassVar[str] = "stribeck"

    def __post_init__(self):
        fs, fd = _check_pair(self.fs, self.fd)
        object.__setattr__(self, "fs", fs)
        object.__setattr__(self, "fd", fd)
        object.__setattr__(self, "vs", Q.check("vs", self.vs))

    @property
    def static(self):
        return self.fs

    def kinetic(self, v_r):
        return self.fd + (self.fs - self.fd) * np.exp(-np.abs(v_r) / self.vs)

    def slope(self, v_r):
        return -np.sign(v_r) * (self.fs - self.fd) / self.vs * np.exp(-np.abs(v_r) / self.vs)


@dataclass(frozen=True)
class UserLaw(FrictionLaw):
    """Any callable ``mu(v_r) >= 0`` (signed ``v_r``), with static coefficient ``fs``.

    The derivative, needed for Floquet multipliers and stability, is taken by central
    differences with relative step ``step``.
    """

    mu: Callable[[float], float]
    fs: float
    step: float = 1e-6
    label: str = field(default="user")

    def __post_init__(self):
        if not callable(self.mu):
            raise ParameterError("mu", self.mu, "a callable mu(v_r) -> coefficient")
        object.__setattr__(self, "fs", Q.check("fs", self.fs))
        object.__setattr__(self, "step", Q.check("step", self.step))

    @property
    def static(self):
        return self.fs

    def kinetic(self, v_r):
        try:
            value = np.asarray(np.vectorize(self.mu, otypes=[float])(v_r), dtype=float)
        except Exception as err:  # noqa: BLE001 - the user's function: whatever it raises or returns
            raise ParameterError("mu(v_r)", f"{type(err).__name__}: {err}", "a function returning one number for each "
                                 "slip speed") from None
        q = Q["fd"]
        ok = np.isfinite(value) & (value >= q.range.lo) & (value <= q.range.hi)
        if not np.all(ok):
            raise ParameterError("mu(v_r)", float(value[~ok].flat[0]), f"a friction coefficient {q.allowed}")
        return value if value.ndim else float(value)

    def slope(self, v_r):
        v = np.asarray(v_r, dtype=float)
        h = self.step * np.maximum(1.0, np.abs(v))
        # stay on the side of v_r = 0 the slip is on
        lo = np.where(v > 0, np.maximum(v - h, 0.5 * v), v - h)
        hi = np.where(v < 0, np.minimum(v + h, 0.5 * v), v + h)
        out = (self.kinetic(hi) - self.kinetic(lo)) / (hi - lo)
        return out if np.ndim(out) else float(out)


def law_names() -> list[str]:
    """Names of the registered built-in laws (the CLI's ``--law`` choices)."""
    return sorted(_REGISTRY)


def make_law(name: str, *, fs: float, fd: float, tau: float | None = None, vs: float | None = None) -> FrictionLaw:
    """Build a registered law from the CLI's parameters, named as the laws' fields.

    ``tau`` is the weakening rate [s/m] of ``linear-weakening``, ``vs`` the Stribeck speed
    [m/s] of ``stribeck``; each is required by its law and refused by the others.
    """
    if not isinstance(name, str) or name not in _REGISTRY:
        raise ParameterError("law", name, "one of " + ", ".join(law_names()))
    needs = {"coulomb": None, "linear-weakening": "tau", "stribeck": "vs"}[name]
    for given, value in (("tau", tau), ("vs", vs)):
        if value is not None and given != needs:
            raise ParameterError(given, value, f"left out with law {name!r} (it sets "
                                 f"{'linear-weakening' if given == 'tau' else 'stribeck'})")
    if needs is not None and {"tau": tau, "vs": vs}[needs] is None:
        raise ParameterError(needs, MISSING, f"given for law {name!r}")
    if name == "coulomb":
        return Coulomb(fs, fd)
    if name == "linear-weakening":
        return LinearWeakening(fs, fd, tau)
    return Stribeck(fs, fd, vs)


@dataclass(frozen=True)
class PressurePower:
    """A friction coefficient that depends on the contact pressure ``P`` as a power, on top of any
    law of the slip speed: ``mu(v_r, P) = mu(v_r) (P / P_ref)^(-n)``, the static
    coefficient likewise (brake linings: ``pressure_exponent`` of 0.05-0.3, friction falling as
    the pressure rises). ``reference_pressure`` [Pa] is the pressure at which the law is its own;
    ``pressure_exponent`` in [-1, 1): below 1 the friction force ``mu P`` still grows with ``P``.

    Used by the contacts of `stickslip.fem`, where ``P`` is a contact node's normal force over
    its tributary length (`stickslip.fem.boundary.tributary_lengths`). ``factor(P)`` is the
    multiplier (1 where ``P <= 0``: no force, nothing to multiply) and ``rate`` the multiplier
    of the friction force's derivative, ``d(mu P)/dP = mu (1 - exponent)``."""

    reference_pressure: float
    pressure_exponent: float

    def __post_init__(self):
        from .quantities import COMMON

        for name in ("reference_pressure", "pressure_exponent"):
            object.__setattr__(self, name, COMMON.check(name, getattr(self, name)))

    @property
    def reference(self) -> float:
        """``reference_pressure`` [Pa]."""
        return self.reference_pressure

    @property
    def exponent(self) -> float:
        """``pressure_exponent``."""
        return self.pressure_exponent

    def factor(self, pressure):
        """``(P / P_ref)^(-n)`` where ``P > 0``, 1 elsewhere."""
        P = np.asarray(pressure, dtype=float)
        positive = P > 0
        return np.where(positive, (np.where(positive, P, self.reference) / self.reference) ** -self.exponent, 1.0)

    @property
    def rate(self) -> float:
        """``d(factor(P) P)/dP / factor(P) = 1 - n``."""
        return 1.0 - self.exponent

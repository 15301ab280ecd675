"""The flutter instability of steady sliding: an elastic half-space sliding on a rigid body with
friction, perturbed by one Fourier mode, and whether the problem is well posed.

Steady sliding in ``+x`` (contact closed, slip rate ``V0 > 0``, shear traction ``f N``) perturbed by
``e^{i k x + s t}`` (``k > 0``, ``s = p k c_s``): the surface stays on the rigid body (``U_y = 0``) and
keeps sliding, so the shear traction follows the normal one, ``d sigma_xy = -f d sigma_eff`` with
``sigma_eff`` the pressure the strength sees. With the surface's stiffness
(`stickslip.sbim.inplane_kernels`: ``sigma_xy = -mu k S11 U_x``, ``sigma_yy = -i mu k S12 U_x`` there)::

    F(p) = S11(p) + i f S12(p) / (1 + kappa p) = 0,

``kappa = 0`` for Coulomb's law (the pressure at once) and ``kappa = k c_s t_r`` for Prakash and
Clifton's regularisation, ``sigma_eff' = -(|V| + V*) / L (sigma_eff - N)``, ``t_r = L / (V0 + V*)``.
A root with ``Re p > 0`` grows at ``Re(p) k c_s`` and travels in the sliding direction at
``-Im(p) c_s`` (sliding in ``-x`` or ``k < 0``: the conjugate roots, the same rates).

**Coulomb's law: ill-posed above f = 1.** The growth rate of a root is proportional to ``k``: the
shortest wavelengths grow fastest, so a run does not converge as its grid is refined (Renardy, 1992;
Martins, Guimaraes and Faria, 1995, found such growing surface waves for large friction and Poisson's
ratio). Here a root leaves the branch cut at ``p = -i sqrt(2)`` when ``f = 1``
for every ``nu > 0`` (there ``b = -i``, ``a = sqrt(1 - 2 / eta^2)`` and ``F = 0`` exactly), travelling
at about ``sqrt(2) c_s``. At ``nu = 0`` the roots stay on the imaginary axis (neutral); at large ``f``
they return to it. `ill_posedness` asks the roots at the coefficients a law can slide with.

**Regularised: well posed.** With ``kappa = k c_s t_r`` the coupling fades for ``|s| t_r >> 1``: the
growth rates stay bounded as ``k`` grows and a run converges as the grid is refined (Ranjith and
Rice, 2001; Cochard and Rice, 2000).

Roots are counted by the argument principle on the rectangle ``FLOOR <= Re p <= R``, ``|Im p| <= R``
(its edges refined until the phase turns by less than 0.3 between points), found from the minima
of ``|F|`` on a grid by Newton's method, and the two must agree.
"""

from __future__ import annotations

import logging
import math

import numpy as np

from ..errors import NoSolutionError, ParameterError
from ..quantities.sbim import SBIM as Q
from .inplane_kernels import inplane_stiffness, wave_speed_ratio
from .surface import Solid

__all__ = ["flutter_function", "flutter_roots", "flutter_growth", "ill_posedness", "bimaterial_flutter_function",
           "bimaterial_roots", "bimaterial_ill_posedness", "FLUTTER_ONSET", "FLOOR"]

log = logging.getLogger("stickslip.sbim")

#: The friction coefficient above which steady sliding on a rigid body flutters (every ``nu > 0``).
FLUTTER_ONSET = 1.0
#: Roots with ``Re p`` below this (a growth by e in more than 1e5 periods) count as neutral.
FLOOR = 1e-6


def flutter_function(p, friction: float, poisson: float, relaxation: float = 0.0) -> np.ndarray:
    """``F(p) = S11(p) + i f S12(p) / (1 + relaxation p)`` at ``p`` with ``Re p > 0`` (module docstring)."""
    S11, _, S12 = inplane_stiffness(p, poisson)
    return S11 + 1j * friction * S12 / (1.0 + relaxation * np.asarray(p, dtype=complex))


def _checked(friction, poisson, relaxation):
    return Q.check("friction", friction), Q.check("poisson", poisson), Q.check("relaxation", relaxation)


def _edge(F, a: complex, b: complex) -> np.ndarray:
    """``F`` along the segment ``a -> b``, refined until consecutive values turn by less than 0.3 rad."""
    t = np.linspace(0.0, 1.0, 257)
    for _ in range(40):
        v = F(a + (b - a) * t)
        turn = np.abs(np.angle(v[1:] / v[:-1]))
        bad = np.nonzero(turn > 0.3)[0]
        if bad.size == 0 or t.size > 2_000_000:
            return v
        t = np.sort(np.concatenate([t, (t[bad] + t[bad + 1]) / 2.0]))
    return v


def _winding(F, R: float) -> int:
    corners = [FLOOR - 1j * R, R - 1j * R, R + 1j * R, FLOOR + 1j * R, FLOOR - 1j * R]
    total = 0.0
    for a, b in zip(corners[:-1], corners[1:]):
        v = _edge(F, a, b)
        total += float(np.sum(np.angle(v[1:] / v[:-1])))
    return int(round(total / (2.0 * math.pi)))


def _newton(F, p: complex) -> complex | None:
    for _ in range(60):
        h = 1e-7 * max(1.0, abs(p))
        try:
            f0 = complex(F(p))
            df = (complex(F(p + h)) - complex(F(p - h))) / (2.0 * h) if p.real > h else \
                (complex(F(p + h)) - f0) / h
        except ParameterError:
            return None
        if df == 0.0:
            return None
        step = f0 / df
        new = p - step
        while new.real <= 0.0:  # stay where F is defined
            step /= 2.0
            new = p - step
        p = new
        if abs(step) < 1e-13 * max(1.0, abs(p)):
            return p if abs(complex(F(p))) < 1e-9 * (1.0 + abs(p)) else None
    return None


def flutter_roots(friction: float, poisson: float, relaxation: float = 0.0) -> np.ndarray:
    """The roots ``p`` with ``Re p > FLOOR`` of `flutter_function` (sliding in ``+x``, ``k > 0``), by the
    largest real part first; empty when steady sliding is stable to every mode of this ``relaxation``."""
    friction, poisson, relaxation = _checked(friction, poisson, relaxation)

    def F(p):
        return flutter_function(p, friction, poisson, relaxation)

    eta = wave_speed_ratio(poisson)
    R = 4.0 + 2.0 * eta + 2.0 * friction * max(1.0, abs(2.0 - eta))
    return _roots(F, R, f"the flutter equation at friction {friction:g}, poisson {poisson:g}, relaxation "
                  f"{relaxation:g}")


def _roots(F, R: float, what: str) -> np.ndarray:
    """The roots of ``F`` with ``FLOOR < Re p < R``, ``|Im p| < R``: counted by the argument principle,
    found from the minima of ``|F|`` on a grid by Newton's method; the two must agree."""
    count = _winding(F, R)
    if count == 0:
        return np.zeros(0, dtype=complex)
    X, Y = np.meshgrid(np.geomspace(FLOOR, R, 160), np.linspace(-R, R, 641))
    A = np.abs(F(X + 1j * Y)) / (1.0 + np.hypot(X, Y))
    inner = A[1:-1, 1:-1]
    low = np.ones(inner.shape, bool)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            if di or dj:
                low &= inner <= A[1 + di:A.shape[0] - 1 + di, 1 + dj:A.shape[1] - 1 + dj]
    found: list[complex] = []
    for i, j in sorted(zip(*np.nonzero(low)), key=lambda ij: inner[ij]):
        p = _newton(F, complex(X[i + 1, j + 1], Y[i + 1, j + 1]))
        if p is not None and FLOOR < p.real < R and abs(p.imag) < R and all(abs(p - q) > 1e-7 for q in found):
            found.append(p)
        if len(found) == count:
            break
    if len(found) != count:
        raise NoSolutionError(f"{what} has {count} roots with a positive real part by the argument principle but "
                              f"{len(found)} were found")
    return np.array(sorted(found, key=lambda q: -q.real))


def flutter_growth(wavenumber: float, friction: float, poisson: float, shear_wave_speed: float,
                   relaxation_time: float = 0.0) -> tuple[float, float]:
    """The fastest perturbation of steady sliding of ``wavenumber`` [1/m]: its growth rate [1/s] and its
    speed along the sliding direction [m/s] (0 and 0 when none grows); ``relaxation_time`` [s] is
    Prakash and Clifton's ``L / (V0 + V*)`` (0: Coulomb's law)."""
    wavenumber = Q.check("wavenumber", wavenumber)
    cs = Q.check("shear_wave_speed", shear_wave_speed)
    relaxation_time = Q.check("relaxation_time", relaxation_time)
    if wavenumber * cs * relaxation_time > 1e12:
        raise ParameterError("relaxation_time", relaxation_time, f"at most {1e12 / (wavenumber * cs):.3g} s here "
                             "(k c_s t_r at most 1e12)", also=("wavenumber", "shear_wave_speed"))
    roots = flutter_roots(friction, poisson, wavenumber * cs * relaxation_time)
    if roots.size == 0:
        return 0.0, 0.0
    return float(roots[0].real * wavenumber * cs), float(-roots[0].imag * cs)


def ill_posedness(law, poisson: float) -> str:
    """Why a run with the friction ``law`` (`stickslip.sbim.interface`) is ill-posed, or ``""``: sliding at
    a coefficient it can take flutters, at a growth rate proportional to the wavenumber; regularised
    (`PrakashClifton`) it is not."""
    poisson = Q.check("poisson", poisson)
    if not hasattr(law, "sliding_coefficients"):
        raise ParameterError("law", law, "a friction law of stickslip.sbim (CoulombFriction, ...)")
    if getattr(law, "relaxation_slip", None) is not None:
        return ""
    worst, f = _fastest(law, FLUTTER_ONSET, lambda c: flutter_roots(c, poisson))
    if not worst:
        return ""
    return (f"ill-posed: sliding with friction {f:g} > {FLUTTER_ONSET:g} on a rigid body flutters (nu = "
            f"{float(poisson):g}): a perturbation of wavenumber k grows at {worst:.3g} k c_s, faster the finer "
            f"the grid, so the run does not converge as the grid is refined; regularise the pressure the "
            f"strength sees (PrakashClifton)")


def bimaterial_flutter_function(p, friction: float, upper: Solid, lower: Solid, relaxation: float = 0.0):
    """The determinant of steady sliding's perturbed conditions between two half-spaces, ``upper`` sliding
    in ``+x`` on ``lower`` (module docstring, Two materials), at ``p = s / (k c_s+)`` with ``Re p > 0``,
    divided by ``(1 + mu- / mu+)(1 + p)^2`` (no root added or lost)."""
    p = np.asarray(p, dtype=complex)
    S11u, S22u, S12u = inplane_stiffness(p, upper.poisson)
    S11l, S22l, S12l = inplane_stiffness(p * (upper.shear_wave_speed / lower.shear_wave_speed), lower.poisson)
    m = lower.shear_modulus / upper.shear_modulus
    fe = friction / (1.0 + relaxation * p)
    # rows: shear and normal tractions equal, shear following the pressure; columns: u+_x, u-_x, u_y
    rows = ((-S11u, -m * S11l, 1j * (S12u - m * S12l)),
            (-1j * S12u, 1j * m * S12l, -(S22u + m * S22l)),
            (-S11u - 1j * fe * S12u, 0.0 * p, 1j * S12u - fe * S22u))
    (a, b, c), (d, e, f), (g, h, i) = rows
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return det / ((1.0 + m) * (1.0 + p) ** 2)


def bimaterial_roots(friction: float, upper: Solid, lower: Solid, relaxation: float = 0.0) -> np.ndarray:
    """The roots ``p = s / (k c_s+)`` with ``Re p > FLOOR`` of `bimaterial_flutter_function`, by the largest
    real part first; empty when steady sliding of ``upper`` on ``lower`` is stable to every mode."""
    for name, solid in (("upper", upper), ("lower", lower)):
        if not isinstance(solid, Solid):
            raise ParameterError(name, solid, "a Solid(shear_modulus, shear_wave_speed, poisson)")
    friction, _, relaxation = _checked(friction, upper.poisson, relaxation)

    def F(p):
        return bimaterial_flutter_function(p, friction, upper, lower, relaxation)

    ratio = upper.shear_wave_speed / lower.shear_wave_speed
    R = 4.0 + 2.0 * max(upper.eta, lower.eta / ratio, 1.0 / ratio) + 2.0 * friction * max(
        1.0, abs(2.0 - upper.eta), abs(2.0 - lower.eta))
    return _roots(F, R, f"the flutter equation of two materials at friction {friction:g}, relaxation {relaxation:g}")


def bimaterial_ill_posedness(law, upper: Solid, lower: Solid) -> str:
    """As `ill_posedness`, for ``upper`` sliding on ``lower``: between two materials any coefficient may
    flutter (Adams; Ranjith and Rice, 2001), so every coefficient the law can slide with is asked."""
    if not hasattr(law, "sliding_coefficients"):
        raise ParameterError("law", law, "a friction law of stickslip.sbim (CoulombFriction, ...)")
    for name, solid in (("upper", upper), ("lower", lower)):
        if not isinstance(solid, Solid):
            raise ParameterError(name, solid, "a Solid(shear_modulus, shear_wave_speed, poisson)")
    if getattr(law, "relaxation_slip", None) is not None:
        return ""
    worst, f = _fastest(law, 0.0, lambda c: bimaterial_roots(c, upper, lower))
    if not worst:
        return ""
    return (f"ill-posed: sliding with friction {f:g} between two materials flutters (Adams' instability): a "
            f"perturbation of wavenumber k grows at {worst:.3g} k c_s of the upper solid, faster the finer the "
            f"grid, so the run does not converge as the grid is refined; regularise the pressure the strength "
            f"sees (PrakashClifton)")


def _fastest(law, onset: float, roots) -> tuple[float, float]:
    """The largest growth ``Re p`` over the coefficients above ``onset`` the ``law`` can slide with, and
    that coefficient (``(0, 0)``: none grows); ``roots(c)`` as `flutter_roots`."""
    worst, f = 0.0, 0.0
    for c in law.sliding_coefficients():
        if c > onset:
            found = roots(c)
            if found.size and found[0].real > worst:
                worst, f = found[0].real, c
    return worst, f

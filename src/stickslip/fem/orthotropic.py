"""An orthotropic material in the plane: a brake lining (pressed along one direction, its
fibres along another).

Material axes 1 and 2 lie in the plane, turned by ``angle`` [deg] counter-clockwise from x and
y; axis 3 is out of the plane. With the engineering constants ``e1, e2, e3`` [Pa], ``nu12,
nu13, nu23`` (``nu_ij``: the contraction along ``j`` per strain along ``i`` under a stress
along ``i``) and the in-plane shear modulus ``g12`` [Pa], the normal compliance is

    S = [[1/e1, -nu12/e1, -nu13/e1], [-nu12/e1, 1/e2, -nu23/e2], [-nu13/e1, -nu23/e2, 1/e3]].

Plane stress (``sigma_33 = 0``) takes the in-plane block ``S[:2, :2]`` and needs no ``e3``;
plane strain (``epsilon_33 = 0``) takes the in-plane block of ``S^-1``, so ``e3, nu13, nu23``
are needed. In Voigt form ``(sigma_11, sigma_22, sigma_12) = D_m (eps_11, eps_22, gamma_12)``
with ``D_m[2, 2] = g12``; in the x-y axes ``D = T^T D_m T``, ``T`` the rotation of engineering
strains into the material axes. An isotropic material is the case ``e1 = e2 = e3 = E``,
``nu12 = nu13 = nu23 = nu``, ``g12 = E / (2 (1 + nu))``. The compliance must be positive
definite (a material that stores energy under every strain).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ParameterError
from ..quantities import FEM as Q

__all__ = ["Orthotropic", "strain_rotation"]


def strain_rotation(angle: float) -> np.ndarray:
    """``T`` with ``(eps_11, eps_22, gamma_12) = T (eps_xx, eps_yy, gamma_xy)`` for material axes
    turned by ``angle`` [deg] counter-clockwise from x, y."""
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    return np.array([[c * c, s * s, c * s], [s * s, c * c, -c * s], [-2 * c * s, 2 * c * s, c * c - s * s]])


@dataclass(frozen=True)
class Orthotropic:
    """In-plane orthotropic linear elastic material (see the module docstring): ``e1, e2`` [Pa],
    ``nu12``, ``g12`` [Pa], ``density`` [kg/m^3], ``angle`` [deg], ``plane`` ``"strain"``
    (default; then ``e3`` [Pa], ``nu13``, ``nu23`` too) or ``"stress"``, Rayleigh ``alpha`` [1/s]
    and ``beta`` [s], a structural ``loss_factor`` (`stickslip.fem.Material`'s). Ranges:
    `stickslip.quantities.FEM`."""

    e1: float
    e2: float
    nu12: float
    g12: float
    density: float
    angle: float = 0.0
    plane: str = "strain"
    e3: float | None = None
    nu13: float | None = None
    nu23: float | None = None
    alpha: float = 0.0
    beta: float = 0.0
    loss_factor: float = 0.0

    #: Orthotropic constants are SI only (a scaled model is isotropic).
    scaled = False

    def __post_init__(self):
        for name in ("e1", "e2", "g12", "density", "nu12", "angle", "plane", "alpha", "beta", "loss_factor"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        out = ("e3", "nu13", "nu23")
        if self.plane == "strain":
            missing = [k for k in out if getattr(self, k) is None]
            if missing:
                raise ParameterError(missing[0], None, "given in plane strain (the out-of-plane direction is held: "
                                     "e3, nu13 and nu23 set its stress)", also=tuple(missing[1:]))
            for name in out:
                object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        elif any(getattr(self, k) is not None for k in out):
            given = [k for k in out if getattr(self, k) is not None]
            raise ParameterError(given[0], getattr(self, given[0]), "left out in plane stress (the out-of-plane "
                                 "stress is zero: only e1, e2, nu12, g12 act)")
        S = self.compliance
        if not np.all(np.linalg.eigvalsh(S if self.plane == "strain" else S[:2, :2]) > 0):
            raise ParameterError("nu12", self.nu12, "Poisson's ratios that make the compliance positive definite "
                                 f"(nu12^2 < e1/e2 = {self.e1 / self.e2:.4g}, and with nu13, nu23 in plane strain: "
                                 "the material must store energy under every strain)",
                                 also=("nu13", "nu23") if self.plane == "strain" else ())

    @property
    def compliance(self) -> np.ndarray:
        """The normal compliance ``S`` [1/Pa] (3 x 3; its third row and column NaN-free zeros in plane stress)."""
        e1, e2, n12 = self.e1, self.e2, self.nu12
        if self.plane == "stress":
            return np.array([[1 / e1, -n12 / e1, 0.0], [-n12 / e1, 1 / e2, 0.0], [0.0, 0.0, 0.0]])
        e3, n13, n23 = self.e3, self.nu13, self.nu23
        return np.array([[1 / e1, -n12 / e1, -n13 / e1], [-n12 / e1, 1 / e2, -n23 / e2],
                         [-n13 / e1, -n23 / e2, 1 / e3]])

    @property
    def material_stiffness(self) -> np.ndarray:
        """``D_m`` [Pa] in the material axes (Voigt, engineering shear strain)."""
        S = self.compliance
        C = np.linalg.inv(S)[:2, :2] if self.plane == "strain" else np.linalg.inv(S[:2, :2])
        D = np.zeros((3, 3))
        D[:2, :2], D[2, 2] = C, self.g12
        return D

    @property
    def stiffness(self) -> np.ndarray:
        """``D`` [Pa] in the x-y axes: ``(sigma_xx, sigma_yy, sigma_xy) = D (eps_xx, eps_yy, gamma_xy)``."""
        T = strain_rotation(self.angle)
        return T.T @ self.material_stiffness @ T

    def sigma_zz(self, sigma: np.ndarray) -> np.ndarray:
        """The out-of-plane stress of in-plane stresses ``(..., 3)`` (x-y axes) [Pa]: 0 in plane
        stress; in plane strain ``e3 (nu13 sigma_11 / e1 + nu23 sigma_22 / e2)`` (from ``eps_33 = 0``)."""
        sigma = np.asarray(sigma, dtype=float)
        if self.plane == "stress":
            return np.zeros(sigma.shape[:-1])
        c, s = math.cos(math.radians(self.angle)), math.sin(math.radians(self.angle))
        sxx, syy, sxy = sigma[..., 0], sigma[..., 1], sigma[..., 2]
        s11 = c * c * sxx + s * s * syy + 2 * c * s * sxy
        s22 = s * s * sxx + c * c * syy - 2 * c * s * sxy
        return self.e3 * (self.nu13 * s11 / self.e1 + self.nu23 * s22 / self.e2)

    @property
    def young(self) -> float:
        """The stiffest of the moduli [Pa] — the scale of strains and loads (`stickslip.fem.assembly`)."""
        return float(max(self.e1, self.e2, self.e3 or 0.0))

    @property
    def poisson(self) -> float:
        """``nu12`` (recorded as the material's Poisson's ratio beside its full description)."""
        return float(self.nu12)

    @property
    def p_wave_speed(self) -> float:
        """The fastest quasi-longitudinal wave in the plane [m/s] — the largest eigenvalue of the
        acoustic tensor ``Gamma_ik = C_ijkl n_j n_l`` over directions ``n`` (every half degree),
        over the density."""
        D = self.stiffness
        fastest = 0.0
        for phi in np.radians(np.arange(0.0, 180.0, 0.5)):
            n1, n2 = math.cos(phi), math.sin(phi)
            g11 = D[0, 0] * n1 * n1 + 2 * D[0, 2] * n1 * n2 + D[2, 2] * n2 * n2
            g22 = D[2, 2] * n1 * n1 + 2 * D[1, 2] * n1 * n2 + D[1, 1] * n2 * n2
            g12 = D[0, 2] * n1 * n1 + (D[0, 1] + D[2, 2]) * n1 * n2 + D[1, 2] * n2 * n2
            fastest = max(fastest, 0.5 * (g11 + g22) + math.hypot(0.5 * (g11 - g22), g12))
        return math.sqrt(fastest / self.density)

    def describe(self, plane: bool = True) -> str:
        """One line: every constant (for a file's attributes; ``plane`` as `stickslip.fem.Material.describe`'s:
        a plane body's material always has its plane)."""
        out = f", e3 = {self.e3:g} Pa, nu13 = {self.nu13:g}, nu23 = {self.nu23:g}" if self.plane == "strain" else ""
        return (f"orthotropic: e1 = {self.e1:g} Pa, e2 = {self.e2:g} Pa, nu12 = {self.nu12:g}, g12 = {self.g12:g} Pa"
                f"{out}, angle = {self.angle:g} deg, plane {self.plane}"
                + (f", loss factor {self.loss_factor:g}" if self.loss_factor else ""))

"""Stiffness, lumped mass and Rayleigh damping of a `Body` (scikit-fem), in SI units.

`assemble(body, material, springs, loads)` returns a `BodySystem`: ``K`` (CSR, N/m per unit
thickness, with the boundary springs), the row-sum lumped ``mass`` (kg per unit thickness),
the constant ``load`` (N per unit thickness, from `stickslip.fem.boundary`) and the Rayleigh
coefficients, on the Cartesian dofs ``2 i`` (x) and ``2 i + 1`` (y) of node ``i``. Plane strain uses the Lamé
parameters ``lambda = E nu / ((1 + nu)(1 - 2 nu))``, ``mu = E / (2 (1 + nu))``; plane stress
replaces ``lambda`` by ``2 lambda mu / (lambda + 2 mu)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
from skfem import Basis, BilinearForm, ElementQuad1, ElementTriP1, ElementVector, MeshQuad, MeshTri, asm
from skfem.helpers import dot
from skfem.models.elasticity import lame_parameters, linear_elasticity

from .. import validation as check
from ..errors import ParameterError
from .body import Body
from .boundary import Load, Spring, boundary_load, boundary_springs

__all__ = ["Material", "BodySystem", "assemble", "cell_stress"]

PLANES = ("strain", "stress")
#: Largest Young's modulus [Pa] and density [kg/m^3] accepted: a thousand times diamond's and
#: osmium's; beyond, springs and loads vanish against the stiffness in double precision.
MAX_MODULUS, MAX_DENSITY = 1e15, 1e7


@dataclass(frozen=True)
class Material:
    """Linear elastic material: Young's modulus ``young`` [Pa], Poisson's ratio ``poisson``,
    ``density`` [kg/m^3], ``plane`` ``"strain"`` (default) or ``"stress"``, and Rayleigh
    damping ``C = alpha M + beta K`` (``alpha`` [1/s], ``beta`` [s], both >= 0)."""

    young: float
    poisson: float
    density: float
    plane: str = "strain"
    alpha: float = 0.0
    beta: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "young", check.in_range("young", self.young, 0.0, MAX_MODULUS, lo_open=True))
        object.__setattr__(self, "poisson", check.poisson_ratio("poisson", self.poisson))
        object.__setattr__(self, "density", check.in_range("density", self.density, 0.0, MAX_DENSITY, lo_open=True))
        object.__setattr__(self, "alpha", check.nonnegative("alpha", self.alpha))
        object.__setattr__(self, "beta", check.nonnegative("beta", self.beta))
        if self.plane not in PLANES:
            raise ParameterError("plane", self.plane, "strain or stress")

    @property
    def lame(self) -> tuple[float, float]:
        """``(lambda, mu)`` of the plane problem [Pa]."""
        lam, mu = lame_parameters(self.young, self.poisson)
        return (2 * lam * mu / (lam + 2 * mu) if self.plane == "stress" else lam), mu

    @property
    def p_wave_speed(self) -> float:
        """``sqrt((lambda + 2 mu) / rho)`` of the plane problem [m/s]: it sets the stable step."""
        lam, mu = self.lame
        return math.sqrt((lam + 2 * mu) / self.density)


@BilinearForm
def _mass(u, v, w):
    return dot(u, v)


@dataclass(frozen=True, eq=False)
class BodySystem:
    """The assembled body: ``K``, the lumped ``mass`` and the constant ``load`` on all ``2 n``
    Cartesian dofs; ``springs`` and ``loads`` are what `assemble` added."""

    body: Body
    material: Material
    K: sp.csr_matrix
    mass: np.ndarray
    load: np.ndarray | None = None
    springs: tuple = ()
    loads: tuple = ()

    def __post_init__(self):
        if self.load is None:
            object.__setattr__(self, "load", np.zeros(self.K.shape[0]))

    @property
    def n_dofs(self) -> int:
        return self.K.shape[0]

    def damping(self) -> sp.csr_matrix:
        """Rayleigh damping ``alpha M + beta K``."""
        m = self.material
        return (sp.diags(m.alpha * self.mass) + m.beta * self.K).tocsr()

    @cached_property
    def basis(self) -> tuple:
        """``(basis, order)``: the scikit-fem vector basis of the body and, for each dof ``2 i + c``,
        its index in scikit-fem's numbering."""
        basis = _basis(self.body)
        order = np.empty(self.n_dofs, dtype=np.int64)
        order[0::2], order[1::2] = basis.nodal_dofs[0], basis.nodal_dofs[1]
        return basis, order

    def dofs(self, nodes) -> np.ndarray:
        """The x and y dofs of ``nodes``, interleaved."""
        nodes = np.asarray(nodes, dtype=np.int64)
        return np.stack([2 * nodes, 2 * nodes + 1], axis=1).ravel()


def _basis(body: Body) -> Basis:
    mesh_type, element = (MeshTri, ElementTriP1) if body.kind == "triangle" else (MeshQuad, ElementQuad1)
    mesh = mesh_type(np.ascontiguousarray(body.points.T), np.ascontiguousarray(body.cells.T))
    return Basis(mesh, ElementVector(element()))


def cell_stress(system: BodySystem, u) -> np.ndarray:
    """The in-plane stress ``(sigma_xx, sigma_yy, sigma_xy)`` [Pa] of the Cartesian displacement
    ``u`` (``(2 n,)`` or ``(k, 2 n)``, in m) in every cell, its mean over the cell: shape
    ``(n_cells, 3)`` or ``(k, n_cells, 3)``. Plane strain or plane stress as the material says
    (in plane strain ``sigma_zz = nu (sigma_xx + sigma_yy)``)."""
    if not isinstance(system, BodySystem):
        raise ParameterError("system", system, "a BodySystem (see assemble)")
    u = np.asarray(u, dtype=float)
    if u.shape[-1] != system.n_dofs or u.ndim > 2:
        raise ParameterError("u", f"an array of shape {u.shape}", f"(2 n,) or (k, 2 n) with 2 n = {system.n_dofs}")
    basis, order = system.basis
    lam, mu = system.material.lame
    weights = basis.dx / basis.dx.sum(axis=1, keepdims=True)
    out = []
    for one in np.atleast_2d(u):
        x = np.empty(system.n_dofs)
        x[order] = one
        g = np.sum(basis.interpolate(x).grad * weights, axis=-1)  # g[i, j] = d u_i / d x_j, cell means
        trace = g[0, 0] + g[1, 1]
        out.append(np.column_stack([lam * trace + 2 * mu * g[0, 0], lam * trace + 2 * mu * g[1, 1],
                                    mu * (g[0, 1] + g[1, 0])]))
    return np.array(out) if u.ndim == 2 else out[0]


def assemble(body: Body, material: Material, springs=(), loads=()) -> BodySystem:
    """Assemble the stiffness and the row-sum lumped mass of ``body`` with its boundary
    ``springs`` (`Spring`) and ``loads`` (`Load`) (see the module docstring)."""
    if not isinstance(body, Body):
        raise ParameterError("body", body, "a Body (see read_body)")
    if not isinstance(material, Material):
        raise ParameterError("material", material, "a Material")
    springs, loads = tuple(springs), tuple(loads)
    for name, items, kind in (("springs", springs, Spring), ("loads", loads, Load)):
        if not all(isinstance(x, kind) for x in items):
            raise ParameterError(name, items, f"a sequence of {kind.__name__}")
    basis = _basis(body)
    K = asm(linear_elasticity(*material.lame), basis)
    lumped = material.density * np.asarray(asm(_mass, basis).sum(axis=1)).ravel()
    # scikit-fem numbers the dofs by component blocks or interleaved depending on the element:
    # reorder to 2 i + c, the convention of the contact machinery
    order = np.empty(2 * len(body.points), dtype=np.int64)
    order[0::2], order[1::2] = basis.nodal_dofs[0], basis.nodal_dofs[1]
    K = K[order][:, order].tocsr()
    if springs:
        K = (K + boundary_springs(body, springs)).tocsr()
    load = boundary_load(body, loads) if loads else None
    return BodySystem(body, material, K, lumped[order], load, springs, loads)

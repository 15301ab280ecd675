"""Stiffness, lumped mass and Rayleigh damping of a `Body` (scikit-fem), in SI units.

`assemble(body, material, springs, loads)` returns a `BodySystem`: ``K`` (CSR, N/m per unit
thickness, with the boundary springs), the lumped ``mass`` (kg per unit thickness: row sums
on linear cells; on quadratic ones, where row sums give corners no mass, each cell's mass
shared in proportion to the diagonal of its consistent mass matrix, Hinton-Rock-Zienkiewicz),
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
from skfem import (Basis, BilinearForm, ElementQuad1, ElementQuad2, ElementTriP1, ElementTriP2, ElementVector,
                   MeshQuad, MeshQuad2, MeshTri, MeshTri2, asm)
from skfem.helpers import dot
from skfem.models.elasticity import lame_parameters, linear_elasticity

from ..quantities import COMMON, FEM as Q
from ..errors import ParameterError
from .body import Body, edge_middles
from .boundary import Load, Spring, boundary_load, boundary_springs

__all__ = ["Material", "BodySystem", "assemble", "cell_stress"]

PLANES = Q["plane"].choices
#: Largest Young's modulus [Pa] and density [kg/m^3] accepted (declared in `stickslip.quantities.FEM`).
MAX_MODULUS, MAX_DENSITY = Q["young"].range.hi, Q["density"].range.hi
#: The largest load over Young's modulus (a strain scale): beyond, linear elasticity says nothing.
MAX_STRAIN = 0.1
#: The stiffest spring on a node, over the elastic stiffness of its own dof: a million times
#: stiffer is a clamp (use one); beyond, the eigenvalues lose the body's digits to round-off.
MAX_SPRING_RATIO = 1e6
#: Bounds of the Rayleigh coefficients on their own [1/s], [s] (declared); a problem bounds them
#: further by its mesh (`stickslip.fem.scheme.ContactProblem.check_damping`).
MAX_ALPHA, MAX_BETA = Q["alpha"].range.hi, Q["beta"].range.hi


@dataclass(frozen=True)
class Material:
    """Linear elastic material: Young's modulus ``young`` [Pa], Poisson's ratio ``poisson``,
    ``density`` [kg/m^3], ``plane`` ``"strain"`` (default) or ``"stress"``, and Rayleigh
    damping ``C = alpha M + beta K`` (``alpha`` [1/s], ``beta`` [s]; on a mesh, an explicit run
    bounds them further: `ContactProblem.check_damping`). Ranges: `stickslip.quantities.FEM`.

    ``scaled=True`` says the numbers are in the units of a scaled model (the paper's annulus:
    ``E = 1``, lengths in ``R``, density ``gamma``), not SI: ``young`` and ``density`` are then
    checked as ``young_scaled`` and ``density_scaled`` instead of against the physical ranges
    in Pa and kg/m^3 (and the damping coefficients are in the scaled units of time)."""

    young: float
    poisson: float
    density: float
    plane: str = "strain"
    alpha: float = 0.0
    beta: float = 0.0
    scaled: bool = False

    def __post_init__(self):
        if not isinstance(self.scaled, bool):
            raise ParameterError("scaled", self.scaled, "true or false")
        suffix = "_scaled" if self.scaled else ""
        for name in ("young", "density"):
            object.__setattr__(self, name, Q.check(name + suffix, getattr(self, name), name))
        for name in ("poisson", "plane") + (() if self.scaled else ("alpha", "beta")):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        for name in ("alpha", "beta") if self.scaled else ():
            object.__setattr__(self, name, COMMON.check("scaled_damping", getattr(self, name), name))

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
        basis, where = _basis(self.body)
        return basis, _dof_order(basis, where)

    def dofs(self, nodes) -> np.ndarray:
        """The x and y dofs of ``nodes``, interleaved."""
        nodes = np.asarray(nodes, dtype=np.int64)
        return np.stack([2 * nodes, 2 * nodes + 1], axis=1).ravel()


_ELEMENTS = {"triangle": (MeshTri, ElementTriP1), "quad": (MeshQuad, ElementQuad1),
             "triangle6": (MeshTri2, ElementTriP2), "quad9": (MeshQuad2, ElementQuad2)}


def _skfem_mesh(body: Body):
    """``(mesh, where)``: the scikit-fem mesh of ``body`` (isoparametric on quadratic cells) and,
    for each node, ``(kind, index)``: 0 for a vertex, 1 for an edge's middle, 2 for a centre,
    with its index among scikit-fem's vertices, facets or elements."""
    mesh_type = _ELEMENTS[body.kind][0]
    if body.order == 1:
        mesh = mesh_type(np.ascontiguousarray(body.points.T), np.ascontiguousarray(body.cells.T))
        return mesh, (np.zeros(len(body.points), dtype=np.int64), np.arange(len(body.points)))
    vertices, t = np.unique(body.corners, return_inverse=True)
    t = t.reshape(body.corners.shape)
    facets = (MeshTri if body.kind == "triangle6" else MeshQuad)(body.points[vertices].T, t.T).facets
    middles = edge_middles(body.cells, body.kind)
    mids = np.array([middles[(a, b) if a < b else (b, a)] for a, b in vertices[facets].T.tolist()], dtype=np.int64)
    centres = body.cells[:, 8] if body.kind == "quad9" else np.zeros(0, dtype=np.int64)
    doflocs = body.points[np.concatenate([vertices, mids, centres])].T
    mesh = mesh_type(np.ascontiguousarray(doflocs), np.ascontiguousarray(t.T))
    kind, index = np.full(len(body.points), -1), np.zeros(len(body.points), dtype=np.int64)
    for k, nodes in enumerate((vertices, mids, centres)):
        kind[nodes], index[nodes] = k, np.arange(len(nodes))
    if np.any(kind < 0):
        raise ParameterError("mesh", body.source, "cells whose every node is a corner, an edge's middle or a centre")
    return mesh, (kind, index)


def _basis(body: Body):
    """``(basis, where)``: the scikit-fem vector basis and `_skfem_mesh`'s node map. A quadratic
    cell whose mapping turns over somewhere inside (a misplaced middle node) is refused."""
    mesh, where = _skfem_mesh(body)
    zero = ParameterError("mesh", body.source, "quadratic cells that do not turn over inside (one has a zero "
                          "Jacobian: a middle node too far from its edge)")
    try:
        basis = Basis(mesh, ElementVector(_ELEMENTS[body.kind][1]()))
        if body.order == 1:
            return basis, where
        # the sign of the mapping's Jacobian at the quadrature points and the nodes of each cell
        det = basis.mapping.detDF(np.hstack([basis.X, basis.elem.doflocs[0::2].T]))
    except Exception as err:  # noqa: BLE001 - scikit-fem raises a bare Exception on a zero Jacobian
        if body.order == 1 or "Jacobian" not in str(err):
            raise
        raise zero from None
    bad = np.flatnonzero(np.any(det <= 0, axis=1))
    if bad.size:
        raise ParameterError("mesh", body.source, f"quadratic cells that do not turn over inside ({bad.size} do, "
                             f"the first is cell {int(bad[0])}: a middle node too far from its edge)")
    return basis, where


def _dof_order(basis, where) -> np.ndarray:
    """For each dof ``2 i + c``, its index in scikit-fem's numbering of ``basis``."""
    kind, index = where
    dofs = [basis.nodal_dofs, basis.facet_dofs, basis.interior_dofs]
    order = np.empty(2 * len(kind), dtype=np.int64)
    for k in range(3):
        sel = np.flatnonzero(kind == k)
        if sel.size:
            order[2 * sel], order[2 * sel + 1] = dofs[k][0, index[sel]], dofs[k][1, index[sel]]
    return order


def _lumped_mass(basis, order: np.ndarray, density: float, quadratic: bool) -> np.ndarray:
    """The lumped mass on the dofs ``2 i + c``: row sums, or on quadratic cells each cell's mass
    shared by the diagonal of its consistent mass matrix."""
    if not quadratic:
        return density * np.asarray(asm(_mass, basis).sum(axis=1)).ravel()[order]
    phi = np.array([np.asarray(b[0])[0] for b in basis.basis[0::2]])  # x-components: (local nodes, cells, points)
    diag = np.sum(phi**2 * basis.dx, axis=-1)
    share = diag / diag.sum(axis=0) * basis.dx.sum(axis=1)
    out = np.zeros(basis.N)
    np.add.at(out, basis.element_dofs[0::2], density * share)
    np.add.at(out, basis.element_dofs[1::2], density * share)
    return out[order]


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
    for i, x in enumerate(loads):
        size = max(abs(x.pressure), *map(abs, x.traction))
        if size > MAX_STRAIN * material.young:
            raise ParameterError("load.pressure" if abs(x.pressure) == size else "load.traction",
                                 x.pressure if abs(x.pressure) == size else list(x.traction),
                                 f"at most {MAX_STRAIN:g} x young = {MAX_STRAIN * material.young:.4g} Pa in size (load "
                                 f"{i} on {x.group!r}: linear elasticity holds for small strains)", also=("young",))
    basis, where = _basis(body)
    K = asm(linear_elasticity(*material.lame), basis)
    # scikit-fem numbers the dofs its own way: reorder to 2 i + c, the contact machinery's
    order = _dof_order(basis, where)
    lumped = _lumped_mass(basis, order, material.density, body.order == 2)
    K = K[order][:, order].tocsr()
    if springs:
        _check_springs(body, springs, K.diagonal())
        K = (K + boundary_springs(body, springs)).tocsr()
    load = boundary_load(body, loads) if loads else None
    return BodySystem(body, material, K, lumped, load, springs, loads)


def _check_springs(body: Body, springs, elastic: np.ndarray) -> None:
    """Refuse a spring stiffer on some dof than ``MAX_SPRING_RATIO`` times its elastic stiffness."""
    for i, spring in enumerate(springs):
        diag = boundary_springs(body, [spring]).diagonal()
        on = diag > 0
        ratio = np.max(diag[on] / elastic[on])
        if ratio > MAX_SPRING_RATIO:
            most = float(np.min(elastic[on] / diag[on])) * MAX_SPRING_RATIO * max(spring.stiffness)
            raise ParameterError(f"spring[{i}].stiffness", list(spring.stiffness),
                                 f"at most {most:.4g} N/m per metre on this mesh and material: on no node more than "
                                 f"{MAX_SPRING_RATIO:g} times the body's own stiffness there (a stiffer spring is a "
                                 "clamp: clamp the group instead)", also=("young",))

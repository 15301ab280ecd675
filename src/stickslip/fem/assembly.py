"""Stiffness, lumped mass and Rayleigh damping of a `Body` (scikit-fem), in SI units.

`assemble(body, material, springs, loads)` returns a `BodySystem`. ``material`` is one
`Material` for the whole body or ``{cell group: Material}``, one for each cell group of the mesh
(a pad's lining and steel backplate): every cell then has its group's Lamé parameters,
density and Rayleigh damping. The system has ``K`` (CSR, N/m per unit
thickness, with the boundary springs), the lumped ``mass`` (kg per unit thickness: row sums
on linear cells; on quadratic ones, where row sums give corners no mass, each cell's mass
shared in proportion to the diagonal of its consistent mass matrix, Hinton-Rock-Zienkiewicz),
the constant ``load`` (N per unit thickness, from `stickslip.fem.boundary`) and the Rayleigh
damping ``C = sum over materials of (alpha M + beta K)`` of each material's cells (a boundary
spring damped with the beta of the cells along its group), on the
Cartesian dofs ``2 i`` (x) and ``2 i + 1`` (y) of node ``i``. Plane strain uses the Lamé
parameters ``lambda = E nu / ((1 + nu)(1 - 2 nu))``, ``mu = E / (2 (1 + nu))``; plane stress
replaces ``lambda`` by ``2 lambda mu / (lambda + 2 mu)``. A cell group may instead be of an
`stickslip.fem.orthotropic.Orthotropic` material (a lining): its cells take the constitutive
matrix ``D`` in x-y axes, ``int eps(v)^T D eps(u)``, in Voigt form.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
from skfem import (Basis, BilinearForm, ElementQuad1, ElementQuad2, ElementTriP1, ElementTriP2, ElementVector,
                   MeshQuad, MeshQuad2, MeshTri, MeshTri2, asm)
from skfem.helpers import ddot, div, dot, sym_grad
from skfem.models.elasticity import lame_parameters

from ..quantities import COMMON, FEM as Q
from ..errors import ParameterError
from .body import Body, edge_middles
from .boundary import Load, Spring, boundary_load, boundary_springs
from .orthotropic import Orthotropic

__all__ = ["Material", "BodySystem", "assemble", "cell_stress", "von_mises", "transport_operators", "materials_of"]

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
    bounds them further: `ContactProblem.check_damping`), and a structural ``loss_factor`` ``eta``
    (the CEA's stiffness of its cells times ``1 + i eta``: every mode damped about ``eta / 2``
    whatever its frequency; refused in explicit runs). Ranges: `stickslip.quantities.FEM`.

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
    loss_factor: float = 0.0

    def __post_init__(self):
        if not isinstance(self.scaled, bool):
            raise ParameterError("scaled", self.scaled, "true or false")
        suffix = "_scaled" if self.scaled else ""
        for name in ("young", "density"):
            object.__setattr__(self, name, Q.check(name + suffix, getattr(self, name), name))
        for name in ("poisson", "plane", "loss_factor") + (() if self.scaled else ("alpha", "beta")):
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

    def describe(self, plane: bool = True) -> str:
        """One line: every constant (for a file's attributes; ``plane=False``: of a solid, without its plane)."""
        return (f"isotropic: young = {self.young:g} Pa, poisson = {self.poisson:g}" + (f", plane {self.plane}" if plane else "")
                + (f", loss factor {self.loss_factor:g}" if self.loss_factor else "")
                + (" (scaled units)" if self.scaled else ""))


@BilinearForm
def _mass(u, v, w):
    return dot(u, v)


@dataclass(frozen=True, eq=False)
class BodySystem:
    """The assembled body: ``K``, the lumped ``mass`` and the constant ``load`` on all ``2 n``
    Cartesian dofs; ``springs`` and ``loads`` are what `assemble` added; ``material`` as given
    to it (one `Material` or ``{cell group: Material}``); ``C`` the Rayleigh damping of the
    materials' cells (None: undamped); ``S`` the structural damping ``sum eta K`` of the materials with a
    loss factor (None: none; the CEA's stiffness is ``K + i S``)."""

    body: Body
    material: Material | dict
    K: sp.csr_matrix
    mass: np.ndarray
    load: np.ndarray | None = None
    springs: tuple = ()
    loads: tuple = ()
    C: sp.csr_matrix | None = None
    S: sp.csr_matrix | None = None

    def __post_init__(self):
        if self.load is None:
            object.__setattr__(self, "load", np.zeros(self.K.shape[0]))

    @property
    def n_dofs(self) -> int:
        return self.K.shape[0]

    @property
    def materials(self) -> dict:
        """``{cell group: Material}``; ``{"": material}`` for one material on the whole body."""
        return materials_of(self.material)

    @property
    def cell_material(self) -> np.ndarray:
        """For every cell, the position of its material in `materials`."""
        return _cell_material(self.body, self.materials)

    def cell_values(self, name: str) -> np.ndarray:
        """A material constant (``young``, ``poisson``, ``density``, ``alpha``, ``beta``) of every cell."""
        return np.array([getattr(m, name) for m in self.materials.values()])[self.cell_material]

    def damping(self) -> sp.csr_matrix:
        """Rayleigh damping: ``alpha M + beta K`` of each material's cells (zero if undamped)."""
        return sp.csr_matrix(self.K.shape) if self.C is None else self.C

    def p_wave_speed(self, cells=None) -> float:
        """The fastest ``sqrt((lambda + 2 mu) / rho)`` [m/s] of the materials of ``cells`` (default all)."""
        which = np.unique(self.cell_material if cells is None else self.cell_material[np.asarray(cells)])
        speeds = [m.p_wave_speed for m in self.materials.values()]
        return max(speeds[int(i)] for i in which)

    @cached_property
    def consistent_mass(self) -> sp.csr_matrix:
        """The consistent mass matrix ``int rho N_i . N_j`` [kg/m] on the ``2 n`` Cartesian dofs
        (each cell's own density); `mass` is its lumped form."""
        basis, order = self.basis
        M = asm(_weighted_mass, basis, rho=_on_points(basis, self.cell_values("density")))
        return M[order][:, order].tocsr()

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


@BilinearForm
def _weighted_mass(u, v, w):
    return w.rho * dot(u, v)


@BilinearForm
def _anisotropic(u, v, w):
    """Linear elasticity with a constitutive matrix ``D`` per cell (fields ``d00 .. d22``), Voigt form."""
    eu, ev = sym_grad(u), sym_grad(v)
    a, b = (eu[0, 0], eu[1, 1], 2.0 * eu[0, 1]), (ev[0, 0], ev[1, 1], 2.0 * ev[0, 1])
    return sum(getattr(w, f"d{i}{j}") * a[j] * b[i] for i in range(3) for j in range(3))


def _constitutive(materials: list, owner: np.ndarray) -> np.ndarray:
    """``D`` [Pa] (3 x 3, x-y axes, Voigt) of every cell: zero on the cells of isotropic materials."""
    per = np.array([m.stiffness if isinstance(m, Orthotropic) else np.zeros((3, 3)) for m in materials])
    return per[owner]


def _anisotropic_stiffness(basis, order: np.ndarray, D: np.ndarray) -> sp.csr_matrix:
    """``K`` of cells of constitutive matrices ``D`` (one per cell), on the dofs ``2 i + c``."""
    fields = {f"d{i}{j}": _on_points(basis, D[:, i, j]) for i in range(3) for j in range(3)}
    return asm(_anisotropic, basis, **fields)[order][:, order].tocsr()


@BilinearForm
def _elasticity(u, v, w):
    """Isotropic linear elasticity with Lamé parameters that vary from cell to cell."""
    return 2.0 * w.mu * ddot(sym_grad(u), sym_grad(v)) + w.lam * div(u) * div(v)


def _on_points(basis, per_cell: np.ndarray) -> np.ndarray:
    """A value per cell at every quadrature point of its cell (scikit-fem's field shape)."""
    return np.repeat(np.asarray(per_cell, dtype=float)[:, None], basis.X.shape[1], axis=1)


def _lumped_mass(basis, order: np.ndarray, density: np.ndarray, quadratic: bool) -> np.ndarray:
    """The lumped mass on the dofs ``2 i + c`` of cells of ``density`` (one per cell): row sums,
    or on quadratic cells each cell's mass shared by the diagonal of its consistent mass matrix."""
    if not quadratic:
        return np.asarray(asm(_weighted_mass, basis, rho=_on_points(basis, density)).sum(axis=1)).ravel()[order]
    phi = np.array([np.asarray(b[0])[0] for b in basis.basis[0::2]])  # x-components: (local nodes, cells, points)
    diag = np.sum(phi**2 * basis.dx, axis=-1)
    share = diag / diag.sum(axis=0) * basis.dx.sum(axis=1)
    out = np.zeros(basis.N)
    np.add.at(out, basis.element_dofs[0::2], density * share)
    np.add.at(out, basis.element_dofs[1::2], density * share)
    return out[order]


def _stiffness(basis, order: np.ndarray, lam: np.ndarray, mu: np.ndarray) -> sp.csr_matrix:
    """``K`` of cells with Lamé parameters ``lam``, ``mu`` (one per cell), on the dofs ``2 i + c``."""
    K = asm(_elasticity, basis, lam=_on_points(basis, lam), mu=_on_points(basis, mu))
    return K[order][:, order].tocsr()


def materials_of(material) -> dict:
    """``{cell group: Material}`` of what `assemble` takes: one `Material` or `Orthotropic`
    (``{"": material}``) or a mapping from cell group names to materials."""
    if isinstance(material, (Material, Orthotropic)):
        return {"": material}
    if isinstance(material, dict) and material and all(isinstance(k, str) and k and
                                                       isinstance(m, (Material, Orthotropic))
                                                       for k, m in material.items()):
        return dict(material)
    raise ParameterError("material", material, "a Material or an Orthotropic, or {cell group name: material} for "
                         "every cell group")


def _cell_material(body: Body, materials: dict) -> np.ndarray:
    """For every cell, the position of its material in ``materials``; a cell group without a
    material, a material for no cell group, a cell in none or in two of them is refused."""
    if list(materials) == [""]:
        return np.zeros(len(body.cells), dtype=np.int64)
    have = ", ".join(sorted(body.cell_groups)) or "none"
    unknown = [k for k in materials if k not in body.cell_groups]
    if unknown:
        raise ParameterError("material.group", unknown[0], f"a cell group of {body.source} (it has: {have})")
    missing = [k for k in body.cell_groups if k not in materials]
    if missing:
        raise ParameterError("material", f"none for cell group {missing[0]!r}",
                             f"a material for every cell group of {body.source} ({have}), or one for the whole body")
    owner = np.full(len(body.cells), -1, dtype=np.int64)
    for i, name in enumerate(materials):
        cells = body.cell_groups[name]
        twice = cells[owner[cells] >= 0]
        if twice.size:
            other = list(materials)[int(owner[twice[0]])]
            raise ParameterError("material.group", name, f"cell groups that do not overlap ({twice.size} of its "
                                 f"cells are also in {other!r}, the first is cell {int(twice[0])})")
        owner[cells] = i
    if np.any(owner < 0):
        raise ParameterError("material", f"none for {int(np.sum(owner < 0))} cells",
                             f"a material for every cell: cell {int(np.argmax(owner < 0))} of {body.source} is in "
                             f"no cell group with one ({have})")
    return owner


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
    mats = list(system.materials.values())
    D = np.array([m.stiffness if isinstance(m, Orthotropic) else _isotropic_matrix(*m.lame) for m in mats])
    D = D[system.cell_material]
    weights = basis.dx / basis.dx.sum(axis=1, keepdims=True)
    out = []
    for one in np.atleast_2d(u):
        x = np.empty(system.n_dofs)
        x[order] = one
        g = np.sum(basis.interpolate(x).grad * weights, axis=-1)  # g[i, j] = d u_i / d x_j, cell means
        strain = np.stack([g[0, 0], g[1, 1], g[0, 1] + g[1, 0]], axis=-1)
        out.append(np.einsum("cij,cj->ci", D, strain))
    return np.array(out) if u.ndim == 2 else out[0]


def _isotropic_matrix(lam: float, mu: float) -> np.ndarray:
    """``D`` of an isotropic material of Lamé parameters ``lam``, ``mu`` (Voigt, engineering shear)."""
    return np.array([[lam + 2 * mu, lam, 0.0], [lam, lam + 2 * mu, 0.0], [0.0, 0.0, mu]])


def transport_operators(system: BodySystem, omega: float, center=(0.0, 0.0)) -> tuple[sp.csr_matrix, sp.csr_matrix]:
    """``(G, B)`` of a body turning at ``omega`` [rad/s] about ``center``, described in space-fixed
    (Eulerian) coordinates: with the body's velocity field ``v = omega e_z x (x - c)`` and
    ``A_ij = int rho N_i . (v . grad) N_j``, the gyroscopic matrix ``G = A - A^T`` (skew) [kg/(m s)]
    and the transport softening ``B = int rho ((v . grad) N_i) . ((v . grad) N_j)`` [kg/(m s^2)]:
    small vibrations ``u`` about the turning body obey ``M u'' + G u' + (K - B) u = f`` (the
    kinetic energy of ``v + u' + (v . grad) u``; the centrifugal load and the stress stiffening
    it causes are left out: a strain of ``rho omega^2 R^2 / E``)."""
    omega = Q.check("omega", omega)
    cx, cy = Q["center"].check_pair(center, "center")
    basis, order = system.basis
    rho = _on_points(basis, system.cell_values("density"))

    def along(u, w):  # (v . grad) u at the quadrature points
        vx, vy = -omega * (w.x[1] - cy), omega * (w.x[0] - cx)
        return u.grad[:, 0] * vx + u.grad[:, 1] * vy

    A = asm(BilinearForm(lambda u, v, w: w.rho * dot(along(u, w), v)), basis, rho=rho)[order][:, order].tocsr()
    B = asm(BilinearForm(lambda u, v, w: w.rho * dot(along(u, w), along(v, w))), basis, rho=rho)[order][:, order]
    return (A - A.T).tocsr(), B.tocsr()


def von_mises(system: BodySystem, sigma) -> np.ndarray:
    """The von Mises stress [Pa] of the cell stresses ``sigma`` (`cell_stress`: ``(..., n_cells, 3)``)
    with the out-of-plane stress of the material's plane: ``sigma_zz = nu (sigma_xx + sigma_yy)``
    in plane strain (each cell's own ``nu``; an orthotropic cell's `Orthotropic.sigma_zz`), 0 in
    plane stress."""
    sigma = np.asarray(sigma, dtype=float)
    sxx, syy, sxy = sigma[..., 0], sigma[..., 1], sigma[..., 2]
    strain = next(iter(system.materials.values())).plane == "strain"
    szz = system.cell_values("poisson") * (sxx + syy) if strain else np.zeros_like(sxx)
    owner = system.cell_material
    for i, m in enumerate(system.materials.values()):
        if isinstance(m, Orthotropic):
            cells = owner == i
            szz[..., cells] = m.sigma_zz(sigma[..., cells, :])
    return np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3.0 * sxy**2)


def assemble(body: Body, material, springs=(), loads=()) -> BodySystem:
    """Assemble the stiffness, the lumped mass and the Rayleigh damping of ``body`` with its
    boundary ``springs`` (`Spring`) and ``loads`` (`Load`) (see the module docstring).
    ``material``: one `Material`, or ``{cell group: Material}`` for every cell group of the mesh."""
    if not isinstance(body, Body):
        raise ParameterError("body", body, "a Body (see read_body)")
    materials = materials_of(material)
    if len({m.scaled for m in materials.values()}) > 1 or len({m.plane for m in materials.values()}) > 1:
        raise ParameterError("material.plane", [m.plane for m in materials.values()],
                             "one plane (strain or stress) and one system of units (SI or scaled) for every material")
    owner = _cell_material(body, materials)
    springs, loads = tuple(springs), tuple(loads)
    for name, items, kind in (("springs", springs, Spring), ("loads", loads, Load)):
        if not all(isinstance(x, kind) for x in items):
            raise ParameterError(name, items, f"a sequence of {kind.__name__}")
    for where, items, field in (("spring", springs, "stiffness"), ("load", loads, "traction")):
        for i, x in enumerate(items):
            if len(getattr(x, field)) != 2:
                raise ParameterError(f"{where}[{i}].{field}", list(getattr(x, field)), "two numbers [x, y] on a "
                                     "plane body (three are a solid's)")
    stiffest = max(m.young for m in materials.values())
    for i, x in enumerate(loads):
        size = max(abs(x.pressure), *map(abs, x.traction))
        if size > MAX_STRAIN * stiffest:
            raise ParameterError("load.pressure" if abs(x.pressure) == size else "load.traction",
                                 x.pressure if abs(x.pressure) == size else list(x.traction),
                                 f"at most {MAX_STRAIN:g} x young = {MAX_STRAIN * stiffest:.4g} Pa in size (load "
                                 f"{i} on {x.group!r}: linear elasticity holds for small strains)", also=("young",))
    basis, where = _basis(body)
    # scikit-fem numbers the dofs its own way: reorder to 2 i + c, the contact machinery's
    order = _dof_order(basis, where)
    mats = list(materials.values())
    lame = np.array([(0.0, 0.0) if isinstance(m, Orthotropic) else m.lame for m in mats])[owner]
    value = lambda name: np.array([getattr(m, name) for m in mats], dtype=float)[owner]  # noqa: E731
    K = _stiffness(basis, order, lame[:, 0], lame[:, 1])
    orthotropic = any(isinstance(m, Orthotropic) for m in mats)
    if orthotropic:
        D = _constitutive(mats, owner)
        K = (K + _anisotropic_stiffness(basis, order, D)).tocsr()
    quadratic = body.order == 2
    lumped = _lumped_mass(basis, order, value("density"), quadratic)
    C = None
    if any(m.alpha > 0 or m.beta > 0 for m in mats):
        beta, alpha_rho = value("beta"), value("alpha") * value("density")
        C = sp.diags(_lumped_mass(basis, order, alpha_rho, quadratic))
        if np.any(beta > 0):
            C = C + _stiffness(basis, order, beta * lame[:, 0], beta * lame[:, 1])
            if orthotropic:
                C = C + _anisotropic_stiffness(basis, order, beta[:, None, None] * D)
        C = sp.csr_matrix(C)
    S = None
    if any(m.loss_factor > 0 for m in mats):  # each material's stiffness times its loss factor (springs: none)
        eta = value("loss_factor")
        S = _stiffness(basis, order, eta * lame[:, 0], eta * lame[:, 1])
        if orthotropic:
            S = S + _anisotropic_stiffness(basis, order, eta[:, None, None] * D)
        S = sp.csr_matrix(S)
    if springs:
        _check_springs(body, springs, K.diagonal())
        K = (K + boundary_springs(body, springs)).tocsr()
        if C is not None:  # a spring is damped with the (largest) beta of the cells along its group
            betas = value("beta")
            for spring in springs:
                b = float(betas[body.cells_along(spring.group)].max())
                C = (C + b * boundary_springs(body, [spring])).tocsr() if b > 0 else C
    load = boundary_load(body, loads) if loads else None
    return BodySystem(body, material, K, lumped, load, springs, loads, C, S)


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

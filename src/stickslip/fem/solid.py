"""A 3-D elastic body (a solid: a pad, a backplate, a disc) read from a mesh, its stiffness and lumped
mass (scikit-fem), its supports and its modes.

`read_solid(path, units)` reads any mesh meshio reads (gmsh ``.msh`` first) whose cells are volumes:
linear or quadratic tetrahedra and hexahedra (meshio's ``tetra``, ``tetra10``, ``hexahedron``, and the
quadratic hexahedra ``hexahedron20`` (serendipity) and ``hexahedron27`` (triquadratic); wedges and pyramids
are refused, said so). ``units`` is the length unit
of the mesh's coordinates, ``"m"`` or ``"mm"`` (a CAD model in millimetres read as metres is a brake
1000 times too large: no default).
Face groups are the named sets of boundary faces (gmsh physical groups of dimension 2: triangles on
tetrahedra, quadrilaterals on hexahedra, of 6, 8 or 9 nodes on quadratic cells) where supports and contacts act; cell groups the named sets
of cells (physical groups of dimension 3: a lining, a backplate), each of which may have its own
material. Checked on the way in, each refused with a `ParameterError` naming the mesh and the problem:
a flat mesh, no volume cells or cells of two kinds, degenerate cells (volume below 1e-10 of the mean),
parts that share no node, face groups whose faces are not on the boundary. Tetrahedra numbered the other
way are turned round (a numbering matter); an inverted hexahedron is refused (it is a mesh error, not an
orientation), and so is a tangled mesh (an inside face whose two cells lie on the same side of it: an
inverted cell that turning round would hide).

`assemble_solid(solid, material)`: ``K`` (CSR, N/m) and the lumped mass (kg per degree of freedom: row
sums of the consistent mass on linear cells; on quadratic tetrahedra each cell's mass shared by the
diagonal of its consistent mass, Hinton-Rock-Zienkiewicz, and so on quadratic hexahedra: on 27 nodes
Simpson's rule, converging at order 4; on 20 nodes at order 2 only, for modes take their consistent mass) on the Cartesian degrees of freedom ``3 i``,
``3 i + 1``, ``3 i + 2`` of node ``i``, with ``material`` one `stickslip.fem.assembly.Material` or one
per cell group. The physics is the 2-D bodies' without the plane: Lamé's ``lambda = E nu / ((1 + nu)
(1 - 2 nu))`` and ``mu = E / (2 (1 + nu))`` (a material's ``plane = "stress"`` means nothing in 3-D
and is refused). `supported_dofs` gives the degrees of freedom a clamp (all three) or a roller (the
one along a coordinate axis) holds on a face group, `solid_supports` the supports with rollers along
any direction too (`stickslip.fem.supports`); `solid_modes` the lowest natural frequencies.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import scipy.sparse as sp

from ..errors import ParameterError
from ..quantities import FEM as Q, MAX_MESH_NODES
from ..validation import count as checked_count, regular_input
from .assembly import Material
from .body import named_sets

__all__ = ["Solid", "SolidSystem", "OrthotropicSolid", "read_solid", "solid_from_meshio", "assemble_solid",
           "supported_dofs", "solid_modes", "solid_static", "solid_damped_modes", "skfem_mesh", "split_held", "VOLUME_KINDS",
           "cell_quadrature", "solid_supports",
           "UNITS"]

#: meshio volume cells read, and the faces of their boundary groups.
VOLUME_KINDS = {"tetra": "triangle", "hexahedron": "quad", "tetra10": "triangle6", "hexahedron20": "quad8",
                "hexahedron27": "quad9"}
#: Not yet (said when met): other volume cells.
LATER = ("wedge", "wedge15", "pyramid", "pyramid13")
#: A quadratic hexahedron's middle-face nodes 20-25 (meshio's numbering, as VTK's): the corners of each face.
HEX_FACE_CORNERS = ((0, 3, 7, 4), (1, 2, 6, 5), (0, 1, 5, 4), (3, 2, 6, 7), (0, 1, 2, 3), (4, 5, 6, 7))
#: Its edge-middle nodes 8-19: the corners of each edge.
HEX_EDGES = ((0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7))
#: Length units of a mesh's coordinates, in metres.
UNITS = {"m": 1.0, "mm": 1e-3}
#: The local faces of each cell kind (meshio's node numbering), each seen from outside the cell.
_FACES = {"tetra": [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
          "hexahedron": [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]}
AXES = {"x": 0, "y": 1, "z": 2}


@dataclass(frozen=True, eq=False)
class Solid:
    """Nodes ``points`` (``(n, 3)`` in metres), cells ``(m, 4 | 10 | 8 | 20 | 27)`` (meshio's numbering,
    tetrahedra of positive volume), ``kind`` (a key of `VOLUME_KINDS`), ``faces``: face group -> its faces
    (``(f, 3 | 6 | 4 | 8 | 9)`` node indices), ``cell_groups``: cell group -> the sorted indices of its cells."""

    points: np.ndarray
    cells: np.ndarray
    kind: str
    faces: dict = field(default_factory=dict)
    cell_groups: dict = field(default_factory=dict)
    source: str = "mesh"

    @property
    def volumes(self) -> np.ndarray:
        """Each cell's volume [m^3] (a hexahedron's as its five tetrahedra's, exact for flat faces)."""
        return np.abs(_volumes(self.points, self.cells, self.kind))

    @property
    def groups(self) -> dict:
        """The face groups (as a 2-D `stickslip.fem.body.Body`'s boundary groups)."""
        return self.faces

    def nodes(self, group: str, option: str = "group") -> np.ndarray:
        """The sorted nodes of a face group; ``option`` names it in an error."""
        if group not in self.faces:
            raise ParameterError(option, group, f"a face group of {self.source} ({', '.join(self.faces) or 'none'})")
        return np.unique(self.faces[group])

    def describe(self) -> str:
        return (f"{self.source}: {len(self.points)} nodes, {len(self.cells)} {self.kind} cells, face groups "
                f"{', '.join(self.faces) or 'none'}, cell groups {', '.join(self.cell_groups) or 'none'}")


def _tet_volumes(p: np.ndarray, t: np.ndarray) -> np.ndarray:
    a, b, c, d = (p[t[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6.0


#: A hexahedron as five tetrahedra (meshio's numbering), each positive on a positive hexahedron.
_HEX_TETS = [[0, 1, 3, 4], [1, 2, 3, 6], [1, 4, 5, 6], [3, 6, 7, 4], [1, 3, 4, 6]]


def _volumes(p: np.ndarray, cells: np.ndarray, kind: str) -> np.ndarray:
    """Signed volumes (positive: the numbering turns as meshio's)."""
    if kind.startswith("tetra"):  # a quadratic tetrahedron's volume as its corners' (exact for straight edges)
        return _tet_volumes(p, cells[:, :4])
    return sum(_tet_volumes(p, cells[:, tet]) for tet in _HEX_TETS)


def solid_from_meshio(mesh, source: str = "mesh", units: str | None = None) -> Solid:
    """A `Solid` from a `meshio.Mesh` whose coordinates are in ``units`` (``"m"`` or ``"mm"``)."""
    if not isinstance(units, str) or units not in UNITS:
        raise ParameterError("units", units, f"the length unit of the mesh's coordinates: {' or '.join(UNITS)} "
                             "(a CAD model is often in mm; no default)")
    try:
        points, blocks = np.asarray(mesh.points, dtype=float), list(mesh.cells)
    except (AttributeError, TypeError, ValueError):
        raise ParameterError("mesh", source, "a meshio.Mesh") from None
    def refuse(why):
        raise ParameterError("mesh", source, why)
    if points.ndim != 2 or points.shape[1] != 3 or not len(points):
        refuse("a mesh of points in three dimensions")
    if not np.all(np.isfinite(points)):
        refuse("a mesh whose coordinates are finite")
    if len(points) > MAX_MESH_NODES:
        refuse(f"a mesh of at most {MAX_MESH_NODES} nodes (it has {len(points)})")
    later = sorted({b.type for b in blocks if b.type in LATER})
    if later:
        refuse(f"tetrahedra or hexahedra, linear or quadratic (it has {', '.join(later)}: these volume cells come "
               "in a later release)")
    kinds = sorted({b.type for b in blocks if b.type in VOLUME_KINDS})
    if not kinds:
        refuse(f"a mesh with volume cells ({', '.join(VOLUME_KINDS)}; it has "
               f"{', '.join(sorted({b.type for b in blocks})) or 'none'}: a 2-D mesh is read by "
               "stickslip.fem.read_body)")
    if len(kinds) > 1:
        refuse(f"one kind of volume cell (it has {' and '.join(kinds)})")
    kind = kinds[0]
    extent = points.max(axis=0) - points.min(axis=0)
    if extent.min() <= 1e-9 * extent.max():
        refuse("a solid (its points lie in a plane: a 2-D mesh is read by stickslip.fem.read_body)")
    volume_blocks = [k for k, b in enumerate(blocks) if b.type == kind]
    cells = np.concatenate([np.asarray(blocks[k].data, dtype=np.int64) for k in volume_blocks])
    if cells.min() < 0 or cells.max() >= len(points):
        refuse("cells whose nodes are points of the mesh")
    vol = _volumes(points, cells, kind)
    mean = float(np.abs(vol).mean())
    if not mean > 0 or np.any(np.abs(vol) < 1e-10 * mean):
        refuse(f"cells of positive volume ({int(np.sum(np.abs(vol) < 1e-10 * max(mean, 1e-300)))} are degenerate)")
    if kind.startswith("tetra"):  # turned round: corners 1 and 2 swapped, and the middles of their edges
        cells[vol < 0] = cells[vol < 0][:, [0, 2, 1, 3, 6, 5, 4, 7, 9, 8][:cells.shape[1]]]
    elif np.any(vol < 0):
        refuse(f"hexahedra numbered as meshio numbers them ({int(np.sum(vol < 0))} are inverted)")
    folded = _folded(cells, kind)
    if folded:
        refuse(f"a mesh without inverted cells ({folded} faces inside it have their two cells on the same side: "
               "a node moved through a face, a tangled mesh)")
    # the cells' groups and the faces' groups (gmsh physical groups through meshio's cell_sets, or MSH 2.2's tags)
    offsets = np.cumsum([0] + [len(blocks[k].data) for k in volume_blocks])
    cell_groups, faces = {}, {}
    face_kind = VOLUME_KINDS[kind]
    boundary = _boundary_faces(cells, kind)
    for name, per_block in named_sets(mesh).items():
        if name.startswith("gmsh:"):
            continue
        own = [np.asarray(per_block[k], dtype=np.int64) + offsets[i] for i, k in enumerate(volume_blocks)
               if k < len(per_block) and per_block[k] is not None and len(per_block[k])]
        if own:
            cell_groups[name] = np.unique(np.concatenate(own))
        found = [np.asarray(blocks[k].data, dtype=np.int64)[np.asarray(per_block[k], dtype=np.int64)]
                 for k, b in enumerate(blocks) if b.type == face_kind and k < len(per_block)
                 and per_block[k] is not None and len(per_block[k])]
        if found:
            group = np.concatenate(found)
            inside = [f for f in group if tuple(sorted(f[:4 if face_kind.startswith("quad") else 3])) not in boundary]
            if inside:
                refuse(f"face group {name!r} on the boundary ({len(inside)} of its {len(group)} faces are inside the "
                       "solid or not faces of its cells)")
            faces[name] = group
    _connected(cells, len(points), source)
    used = np.unique(cells)
    if len(used) < len(points):  # points no cell uses (gmsh's geometry points): dropped, the numbering kept dense
        new = -np.ones(len(points), dtype=np.int64)
        new[used] = np.arange(len(used))
        points, cells = points[used], new[cells]
        faces = {name: new[f] for name, f in faces.items()}
    return Solid(points * UNITS[units], cells, kind, faces, cell_groups, source)


def _folded(cells: np.ndarray, kind: str) -> int:
    """How many faces shared by two cells are seen the same way round from both (each cell's faces
    turned outward, `_FACES`): two cells on the same side of their face, a fold."""
    local = np.array(_FACES["tetra" if kind.startswith("tetra") else "hexahedron"])
    f = cells[:, local].reshape(-1, local.shape[1])
    first = np.argmin(f, axis=1)  # each face's cycle started at its least node: its turn is then whether
    rolled = np.take_along_axis(f, (first[:, None] + np.arange(f.shape[1])) % f.shape[1], axis=1)
    forward = rolled[:, 1] < rolled[:, -1]  # it runs up or down from there
    _, inverse, counts = np.unique(np.sort(f, axis=1), axis=0, return_inverse=True, return_counts=True)
    ups = np.bincount(inverse.ravel(), weights=forward, minlength=len(counts))
    return int(np.sum((counts == 2) & (ups != 1)))


def _boundary_faces(cells: np.ndarray, kind: str) -> set:
    """The faces (sorted node tuples) that belong to one cell only."""
    counts: dict = {}
    for local in _FACES["tetra" if kind.startswith("tetra") else "hexahedron"]:  # by their corners
        for face in map(tuple, np.sort(cells[:, local], axis=1)):
            counts[face] = counts.get(face, 0) + 1
    return {f for f, k in counts.items() if k == 1}


def _connected(cells: np.ndarray, n: int, source: str) -> None:
    from scipy.sparse.csgraph import connected_components

    rows = np.repeat(np.arange(len(cells)), cells.shape[1])
    incidence = sp.csr_array((np.ones(rows.size), (rows, cells.ravel())), shape=(len(cells), n))
    parts, labels = connected_components(incidence.T @ incidence, directed=False)
    used = np.unique(cells)
    parts = len(np.unique(labels[used]))
    if parts > 1:
        raise ParameterError("mesh", source, f"one connected solid (its cells form {parts} parts that share no node: "
                             "parts meshed apart, their interface nodes duplicated; mesh them as one, or join them "
                             "with a contact)")


def read_solid(path, units: str | None = None) -> Solid:
    """Read a 3-D mesh file (any format meshio reads) whose coordinates are in ``units``."""
    from .body import read_meshio

    path = regular_input("mesh", path, "a mesh file meshio reads")
    mesh = read_meshio(path)
    return solid_from_meshio(mesh, Path(path).name, units)


@dataclass(frozen=True, eq=False)
class SolidSystem:
    """``K`` (CSR, N/m), the lumped ``mass`` (kg per degree of freedom), the constant ``load`` (N per
    degree of freedom, from pressures and tractions on face groups), the ``consistent_mass`` (CSR, kg) and the Rayleigh
    ``damping`` (CSR, N s/m: each material's ``alpha`` times its lumped mass plus ``beta`` times its K)
    of ``solid``."""

    solid: Solid
    K: sp.csr_array
    mass: np.ndarray
    load: np.ndarray
    consistent_mass: sp.csr_array
    damping: sp.csr_array
    materials: dict = field(default_factory=dict)  # {cell group: material}, {"": material} for one
    group_mass: dict = field(default_factory=dict)  # {cell group: its lumped mass per dof}, for energy shares
    group_stiffness: dict = field(default_factory=dict)  # {cell group: its stiffness (CSR)}, for energy shares
    S: sp.csr_array | None = None  # the structural damping sum eta K of materials with a loss factor (None: none)

    @property
    def n_dofs(self) -> int:
        return 3 * len(self.solid.points)

    @property
    def body(self) -> Solid:
        """The solid (named as a 2-D `BodySystem`'s body: `stickslip.fem.pair` reads either)."""
        return self.solid

    @property
    def C(self):
        """The damping, or None where every material is undamped (as a 2-D `BodySystem`'s)."""
        return self.damping if self.damping.nnz else None

    def dofs(self, nodes) -> np.ndarray:
        """The degrees of freedom ``3 i, 3 i + 1, 3 i + 2`` of ``nodes``."""
        return (3 * np.asarray(nodes, dtype=np.int64)[:, None] + np.arange(3)).ravel()


#: Voigt order of the stress and (engineering) strain components: 11, 22, 33, 23, 13, 12.
VOIGT = ((0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1))


@dataclass(frozen=True)
class OrthotropicSolid:
    """An orthotropic linear elastic material in three dimensions (a brake lining): Young's moduli ``e1,
    e2, e3`` [Pa] along its axes, Poisson's ratios ``nu12, nu13, nu23`` (``nu_ij``: the contraction along
    ``j`` per strain along ``i`` under a stress along ``i``), shear moduli ``g12, g13, g23`` [Pa],
    ``density`` [kg/m^3], its axes 1 and 2 as two orthogonal directions ``axis1``, ``axis2`` in the
    solid's x, y, z (default x and y; axis 3 is their cross product), and Rayleigh damping ``alpha``
    [1/s], ``beta`` [s], a structural ``loss_factor`` (`stickslip.fem.Material`'s). A transversely isotropic lining
    (isotropic in its plane, its axis 3 the pressing direction) is the case ``e1 = e2``, ``nu13 = nu23``,
    ``g13 = g23``, ``g12 = e1 / (2 (1 + nu12))``. The compliance must be positive definite."""

    e1: float
    e2: float
    e3: float
    nu12: float
    nu13: float
    nu23: float
    g12: float
    g13: float
    g23: float
    density: float
    axis1: tuple = (1.0, 0.0, 0.0)
    axis2: tuple = (0.0, 1.0, 0.0)
    alpha: float = 0.0
    beta: float = 0.0
    loss_factor: float = 0.0

    def __post_init__(self):
        for name in ("e1", "e2", "e3", "nu12", "nu13", "nu23", "g12", "g13", "g23", "density", "alpha", "beta",
                     "loss_factor"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        axes = []
        for name in ("axis1", "axis2"):
            try:
                a = np.asarray(getattr(self, name), dtype=float)
            except (TypeError, ValueError):
                a = np.zeros(0)
            if a.shape != (3,) or not np.all(np.isfinite(a)) or not np.linalg.norm(a) > 0:
                raise ParameterError(name, getattr(self, name), "a direction: three finite numbers, not all zero")
            axes.append(a / np.linalg.norm(a))
        if abs(axes[0] @ axes[1]) > 1e-9:
            raise ParameterError("axis2", self.axis2, f"a direction orthogonal to axis1 = {self.axis1} (cosine "
                                 f"{axes[0] @ axes[1]:.3g})")
        object.__setattr__(self, "axis1", tuple(axes[0]))
        object.__setattr__(self, "axis2", tuple(axes[1]))
        if not np.all(np.linalg.eigvalsh(self.compliance[:3, :3]) > 0):
            raise ParameterError("nu12", self.nu12, "Poisson's ratios that make the compliance positive definite (the "
                                 "material must store energy under every strain)", also=("nu13", "nu23"))

    @property
    def compliance(self) -> np.ndarray:
        """``S`` [1/Pa] in the material axes (6 x 6, Voigt with engineering shear strains)."""
        e1, e2, e3, n12, n13, n23 = self.e1, self.e2, self.e3, self.nu12, self.nu13, self.nu23
        S = np.zeros((6, 6))
        S[:3, :3] = [[1 / e1, -n12 / e1, -n13 / e1], [-n12 / e1, 1 / e2, -n23 / e2], [-n13 / e1, -n23 / e2, 1 / e3]]
        S[3, 3], S[4, 4], S[5, 5] = 1 / self.g23, 1 / self.g13, 1 / self.g12
        return S

    @property
    def stiffness(self) -> np.ndarray:
        """``D`` [Pa] in the solid's x, y, z (6 x 6, Voigt): the material's, turned onto its axes as a
        fourth-order tensor, ``C_pqrs = A_pi A_qj A_rk A_sl C_ijkl`` (``A``'s columns the axes)."""
        C_m = np.linalg.inv(self.compliance)
        tensor = np.zeros((3, 3, 3, 3))
        for I, (i, j) in enumerate(VOIGT):
            for J, (k, l) in enumerate(VOIGT):
                for a, b in {(i, j), (j, i)}:
                    for c, d in {(k, l), (l, k)}:
                        tensor[a, b, c, d] = C_m[I, J]
        a1, a2 = np.array(self.axis1), np.array(self.axis2)
        A = np.column_stack([a1, a2, np.cross(a1, a2)])
        turned = np.einsum("pi,qj,rk,sl,ijkl->pqrs", A, A, A, A, tensor)
        return np.array([[turned[i, j, k, l] for k, l in VOIGT] for i, j in VOIGT])

    @property
    def young(self) -> float:
        """The stiffest of the moduli [Pa] (a scale of strains and loads)."""
        return float(max(self.e1, self.e2, self.e3))

    def describe(self, plane: bool = False) -> str:
        """One line: every constant (for a file's attributes; ``plane`` ignored: a solid has none)."""
        axes = [f"[{', '.join(f'{a:g}' for a in axis)}]" for axis in (self.axis1, self.axis2)]
        return (f"orthotropic: e1 = {self.e1:g} Pa, e2 = {self.e2:g} Pa, e3 = {self.e3:g} Pa, nu12 = {self.nu12:g}, "
                f"nu13 = {self.nu13:g}, nu23 = {self.nu23:g}, g12 = {self.g12:g} Pa, g13 = {self.g13:g} Pa, "
                f"g23 = {self.g23:g} Pa, axis1 = {axes[0]}, axis2 = {axes[1]}"
                + (f", loss factor {self.loss_factor:g}" if self.loss_factor else ""))


def _materials(solid: Solid, material) -> list[tuple[np.ndarray, Material]]:
    """``(cells, Material)`` pairs covering every cell once."""
    if isinstance(material, (Material, OrthotropicSolid)):
        pairs = [(np.arange(len(solid.cells)), material)]
    elif isinstance(material, dict) and material:
        unknown = sorted(set(material) - set(solid.cell_groups))
        if unknown:
            raise ParameterError("material", unknown[0], f"a cell group of {solid.source} "
                                 f"({', '.join(solid.cell_groups) or 'none'})")
        pairs = [(solid.cell_groups[g], m) for g, m in material.items()]
        for g, m in material.items():
            if not isinstance(m, (Material, OrthotropicSolid)):
                raise ParameterError(f"material[{g}]", m, "a stickslip.fem.Material or OrthotropicSolid")
        seen = np.zeros(len(solid.cells), dtype=int)
        for cells, _ in pairs:
            seen[cells] += 1
        if np.any(seen != 1):
            raise ParameterError("material", sorted(material), f"one material for every cell ({int(np.sum(seen == 0))} "
                                 f"cells have none, {int(np.sum(seen > 1))} two or more)")
    else:
        raise ParameterError("material", material, "a stickslip.fem.Material or OrthotropicSolid, or "
                             "{cell group: one of them}")
    for _, m in pairs:
        if isinstance(m, Material) and m.plane != "strain":
            raise ParameterError("plane", m.plane, "'strain' (its default) for a solid: plane stress is a 2-D model")
    return pairs


def skfem_mesh(solid: Solid):
    """``(mesh, element, ours, vertex)``: the scikit-fem mesh and vector element of ``solid``'s cells, our
    degree of freedom of each of scikit-fem's (found by place: a quadratic mesh's vertices are numbered
    anew by scikit-fem) and our node of each of its vertices."""
    from scipy.spatial import cKDTree
    from skfem import (Basis, ElementHex1, ElementHex2, ElementHexS2, ElementTetP1, ElementTetP2, ElementVector,
                       MeshHex1, MeshHex2, MeshTet1, MeshTet2)
    from skfem.io.meshio import INV_HEX_MAPPING

    p = np.ascontiguousarray(solid.points.T)
    if solid.kind == "tetra":
        mesh, element = MeshTet1(p, np.ascontiguousarray(solid.cells.T), sort_t=False), ElementVector(ElementTetP1())
    elif solid.kind == "tetra10":  # meshio's and scikit-fem's edge order agree: (0 1) (1 2) (0 2) (0 3) (1 3) (2 3)
        mesh, element = MeshTet2(doflocs=p, t=np.ascontiguousarray(solid.cells.T)), ElementVector(ElementTetP2())
    elif solid.kind == "hexahedron27":  # scikit-fem's reordering of meshio's numbering (its own meshio reader's)
        t = np.ascontiguousarray(solid.cells[:, INV_HEX_MAPPING].T)
        mesh, element = MeshHex2(doflocs=p, t=t), ElementVector(ElementHex2())
    elif solid.kind == "hexahedron20":  # the serendipity cell's own geometry, written as a triquadratic one
        cells, extra = _serendipity_to_27(solid.points, solid.cells)
        geometry = np.ascontiguousarray(np.vstack([solid.points, extra]).T)
        mesh = MeshHex2(doflocs=geometry, t=np.ascontiguousarray(cells[:, INV_HEX_MAPPING].T))
        element = ElementVector(ElementHexS2())
    else:
        t = np.ascontiguousarray(solid.cells[:, INV_HEX_MAPPING[:8]].T)
        mesh, element = MeshHex1(p, t, sort_t=False), ElementVector(ElementHex1())
    basis = Basis(mesh, element, intorder=1)
    tree = cKDTree(solid.points)
    size = float(np.ptp(solid.points, axis=0).max())
    distance, node = tree.query(basis.doflocs.T)
    component = np.zeros(basis.N, dtype=np.int64)
    for c in range(3):
        component[basis.nodal_dofs[c]] = c
        for dofs in (basis.edge_dofs, basis.facet_dofs, basis.interior_dofs):
            if dofs.size:
                component[dofs[c]] = c
    far, vertex = tree.query(mesh.p.T)
    far = far[np.unique(mesh.t)]  # (a 20-node cell's added points are in mesh.p, but no cell's vertex)
    if distance.max() > 1e-9 * size or far.max() > 1e-9 * size:  # not a user's error: said, never hidden
        raise RuntimeError("stickslip.fem.solid: a scikit-fem degree of freedom is at no node of the mesh")
    return mesh, element, 3 * node + component, vertex


def cell_quadrature(solid: Solid) -> dict:
    """scikit-fem's ``intorder`` for ``solid``'s cells, as keyword arguments of a ``Basis``: on quadratic
    hexahedra 3 x 3 x 3 Gauss points (exact for the stiffness and the mass of a parallelepiped; scikit-fem's
    default, 7 x 7 x 7, costs 13 times as much), else scikit-fem's default."""
    return {"intorder": 5} if solid.kind in ("hexahedron20", "hexahedron27") else {}


def _serendipity_to_27(points: np.ndarray, cells: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(cells27, extra)``: 20-node hexahedra with their middle-face and centre nodes added (``extra``,
    numbered after ``points``) where the serendipity cell puts them: a face's middle at ``-1/4`` of its
    corners plus ``1/2`` of its edge middles, the centre at ``-1/4`` of the corners plus ``1/4`` of the
    edge middles (the serendipity functions at those points). Its space lies in the triquadratic one, so
    the triquadratic map through these 27 points is the serendipity cell's own map."""
    x = points[cells]  # (m, 20, 3)
    corners, middles = x[:, :8].sum(axis=1), x[:, 8:].sum(axis=1)
    faces = []
    for face in HEX_FACE_CORNERS:
        edges = [8 + k for k, (a, b) in enumerate(HEX_EDGES) if a in face and b in face]
        faces.append(-0.25 * x[:, list(face)].sum(axis=1) + 0.5 * x[:, edges].sum(axis=1))
    extra = np.concatenate(faces + [-0.25 * corners + 0.25 * middles])  # face k of every cell, then the centres
    m, n = len(cells), len(points)
    added = n + np.arange(7)[None, :] * m + np.arange(m)[:, None]
    return np.hstack([cells, added]), extra


def _facets(mesh, vertex: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """The scikit-fem facet numbers of ``faces`` (our node indices, its corners first)."""
    ours = {tuple(sorted(vertex[f].tolist())): k for k, f in enumerate(mesh.facets.T)}
    corners = 4 if mesh.facets.shape[0] == 4 else 3
    return np.array([ours[tuple(sorted(f[:corners]))] for f in faces.tolist()], dtype=np.int64)


def assemble_solid(solid: Solid, material, loads=(), springs=()) -> SolidSystem:
    """Stiffness and lumped mass of ``solid`` with ``material`` (one, or one per cell group), the
    load of ``loads``: `stickslip.fem.Load` on face groups, a uniform ``pressure`` [Pa] (positive: into
    the solid) and ``traction = (tx, ty, tz)`` [Pa] on each, and ``springs``: `stickslip.fem.Spring` from
    a face group's nodes to the ground, total ``stiffness = (kx, ky, kz)`` [N/m] shared by the nodes'
    integrals of their shape functions over the group (so a rigid motion of the group meets exactly
    the total; a quadratic triangle's corners get none, as a uniform traction gives them no force)."""
    from skfem import Basis, BilinearForm, FacetBasis, LinearForm, asm
    from skfem.helpers import ddot, dot, eye, sym_grad, trace

    from .boundary import Load, Spring

    if not isinstance(solid, Solid):
        raise ParameterError("solid", solid, "a stickslip.fem.solid.Solid (read_solid)")
    pairs = _materials(solid, material)
    loads = list(loads) if isinstance(loads, (list, tuple)) else [loads]
    springs = list(springs) if isinstance(springs, (list, tuple)) else [springs]
    for i, load in enumerate(loads):
        if not isinstance(load, Load):
            raise ParameterError("loads", load, "stickslip.fem.Load (a pressure and a traction on a face group)")
        solid.nodes(load.group, "load.group")
        if len(load.traction) != 3 and any(load.traction):
            raise ParameterError(f"load[{i}].traction", list(load.traction), "three numbers [tx, ty, tz] on a solid")
    for i, spring in enumerate(springs):
        if not isinstance(spring, Spring):
            raise ParameterError("springs", spring, "stickslip.fem.Spring (springs on a face group)")
        solid.nodes(spring.group, "spring.group")
        if len(spring.stiffness) != 3:
            raise ParameterError(f"spring[{i}].stiffness", list(spring.stiffness), "three numbers [kx, ky, kz] on a "
                                 "solid")
    mesh, element, ours, vertex = skfem_mesh(solid)
    n = 3 * len(solid.points)
    to_ours = sp.csr_array((np.ones(n), (ours, np.arange(n))), shape=(n, n))  # scikit-fem's dofs -> ours
    K, M = sp.csr_array((n, n)), sp.csr_array((n, n))
    parts = []  # each material's K and consistent mass (its Rayleigh damping)
    for cells, m in pairs:
        basis = Basis(mesh, element, elements=cells, **cell_quadrature(solid))
        if isinstance(m, OrthotropicSolid):
            D = m.stiffness

            @BilinearForm
            def stiffness(u, v, w):  # sum_IJ D_IJ eps_J(u) eps_I(v), Voigt with engineering shears
                eu, ev = sym_grad(u), sym_grad(v)
                vu = [eu[i, j] * (1.0 if i == j else 2.0) for i, j in VOIGT]
                vv = [ev[i, j] * (1.0 if i == j else 2.0) for i, j in VOIGT]
                return sum(D[I, J] * vu[J] * vv[I] for I in range(6) for J in range(6) if D[I, J] != 0.0)
        else:
            lam = m.young * m.poisson / ((1 + m.poisson) * (1 - 2 * m.poisson))
            mu = m.young / (2 * (1 + m.poisson))

            @BilinearForm
            def stiffness(u, v, w):
                eu = sym_grad(u)
                return ddot(2.0 * mu * eu + lam * eye(trace(eu), 3), sym_grad(v))

        @BilinearForm
        def inertia(u, v, w):
            return m.density * dot(u, v)

        Kg, Mg = to_ours @ asm(stiffness, basis) @ to_ours.T, to_ours @ asm(inertia, basis) @ to_ours.T
        parts.append((cells, m, Kg, Mg))
        K, M = K + Kg, M + Mg
    f = np.zeros(n)
    for load in loads:
        t = np.zeros(3) if len(load.traction) != 3 else np.asarray(load.traction, float)
        if load.pressure == 0.0 and not t.any():
            continue
        facets = FacetBasis(mesh, element, facets=_facets(mesh, vertex, solid.faces[load.group]))

        @LinearForm
        def pushed(v, w):
            return -load.pressure * dot(w.n, v) + t[0] * v[0] + t[1] * v[1] + t[2] * v[2]  # w.n: the outward normal

        f += asm(pushed, facets)
    f = to_ours @ f
    if springs:  # each node's share: its shape function's integral over the group, over the group's area
        diag = np.zeros(n)

        @LinearForm
        def area(v, w):
            return v[0]

        for spring in springs:
            share = (to_ours @ asm(area, FacetBasis(mesh, element, facets=_facets(mesh, vertex,
                                                                                     solid.faces[spring.group]))))[0::3]
            for d in range(3):
                diag[d::3] += spring.stiffness[d] * share / share.sum()
        K = K + sp.diags_array(diag)
    mass, C, S = np.zeros(n), sp.csr_array((n, n)), None
    names = list(material) if isinstance(material, dict) else [""]  # each material's cell group
    group_mass, group_stiffness = {}, {}
    for (cells, m, Kg, Mg), name in zip(parts, names):
        lumped = _lumped(solid, cells, m.density, Mg)
        mass += lumped
        group_mass[name], group_stiffness[name] = lumped, sp.csr_array(Kg)
        if m.alpha or m.beta:  # Rayleigh, each material's own: C = sum (alpha M + beta K) over its cells
            C = C + m.alpha * sp.diags_array(lumped) + m.beta * Kg
        if m.loss_factor:  # structural: the CEA's stiffness K + i sum eta K over each material's cells
            S = m.loss_factor * Kg if S is None else S + m.loss_factor * Kg
    return SolidSystem(solid, sp.csr_array(K), mass, f, sp.csr_array(M), sp.csr_array(C),
                       {name: m for name, (_, m) in zip(names, pairs)}, group_mass, group_stiffness,
                       None if S is None else sp.csr_array(S))


def _lumped(solid: Solid, cells: np.ndarray, density: float, consistent) -> np.ndarray:
    """The lumped mass of ``cells``: the row sums of their ``consistent`` mass; on quadratic tetrahedra,
    where row sums give corners no (or negative) mass, each cell's shared by the diagonal of its consistent
    mass (Hinton-Rock-Zienkiewicz; on a straight-edged cell 6 : 32, corner : edge node)."""
    if solid.kind in ("tetra", "hexahedron"):
        return np.asarray(consistent.sum(axis=1)).ravel()
    if solid.kind != "tetra10":
        return _hinton_rock(solid, cells, density)
    mass = np.zeros(3 * len(solid.points))
    share = density * solid.volumes[cells]
    for k in range(10):
        np.add.at(mass, 3 * solid.cells[cells, k], share * (1.0 / 36.0 if k < 4 else 4.0 / 27.0))
    mass[1::3], mass[2::3] = mass[0::3], mass[0::3]
    return mass


def _hinton_rock(solid: Solid, cells: np.ndarray, density: float) -> np.ndarray:
    """Hinton-Rock-Zienkiewicz on any cells: each cell's mass ``density int dV`` shared by the
    diagonal ``density int N_i^2 dV`` of its consistent mass (scikit-fem's shape functions, the cell's
    own map)."""
    from scipy.spatial import cKDTree
    from skfem import Basis

    mesh, element, _, _ = skfem_mesh(solid)
    basis = Basis(mesh, element.elem, elements=cells, intorder=5)  # the scalar element: a function per node
    node = cKDTree(solid.points).query(basis.doflocs.T)[1]  # skfem_mesh checked each is at a node
    dx = basis.dx  # (cells, points)
    diagonal = np.array([np.sum(np.asarray(phi[0]) ** 2 * dx, axis=1) for phi in basis.basis])  # (functions, cells)
    share = density * dx.sum(axis=1) * diagonal / diagonal.sum(axis=0)
    mass = np.zeros(3 * len(solid.points))
    np.add.at(mass, 3 * node[basis.element_dofs[:, cells]], share)
    mass[1::3], mass[2::3] = mass[0::3], mass[0::3]
    return mass


def split_held(system, held) -> tuple:
    """``(n, supports)``: the solid's degrees of freedom and its `stickslip.fem.supports.Supports` from
    ``held``, one (`solid_supports`) or the indices of the degrees of freedom held (checked)."""
    from .supports import Supports

    if not isinstance(system, SolidSystem):
        raise ParameterError("system", system, "a SolidSystem (assemble_solid)")
    n = system.n_dofs
    if isinstance(held, Supports):
        if held.n != n:
            raise ParameterError("held", f"supports of {held.n} degrees of freedom", f"the supports of this solid "
                                 f"({n} degrees of freedom)")
        return n, held
    try:
        given = np.asarray(held).ravel()
    except (TypeError, ValueError):
        given = np.asarray([None])
    if given.size and not np.issubdtype(given.dtype, np.integer):
        raise ParameterError("held", f"{given.size} values of type {given.dtype}", "integer indices of degrees of "
                             "freedom (supported_dofs gives them; a float such as 1.5 names no degree of freedom)")
    held = given.astype(np.int64)
    if held.size and (held.min() < 0 or held.max() >= n):
        raise ParameterError("held", f"{held.size} indices", f"degrees of freedom of the solid (0 to {n - 1})")
    mask = np.zeros(n, bool)
    mask[held] = True
    return n, Supports(mask)


def solid_static(system: SolidSystem, held=()) -> np.ndarray:
    """The static displacement under the system's load with the degrees of freedom ``held`` at zero
    (every degree of freedom; a sparse direct solve). A solid free to move as a rigid body is refused."""
    from scipy.sparse.linalg import splu

    n, sup = split_held(system, held)
    r = system.solid.points - system.solid.points.mean(axis=0)
    rigid = np.zeros((len(r), 3, 6))  # the six rigid motions: three translations, three rotations w x r
    rigid[:, [0, 1, 2], [0, 1, 2]] = 1.0
    for k, w in enumerate(np.eye(3)):
        rigid[:, :, 3 + k] = np.cross(w, r)
    rigid = rigid.reshape(n, 6)
    if sup.rotation is not None:  # each held degree of freedom's part of each rigid motion, in its node's frame
        rigid = sup.rotation.T @ rigid
    count = int(sup.held.sum())
    if not count or np.linalg.matrix_rank(rigid[sup.held], tol=1e-9 * np.abs(rigid).max()) < 6:
        raise ParameterError("held", f"{count} degrees of freedom", "supports that hold every rigid motion "
                             "(three translations and three rotations; some are free)")
    return sup.expand(splu(sp.csc_array(sup.restrict(system.K))).solve(sup.load(system.load)))


def _support_groups(solid, clamped, rollers, rollers_allowed: str) -> list:
    """The clamped face groups as a list, ``solid``, ``clamped`` and ``rollers`` checked (`supported_dofs`,
    `solid_supports`)."""
    if not isinstance(solid, Solid):
        raise ParameterError("solid", solid, "a stickslip.fem.solid.Solid (read_solid)")
    groups = [clamped] if isinstance(clamped, str) else clamped
    if not isinstance(groups, (list, tuple)) or not all(isinstance(g, str) for g in groups):
        raise ParameterError("clamped", clamped, "a face group name or a list of them")
    if rollers is not None and not isinstance(rollers, dict):
        raise ParameterError("rollers", rollers, rollers_allowed)
    return list(groups)


def supported_dofs(solid: Solid, clamped=(), rollers=None) -> np.ndarray:
    """The degrees of freedom held: every one of the nodes of each face group in ``clamped``, and
    along its axis (``"x"``, ``"y"`` or ``"z"``) those of each face group of ``rollers``
    (``{group: axis}``: a symmetry plane or a sliding support normal to that axis). A roller along
    another direction is no degree of freedom: `solid_supports` gives it."""
    groups = _support_groups(solid, clamped, rollers, "{face group: axis} or None")
    held = [3 * solid.nodes(g, "clamped")[:, None] + np.arange(3) for g in groups]
    for group, axis in dict(rollers or {}).items():
        if not isinstance(axis, str) or axis not in AXES:
            raise ParameterError(f"rollers[{group}]", axis, "a coordinate axis: x, y or z (a roller along another "
                                 "direction: solid_supports)")
        held.append(3 * solid.nodes(group, "rollers") + AXES[axis])
    return np.unique(np.concatenate([np.ravel(h) for h in held])) if held else np.zeros(0, dtype=np.int64)


def solid_supports(solid: Solid, clamped=(), rollers=None):
    """The `stickslip.fem.supports.Supports` of ``solid``: every degree of freedom of the nodes of each
    face group in ``clamped``, and for each face group of ``rollers`` (``{group: axes or direction}``)
    its nodes held along coordinate axes (``"x"``, ``"yz"``) or along a direction ``[dx, dy, dz]`` (a
    face at an angle: ``d . u = 0``, the node's degrees of freedom in a frame of its own). `solid_modes`,
    `solid_static` and `solid_damped_modes` take it as ``held``."""
    from .supports import direction_of, supports_from

    groups = _support_groups(solid, clamped, rollers, "{face group: axes or a direction} or None")
    held = [(solid.nodes(g, "clamped"), list(np.eye(3))) for g in groups]
    held += [(solid.nodes(g, "rollers"), direction_of(d, 3, f"rollers[{g}]")) for g, d in dict(rollers or {}).items()]
    return supports_from(len(solid.points), 3, held)


def solid_modes(system: SolidSystem, held=(), count: int = 6, mass: str = "lumped") -> tuple[np.ndarray, np.ndarray]:
    """``(frequencies [Hz], shapes)``: the ``count`` lowest natural frequencies of ``system`` with the
    degrees of freedom ``held`` at zero, and their shapes (one column per mode, every degree of freedom;
    mass-normalised), with the ``"lumped"`` mass (an explicit run's) or the ``"consistent"`` one (its
    frequencies converge at order 2p, p the cells' order). Rigid-body modes of an unsupported solid come
    out near 0 Hz."""
    from scipy.sparse.linalg import eigsh

    n, sup = split_held(system, held)
    k = checked_count("count", count, max(1, min(len(sup.free) - 1, 500)), "modes")
    if mass not in ("lumped", "consistent"):
        raise ParameterError("mass", mass, "'lumped' or 'consistent'")
    Kf, lumped = sup.restrict(system.K), sup.mass(system.mass)
    Mf = sp.diags_array(lumped) if mass == "lumped" else sup.restrict(system.consistent_mass)
    shift = -1e-6 * float(np.max(Kf.diagonal() / lumped))  # below zero: a free solid's rigid modes
    values, vectors = eigsh(sp.csc_array(Kf), k=k, M=sp.csc_array(Mf), sigma=shift, which="LM")
    order = np.argsort(values)
    shapes = sup.expand(vectors[:, order])
    return np.sqrt(np.clip(values[order], 0.0, None)) / (2 * math.pi), shapes


def solid_damped_modes(system: SolidSystem, held=(), near: float = 0.0, count: int = 6) -> tuple:
    """``(growth_rates [1/s], frequencies [Hz], shapes)`` of the damped modes ``w e^(s t)`` of ``system``
    (``(s^2 M + s C + K) w = 0``, the lumped mass, the Rayleigh damping) with the degrees of freedom
    ``held`` at zero: the ``count`` eigenvalues nearest ``i 2 pi near`` (the shared shift-invert search
    of the CEA, `stickslip.fem.cea.eigenvalues_near`), one of each conjugate pair, by frequency."""
    from .cea import eigenvalues_near

    n, sup = split_held(system, held)
    near = Q.check("near", near)
    k = checked_count("count", count, max(1, min(len(sup.free) - 2, 500)), "modes")
    Kf, Cf = sp.csc_array(sup.restrict(system.K)), sp.csc_array(sup.restrict(system.damping))
    s, vectors, trusted, _, _ = eigenvalues_near(Kf, Cf, sup.mass(system.mass), near, 2 * k, True)
    keep = np.flatnonzero(trusted)
    order = keep[np.argsort(s[keep].imag)][:k]
    shapes = sup.expand(np.asarray(vectors[:, order], dtype=complex))
    return s[order].real, s[order].imag / (2 * math.pi), shapes

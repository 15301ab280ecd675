"""A 2-D elastic body read from a mesh: nodes, cells and named boundary groups.

`read_body(path)` reads any mesh meshio reads (gmsh ``.msh`` first); `body_from_meshio(mesh)`
takes a `meshio.Mesh`. The body is one kind of cell in the plane: linear (3-node triangles,
4-node quadrilaterals) or quadratic (6-node triangles, 9-node quadrilaterals, gmsh's
``-order 2``; their edges may be curved). Boundary groups are the named sets of edges
(gmsh physical groups of dimension 1) on which contact, clamping or loads act: 2-node lines
on a linear mesh, 3-node lines on a quadratic one. Cell groups are the named sets of cells
(gmsh physical groups of dimension 2: a pad's lining and backplate), each of which may have
its own material (`stickslip.fem.assembly.assemble`).

Checked on the way in, each refused with a `ParameterError` naming the mesh and the
problem: a mesh that is not planar, no cells or cells of another kind, mixed kinds,
inverted elements (some cells turn the other way than the rest), degenerate elements
(area below 1e-10 of the mean), parts that share no node (a lining and a backplate meshed
apart, their interface nodes duplicated: one body has one connected mesh), and boundary groups
whose edges are not on the boundary (on a quadratic mesh, also those whose middle node is not
their cells').
Unused points are dropped and the cells are oriented counter-clockwise.
"""

from __future__ import annotations

import contextlib
import io
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import ParameterError
from ..quantities import FEM as Q, MAX_MESH_NODES
import os

__all__ = ["Body", "read_body", "read_meshio", "named_sets", "body_from_meshio", "edge_middles", "CELL_KINDS"]

#: meshio cell types accepted for the body: linear and quadratic triangles and quadrilaterals.
CELL_KINDS = ("triangle", "quad", "triangle6", "quad9")
_CORNERS = {"triangle": 3, "quad": 4, "triangle6": 3, "quad9": 4}
_SIZE = {"triangle": 3, "quad": 4, "triangle6": 6, "quad9": 9}
#: the nodes of a cell turned round (clockwise <-> counter-clockwise), meshio's numbering: the
#: corners, then the middle node of the edge from corner k to k + 1, then the centre
_TURN = {"triangle": [2, 1, 0], "quad": [3, 2, 1, 0], "triangle6": [2, 1, 0, 4, 3, 5],
         "quad9": [3, 2, 1, 0, 6, 5, 4, 7, 8]}


@dataclass(frozen=True, eq=False)
class Body:
    """Nodes ``points`` (``(n, 2)``, the mesh's units), cells ``(m, 3 | 4 | 6 | 9)``
    counter-clockwise, ``kind`` (``triangle``, ``quad``, ``triangle6`` or ``quad9``) and boundary
    ``groups``: name -> edges ``(e, 2)`` (ends) or, on a quadratic mesh, ``(e, 3)`` (ends, middle);
    ``cell_groups``: name -> the sorted indices of its cells."""

    points: np.ndarray
    cells: np.ndarray
    kind: str
    groups: dict = field(default_factory=dict)
    source: str = "mesh"
    cell_groups: dict = field(default_factory=dict)

    @property
    def order(self) -> int:
        """1 for linear cells, 2 for quadratic ones."""
        return 2 if self.kind in ("triangle6", "quad9") else 1

    @property
    def corners(self) -> np.ndarray:
        """The corner nodes of every cell ``(m, 3 | 4)``, counter-clockwise."""
        return self.cells[:, :_CORNERS[self.kind]]

    @property
    def areas(self) -> np.ndarray:
        """Signed area of every cell (positive — counter-clockwise); of the straight-sided cell
        through its corners on a quadratic mesh."""
        return _areas(self.points, self.corners)

    def segments(self, name: str, option: str = "group") -> np.ndarray:
        """The straight pieces ``(k, 2)`` of boundary group ``name``: its edges, each cut at its
        middle node on a quadratic mesh (a chain through every node of the group)."""
        edges = self.group(name, option)
        if edges.shape[1] == 2:
            return edges
        return np.concatenate([edges[:, [0, 2]], edges[:, [2, 1]]])

    def group(self, name: str, option: str = "group") -> np.ndarray:
        """Edges of the boundary group ``name``; an unknown name is a `ParameterError` naming
        ``option`` and listing the groups the mesh has."""
        if not isinstance(name, str) or name not in self.groups:
            have = ", ".join(sorted(self.groups)) or "none"
            raise ParameterError(option, name, f"a boundary group of {self.source} (it has: {have})")
        return self.groups[name]

    def oriented(self, name: str, option: str = "group") -> np.ndarray:
        """The edges of group ``name`` oriented as in their cell (counter-clockwise: the body on
        the left of each edge's direction)."""
        edges = self.group(name, option)
        cells = self.corners
        directed = {tuple(e) for e in np.stack([cells, np.roll(cells, -1, axis=1)], axis=-1).reshape(-1, 2).tolist()}
        forward = np.array([tuple(e) in directed for e in edges[:, :2].tolist()], dtype=bool)
        turned = edges[:, [1, 0] + list(range(2, edges.shape[1]))]
        return np.where(forward[:, None], edges, turned)

    def cells_along(self, name: str, option: str = "group") -> np.ndarray:
        """Sorted indices of the cells with an edge in boundary group ``name``."""
        n = np.int64(len(self.points))
        edges = np.sort(self.group(name, option)[:, :2], axis=1).astype(np.int64)
        corners = self.corners
        sides = np.sort(np.stack([corners, np.roll(corners, -1, axis=1)], axis=-1), axis=-1).astype(np.int64)
        hit = np.isin(sides[..., 0] * n + sides[..., 1], edges[:, 0] * n + edges[:, 1]).any(axis=1)
        return np.flatnonzero(hit).astype(np.int64)

    def nodes(self, name: str, option: str = "group") -> np.ndarray:
        """Sorted node indices of the boundary group ``name``."""
        return np.unique(self.group(name, option))

    def describe(self) -> str:
        groups = ", ".join(f"{k} ({len(v)} edges)" for k, v in sorted(self.groups.items()))
        cells = ", ".join(f"{k} ({len(v)} cells)" for k, v in sorted(self.cell_groups.items()))
        return (f"{len(self.cells)} {self.kind}s, {len(self.points)} nodes; boundary groups: {groups or 'none'}"
                + (f"; cell groups: {cells}" if cells else ""))


def _areas(points: np.ndarray, cells: np.ndarray) -> np.ndarray:
    x, y = points[cells, 0], points[cells, 1]
    return 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)


def _boundary_edges(cells: np.ndarray) -> set:
    edges = np.stack([cells, np.roll(cells, -1, axis=1)], axis=-1).reshape(-1, 2)
    keys, counts = np.unique(np.sort(edges, axis=1), axis=0, return_counts=True)
    return {tuple(k) for k in keys[counts == 1]}


def edge_middles(cells: np.ndarray, kind: str) -> dict:
    """``{(a, b): m}``, ``a < b``: the middle node of every edge of quadratic ``cells``."""
    k = _CORNERS[kind]
    corners = cells[:, :k]
    ends = np.sort(np.stack([corners, np.roll(corners, -1, axis=1)], axis=-1), axis=-1).reshape(-1, 2)
    return dict(zip(map(tuple, ends.tolist()), cells[:, k:2 * k].ravel().tolist()))


def body_from_meshio(mesh, source: str = "mesh") -> Body:
    """The `Body` of a `meshio.Mesh` (see the module docstring for what is checked)."""
    bad = lambda allowed: ParameterError("mesh", source, allowed)  # noqa: E731
    points = np.asarray(getattr(mesh, "points", None), dtype=float)
    if points.ndim != 2 or points.shape[0] == 0 or points.shape[1] not in (2, 3) or not np.all(np.isfinite(points)):
        raise bad("a mesh with finite 2-D points")
    if points.shape[0] > MAX_MESH_NODES:
        raise bad(f"a mesh of at most {MAX_MESH_NODES} nodes (this one has {points.shape[0]}: about 2 GB and a minute "
                  "to assemble at the bound)")
    coordinates = Q["coordinates"]
    if not np.all((points >= coordinates.range.lo) & (points <= coordinates.range.hi)):
        raise bad(f"a mesh with coordinates {coordinates.allowed} (this one reaches {np.abs(points).max():.3g})")
    extent = float(np.ptp(points[:, :2], axis=0).max()) or 1.0
    if points.shape[1] == 3 and np.ptp(points[:, 2]) > 1e-12 * extent:
        raise bad("a planar mesh (all z equal): this one is 3-D")
    blocks = [(c.type, np.asarray(c.data)) for c in mesh.cells]
    kinds = {t for t, _ in blocks if t not in ("vertex", "line", "line3")}
    if not kinds:
        raise bad("a mesh with 2-D cells (triangles or quadrilaterals); it has none")
    if len(kinds) > 1 or not kinds <= set(CELL_KINDS):
        raise bad("a mesh of one kind of cell, triangle, quad, triangle6 or quad9 "
                  f"(it has {', '.join(sorted(kinds))})")
    kind = kinds.pop()
    quadratic = kind in ("triangle6", "quad9")
    cells = np.concatenate([d for t, d in blocks if t == kind]).astype(np.int64)
    used, cells = np.unique(cells, return_inverse=True)
    cells = cells.reshape(-1, _SIZE[kind])
    points = points[used, :2]
    areas = _areas(points, cells[:, :_CORNERS[kind]])
    if np.all(areas < 0):
        cells, areas = cells[:, _TURN[kind]], -areas  # a mesh oriented clockwise throughout: turned round
    tiny = ~(np.abs(areas) > 1e-10 * np.mean(np.abs(areas)))  # (NaN counts as no area)
    if np.any(tiny):
        raise bad(f"a mesh without degenerate cells ({int(tiny.sum())} have no area, the first is cell "
                  f"{int(np.argmax(tiny))})")
    if np.any(areas < 0):
        flipped = areas < 0
        raise bad(f"a mesh without inverted cells ({int(flipped.sum())} of {len(cells)} turn the other way, "
                  f"the first is cell {int(np.argmax(flipped))})")
    _connected(cells, len(points), _cell_groups(mesh, blocks, kind), source)
    renumber = np.full(int(used.max()) + 1, -1)
    renumber[used] = np.arange(used.size)
    boundary = _boundary_edges(cells[:, :_CORNERS[kind]])
    middles = edge_middles(cells, kind) if quadratic else {}
    groups, cell_groups = {}, _cell_groups(mesh, blocks, kind)
    for name, per_block in named_sets(mesh).items():
        if name.startswith("gmsh:"):
            continue
        edges = [(t, d[np.asarray(idx, dtype=np.int64)]) for (t, d), idx in zip(blocks, per_block)
                 if t in ("line", "line3") and len(idx)]
        if not edges:
            continue  # a group of cells or points, not of edges
        if quadratic and any(t != "line3" for t, _ in edges):
            raise bad(f"boundary group {name!r} of 3-node lines (line3), as the quadratic cells have")
        edges = np.concatenate([d for _, d in edges])[:, :3 if quadratic else 2].astype(np.int64)
        if np.any(edges >= renumber.size) or np.any(renumber[edges] < 0):
            raise bad(f"boundary group {name!r} on nodes of the body's cells")
        edges = renumber[edges]
        inside = [e for e in map(tuple, np.sort(edges[:, :2], axis=1)) if e not in boundary]
        if inside:
            raise bad(f"boundary group {name!r} on the boundary ({len(inside)} of its {len(edges)} edges are "
                      "inside the body)")
        if quadratic:
            wrong = [k for k, e in enumerate(edges.tolist()) if middles[tuple(sorted(e[:2]))] != e[2]]
            if wrong:
                raise bad(f"boundary group {name!r} with the middle nodes of its cells' edges ({len(wrong)} of "
                          f"its {len(edges)} edges have another, the first is edge {wrong[0]})")
        groups[name] = edges
    return Body(points, cells, kind, groups, source, cell_groups)


def _connected(cells: np.ndarray, n: int, cell_groups: dict, source: str) -> None:
    """Refuse a mesh whose cells make more than one part sharing no node, naming each part by its
    cell groups (or its count of cells): the parts would move apart, and a contact on one of them
    would find no steady state (the active set cycles)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    rows = np.repeat(cells[:, 0], cells.shape[1])
    graph = coo_matrix((np.ones(rows.size), (rows, cells.ravel())), shape=(n, n))
    parts, label = connected_components(graph, directed=False)
    if parts == 1:
        return
    of_cell = label[cells[:, 0]]
    names = []
    for part in range(min(parts, 5)):
        groups = [g for g, idx in sorted(cell_groups.items()) if np.any(of_cell[idx] == part)]
        names.append(f"{' + '.join(groups) or 'cells'} ({int(np.sum(of_cell == part))} cells)")
    raise ParameterError("mesh", source, f"one connected body: this mesh has {parts} parts that share no node "
                         f"({'; '.join(names)}{'; ...' if parts > 5 else ''}): where parts meet, their nodes are "
                         "duplicated; join them (gmsh: Coherence, or BooleanFragments before meshing)")


def _cell_groups(mesh, blocks, kind: str) -> dict:
    """``{name: sorted cell indices}`` of the named sets of 2-D cells (gmsh's physical surfaces),
    the cells numbered as the body's: the blocks of ``kind`` one after another."""
    offsets, at = [], 0
    for t, d in blocks:
        offsets.append(at if t == kind else -1)
        at += len(d) if t == kind else 0
    out = {}
    for name, per_block in named_sets(mesh).items():
        if name.startswith("gmsh:"):
            continue
        found = [start + np.asarray(idx, dtype=np.int64) for start, idx in zip(offsets, per_block)
                 if start >= 0 and len(idx)]
        if found:
            out[name] = np.unique(np.concatenate(found))
    return out


def named_sets(mesh) -> dict:
    """``{name: per block, the indices of its cells}`` of a `meshio.Mesh`: its ``cell_sets`` (gmsh 4
    files, meshio's own), or where a file has none, its gmsh physical groups by their names (``field_data``
    and the ``gmsh:physical`` tags of MSH 2.2 files, which meshio reads into no sets)."""
    sets = {k: v for k, v in (getattr(mesh, "cell_sets", None) or {}).items() if not k.startswith("gmsh:")}
    tags = (getattr(mesh, "cell_data", None) or {}).get("gmsh:physical")
    if sets or tags is None:
        return sets
    out = {}
    for name, (tag, dim) in (getattr(mesh, "field_data", None) or {}).items():
        per_block = [np.flatnonzero(np.asarray(t) == tag) for t in tags]
        if any(len(b) for b in per_block):
            out[str(name)] = per_block
    return out


def read_meshio(path):
    """The `meshio.Mesh` of a mesh file meshio reads (gmsh ``.msh``, VTK, XDMF, ...), its reader's
    complaints caught into a `ParameterError` naming the file."""
    if not isinstance(path, (str, os.PathLike)):
        raise ParameterError("mesh", path, "an existing mesh file (a path)")
    import meshio

    path = Path(path)
    if not path.is_file():
        raise ParameterError("mesh", str(path), "an existing mesh file")
    try:  # meshio prints its own complaint and calls sys.exit on a file no reader takes: both caught
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            return meshio.read(path)
    except (Exception, SystemExit) as err:  # noqa: BLE001 - whatever the reader of that format raises
        why = "no reader of meshio takes it" if isinstance(err, SystemExit) else \
            f"{type(err).__name__}: {str(err).splitlines()[0] if str(err) else 'unreadable'}"
        raise ParameterError("mesh", str(path), f"a mesh file meshio reads ({why})") from None


def read_body(path) -> Body:
    """The `Body` of a mesh file meshio reads (gmsh ``.msh``, VTK, XDMF, ...)."""
    mesh = read_meshio(path)
    return body_from_meshio(mesh, str(path))

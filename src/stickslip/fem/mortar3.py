"""The mortar coupling (`stickslip.fem.pair`) of two 3-D solids' face groups (`stickslip.fem.solid`).

**Why mortar, not node-to-surface.** As in 2-D: a uniform pressure passes a non-matching interface
exactly (the contact patch test), which one-pass node-to-surface fails; and with dual multipliers
the contact conditions stay node by node.

**Faces.** A group's faces are the cells' own: flat triangles (``tetra``), bilinear quadrilaterals
(``hexahedron``), quadratic triangles (``tetra10``) or quadrilaterals of 8 (``hexahedron20``) or 9
(``hexahedron27``) nodes (their corners span the plane used to integrate, so a curved quadratic face is
integrated flat). On each slave face the multiplier is
``sum_j phi_j lambda_j`` with dual functions ``phi_j = sum_k A_jk Nt_k`` biorthogonal to the face's
``Nt`` (``A = D_e M_e^-1``, ``M_e = int Nt Nt^T``, ``D_e`` the diagonal of ``int Nt``): ``Nt = N``, the
face's shape functions, on linear and bilinear faces, so that ``D_jk = int phi_j N_k = delta_jk int N_j``
is diagonal, and so on a 9-node quadrilateral (every ``int N_j`` positive: 1/36, 1/9 and 4/9 of a
parallelogram's area); on a quadratic triangle and an 8-node quadrilateral, whose corners' ``int N_j`` are
0 and negative (-1/12 of the area), the shape functions transformed as in Popp, Wohlmuth, Gee and Wall
(2012): ``Nt_corner = N_corner + a (N of its two edge middles)``, ``Nt_middle = (1 - 2 a) N_middle``,
``a = 1/5``; there ``D_jk = int phi_j N_k`` couples a face's nodes (still positive row sums ``int Nt_j``,
the node's share of the area).

**Integration.** The master faces near a slave face are projected onto its plane along its normal
and clipped against it (Sutherland-Hodgman, both convex), and ``M_jl = int phi_j N_l`` is integrated
over each overlap polygon's fan of triangles by scikit-fem's rule of degree 5: exact for flat faces
(the integrands are polynomials of degree at most 4 there: the contact patch test passes to
round-off across any two non-matching meshes), an approximation of the projection on curved ones.

**Normals.** A slave node's normal is the mean of its faces' normals weighted by ``int Nt_j`` on
each, pointing from the master into the slave; faces are oriented by the cell each bounds (a mesh's
face groups need no particular orientation). A master face facing away from the slave face (the far
side of a disc) is not its partner; one farther than the window along the normal neither.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ..errors import ParameterError

__all__ = ["solid_mortar", "outward_faces", "face_shapes", "TRANSFORM"]

#: Popp et al.'s weight of a quadratic triangle's edge middles in its corners' transformed functions.
TRANSFORM = 0.2
#: Each face kind (by its node count) turned round: its normal reversed (meshio's numbering).
_TURN = {3: [0, 2, 1], 4: [0, 3, 2, 1], 6: [0, 2, 1, 5, 4, 3], 8: [0, 3, 2, 1, 7, 6, 5, 4],
         9: [0, 3, 2, 1, 7, 6, 5, 4, 8]}
#: The corners of a face of each node count.
CORNERS = {3: 3, 4: 4, 6: 3, 8: 4, 9: 4}
#: The two edge middles next to each corner of the quadratic faces whose shape functions are transformed.
_NEXT = {6: ((3, 5), (3, 4), (4, 5)), 8: ((4, 7), (4, 5), (5, 6), (6, 7))}


def _rule():
    from skfem.quadrature import get_quadrature
    from skfem.refdom import RefTri

    points, weights = get_quadrature(RefTri, 5)
    return points.T, 2.0 * weights  # barycentric (xi, eta) of the reference triangle; weights summing to 1


def outward_faces(solid, group: str, option: str = "group") -> np.ndarray:
    """The faces of ``group`` of ``solid`` (``(f, 3 | 4 | 6 | 8 | 9)`` node indices), each turned so that its
    corners go round counter-clockwise seen from outside the solid (away from the cell it bounds)."""
    solid.nodes(group, option)  # a group it has
    faces = np.asarray(solid.faces[group])
    corners = CORNERS[faces.shape[1]]
    cells = solid.cells[:, :4] if solid.kind.startswith("tetra") else solid.cells[:, :8]
    n = len(solid.points)
    rows = np.repeat(np.arange(len(cells)), cells.shape[1])
    incidence = sp.csr_array((np.ones(rows.size), (cells.ravel(), rows)), shape=(n, len(cells)))
    picked = sp.csr_array((np.ones(faces.shape[0] * corners), (np.repeat(np.arange(faces.shape[0]), corners),
                                                               faces[:, :corners].ravel())), shape=(len(faces), n))
    hits = (picked @ incidence).tocoo()  # the cell holding every corner of a face
    owner = np.full(len(faces), -1)
    full = hits.data >= corners - 0.5
    owner[hits.row[full]] = hits.col[full]
    if np.any(owner < 0):
        raise ParameterError(option, group, "a face group whose faces are faces of the solid's cells")
    p = solid.points
    away = p[faces[:, :corners]].mean(axis=1) - p[cells[owner]].mean(axis=1)
    turn = np.einsum("ij,ij->i", _normals(p, faces), away) < 0
    faces = faces.copy()
    faces[turn] = faces[turn][:, _TURN[faces.shape[1]]]
    return faces


def _normals(p: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Each face's normal by its corners (a quadrilateral's by its diagonals), not unit."""
    if CORNERS[faces.shape[1]] == 4:
        return np.cross(p[faces[:, 2]] - p[faces[:, 0]], p[faces[:, 3]] - p[faces[:, 1]])
    return np.cross(p[faces[:, 1]] - p[faces[:, 0]], p[faces[:, 2]] - p[faces[:, 0]])


def face_shapes(size: int, xi: np.ndarray) -> np.ndarray:
    """The shape functions ``(q, size)`` of a face of ``size`` nodes at local points ``xi`` ``(q, 2)``:
    a triangle's barycentric ``(xi, eta)`` (linear, or quadratic with meshio's edge middles 01, 12,
    20), a quadrilateral's ``[-1, 1]^2`` (bilinear, corners counter-clockwise from ``(-1, -1)``; of 8
    nodes, serendipity, or 9, biquadratic, with the edge middles 01, 12, 23, 30 and the centre)."""
    x, y = xi[:, 0], xi[:, 1]
    if size == 4:
        return 0.25 * np.column_stack([(1 - x) * (1 - y), (1 + x) * (1 - y), (1 + x) * (1 + y), (1 - x) * (1 + y)])
    if size == 9:  # products of the 1-D quadratics at -1, 0, 1
        qx = np.column_stack([0.5 * x * (x - 1), 1 - x * x, 0.5 * x * (x + 1)])
        qy = np.column_stack([0.5 * y * (y - 1), 1 - y * y, 0.5 * y * (y + 1)])
        at = [(0, 0), (2, 0), (2, 2), (0, 2), (1, 0), (2, 1), (1, 2), (0, 1), (1, 1)]
        return np.column_stack([qx[:, i] * qy[:, j] for i, j in at])
    if size == 8:
        sx, sy = np.array([-1, 1, 1, -1]), np.array([-1, -1, 1, 1])
        corner = [0.25 * (1 + a * x) * (1 + b * y) * (a * x + b * y - 1) for a, b in zip(sx, sy)]
        middle = [0.5 * (1 - x * x) * (1 - y), 0.5 * (1 + x) * (1 - y * y), 0.5 * (1 - x * x) * (1 + y),
                  0.5 * (1 - x) * (1 - y * y)]
        return np.column_stack(corner + middle)
    L = np.column_stack([1.0 - x - y, x, y])
    if size == 3:
        return L
    return np.column_stack([L[:, 0] * (2 * L[:, 0] - 1), L[:, 1] * (2 * L[:, 1] - 1), L[:, 2] * (2 * L[:, 2] - 1),
                            4 * L[:, 0] * L[:, 1], 4 * L[:, 1] * L[:, 2], 4 * L[:, 2] * L[:, 0]])


def _transformed(N: np.ndarray) -> np.ndarray:
    """The functions the dual basis is biorthogonal to: ``N`` itself, or on a quadratic triangle and
    an 8-node quadrilateral Popp et al.'s transformed ones (see the module docstring)."""
    if N.shape[1] not in _NEXT:
        return N
    a = TRANSFORM
    out = N.copy()
    corners = CORNERS[N.shape[1]]
    for corner, (m1, m2) in enumerate(_NEXT[N.shape[1]]):
        out[:, corner] += a * (N[:, m1] + N[:, m2])
    out[:, corners:] *= 1.0 - 2.0 * a
    return out


def _local(corners: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Local coordinates ``(q, 2)`` of the 2-D points ``x`` in the face whose 2-D corners are
    ``corners`` (3: affine; 4: bilinear, by Newton's method, exact in one step on a parallelogram)."""
    if len(corners) == 3:
        T = np.column_stack([corners[1] - corners[0], corners[2] - corners[0]])
        return np.linalg.solve(T, (x - corners[0]).T).T
    xi = np.zeros((len(x), 2))
    for _ in range(20):
        N = face_shapes(4, xi)
        r = N @ corners - x
        s, t = xi[:, 0], xi[:, 1]
        dN = 0.25 * np.stack([np.column_stack([-(1 - t), 1 - t, 1 + t, -(1 + t)]),
                              np.column_stack([-(1 - s), -(1 + s), 1 + s, 1 - s])], axis=2)  # (q, 4, 2)
        J = np.einsum("qkd,ke->qed", dN, corners)  # (q, 2 [x, y], 2 [xi, eta])
        step = np.linalg.solve(J, -r[..., None])[..., 0]
        xi = xi + step
        if np.max(np.abs(step)) < 1e-14:
            break
    return xi


def _clip(subject: list, clip: np.ndarray) -> list:
    """The part of the convex polygon ``subject`` (2-D points, counter-clockwise) inside the convex
    polygon ``clip`` (counter-clockwise): Sutherland-Hodgman."""
    out = subject
    for i in range(len(clip)):
        a, edge = clip[i], clip[(i + 1) % len(clip)] - clip[i]
        side = [edge[0] * (q[1] - a[1]) - edge[1] * (q[0] - a[0]) for q in out]
        kept = []
        for k in range(len(out)):
            s, e, ss, se = out[k - 1], out[k], side[k - 1], side[k]
            if se >= 0.0:
                if ss < 0.0:
                    kept.append(s + (ss / (ss - se)) * (e - s))
                kept.append(e)
            elif ss >= 0.0:
                kept.append(s + (ss / (ss - se)) * (e - s))
        out = kept
        if len(out) < 3:
            return []
    return out


def _area2(poly) -> float:
    """Twice the signed area of a 2-D polygon."""
    q = np.asarray(poly)
    return float(np.sum(q[:, 0] * np.roll(q[:, 1], -1) - np.roll(q[:, 0], -1) * q[:, 1]))


def _points(poly: np.ndarray, rule) -> tuple[np.ndarray, np.ndarray]:
    """Quadrature points ``(q, 2)`` and weights [m^2] over a convex 2-D polygon (its fan of triangles)."""
    xi, w = rule
    a, b, c = poly[0], poly[1:-1], poly[2:]
    area = 0.5 * np.abs((b[:, 0] - a[0]) * (c[:, 1] - a[1]) - (c[:, 0] - a[0]) * (b[:, 1] - a[1]))
    x = a + xi[None, :, :1] * (b - a)[:, None, :] + xi[None, :, 1:] * (c - a)[:, None, :]
    return x.reshape(-1, 2), (area[:, None] * w[None, :]).ravel()


def solid_mortar(slave, slave_group: str, master, master_group: str, reach: float):
    """``(slave_nodes, normal, D, M, deep, away, found)`` of the mortar coupling of two solids' face
    groups (see the module docstring): ``deep`` the deepest interpenetration met beyond the window
    [m] (negative, or 0), ``away`` the master faces skipped as facing away, ``found`` the overlaps
    integrated. ``reach`` times the slave face's diameter is the window along the normal."""
    from scipy.spatial import cKDTree

    rule = _rule()
    s_faces = outward_faces(slave, slave_group, "slave_group")
    m_faces = outward_faces(master, master_group, "master_group")
    xs, xm = slave.points, master.points
    sc, mc = (CORNERS[f.shape[1]] for f in (s_faces, m_faces))
    nodes = np.unique(s_faces)
    where = np.full(len(xs), -1)
    where[nodes] = np.arange(len(nodes))
    n_s = -_normals(xs, s_faces)
    n_s /= np.linalg.norm(n_s, axis=1)[:, None]  # each slave face's: from the master into the slave
    o_m = _normals(xm, m_faces)
    o_m /= np.linalg.norm(o_m, axis=1)[:, None]  # each master face's outward
    m_centre = xm[m_faces[:, :mc]].mean(axis=1)
    m_size = float(np.max(np.linalg.norm(xm[m_faces[:, :mc]] - m_centre[:, None, :], axis=2)))
    seen = xs[nodes]
    window = reach * float(np.linalg.norm(seen.max(axis=0) - seen.min(axis=0)))
    tree = cKDTree(m_centre)
    normal = np.zeros((len(nodes), 3))
    D_r, D_c, D_v, M_r, M_c, M_v = [], [], [], [], [], []
    deep, away, found = 0.0, 0, 0
    for e, face in enumerate(s_faces):
        n, origin = n_s[e], xs[face[0]]
        e1 = xs[face[1]] - origin
        e1 /= np.linalg.norm(e1)
        frame = np.array([e1, np.cross(e1, n)])  # the face's corners counter-clockwise in this frame
        s2 = (xs[face[:sc]] - origin) @ frame.T
        x, w = _points(s2, rule)
        N = face_shapes(len(face), _local(s2, x))
        Nt = _transformed(N)
        A = np.diag(w @ Nt) @ np.linalg.inv(Nt.T @ (w[:, None] * Nt))  # dual: int phi_j Nt_k = delta_jk int Nt_k
        D_e = A @ (Nt.T @ (w[:, None] * N))
        rows = where[face]
        D_r.append(np.repeat(rows, len(face)))
        D_c.append(np.tile(face, len(face)))
        D_v.append(D_e.ravel())
        normal[rows] += (w @ Nt)[:, None] * n
        centre = xs[face[:sc]].mean(axis=0)
        size = float(np.max(np.linalg.norm(xs[face[:sc]] - centre, axis=1)))
        for f in tree.query_ball_point(centre, size + m_size + window):
            facing = float(o_m[f] @ n)
            if facing <= 1e-12:  # a master face facing away, or edge-on
                away += 1
                continue
            m2 = (xm[m_faces[f, :mc]] - origin) @ frame.T  # projected along n onto the slave's plane
            turn = _area2(m2)
            if abs(turn) <= 1e-12 * abs(_area2(s2)):
                continue
            poly = _clip(list(m2 if turn > 0 else m2[::-1]), s2)
            if not poly or _area2(poly) <= 1e-12 * abs(_area2(s2)):
                continue
            poly = np.asarray(poly)
            mid = origin + poly.mean(axis=0) @ frame
            gap = float(o_m[f] @ (mid - xm[m_faces[f, 0]])) / facing  # along n, from the master to the slave
            if abs(gap) > window:
                deep = min(deep, gap)
                continue
            found += 1
            xq, wq = _points(poly, rule)
            phi = _transformed(face_shapes(len(face), _local(s2, xq))) @ A.T
            Nm = face_shapes(m_faces.shape[1], _local(m2, xq))
            block = phi.T @ (wq[:, None] * Nm)
            M_r.append(np.repeat(rows, m_faces.shape[1]))
            M_c.append(np.tile(m_faces[f], len(face)))
            M_v.append(block.ravel())
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    shape_s, shape_m = (len(nodes), len(xs)), (len(nodes), len(xm))
    D = sp.csr_matrix((np.concatenate(D_v), (np.concatenate(D_r), np.concatenate(D_c))), shape=shape_s)
    D.data[np.abs(D.data) < 1e-14 * np.abs(D.data).max()] = 0.0
    D.eliminate_zeros()
    if M_r:
        M = sp.csr_matrix((np.concatenate(M_v), (np.concatenate(M_r), np.concatenate(M_c))), shape=shape_m)
    else:
        M = sp.csr_matrix(shape_m)
    return nodes, normal, D, M, min(deep, 0.0), away, found

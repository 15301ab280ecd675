"""How far a curved contact surface meshed with straight segments lies from the curve.

A segment of length ``h`` between two nodes of a circle of radius ``R`` lies inside it by its
sagitta ``R - sqrt(R^2 - h^2 / 4)`` (about ``h^2 / (8 R)``) at its middle. `facet_deviation` finds
each segment's from the mesh alone: the curvature at each node is that of the circle through
it and its two neighbours along the group (Menger's: ``4 area / (product of the sides)``; exact
for nodes on a circle, whatever their spacing), a segment's the mean of its ends', and a node
where the group turns by more than `CORNER` is a corner (no curvature: a pad's corner is not
a curved face). A straight face has none.

On a solid's faces (`face_deviation`) the surface's normal curvature along each edge of a face is
read from the turn of its normal between the edge's ends, ``|(n_b - n_a) . (x_b - x_a)| / h^2`` (the
nodal normals the mean of the faces' about each node, a node where one of them turns by more than
`CORNER` a corner), exact on a cylinder along any edge (Euler's ``cos^2``) and on a sphere; a face's
deviation is its edges' largest sagitta.

Where the deviation is not small against the compression the contact carries (the
interference the bodies' overlap puts on it), the gap from node to node is set by the
facets, not by the bodies: the pressure alternates between zero and twice its mean along the
contact (`stickslip.fem.pair.steady_pair` warns).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["facet_deviation", "face_deviation", "CORNER"]

#: A node where the group's direction turns by more than this [rad] is a corner.
CORNER = math.radians(45.0)


def facet_deviation(points: np.ndarray, edges: np.ndarray) -> np.ndarray:
    """Each segment's (``edges``, node index pairs, in any order and direction) largest distance
    from the smooth curve through the nodes [m] (see the module docstring)."""
    edges = np.asarray(edges)[:, :2]
    points = np.asarray(points)[:, :2]
    neighbours: dict[int, list[int]] = {}
    for a, b in edges.tolist():
        neighbours.setdefault(a, []).append(b)
        neighbours.setdefault(b, []).append(a)
    curvature = {}
    for node, near in neighbours.items():
        if len(near) != 2:  # an end of the group, or where groups branch: from its neighbours' curvature
            continue
        p, q, r = points[near[0]], points[node], points[near[1]]
        u, v = q - p, r - q
        cross = u[0] * v[1] - u[1] * v[0]
        turn = math.atan2(abs(cross), float(u @ v))
        sides = np.linalg.norm(u) * np.linalg.norm(v) * np.linalg.norm(r - p)
        curvature[node] = 0.0 if turn > CORNER or sides == 0 else 2.0 * abs(cross) / sides
    for node, near in neighbours.items():  # an end: its neighbour's
        if node not in curvature:
            known = [curvature[n] for n in near if n in curvature]
            curvature[node] = float(np.mean(known)) if known else 0.0
    k = np.array([0.5 * (curvature[a] + curvature[b]) for a, b in edges.tolist()])
    h = np.linalg.norm(points[edges[:, 1]] - points[edges[:, 0]], axis=1)
    # R - sqrt(R^2 - h^2/4) without the cancellation: k h^2 / (4 (1 + sqrt(1 - k^2 h^2 / 4)))
    return k * h**2 / (4.0 * (1.0 + np.sqrt(np.clip(1.0 - (k * h) ** 2 / 4.0, 0.0, None))))


def face_deviation(points: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Each face's (``faces``: corner node indices, triangles or quadrilaterals of one surface, oriented
    alike) largest distance from the smooth surface through the nodes [m] (see the module docstring)."""
    from ..errors import ParameterError

    try:
        points = np.asarray(points, dtype=float)
        faces = np.asarray(faces)
    except (TypeError, ValueError):
        raise ParameterError("points", "not numbers", "an (n, 3) array of node coordinates [m] and faces of "
                             "node indices") from None
    if points.ndim != 2 or points.shape[1] != 3 or not np.all(np.isfinite(points)):
        raise ParameterError("points", f"an array of shape {points.shape}", "(n, 3) finite node coordinates [m]")
    if faces.ndim != 2 or faces.shape[1] not in (3, 4) or not np.issubdtype(faces.dtype, np.integer) or \
            (faces.size and (faces.min() < 0 or faces.max() >= len(points))):
        raise ParameterError("faces", f"an array of shape {faces.shape}", "(f, 3) or (f, 4) corner node indices of "
                             "the points")
    corners = faces.shape[1]
    a, b, c = points[faces[:, 0]], points[faces[:, 1]], points[faces[:, 2]]
    normal = np.cross(c - a, points[faces[:, 3]] - b) if corners == 4 else np.cross(b - a, c - a)  # quads: diagonals
    unit = normal / np.linalg.norm(normal, axis=1)[:, None]
    total = np.zeros_like(points)
    np.add.at(total, faces.ravel(), np.repeat(normal, corners, axis=0))
    length = np.linalg.norm(total, axis=1)
    nodal = total / np.where(length > 0, length, 1.0)[:, None]
    # a corner: one of its faces turned from the mean by more than CORNER (no curvature there)
    corner = np.zeros(len(points), bool)
    turned = np.einsum("fci,fi->fc", nodal[faces], unit) < math.cos(CORNER)
    corner[faces[turned]] = True
    out = np.zeros(len(faces))
    for k in range(corners):
        i, j = faces[:, k], faces[:, (k + 1) % corners]
        d = points[j] - points[i]
        h = np.linalg.norm(d, axis=1)
        # the surface's normal curvature along the edge (Euler's: a diagonal across a cylinder bends less)
        bend = np.where(corner[i] | corner[j], 0.0, np.abs(np.einsum("fi,fi->f", nodal[j] - nodal[i], d)))
        kappa = bend / np.where(h > 0, h * h, 1.0)
        sag = kappa * h**2 / (4.0 * (1.0 + np.sqrt(np.clip(1.0 - (kappa * h) ** 2 / 4.0, 0.0, None))))
        out = np.maximum(out, sag)
    return out

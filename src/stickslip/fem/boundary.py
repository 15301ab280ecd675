"""Elastic supports and loads on the boundary groups of a general body (SI, per unit thickness).

* `Spring(group, stiffness)`: the nodes of a boundary group tied to the ground by springs
  along x and y. ``stiffness = (kx, ky)`` is the *total* stiffness of the group [N/m per
  metre of thickness, i.e. Pa], shared between its nodes by their tributary length (the
  integral of their shape function along the group: 1/6, 2/3, 1/6 of a straight quadratic
  edge), so a
  rigid motion of the group meets exactly ``(kx, ky)``: the spring of the 1-DOF oscillator
  when the body is stiff.
* `Load(group, pressure, traction)`: a uniform ``pressure`` [Pa] (positive pushes into the
  body, along the inward normal) and a uniform ``traction = (tx, ty)`` [Pa] on a boundary
  group. The nodal forces are the consistent ones of the edges (on a linear edge half of its
  force to each end; on a quadratic one, curved or not, the integral of each node's shape
  function along it, by Gauss quadrature), exact for uniform loads on straight edges.

`boundary_springs` and `boundary_load` turn them into a sparse stiffness and a force vector
on the dofs ``2 i + c`` of `stickslip.fem.assemble`, which adds them to the body's system.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ..quantities import FEM as Q
from ..errors import ParameterError
from .body import Body

__all__ = ["tributary_lengths", "Spring", "Load", "boundary_springs", "boundary_load"]

#: Largest spring stiffness accepted [N/m per m] (declared in `stickslip.quantities.FEM`).
LIMIT = Q["stiffness"].range.hi


@dataclass(frozen=True)
class Spring:
    """Springs along x and y from the nodes of boundary ``group`` to the ground, total
    ``stiffness = (kx, ky)`` >= 0 [Pa = N/m per metre of thickness]; on a solid's face group
    ``(kx, ky, kz)`` [N/m] (`stickslip.fem.solid.assemble_solid`)."""

    group: str
    stiffness: tuple

    def __post_init__(self):
        if not isinstance(self.group, str):
            raise ParameterError("spring.group", self.group, "the name of a boundary group")
        k = Q["stiffness"].check_vector(self.stiffness, "spring.stiffness")
        if max(k) == 0:
            raise ParameterError("spring.stiffness", self.stiffness, "numbers >= 0, not all zero")
        object.__setattr__(self, "stiffness", k)


@dataclass(frozen=True)
class Load:
    """A uniform ``pressure`` [Pa] (positive: into the body) and ``traction = (tx, ty)`` [Pa]
    on boundary ``group`` (on a solid's face group ``(tx, ty, tz)``)."""

    group: str
    pressure: float = 0.0
    traction: tuple = (0.0, 0.0)

    def __post_init__(self):
        if not isinstance(self.group, str):
            raise ParameterError("load.group", self.group, "the name of a boundary group")
        object.__setattr__(self, "pressure", Q.check("pressure", self.pressure, "load.pressure"))
        object.__setattr__(self, "traction", Q["traction"].check_vector(self.traction, "load.traction"))


#: 4-point Gauss rule on [-1, 1] for the quadratic edges
_XI, _W = np.polynomial.legendre.leggauss(4)


def _edge_integrals(body: Body, edges: np.ndarray):
    """For each edge and each of its nodes: ``(length, inward)``, the integrals along the edge of
    the node's shape function times 1 [m] and times the inward normal [m] (the body on the left
    of the edge's direction)."""
    p = body.points[edges]  # (e, 2 | 3, 2)
    if edges.shape[1] == 2:
        d = p[:, 1] - p[:, 0]
        inward = 0.5 * np.stack([-d[:, 1], d[:, 0]], axis=1)
        return np.repeat(0.5 * np.hypot(d[:, 0], d[:, 1])[:, None], 2, axis=1), np.stack([inward, inward], axis=1)
    xi = _XI[:, None]
    shape = np.concatenate([xi * (xi - 1) / 2, xi * (xi + 1) / 2, 1 - xi**2], axis=1)  # ends, middle
    slope = np.concatenate([xi - 0.5, xi + 0.5, -2 * xi], axis=1)
    tangent = np.einsum("qk,ekc->eqc", slope, p)  # dx/dxi at the Gauss points
    weight = _W[None, :, None] * shape[None]  # (1, q, k)
    length = np.einsum("eq,eqk->ek", np.hypot(tangent[..., 0], tangent[..., 1]), weight)
    normal = np.stack([-tangent[..., 1], tangent[..., 0]], axis=-1)
    return length, np.einsum("eqc,eqk->ekc", normal, weight)


def tributary_lengths(body: Body, group: str) -> np.ndarray:
    """Each node's share [m] of boundary ``group`` (0 off it): the integral along the group of the
    node's shape function, so that a uniform pressure ``P`` gives the node the normal force ``P``
    times its share (half of each adjacent edge on a linear mesh; a sixth and two thirds of an edge
    at a quadratic edge's ends and middle)."""
    edges = body.group(group, "contact_group")
    length, _ = _edge_integrals(body, edges)
    share = np.zeros(len(body.points))
    np.add.at(share, edges.ravel(), length.ravel())
    return share


def boundary_springs(body: Body, springs) -> sp.csr_matrix:
    """The (diagonal) stiffness of ``springs`` on all ``2 n`` dofs of ``body``."""
    diag = np.zeros(2 * len(body.points))
    for spring in springs:
        edges = body.group(spring.group, "spring.group")
        length, _ = _edge_integrals(body, edges)
        share = np.zeros(len(body.points))
        np.add.at(share, edges.ravel(), (length / length.sum()).ravel())
        diag[0::2] += spring.stiffness[0] * share
        diag[1::2] += spring.stiffness[1] * share
    return sp.diags(diag).tocsr()


def boundary_load(body: Body, loads) -> np.ndarray:
    """Nodal forces [N per metre of thickness] of ``loads`` on all ``2 n`` dofs of ``body``."""
    force = np.zeros((len(body.points), 2))
    for load in loads:
        edges = body.oriented(load.group, "load.group")
        length, inward = _edge_integrals(body, edges)
        per_node = load.pressure * inward + length[..., None] * np.asarray(load.traction)
        np.add.at(force, edges.ravel(), per_node.reshape(-1, 2))
    return force.ravel()

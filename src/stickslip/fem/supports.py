"""Supports of a body or a pair of bodies: the degrees of freedom held, along coordinate axes or along
any direction, 2-D and 3-D alike.

A roller along a coordinate axis holds one Cartesian degree of freedom of each node: the held ones
are left out of every operator (``K[free][:, free]``). A roller along another direction ``d`` (a face
at an angle: a symmetry plane of an obliquely cut sector, a caliper's slanted abutment) holds
``d . u = 0``, which no Cartesian degree of freedom says: such a node's degrees of freedom are written
in a frame of its own whose first axis is ``d`` (the others complete it to an orthonormal frame), and
that first one is held, as the nodal frames of commercial codes ("skew" or local systems) do. With
``R`` the orthogonal rotation from those frames (identity elsewhere), ``u = R u_f``, and the free
ones ``u = P q`` with ``P = R[:, free]``: the operators on the free degrees of freedom are
``P^T K P``, the loads ``P^T F``, constraint rows ``G P``. A node held along several directions
(where two faces meet) is held along every combination of them (an orthonormal basis of their span,
by a QR factorisation of rank decided at 1e-9); held along every axis, it is clamped.

The lumped mass of a node is the same along each axis, so ``P^T diag(m) P`` stays diagonal with the
node's mass: an explicit run keeps its diagonal mass.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp

from ..errors import ParameterError

__all__ = ["Supports", "supports_from", "direction_of"]

#: A direction's rank test: a direction within this of the span of those already held adds nothing.
RANK = 1e-9


def direction_of(value, dimension: int, option: str):
    """A roller's direction as the user wrote it: coordinate axes (``"x"``, ``"xz"``: held along each), or a
    vector of ``dimension`` finite numbers not all 0 (held along it). Returns a list of unit vectors."""
    axes = "xyz"[:dimension]
    if isinstance(value, str):
        if not value or len(set(value)) != len(value) or any(a not in axes for a in value):
            raise ParameterError(option, value, f"coordinate axes ({' or '.join(axes)}, or several: \"{axes[:2]}\" "
                                 f"holds both) or a direction of {dimension} numbers, e.g. "
                                 f"[{', '.join(['0.6', '0.8', '0'][:dimension])}]")
        return [np.eye(dimension)[axes.index(a)] for a in value]
    try:
        d = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        d = np.zeros(0)
    if isinstance(value, bool) or (isinstance(value, (list, tuple)) and any(isinstance(x, bool) for x in value)) or \
            d.shape != (dimension,) or not np.all(np.isfinite(d)) or \
            not np.abs(d).max() > 1e-150:
        raise ParameterError(option, value, f"coordinate axes ({' or '.join(axes)}) or a direction of {dimension} "
                             "finite numbers, not all 0")
    d = d / np.abs(d).max()  # first to its largest component: [1e300, 1e300, 0] has no finite norm
    return [d / np.linalg.norm(d)]


@dataclass(frozen=True, eq=False)
class Supports:
    """``held`` (bool per degree of freedom, in the nodes' frames) and ``rotation`` (CSR, orthogonal:
    ``u = rotation @ u_frames``; None: every frame Cartesian)."""

    held: np.ndarray
    rotation: sp.csr_array | None = None

    @property
    def n(self) -> int:
        return int(self.held.size)

    @cached_property
    def free(self) -> np.ndarray:
        """The free degrees of freedom (indices, in the nodes' frames)."""
        return np.flatnonzero(~self.held)

    @cached_property
    def basis(self) -> sp.csr_array:
        """``P`` (``n x free``): the displacements of the free degrees of freedom."""
        if self.rotation is None:
            k = self.free.size
            return sp.csr_array((np.ones(k), (self.free, np.arange(k))), shape=(self.n, k))
        return sp.csr_array(self.rotation[:, self.free])

    def restrict(self, X):
        """``P^T X P`` of a square operator on every degree of freedom (CSR)."""
        if self.rotation is None:
            return sp.csr_array(X)[self.free][:, self.free]
        P = self.basis
        return sp.csr_array(P.T @ sp.csr_array(X) @ P)

    def columns(self, X):
        """``X P`` of rows on every degree of freedom (CSR)."""
        if self.rotation is None:
            return sp.csr_array(X)[:, self.free]
        return sp.csr_array(sp.csr_array(X) @ self.basis)

    def load(self, f: np.ndarray) -> np.ndarray:
        """``P^T f`` of a vector on every degree of freedom."""
        return f[self.free] if self.rotation is None else self.basis.T @ f

    def mass(self, m: np.ndarray) -> np.ndarray:
        """The lumped mass on the free degrees of freedom (a node's the same along every axis)."""
        return m[self.free]

    def expand(self, q: np.ndarray) -> np.ndarray:
        """``P q``: displacements (columns of) on every degree of freedom, the held ones 0."""
        if self.rotation is None:
            out = np.zeros((self.n,) + q.shape[1:], dtype=q.dtype)
            out[self.free] = q
            return out
        return self.basis @ q


def supports_from(n_nodes: int, dimension: int, held: list) -> Supports:
    """The `Supports` of ``n_nodes`` nodes in ``dimension`` from ``held``: ``(nodes, directions)`` pairs
    (node indices, unit vectors from `direction_of`)."""
    per_node: dict = {}
    for nodes, directions in held:
        for node in np.asarray(nodes, dtype=np.int64).tolist():
            per_node.setdefault(node, []).extend(directions)
    mask = np.zeros(dimension * n_nodes, bool)
    blocks = {}
    for node, directions in per_node.items():
        if all(np.count_nonzero(d) == 1 for d in directions):  # along coordinate axes: held as they are
            for d in directions:
                mask[dimension * node + int(np.flatnonzero(d)[0])] = True
            continue
        frame, rank = _completed(directions, dimension)
        blocks[node] = frame
        mask[dimension * node + np.arange(rank)] = True
    if not blocks:
        return Supports(mask)
    n = dimension * n_nodes
    turned = np.array(sorted(blocks))
    keep = np.ones(n, bool)
    keep[(dimension * turned[:, None] + np.arange(dimension)).ravel()] = False
    rows, cols, vals = [np.flatnonzero(keep)], [np.flatnonzero(keep)], [np.ones(int(keep.sum()))]
    i, j = (k.ravel() for k in np.meshgrid(np.arange(dimension), np.arange(dimension), indexing="ij"))
    for node in turned.tolist():
        rows.append(dimension * node + i)
        cols.append(dimension * node + j)
        vals.append(blocks[node].ravel())
    R = sp.csr_array((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n))
    return Supports(mask, R)


def _completed(directions: list, dimension: int) -> tuple[np.ndarray, int]:
    """``(frame, rank)``: an orthonormal frame (columns, a rotation) whose first ``rank`` columns span
    the ``directions`` (Gram-Schmidt; a direction within `RANK` of the span before it adds nothing)."""
    basis, rank = [], 0
    for k, v in enumerate(list(directions) + list(np.eye(dimension))):
        w = v - sum((v @ b) * b for b in basis)
        if np.linalg.norm(w) > RANK:
            basis.append(w / np.linalg.norm(w))
            rank += k < len(directions)
        if len(basis) == dimension:
            break
    frame = np.column_stack(basis)
    if np.linalg.det(frame) < 0:  # a rotation, not a reflection (either would do: one convention)
        frame[:, -1] *= -1.0
    return frame, rank

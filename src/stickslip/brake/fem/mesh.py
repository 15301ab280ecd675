"""Structured mesh of the annulus ``1 < r < xi`` and its assembly, eq. [10]: the general body's
(`stickslip.fem.assemble`, scikit-fem) on this mesh, turned into polar frames and read as a stencil.

Lengths are in units of ``R`` and stresses in units of ``E`` (paper scaling above [10]).
The mesh has ``n_theta`` nodes around and ``n_r`` layers of bilinear quadrilaterals
(``ElementQuad1``), nodes at ``r_i = 1 + (xi - 1) i / n_r`` and ``theta_j = 2 pi j / n_theta``.
Quadrilaterals are used rather than triangles because every cell is then the mirror image
of its neighbour in ``theta``: the discrete operator has no preferred direction around
the ring, which matters for travelling waves whose direction is the physics.

Every nodal displacement is written in the node's polar frame ``(u_r, u_theta)``
(``u_cart = T u_polar``, ``T`` orthogonal per node). The lumped mass is isotropic per node,
so it stays diagonal, and the contact conditions at ``r = 1`` act on single degrees of
freedom: node ``(i, j)`` has dofs ``2 (i n_theta + j) + {0: radial, 1: hoop}``, the contact
nodes are ``i = 0`` (dofs ``2 j`` and ``2 j + 1``) and the clamped ring ``i = n_r`` comes
last and is dropped. In these frames the stiffness is block circulant in ``j``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import meshio
import numpy as np
import scipy.sparse as sp
from skfem import MeshQuad

from ...quantities import BRAKE as Q, MAX_MESH_NODES
from ...contact import stencil_matrix
from ...errors import ParameterError

__all__ = ["AnnulusMesh", "FemSystem", "annulus_mesh", "assemble"]


@dataclass(frozen=True, eq=False)
class AnnulusMesh:
    """A structured quadrilateral mesh of the annulus ``1 < r < xi`` (see `annulus_mesh`)."""

    n_theta: int
    n_r: int
    xi: float
    mesh: MeshQuad

    @property
    def radii(self) -> np.ndarray:
        return np.linspace(1.0, self.xi, self.n_r + 1)

    @property
    def theta(self) -> np.ndarray:
        """Angles of the nodes of one ring (the contact nodes at ``r = 1``)."""
        return 2.0 * np.pi * np.arange(self.n_theta) / self.n_theta

    @property
    def h_theta(self) -> float:
        """Arc length per node on the contact circle ``r = 1`` (the tributary length)."""
        return 2.0 * np.pi / self.n_theta

    @property
    def h_r(self) -> float:
        return (self.xi - 1.0) / self.n_r

    @cached_property
    def body(self):
        """The mesh as a general `stickslip.fem.Body` (the same nodes and cells, in the same
        order), with the boundary groups ``bore`` (the contact circle ``r = 1``, its edges from
        node ``j`` to ``j + 1``) and ``rim`` (the clamped circle ``r = xi``)."""
        from ...fem import body_from_meshio

        n, ring = self.n_theta, np.arange(self.n_theta)
        bore = np.column_stack([ring, (ring + 1) % n])
        none, every = np.array([], dtype=np.int64), np.arange(n)
        blocks = [meshio.CellBlock("quad", self.mesh.t.T), meshio.CellBlock("line", bore),
                  meshio.CellBlock("line", bore + self.n_r * n)]
        sets = {"bore": [none, every, none], "rim": [none, none, every]}
        return body_from_meshio(meshio.Mesh(self.mesh.p.T, blocks, cell_sets=sets), self.describe())

    @cached_property
    def polar_rotation(self) -> sp.csr_matrix:
        """``T`` with Cartesian ``u = T w`` at every node, ``w`` its polar components ``(u_r, u_theta)``."""
        ang = np.arctan2(self.mesh.p[1], self.mesh.p[0])
        c, s = np.cos(ang), np.sin(ang)
        k = np.arange(ang.size)
        dx, dy = 2 * k, 2 * k + 1
        rows = np.concatenate([dx, dy, dx, dy])
        cols = np.concatenate([dx, dx, dy, dy])
        return sp.csr_matrix((np.concatenate([c, s, -s, c]), (rows, cols)), shape=(2 * ang.size, 2 * ang.size))

    def describe(self) -> str:
        return (f"{self.n_theta} x {self.n_r} bilinear quadrilaterals (xi = {self.xi:g}; "
                f"h_theta = {self.h_theta:.3g} R at r = R, h_r = {self.h_r:.3g} R)")


def annulus_mesh(n_theta: int = 256, n_r: int = 16, xi: float = 1.5) -> AnnulusMesh:
    """Structured mesh of ``1 < r < xi``: ``n_theta`` nodes around, ``n_r`` layers.

    Parameters
    ----------
    n_theta : int
        Nodes around the ring, a multiple of 8, >= 16.
    n_r : int
        Layers of elements across the ring, >= 1.
    xi : float
        ``R*/R`` > 1.
    """
    n_theta, n_r, xi = Q.check("n_theta", n_theta), Q.check("n_r", n_r), Q.check("xi", xi)
    if n_theta < 16 or n_theta % 8:
        raise ParameterError("n_theta", n_theta, "a multiple of 8, >= 16")
    if n_theta * (n_r + 1) > MAX_MESH_NODES:
        raise ParameterError("n_r", n_r, f"at most {MAX_MESH_NODES // n_theta - 1} with n_theta = {n_theta} (a mesh of "
                             f"at most {MAX_MESH_NODES} nodes, about 2 GB and a minute to assemble)",
                             also=("n_theta",))
    r = np.linspace(1.0, xi, n_r + 1)
    th = 2.0 * np.pi * np.arange(n_theta) / n_theta
    R, T = np.meshgrid(r, th, indexing="ij")
    p = np.vstack([(R * np.cos(T)).ravel(), (R * np.sin(T)).ravel()])
    i, j = np.meshgrid(np.arange(n_r), np.arange(n_theta), indexing="ij")
    i, j = i.ravel(), j.ravel()
    jp = (j + 1) % n_theta
    t = np.vstack([i * n_theta + j, (i + 1) * n_theta + j, (i + 1) * n_theta + jp, i * n_theta + jp])
    return AnnulusMesh(n_theta, n_r, xi, MeshQuad(p, t))


@dataclass(frozen=True, eq=False)
class FemSystem:
    """Stiffness and lumped mass of the clamped annulus in polar nodal frames.

    ``K`` (CSR, units of ``E``, per unit length in z) and ``mass`` (diagonal, unit density:
    the physical mass matrix is ``gamma * mass`` in the paper's time ``t = Omega t̄``) act on
    the free dofs ``2 (i n_theta + j) + c``, ``i < n_r``. ``stencil[i, di + 1, dj + 1, c, c']``
    is the coupling of dof ``c`` of node ``(i, j)`` with dof ``c'`` of node ``(i + di, j + dj)``,
    the same for every ``j`` (``K`` is built from it, so it is exactly block circulant and
    symmetric).
    """

    mesh: AnnulusMesh
    nu: float
    K: sp.csr_matrix
    mass: np.ndarray
    stencil: np.ndarray

    @property
    def n_free(self) -> int:
        return self.K.shape[0]

    @property
    def n_contact(self) -> int:
        return self.mesh.n_theta

    def radial(self, u: np.ndarray) -> np.ndarray:
        """Free-dof vector(s) -> ``u_r`` on the grid ``(..., n_r, n_theta)`` (clamped ring omitted)."""
        u = np.asarray(u)
        return u[..., 0::2].reshape(u.shape[:-1] + (self.mesh.n_r, self.mesh.n_theta))

    def hoop(self, u: np.ndarray) -> np.ndarray:
        u = np.asarray(u)
        return u[..., 1::2].reshape(u.shape[:-1] + (self.mesh.n_r, self.mesh.n_theta))

    def from_fields(self, ur, ut) -> np.ndarray:
        """``u_r(r_i, theta_j)``, ``u_theta`` on ``(n_r, n_theta)`` -> free-dof vector."""
        u = np.empty(self.n_free)
        u[0::2], u[1::2] = np.ravel(ur), np.ravel(ut)
        return u


def _stencil(K_pol: sp.csr_matrix, n_theta: int, n_r: int) -> np.ndarray:
    """Couplings of the nodes ``j = 0`` (free layers), symmetrised: ``C[i, di, dj, c, c']``."""
    C = np.zeros((n_r, 3, 3, 2, 2))
    rows = np.array([2 * i * n_theta + c for i in range(n_r) for c in (0, 1)])
    sub = K_pol[rows].tocoo()
    node, comp = np.divmod(sub.col, 2)
    i2, j2 = np.divmod(node, n_theta)
    dj = np.where(j2 > n_theta // 2, j2 - n_theta, j2)
    i, c = np.divmod(sub.row, 2)
    keep = i2 < n_r  # the clamped ring is fixed
    np.add.at(C, (i[keep], (i2 - i)[keep] + 1, dj[keep] + 1, c[keep], comp[keep]), sub.data[keep])
    T = np.zeros_like(C)  # C[i, di, dj, c, c'] = C[i + di, -di, -dj, c', c] by symmetry of K
    for di in (-1, 0, 1):
        lo, hi = max(0, -di), min(n_r, n_r - di)
        T[lo:hi, di + 1] = np.flip(C[lo + di:hi + di, 1 - di], axis=1).transpose(0, 1, 3, 2)
    return 0.5 * (C + T)


def assemble(mesh: AnnulusMesh, nu: float = 0.3) -> FemSystem:
    """Assemble the plane-strain stiffness and the row-sum lumped mass: `stickslip.fem.assemble`
    on the mesh's `AnnulusMesh.body` in the paper's units (``E = 1``, unit density), in polar frames.

    Parameters
    ----------
    mesh : AnnulusMesh
        From `annulus_mesh`.
    nu : float
        Poisson's ratio in [0, 0.5); ``E = 1`` (stresses in units of ``E``).
    """
    if not isinstance(mesh, AnnulusMesh):
        raise ParameterError("mesh", mesh, "an AnnulusMesh (see annulus_mesh)")
    from ...fem import Material, assemble as assemble_body

    nu = Q.check("nu", nu)
    general = assemble_body(mesh.body, Material(1.0, nu, 1.0, scaled=True))
    T = mesh.polar_rotation
    K_pol = (T.T @ general.K @ T).tocsr()
    C = _stencil(K_pol, mesh.n_theta, mesh.n_r)
    ring_mass = general.mass[0::2][:: mesh.n_theta][: mesh.n_r]  # the same on every node of a ring
    mass = np.repeat(ring_mass, 2 * mesh.n_theta)
    return FemSystem(mesh, nu, stencil_matrix(C, mesh.n_theta), mass, C)

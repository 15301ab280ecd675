"""Small contact problems with exact solutions, written as `ExplicitScheme`s on the general
sparse path (they also show how a new geometry plugs into `stickslip.contact`).

* `SpringBlocks`: independent blocks of mass ``m``, each with a normal spring ``k_n`` whose
  rest position is ``delta`` below the rigid surface (so it presses with ``k_n delta``) and
  a tangential spring ``k_t`` to the ground, on a surface moving at ``speed``: the one-degree-
  of-freedom friction oscillator of the paper's section 2 with ``f_s = f_d = f``.
* `Bar`: an elastic bar (linear elements, lumped mass, ``c = sqrt(E/rho)``) between two
  rigid walls, frictionless. The dof of the right end is its displacement *towards the
  left*, so that both ends meet their wall as ``u_n >= gap0``.
"""

from dataclasses import dataclass, field
from functools import cached_property
from typing import ClassVar

import numpy as np
import scipy.sparse as sp

from stickslip.contact import ExplicitScheme


@dataclass(frozen=True)
class BlockParams:
    """Spring-block parameters (any consistent units)."""

    mass: float = 1.0
    k_n: float = 4.0
    k_t: float = 1.0
    delta: float = 0.5       # press of the normal spring: normal reaction k_n delta
    friction: float = 0.3
    speed: float = 0.2       # of the rigid surface


@dataclass(frozen=True)
class SpringBlocks(ExplicitScheme):
    """``blocks`` independent spring-blocks; dofs ``(normal, tangential)`` per block, interleaved."""

    PARAMS: ClassVar[type] = BlockParams
    params: BlockParams = field(default_factory=BlockParams)
    blocks: int = 1
    beta2: float = 0.5
    courant: float = 0.5

    def __post_init__(self):
        self.validate_common()

    @property
    def omega_max(self) -> float:
        p = self.params
        return float(np.sqrt(max(p.k_n, p.k_t) / p.mass))

    @property
    def transit_time(self) -> float:
        return 2 * np.pi / self.omega_max

    @property
    def theta(self) -> np.ndarray:
        return 2 * np.pi * np.arange(self.blocks) / self.blocks

    @property
    def mass(self) -> float:
        return self.params.mass

    @cached_property
    def contact_dofs(self):
        j = np.arange(self.blocks, dtype=np.int64)
        return 2 * j, 2 * j + 1

    @cached_property
    def surface(self):
        return np.full(self.blocks, self.params.delta), np.full(self.blocks, self.params.speed)

    def operator_matrix(self):
        p = self.params
        return sp.diags(np.tile([p.k_n / p.mass, p.k_t / p.mass], self.blocks)).tocsr()

    def steady_reference(self):
        p = self.params
        u = np.zeros(2 * self.blocks)
        u[0::2] = p.delta
        u[1::2] = p.friction * p.k_n * p.delta / p.k_t
        r_n = np.full(self.blocks, p.k_n * p.delta / p.mass)
        return u, r_n, p.friction * r_n


@dataclass(frozen=True)
class BarParams:
    """A bar of ``length`` with ``young`` modulus and ``density`` (unit cross-section) between
    walls ``gap_left`` and ``gap_right`` away from its ends, frictionless."""

    length: float = 1.0
    young: float = 1.0
    density: float = 1.0
    gap_left: float = 0.1
    gap_right: float = 0.1
    friction: float = 0.0

    @property
    def wave_speed(self) -> float:
        return float(np.sqrt(self.young / self.density))


@dataclass(frozen=True)
class Bar(ExplicitScheme):
    """``elements`` linear elements; dofs: axial displacements of the nodes (the last one
    flipped, see the module docstring), then one transverse dof per end (no stiffness)."""

    PARAMS: ClassVar[type] = BarParams
    params: BarParams = field(default_factory=BarParams)
    elements: int = 40
    beta2: float = 0.5
    courant: float = 0.9

    def __post_init__(self):
        self.validate_common()

    @property
    def h(self) -> float:
        return self.params.length / self.elements

    @cached_property
    def masses(self) -> np.ndarray:
        p, n = self.params, self.elements
        m = np.full(n + 1, p.density * self.h)
        m[[0, -1]] /= 2
        return np.concatenate([m, m[[0, -1]]])

    @cached_property
    def stiffness(self) -> sp.csr_matrix:
        p, n = self.params, self.elements
        k = p.young / self.h
        main = np.full(n + 1, 2 * k)
        main[[0, -1]] = k
        K = sp.diags([main, np.full(n, -k), np.full(n, -k)], [0, 1, -1]).tolil()
        K[n, n - 1] = K[n - 1, n] = k  # the last dof is flipped
        return sp.block_diag([K.tocsr(), sp.csr_matrix((2, 2))]).tocsr()

    @property
    def omega_max(self) -> float:
        A = (self.stiffness / self.masses[:, None]).toarray()
        return float(np.sqrt(np.max(np.linalg.eigvals(A).real)))

    @property
    def transit_time(self) -> float:
        return self.params.length / self.params.wave_speed

    @property
    def theta(self) -> np.ndarray:
        return np.array([0.0, np.pi])

    @property
    def mass(self) -> np.ndarray:
        return self.masses

    @cached_property
    def contact_dofs(self):
        n = self.elements
        return np.array([0, n], dtype=np.int64), np.array([n + 1, n + 2], dtype=np.int64)

    @cached_property
    def surface(self):
        return -np.array([self.params.gap_left, self.params.gap_right]), np.zeros(2)

    def operator_matrix(self):
        return sp.diags(1.0 / self.masses) @ self.stiffness

    def steady_reference(self):
        return np.zeros(self.elements + 3), np.zeros(2), np.zeros(2)

    def rigid_velocity(self, v_axial: float) -> np.ndarray:
        """The dof velocity of the whole bar moving at ``v_axial`` (positive to the right)."""
        v = np.zeros(self.elements + 3)
        v[:self.elements + 1] = v_axial
        v[self.elements] = -v_axial  # flipped dof
        return v

    def axial(self, u: np.ndarray) -> np.ndarray:
        """Axial displacements of the nodes (unflipped) from dof vector(s)."""
        x = np.array(u[..., :self.elements + 1])
        x[..., -1] *= -1
        return x

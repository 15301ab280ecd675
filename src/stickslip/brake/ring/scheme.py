"""The reduced equations [12] on the ring by the method of lines, and their explicit scheme.

Space: ``N`` nodes ``theta_j = j dtheta`` (periodic), second-order centred differences

    (L W)_j = (W_{j+1} - 2 W_j + W_{j-1}) / dtheta^2,   (G W)_j = (W_{j+1} - W_{j-1}) / (2 dtheta),

so that the internal accelerations (per unit modal mass, [12] corrected) are

    A_U = b L U + D G V - g U,      A_V = a L V - D G U - h V,      A = -K u.

``G`` is antisymmetric, so ``K`` is symmetric: the free problem has a conserved energy.
The dofs are ``u = (U_0, V_0, U_1, V_1, ...)``: one ring of nodes with a normal (``U``) and
a tangential (``V``) dof each, so ``K`` is a block-circulant stencil of
`stickslip.contact.kernel.stencil_apply` with ``n_r = 1``. Time: the explicit beta2 scheme
with forward-increment Lagrange multipliers of `stickslip.contact` ([22], [23];
``beta2 = 1/2`` is central differences); the shaft is the rigid surface, at ``U = delta``,
moving at speed 1. The reactions are per unit modal mass (``p = M P``, ``q = M Q``).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import ClassVar

import numpy as np

from ...quantities import BRAKE as Q
from ...contact import ExplicitScheme, discrete_rates
from ...errors import ParameterError
from ..reduced import BrakeParams, ReducedCoefficients

__all__ = ["RingScheme"]


@dataclass(frozen=True)
class RingScheme(ExplicitScheme):
    """Discretisation of [12] on ``nodes`` points and its explicit time step.

    Parameters
    ----------
    params : BrakeParams
        Dimensionless parameters (``delta > 0`` is not required here).
    nodes : int
        Number of nodes around the ring, >= 8.
    beta2 : float
        Newmark ``gamma`` of the explicit scheme [22], in [1/2, 1]: 1/2 is central
        differences (second order, no numerical damping); the paper uses 0.9 (first
        order, damps high frequencies).
    courant : float
        ``dt / dt_max`` in (0, 1], ``dt_max = sqrt(2/beta2) / omega_max`` the stability
        limit of the free discrete problem (``omega_max`` its highest frequency).
    """

    PARAMS: ClassVar[type] = BrakeParams
    params: BrakeParams
    nodes: int = 512
    beta2: float = 0.5
    courant: float = 0.9

    def __post_init__(self):
        self.validate_common()
        nodes = Q.check("nodes", self.nodes)
        if nodes < 8:
            raise ParameterError("nodes", nodes, "an integer >= 8")
        object.__setattr__(self, "nodes", nodes)

    @cached_property
    def coefficients(self) -> ReducedCoefficients:
        return self.params.coefficients()

    @property
    def dtheta(self) -> float:
        return 2.0 * np.pi / self.nodes

    @property
    def theta(self) -> np.ndarray:
        return self.dtheta * np.arange(self.nodes)

    # --- the interface of stickslip.contact ----------------------------------------------
    @cached_property
    def stencil(self) -> np.ndarray:
        """``M^{-1} K`` as couplings of node ``j`` with ``j - 1, j, j + 1`` (one layer)."""
        c, d = self.coefficients, self.dtheta
        C = np.zeros((1, 3, 3, 2, 2))
        C[0, 1, 1] = [[2 * c.b / d**2 + c.g, 0.0], [0.0, 2 * c.a / d**2 + c.h]]
        for dj in (-1, 1):
            C[0, 1, dj + 1] = [[-c.b / d**2, -dj * c.D / (2 * d)], [dj * c.D / (2 * d), -c.a / d**2]]
        return C

    @property
    def mass(self) -> float:
        """``dtheta``: energies are integrals over ``theta`` per unit modal mass."""
        return self.dtheta

    @cached_property
    def contact_dofs(self) -> tuple[np.ndarray, np.ndarray]:
        j = np.arange(self.nodes, dtype=np.int64)
        return 2 * j, 2 * j + 1

    @cached_property
    def surface(self) -> tuple[np.ndarray, np.ndarray]:
        """The shaft: ``U >= delta``, surface speed 1 (paper time ``Omega t``, lengths over ``R``)."""
        return np.full(self.nodes, self.params.delta), np.ones(self.nodes)

    def steady_reference(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Steady sliding [16]: ``U_e = delta``, ``V_e = delta f g / h``, ``P_e = g delta``, ``Q_e = f P_e``."""
        p, c = self.params, self.coefficients
        u = np.empty(2 * self.nodes)
        u[0::2], u[1::2] = p.delta, p.delta * p.friction * c.g / c.h
        P = np.full(self.nodes, c.g * p.delta)
        return u, P, p.friction * P

    @cached_property
    def omega_max(self) -> float:
        return float(self.frequencies(np.arange(self.nodes // 2 + 1)).max())

    @property
    def transit_time(self) -> float:
        """Time for a P-wave (speed ``sqrt(a)``) to go once around the ring: ``2 pi / sqrt(a)``."""
        return float(2.0 * np.pi / np.sqrt(self.coefficients.a))

    @property
    def speed_scales(self) -> dict:
        return {"sqrt_a": float(np.sqrt(self.coefficients.a))}

    # --- the ring's own analysis ---------------------------------------------------------
    def fields(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(U, V)`` from a dof vector (or an array of them, dofs on the last axis)."""
        u = np.asarray(u)
        return u[..., 0::2], u[..., 1::2]

    def dofs(self, U, V) -> np.ndarray:
        """The dof vector ``(U_0, V_0, U_1, V_1, ...)`` of nodal fields ``U, V``."""
        u = np.empty(2 * self.nodes)
        u[0::2], u[1::2] = U, V
        return u

    def symbols(self, k, discrete: bool = True):
        """Symbols of ``-d^2/dtheta^2`` and ``d/(i dtheta)`` for ``e^{i k theta}``."""
        k = np.asarray(k, dtype=float)
        if not discrete:
            return k**2, k
        d = self.dtheta
        return (2.0 * np.sin(k * d / 2.0) / d) ** 2, np.sin(k * d) / d

    def frequencies(self, k, discrete: bool = True) -> np.ndarray:
        """``omega(k)`` of the free problem (``f = 0``, no contact), both branches, shape ``(..., 2)``.

        ``omega^2`` are the eigenvalues of ``[[b s2 + g, -i D s1], [i D s1, a s2 + h]]``,
        with ``(s2, s1) = (k^2, k)`` (continuous) or the centred-difference symbols.
        """
        s2, s1 = self.symbols(k, discrete)
        c = self.coefficients
        kU, kV = c.b * s2 + c.g, c.a * s2 + c.h
        mean, rad = (kU + kV) / 2.0, np.sqrt(((kU - kV) / 2.0) ** 2 + (c.D * s1) ** 2)
        return np.sqrt(np.stack([mean - rad, mean + rad], axis=-1))

    def growth_rates(self, modes) -> np.ndarray:
        """Fully discrete ``s(n)`` of steady sliding (cf. `stickslip.brake.growth_rates`).

        With contact kept and forward slip, the scheme keeps ``U = delta`` at the nodes and
        gives ``P_m = g delta - D (G V)_m`` exactly, so mode ``n`` of ``V`` follows the
        scheme for ``V'' = -lambda V``, ``lambda = a s2 + h + i f D s1`` (discrete symbols).
        Returns ``log(z)/dt`` for the amplification factor ``z`` of largest modulus.
        """
        n = np.atleast_1d(np.asarray(modes, dtype=float))
        s2, s1 = self.symbols(n)
        c, f = self.coefficients, self.params.friction
        return discrete_rates(c.a * s2 + c.h + 1j * f * c.D * s1, self.dt, self.beta2)

    def accelerations(self, U, V):
        """Internal accelerations ``-K u`` of nodal fields (numpy, independent of the stencil)."""
        c, d = self.coefficients, self.dtheta
        lap = lambda W: (np.roll(W, -1, axis=-1) - 2.0 * W + np.roll(W, 1, axis=-1)) / d**2  # noqa: E731
        grad = lambda W: (np.roll(W, -1, axis=-1) - np.roll(W, 1, axis=-1)) / (2.0 * d)  # noqa: E731
        return c.b * lap(U) + c.D * grad(V) - c.g * U, c.a * lap(V) - c.D * grad(U) - c.h * V

"""Explicit scheme for the reduced equations [12] on the ring (method of lines).

Space: ``N`` nodes ``theta_j = j dtheta`` (periodic), second-order centred differences

    (L W)_j = (W_{j+1} - 2 W_j + W_{j-1}) / dtheta^2,   (G W)_j = (W_{j+1} - W_{j-1}) / (2 dtheta),

so that the internal accelerations (per unit modal mass, [12] corrected) are

    A_U = b L U + D G V - g U,      A_V = a L V - D G U - h V,      A = -K u.

``G`` is antisymmetric, so ``K`` is symmetric: the free problem has a conserved energy.
Time: the explicit Newmark scheme (``beta = 0``, ``gamma = beta2``), i.e. eq. [22] read
with ``u_dd_m`` for ``u_dd_{m+1}``; ``beta2 = 1/2`` is central differences. Contact and
friction by forward-increment Lagrange multipliers [23] (Carpenter, Taylor & Katona 1991):
the reactions ``r_m = (P_m, Q_m)`` act at ``t_m`` and the constraints hold at ``t_{m+1}``:

    u*_{m+1} = u_m + dt v*_m + dt^2/2 A_m,   v*_m = v_{m-1} + dt ((1 - beta2) a_{m-1} + beta2 A_m),
    u_{m+1} = u*_{m+1} + c dt^2 r_m,   c = beta2 + 1/2,
    P_m = max(0, (delta - U*_{m+1}) / (c dt^2)),
    Q_m = clip((V_m + dt - V*_{m+1}) / (c dt^2), -f P_m, f P_m).

The mass is diagonal, so this is exact node by node (no iteration): the stick reaction
makes the node move with the shaft, ``V_{m+1} - V_m = dt`` (surface speed 1); projecting
it on ``[-f P, f P]`` solves the discrete Coulomb inclusion ``Q in f P Sign(1 - w)``,
``w = (V_{m+1} - V_m)/dt``, because ``w`` is affine and increasing in ``Q``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numba import njit

from ... import validation as check
from ...errors import ParameterError
from ..reduced.coefficients import ReducedCoefficients
from ..reduced.params import BrakeParams

__all__ = ["RingScheme", "advance", "bare", "energies", "amplification_matrix", "STICK", "SLIP_POS", "SLIP_NEG",
           "SEPARATION", "STATE_NAMES"]

#: Node states (``state`` arrays): [17] stick, [18] positive slip, [19] reverse slip, [20] separation.
STICK, SLIP_POS, SLIP_NEG, SEPARATION = 0, 1, 2, 3
STATE_NAMES = ("stick", "slip", "reverse_slip", "separation")


@njit(cache=True)
def _internal(U, V, aU, aV, a, b, g, h, D, dth):
    n = U.shape[0]
    i2, i1 = 1.0 / (dth * dth), 0.5 / dth
    for j in range(n):
        jm = j - 1 if j > 0 else n - 1
        jp = j + 1 if j < n - 1 else 0
        aU[j] = b * (U[jp] - 2.0 * U[j] + U[jm]) * i2 + D * (V[jp] - V[jm]) * i1 - g * U[j]
        aV[j] = a * (V[jp] - 2.0 * V[j] + V[jm]) * i2 - D * (U[jp] - U[jm]) * i1 - h * V[j]


@njit(cache=True)
def advance(U, V, vU, vV, aU, aV, P, Q, state, work, nsteps, dt, coef, delta, f, beta2, contact):
    """Advance ``nsteps`` steps in place (compiled).

    On entry ``(U, V) = u_m``, ``(vU, vV) = v_{m-1}``, ``(aU, aV) = a_{m-1}``; on exit the
    same for ``m + nsteps``. ``P, Q, state`` receive the reactions and node states of the
    last step (time ``t_{m+nsteps-1}``), ``work[0:2]`` that step's ``u_m`` (U then V rows
    of a ``(2, N)`` array) for snapshots. ``coef = (a, b, g, h, D, dtheta)``.
    """
    a, b, g, h, D, dth = coef[0], coef[1], coef[2], coef[3], coef[4], coef[5]
    n = U.shape[0]
    cdt2 = (beta2 + 0.5) * dt * dt
    on = 1.0 if contact else 0.0
    AU, AV = np.empty(n), np.empty(n)
    for _ in range(nsteps):
        _internal(U, V, AU, AV, a, b, g, h, D, dth)
        work[0, :] = U
        work[1, :] = V
        for j in range(n):  # branch-free, so that the loop vectorises
            vsu = vU[j] + dt * ((1.0 - beta2) * aU[j] + beta2 * AU[j])
            vsv = vV[j] + dt * ((1.0 - beta2) * aV[j] + beta2 * AV[j])
            us = U[j] + dt * vsu + 0.5 * dt * dt * AU[j]
            vs = V[j] + dt * vsv + 0.5 * dt * dt * AV[j]
            p = on * max((delta - us) / cdt2, 0.0)
            trial = (V[j] + dt - vs) / cdt2
            lim = f * p
            q = min(max(trial, -lim), lim)
            touch = p > 0.0
            state[j] = SEPARATION * (1 - touch) + touch * (SLIP_POS * (trial > lim) + SLIP_NEG * (trial < -lim))
            P[j], Q[j] = p, q
            aU[j], aV[j] = AU[j] + p, AV[j] + q
            vU[j], vV[j] = vsu + beta2 * dt * p, vsv + beta2 * dt * q
            U[j] = delta if touch else us
            V[j] = vs + cdt2 * q


@njit(cache=True)
def bare(U, V, vU, vV, aU, aV, nsteps, dt, coef, beta2):
    """The same update without contact or friction (compiled): the benchmark baseline."""
    a, b, g, h, D, dth = coef[0], coef[1], coef[2], coef[3], coef[4], coef[5]
    n = U.shape[0]
    AU, AV = np.empty(n), np.empty(n)
    for _ in range(nsteps):
        _internal(U, V, AU, AV, a, b, g, h, D, dth)
        for j in range(n):
            vU[j] += dt * ((1.0 - beta2) * aU[j] + beta2 * AU[j])
            vV[j] += dt * ((1.0 - beta2) * aV[j] + beta2 * AV[j])
            U[j] += dt * vU[j] + 0.5 * dt * dt * AU[j]
            V[j] += dt * vV[j] + 0.5 * dt * dt * AV[j]
            aU[j], aV[j] = AU[j], AV[j]


@njit(cache=True)
def energies(U0, V0, U1, V1, dt, coef, Ue, Ve):
    """``(kinetic, elastic)`` of the scheme at ``t_{m+1/2}``: ``|w|^2/2`` and
    ``(u_m - u_e) K (u_{m+1} - u_e)/2`` (times ``dtheta``), ``w = (u_{m+1} - u_m)/dt``,
    ``u_e = (Ue, Ve)`` a uniform reference state. With ``u_e = 0`` their sum is exactly
    conserved by central differences in the free problem, and its change over a step is
    the work ``r_m . (u_{m+1} - u_{m-1})/2`` of the reactions.
    """
    n = U0.shape[0]
    X0, Y0, X1, Y1 = U0 - Ue, V0 - Ve, U1 - Ue, V1 - Ve
    AU, AV = np.empty(n), np.empty(n)
    _internal(X1, Y1, AU, AV, coef[0], coef[1], coef[2], coef[3], coef[4], coef[5])
    kin, ela = 0.0, 0.0
    for j in range(n):
        wu, wv = (U1[j] - U0[j]) / dt, (V1[j] - V0[j]) / dt
        kin += wu * wu + wv * wv
        ela -= X0[j] * AU[j] + Y0[j] * AV[j]
    return 0.5 * coef[5] * kin, 0.5 * coef[5] * ela


def amplification_matrix(w2, beta2):
    """One step for ``x'' = -lambda x``, ``w2 = lambda dt^2`` (complex allowed):
    ``(u_m, v_{m-1} dt, a_{m-1} dt^2) -> (u_{m+1}, v_m dt, a_m dt^2)``."""
    am = np.array([-w2, 0.0, 0.0], dtype=complex)
    vm = np.array([0.0, 1.0, 1.0 - beta2]) + beta2 * am
    um = np.array([1.0, 0.0, 0.0]) + vm + 0.5 * am
    return np.array([um, vm, am])


@dataclass(frozen=True)
class RingScheme:
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

    params: BrakeParams
    nodes: int = 512
    beta2: float = 0.5
    courant: float = 0.9

    def __post_init__(self):
        if not isinstance(self.params, BrakeParams):
            raise ParameterError("params", self.params, "a stickslip.brake.BrakeParams")
        nodes = check.positive_int("nodes", self.nodes)
        if nodes < 8:
            raise ParameterError("nodes", nodes, "an integer >= 8")
        object.__setattr__(self, "nodes", nodes)
        object.__setattr__(self, "beta2", check.in_range("beta2", self.beta2, 0.5, 1.0))
        object.__setattr__(self, "courant", check.in_range("courant", self.courant, 0.0, 1.0, lo_open=True))

    @cached_property
    def coefficients(self) -> ReducedCoefficients:
        return self.params.coefficients()

    @property
    def dtheta(self) -> float:
        return 2.0 * np.pi / self.nodes

    @property
    def theta(self) -> np.ndarray:
        return self.dtheta * np.arange(self.nodes)

    @cached_property
    def coef(self) -> np.ndarray:
        c = self.coefficients
        return np.array([c.a, c.b, c.g, c.h, c.D, self.dtheta])

    @property
    def order(self) -> int:
        """Order of accuracy in time: 2 for central differences, 1 otherwise."""
        return 2 if self.beta2 == 0.5 else 1

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

    @cached_property
    def omega_max(self) -> float:
        return float(self.frequencies(np.arange(self.nodes // 2 + 1)).max())

    @cached_property
    def dt_max(self) -> float:
        """Stability limit ``sqrt(2/beta2) / omega_max`` of the explicit scheme."""
        return float(np.sqrt(2.0 / self.beta2) / self.omega_max)

    @property
    def dt(self) -> float:
        return self.courant * self.dt_max

    @property
    def transit_time(self) -> float:
        """Time for a P-wave (speed ``sqrt(a)``) to go once around the ring: ``2 pi / sqrt(a)``."""
        return float(2.0 * np.pi / np.sqrt(self.coefficients.a))

    @property
    def steps_per_transit(self) -> float:
        return self.transit_time / self.dt

    def step_factor(self, omega) -> np.ndarray:
        """Spectral radius per step of the scheme for a free mode of frequency ``omega``."""
        out = [np.abs(np.linalg.eigvals(amplification_matrix((w * self.dt) ** 2, self.beta2))).max()
               for w in np.ravel(omega)]
        return np.reshape(out, np.shape(omega))

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
        lam = c.a * s2 + c.h + 1j * f * c.D * s1
        out = []
        for w2 in lam * self.dt**2:
            z = np.linalg.eigvals(amplification_matrix(w2, self.beta2))
            out.append(np.log(z[np.argmax(np.abs(z))]) / self.dt)
        return np.asarray(out)

    def accelerations(self, U, V):
        """Internal accelerations ``-K u`` (numpy reference of the compiled kernel)."""
        c, d = self.coefficients, self.dtheta
        lap = lambda W: (np.roll(W, -1, axis=-1) - 2.0 * W + np.roll(W, 1, axis=-1)) / d**2  # noqa: E731
        grad = lambda W: (np.roll(W, -1, axis=-1) - np.roll(W, 1, axis=-1)) / (2.0 * d)  # noqa: E731
        return c.b * lap(U) + c.D * grad(V) - c.g * U, c.a * lap(V) - c.D * grad(U) - c.h * V

    def elastic_energy(self, U, V, U2=None, V2=None) -> np.ndarray:
        """``dtheta u^T K u2 / 2`` (``u2 = u`` by default), over the last axis."""
        U2, V2 = (U, V) if U2 is None else (U2, V2)
        aU, aV = self.accelerations(U2, V2)
        return -0.5 * self.dtheta * np.sum(U * aU + V * aV, axis=-1)

    def kinetic_energy(self, vU, vV) -> np.ndarray:
        return 0.5 * self.dtheta * np.sum(vU**2 + vV**2, axis=-1)

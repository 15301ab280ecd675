"""Closed-form zone solutions of the travelling-wave equations [15] (corrected).

For ``U(phi), V(phi)``, ``phi = theta - c t`` (so ``U_t = -c U'``), the reduced model
[12] (corrected, see ``docs/theory/brake.md``) becomes

    (c^2 - b) U'' - D V' + g U = P,      (c^2 - a) V'' + D U' + h V = Q,

with slip velocity ``w = 1 - V_t = 1 + c V'``. In each zone [17]-[20] this is a linear
system with constant coefficients for the state ``y = (U, U', V, V')``:

* separation [20]: ``P = Q = 0``, a homogeneous 4th-order system;
* stick [17]: ``U = delta``, ``V' = -1/c``, so ``P = g delta + D/c`` is constant and
  ``Q = h V`` is linear in ``phi``;
* slip [18] (``s = +1``) / reverse slip [19] (``s = -1``): ``U = delta``,
  ``P = g U - D V'`` and ``(c^2 - a) V'' = f s P - h V``, a damped oscillator.

The flows are exact: polynomial for stick, the Putzer formula for the 2x2 slip block
(robust through its double root), an eigen-decomposition for separation (its
eigenvalues are ``+-i omega_1, +-i omega_2`` with ``omega_1 != omega_2`` whenever
``c^2 > a``) with `scipy.linalg.expm` as a fallback.

Everything here works in *internal units* (`Scaling`): every coefficient of [13] is
proportional to ``1/gamma``, so with ``c = c_hat/sqrt(gamma)``,
``(U, V) = sqrt(gamma) (U_hat, V_hat)`` and ``(P, Q) = (P_hat, Q_hat)/sqrt(gamma)`` the
equations hold with the ``gamma = 1`` coefficients and the mismatch
``delta_hat = delta/sqrt(gamma)``, while ``w = 1 + c_hat V_hat'``. The waves therefore
depend on ``(xi, nu, f)`` and on ``delta/sqrt(gamma)`` only (not on ``delta`` and
``Omega`` separately).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.linalg import expm

from ..reduced.coefficients import coefficients
from ..reduced.params import BrakeParams

__all__ = ["STICK", "SLIP", "REVERSE", "SEPARATION", "KINDS", "CONTACT", "Scaling", "ZoneFlows",
           "slip_sign"]

STICK, SLIP, REVERSE, SEPARATION = "stick", "slip", "reverse-slip", "separation"
KINDS = (STICK, SLIP, REVERSE, SEPARATION)
CONTACT = frozenset({STICK, SLIP, REVERSE})


def slip_sign(kind: str) -> int:
    """``s`` in ``Q = s f P``: +1 for slip, -1 for reverse slip (0 otherwise)."""
    return {SLIP: 1, REVERSE: -1}.get(kind, 0)


@dataclass(frozen=True)
class Scaling:
    """Map between the paper's dimensionless variables and the internal ones.

    Internal: the coefficients of [13] at ``gamma = 1`` and ``delta_hat = delta/sqrt(gamma)``.
    """

    params: BrakeParams

    @cached_property
    def root_gamma(self) -> float:
        return math.sqrt(self.params.gamma)

    @cached_property
    def coefficients(self):
        """Coefficients of [13] at ``gamma = 1`` (those of ``params`` times ``gamma``)."""
        p = self.params
        return coefficients(p.xi, p.nu, 1.0)

    @property
    def delta(self) -> float:
        """``delta_hat = delta / sqrt(gamma)``: the only way delta and gamma enter."""
        return self.params.delta / self.root_gamma

    def speed(self, c_hat):
        """Wave speed in the paper's units (``theta`` per unit ``t = Omega t̄``)."""
        return np.asarray(c_hat) / self.root_gamma

    def internal_speed(self, c):
        return np.asarray(c) * self.root_gamma


class ZoneFlows:
    """Exact flows of the four zones for one wave speed ``c`` (internal units).

    ``flow(kind, y0, s)`` returns ``y(s)`` for ``s`` (scalar or 1-D array) measured in
    ``phi`` from the start state ``y0`` (``s`` may be negative).
    """

    def __init__(self, coef, friction: float, delta: float, c: float):
        self.a, self.b, self.g, self.h, self.D = coef.a, coef.b, coef.g, coef.h, coef.D
        self.f, self.delta, self.c = float(friction), float(delta), float(c)
        self.ca, self.cb = c * c - self.a, c * c - self.b
        self._sep = None

    # --- forces ---------------------------------------------------------------------
    def stick_pressure(self) -> float:
        """``P = g delta + D/c`` in the stick zone (constant)."""
        return self.g * self.delta + self.D / self.c

    def pressure(self, kind: str, Y) -> np.ndarray:
        """Contact pressure ``P`` for states ``Y`` (last axis ``(U, U', V, V')``)."""
        Y = np.asarray(Y)
        if kind == SEPARATION:
            return np.zeros(Y.shape[:-1])
        return self.g * Y[..., 0] - self.D * Y[..., 3]

    def traction(self, kind: str, Y) -> np.ndarray:
        """Friction traction ``Q`` (``h V + D U'`` in stick, ``s f P`` in slip)."""
        Y = np.asarray(Y)
        if kind == SEPARATION:
            return np.zeros(Y.shape[:-1])
        if kind == STICK:
            return self.h * Y[..., 2] + self.D * Y[..., 1]
        return slip_sign(kind) * self.f * self.pressure(kind, Y)

    def slip_velocity(self, Y) -> np.ndarray:
        """``w = 1 - V_t = 1 + c V'`` (0 in stick)."""
        return 1.0 + self.c * np.asarray(Y)[..., 3]

    def second_derivatives(self, kind: str, Y):
        """``(U'', V'')`` from the zone equations."""
        Y = np.asarray(Y)
        U, dU, V, dV = Y[..., 0], Y[..., 1], Y[..., 2], Y[..., 3]
        if kind == SEPARATION:
            return (self.D * dV - self.g * U) / self.cb, (-self.D * dU - self.h * V) / self.ca
        if kind == STICK:
            return np.zeros_like(U), np.zeros_like(U)
        return np.zeros_like(U), (self.traction(kind, Y) - self.h * V) / self.ca

    def matrix(self, kind: str) -> np.ndarray:
        """``M`` with ``y' = M y`` in the zone (state ``(U, U', V, V')``)."""
        M = np.zeros((4, 4))
        M[2, 3] = 1.0
        if kind == SEPARATION:
            M[0, 1] = 1.0
            M[1, 0], M[1, 3] = -self.g / self.cb, self.D / self.cb
            M[3, 1], M[3, 2] = -self.D / self.ca, -self.h / self.ca
        elif kind in (SLIP, REVERSE):
            fs = slip_sign(kind) * self.f
            M[3, 0], M[3, 2], M[3, 3] = fs * self.g / self.ca, -self.h / self.ca, -fs * self.D / self.ca
        return M

    # --- exact flows ------------------------------------------------------------------
    def flow(self, kind: str, y0, s) -> np.ndarray:
        y0 = np.asarray(y0, dtype=float)
        s = np.asarray(s, dtype=float)
        if kind == STICK:
            out = np.broadcast_to(y0, s.shape + (4,)).copy()
            out[..., 2] = y0[2] + s * y0[3]
            return out
        if kind == SEPARATION:
            return self._flow_separation(y0, s)
        return self._flow_slip(kind, y0, s)

    def _flow_slip(self, kind, y0, s):
        # V - V_s obeys x'' = -(fs D/ca) x' - (h/ca) x, with V_s = fs g U/h.
        fs = slip_sign(kind) * self.f
        Vs = fs * self.g * y0[0] / self.h
        tau = -0.5 * fs * self.D / self.ca  # half the trace
        det = self.h / self.ca
        mu2 = tau * tau - det
        x0, v0 = y0[2] - Vs, y0[3]
        with np.errstate(over="ignore", invalid="ignore"):
            x, v = self._putzer(tau, det, mu2, x0, v0, s)
        out = np.empty(s.shape + (4,))
        out[..., 0], out[..., 1], out[..., 2], out[..., 3] = y0[0], y0[1], x + Vs, v
        return out

    @staticmethod
    def _putzer(tau, det, mu2, x0, v0, s):
        e = np.exp(tau * s)
        if mu2 > 1e-14 * (tau * tau + abs(det)):
            mu = math.sqrt(mu2)
            ch, sh = np.cosh(mu * s), np.sinh(mu * s) / mu
        elif mu2 < -1e-14 * (tau * tau + abs(det)):
            mu = math.sqrt(-mu2)
            ch, sh = np.cos(mu * s), np.sin(mu * s) / mu
        else:  # double root: the limit of the Putzer formula
            ch, sh = np.ones_like(s), s.copy()
        # e^{As} = e^{tau s} [ch I + sh (A - tau I)], A = [[0, 1], [-det, 2 tau]]
        x = e * (ch * x0 + sh * (-tau * x0 + v0))
        v = e * (ch * v0 + sh * (-det * x0 + tau * v0))
        return x, v

    def _separation_modes(self):
        if self._sep is None:
            M = self.matrix(SEPARATION)
            lam, vec = np.linalg.eig(M)
            cond = np.linalg.cond(vec)
            self._sep = (lam, vec, np.linalg.inv(vec)) if cond < 1e8 else (None, M, None)
        return self._sep

    def _flow_separation(self, y0, s):
        lam, vec, inv = self._separation_modes()
        if lam is None:  # ill-conditioned eigenvectors (not expected for c^2 > a)
            M = vec
            return np.einsum("...ij,j->...i", expm(M * s[..., None, None]), y0)
        coef = inv @ y0
        return np.real(np.einsum("ij,...j->...i", vec, np.exp(np.multiply.outer(s, lam)) * coef))

    def max_rate(self, kind: str) -> float:
        """Largest ``|eigenvalue|`` of the zone matrix (sets the event-search step)."""
        if kind == STICK:
            return 0.0
        return float(np.max(np.abs(np.linalg.eigvals(self.matrix(kind)))))

    # --- jump at a landing (impact) ----------------------------------------------------
    def impulses(self, y_left, y_right):
        """``(Pi, Q_Pi)``: normal and tangential impulses across a point (``phi`` order).

        Integrating [15] across a switching point: ``(c^2 - b)[U'] = Pi`` and
        ``(c^2 - a)[V'] = Q_Pi``, where ``P, Q`` carry Dirac masses ``Pi, Q_Pi``.
        """
        return self.cb * (y_right[1] - y_left[1]), self.ca * (y_right[3] - y_left[3])

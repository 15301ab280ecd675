"""Exact free vibrations of the plane-strain annulus clamped at ``r = xi``, free at ``r = 1``.

With the paper's scaling (lengths ``R``, stresses ``E``, time ``1/Omega``) the equation of
motion is ``div sigma = gamma u_tt`` ([10] without contact). Helmholtz potentials
``u = grad phi + curl(psi e_z)`` with ``phi = F(r) cos n theta``, ``psi = G(r) sin n theta``
satisfy ``Delta phi + k_p^2 phi = 0``, ``Delta psi + k_s^2 psi = 0`` for a mode
``e^{i omega t}``, ``k_p^2 = gamma omega^2 / ã``, ``k_s^2 = gamma omega^2 / b̃``
(``ã = (lambda + 2 mu)/E``, ``b̃ = mu/E``), so ``F, G`` are combinations of ``J_n, Y_n``.
The amplitudes (factors ``cos n theta`` for ``u_r, sigma_rr`` and ``sin n theta`` for
``u_theta, sigma_rtheta``) are

    u_r = F' + n G / r,                 u_theta = -n F / r - G',
    sigma_rr = ã F'' + (ã - 2 b̃) (F'/r - n^2 F/r^2) + 2 b̃ n (G'/r - G/r^2),
    sigma_rtheta = b̃ (-2 n F'/r + 2 n F/r^2 - G'' + G'/r - n^2 G/r^2),

with ``F'' = -F'/r - (k_p^2 - n^2/r^2) F`` (Bessel's equation), the same for ``G``.
The boundary conditions ``u_r = u_theta = 0`` at ``r = xi`` and ``sigma_rr = sigma_rtheta = 0``
at ``r = 1`` on the four basis functions ``(J_n, Y_n)(k_p r)``, ``(J_n, Y_n)(k_s r)`` give a
real 4x4 matrix; its determinant vanishes at the natural frequencies. For ``n = 0`` it
factors into the breathing (``phi``) and torsional (``psi``) modes. Frequencies are
returned as ``omega sqrt(gamma)`` (i.e. ``omega̅ R / sqrt(E/rho)``), free of ``Omega``.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq
from scipy.special import jv, jvp, yv, yvp

from ...quantities import BRAKE as Q
from ...errors import ParameterError
from ..reduced.coefficients import elastic_moduli

__all__ = ["characteristic_matrix", "annulus_frequencies"]


def _columns(n, k, r):
    """``(Z, Z', Z'')`` for ``Z = J_n(k r)`` and ``Y_n(k r)`` (2 columns each)."""
    out = []
    for f, fp in ((jv, jvp), (yv, yvp)):
        Z, Zp = f(n, k * r), k * fp(n, k * r)
        Zpp = -Zp / r - (k**2 - n**2 / r**2) * Z
        out.append((Z, Zp, Zpp))
    return out


def characteristic_matrix(w, n: int, xi: float, nu: float) -> np.ndarray:
    """The 4x4 boundary matrix at ``w = omega sqrt(gamma) > 0`` (vectorised: shape ``w.shape + (4, 4)``);
    rows ``u_r(xi), u_theta(xi), sigma_rr(1), sigma_rtheta(1)``, columns ``J_n, Y_n`` of ``phi``
    then of ``psi``; each column scaled by its largest entry (the roots are unchanged)."""
    xi, nu = Q.check("xi", xi), Q.check("nu", nu)
    if isinstance(n, bool) or int(n) != n or n < 0:
        raise ParameterError("n", n, "an integer >= 0")
    w = np.asarray(w, dtype=float)
    if not np.all(np.isfinite(w) & (w > 0)):
        raise ParameterError("w", w, "finite and > 0")
    return _matrix(w, int(n), xi, nu)


def _matrix(w, n, xi, nu):
    at, bt = (float(x) for x in elastic_moduli(nu))
    kp, ks = w / np.sqrt(at), w / np.sqrt(bt)
    M = np.zeros(w.shape + (4, 4))
    for col, (Z, Zp, _) in enumerate(_columns(n, kp, xi)):  # phi = F
        M[..., 0, col], M[..., 1, col] = Zp, -n * Z / xi
    for col, (Z, Zp, _) in enumerate(_columns(n, ks, xi)):  # psi = G
        M[..., 0, 2 + col], M[..., 1, 2 + col] = n * Z / xi, -Zp
    for col, (F, Fp, Fpp) in enumerate(_columns(n, kp, 1.0)):
        M[..., 2, col] = at * Fpp + (at - 2 * bt) * (Fp - n**2 * F)
        M[..., 3, col] = bt * (-2 * n * Fp + 2 * n * F)
    for col, (G, Gp, Gpp) in enumerate(_columns(n, ks, 1.0)):
        M[..., 2, 2 + col] = 2 * bt * n * (Gp - G)
        M[..., 3, 2 + col] = bt * (-Gpp + Gp - n**2 * G)
    return M / np.abs(M).max(axis=-2, keepdims=True)


def _det(w, n, xi, nu):
    return np.linalg.det(_matrix(np.asarray(w, dtype=float), n, xi, nu))


#: The most points of the determinant's scan (a second or so of work each 1e6).
MAX_SCAN = 1e8


def annulus_frequencies(xi: float, nu: float, n: int, count: int = 2, w_max: float | None = None,
                        step: float = 2e-3) -> np.ndarray:
    """The ``count`` lowest natural frequencies ``omega sqrt(gamma)`` of mode ``n`` (exact).

    Parameters
    ----------
    xi, nu : float
        ``R*/R > 1`` and Poisson's ratio in [0, 0.5).
    n : int
        Number of waves around the ring, >= 0.
    count : int
        How many roots (ascending).
    w_max : float, optional
        Search bound; default ``40 + 4 n`` (in units of ``sqrt(E/rho)/R``).
    step : float
        Scan step for sign changes of the determinant, relative to ``sqrt(b̃)``;
        each bracket is then refined by Brent's method to 1e-14.
    """
    xi, nu = Q.check("xi", xi), Q.check("nu", nu)
    n, count = Q.check("n", n), Q.check("count", count)
    step = Q.check("step", step) * np.sqrt(float(elastic_moduli(nu)[1]))
    w_max = 40.0 + 4.0 * n if w_max is None else Q.check("w_max", w_max)
    if w_max / step > MAX_SCAN:
        raise ParameterError("step", step / np.sqrt(float(elastic_moduli(nu)[1])), f">= {w_max / MAX_SCAN:.3g} "
                             f"with w_max = {w_max:g} (a scan of at most {MAX_SCAN:.0e} points)", also=("w_max", "n"))
    roots, lo = [], step
    while lo < w_max and len(roots) < count:  # scan in blocks until enough roots are bracketed
        grid = np.arange(lo, min(lo + 1000 * step, w_max + step), step)
        d = _det(grid, n, xi, nu)
        for k in np.flatnonzero(np.sign(d[:-1]) * np.sign(d[1:]) < 0):
            roots.append(brentq(lambda w: float(_det(w, n, xi, nu)), grid[k], grid[k + 1], xtol=1e-14, rtol=1e-14))
        lo = grid[-1]
    if len(roots) < count:
        raise ParameterError("w_max", w_max, f"large enough to hold {count} roots for n = {n} (found {len(roots)})")
    return np.array(roots[:count])

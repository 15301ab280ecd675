"""Slip waves of an elastic half-space sliding on a rigid plane with Coulomb friction.

Short waves on the contact circle (``n >> 1``, ``n (xi - 1) >> 1``) see a half-space. In
steady sliding the surface is held (``u_y = 0``) and slips with ``sigma_xy = eps f sigma_yy``
(``eps = +-1``, the direction of slip). With ``c_s = 1``, wavenumber ``k = 1`` and
potentials ``phi = A e^{-p y}``, ``psi = B e^{-q y}`` (``e^{i x + s t}``, ``y > 0`` in the body)

    p = sqrt(1 + s^2 / c_p^2),   q = sqrt(1 + s^2),   Re p, Re q > 0,

the two boundary conditions give the dispersion relation

    F(s) = s^2 + i eps f ((s^2 + 2)/p - 2 q) = 0.

At ``s^2 = -2`` (phase speed ``sqrt(2) c_s < c_p``) ``F = 2 (eps f - 1)``, so a root sits on
the edge of the admissible region (``Re q = 0``) at ``f = 1``; for ``f > 1`` it moves into
``Re s > 0``: a surface wave grows at a rate proportional to its wavenumber,
``Re s = rho(f) k c_s``, i.e. steady sliding is **ill-posed** (Hadamard): on a mesh the
fastest growth is at the grid scale and grows like ``1/h``. For ``f <= 1`` there is no such
root and the growth rates of the ring stay bounded in ``n``. (The paper's third case,
``f = 2``, is in the ill-posed range: ``rho = 0.298`` for ``nu = 0.3``.)
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import root

from ...quantities import BRAKE as Q
from ..reduced.coefficients import elastic_moduli

__all__ = ["slip_wave_rate", "dispersion"]


def dispersion(s, friction: float, nu: float, eps: float = 1.0):
    """``F(s)`` of the module docstring, and ``(p, q)`` (principal square roots)."""
    at, bt = (float(x) for x in elastic_moduli(nu))
    s = np.asarray(s, dtype=complex)
    p, q = np.sqrt(1.0 + s * s * bt / at), np.sqrt(1.0 + s * s)
    return s * s + 1j * eps * friction * ((s * s + 2.0) / p - 2.0 * q), p, q


def slip_wave_rate(friction: float, nu: float = 0.3) -> complex:
    """The growing slip wave ``s / (k c_s)`` (largest ``Re s > 0``, ``eps = +1``), or ``nan``.

    Parameters
    ----------
    friction : float
        Coulomb coefficient ``f >= 0``.
    nu : float
        Poisson's ratio in [0, 0.5).

    Returns
    -------
    complex
        ``s`` for ``k = c_s = 1`` (multiply by ``k c_s``); ``nan`` if no admissible root with
        ``Re s > 1e-9`` exists (``f <= 1``). For ``eps = -1`` the root is the conjugate.
    """
    f, nu = Q.check("friction", friction), Q.check("nu", nu)
    found = []
    for re in (0.02, 0.1, 0.3, 0.6, 1.0):
        for im in (1.0, 1.3, 1.42, 1.6, 2.0):
            def g(x):
                val = dispersion(x[0] + 1j * x[1], f, nu)[0]
                return [val.real, val.imag]
            sol = root(g, [re, im], tol=1e-14)
            s = complex(sol.x[0], sol.x[1])
            val, p, q = dispersion(s, f, nu)
            if sol.success and abs(val) < 1e-10 and s.real > 1e-9 and p.real > 0 and q.real > 0:
                found.append(s)
    return max(found, key=lambda z: z.real) if found else complex(np.nan, np.nan)

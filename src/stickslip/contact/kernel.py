"""Compiled kernels of the explicit beta2 scheme with forward-increment multipliers ([22], [23]).

The semi-discrete problem is ``M u'' = -K u + C^T lambda`` with a lumped (diagonal) mass
``M`` and one reaction pair per contact node: ``lambda_n`` on its normal dof and
``lambda_t`` on its tangential dof. With ``A_m = -M^{-1} K u_m`` (the model's operator),
one step is (Carpenter, Taylor & Katona 1991; the paper's [22], [23]):

    predictor:  v*_m = v_{m-1} + dt ((1 - beta2) a_{m-1} + beta2 A_m),
                u*_{m+1} = u_m + dt v*_m + dt^2/2 A_m,
    contact:    r_n = max(0, (g_j - u*_n) / (c dt^2)),                  c = beta2 + 1/2,
                r* = (u_t,m + dt s_j - u*_t) / (c dt^2),
                r_t = r* if |r*| <= f_s r_n (stick), else sign(r*) f r_n (slip),
    corrector:  u_{m+1} = u* + c dt^2 r,   a_m = A_m + r,   v_m = v*_m + beta2 dt r,

``r = M^{-1} lambda`` (reactions per unit mass), ``g_j`` the position of the rigid surface
along the normal of node ``j`` (``u_n >= g_j``) and ``s_j`` its tangential speed. Because
``u_{m+1}`` depends on ``r_m`` through ``c dt^2`` exactly (``c dt^2 = dt^2/2`` from
``u*`` plus ``beta2 dt^2`` from ``v*``), the normal multiplier makes ``u_n = g_j`` where it is
positive, and the tangential one makes a sticking node move with the surface; clipping
it to ``[-f r_n, f r_n]`` solves the discrete Coulomb law, the slip velocity being affine
and increasing in ``r_t``. With a static coefficient ``f_s > f`` a node sticks while the
reaction that holds it to the surface, ``r*``, stays within ``f_s r_n`` (the 1-DOF
oscillator's stick condition, node by node), and slips with the kinetic ``f r_n`` otherwise;
``f_s = f`` is plain Coulomb (the same numbers as the clipping). A kinetic coefficient that
depends on the slip speed (`kinetic_coefficient`: linear weakening, Stribeck) is taken at the
slip speed of the step itself, ``|v_r| = c dt (|r*| - mu(|v_r|) r_n)`` (the slip of ``u_t``
over the step against the surface's, per ``dt``), solved node by node: in closed form for
linear weakening, by Newton's method for Stribeck (convex in ``|v_r|``: one root, reached
monotonically from the Coulomb one), still with no iteration between nodes. The mass is diagonal and
each multiplier acts on one dof, so this is exact node by node, with no iteration
(``docs/theory/contact.md``). A constant external load per unit mass ``b`` (pressure on a
boundary) is added to ``A_m``.

`explicit_step` does the predictor, the multipliers and the corrector once ``A_m`` is
known. `advance` is the compiled loop: it computes ``A_m`` from one of two forms of the
operator ``M^{-1} K`` and calls `explicit_step`:

* a sparse matrix, the general path for any mesh: in 2 x 2 blocks (`block2_apply`: the two
  dofs of a node against those of another, one column index per four entries) where the
  operator has that structure, as every 2-D mesh with whole nodes kept does, else in CSR
  (`csr_apply`): any operator;
* a stencil (`stencil_apply`): a block-circulant operator on ``n_r`` closed rings of ``n_theta``
  nodes with two dofs each (``2 (i n_theta + j) + c``, couplings to the 3 x 3 neighbouring
  nodes, the same for every ``j``), read from ``n_r x 36`` numbers instead of ``nnz``:
  the FE annulus (``n_r`` layers) and the reduced model on the ring (``n_r = 1``).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .states import SEPARATION, SLIP_NEG, SLIP_POS
from ..kernelcopy import copy

__all__ = ["internal", "explicit_step", "kinetic_coefficient", "COULOMB", "LINEAR_WEAKENING", "STRIBECK", "predictor", "csr_apply", "block2_apply", "stencil_apply", "advance", "multiplier_factor"]


@njit(cache=True)
def multiplier_factor(beta2, dt):
    """``(beta2 + 1/2) dt^2``: how much a reaction per unit mass moves ``u_{m+1}`` ([23], erratum B5)."""
    return (beta2 + 0.5) * dt * dt


@njit(cache=True)
def predictor(u, v, a, A, dt, beta2):
    """Explicit Newmark predictor in place: ``v <- v*_m``, ``u <- u*_{m+1}``, ``a <- A_m``."""
    for k in range(u.shape[0]):
        vs = v[k] + dt * ((1.0 - beta2) * a[k] + beta2 * A[k])
        v[k] = vs
        u[k] += dt * vs + 0.5 * dt * dt * A[k]
        a[k] = A[k]


#: Kinds of kinetic friction of `explicit_step` (``law[0]``): constant ``f`` (Coulomb), linear
#: weakening ``f (1 - tau |v_r|)`` (``law[1] = tau`` [s/m], floored at 0), Stribeck ``f + (f_s -
#: f) exp(-|v_r| / v_s)`` (``law[1] = v_s`` [m/s]).
COULOMB, LINEAR_WEAKENING, STRIBECK = 0, 1, 2


@njit(cache=True)
def kinetic_coefficient(kind, par, f, fs, excess, p, cdt):
    """The kinetic coefficient ``mu`` of a slipping node at its slip speed of the step.

    ``excess = |r*|`` exceeds ``fs p``; the slip speed is ``x = cdt (excess - mu(x) p)``
    (``cdt = (beta2 + 1/2) dt``), ``mu`` of ``kind`` (`COULOMB`, `LINEAR_WEAKENING`,
    `STRIBECK`) with parameter ``par``. Linear weakening: ``x`` in closed form while ``mu > 0``
    (a step so long that ``cdt p f tau >= 1`` has no root there: ``mu = 0``). Stribeck: Newton on
    the convex ``h(x) = x - cdt (excess - mu(x) p)`` from the Coulomb root, where ``h >= 0``."""
    if kind == LINEAR_WEAKENING:
        slope = 1.0 - cdt * p * f * par
        if slope <= 0.0:
            return 0.0
        x = cdt * (excess - f * p) / slope
        return max(f * (1.0 - par * x), 0.0)
    if kind == STRIBECK:
        x = cdt * (excess - f * p)
        for _ in range(60):
            e = np.exp(-x / par)
            h = x - cdt * (excess - (f + (fs - f) * e) * p)
            dh = 1.0 - cdt * p * (fs - f) / par * e
            step = h / dh
            x -= step
            if not step > 1e-15 * x:  # monotone from the right: done when the step stops shrinking x
                break
        return f + (fs - f) * np.exp(-x / par)
    return f


@njit(cache=True)
def explicit_step(u, v, a, A, normal, tangent, gap0, speed, dt, beta2, f, fs, contact, lam_n, lam_t, state, ut_old,
                  law):
    """One step of the scheme in place, given ``A = -M^{-1} K u_m``.

    ``u, v, a`` hold ``u_m, v_{m-1}, a_{m-1}`` on entry and ``u_{m+1}, v_m, a_m`` on exit.
    Contact node ``j`` has its normal dof ``normal[j]`` and tangential dof ``tangent[j]``,
    the rigid surface at ``gap0[j]`` along the normal and moving at ``speed[j]``; ``f`` and
    ``fs >= f`` are the kinetic and static friction coefficients, the kinetic one of kind
    ``law[0]`` with parameter ``law[1]`` (`kinetic_coefficient`; ``(COULOMB, 0)``: constant);
    ``law[2] = n`` (0: none) makes both depend on the pressure, times ``(P / P_ref)^(-n)`` with
    ``P / P_ref = p law[3 + j]`` at node ``j`` (``p`` its normal reaction per unit mass); a
    ``law`` of two entries (as before the pressure dependence) has none.
    ``lam_n, lam_t, state`` receive the reactions per unit mass and the node states;
    ``ut_old`` is scratch of the size of ``normal``. ``contact=False``: no reactions.
    """
    nc = normal.shape[0]
    for j in range(nc):
        ut_old[j] = u[tangent[j]]
    predictor(u, v, a, A, dt, beta2)
    cdt2 = multiplier_factor(beta2, dt)
    on = 1.0 if contact else 0.0
    kind = int(law[0])
    expo = law[2] if law.shape[0] > 2 else 0.0  # a law of two entries (kind, parameter): no pressure dependence
    if expo != 0.0 and law.shape[0] < 3 + nc:
        raise ValueError("law: [kind, parameter, exponent] and one pressure scale per contact node")
    for j in range(nc):  # branch-free for Coulomb, so that the loop vectorises
        r, t = normal[j], tangent[j]
        p = on * max((gap0[j] - u[r]) / cdt2, 0.0)
        trial = (ut_old[j] + dt * speed[j] - u[t]) / cdt2
        g = 1.0  # a coefficient that depends on the pressure: (P / P_ref)^(-n), P = p law[3 + j]
        if expo != 0.0 and p > 0.0:
            g = (p * law[3 + j]) ** (-expo)
        held = fs * g * p
        stick = abs(trial) <= held
        mu = f * g
        if kind != COULOMB and not stick:
            mu = kinetic_coefficient(kind, law[1], f * g, fs * g, abs(trial), p, cdt2 / dt)
        lim = mu * p
        q = stick * trial + (1 - stick) * min(max(trial, -lim), lim)
        touch = p > 0.0
        state[j] = SEPARATION * (1 - touch) + touch * (SLIP_POS * (trial > held) + SLIP_NEG * (trial < -held))
        lam_n[j], lam_t[j] = p, q
        a[r] += p
        a[t] += q
        v[r] += beta2 * dt * p
        v[t] += beta2 * dt * q
        u[r] = gap0[j] if touch else u[r]
        u[t] += cdt2 * q


@njit(cache=True)
def csr_apply(indptr, indices, data, u, out):
    """``out = -A u`` for a CSR matrix ``A`` (``(indptr, indices, data)``, e.g. ``M^{-1} K``)."""
    for i in range(out.shape[0]):
        acc = 0.0
        for k in range(indptr[i], indptr[i + 1]):
            acc += data[k] * u[indices[k]]
        out[i] = -acc


@njit(cache=True)
def block2_apply(indptr, indices, data, u, out):
    """``out = -A u`` for ``A`` in 2 x 2 blocks (block sparse rows): block row ``I`` couples dofs
    ``2I, 2I + 1`` with ``2J, 2J + 1``, ``J = indices[k]`` for ``k`` in ``indptr[I]:indptr[I + 1]``,
    through ``data[4k:4k + 4]`` (row-major). The same product as `csr_apply` with a quarter of
    the column indices to read."""
    for i in range(indptr.shape[0] - 1):
        a0 = 0.0
        a1 = 0.0
        for k in range(indptr[i], indptr[i + 1]):
            j = 2 * indices[k]
            x0, x1 = u[j], u[j + 1]
            b = 4 * k
            a0 += data[b] * x0 + data[b + 1] * x1
            a1 += data[b + 2] * x0 + data[b + 3] * x1
        out[2 * i] = -a0
        out[2 * i + 1] = -a1


@njit(cache=True)
def _single_ring(C, u, out):
    """`stencil_apply` for one ring of nodes (``n_r = 1``): one pass, branch-free inside."""
    N = out.shape[0] // 2
    m00, m01, m10, m11 = C[0, 1, 0, 0, 0], C[0, 1, 0, 0, 1], C[0, 1, 0, 1, 0], C[0, 1, 0, 1, 1]
    c00, c01, c10, c11 = C[0, 1, 1, 0, 0], C[0, 1, 1, 0, 1], C[0, 1, 1, 1, 0], C[0, 1, 1, 1, 1]
    p00, p01, p10, p11 = C[0, 1, 2, 0, 0], C[0, 1, 2, 0, 1], C[0, 1, 2, 1, 0], C[0, 1, 2, 1, 1]
    for k in range(2, 2 * N - 2, 2):
        um, vm, uc, vc, up, vp = u[k - 2], u[k - 1], u[k], u[k + 1], u[k + 2], u[k + 3]
        out[k] = -(m00 * um + m01 * vm + c00 * uc + c01 * vc + p00 * up + p01 * vp)
        out[k + 1] = -(m10 * um + m11 * vm + c10 * uc + c11 * vc + p10 * up + p11 * vp)
    for j in (0, N - 1):  # periodic wrap
        jm = j - 1 if j > 0 else N - 1
        jp = j + 1 if j < N - 1 else 0
        um, vm, uc, vc, up, vp = u[2 * jm], u[2 * jm + 1], u[2 * j], u[2 * j + 1], u[2 * jp], u[2 * jp + 1]
        out[2 * j] = -(m00 * um + m01 * vm + c00 * uc + c01 * vc + p00 * up + p01 * vp)
        out[2 * j + 1] = -(m10 * um + m11 * vm + c10 * uc + c11 * vc + p10 * up + p11 * vp)


@njit(cache=True)
def stencil_apply(C, u, out):
    """``out = -A u`` for the block-circulant ``A`` of stencil ``C[i, di + 1, dj + 1, c, c']``:
    the coupling of dof ``c`` of node ``(i, j)`` with dof ``c'`` of node ``(i + di, (j + dj) mod
    n_theta)``; layers ``i + di`` outside ``[0, n_r)`` are fixed (zero).

    The two dofs of each node are read apart first, one row per layer and dof with the periodic
    neighbours copied to its ends, so that the inner loops run over consecutive numbers (about
    three times faster than over the interleaved vector, benchmarks/brake_fem.py); the sums are
    the same, in the same order, to the bit."""
    n_r = C.shape[0]
    if n_r == 1:
        _single_ring(C, u, out)
        return
    N = out.shape[0] // (2 * n_r)
    ur = np.empty((n_r, N + 2))
    ut = np.empty((n_r, N + 2))
    for i in range(n_r):
        base = 2 * i * N
        for j in range(N):
            ur[i, j + 1] = u[base + 2 * j]
            ut[i, j + 1] = u[base + 2 * j + 1]
        ur[i, 0], ut[i, 0] = ur[i, N], ut[i, N]  # periodic neighbours
        ur[i, N + 1], ut[i, N + 1] = ur[i, 1], ut[i, 1]
    s0 = np.empty(N)
    s1 = np.empty(N)
    for i in range(n_r):
        s0[:] = 0.0
        s1[:] = 0.0
        for di in range(-1, 2):
            i2 = i + di
            if i2 < 0 or i2 >= n_r:
                continue
            for dj in range(-1, 2):
                c00, c01 = C[i, di + 1, dj + 1, 0, 0], C[i, di + 1, dj + 1, 0, 1]
                c10, c11 = C[i, di + 1, dj + 1, 1, 0], C[i, di + 1, dj + 1, 1, 1]
                for j in range(N):
                    x, y = ur[i2, j + 1 + dj], ut[i2, j + 1 + dj]
                    s0[j] += c00 * x + c01 * y
                    s1[j] += c10 * x + c11 * y
        base = 2 * i * N
        for j in range(N):  # 0 - s, as the interleaved loop's subtractions from 0 (-0.0 and NaN's sign too)
            out[base + 2 * j] = 0.0 - s0[j]
            out[base + 2 * j + 1] = 0.0 - s1[j]


@njit(cache=True)
def internal(C, indptr, indices, data, block, load, damping, u, v, w, A):
    """``A = A_m``: ``-(M^{-1} K)(u_m + beta v_{m-1}) - alpha v_{m-1} + load`` (``load`` empty: none;
    Rayleigh ``damping = (alpha, beta)``), ``M^{-1} K`` as `advance` reads it; ``w`` is scratch."""
    alpha, beta = damping[0], damping[1]
    damped = alpha != 0.0 or beta != 0.0
    x = u
    if damped:
        for k in range(u.shape[0]):
            w[k] = u[k] + beta * v[k]
        x = w
    if C.shape[0] > 0:
        stencil_apply(C, x, A)
    elif block == 2:
        block2_apply(indptr, indices, data, x, A)
    else:
        csr_apply(indptr, indices, data, x, A)
    if damped:
        for k in range(u.shape[0]):
            A[k] -= alpha * v[k]
    if load.shape[0] > 0:
        A += load


@njit(cache=True)
def advance(C, indptr, indices, data, block, load, damping, u, v, a, normal, tangent, gap0, speed, nsteps, dt, beta2, f, fs,
            contact, lam_n, lam_t, state, work, law):
    """``nsteps`` steps of the scheme in place, ``A_m = -(M^{-1} K) u_m + load`` (``load`` empty: none),
    with Rayleigh ``damping = (alpha, beta)`` on ``v_{m-1}`` if not both zero.

    ``M^{-1} K`` is the stencil ``C`` (`stencil_apply`) if ``C`` is not empty, else the sparse
    matrix ``(indptr, indices, data)``: in 2 x 2 blocks if ``block == 2`` (`block2_apply`), in CSR
    if ``block == 1`` (`csr_apply`). ``work`` receives ``u_m`` of the last
    step; the other arguments (``law``: the kind of kinetic friction) are those of `explicit_step`.
    """
    A = np.empty(u.shape[0])
    ut_old = np.empty(normal.shape[0])
    w = np.empty(u.shape[0])
    for step in range(nsteps):
        internal(C, indptr, indices, data, block, load, damping, u, v, w, A)
        if step == nsteps - 1:
            copy(work, u)
        explicit_step(u, v, a, A, normal, tangent, gap0, speed, dt, beta2, f, fs, contact, lam_n, lam_t, state, ut_old,
                      law)

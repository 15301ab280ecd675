"""The explicit scheme's forward-increment multipliers between two deformable bodies.

`kernel.explicit_step` solves each contact node's multipliers in closed form because the
mass is diagonal and each multiplier moves one dof. Between two bodies a contact force at
slave node ``j`` acts on the slave node and, with the opposite sign, on the master nodes
``l`` facing it, spread by weights ``w_jl`` (the mortar's ``M_jl / D_jj``: Carpenter, Taylor
and Katona 1991 treat a pair of bodies the same way). With the slave node's dofs in its
frame ``(n_j, t_j)`` and the master's Cartesian, the relative displacement at ``j`` is

    d_n = u_n,j - sum_l w_jl n_j . u_l,     d_t = u_t,j - sum_l w_jl t_j . u_l,

and a force ``F_j = (F_n, F_t)`` moves it by ``c dt^2 W_j F_j`` (``c = beta2 + 1/2``), with
``W_j = 1/m_j + sum_l w_jl^2 / m_l`` (isotropic lumped masses: no coupling of ``n`` and ``t``
at one node); forces at nodes that share a master node move each other's ``d``. The
conditions are those of `kernel.explicit_step` on ``d`` instead of ``u``: ``d_n >= gap0``
(Signorini), and the tangential multiplier that makes the slave move with the master's
material (its deformation plus the master's own motion at ``speed`` along ``t_j``), kept
within ``f_s F_n`` to stick, else slipping at ``mu F_n`` (``mu`` at the slip speed of the step,
`kernel.kinetic_coefficient`). They are solved by projected Gauss-Seidel over the contact
nodes (node by node in closed form, then again with the neighbours' new forces) until no
force changes by more than ``1e-12`` of the largest; a master that does not move (infinite
mass, ``inv_mass = 0``) makes the first sweep exact, the rigid-surface kernel's numbers.

Forces are stored per unit mass of the slave node (``lam = F / m_j``), as the rigid-surface
kernel's reactions are.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .kernel import COULOMB, csr_apply, internal, kinetic_coefficient, multiplier_factor, predictor
from .states import SEPARATION, SLIP_NEG, SLIP_POS, STICK
from ..kernelcopy import copy

__all__ = ["relative", "coupled_contact", "coupled_advance"]


@njit(cache=True)
def relative(u, j, normal, tangent, nvec, tvec, mptr, mdof, mw):
    """``(d_n, d_t)`` of contact node ``j`` (see the module docstring)."""
    dn, dt_ = u[normal[j]], u[tangent[j]]
    for k in range(mptr[j], mptr[j + 1]):
        i = mdof[k]
        if i < 0:
            continue
        ux, uy = u[i], u[i + 1]
        dn -= mw[k] * (nvec[j, 0] * ux + nvec[j, 1] * uy)
        dt_ -= mw[k] * (tvec[j, 0] * ux + tvec[j, 1] * uy)
    return dn, dt_


@njit(cache=True)
def _push(u, j, fn, ft, scale, normal, tangent, nvec, tvec, mptr, mdof, mw, inv_mass):
    """Move the dofs by a force ``(fn, ft)`` at node ``j`` times ``scale`` (``c dt^2``)."""
    u[normal[j]] += scale * fn * inv_mass[normal[j]]
    u[tangent[j]] += scale * ft * inv_mass[tangent[j]]
    fx = fn * nvec[j, 0] + ft * tvec[j, 0]
    fy = fn * nvec[j, 1] + ft * tvec[j, 1]
    for k in range(mptr[j], mptr[j + 1]):
        i = mdof[k]
        if i < 0:
            continue
        u[i] -= scale * mw[k] * fx * inv_mass[i]
        u[i + 1] -= scale * mw[k] * fy * inv_mass[i + 1]


@njit(cache=True)
def coupled_contact(u, d_old, normal, tangent, nvec, tvec, mptr, mdof, mw, inv_mass, gap0, speed, dt, beta2, f, fs,
                    law, contact, force_n, force_t, state, max_sweeps):
    """The contact forces of one step in place: ``u`` holds the predictor ``u*_{m+1}`` on entry
    and ``u_{m+1}`` on exit, ``d_old`` the tangential ``d_t`` of every node at ``u_m``;
    ``force_n, force_t`` receive the forces, ``state`` the node states. Returns the sweeps taken
    (``max_sweeps + 1``: not converged in ``max_sweeps``)."""
    nc = normal.shape[0]
    cdt2 = multiplier_factor(beta2, dt)
    kind = int(law[0])
    expo = law[2] if law.shape[0] > 2 else 0.0  # a law of two entries (kind, parameter): no pressure dependence
    if expo != 0.0 and law.shape[0] < 3 + nc:
        raise ValueError("law: [kind, parameter, exponent] and one pressure scale per contact node")
    for j in range(nc):
        force_n[j] = 0.0
        force_t[j] = 0.0
        state[j] = SEPARATION
    if not contact:
        return 0
    W = np.empty(nc)
    for j in range(nc):
        w = inv_mass[normal[j]]
        for k in range(mptr[j], mptr[j + 1]):
            if mdof[k] >= 0:
                w += mw[k] * mw[k] * inv_mass[mdof[k]]
        W[j] = w
    sweeps = 0
    for sweep in range(max_sweeps):
        sweeps = sweep + 1
        change, largest = 0.0, 0.0
        for j in range(nc):
            dn, dt_ = relative(u, j, normal, tangent, nvec, tvec, mptr, mdof, mw)
            g = cdt2 * W[j]
            dn -= g * force_n[j]  # without this node's own force
            dt_ -= g * force_t[j]
            p = max((gap0[j] - dn) / g, 0.0)
            trial = (d_old[j] + dt * speed[j] - dt_) / g
            scale = 1.0  # a coefficient that depends on the pressure: (P / P_ref)^(-n), P = p law[3 + j]
            if expo != 0.0 and p > 0.0:
                scale = (p * law[3 + j]) ** (-expo)
            held = fs * scale * p
            stick = abs(trial) <= held
            q = trial
            if not stick:
                mu = f * scale
                if kind != COULOMB:
                    mu = kinetic_coefficient(kind, law[1], f * scale, fs * scale, abs(trial), p, g / dt)
                q = min(max(trial, -mu * p), mu * p)
            touch = p > 0.0
            state[j] = SEPARATION if not touch else (STICK if stick else (SLIP_POS if trial > 0 else SLIP_NEG))
            dfn, dft = p - force_n[j], q - force_t[j]
            if dfn != 0.0 or dft != 0.0:
                _push(u, j, dfn, dft, cdt2, normal, tangent, nvec, tvec, mptr, mdof, mw, inv_mass)
            change = max(change, abs(dfn), abs(dft))
            largest = max(largest, p, abs(q))
            force_n[j], force_t[j] = p, q
        if change <= 1e-12 * largest:
            return sweeps
    return max_sweeps + 1


@njit(cache=True)
def coupled_advance(indptr, indices, data, block, load, damping, gyro_ptr, gyro_idx, gyro_data, u, v, a, normal, tangent,
                    nvec, tvec, mptr, mdof, mw, inv_mass, gap0, speed, nsteps, dt, beta2, f, fs, law, contact, lam_n,
                    lam_t, state, work, max_sweeps):
    """``nsteps`` steps of the scheme for two bodies in contact, in place (the operator, load
    and damping as in `kernel.advance`, the sparse paths only); ``lam_n, lam_t`` receive the
    forces per unit mass of the slave node. A velocity operator ``M^{-1} G`` in CSR
    ``(gyro_ptr, gyro_idx, gyro_data)`` (a turning partner's gyroscopic matrix; ``gyro_ptr`` of
    length 1: none) acts on ``v_{m-1}`` as the damping does: ``A_m -= M^{-1} G v_{m-1}``. Returns
    the most sweeps any step took (at once when a step does not converge: ``max_sweeps + 1``)."""
    n = u.shape[0]
    nc = normal.shape[0]
    A = np.empty(n)
    ustar = np.empty(n)
    w = np.empty(n)
    d_old = np.empty(nc)
    spin = np.empty(n)
    turning = gyro_ptr.shape[0] > 1
    no_stencil = np.zeros((0, 3, 3, 2, 2))
    cdt2 = multiplier_factor(beta2, dt)
    most = 0
    for step in range(nsteps):
        internal(no_stencil, indptr, indices, data, block, load, damping, u, v, w, A)
        if turning:
            csr_apply(gyro_ptr, gyro_idx, gyro_data, v, spin)  # -M^{-1} G v_{m-1}
            A += spin
        if step == nsteps - 1:
            copy(work, u)
        for j in range(nc):
            d_old[j] = relative(u, j, normal, tangent, nvec, tvec, mptr, mdof, mw)[1]
        predictor(u, v, a, A, dt, beta2)
        copy(ustar, u)
        sweeps = coupled_contact(u, d_old, normal, tangent, nvec, tvec, mptr, mdof, mw, inv_mass, gap0, speed, dt,
                                 beta2, f, fs, law, contact, lam_n, lam_t, state, max_sweeps)
        most = max(most, sweeps)
        if sweeps > max_sweeps:
            return most
        for k in range(n):
            r = (u[k] - ustar[k]) / cdt2
            a[k] += r
            v[k] += beta2 * dt * r
        for j in range(nc):
            m = inv_mass[normal[j]]
            lam_n[j] *= m
            lam_t[j] *= m
    return most

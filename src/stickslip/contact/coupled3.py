"""The forward-increment multipliers between two deformable *solids*: a Coulomb disc per node.

As `stickslip.contact.coupled` between two plane bodies, with a third dof per node. At slave
node ``j`` the frame is ``(n_j, t_j, b_j)``: the normal, the master's sliding direction there
and ``b_j = n_j x t_j`` across it; the slave node's dofs are in that frame, the master's
Cartesian ``(x, y, z)``, and the relative displacement is

    d_k = u_k,j - sum_l w_jl k_j . u_l,      k = n, t, b.

Signorini on ``d_n >= gap0`` as in the plane. The friction force is a vector in the tangent
plane: the trial force that makes the slave move with the master's material over the step,

    q* = (d_t,old + dt speed - d_t, d_b,old - d_b) / (c dt^2 W_j),

sticks while ``|q*| <= f_s P``; otherwise the node slips with ``q = mu P q* / |q*|``, the force
on the disc of radius ``mu P`` in the direction of ``q*`` (which is the direction of the slip of
the step: the slip velocity is ``c dt W_j (q* - q)``, parallel to ``q*``), ``mu`` at the slip
speed ``|v_r|`` of the step (`stickslip.contact.kernel.kinetic_coefficient` with ``|q*|``).
Solved node by node in closed form inside the projected Gauss-Seidel sweeps of the plane
kernel. A node slipping with ``q*`` along ``+t`` is ``slip`` (the slave lags the master), along
``-t`` ``reverse_slip``; a slip across the sliding direction counts by its ``t`` component's sign.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .kernel import COULOMB, csr_apply, internal, kinetic_coefficient, multiplier_factor, predictor
from .states import SEPARATION, SLIP_NEG, SLIP_POS, STICK
from ..kernelcopy import copy

__all__ = ["relative3", "coupled_contact3", "coupled_advance3"]


@njit(cache=True)
def relative3(u, j, dofs, frame, mptr, mdof, mw):
    """``(d_n, d_t, d_b)`` of contact node ``j``: ``dofs[j]`` its three dofs (n, t, b), ``frame[j]`` the
    3 x 3 rows ``n, t, b``, ``mdof[k]`` the x, y, z dofs of the master node of entry ``k`` (-1: held;
    see the module docstring)."""
    dn, dt_, db = u[dofs[j, 0]], u[dofs[j, 1]], u[dofs[j, 2]]
    for k in range(mptr[j], mptr[j + 1]):
        for x in range(3):
            i = mdof[k, x]
            if i < 0:
                continue
            dn -= mw[k] * frame[j, 0, x] * u[i]
            dt_ -= mw[k] * frame[j, 1, x] * u[i]
            db -= mw[k] * frame[j, 2, x] * u[i]
    return dn, dt_, db


@njit(cache=True)
def _push3(u, j, force, scale, dofs, frame, mptr, mdof, mw, inv_mass):
    """Move the dofs by the force ``force = (f_n, f_t, f_b)`` at node ``j`` times ``scale`` (``c dt^2``)."""
    for c in range(3):
        u[dofs[j, c]] += scale * force[c] * inv_mass[dofs[j, c]]
    for k in range(mptr[j], mptr[j + 1]):
        for x in range(3):
            i = mdof[k, x]
            if i < 0:
                continue
            fx = force[0] * frame[j, 0, x] + force[1] * frame[j, 1, x] + force[2] * frame[j, 2, x]
            u[i] -= scale * mw[k] * fx * inv_mass[i]


@njit(cache=True)
def coupled_contact3(u, d_old, dofs, frame, mptr, mdof, mw, inv_mass, gap0, speed, dt, beta2, f, fs, law, contact,
                     forces, state, max_sweeps):
    """The contact forces of one step in place: ``u`` holds the predictor on entry and ``u_{m+1}`` on
    exit, ``d_old[j]`` the tangential ``(d_t, d_b)`` of node ``j`` at ``u_m``; ``forces[j]`` receives
    ``(F_n, F_t, F_b)``, ``state`` the node states. Returns the sweeps taken (``max_sweeps + 1``: not
    converged)."""
    nc = dofs.shape[0]
    cdt2 = multiplier_factor(beta2, dt)
    kind = int(law[0])
    expo = law[2] if law.shape[0] > 2 else 0.0
    if expo != 0.0 and law.shape[0] < 3 + nc:
        raise ValueError("law: [kind, parameter, exponent] and one pressure scale per contact node")
    for j in range(nc):
        forces[j, 0] = 0.0
        forces[j, 1] = 0.0
        forces[j, 2] = 0.0
        state[j] = SEPARATION
    if not contact:
        return 0
    W = np.empty(nc)
    for j in range(nc):
        w = inv_mass[dofs[j, 0]]
        for k in range(mptr[j], mptr[j + 1]):
            for x in range(3):  # a node's lumped mass is the same along x, y, z: a held axis counts as rigid
                if mdof[k, x] >= 0:
                    w += mw[k] * mw[k] * inv_mass[mdof[k, x]] / 3.0
        W[j] = w
    change_vec = np.empty(3)
    sweeps = 0
    for sweep in range(max_sweeps):
        sweeps = sweep + 1
        change, largest = 0.0, 0.0
        for j in range(nc):
            dn, d1, d2 = relative3(u, j, dofs, frame, mptr, mdof, mw)
            g = cdt2 * W[j]
            dn -= g * forces[j, 0]  # without this node's own force
            d1 -= g * forces[j, 1]
            d2 -= g * forces[j, 2]
            p = max((gap0[j] - dn) / g, 0.0)
            q1 = (d_old[j, 0] + dt * speed[j] - d1) / g
            q2 = (d_old[j, 1] - d2) / g
            size = np.sqrt(q1 * q1 + q2 * q2)
            scale = 1.0  # a coefficient that depends on the pressure: (P / P_ref)^(-n), P = p law[3 + j]
            if expo != 0.0 and p > 0.0:
                scale = (p * law[3 + j]) ** (-expo)
            stick = size <= fs * scale * p
            if not stick:
                mu = f * scale
                if kind != COULOMB:
                    mu = kinetic_coefficient(kind, law[1], f * scale, fs * scale, size, p, g / dt)
                shrink = mu * p / size  # onto the disc of radius mu p, along q*
                q1 *= shrink
                q2 *= shrink
            state[j] = SEPARATION if not p > 0.0 else (STICK if stick else (SLIP_POS if q1 > 0 else SLIP_NEG))
            change_vec[0], change_vec[1], change_vec[2] = p - forces[j, 0], q1 - forces[j, 1], q2 - forces[j, 2]
            if change_vec[0] != 0.0 or change_vec[1] != 0.0 or change_vec[2] != 0.0:
                _push3(u, j, change_vec, cdt2, dofs, frame, mptr, mdof, mw, inv_mass)
            change = max(change, abs(change_vec[0]), abs(change_vec[1]), abs(change_vec[2]))
            largest = max(largest, p, np.sqrt(q1 * q1 + q2 * q2))
            forces[j, 0], forces[j, 1], forces[j, 2] = p, q1, q2
        if change <= 1e-12 * largest:
            return sweeps
    return max_sweeps + 1


@njit(cache=True)
def coupled_advance3(indptr, indices, data, block, load, damping, gyro_ptr, gyro_idx, gyro_data, u, v, a, dofs, frame,
                     mptr, mdof, mw, inv_mass, gap0, speed, nsteps, dt, beta2, f, fs, law, contact, lam, state, work,
                     max_sweeps):
    """``nsteps`` steps of the scheme for two solids in contact, in place, as
    `stickslip.contact.coupled.coupled_advance` for plane bodies; ``lam[j]`` receives the forces
    ``(n, t, b)`` per unit mass of slave node ``j``. Returns the most sweeps any step took."""
    n = u.shape[0]
    nc = dofs.shape[0]
    A = np.empty(n)
    ustar = np.empty(n)
    w = np.empty(n)
    d_old = np.empty((nc, 2))
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
            _, d1, d2 = relative3(u, j, dofs, frame, mptr, mdof, mw)
            d_old[j, 0], d_old[j, 1] = d1, d2
        predictor(u, v, a, A, dt, beta2)
        copy(ustar, u)
        sweeps = coupled_contact3(u, d_old, dofs, frame, mptr, mdof, mw, inv_mass, gap0, speed, dt, beta2, f, fs, law,
                                  contact, lam, state, max_sweeps)
        most = max(most, sweeps)
        if sweeps > max_sweeps:
            return most
        for k in range(n):
            r = (u[k] - ustar[k]) / cdt2
            a[k] += r
            v[k] += beta2 * dt * r
        for j in range(nc):
            m = inv_mass[dofs[j, 0]]
            for c in range(3):
                lam[j, c] *= m
    return most

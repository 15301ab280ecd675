"""The spring-slider's equations and their Jacobian as kernels numba compiles (`stickslip.jit`).

The same equations as `stickslip.rsf.SpringSlider.rhs` (whose complex-step Jacobian is the
reference), written with scalars so that a compiled integrator's calls cost microseconds, not the
tens of microseconds of numpy's small arrays: ``y = (ln V, psi_1[, psi_2], tau, slip)`` and the
parameters packed by `pack` into one array,

    a, f0, ln V_0, stiffness, normal stress, mass, load velocity, evolution (0 aging, 1 slip,
    2 prz), regularised (0 or 1), states (1 or 2), b_1, b_2, D_c1, D_c2.

`friction` and `state_rate` are one node's law, written for the slider's equations (the interface
runs of `stickslip.sbim` take the law vectorised over their nodes, `stickslip.sbim.ratestate`). The Jacobian is written out by hand (the derivation in the comments); the tests hold
it to the complex-step one of `SpringSlider.rhs`.
"""

from __future__ import annotations

import math

import numpy as np

from ..jit import KernelSet

__all__ = ["pack", "friction", "state_rate", "rhs", "jacobian", "KERNELS", "EVOLUTIONS", "LARGE_LOG"]

#: The evolution laws' codes in the packed parameters.
EVOLUTIONS = ("aging", "slip", "prz")
#: Above it ``asinh(exp(z))`` is ``z + ln 2`` to round-off (and ``exp(z)`` could overflow); here and in
#: `stickslip.rsf.RateState.friction`.
LARGE_LOG = 30.0

A, F0, LOG_VREF, K, SIGMA, MASS, VLOAD, EVOLUTION, REGULARIZED, STATES, B, DC = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12
SIZE = 14


def pack(slider, v_load: float) -> np.ndarray:
    """The parameters of ``slider`` (a `stickslip.rsf.SpringSlider`) pulled at ``v_load``."""
    law = slider.law
    p = np.zeros(SIZE)
    p[A], p[F0], p[LOG_VREF] = law.a, law.f0, math.log(law.v_ref)
    p[K], p[SIGMA], p[MASS], p[VLOAD] = slider.stiffness, slider.normal_stress, slider.mass, v_load
    p[EVOLUTION], p[REGULARIZED], p[STATES] = EVOLUTIONS.index(law.evolution), float(law.regularized), law.states
    p[B:B + law.states], p[DC:DC + law.states] = law.b_values, law.dc_values
    return p


def friction(log_v, big_psi, p):
    """``(mu, d mu / d ln V, d mu / d Psi, d^2 mu / d ln V^2)`` at ``ln V`` and
    ``Psi = f0 + sum_i b_i psi_i``; with the regularised law ``mu = a asinh(V / (2 V_0) e^(Psi / a))``,
    whose slope ``s = a / sqrt(1 + e^(-2 z))`` (``z = ln V - ln 2 V_0 + Psi / a``) is
    ``d mu / d ln V = a d mu / d Psi``."""
    a = p[A]
    if p[REGULARIZED] == 0.0:
        return big_psi + a * (log_v - p[LOG_VREF]), a, 1.0, 0.0
    z = log_v - p[LOG_VREF] - math.log(2.0) + big_psi / a
    if z > LARGE_LOG:
        mu = a * (z + math.log(2.0))
    else:
        mu = a * math.asinh(math.exp(z))
    e = math.exp(-2.0 * z)
    slope = a / math.sqrt(1.0 + e)
    return mu, slope, slope / a, a * e / (1.0 + e) ** 1.5  # ds/dz = a e (1 + e)^(-3/2)


def state_rate(log_v, psi, dc, p):
    """``(psi', d psi' / d psi, d psi' / d ln V)`` of one state variable of slip distance ``dc``."""
    v = math.exp(log_v)
    law = p[EVOLUTION]
    if law == 0.0:  # aging: V_0/D_c e^-psi - V/D_c
        heal = p[LOG_VREF] - psi
        return math.exp(heal) / dc - v / dc, -math.exp(heal) / dc, -v / dc
    if law == 1.0:  # slip: -(V/D_c)(psi + ln V - ln V_0)
        w = psi + log_v - p[LOG_VREF]
        return -(v / dc) * w, -v / dc, -(v / dc) * (w + 1.0)
    heal = math.exp(p[LOG_VREF] - psi) / dc  # prz: V_0/D_c e^-psi - V^2 e^psi / (4 D_c V_0)
    wear = v * v * math.exp(psi - p[LOG_VREF]) / (4.0 * dc)
    return heal - wear, -heal - wear, -2.0 * wear


def rhs(y, p, out):
    """``y'`` into ``out``."""
    n = int(p[STATES])
    log_v, tau = y[0], y[1 + n]
    v = math.exp(log_v)
    big_psi, drive = p[F0], 0.0
    for i in range(n):
        big_psi += p[B + i] * y[1 + i]
    for i in range(n):
        rate, _, _ = state_rate(log_v, y[1 + i], p[DC + i], p)
        out[1 + i] = rate
        drive += p[B + i] * rate
    mu, mu_v, mu_psi, _ = friction(log_v, big_psi, p)
    if p[MASS] == 0.0:  # the spring's stress rate equals the strength's: sigma (mu_v (ln V)' + mu_Psi Psi')
        out[0] = (p[K] * (p[VLOAD] - v) / p[SIGMA] - mu_psi * drive) / mu_v
    else:
        out[0] = (tau - p[SIGMA] * mu) / (p[MASS] * v)
    out[1 + n] = p[K] * (p[VLOAD] - v)
    out[2 + n] = v


def jacobian(y, p, out):
    """``d y' / d y`` into ``out`` (square, zeroed here)."""
    n = int(p[STATES])
    log_v, tau = y[0], y[1 + n]
    v = math.exp(log_v)
    out[:, :] = 0.0
    big_psi, drive, drive_v = p[F0], 0.0, 0.0
    for i in range(n):
        big_psi += p[B + i] * y[1 + i]
    for i in range(n):
        rate, d_psi, d_v = state_rate(log_v, y[1 + i], p[DC + i], p)
        out[1 + i, 1 + i], out[1 + i, 0] = d_psi, d_v
        drive += p[B + i] * rate
        drive_v += p[B + i] * d_v
    mu, mu_v, mu_psi, curve = friction(log_v, big_psi, p)
    a = p[A]
    if p[MASS] == 0.0:
        # (ln V)' = N / D, N = k (V_l - V) / sigma - mu_Psi sum b_i g_i, D = mu_v; with the regularised
        # law mu_v = s(z), mu_Psi = s / a, dz/d ln V = 1, dz/d psi_j = b_j / a; otherwise D' = 0.
        num = p[K] * (p[VLOAD] - v) / p[SIGMA] - mu_psi * drive
        d_num = -p[K] * v / p[SIGMA] - (curve / a) * drive - mu_psi * drive_v
        out[0, 0] = (d_num * mu_v - num * curve) / (mu_v * mu_v)
        for j in range(n):
            dz = p[B + j] / a
            d_num = -(curve / a) * dz * drive - mu_psi * p[B + j] * out[1 + j, 1 + j]
            out[0, 1 + j] = (d_num * mu_v - num * curve * dz) / (mu_v * mu_v)
    else:
        # (ln V)' = (tau - sigma mu) e^(-ln V) / m
        excess = tau - p[SIGMA] * mu
        out[0, 0] = (-p[SIGMA] * mu_v - excess) / (p[MASS] * v)
        for j in range(n):
            out[0, 1 + j] = -p[SIGMA] * mu_psi * p[B + j] / (p[MASS] * v)
        out[0, 1 + n] = 1.0 / (p[MASS] * v)
    out[1 + n, 0] = -p[K] * v
    out[2 + n, 0] = v


KERNELS = KernelSet(globals(), ("friction", "state_rate", "rhs", "jacobian"))

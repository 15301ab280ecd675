"""Dormand and Prince's order-8 pair, for the compiled integrators (numba): the tableau of
`scipy.integrate.DOP853` and scipy's error norm and step-size control, shared by the 1-DOF
oscillator's slip flows (`stickslip.oscillator.slipkernel`) and the systems' flows under laws
that are not affine (`stickslip.system.smoothkernel`)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.integrate import DOP853

__all__ = ["WEIGHTS", "NODES", "STAGES", "E3", "E5", "EXPONENT", "SAFETY", "MIN_FACTOR", "MAX_FACTOR", "EPS",
           "stage", "error_norm", "next_factor"]

E3 = np.ascontiguousarray(DOP853.E3, dtype=float)
E5 = np.ascontiguousarray(DOP853.E5, dtype=float)
STAGES = int(DOP853.n_stages)
#: Row ``s < STAGES``: the weights of stage ``s``'s state; row ``STAGES``: the solution's.
WEIGHTS = np.vstack([np.ascontiguousarray(DOP853.A, dtype=float), np.ascontiguousarray(DOP853.B, dtype=float)])
#: The stages' times as fractions of the step.
NODES = np.ascontiguousarray(DOP853.C, dtype=float)
EXPONENT = -1.0 / (DOP853.error_estimator_order + 1)
SAFETY, MIN_FACTOR, MAX_FACTOR = 0.9, 0.2, 10.0
EPS = 2.220446049250313e-16


@njit(cache=True)
def stage(K, s, y, h, out):
    """The state at which stage ``s`` (1 to ``STAGES``; ``STAGES``: the step's end) takes its slope, into
    ``out``: ``y + h sum_j WEIGHTS[s, j] K[j]`` over the slopes ``K[:s]`` taken before it."""
    for i in range(y.size):
        acc = 0.0
        for j in range(s):
            acc += WEIGHTS[s, j] * K[j, i]
        out[i] = y[i] + h * acc


@njit(cache=True)
def error_norm(K, h, y, y_new, rtol, atol):
    """scipy's error norm of DOP853 (orders 5 and 3 combined) for the step of length ``h`` from ``y``
    to ``y_new`` with stage slopes ``K`` (``STAGES + 1`` rows, the last the slope at ``y_new``)."""
    n = y.size
    e5, e3 = 0.0, 0.0
    for i in range(n):
        scale = atol + rtol * max(abs(y[i]), abs(y_new[i]))
        a5, a3 = 0.0, 0.0
        for j in range(STAGES + 1):
            a5 += K[j, i] * E5[j]
            a3 += K[j, i] * E3[j]
        e5 += (a5 / scale) ** 2
        e3 += (a3 / scale) ** 2
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(h) * e5 / math.sqrt((e5 + 0.01 * e3) * n)


@njit(cache=True)
def next_factor(err, rejected):
    """The factor of the next step after an accepted one of error ``err`` (not above 1 after a rejection)."""
    factor = MAX_FACTOR if err == 0.0 else min(MAX_FACTOR, max(MIN_FACTOR, SAFETY * err ** EXPONENT))
    return min(1.0, factor) if rejected else factor

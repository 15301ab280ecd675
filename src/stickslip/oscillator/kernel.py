"""The event loop for affine friction laws (closed-form slip segments), and the closed-form flow.

The same algorithm as `Engine.run` with `AffineSlip` flows, written as one function over
floats that numba compiles, so that 10^4 stick-slip cycles take milliseconds; a short job
(a limit cycle, a run of a few hundred segments) runs the same source interpreted and spares
numba's start-up (`stickslip.jit`: `KERNELS.choose`). Roots of the closed-form velocity are
found by Newton's method safeguarded by bisection on a bracket where the velocity is
monotone (its derivative, the acceleration, is known in closed form), to a few ulps.
"""

from __future__ import annotations

import math

import numpy as np

from ..jit import KernelSet

_EPS = 2.220446049250313e-16


def cos_sin(om2, t):
    """``(C, S)`` with ``C = cos(w t)``, ``S = sin(w t)/w`` for ``om2 = w^2`` (cosh, sinh if ``om2 < 0``),
    by series near ``t = 0``."""
    z = om2 * t * t
    if abs(z) < 1e-4:
        return 1 - z / 2 + z * z / 24 - z**3 / 720, t * (1 - z / 6 + z * z / 120 - z**3 / 5040)
    if om2 > 0:
        w = math.sqrt(om2)
        return math.cos(w * t), math.sin(w * t) / w
    w = math.sqrt(-om2)
    return math.cosh(w * t), math.sinh(w * t) / w


def damped_cos_sin(sigma, w02, om2, t):
    """``e^{sigma t} C`` and ``e^{sigma t} S`` (`cos_sin`), computed without overflow.

    Overdamped (``om2 < 0``) and ``w t > 20``, ``cosh`` and ``sinh`` alone overflow long
    before the product with ``e^{sigma t}`` does; there the product is written with the
    exponent of the slow root, ``sigma + w = -w02 / (w - sigma)`` for ``sigma <= 0``,
    which has no cancellation.
    """
    if om2 < 0:
        w = math.sqrt(-om2)
        if w * t > 20.0:
            slow = -w02 / (w - sigma) if sigma <= 0 else sigma + w
            e = math.exp(slow * t)
            tail = math.exp(-2.0 * w * t)
            return 0.5 * e * (1.0 + tail), 0.5 * e * (1.0 - tail) / w
    c, s = cos_sin(om2, t)
    e = math.exp(sigma * t)
    return e * c, e * s


def velocity_acceleration(sigma, w02, om2, xi0, v0, t):
    """Velocity and acceleration at local time t."""
    c, s = damped_cos_sin(sigma, w02, om2, t)
    a0 = 2 * sigma * v0 - w02 * xi0
    return v0 * c + (sigma * v0 - w02 * xi0) * s, a0 * c + (sigma * a0 - w02 * v0) * s


def _x(sigma, w02, om2, xi0, v0, t):
    c, s = damped_cos_sin(sigma, w02, om2, t)
    return xi0 * c + (v0 - sigma * xi0) * s


def state(sigma, w02, om2, xi0, v0, t):
    """``(xi, v)`` at the local times ``t`` (an array)."""
    xi, v = np.empty(t.size), np.empty(t.size)
    for i in range(t.size):
        c, s = damped_cos_sin(sigma, w02, om2, t.flat[i])
        xi[i] = xi0 * c + (v0 - sigma * xi0) * s
        v[i] = v0 * c + (sigma * v0 - w02 * xi0) * s
    return xi, v


def next_piece(sigma, w02, om2, xi0, v0, ta, t_max):
    """The next zero of the acceleration after ``ta`` (or t_max)."""
    a0 = 2 * sigma * v0 - w02 * xi0
    b = sigma * a0 - w02 * v0
    if om2 > 0:
        w = math.sqrt(om2)
        phi = math.atan2(b / w, a0)
        k = math.ceil((w * ta - phi - math.pi / 2) / math.pi)
        t = (phi + math.pi / 2 + k * math.pi) / w
        while t <= ta:
            k += 1
            t = (phi + math.pi / 2 + k * math.pi) / w
        return min(t, t_max)
    if om2 < 0:
        w = math.sqrt(-om2)
        r = -a0 * w / b if b != 0 else -1.0
        t = math.atanh(r) / w if 0 < r < 1 else -1.0
    else:
        t = -a0 / b if b != 0 else -1.0
    return t if ta < t < t_max else t_max


def _sign(g, tol):
    return 0 if abs(g) <= tol else (1 if g > 0 else -1)


def velocity_root(sigma, w02, om2, xi0, v0, level, ta, tb):
    """Root of v(t) = level in [ta, tb], v monotone there: safeguarded Newton."""
    ga = velocity_acceleration(sigma, w02, om2, xi0, v0, ta)[0] - level
    t = 0.5 * (ta + tb)
    for _ in range(200):
        g, a = velocity_acceleration(sigma, w02, om2, xi0, v0, t)
        g -= level
        if g == 0.0:
            return t
        if (g > 0) == (ga > 0):
            ta, ga = t, g
        else:
            tb = t
        step = g / a if a != 0 else 0.0
        t_new = t - step
        if not (ta < t_new < tb) or a == 0:
            t_new = 0.5 * (ta + tb)
        if abs(t_new - t) <= 2 * _EPS * abs(t) or tb - ta <= 4 * _EPS * abs(tb):
            return t_new
        t = t_new
    return t


def run_affine(p, x0, v0, mode, t_end, max_segments, section, use_section):
    """Event loop. ``p = (m, k, c, N, V, mu0, mu1, fs)``.

    Returns ``(modes, t, x, v, n, status)``: segment ``i`` has mode ``modes[i]`` and
    runs from ``(t[i], x[i], v[i])`` to ``(t[i+1], x[i+1], v[i+1])``. Status: 0 reached
    t_end, 1 reached the section, -1 law validity exceeded, -2 max_segments, -3 Zeno.
    """
    m, k, c, n_f, V, mu0, mu1, fs = p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]
    w02 = k / m
    sigma = -(c - mu1 * n_f) / (2 * m)
    om2 = w02 - sigma * sigma
    x_hi = (fs * n_f - c * V) / k
    max_speed = mu0 / mu1 if mu1 > 0 else np.inf
    modes = np.zeros(max_segments, np.int8)
    ts = np.zeros(max_segments + 1)
    xs = np.zeros(max_segments + 1)
    vs = np.zeros(max_segments + 1)
    tsum, comp, x, v = 0.0, 0.0, x0, v0  # time = tsum + comp (Neumaier summation)
    t = 0.0
    ts[0], xs[0], vs[0] = t, x, v
    n, status, tiny = 0, 0, 0
    tiny_dt = 1e-12 / math.sqrt(w02)
    while True:
        if t >= t_end:
            break
        if n >= max_segments:
            status = -2
            break
        modes[n] = mode
        which = -1
        if mode == 0:
            dt = max(0.0, (x_hi - x) / V)
            if tsum + (dt + comp) > t_end:
                dt = t_end - t
                x = x + V * dt
                mode_next = 0
                hit = False
            else:
                x = x_hi
                mode_next = 1
                hit = True
            v = V
        else:
            s = mode
            x_c = (s * n_f * mu0 - mu1 * n_f * V) / k
            xi0 = x - x_c
            scale = max(abs(v), math.sqrt(w02) * abs(xi0), abs(V))
            tol = 16 * _EPS * scale
            t_max = t_end - t
            ta = 0.0
            ga_v = v - V
            ga_s = v - section
            dt = t_max
            while True:
                tb = next_piece(sigma, w02, om2, xi0, v, ta, t_max)
                vb = velocity_acceleration(sigma, w02, om2, xi0, v, tb)[0]
                gb_v, gb_s = vb - V, vb - section
                sa, sb = _sign(ga_v, tol), _sign(gb_v, tol)
                if sa != 0 and sb != sa and sa == -s:
                    dt = tb if sb == 0 else velocity_root(sigma, w02, om2, xi0, v, V, ta, tb)
                    which = 0
                sa, sb = _sign(ga_s, tol), _sign(gb_s, tol)
                if use_section and s == 1 and sa < 0 and sb != sa:
                    d2 = tb if sb == 0 else velocity_root(sigma, w02, om2, xi0, v, section, ta, tb)
                    if which < 0 or d2 < dt:
                        dt, which = d2, 1
                if which >= 0:  # the segment ends in this piece, where the speed is monotone between valid ends
                    break
                if abs(V - vb) > max_speed * (1 + 1e-12):  # (checked only within the segment: beyond its end the
                    status = -1  # closed form may leave the law's range; a run stopped there for it, falsely)
                    break
                if tb >= t_max:
                    break
                ta, ga_v, ga_s = tb, gb_v, gb_s
            if status < 0:
                break
            x_new = x_c + _x(sigma, w02, om2, xi0, v, dt)
            v_new = velocity_acceleration(sigma, w02, om2, xi0, v, dt)[0]
            hit = which >= 0
            if which == 0:
                v_new = V
                force = k * x_new + c * V
                mode_next = 0 if abs(force) <= fs * n_f else (1 if force > 0 else -1)
            elif which == 1:
                v_new = section
                mode_next = mode
            else:
                mode_next = mode
            x, v = x_new, v_new
        # compensated time
        s_sum = tsum + dt
        if abs(tsum) >= abs(dt):
            comp += (tsum - s_sum) + dt
        else:
            comp += (dt - s_sum) + tsum
        tsum = s_sum
        t = tsum + comp
        n += 1
        ts[n], xs[n], vs[n] = t, x, v
        tiny = tiny + 1 if (dt < tiny_dt and mode != 0) else 0
        if tiny > 100:
            status = -3
            break
        if mode != 0 and which == 1:
            status = 1
            break
        if not hit:
            break
        mode = mode_next
    return modes[:n], ts[: n + 1], xs[: n + 1], vs[: n + 1], n, status


#: Interpreted cost of a segment of `run_affine` and of a sample of `state` [µs] (measured: 16 and 0.9).
SEGMENT_COST, SAMPLE_COST = 20.0, 1.0

#: The kernels, compiled or interpreted (`stickslip.jit.KernelSet`).
KERNELS = KernelSet(globals(), ("cos_sin", "damped_cos_sin", "velocity_acceleration", "_x", "state", "next_piece",
                                "_sign", "velocity_root", "run_affine"))

"""The flow of a slip mode under a friction law that is not affine, compiled (numba).

DOP853 (`stickslip.dop853`: the tableau of `scipy.integrate.DOP853`, order 8, its error estimated
from the embedded orders 5 and 3, with scipy's step-size control), around a compiled law
(`stickslip.lawkernel.compiled`: the callbacks ``mu`` and ``dmu`` of `stickslip.lawkernel` and
their three numbers ``lp``). Events are located without dense output: the state at a time inside an accepted step is a step
of that length from the step's start, of the same order. A crossing of a velocity level is found
by Newton's method on that length (the derivative is the acceleration), kept in its bracket by
bisection, on pieces where the velocity is monotone (split at a zero of the acceleration, found
the same way). With the variational equations (``y`` of 6 numbers: ``x, v`` and the 2 x 2
``d(x, v)/d(x0, v0)`` by rows) the monodromy's factor comes along.

``p = (m, k, c, N, V, s, mu_lo, mu_hi)``: the oscillator, the mode's sign ``s = sign(v_r)`` and the
coefficients a law may take; a coefficient outside them (or not finite) stops the segment.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..dop853 import EPS, EXPONENT, MIN_FACTOR, SAFETY, STAGES, error_norm, next_factor, stage
from ..kernelcopy import copy, copy_rows

__all__ = ["segment", "evaluate", "run", "DONE", "CROSSED", "BAD_LAW", "STEP_TOO_SMALL"]

#: How a segment ended: at ``t_max``; at a level crossed; a friction coefficient out of its range
#: (the value returned); a step below round-off of the time (the flow cannot be integrated).
DONE, CROSSED, BAD_LAW, STEP_TOO_SMALL = 0, 1, 2, 3


@njit(cache=True)
def _rhs(mu, dmu, lp, p, y, out):
    """``y'`` into ``out``; returns the friction coefficient."""
    m, k, c, N, V, s = p[0], p[1], p[2], p[3], p[4], p[5]
    v_r = s * max(abs(V - y[1]), 1e-300)  # on the mode's side of v_r = 0
    coefficient = mu(v_r, lp[0], lp[1], lp[2])
    out[0] = y[1]
    out[1] = (s * N * coefficient - c * y[1] - k * y[0]) / m
    if y.size > 2:  # d/dt Phi = J Phi, J = [[0, 1], [-k/m, (-s N mu' - c)/m]]  (F = s N mu(V - v))
        j10, j11 = -k / m, (-s * N * dmu(v_r, lp[0], lp[1], lp[2]) - c) / m
        out[2], out[3] = y[4], y[5]
        out[4] = j10 * y[2] + j11 * y[4]
        out[5] = j10 * y[3] + j11 * y[5]
    return coefficient


@njit(cache=True)
def _step(mu, dmu, lp, p, y, f, h, K, tmp, y_new):
    """One DOP853 step of length ``h`` from ``(y, f = y')``: ``y_new``, its slope in ``K[-1]``;
    returns a friction coefficient out of range met on the way, or 0."""
    bad = 0.0
    copy(K[0], f)
    for s in range(1, STAGES + 1):
        stage(K, s, y, h, tmp)
        if s == STAGES:
            copy(y_new, tmp)
        coefficient = _rhs(mu, dmu, lp, p, tmp, K[s])
        if not (p[6] <= coefficient <= p[7]):
            bad = coefficient  # (never 0: the range holds 0)
    return bad


@njit(cache=True)
def _at(mu, dmu, lp, p, y, f, s, K, tmp, out, slope):
    """The state ``out`` at ``s`` into a step from ``(y, f)`` (a step of length ``s``), its slope ``slope``."""
    if s == 0.0:
        copy(out, y)
        copy(slope, f)
        return
    _step(mu, dmu, lp, p, y, f, s, K, tmp, out)
    copy(slope, K[STAGES])


@njit(cache=True)
def _root(mu, dmu, lp, p, y, f, a, b, level, which, t0, K, tmp, w, dw):
    """A zero in ``[a, b]`` (its ends of opposite signs) of ``v - level`` (``which == 0``) or of the
    acceleration (``which == 1``): Newton's method on the step length (the derivatives: the
    acceleration; the jerk ``-k/m v + (-s N mu' - c)/m a``), kept within the bracket by bisection,
    to a few ulps of ``t0 + s``."""
    _at(mu, dmu, lp, p, y, f, a, K, tmp, w, dw)
    ga = (w[1] - level) if which == 0 else dw[1]
    s = 0.5 * (a + b)
    for _ in range(200):
        _at(mu, dmu, lp, p, y, f, s, K, tmp, w, dw)
        if which == 0:
            g, d = w[1] - level, dw[1]
        else:
            v_r = p[5] * max(abs(p[4] - w[1]), 1e-300)
            g = dw[1]
            d = (-p[1] * w[1] + (-p[5] * p[3] * dmu(v_r, lp[0], lp[1], lp[2]) - p[2]) * dw[1]) / p[0]
        if g == 0.0:
            return s
        if (g > 0) == (ga > 0):
            a, ga = s, g
        else:
            b = s
        new = s - g / d if d != 0.0 else 0.5 * (a + b)
        if not (a < new < b):
            new = 0.5 * (a + b)
        if b - a <= 4 * EPS * abs(t0 + new) + 1e-300 or abs(new - s) <= 2 * EPS * abs(t0 + s):
            return new
        s = new
    return s


@njit(cache=True)
def _sign(g, tol):
    return 0 if abs(g) <= tol else (1 if g > 0 else -1)


@njit(cache=True)
def segment(mu, dmu, lp, p, y0, t_max, levels, directions, rtol, atol, tol, h, cap):
    """Integrate from ``y0`` until ``v`` crosses one of ``levels`` (each from the side its
    ``direction`` says: +1 upward, -1 downward, 0 either; a start on a level is no crossing) or
    ``t_max``. ``h`` the first step to try, ``tol`` the round-off of a velocity.

    Returns ``(status, index, t, y, steps, starts, states, slopes, v_low, v_high, value, h)``: the
    level crossed (-1 if none), the time and state at the end; the accepted steps' start times,
    states and slopes (``steps`` of them: `evaluate`); the lowest and highest velocity on the way;
    with `BAD_LAW` the coefficient met; the step it would try next (a guess for the next segment)."""
    n = y0.size
    K = np.empty((STAGES + 1, n))
    tmp, y_new, w, dw = np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    y, f = y0.copy(), np.empty(n)
    starts, states, slopes = np.empty(cap), np.empty((cap, n)), np.empty((cap, n))
    coefficient = _rhs(mu, dmu, lp, p, y, f)
    v_low = v_high = y[1]
    if not (p[6] <= coefficient <= p[7]):
        return BAD_LAW, -1, 0.0, y, 0, starts, states, slopes, v_low, v_high, coefficient, h
    t, steps, rejected = 0.0, 0, False
    while t < t_max:
        if t_max - t <= 10 * EPS * abs(t):  # t_max within round-off of this step's start: reached
            break
        h = min(h, t_max - t)
        if h <= 10 * EPS * max(abs(t), 1e-300):
            return STEP_TOO_SMALL, -1, t, y, steps, starts, states, slopes, v_low, v_high, 0.0, h
        bad = _step(mu, dmu, lp, p, y, f, h, K, tmp, y_new)
        if bad != 0.0:
            return BAD_LAW, -1, t, y, steps, starts, states, slopes, v_low, v_high, bad, h
        err = error_norm(K, h, y, y_new, rtol, atol)
        if err > 1.0:
            h *= max(MIN_FACTOR, SAFETY * err ** EXPONENT)
            rejected = True
            continue
        if steps == starts.size:  # room for more steps
            starts, states, slopes = _grow(starts, steps + 1), _grow(states, steps + 1), _grow(slopes, steps + 1)
        starts[steps] = t
        copy(states[steps], y)
        copy(slopes[steps], f)
        steps += 1
        f_new = K[STAGES].copy()
        # pieces of the step where v is monotone: [0, h], or split at a zero of the acceleration
        cut = -1.0
        if f[1] * f_new[1] < 0:
            cut = _root(mu, dmu, lp, p, y, f, 0.0, h, 0.0, 1, t, K, tmp, w, dw)
        a, va, again = 0.0, y[1], False
        for piece in range(2):
            b = cut if (piece == 0 and cut > 0) else h
            if b == h:
                vb = y_new[1]
            else:
                _at(mu, dmu, lp, p, y, f, b, K, tmp, w, dw)
                vb = w[1]
            best, index = math.inf, -1
            for i in range(levels.size):
                sa, sb = _sign(va - levels[i], tol), _sign(vb - levels[i], tol)
                if sa != 0 and sb != sa and (directions[i] == 0 or directions[i] == -sa):
                    s = b if sb == 0 else _root(mu, dmu, lp, p, y, f, a, b, levels[i], 0, t, K, tmp, w, dw)
                    if s < best:
                        best, index = s, i
            if index >= 0:
                _at(mu, dmu, lp, p, y, f, best, K, tmp, w, dw)
                short = error_norm(K, best, y, w, rtol, atol) if best > 0 else 0.0
                if short > 1.0 and best > 10 * EPS * abs(t):
                    # the step to the crossing is not resolved (a law that changes within the step: its
                    # error was judged on the whole step): steps up to it, shorter, under the error control
                    steps -= 1
                    h = best * max(MIN_FACTOR, SAFETY * short ** EXPONENT)
                    rejected, again = True, True
                    break
                v_low, v_high = min(v_low, w[1]), max(v_high, w[1])
                return CROSSED, index, t + best, w.copy(), steps, starts, states, slopes, v_low, v_high, 0.0, h
            v_low, v_high = min(v_low, vb), max(v_high, vb)
            if b == h:
                break
            a, va = b, vb
        if again:
            continue
        copy(y, y_new)
        copy(f, f_new)
        t += h
        h *= next_factor(err, rejected)
        rejected = False
    return DONE, -1, t_max, y, steps, starts, states, slopes, v_low, v_high, 0.0, h


@njit(cache=True)
def evaluate(mu, dmu, lp, p, starts, states, slopes, steps, times):
    """``(x, v)`` at the local ``times`` of a segment from its accepted steps (`segment`)."""
    n = states.shape[1]
    K = np.empty((STAGES + 1, n))
    tmp, w, dw = np.empty(n), np.empty(n), np.empty(n)
    x, v = np.empty(times.size), np.empty(times.size)
    for q in range(times.size):
        i = max(0, np.searchsorted(starts[:steps], times[q], side="right") - 1)
        _at(mu, dmu, lp, p, states[i], slopes[i], times[q] - starts[i], K, tmp, w, dw)
        x[q], v[q] = w[0], w[1]
    return x, v


@njit(cache=True)
def _grow(a, size):
    """``a`` with room for ``size`` rows (doubled until it has)."""
    if a.shape[0] >= size:
        return a
    rows = a.shape[0]
    while rows < size:
        rows *= 2
    out = np.empty((rows,) + a.shape[1:], dtype=a.dtype)
    copy(out.reshape(out.size), a.reshape(a.size))  # the first rows: C order
    return out


@njit(cache=True)
def run(mu, dmu, lp, osc, x0, v0, mode, t_end, section, use_section, variational, rtol, atol, max_events,
        max_speed):
    """`Engine`'s event loop for a numeric law, compiled: stick segments in closed form, slip
    segments by `segment`, the mode after a switch by Filippov's convention. ``osc = (m, k, c, N,
    V, mu_lo, mu_hi, x_lo, x_hi, omega)``.

    Returns ``(status, value, modes, t, x, v, jacobians, ranges, first, starts, states, slopes,
    ends)``: status as `Engine.run`'s (0 t_end, 1 the section, -1 the law's range of speeds
    left, -2 max_events, -3 Zeno; 2 a coefficient out of range, ``value``; 3 a step below
    round-off); segment ``i`` has ``modes[i]``, runs from ``t[i], x[i], v[i]`` to the next, with
    the flow's Jacobian, its lowest and highest velocity, and its accepted steps
    ``first[i]:first[i + 1]`` of ``starts`` (local times), ``states``, ``slopes`` (for `evaluate`);
    ``ends[i]`` its local duration as the search found it."""
    m, k, c, N, V = osc[0], osc[1], osc[2], osc[3], osc[4]
    x_lo, x_hi, omega = osc[7], osc[8], osc[9]
    n = 6 if variational else 2
    cap = 64
    modes = np.empty(cap, dtype=np.int64)
    t = np.empty(cap + 1)
    x, v = np.empty(cap + 1), np.empty(cap + 1)
    jac = np.empty((cap, 2, 2))
    ranges = np.empty((cap, 2))
    ends = np.empty(cap)
    first = np.zeros(cap + 1, dtype=np.int64)
    starts, states, slopes = np.empty(256), np.empty((256, n)), np.empty((256, n))
    p = np.empty(8)
    p[0], p[1], p[2], p[3], p[4], p[6], p[7] = m, k, c, N, V, osc[5], osc[6]
    levels, sides = np.empty(2), np.empty(2, dtype=np.int64)
    h = np.array([0.01 / omega, 0.01 / omega])  # the next step to try, per slip direction
    tsum, comp = 0.0, 0.0  # the time: tsum + comp (Neumaier's summation)
    t[0], x[0], v[0] = 0.0, x0, v0
    count, status, tiny, value = 0, 0, 0, 0.0
    y0 = np.zeros(n)
    while tsum + comp < t_end:
        if count >= max_events:
            status = -2
            break
        if count + 1 >= modes.size:  # room for as many segments again
            cap = 2 * modes.size
            modes, jac, ranges, ends = _grow(modes, cap), _grow(jac, cap), _grow(ranges, cap), _grow(ends, cap)
            t, x, v, first = _grow(t, cap + 1), _grow(x, cap + 1), _grow(v, cap + 1), _grow(first, cap + 1)
        modes[count] = mode
        now = tsum + comp
        if mode == 0:  # stick: to the release at x_hi, in closed form
            dt = max(0.0, (x_hi - x[count]) / V)
            hit = tsum + (dt + comp) <= t_end
            if not hit:
                dt = t_end - now
            s = tsum + dt
            comp += (tsum - s) + dt if abs(tsum) >= abs(dt) else (dt - s) + tsum
            tsum = s
            t[count + 1], x[count + 1], v[count + 1] = tsum + comp, x_hi if hit else x[count] + V * dt, V
            jac[count, 0, 0], jac[count, 0, 1], jac[count, 1, 0], jac[count, 1, 1] = 1.0, 0.0, 0.0, 1.0
            ranges[count, 0] = ranges[count, 1] = V
            ends[count] = dt
            first[count + 1] = first[count]
            count += 1
            if not hit:
                break
            mode = 1
            continue
        p[5] = mode
        levels[0], sides[0] = V, 1 if mode == 1 else -1
        nl = 1
        if use_section and mode == 1:
            levels[1], sides[1] = section, 1
            nl = 2
        y0[0], y0[1] = x[count], v[count]
        if variational:
            y0[2], y0[3], y0[4], y0[5] = 1.0, 0.0, 0.0, 1.0
        scale = max(abs(v[count]), omega * abs(x[count]), abs(levels[0]), abs(levels[nl - 1]), 1e-300)
        side = 0 if mode == 1 else 1
        out = segment(mu, dmu, lp, p, y0, t_end - now, levels[:nl], sides[:nl], rtol, atol * max(scale, V),
                      16 * EPS * scale, min(t_end - now, h[side]), np.int64(64))  # (an int64: as Python calls it)
        seg_status, index, dt, y, steps = out[0], out[1], out[2], out[3], out[4]
        h[side] = out[11]
        if seg_status == BAD_LAW or seg_status == STEP_TOO_SMALL:
            status, value = (2 if seg_status == BAD_LAW else 3), out[10]
            break
        begin = first[count]
        if begin + steps > starts.size:
            starts = _grow(starts, begin + steps)
            states, slopes = _grow(states, begin + steps), _grow(slopes, begin + steps)
        copy(starts[begin:], out[5][:steps])
        copy_rows(states, begin, out[6], steps)
        copy_rows(slopes, begin, out[7], steps)
        first[count + 1] = begin + steps
        ranges[count, 0], ranges[count, 1] = out[8], out[9]
        ends[count] = dt
        if variational:
            jac[count, 0, 0], jac[count, 0, 1], jac[count, 1, 0], jac[count, 1, 1] = y[2], y[3], y[4], y[5]
        s = tsum + dt
        comp += (tsum - s) + dt if abs(tsum) >= abs(dt) else (dt - s) + tsum
        tsum = s
        t[count + 1], x[count + 1] = tsum + comp, y[0]
        v[count + 1] = levels[index] if seg_status == CROSSED else y[1]  # onto the line that was crossed
        count += 1
        if max(abs(V - out[8]), abs(V - out[9])) > max_speed * (1 + 1e-12):
            status = -1
            break
        tiny = tiny + 1 if dt < 1e-12 / omega else 0
        if tiny > 100:
            status = -3
            break
        if seg_status != CROSSED:
            break
        if index == 1:
            status = 1
            break
        xs = x[count]
        mode = 0 if x_lo <= xs <= x_hi else (1 if xs > x_hi else -1)
    return (status, value, modes[:count], t[:count + 1], x[:count + 1], v[:count + 1], jac[:count], ranges[:count],
            first[:count + 1], starts, states, slopes, ends[:count])

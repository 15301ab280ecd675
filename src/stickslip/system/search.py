"""The first event of an affine flow ``z' = A z``, compiled (numba).

`Flow.first_event`'s search, written over arrays: steps of ``h`` (a fraction of the fastest time
scale of ``A``); within a step the flow is its Taylor series ``z(s) = sum_k (s/dt)^k P[k]``,
``P[k] = (dt A)^k z / k!``, summed to round-off (``|dt A|`` about a quarter: 20-odd terms), so a
switching function ``g_r(s) = G[r] . z(s)`` is a polynomial and its slope ``G[r] . A z(s)`` its derivative
(``G A z(s)``: the polynomial's derivative). A row's zero within the step is a sign change of ``g_r`` between the step's ends,
or a dip between them seen by the slope changing sign; each is found by Newton's method on the
polynomial, safeguarded by bisection, to a few ulps. The series of a step is made only when a
row needs it if the step's matrix exponential ``E = expm(h A)`` is given (a large flow visited
for many steps: one product per step instead of twenty).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from ..kernelcopy import copy

__all__ = ["search", "MAX_TERMS", "NO_EVENT", "EVENT", "WANTS_EXPONENTIAL"]

_EPS = 2.220446049250313e-16
#: Terms of a step's Taylor series at most (a step whose series is not at round-off by then is halved).
MAX_TERMS = 60
#: Points of a step at which a switching function that starts on its line without rising and ends
#: below it is looked at: above the line at one of them, it rose first (its zero is the one after).
RISE_SAMPLES = 32
_SUMS = {"reassoc", "contract"}
#: What `search` found: nothing up to ``t_max``; events at ``t``; ``budget`` steps taken without
#: ``E`` (at a step's end ``t``: the caller may make ``E`` and search on from there).
NO_EVENT, EVENT, WANTS_EXPONENTIAL = 0, 1, 2


@njit(cache=True)
def _series(A, z, dt, P):
    """``P[k] = (dt A)^k z / k!`` until it is at round-off: the count of terms, or 0."""
    m = z.size
    copy(P[0], z)
    big = np.abs(z).max()
    before = big
    for k in range(1, MAX_TERMS):
        f = dt / k
        _mv(A, P[k - 1], P[k])
        size = 0.0
        for i in range(m):
            P[k, i] *= f
            size = max(size, abs(P[k, i]))
        big = max(big, size)
        if size <= 1e-20 * big and before <= 1e-17 * big:
            return k + 1
        before = size
    return 0


@njit(cache=True)
def _converged(A, z, dt, P):
    """`_series` of the step ``dt``, halved until its series reaches round-off: ``(K, dt)``."""
    K = _series(A, z, dt, P)
    for _ in range(64):
        if K:
            return K, dt
        dt *= 0.5
        K = _series(A, z, dt, P)
    raise FloatingPointError("the flow's Taylor series does not reach round-off (a state that is not finite?)")


@njit(cache=True)
def _near(g, dg, g1, dg1, tol):
    """Whether a row is within round-off of zero at an end of the step, below it, or dips."""
    for r in range(g.size):
        if g1[r] <= tol[r] or g[r] <= tol[r] or dg[r] < 0 < dg1[r]:
            return True
    return False


@njit(cache=True)
def _coefficients(P, K, dt, row, c):
    """``c[0, k] = row . P[k]`` (``k < K``) and the slope's, ``c[1, k] = (k + 1) c[0, k + 1] / dt``
    (``A P[k] = (k + 1) P[k + 1] / dt``: the polynomial's derivative)."""
    m = row.size
    for k in range(K):
        acc = 0.0
        for j in range(m):
            acc += row[j] * P[k, j]
        c[0, k] = acc
    for k in range(K - 1):
        c[1, k] = (k + 1) * c[0, k + 1] / dt
    c[1, K - 1] = 0.0


@njit(cache=True)
def _value(c, K, u):
    """``sum_k c[k] u^k`` (Horner) and its derivative in ``u``."""
    f, d = c[K - 1], 0.0
    for k in range(K - 2, -1, -1):
        d = d * u + f
        f = f * u + c[k]
    return f, d


@njit(cache=True)
def _root(c, K, dt, a, b):
    """A zero in ``[a, b]`` of ``s -> sum_k c[k] (s/dt)^k``, which changes sign there (else the end
    nearer zero): Newton's method kept within the bracket by bisection, to a few ulps."""
    fa = _value(c, K, a / dt)[0]
    fb = _value(c, K, b / dt)[0]
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if (fa > 0) == (fb > 0):
        return a if abs(fa) < abs(fb) else b
    s = 0.5 * (a + b)
    for _ in range(400):
        f, d = _value(c, K, s / dt)
        if f == 0.0:
            return s
        if (f > 0) == (fa > 0):
            a, fa = s, f
        else:
            b = s
        new = s - f * dt / d if d != 0.0 else 0.5 * (a + b)
        if not (a < new < b):
            new = 0.5 * (a + b)
        if b - a <= 4 * _EPS * abs(new) + 1e-300 or abs(new - s) <= 2 * _EPS * abs(s):
            return new
        s = new
    return s


@njit(cache=True)
def _crossing(P, K, row, c, dt, g0, dg0, g1, dg1, tol):
    """When in ``(0, dt]`` the switching function ``row . z(s)`` first reaches zero from above; -1.0 if
    it does not. ``c`` holds the coefficients of it and of its slope (`_coefficients`), made when
    first needed (most rows are decided by their ends' values and slopes)."""
    start = 0.0
    made = False
    if g0 <= tol:  # on the switching line at the start: departing (rising) or leaving at once
        if dg0 <= 0 and g1 <= tol:  # leaving at once, unless it rises first (at rest on it: a contact let go
            _coefficients(P, K, dt, row, c)  # with no velocity departs by its curvature) and comes back
            low = g1
            for i in range(1, RISE_SAMPLES + 1):
                u = i / RISE_SAMPLES
                value = _value(c[0], K, u)[0]
                if value > tol:
                    return _root(c[0], K, dt, u * dt, dt)  # above the line there: the zero after it
                low = min(low, value)
            if low >= -tol:  # on the line through the step to round-off (a reaction or gap that stays 0)
                return -1.0
            return 0.0
        if g1 > tol and dg1 >= 0:
            return -1.0
        if dg0 > 0 and dg1 < 0:  # rose, then fell: from its top
            _coefficients(P, K, dt, row, c)
            made = True
            start = _root(c[1], K, dt, 0.0, dt)
            if _value(c[0], K, start / dt)[0] <= tol:
                return -1.0
        elif g1 > tol:
            return -1.0
    if g1 <= 0:
        above = g0 > 0 if start == 0.0 else _value(c[0], K, start / dt)[0] > 0  # (c made when start > 0)
        if not above:
            return start
        if not made:
            _coefficients(P, K, dt, row, c)
        return _root(c[0], K, dt, start, dt)
    if dg0 < 0 < dg1 and g0 > tol:  # a dip between the steps: below zero at its bottom?
        _coefficients(P, K, dt, row, c)
        bottom = _root(c[1], K, dt, 0.0, dt)
        if _value(c[0], K, bottom / dt)[0] <= 0:
            return _root(c[0], K, dt, 0.0, bottom)
    return -1.0


@njit(cache=True, fastmath=_SUMS)
def _mv(A, x, out):
    """``out = A x`` by loops: no allocation, and no call into scipy's BLAS, whose threads would spin
    against numpy's on the same cores (the sums reassociated, so that they vectorise)."""
    for i in range(A.shape[0]):
        acc = 0.0
        for j in range(x.size):
            acc += A[i, j] * x[j]
        out[i] = acc


@njit(cache=True, fastmath=_SUMS)
def _mv_abs(A, x, out):
    """``out = |A| |x|`` (the size of the terms of ``A x``)."""
    for i in range(A.shape[0]):
        acc = 0.0
        for j in range(x.size):
            acc += abs(A[i, j]) * abs(x[j])
        out[i] = acc


@njit(cache=True)
def _sum(P, K, u, out):
    """``out = sum_{k<K} u^k P[k]``."""
    copy(out, P[K - 1])
    for k in range(K - 2, -1, -1):
        for j in range(out.size):
            out[j] = out[j] * u + P[k, j]


@njit(cache=True)
def _ends(A, G, z, scale, g, dg, tol, w):
    """The rows ``g = G z``, their slopes ``dg = G A z`` and their round-off ``tol`` at ``z`` (``w`` a
    work array of the size of ``z``)."""
    _mv(G, z, g)
    _mv(A, z, w)
    _mv(G, w, dg)
    _mv_abs(G, z, tol)
    for r in range(G.shape[0]):
        tol[r] = 64 * _EPS * (tol[r] + scale[r])


@njit(cache=True)
def search(A, G, E, has_E, z0, t_max, h, scale, budget):
    """The first zero, from above, of a row of ``G z(t)`` within ``(0, t_max]``.

    Returns ``(status, t, z, rows, steps)``: `EVENT` with the time, the state there and the rows
    at zero there (those whose zero comes within 1e-9 of the first, and those within
    round-off of it); `NO_EVENT` with ``t_max`` and the state there; `WANTS_EXPONENTIAL` after
    ``budget`` steps with ``has_E`` false, at the end of the last (the search goes on from there).
    ``scale[r]`` is the size of row ``r``'s terms at the search's start, for its round-off (empty:
    from ``z0``)."""
    m, nr = z0.size, G.shape[0]
    P = np.empty((MAX_TERMS, m))
    c = np.empty((2, MAX_TERMS))
    z, z1, w = z0.copy(), np.empty(m), np.empty(m)
    g, dg, g1, dg1, tol = np.empty(nr), np.empty(nr), np.empty(nr), np.empty(nr), np.empty(nr)
    if scale.size == 0:  # the start's: |G| |z0|
        scale = np.empty(nr)
        _mv_abs(G, z0, scale)
    _ends(A, G, z, scale, g, dg, tol, w)
    found = np.empty(nr)
    t, steps = 0.0, 0
    while t < t_max:
        dt = min(h, t_max - t)
        use_E = has_E and dt == h
        K = 0
        if use_E:
            _mv(E, z, z1)
        else:
            K, dt = _converged(A, z, dt, P)
            _sum(P, K, 1.0, z1)
        steps += 1
        _ends(A, G, z1, scale, g1, dg1, tol, w)
        if use_E and _near(g, dg, g1, dg1, tol):  # a row needs the step's series
            K = _series(A, z, dt, P)
            if K == 0:  # (not at round-off: shorter steps, as without E)
                K, dt = _converged(A, z, 0.5 * dt, P)
                _sum(P, K, 1.0, z1)
                _ends(A, G, z1, scale, g1, dg1, tol, w)
        first = np.inf
        for r in range(nr):
            found[r] = -1.0
            if g1[r] > tol[r] and g[r] > tol[r] and not (dg[r] < 0 < dg1[r]):
                continue  # above the line at both ends and no dip: no zero within the step
            s = _crossing(P, K, G[r], c, dt, g[r], dg[r], g1[r], dg1[r], tol[r])
            found[r] = s
            if s >= 0 and s < first:
                first = s
        if first < np.inf:
            ze = np.empty(m)
            _sum(P, K, first / dt, ze)
            ge = np.empty(nr)
            _mv(G, ze, ge)
            rows = np.empty(nr, dtype=np.int64)
            count = 0
            ahead = min(h, t_max - t - first)  # the step after the event: does a row at zero there leave it?
            Ka, dta, Pa = -1, ahead, P
            g0a, dg0a, ta, g1a, dg1a, t1a = ge, ge, ge, ge, ge, ge
            for r in range(nr):
                if found[r] >= 0 and found[r] <= first * (1 + 1e-9) + 1e-300:
                    rows[count] = r
                    count += 1
                elif ge[r] <= tol[r]:  # on its line to round-off: an event only if it leaves the line at once
                    if Ka < 0 and ahead > 0:  # (not one departing from it, as a gap just opened at a tangency)
                        Pa = np.empty((MAX_TERMS, m))
                        Ka, dta = _converged(A, ze, ahead, Pa)
                        za = np.empty(m)
                        _sum(Pa, Ka, 1.0, za)
                        g0a, dg0a, ta = np.empty(nr), np.empty(nr), np.empty(nr)
                        g1a, dg1a, t1a = np.empty(nr), np.empty(nr), np.empty(nr)
                        _ends(A, G, ze, scale, g0a, dg0a, ta, w)
                        _ends(A, G, za, scale, g1a, dg1a, t1a, w)
                    band = max(ta[r], tol[r])  # (as the search from there would: a row that rises off its line
                    if Ka < 0 or dg0a[r] * dta < -max(band, 1e-9 * abs(g1a[r])) or _crossing(  # is no event)
                            Pa, Ka, G[r], c, dta, g0a[r], dg0a[r], g1a[r], dg1a[r], band) == 0.0:
                        rows[count] = r
                        count += 1
            return EVENT, t + first, ze, rows[:count], steps
        t = t + dt
        z, z1, g, g1, dg, dg1 = z1, z, g1, g, dg1, dg
        if not has_E and steps >= budget and t < t_max:
            return WANTS_EXPONENTIAL, t, z, np.empty(0, dtype=np.int64), steps
    return NO_EVENT, t_max, z, np.empty(0, dtype=np.int64), steps

"""The motion of a system between switches under laws that are not affine, compiled (numba).

For a system whose contacts stick or slip with constant normal forces under laws that are affine in
the slip speed, Stribeck's law or a user's function numba compiles (`stickslip.lawkernel.compiled`;
at most `SLOTS` = 4 such functions in one system), and no rate-and-state contact: the equations of
`stickslip.system.RateStateEquations` in a mode (slipping contacts' forces ``s N mu(v_r)``, the
stuck ones' the forces that hold them) integrated by DOP853 (`stickslip.dop853`, scipy's tableau and
step control) with the mode's switching functions (`stickslip.system.rate_state_modes.mode_events`)
located as `scipy.integrate.solve_ivp` locates terminal events: a sign change in the event's
direction between two accepted steps, its time found to round-off (regula falsi kept in its
bracket), the state there a step of that length from the step's start (of the same order).
`rate_state_simulate` chooses the next mode at each switch, as with Radau.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .. import lawkernel
from ..dop853 import EPS, EXPONENT, MIN_FACTOR, NODES, SAFETY, STAGES, error_norm, next_factor, stage
from ..kernelcopy import copy
from ..quantities import OSCILLATOR
from ..rsf import RateState

__all__ = ["Compiled", "Solution", "Failed", "compiled_laws", "SLOTS", "DONE", "CROSSED", "BAD_LAW", "STEP_TOO_SMALL",
           "BUDGET"]

#: How a segment ended: at its end time; at an event; a law's value not finite; a step below the
#: round-off of the time; more steps than allowed.
DONE, CROSSED, BAD_LAW, STEP_TOO_SMALL, BUDGET = 0, 1, 2, 3, 4
#: Event kinds: a slipping contact's slip rate (toward zero), its slip speed against its law's
#: largest, a stuck contact's force against ``+f_s N(x)`` and against ``-f_s N(x)``, a unilateral
#: contact's normal force ``N(x)`` (to zero: opening; from zero: closing).
ZERO, LIMIT, RELEASE_UP, RELEASE_DOWN, NORMAL = 0, 1, 2, 3, 4
#: A unilateral contact off its surface (`stickslip.system.flow.OPEN`).
OPEN = 2
#: The most compiled law functions in one system (each its own argument of the compiled functions).
SLOTS = 4


@njit(cache=True)
def _rhs(mu1, mu2, mu3, mu4, P, t, y, out, vr, force, lam, nf):
    """``y'`` into ``out``, the slip rates ``vr``, the slipping contacts' forces ``force`` and the stuck
    ones' ``lam``; False where a law's value is not a friction coefficient (outside ``bounds``, the
    declared range of ``fd``, or not a number)."""
    Mi, K, C, f0, B, freq, W, V, N, Kn, push, mode, kind, num, stuck, MiE, G, bounds = P
    n, k = Mi.shape[0], W.shape[1]
    ok = True
    for i in range(k):
        acc, normal = V[i], N[i]
        for r in range(n):
            acc -= W[r, i] * y[n + r]
            normal -= Kn[r, i] * y[r]
        vr[i], nf[i] = acc, normal
        s = mode[i]
        if s == 0 or s == OPEN:
            force[i] = 0.0
            continue
        v = acc if s * acc > 0 else s * 1e-300  # just released: its side of zero
        if kind[i] == 0:
            mu = num[i, 0] - num[i, 1] * abs(v)
        elif kind[i] == 1:
            mu = mu1(v, num[i, 0], num[i, 1], num[i, 2])
        elif kind[i] == 2:
            mu = mu2(v, num[i, 0], num[i, 1], num[i, 2])
        elif kind[i] == 3:
            mu = mu3(v, num[i, 0], num[i, 1], num[i, 2])
        else:
            mu = mu4(v, num[i, 0], num[i, 1], num[i, 2])
        if not bounds[0] <= mu <= bounds[1]:  # (NaN too) a coefficient out of the declared range
            ok = False
        force[i] = s * normal * mu
    rest = f0.copy()
    for j in range(freq.size):
        c, sn = math.cos(freq[j] * t), math.sin(freq[j] * t)
        for r in range(n):
            rest[r] += B[r, 2 * j] * c + B[r, 2 * j + 1] * sn
    for r in range(n):
        acc = rest[r]
        for q in range(n):
            acc -= K[r, q] * y[q] + C[r, q] * y[n + q]
        for i in range(k):
            acc += W[r, i] * force[i]
            if mode[i] != OPEN:
                acc += push[r, i] * nf[i]
        rest[r] = acc
    for r in range(n):
        acc = 0.0
        for q in range(n):
            acc += Mi[r, q] * rest[q]
        out[n + r] = acc
        out[r] = y[n + r]
    m = stuck.size
    if m:  # M a = rest + E lam with E^T a = 0
        q = np.empty(m)
        for a in range(m):
            acc = 0.0
            for r in range(n):
                acc += W[r, stuck[a]] * out[n + r]
            q[a] = acc
        for a in range(m):
            acc = 0.0
            for b in range(m):
                acc -= G[a, b] * q[b]
            lam[a] = acc
        for r in range(n):
            acc = 0.0
            for a in range(m):
                acc += MiE[r, a] * lam[a]
            out[n + r] += acc
    return ok


@njit(cache=True)
def _events(mu1, mu2, mu3, mu4, P, ev, t, y, slope, vr, force, lam, nf, g):
    """The switching functions ``g`` at ``(t, y)`` (and the slope there); False where a law has no value."""
    index, kind, level, contact = ev
    ok = _rhs(mu1, mu2, mu3, mu4, P, t, y, slope, vr, force, lam, nf)
    for e in range(index.size):
        i = index[e]
        if kind[e] == ZERO:
            g[e] = vr[i]
        elif kind[e] == LIMIT:
            g[e] = abs(vr[i]) - level[e]
        elif kind[e] == RELEASE_UP:
            g[e] = lam[i] - level[e] * max(nf[contact[e]], 0.0)
        elif kind[e] == RELEASE_DOWN:
            g[e] = lam[i] + level[e] * max(nf[contact[e]], 0.0)
        else:  # a unilateral contact's normal force (opening, closing)
            g[e] = nf[i]
    return ok


@njit(cache=True)
def _step(mu1, mu2, mu3, mu4, P, t, y, f, h, K, tmp, y_new, vr, force, lam, nf):
    """One DOP853 step of length ``h`` from ``(t, y, f = y')``: ``y_new``, its slope in ``K[-1]``;
    False where a law had no value on the way."""
    ok = True
    copy(K[0], f)
    for s in range(1, STAGES + 1):
        stage(K, s, y, h, tmp)
        if s == STAGES:
            copy(y_new, tmp)
        ts = t + h if s == STAGES else t + NODES[s] * h
        ok = _rhs(mu1, mu2, mu3, mu4, P, ts, tmp, K[s], vr, force, lam, nf) and ok
    return ok


@njit(cache=True)
def _root(mu1, mu2, mu3, mu4, P, ev, e, t, y, f, h, ga, gb, K, tmp, w, slope, vr, force, lam, nf, g):
    """The step length in ``[0, h]`` at which event ``e`` changes sign (``ga``, ``gb`` at the ends):
    regula falsi (Illinois), kept in its bracket by bisection, to round-off of the time."""
    if ga == 0.0:
        return 0.0
    if gb == 0.0:
        return h
    a, b, side = 0.0, h, 0
    for _ in range(200):
        s = (a * gb - b * ga) / (gb - ga)
        if not (a < s < b):
            s = 0.5 * (a + b)
        _step(mu1, mu2, mu3, mu4, P, t, y, f, s, K, tmp, w, vr, force, lam, nf)
        _events(mu1, mu2, mu3, mu4, P, ev, t + s, w, slope, vr, force, lam, nf, g)
        gs = g[e]
        if gs == 0.0:
            return s
        if (gs > 0) == (ga > 0):
            a, ga = s, gs
            if side == -1:
                gb *= 0.5
            side = -1
        else:
            b, gb = s, gs
            if side == 1:
                ga *= 0.5
            side = 1
        if b - a <= 4 * EPS * abs(t + b) + 1e-300:
            return b
    return b


@njit(cache=True)
def _fill(mu1, mu2, mu3, mu4, P, t, y, f, upto, t_eval, q, Y, K, tmp, w, vr, force, lam, nf):
    """The samples at ``t_eval[q:]`` up to ``upto`` from the step that starts at ``(t, y, f)``; the next ``q``."""
    while q < t_eval.size and t_eval[q] <= upto:
        s = t_eval[q] - t
        if s <= 0.0:
            copy(Y[q], y)
        else:
            _step(mu1, mu2, mu3, mu4, P, t, y, f, s, K, tmp, w, vr, force, lam, nf)
            copy(Y[q], w)
        q += 1
    return q


@njit(cache=True)
def segment(mu1, mu2, mu3, mu4, P, ev, directions, t0, y0, t_end, t_eval, rtol, atol, h, max_steps):
    """From ``(t0, y0)`` to ``t_end`` or the first event (``ev`` = (index, kind, level) and their
    ``directions``, as scipy's events have them), with the samples at ``t_eval`` (increasing, from
    ``t0``) on the way, up to the event's time. Returns ``(status, event, t, y, Y, samples, h)``:
    the event reached (-1: none), the time and state at the end, the samples taken and the step
    to try next."""
    n, ne = y0.size, directions.size
    k = P[6].shape[1]
    K = np.empty((STAGES + 1, n))
    tmp, y_new, w, f, slope = np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    vr, force, lam, nf = np.empty(k), np.empty(k), np.empty(max(P[14].size, 1)), np.empty(k)
    g_old, g_new, g = np.empty(ne), np.empty(ne), np.empty(ne)
    Y = np.empty((t_eval.size, n))
    t, y = t0, y0.copy()
    if not _events(mu1, mu2, mu3, mu4, P, ev, t, y, f, vr, force, lam, nf, g_old):
        return BAD_LAW, -1, t, y, Y, 0, h
    # (an int64, not the literal 0: numba would compile another `_fill` for a literal)
    q = _fill(mu1, mu2, mu3, mu4, P, t, y, f, t, t_eval, np.int64(0), Y, K, tmp, w, vr, force, lam, nf)
    rejected, steps = False, 0
    while t_end - t > 10 * EPS * abs(t):
        steps += 1
        if steps > max_steps:
            return BUDGET, -1, t, y, Y, q, h
        h = min(h, t_end - t)
        if h <= 10 * EPS * max(abs(t), 1e-300):
            return STEP_TOO_SMALL, -1, t, y, Y, q, h
        if not _step(mu1, mu2, mu3, mu4, P, t, y, f, h, K, tmp, y_new, vr, force, lam, nf):
            h *= 0.5  # a stage beyond the law's range: a shorter step, until round-off says the law ends here
            rejected = True
            if h <= 10 * EPS * max(abs(t), 1e-300):
                return BAD_LAW, -1, t, y, Y, q, h
            continue
        err = error_norm(K, h, y, y_new, rtol, atol)
        if err > 1.0:
            h *= max(MIN_FACTOR, SAFETY * err ** EXPONENT)
            rejected = True
            continue
        _events(mu1, mu2, mu3, mu4, P, ev, t + h, y_new, slope, vr, force, lam, nf, g_new)
        best, hit = math.inf, -1
        for e in range(ne):
            ga, gb = g_old[e], g_new[e]
            up, down = ga <= 0.0 <= gb, gb <= 0.0 <= ga
            if (up and directions[e] > 0) or (down and directions[e] < 0) or ((up or down) and directions[e] == 0):
                s = _root(mu1, mu2, mu3, mu4, P, ev, e, t, y, f, h, ga, gb, K, tmp, w, slope, vr, force, lam, nf, g)
                if s < best:
                    best, hit = s, e
        if hit >= 0:
            _step(mu1, mu2, mu3, mu4, P, t, y, f, best, K, tmp, w, vr, force, lam, nf)
            short = error_norm(K, best, y, w, rtol, atol) if best > 0 else 0.0
            if short > 1.0 and best > 10 * EPS * abs(t):  # the step to the event not resolved: shorter steps
                h = best * max(MIN_FACTOR, SAFETY * short ** EXPONENT)
                rejected = True
                continue
            end = w.copy()
            q = _fill(mu1, mu2, mu3, mu4, P, t, y, f, t + best, t_eval, q, Y, K, tmp, w, vr, force, lam, nf)
            return CROSSED, hit, t + best, end, Y, q, h
        q = _fill(mu1, mu2, mu3, mu4, P, t, y, f, min(t + h, t_end), t_eval, q, Y, K, tmp, w, vr, force, lam, nf)
        copy(y, y_new)
        copy(f, slope)
        copy(g_old, g_new)
        t += h
        h *= next_factor(err, rejected)
        rejected = False
    q = _fill(mu1, mu2, mu3, mu4, P, t, y, f, t_end, t_eval, q, Y, K, tmp, w, vr, force, lam, nf)
    return DONE, -1, t_end, y, Y, q, h


def compiled_laws(eq) -> tuple | None:
    """``(callbacks, kind, numbers)`` for `Compiled` of ``eq`` (`stickslip.system.RateStateEquations`):
    None where its system has a rate-and-state contact, a force history, a law numba cannot compile,
    or more than `SLOTS` compiled law functions (its runs then stay with Radau in Python)."""
    if any(isinstance(law, RateState) for law in eq.laws) or eq.system.history is not None:
        return None
    functions, kind, numbers = [], [], []
    for law in eq.laws:
        if law.affine is not None:
            kind.append(0)
            numbers.append((*law.affine, 0.0))
            continue
        made = lawkernel.compiled(law)
        if made is None:
            return None
        if made[0] not in functions:
            functions.append(made[0])
        kind.append(1 + functions.index(made[0]))
        numbers.append(tuple(float(a) for a in made[2]))
    if len(functions) > SLOTS:
        return None
    functions += [functions[0] if functions else lawkernel.stribeck_mu] * (SLOTS - len(functions))
    return tuple(functions), np.array(kind, dtype=np.int64), np.array(numbers, dtype=float).reshape(-1, 3)


class Solution:
    """What `rate_state_simulate` reads of a segment, as of `scipy.integrate.solve_ivp`'s result:
    ``t``, ``y`` (samples by columns), ``status`` (0 at the end, 1 at an event), ``t_events`` and
    ``y_events`` (one list per event, the one reached holding its time and state)."""

    def __init__(self, t, y, status, events, hit, te, ye):
        self.t, self.y, self.status = t, y, status
        self.t_events = [np.array([te]) if i == hit else np.empty(0) for i in range(events)]
        self.y_events = [ye[None, :] if i == hit else np.empty((0, ye.size)) for i in range(events)]
        self.message = "" if status >= 0 else "failed"


class Failed(Exception):
    """The compiled flow stopped where the Python one says why (a law without a value or with one out
    of range, a step below round-off, too many steps): the run is made again with Radau."""


class Compiled:
    """The compiled flows of ``eq``'s system (`compiled_laws` not None): `solve` for each mode."""

    #: The most steps between two switches (a run that needs more is made again with Radau, which
    #: says where it got to).
    MAX_STEPS = 10**6

    def __init__(self, eq, laws):
        self.eq, (self.callbacks, self.kind, self.numbers) = eq, laws
        system = eq.system
        freq = np.array([hm.frequency for hm in system.harmonics], dtype=float)
        B = np.ascontiguousarray(system.forcing_matrix[:, :2 * freq.size], dtype=float)
        self.fixed = (np.ascontiguousarray(system.inverse_mass), np.ascontiguousarray(system.stiffness, dtype=float),
                      np.ascontiguousarray(system.damping, dtype=float), np.asarray(system.force, dtype=float), B, freq,
                      np.ascontiguousarray(system.directions, dtype=float), np.asarray(eq.V, dtype=float),
                      np.asarray(eq.N, dtype=float), np.ascontiguousarray(eq.Kn, dtype=float),
                      np.ascontiguousarray(eq.push, dtype=float))
        self.h = math.inf
        allowed = OSCILLATOR["fd"].range
        self.bounds = np.array([allowed.lo, allowed.hi], dtype=float)

    def _mode(self):
        eq, n = self.eq, self.eq.n
        stuck = np.array(eq.stuck, dtype=np.int64)
        if stuck.size:
            MiE, G = np.ascontiguousarray(eq.MiE), np.ascontiguousarray(eq.gram_inv)
        else:
            MiE, G = np.zeros((n, 0)), np.zeros((0, 0))
        return (*self.fixed, np.array(eq.mode, dtype=np.int64), self.kind, self.numbers, stuck, MiE, G, self.bounds)

    def _events(self, switches):
        eq = self.eq
        index, kind, level, direction = [], [], [], []
        for e in switches:
            law = eq.laws[e.contact]
            if e.kind == "zero":
                index.append(e.contact), kind.append(ZERO), level.append(0.0)
            elif e.kind == "limit":
                index.append(e.contact), kind.append(LIMIT), level.append(law.max_speed)
            elif e.kind == "release":
                index.append(eq.stuck.index(e.contact))
                kind.append(RELEASE_UP if e.direction > 0 else RELEASE_DOWN), level.append(law.static)
            else:  # "open", "close"
                index.append(e.contact), kind.append(NORMAL), level.append(0.0)
            direction.append(e.direction)
        contact = np.array([e.contact for e in switches], dtype=np.int64)
        return ((np.array(index, dtype=np.int64), np.array(kind, dtype=np.int64), np.array(level, dtype=float),
                 contact), np.array(direction, dtype=float))

    def solve(self, t0: float, t_end: float, y0, t_eval, rtol: float, switches) -> Solution:
        """The segment from ``(t0, y0)`` in ``eq``'s current mode with its ``switches`` (`mode_events`)."""
        ev, directions = self._events(switches)
        y0 = np.asarray(y0, dtype=float)
        scale = max(float(np.abs(y0).max()), 1.0)
        h = self.h if math.isfinite(self.h) else 1e-3 * max(t_end - t0, 1e-300)
        status, hit, t, y, Y, q, h = segment(*self.callbacks, self._mode(), ev, directions, float(t0), y0,
                                             float(t_end), np.asarray(t_eval, dtype=float), rtol, 1e-3 * rtol * scale,
                                             min(h, t_end - t0), self.MAX_STEPS)
        if status not in (DONE, CROSSED) or not np.all(np.isfinite(y)):
            raise Failed
        self.h = h
        return Solution(np.asarray(t_eval[:q], dtype=float), Y[:q].T, 0 if status == DONE else 1, len(switches), hit,
                        t, y)

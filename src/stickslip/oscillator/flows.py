"""Flows of one slip mode: closed form for affine laws, DOP853 otherwise (compiled with the law
where numba can compile it, `CompiledSlip`; in Python, `NumericSlip`).

The classes answer the same three questions for a slip segment that starts at
``(x0, v0)`` at local time 0:

* ``first_crossing(x0, v0, t_max, levels)``: the first time ``v(t)`` crosses one of
  the ``levels`` (``(value, direction)`` pairs, direction +1 upward, -1 downward);
* ``evaluate(t)``: the state on the segment just computed;
* ``jacobian``: the derivative of the end state with respect to the start state.

A start exactly on a level (a departure from the switching line or the section) is
never counted as a crossing.
"""

from __future__ import annotations

import math

import numpy as np
import scipy  # its submodules load on first use (scipy.optimize, scipy.integrate)

from ..errors import NoSolutionError, ParameterError
from ..quantities import OSCILLATOR as Q
from . import kernel  # slipkernel (laws that are not affine) is imported where it runs
from .model import Mode, Oscillator

_EPS = np.finfo(float).eps


def _sign(value: float, tol: float) -> int:
    return 0 if abs(value) <= tol else (1 if value > 0 else -1)


def _root(fun, a: float, b: float) -> float:
    return scipy.optimize.brentq(fun, a, b, xtol=1e-300, rtol=4 * _EPS, maxiter=200)


def _scan(g, times, levels, tol, root=None):
    """First crossing of ``g(t, level) = 0`` over consecutive monotone pieces.

    ``times`` is an iterable of increasing times; ``g`` is monotone between
    neighbours; ``root(level, ta, tb)`` finds the crossing in a piece (default: Brent's method
    on ``g``). Returns ``(t, level_index)`` or ``(last_time, None)``.
    """
    times = iter(times)
    ta = next(times)
    ga = [g(ta, level) for level, _ in levels]
    for tb in times:
        gb = [g(tb, level) for level, _ in levels]
        best = (math.inf, None)
        for index, (level, direction) in enumerate(levels):
            sa, sb = _sign(ga[index], tol), _sign(gb[index], tol)
            if sa != 0 and sb != sa and (direction == 0 or direction == -sa):
                t = tb if sb == 0 else (root(level, ta, tb) if root else _root(lambda t: g(t, level), ta, tb))
                best = min(best, (t, index), key=lambda p: p[0])
        if best[1] is not None:
            return best
        ta, ga = tb, gb
    return ta, None


class AffineSlip:
    """Closed-form flow of a slip mode when ``mu = mu0 - mu1 |v_r|``.

    In mode ``s = sign(v_r)`` the equation is linear with constant coefficients,
    ``m x'' + (c - mu1 N) x' + k x = s N mu0 - mu1 N V``: an oscillator centred at
    ``x_c`` with damping that is negative for a falling law.
    """

    def __init__(self, osc: Oscillator, mode: Mode):
        mu0, mu1 = osc.friction.affine
        s, m, k, n, v = int(mode), osc.mass, osc.stiffness, osc.normal_force, osc.belt_speed
        self.osc, self.mode = osc, mode
        self.x_c = (s * n * mu0 - mu1 * n * v) / k
        self.sigma = -(osc.damping - mu1 * n) / (2.0 * m)
        self.w02 = k / m
        self.om2 = self.w02 - self.sigma**2
        self._x0 = self._v0 = 0.0

    def _state(self, t, x0, v0):
        t = np.asarray(t, dtype=float)
        kernels = kernel.KERNELS.choose(t.size * kernel.SAMPLE_COST)
        xi, v = kernels.state(self.sigma, self.w02, self.om2, x0 - self.x_c, v0, t.ravel())
        kernel.KERNELS.charge(kernels, t.size * kernel.SAMPLE_COST)
        return (xi + self.x_c).reshape(t.shape), v.reshape(t.shape)

    def _pieces(self, x0, v0, t_max):
        """0, the zeros of the acceleration in (0, t_max) (lazily), then t_max."""
        t, xi0 = 0.0, x0 - self.x_c
        next_piece = kernel.KERNELS.choose(0).next_piece
        yield t
        while t < t_max:
            t = next_piece(self.sigma, self.w02, self.om2, xi0, v0, t, t_max)
            yield t

    def first_crossing(self, x0, v0, t_max, levels):
        """First crossing time and level index, or ``(t_max, None)``."""
        self._x0, self._v0 = x0, v0
        xi0 = x0 - self.x_c
        scale = max(abs(v0), math.sqrt(self.w02) * abs(xi0), *(abs(l) for l, _ in levels))
        kernels = kernel.KERNELS.choose(0)
        g = lambda t, level: kernels.velocity_acceleration(self.sigma, self.w02, self.om2, xi0, v0, t)[0] - level
        # each crossing by the event loop's own root finder (safeguarded Newton on the closed form)
        root = lambda level, ta, tb: kernels.velocity_root(self.sigma, self.w02, self.om2, xi0, v0, level, ta, tb)
        t, index = _scan(g, self._pieces(x0, v0, t_max), levels, 16 * _EPS * scale, root)
        return (t_max, None) if index is None else (t, index)

    def evaluator(self):
        """Callable ``t -> (x, v)`` on the last segment (local time)."""
        x0, v0 = self._x0, self._v0
        return lambda t: self._state(t, x0, v0)

    def velocity_range(self, x0, v0, duration) -> tuple[float, float]:
        """Smallest and largest velocity over ``[0, duration]`` from ``(x0, v0)``: exact, at the
        ends and at the acceleration's zeros between them (where the velocity is extreme)."""
        _, v = self._state(np.fromiter(self._pieces(x0, v0, duration), float), x0, v0)
        return float(v.min()), float(v.max())

    def jacobian(self, t):
        """``d(x, v)(t) / d(x0, v0)``: the matrix exponential, in closed form."""
        c, s = kernel.KERNELS.choose(0).damped_cos_sin(self.sigma, self.w02, self.om2, t)
        return np.array([[c - self.sigma * s, s], [-self.w02 * s, c + self.sigma * s]])


class _Integrated:
    """What the numerical flows share: the end of the last segment (``_end``: ``x, v`` and, with
    ``variational``, the 2 x 2 derivative by rows) and its Jacobian."""

    def end(self):
        """``(x, v)`` at the end of the last segment."""
        return float(self._end[0]), float(self._end[1])

    def jacobian(self, t=None):
        """Derivative of the end state of the last segment w.r.t. its start state."""
        if not self.variational:
            raise RuntimeError("jacobian needs variational=True")
        return np.asarray(self._end[2:]).reshape(2, 2)


class NumericSlip(_Integrated):
    """Flow of a slip mode for a general law: DOP853 (order 8) with dense output.

    Crossings are located with Brent's method on the dense output of the step where
    the sign changes. With ``variational=True`` the 2x2 variational equations are
    integrated along, for Floquet multipliers.
    """

    def __init__(self, osc: Oscillator, mode: Mode, rtol=1e-12, atol=1e-14, variational=False):
        self.osc, self.mode, self.rtol, self.atol = osc, mode, rtol, atol
        self.variational = variational
        self._pieces: list = []

    def _rhs(self, t, y):
        o, s = self.osc, int(self.mode)
        x, v = y[0], y[1]
        v_r = s * max(abs(o.belt_speed - v), 1e-300)  # on the mode's side of v_r = 0
        mu = o.friction.kinetic(v_r)
        acc = (s * o.normal_force * mu - o.damping * v - o.stiffness * x) / o.mass
        if not self.variational:
            return np.array([v, acc])
        # F = s N mu(v_r) with v_r = V - v, so dF/dv = -s N mu'(v_r)
        dacc_dv = (-s * o.normal_force * o.friction.slope(v_r) - o.damping) / o.mass
        jac = np.array([[0.0, 1.0], [-o.stiffness / o.mass, dacc_dv]])
        phi = y[2:].reshape(2, 2)
        return np.concatenate(([v, acc], (jac @ phi).ravel()))

    def first_crossing(self, x0, v0, t_max, levels):
        y0 = [x0, v0] + ([1.0, 0.0, 0.0, 1.0] if self.variational else [])
        scale = max(abs(v0), self.osc.omega * abs(x0), *(abs(l) for l, _ in levels), 1e-300)
        atol = np.full(len(y0), self.atol * max(scale, self.osc.belt_speed))
        solver = scipy.integrate.DOP853(self._rhs, 0.0, y0, t_max, rtol=self.rtol, atol=atol)
        self._pieces, self._extremes = [], [v0]
        tol = 16 * _EPS * scale
        while solver.status == "running":
            t_old, y_old, a_old = solver.t, solver.y.copy(), solver.f[1]
            message = solver.step()
            if solver.status == "failed":
                raise NoSolutionError(f"the slip flow could not be integrated (DOP853: {message}): the friction law "
                                      "changes faster than double precision resolves")
            dense = solver.dense_output()
            self._pieces.append((t_old, solver.t, dense))
            times = [t_old, solver.t]
            if a_old * solver.f[1] < 0:  # a velocity extremum inside the step: split there
                acc = lambda t: float(self.osc.acceleration(*dense(t)[:2], self.mode))
                times.insert(1, _root(acc, t_old, solver.t))
            g = lambda t, level: (y_old[1] if t == t_old else float(dense(t)[1])) - level
            t_hit, index = _scan(g, times, levels, tol)
            if index is not None:
                self._extremes += [float(dense(t)[1]) for t in times[1:] if t < t_hit] + [float(dense(t_hit)[1])]
                self._end = dense(t_hit)
                return t_hit, index
            self._extremes += [float(dense(t)[1]) for t in times[1:]]
        self._end = solver.y
        return t_max, None

    def evaluator(self):
        """Callable ``t -> (x, v)`` on the last segment (local time)."""
        pieces = list(self._pieces)
        starts = np.array([p[0] for p in pieces])

        def evaluate(t):
            t = np.atleast_1d(np.asarray(t, dtype=float))
            idx = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, len(pieces) - 1)
            out = np.empty((2, t.size))
            for i in np.unique(idx):
                sel = idx == i
                out[:, sel] = pieces[i][2](t[sel])[:2]
            return out[0], out[1]

        return evaluate

    def speed_extremes(self):
        return np.asarray(self._extremes)



def compiled_failure(status: int, value: float):
    """Raise what a compiled run's failure ``status`` (`slipkernel`) means (``value``: the coefficient met)."""
    from . import slipkernel

    if status == slipkernel.BAD_LAW:
        raise ParameterError("mu(v_r)", float(value), f"a friction coefficient {Q['fd'].allowed}")
    raise NoSolutionError("the slip flow could not be integrated (DOP853: the step fell below the round-off of the "
                          "time): the friction law changes faster than double precision resolves")


class CompiledSlip(_Integrated):
    """`NumericSlip`'s DOP853 at the same tolerances, compiled with the law (`slipkernel`):
    ``law = (mu, slope, numbers)`` from `stickslip.lawkernel.compiled`."""

    def __init__(self, osc: Oscillator, mode: Mode, law, rtol=1e-12, atol=1e-14, variational=False):
        self.osc, self.mode, self.rtol, self.atol = osc, mode, rtol, atol
        self.variational = variational
        self.mu, self.slope = law[0], law[1]
        self.params = np.array(law[2], dtype=float)
        allowed = Q["fd"].range
        self.p = np.array([osc.mass, osc.stiffness, osc.damping, osc.normal_force, osc.belt_speed, int(mode),
                           allowed.lo, allowed.hi])
        self._run, self._h = None, 0.01 / osc.omega  # the first step to try: the last segment's next

    def first_crossing(self, x0, v0, t_max, levels):
        y0 = np.array([x0, v0] + ([1.0, 0.0, 0.0, 1.0] if self.variational else []))
        scale = max(abs(v0), self.osc.omega * abs(x0), *(abs(l) for l, _ in levels), 1e-300)
        atol = self.atol * max(scale, self.osc.belt_speed)
        values = np.array([float(l) for l, _ in levels])
        sides = np.array([int(d) for _, d in levels], dtype=np.int64)
        h0 = min(t_max, self._h)
        from . import slipkernel

        run = slipkernel.segment(self.mu, self.slope, self.params, self.p, y0, float(t_max), values, sides,
                                 self.rtol, atol, 16 * _EPS * scale, h0, 64)
        status, index, t, y = run[:4]
        if status in (slipkernel.BAD_LAW, slipkernel.STEP_TOO_SMALL):
            compiled_failure(status, run[10])
        self._run, self._end, self._h = run, y, run[11]
        return (t, int(index)) if status == slipkernel.CROSSED else (t_max, None)

    def evaluator(self):
        """Callable ``t -> (x, v)`` on the last segment (local time)."""
        run = self._run  # (a new run's arrays: the next search makes its own)
        steps = run[4]
        return StepPieces(self.mu, self.slope, self.params, self.p, run[5][:steps], run[6][:steps], run[7][:steps],
                          run[2], run[3][:2])

    def speed_extremes(self):
        return np.array([self._run[8], self._run[9]])



class StepPieces:
    """``t -> (x, v)`` on a segment of the compiled flow, from its accepted steps (start times
    ``starts``, states, slopes): a step from the start of the step ``t`` falls in; its end
    (``end_t``, ``end``) as the search found it."""

    def __init__(self, mu, slope, params, p, starts, states, slopes, end_t, end):
        self._args = (mu, slope, params, p)
        self._steps = (np.ascontiguousarray(starts), states, slopes)
        self.end_t, self.end = float(end_t), (float(end[0]), float(end[1]))
        self._two = None

    def __call__(self, t):
        t = np.atleast_1d(np.asarray(t, dtype=float))
        starts, states, slopes = self._steps
        if self._two is None:  # the states without the variational part, made at the first call
            self._two = np.ascontiguousarray(states[:, :2]), np.ascontiguousarray(slopes[:, :2])
        flat = np.ascontiguousarray(t.ravel())
        from . import slipkernel

        x, v = slipkernel.evaluate(*self._args, starts, *self._two, starts.size, flat)
        at_end = flat >= self.end_t  # the end itself: the state the search stopped at
        x[at_end], v[at_end] = self.end
        return x, v

"""The affine flow of one contact state, and its first event, in closed form.

In a state (each contact sticking, ``0``, slipping with ``sign(v_r) = +-1``, or open, ``2``) and
with laws affine in the slip speed (``mu = mu0 - mu1 |v_r|``), the motion is linear:

    M a = r + W_S lam,   r = f - C_eff v - K x + sum_slip w_j N_j (s_j mu0_j - mu1_j V_j),
    C_eff = C - sum_slip N_j mu1_j w_j w_j^T,   W_S^T a = 0,

so ``lam = -D^-1 W_S^T M^-1 r`` (``D = W_S^T M^-1 W_S``, minimum-norm where sticking contacts are
redundant) and ``z = (x, v, e, 1)`` obeys ``z' = A z``: ``z(t) = expm(t A) z(0)``, exact to round-off.
The harmonic forces ``B e`` (`System.harmonics`) ride on ``e = (cos W t, sin W t, ...)``, whose
motion ``e' = G e`` is a rotation: ``f`` above is ``f + B e``, affine in ``z`` as the rest. A
`ForceHistory` adds the time to ``e`` (``t' = 1``) and, on each of its pieces, ``offset + rate t``
to ``f``: a flow is then that of one piece.
Every switching function is linear in ``z``: a slipping contact's ``s_j v_r``, a sticking one's
``f_s N -+ F``, a unilateral contact's ``N(x)`` (opening; ``-N(x)`` while open: closing; a normal
force ``N(x) = N_0 - k_n n . x`` adds ``k_n n n^T`` to the stiffness and, slipping, the friction
``s mu0 k_n w n^T``; a rigid one's normal force is the reaction of ``n . x = 0``, solved with the
sticking contacts' forces, and while open its gap ``n . x`` is the closing function). The first
time one of them reaches zero is found on the exact flow, at steps
of a fraction of the fastest time scale of ``A`` (a sign change, or a dip between two steps
seen by the derivative, which is linear in ``z`` too), then on the step's Taylor series to
round-off: compiled, in `stickslip.system.search`.
"""

from __future__ import annotations

import functools
import math
from contextlib import contextmanager
from contextvars import ContextVar

import numpy as np
from scipy.linalg import expm

from .model import System
from .search import EVENT, NO_EVENT, search

__all__ = ["Flow", "shares_flows", "CACHE_BYTES", "SLIP_ZERO", "STICK_LIMIT", "LAW_LIMIT", "OPENING", "CLOSING", "OPEN", "STATE_FLAGS"]

_NO_STEP, _EMPTY = np.zeros((1, 1)), np.zeros(0)
#: Steps per fastest time scale ``1/max|eig(A)|`` of the event search: a switching function
#: is a sum of the flow's modes, so it changes sign at most about once within such a step
#: (a dip that returns within it is seen by the derivative's sign change).
STEPS_PER_SCALE = 4.0
#: Steps of a flow's event search taken by its Taylor series before its step's matrix exponential
#: is computed (and kept): a flow visited briefly never pays for the exponential of a large matrix.
EXPM_AFTER = 64
#: What a switching function's zero means: a slipping contact's slip velocity reached zero, a
#: sticking one's force reached f_s N, a slipping one's slip speed reached its law's limit.
#: A unilateral contact's normal force reached zero (it opens), an open one's gap closed.
SLIP_ZERO, STICK_LIMIT, LAW_LIMIT, OPENING, CLOSING = 0, 1, 2, 3, 4
#: The state of an open contact (no force; the others are -1, 0, 1: reverse slip, stick, slip).
OPEN = 2
#: Bytes of flows one cache keeps (`Flow.cached`): a wave on a ring of 512 nodes meets hundreds of
#: contact states, each a flow of 2049-square matrices (about 0.1 GB); kept all, a run took 16 GB.
CACHE_BYTES = 2 * 2**30
#: CF flags of a variable of contact states.
STATE_FLAGS = {"flag_values": np.array([-1, 0, 1, OPEN], dtype=np.int8), "flag_meanings": "reverse_slip stick slip open"}


def _nonzero_rows(X: np.ndarray) -> np.ndarray:
    """The indices of the rows of ``X`` with a nonzero."""
    return np.flatnonzero(np.any(X != 0.0, axis=1))


def _pinv(X: np.ndarray) -> np.ndarray:
    """The pseudo-inverse of the square ``X``; of a diagonal one (contacts on distinct degrees of freedom
    of a lumped mass) without an SVD: ``1/d`` where ``|d|`` exceeds `numpy.linalg.pinv`'s cutoff, else 0."""
    d = np.diag(X)
    if np.any(X - np.diag(d)):
        return np.linalg.pinv(X)
    big = np.abs(d) > 1e-15 * np.abs(d).max(initial=0.0)
    return np.diag(np.divide(1.0, d, out=np.zeros_like(d), where=big))


#: The flows shared by one computation (`Flow.shared`): its system and the cache, or None.
_SHARED: ContextVar = ContextVar("stickslip_shared_flows", default=None)


def shares_flows(function):
    """``function(system, ...)`` run within `Flow.shared` of its ``system`` (the first argument)."""
    @functools.wraps(function)
    def within(system, *args, **kwargs):
        if not isinstance(system, System):  # the function's own checks say what it takes
            return function(system, *args, **kwargs)
        with Flow.shared(system):
            return function(system, *args, **kwargs)
    return within


class Flow:
    """The flow of the contact state ``states`` (a tuple of -1, 0, 1 per contact), on the ``piece``
    of the system's `ForceHistory` (if it has one)."""

    def __init__(self, system: System, states: tuple[int, ...], piece: int = 0):
        n, size = system.dofs, system.size
        self.states = tuple(int(s) for s in states)
        W, minv = system.directions, system.apply_inverse_mass
        stuck = [i for i, s in enumerate(self.states) if s == 0]
        k_eff, c_eff = system.stiffness, system.damping  # copied only where a contact changes them
        g = system.force.copy()
        B = system.forcing_matrix  # the harmonic forces B e: carried with g (columns 2n:-1 of z)
        if system.history is not None:  # this piece's offset + rate t (t: the last of e)
            offset, rate, _ = system.history.piece(piece)
            g += offset
            B = B.copy()
            B[:, -1] = rate
        e = slice(2 * n, size - 1)
        force_rows = np.zeros((len(self.states), size))
        normal = system.normal_rows.copy()
        kn = system.normal_directions  # k_n n per contact (columns)
        push = np.zeros(len(self.states))  # N(x) n on the structure: k_n n n^T, N_0 n
        fric = np.zeros(len(self.states))  # a unilateral contact slipping: F = s mu0 N(x): s mu0 k_n w n^T, ...
        falling = np.zeros(len(self.states))  # a slipping contact's N mu1: C_eff = C - sum N mu1 w w^T
        closed = [j for j, (c, s) in enumerate(zip(system.contacts, self.states)) if c.rigid and s != OPEN]
        pressed = []  # the force direction of each closed rigid contact's reaction: n (+ s mu0 w slipping)
        for j, (c, s) in enumerate(zip(system.contacts, self.states)):
            if s == OPEN:
                normal[j] = 0.0
                continue
            if c.rigid:
                pressed.append(c.normal_direction + (s * c.friction.affine[0] * c.direction if s else 0.0))
                continue
            if c.pushes:
                push[j] = 1.0
                g += c.normal_direction * c.normal_force
            if s == 0:
                continue
            mu0, mu1 = c.friction.affine
            w, V = c.direction, c.surface_speed
            if c.unilateral:  # Coulomb only
                force_rows[j] = s * mu0 * normal[j]
                fric[j] = s * mu0
                g += w * s * mu0 * c.normal_force
                continue
            N = c.normal_force
            falling[j] = N * mu1
            g += w * N * (s * mu0 - mu1 * V)
            force_rows[j, n:2 * n] = N * mu1 * w
            force_rows[j, -1] = N * (s * mu0 - mu1 * V)
        # M^-1 K_eff and M^-1 C_eff: the system's own (computed once) unless a contact changes K or C
        if push.any() or fric.any():
            k_eff = k_eff + (system.normal_units * push + W * fric) @ kn.T
            minv_k = minv(k_eff)
        else:
            minv_k = system.inverse_mass_stiffness
        if falling.any():
            c_eff = c_eff - (W * falling) @ W.T
            minv_c = minv(c_eff)
        else:
            minv_c = system.inverse_mass_damping
        minv_g, minv_b = minv(g), minv(B)
        if stuck or closed:
            # M a = r + E mu, G^T a = 0 (sticking: w . a = 0; closed: n . a = 0): mu = -L r,
            # L = (G^T M^-1 E)^+ G^T M^-1 and P = M^-1 - M^-1 E L; P's products with K, C, g, B are
            # taken as M^-1 (.) - M^-1 E (L (.)): the constraints (a few columns) are all that is
            # multiplied per state, never an n x n product (a ring of 2N = 1024 degrees of freedom:
            # the wave-stability figure's flows spent 85 s of 230 in n x n products)
            G = np.hstack([W[:, stuck], system.normal_units[:, closed]])
            E = np.hstack([W[:, stuck], np.array(pressed).T.reshape(n, len(closed))])
            MinvG, MinvE = minv(G), minv(E)
            Ainv = _pinv(MinvG.T @ E)  # (G^T M^-1 E)^+: M^-1 is symmetric
            L = Ainv @ MinvG.T
            # a contact's direction has a few nonzeros (and M^-1 E too, a lumped mass): the rows where M^-1 G
            # and M^-1 E are nonzero are all that the products need (all rows where they are dense)
            rg, rows_e = _nonzero_rows(MinvG), _nonzero_rows(MinvE)
            LK, Lg, LB = Ainv @ (MinvG[rg].T @ k_eff[rg]), L @ g, L @ B
            LC = Ainv @ (MinvG[rg].T @ c_eff[rg]) if c_eff.any() else None
            mu = np.zeros((len(stuck) + len(closed), size))
            mu[:, :n], mu[:, -1], mu[:, e] = LK, -Lg, -LB
            if LC is not None:
                mu[:, n:2 * n] = LC
            force_rows[stuck] = mu[:len(stuck)]
            normal[closed] = mu[len(stuck):]
            for j in closed:
                if self.states[j] != 0:
                    force_rows[j] = self.states[j] * system.contacts[j].friction.affine[0] * normal[j]
            # the velocity put on the constraints by impulses along the forces' directions: v + Q (V - G^T v),
            # Q = M^-1 E (G^T M^-1 E)^+ (sticking: the smallest change in the metric of M; a rigid contact
            # landing: a plastic impact with the friction impulse of its state)
            Q = MinvE @ Ainv
            target = np.array([system.contacts[i].surface_speed for i in stuck] + [0.0] * len(closed))
            self._stick = (Q, G, target)
            Nc, MinvNc = G[:, len(stuck):], MinvG[:, len(stuck):]  # the closed rigid contacts: n . x = 0 exactly
            self._onto = (MinvNc @ _pinv(Nc.T @ MinvNc), Nc) if closed else None
            # an impact: impulses only where a rigid contact holds (a finite normal force takes none)
            held = [k for k, i in enumerate(stuck) if system.contacts[i].rigid] + list(range(len(stuck), G.shape[1]))
            if len(held) == G.shape[1]:
                Gi, MinvEi, Ki = G, MinvE, Ainv
            else:
                Gi, MinvEi = G[:, held], MinvE[:, held]
                Ki = _pinv(Gi.T @ MinvEi)
            self._impact = (MinvEi, Ki, Gi, target[held], [i for i in stuck if system.contacts[i].rigid], closed)
        else:
            self._stick = self._onto = self._impact = None
        self.normal_rows = normal
        A = np.zeros((size, size))
        A[np.arange(n), n + np.arange(n)] = 1.0
        A[n:2 * n, :n] = -minv_k
        A[n:2 * n, n:2 * n] = -minv_c
        A[n:2 * n, -1] = minv_g
        A[n:2 * n, e] = minv_b
        if stuck or closed:  # -P K = -M^-1 K + M^-1 E (L K), ...: on the rows of M^-1 E's nonzeros
            ME = MinvE[rows_e]
            A[n + rows_e, :n] += ME @ LK
            if LC is not None:
                A[n + rows_e, n:2 * n] += ME @ LC
            A[n + rows_e, -1] -= ME @ Lg
            A[n + rows_e, e] -= ME @ LB
        A[e, e] = system.rotation
        A[e, -1] = system.clock
        self.A, self.n = A, n
        self.force_rows = force_rows
        slip = np.zeros((len(self.states), size))  # v_r = V - w . v
        slip[:, n:2 * n] = -W.T
        slip[:, -1] = [c.surface_speed for c in system.contacts]
        self.slip_rows = slip
        # switching functions (an event when one reaches zero from above), in the order of the contacts:
        # each row a factor times a row of one source (the rows built together, per kind)
        owners, kinds, factors = [], [], []
        for i, (c, s) in enumerate(zip(system.contacts, self.states)):
            if s == OPEN:  # N(x) < 0 while open (a rigid contact: the gap n . x > 0): closes where it reaches 0
                owners.append(i), kinds.append(CLOSING), factors.append(1.0 if c.rigid else -1.0)
                continue
            if c.unilateral:  # N(x) > 0 while closed: opens where it reaches 0
                owners.append(i), kinds.append(OPENING), factors.append(1.0)
            if s == 0:  # f_s N -+ F
                owners += [i, i]
                kinds += [STICK_LIMIT, STICK_LIMIT]
                factors += [-1.0, 1.0]
            else:  # s v_r; and -s v_r + max_speed where the law ends
                owners.append(i), kinds.append(SLIP_ZERO), factors.append(float(s))
                if math.isfinite(c.friction.max_speed):
                    owners.append(i), kinds.append(LAW_LIMIT), factors.append(-float(s))
        owners, kinds, factors = np.array(owners), np.array(kinds), np.array(factors)
        rows = np.empty((owners.size, size))
        for kind, source in ((CLOSING, system.normal_rows), (OPENING, normal), (SLIP_ZERO, slip), (LAW_LIMIT, slip),
                             (STICK_LIMIT, force_rows)):
            k = np.flatnonzero(kinds == kind)
            if k.size:
                rows[k] = factors[k, None] * source[owners[k]]
        k = np.flatnonzero(kinds == STICK_LIMIT)
        if k.size:
            static = np.array([system.contacts[i].friction.static for i in owners[k]])
            rows[k] = static[:, None] * normal[owners[k]] + rows[k]
        k = np.flatnonzero(kinds == LAW_LIMIT)
        if k.size:
            rows[k, -1] += [system.contacts[i].friction.max_speed for i in owners[k]]
        self.rows, self.owners, self.kinds = rows, owners, kinds
        # a bound of the fastest time scale: the infinity norm of A scaled by diag(s I, I), s^2 = |P K|
        # (at least the spectral radius, and equal to it for a chain's Laplacian; no eigensolve)
        stiff = float(np.abs(A[n:2 * n, :n]).sum(axis=1).max()) if n else 0.0
        damp = float(np.abs(A[n:2 * n, n:2 * n]).sum(axis=1).max()) if n else 0.0
        rho = max(math.sqrt(stiff) + damp, max((h.frequency for h in system.harmonics), default=0.0))
        self.h = STEPS_PER_SCALE ** -1 / rho if rho > 0 else math.inf
        times = None if system.history is None else system.history.times
        if times is not None and 0 < piece < times.size:  # the step resolves a ramp's piece too (its terms grow)
            self.h = min(self.h, (times[piece] - times[piece - 1]) / STEPS_PER_SCALE)
        self._step = None
        self._taken = 0  # steps of the event search on this flow (its step's exponential once many)
        #: About the memory this flow holds (its step's exponential counted as if computed), in bytes.
        self.nbytes = 2 * A.nbytes + sum(a.nbytes for a in (self.rows, force_rows, normal, slip))

    @classmethod
    def cached(cls, system: System, states: tuple, cache: dict, piece: int = 0) -> "Flow":
        """The flow of ``states``, built once per ``cache`` (a run or a monodromy revisits few states;
        one cache per ``piece`` of a force history) while the cache holds at most `CACHE_BYTES`: the
        flows used longest ago are dropped beyond it (built again if met again)."""
        key, shared = states, _SHARED.get()
        if shared is not None and shared[0] is system:  # one cache for the whole computation (`shared`)
            cache, key = shared[1], (states, piece)
        flow = cache.pop(key, None)
        if flow is None:
            flow = cls(system, states, piece)
        cache[key] = flow  # the most recently used last
        while len(cache) > 1 and len(cache) * flow.nbytes > CACHE_BYTES:
            del cache[next(iter(cache))]
        return flow

    @staticmethod
    @contextmanager
    def shared(system: System):
        """Within it, every flow of ``system`` that `cached` gives is built once for all the runs,
        monodromies and Newton steps of one computation (a cycle's returns revisit the same contact
        states; each run's own cache rebuilt them: 12,681 flows for 24,042 uses in the waves' stability
        figure), in the cache's bytes (`CACHE_BYTES`). Scoped, so that a computation's numbers depend
        on its own inputs only (a flow keeps its step's exponential once its search has taken many)."""
        token = _SHARED.set((system, {}))
        try:
            yield
        finally:
            _SHARED.reset(token)

    def propagate(self, z: np.ndarray, t: float) -> np.ndarray:
        """``expm(t A) z``."""
        return expm(t * self.A) @ z

    def stick(self, z: np.ndarray) -> np.ndarray:
        """``z`` with the slip velocity of this state's sticking contacts exactly zero and the normal
        velocity of its closed rigid contacts too: ``v + Q (V - G^T v)``, ``G`` the constraints'
        directions, ``V`` their speeds, by impulses along the constraint forces' directions ``E``,
        ``Q = M^-1 E (G^T M^-1 E)^+`` (without rigid contacts the smallest change of the velocity in
        the metric of M, `simulate.zero_slip`; a rigid contact landing: its plastic impact, with the
        friction impulse ``s f_d`` times the normal one slipping). The closed rigid contacts' gaps are
        set to exactly 0 too (the smallest change of ``x`` in the metric of M: round-off after a landing,
        which the saltation already maps onto the surface)."""
        if self._stick is None:
            return z
        Q, G, V = self._stick
        n = self.n
        z = z.copy()
        z[n:2 * n] += Q @ (V - G.T @ z[n:2 * n])
        if self._onto is not None:  # and on their surfaces (a landing found to round-off: the gap exactly 0)
            Lx, Nc = self._onto
            z[:n] -= Lx @ (Nc.T @ z[:n])
        return z

    def impact(self, z: np.ndarray) -> tuple[np.ndarray, dict]:
        """``(z+, impulses)``: a plastic impact onto this state's closed rigid contacts (and the
        tangential constraint of those that stick): the velocity put on them by impulses along their
        forces' directions (with the friction impulse of those slipping), and each closed rigid
        contact's normal impulse (contact -> impulse; < 0: it would pull; those that stick have their
        tangential one in ``tangential_impulses`` after the call). The other contacts take no impulse
        (a finite normal force); the closed ones' gaps are set to exactly 0 as in `stick`."""
        if self._impact is None:
            return z, {}
        ME, K, G, V, stuck, closed = self._impact
        n = self.n
        z = z.copy()
        mu = K @ (V - G.T @ z[n:2 * n])
        z[n:2 * n] += ME @ mu
        if self._onto is not None:
            Lx, Nc = self._onto
            z[:n] -= Lx @ (Nc.T @ z[:n])
        impulses = {j: float(mu[len(stuck) + k]) for k, j in enumerate(closed)}
        self.tangential_impulses = {j: float(mu[k]) for k, j in enumerate(stuck)}
        return z, impulses

    def projection(self) -> np.ndarray:
        """The linear part of `impact` on ``(x, v)`` (2n x 2n): the reset of a plastic impact."""
        n = self.n
        out = np.eye(2 * n)
        if self._impact is not None:
            ME, K, G, _, _, _ = self._impact
            out[n:, n:] -= ME @ K @ G.T
        return out

    def project(self, X: np.ndarray) -> np.ndarray:
        """``projection() @ X`` (``X`` a vector or 2n rows) without forming the projection: the identity
        but on the velocities, ``v - M^-1 E K G^T v`` (a few columns)."""
        out = np.array(X, dtype=float)
        if self._impact is not None:
            ME, K, G, _, _, _ = self._impact
            n = self.n
            out[n:] -= ME @ (K @ (G.T @ out[n:]))
        return out

    def acceleration(self, z: np.ndarray) -> np.ndarray:
        return (self.A @ z)[self.n:2 * self.n]

    def first_event(self, z0: np.ndarray, t_max: float):
        """``(t, z(t), rows)``: the first switching time within ``(0, t_max]`` and the switching
        functions (indices of ``rows``: their contact in ``owners``, what they mean in ``kinds``)
        that reached zero there; ``(t_max, z(t_max), ())`` if none. Compiled (`search`): within a
        step the flow is its Taylor series, so the roots are found on polynomials; a flow
        searched for more than `EXPM_AFTER` steps has its step's matrix exponential made and kept."""
        t, z, scale = 0.0, np.ascontiguousarray(z0, dtype=float), _EMPTY
        while True:
            E = self._step if self._step is not None else _NO_STEP
            status, dt, z, hit, taken = search(self.A, self.rows, E, self._step is not None, z, t_max - t,
                                               self.h if np.isfinite(self.h) else t_max, scale,
                                               max(1, EXPM_AFTER - self._taken))
            self._taken += taken
            t += dt
            if status == EVENT:
                return t, z, tuple(hit.tolist())
            if status == NO_EVENT:
                return t_max, z, ()
            scale = np.abs(self.rows) @ np.abs(z0)  # the start's
            self._step = expm(self.h * self.A)

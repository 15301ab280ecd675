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

import math

import numpy as np
from scipy.linalg import expm

from .model import System
from .search import EVENT, NO_EVENT, search

__all__ = ["Flow", "CACHE_BYTES", "SLIP_ZERO", "STICK_LIMIT", "LAW_LIMIT", "OPENING", "CLOSING", "OPEN", "STATE_FLAGS"]

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


class Flow:
    """The flow of the contact state ``states`` (a tuple of -1, 0, 1 per contact), on the ``piece``
    of the system's `ForceHistory` (if it has one)."""

    def __init__(self, system: System, states: tuple[int, ...], piece: int = 0):
        n, size = system.dofs, system.size
        self.states = tuple(int(s) for s in states)
        W, Minv = system.directions, system.inverse_mass
        stuck = [i for i, s in enumerate(self.states) if s == 0]
        c_eff = system.damping.copy()
        k_eff = system.stiffness.copy()
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
            c_eff -= N * mu1 * np.outer(w, w)
            g += w * N * (s * mu0 - mu1 * V)
            force_rows[j, n:2 * n] = N * mu1 * w
            force_rows[j, -1] = N * (s * mu0 - mu1 * V)
        if push.any():
            k_eff += (system.normal_units * push) @ kn.T
        if fric.any():
            k_eff += (W * fric) @ kn.T
        if stuck or closed:
            # M a = r + E mu, G^T a = 0 (sticking: w . a = 0; closed: n . a = 0): mu = -L r
            G = np.hstack([W[:, stuck], system.normal_units[:, closed]])
            E = np.hstack([W[:, stuck], np.array(pressed).T.reshape(n, len(closed))])
            # one pseudo-inverse and one M^-1 E serve L, Q and (all constraints held) the impact:
            # the same products in the same order as written out three times (2N = 256 degrees of
            # freedom: the wave-stability figure's flows spent 13 s of 20 in three equal SVDs)
            Ainv, MinvE = np.linalg.pinv(G.T @ Minv @ E), Minv @ E
            L = Ainv @ G.T @ Minv
            P = Minv - MinvE @ L
            mu = np.zeros((len(stuck) + len(closed), size))
            mu[:, :n], mu[:, n:2 * n], mu[:, -1], mu[:, e] = L @ k_eff, L @ c_eff, -L @ g, -L @ B
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
            Nc = system.normal_units[:, closed]  # the closed rigid contacts' positions: n . x = 0 exactly
            self._onto = (Minv @ Nc @ np.linalg.pinv(Nc.T @ Minv @ Nc), Nc) if closed else None
            # an impact: impulses only where a rigid contact holds (a finite normal force takes none)
            held = [k for k, i in enumerate(stuck) if system.contacts[i].rigid] + list(range(len(stuck), G.shape[1]))
            if len(held) == G.shape[1]:
                Gi, MinvEi, Ki = G, MinvE, Ainv
            else:
                Gi, Ei = G[:, held], E[:, held]
                MinvEi, Ki = Minv @ Ei, np.linalg.pinv(Gi.T @ Minv @ Ei)
            self._impact = (MinvEi, Ki, Gi, target[held], [i for i in stuck if system.contacts[i].rigid], closed)
        else:
            P = Minv
            self._stick = self._onto = self._impact = None
        self.normal_rows = normal
        A = np.zeros((size, size))
        A[:n, n:2 * n] = np.eye(n)
        A[n:2 * n, :n] = -P @ k_eff
        A[n:2 * n, n:2 * n] = -P @ c_eff
        A[n:2 * n, -1] = P @ g
        A[n:2 * n, e] = P @ B
        A[e, e] = system.rotation
        A[e, -1] = system.clock
        self.A, self.n = A, n
        self.force_rows = force_rows
        slip = np.zeros((len(self.states), size))  # v_r = V - w . v
        slip[:, n:2 * n] = -W.T
        slip[:, -1] = [c.surface_speed for c in system.contacts]
        self.slip_rows = slip
        rows, owners, kinds = [], [], []  # switching functions: an event when one reaches zero from above
        for i, (c, s) in enumerate(zip(system.contacts, self.states)):
            if s == OPEN:  # N(x) < 0 while open (a rigid contact: the gap n . x > 0): closes where it reaches 0
                rows.append((1.0 if c.rigid else -1.0) * c.normal_row(n, system.extra))
                owners.append(i)
                kinds.append(CLOSING)
                continue
            if c.unilateral:
                rows.append(normal[i].copy())
                owners.append(i)
                kinds.append(OPENING)
            if s == 0:
                limit = c.friction.static * normal[i]
                rows += [limit - force_rows[i], limit + force_rows[i]]
                owners += [i, i]
                kinds += [STICK_LIMIT, STICK_LIMIT]
            else:
                rows.append(s * slip[i])
                owners.append(i)
                kinds.append(SLIP_ZERO)
                if math.isfinite(c.friction.max_speed):  # the law holds up to it: |v_r| < max_speed
                    valid = -s * slip[i]
                    valid[-1] += c.friction.max_speed
                    rows.append(valid)
                    owners.append(i)
                    kinds.append(LAW_LIMIT)
        self.rows, self.owners, self.kinds = np.array(rows), np.array(owners), np.array(kinds)
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
        flow = cache.pop(states, None)
        if flow is None:
            flow = cls(system, states, piece)
        cache[states] = flow  # the most recently used last
        while len(cache) > 1 and len(cache) * flow.nbytes > CACHE_BYTES:
            del cache[next(iter(cache))]
        return flow

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

"""The FE annulus in a breathing motion bouncing on the shaft, against the exact solution of
the same semi-discrete problem.

Frictionless (``f = 0``), axisymmetric: the ring starts in steady contact (Lamé state) with
an outward velocity proportional to it, flies off, comes back, is held on the shaft and
lifts off again. The semi-discrete problem ``M u'' + K u = C^T lambda`` (the annulus's
lumped mass and assembled sparse stiffness) is solved exactly, event by event, by modal
superposition: in flight ``lambda = 0``; at impact the contact nodes stop (a lumped-mass
node meeting a rigid wall: restitution 0, the limit of the scheme's contact step as
``dt -> 0``); held, ``u_r = delta`` at the contact nodes until their reaction
``(K u)_r`` vanishes. The explicit scheme must find the impact, lift-off and next impact
within a bound in units of its step, and the energy left after the rebound must converge
to the exact one as the step is refined. Bounds fixed from the scheme's theory before the
runs: event times within 1.5 steps at beta2 = 1/2 and 4 steps at beta2 = 0.9 (the numerical
damping delays the motion), energy error of order >= 1 at beta2 = 1/2 and decreasing at 0.9.
"""

import numpy as np
import pytest
import scipy.linalg as sl
import scipy.optimize as so

from stickslip.brake import BrakeParams
from stickslip.brake.fem import FemScheme
from stickslip.contact.energy import trace

PARAMS = BrakeParams(xi=1.5, nu=0.3, gamma=1e-2, delta=1e-3, friction=0.0)
COURANTS = (0.8, 0.4, 0.2)


class Modal:
    """``M y'' + K y = K offset`` solved exactly (``M`` diagonal) from ``y(0), y'(0)``."""

    def __init__(self, M, K, offset):
        w2, self.V = sl.eigh(K, np.diag(M))
        self.w, self.M, self.offset = np.sqrt(w2), M, offset

    def start(self, y0, v0):
        self.q0, self.dq0 = self.V.T @ (self.M * (y0 - self.offset)), self.V.T @ (self.M * v0)
        return self

    def at(self, t):
        wt = self.w * np.atleast_1d(t)[:, None]
        q = self.q0 * np.cos(wt) + self.dq0 / self.w * np.sin(wt)
        dq = -self.q0 * self.w * np.sin(wt) + self.dq0 * np.cos(wt)
        return q @ self.V.T + self.offset, dq @ self.V.T


def exact_events(s, u0, v0, t_end, events=3):
    """``[(kind, time, energy after)]`` of the event-driven exact solution (module docstring)."""
    K = s.system.K.toarray()
    n = K.shape[0]
    M = np.broadcast_to(np.asarray(s.mass, float), (n,)).copy()
    normal, delta = s.contact_dofs[0], s.params.delta
    free = np.setdiff1d(np.arange(n), normal)
    held_u = np.zeros(n)
    held_u[normal] = delta
    held_u[free] = -np.linalg.solve(K[np.ix_(free, free)], K[np.ix_(free, normal)] @ held_u[normal])
    flight, held = Modal(M, K, np.zeros(n)), Modal(M[free], K[np.ix_(free, free)], held_u[free])

    def state(phase, tau):
        if phase == "flight":
            return flight.at(tau)
        y, dy = held.at(tau)
        u, v = np.tile(held_u, (y.shape[0], 1)), np.zeros((y.shape[0], n))
        u[:, free], v[:, free] = y, dy
        return u, v

    def switch(phase, tau):  # the gap in flight, the reaction (force) held; both > 0 until the event
        u = state(phase, tau)[0]
        return u[:, normal[0]] - delta if phase == "flight" else u @ K[normal[0]]

    t, u, v, phase, out = 0.0, u0.copy(), v0.copy(), "flight", []
    while len(out) < events:
        (flight if phase == "flight" else held).start(u if phase == "flight" else u[free],
                                                       v if phase == "flight" else v[free])
        taus = np.linspace(0.0, t_end - t, 40001)[1:]
        g = switch(phase, taus)
        first = np.argmax(g > 1e-9 * np.abs(g).max())  # leave the switching point first
        k = first + np.flatnonzero(g[first:] <= 0)[0]
        tau = so.brentq(lambda x: switch(phase, x)[0], taus[k - 1], taus[k], xtol=1e-15)
        u, v = (a[0] for a in state(phase, tau))
        if phase == "flight":
            v[normal], u[normal], phase = 0.0, delta, "held"  # the contact nodes stop
        else:
            phase = "flight"
        t += tau
        out.append((phase, t, 0.5 * M @ v**2 + 0.5 * u @ K @ u))
        if len(out) == 1:  # the reaction per unit mass of a contact node, held, at any time after impact
            t_held, held_start = t, (u[free].copy(), v[free].copy())
    out_reaction = lambda time: (Modal(M[free], K[np.ix_(free, free)], held_u[free]).start(*held_start)  # noqa: E731
                                 .at(time - t_held)[0][0] @ K[normal[0], free] + K[normal[0], normal] @ held_u[normal]
                                 ) / M[normal[0]]
    return out, out_reaction


def _run(beta2, courant):
    s = FemScheme(PARAMS, 16, 4, beta2=beta2, courant=courant)
    u0 = s.steady.u.copy()
    M = np.broadcast_to(np.asarray(s.mass, float), u0.shape)
    K = s.system.K.toarray()
    v0 = 3 * Modal(M.copy(), K, 0 * u0).w[0] * u0  # flies about 3 delta off the shaft
    ref, reaction = exact_events(s, u0, v0, 0.3)
    tr = trace(s, s.initial_state(u0, v0, contact=False), int(0.2 / s.dt))
    on = tr.lam_n[:, 0] > 0
    assert np.all(on == (tr.lam_n > 0).all(axis=1))  # axisymmetric: every contact node alike
    edges = (np.flatnonzero(np.diff(on.astype(int))) + 1)[:3] * s.dt
    m = int(0.5 * (ref[1][1] + ref[2][1]) / s.dt)  # mid-flight after the rebound
    w, um = (tr.u[m + 1] - tr.u[m]) / s.dt, 0.5 * (tr.u[m + 1] + tr.u[m])
    energy = 0.5 * M @ w**2 + 0.5 * um @ K @ um
    h = int(0.5 * (ref[0][1] + ref[1][1]) / s.dt)  # mid-contact
    held = (np.abs(tr.u[h + 1, s.contact_dofs[0]] / s.params.delta - 1).max(),
            abs(tr.lam_n[h, 0] / reaction(h * s.dt) - 1))
    return s, np.array([r[1] for r in ref]), edges, ref[1][2], energy, held


@pytest.mark.parametrize("beta2, steps", [(0.5, 1.5), (0.9, 4.0)])
def test_breathing_ring_impact_lift_off_and_rebound_energy(beta2, steps):
    """Measured (2026-11-23): events within 0.9 steps (beta2 = 1/2) and 3.8 steps (0.9); the
    energy after the rebound (0.870 of the initial one, exact) is met to 4.7e-2, 5.7e-3, 2.5e-3
    at beta2 = 1/2, and to 0.54, 0.36, 0.22 at 0.9 (its damping of the mesh's high modes). The
    reaction bounds below were set after a first run (they are reported, not predicted)."""
    errors, reactions = [], []
    for courant in COURANTS:
        s, exact, found, e_exact, e_scheme, (on_shaft, reaction) = _run(beta2, courant)
        reactions.append(reaction)
        assert on_shaft <= 1e-12  # held on the shaft, not creeping into it
        assert found.size == 3 and np.all(np.abs(found - exact) <= steps * s.dt), (found - exact) / s.dt
        errors.append(abs(e_scheme - e_exact) / e_exact)
    assert errors[0] > errors[1] > errors[2]
    # the reaction mid-contact against the exact (K u)_r / m: 5e-3, 2e-4, 5e-4 at 1/2; 0.22, 0.13, 0.07 at 0.9
    assert max(reactions) < 0.01 if beta2 == 0.5 else reactions[0] > reactions[1] > reactions[2]
    if beta2 == 0.5:
        assert np.log(errors[0] / errors[2]) / np.log(COURANTS[0] / COURANTS[2]) >= 1.0

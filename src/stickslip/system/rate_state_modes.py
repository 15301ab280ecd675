"""Contacts that stick in a system with rate-and-state contacts: their modes and switches.

A contact whose law is not rate-and-state (Coulomb, Stribeck, ...) slips with the force
``s N mu(v)`` or sticks with the force that keeps its slip rate at zero (`RateStateEquations`
in a mode). Between switches the motion is smooth and Radau IIA integrates it; a switch is an
event of the run: a slipping contact's slip rate reaching zero (from its side), a stuck
contact's force reaching ``+-f_s N``. At a switch the next mode is chosen as the exact runs of
`stickslip.system.simulate` choose it: the contacts at zero slip rate stick unless the forces
that would hold them all exceed ``f_s N`` somewhere; the one exceeding it most is released in
its force's direction and the rest chosen again; a contact whose force reached its limit is
released. A stuck contact's slip rate is set to exactly zero (the smallest change of the
velocities in the metric of ``M``). A unilateral contact (with a normal spring: ``N(x) = N_0 - k_n
n . x``) opens where ``N(x)`` falls to zero and closes where it comes back (events too; no impact: the
normal force is continuous), its limit ``f_s N(x)``; closing, it slips the way its slip rate is, or
is chosen with the others where that is zero. One whose normal force does not act on the structure
(``normal_on_structure`` false: an eliminated constraint) opening stops the run.
"""

from __future__ import annotations

import numpy as np

from ..errors import NoSolutionError
from .flow import OPEN
from .simulate import zero_slip

__all__ = ["first_mode", "choose_mode", "mode_events", "switch", "sticking"]

#: A slip rate this small against the run's speeds is zero: a contact that gets there at an event of
#: another one (two contacts reaching zero together, to the event location's round-off) may stick.
ZERO = 1e-10


def sticking(eq) -> list[int]:
    """The contacts that may stick (their law is not rate-and-state), open ones left out."""
    return [i for i, r in enumerate(eq.rsf) if not r and eq.mode[i] != OPEN]


def _speed(eq, y) -> float:
    return max(float(np.abs(eq.V).max()), float(np.abs(y[eq.n:2 * eq.n]).max()), 1e-300)


def choose_mode(eq, t: float, y: np.ndarray, mode: tuple, zero, released: dict) -> tuple[tuple, np.ndarray]:
    """``(mode, y)`` from ``t`` on: the contacts in ``zero`` stick unless their forces exceed ``f_s N``
    (released in the force's direction, the largest excess first), those in ``released``
    (contact -> direction) slip; the stuck contacts' slip rates set to zero in ``y``. Sets ``eq``'s mode.
    A `NoSolutionError` where a slipping contact is beyond its law's largest slip speed."""
    mode = list(mode)
    for i in zero:
        mode[i] = released.get(i, 0)
    while True:
        eq.set_mode(mode)
        y = zero_slip(eq.system, y, eq.stuck)
        if not eq.stuck:
            break
        lam = eq.stick_forces(t, y)
        normal = eq.normal(y)
        limit = np.array([eq.laws[i].static * max(normal[i], 0.0) for i in eq.stuck])  # (N a round-off below 0)
        k = int(np.argmax(np.abs(lam) - limit))
        if abs(lam[k]) <= limit[k]:
            break
        mode[eq.stuck[k]] = 1 if lam[k] > 0 else -1
    vr = eq.V - eq.system.directions.T @ y[eq.n:2 * eq.n]
    for i in sticking(eq):
        if mode[i] != 0 and abs(vr[i]) >= eq.laws[i].max_speed:
            raise NoSolutionError(f"simulation stopped at t = {t:.17g}: the slip speed of contact {i} is beyond the "
                                  f"limit of its friction law, |v_r| < {eq.laws[i].max_speed:.6g} (beyond it the law "
                                  "gives no friction coefficient)")
    return tuple(mode), y


def first_mode(eq, y: np.ndarray) -> tuple[tuple, np.ndarray]:
    """The mode at the start: a unilateral contact whose normal force is not positive is open; each
    other contact that may stick slips the way its slip rate is, or sticks where it is zero (and holds)."""
    vr = eq.V - eq.system.directions.T @ y[eq.n:2 * eq.n]
    speed = _speed(eq, y)
    normal = eq.normal(y)
    mode = tuple(OPEN if c.unilateral and normal[i] <= 0.0 else (1 if vr[i] >= 0 else -1)
                 for i, c in enumerate(eq.system.contacts))
    eq.set_mode(mode)
    _held(eq, 0.0)
    zero = {i for i in sticking(eq) if abs(vr[i]) <= 1e-14 * speed}
    return choose_mode(eq, 0.0, y, mode, zero, {})


def _held(eq, t: float) -> None:
    """A `NoSolutionError` where a contact whose normal force only loads it is open (its constraint let go)."""
    for i, c in enumerate(eq.system.contacts):
        if eq.mode[i] == OPEN and not c.pushes:
            raise NoSolutionError(f"simulation stopped at t = {t:.17g}: the normal force of contact {i} reached zero; "
                                  "its normal motion is an eliminated constraint (normal_on_structure = false), whose "
                                  "letting go the model does not follow")


class _Event:
    """One switching function of the current mode (an event of `scipy.integrate.solve_ivp`)."""

    terminal = True

    def __init__(self, eq, contact: int, kind: str, direction: float, function):
        self.eq, self.contact, self.kind, self.direction, self.function = eq, contact, kind, direction, function

    def __call__(self, t, y):
        return self.function(t, y)


def mode_events(eq) -> list:
    """The switching functions of ``eq``'s mode: each slipping contact's slip rate (toward zero from
    its side), each stuck contact's force against ``+-f_s N``, a law's largest slip speed."""
    out, W = [], eq.system.directions
    n = eq.n
    for i, c in enumerate(eq.system.contacts):  # a unilateral contact's normal force through zero
        if c.unilateral and not eq.rsf[i]:
            kind, way = ("close", 1.0) if eq.mode[i] == OPEN else ("open", -1.0)
            out.append(_Event(eq, i, kind, way, lambda t, y, i=i: eq.normal(y)[i]))
    for i in sticking(eq):
        s = eq.mode[i]
        if s != 0:
            out.append(_Event(eq, i, "zero", -float(s), lambda t, y, i=i: eq.V[i] - W[:, i] @ y[n:2 * n]))
            top = eq.laws[i].max_speed
            if np.isfinite(top):
                out.append(_Event(eq, i, "limit", 1.0, lambda t, y, i=i, top=top:
                                  abs(eq.V[i] - W[:, i] @ y[n:2 * n]) - top))
        else:
            k, fs = eq.stuck.index(i), eq.laws[i].static
            out.append(_Event(eq, i, "release", 1.0, lambda t, y, i=i, k=k, fs=fs:
                              eq.stick_forces(t, y)[k] - fs * max(eq.normal(y)[i], 0.0)))
            out.append(_Event(eq, i, "release", -1.0, lambda t, y, i=i, k=k, fs=fs:
                              eq.stick_forces(t, y)[k] + fs * max(eq.normal(y)[i], 0.0)))
    return out


def switch(eq, t: float, y: np.ndarray, event: _Event) -> tuple[tuple, np.ndarray]:
    """The mode after ``event`` at ``(t, y)`` and the state (stuck contacts' slip rates zeroed). The
    contacts at zero slip rate then (or past it), the stuck ones included, are chosen again."""
    vr = eq.V - eq.system.directions.T @ y[eq.n:2 * eq.n]
    speed = _speed(eq, y)
    mode = list(eq.mode)
    i = event.contact
    if event.kind == "open":
        mode[i] = OPEN
        eq.set_mode(mode)
        _held(eq, t)
    elif event.kind == "close":
        mode[i] = 1 if vr[i] >= 0 else -1
        eq.set_mode(mode)
    zero = {j for j in sticking(eq) if mode[j] == 0 or abs(vr[j]) <= ZERO * speed or mode[j] * vr[j] < 0}
    if event.kind in ("zero", "limit", "release"):
        zero.add(i)
    released = {i: int(event.direction)} if event.kind == "release" else {}
    return choose_mode(eq, t, y, tuple(mode), zero, released)

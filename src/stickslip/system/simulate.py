"""Event-driven simulation of a `System`: exact switching between contact states.

Between events the motion is the closed-form flow of the contact state (`Flow`). At an event
(a slipping contact's slip velocity reaching zero, or a sticking contact's force reaching
``f_s N``) the next state is chosen for all contacts at zero slip velocity at once: every one
of them sticks, then the one whose sticking force exceeds ``f_s N`` the most is released in the
direction of that force, and so on until every sticking force is admissible (an active set:
at most one solve per contact). The released contacts must then slip the way they were
released (their slip acceleration has the force's sign); if not, no state is consistent and
the simulation stops with a `NoSolutionError` saying so. A contact that sticks has its slip
velocity set to exactly zero (the velocity moved in the metric of ``M``, by round-off).
A rigid contact that lands (`land`) loses its normal velocity in a plastic impact with its friction
impulse; a closed one whose reaction would pull opens (the most pulling first, as for releases).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy

from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..quantities import SYSTEM as Q
from ..results import Result
from .flow import CLOSING, LAW_LIMIT, OPEN, OPENING, STATE_FLAGS, Flow
from .model import System

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["SystemRun", "Segment", "simulate", "choose_states", "zero_slip", "longest_run", "affine_laws", "land"]

#: Events in a row without time passing before the simulation is said to chatter.
MAX_INSTANT_EVENTS = 64
#: The most numbers the samples of a run hold (1 GB of float64).
MAX_NUMBERS = 1.25e8
#: The most steps of the event search in a run (each a product with the step's matrix exponential:
#: about a minute for a small system).
MAX_STEPS = 1e7


@dataclass(frozen=True, eq=False, repr=False)
class SystemRun(Result):
    """A simulated trajectory: samples and events."""

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    states: np.ndarray
    friction_force: np.ndarray
    event_time: np.ndarray
    event_contact: np.ndarray
    event_state: np.ndarray
    #: With ``simulate(..., segments=True)``: one `Segment` per piece of the flow, in order.
    segments: tuple = ()
    MODEL = "system"

    def to_dict(self) -> dict:
        return {"events": int(self.event_time.size), "t_end": float(self.t[-1]),
                "x_end": self.x[-1].tolist(), "v_end": self.v[-1].tolist(), "states_end": self.states[-1].tolist()}

    def to_xarray(self) -> xr.Dataset:
        """Units and meanings from the declarations (`stickslip.cf.finish`)."""
        n, k = self.x.shape[1], self.states.shape[1]
        ds = xr.Dataset(
            {"x": (("t", "dof"), self.x), "v": (("t", "dof"), self.v),
             "contact_state": (("t", "contact"), self.states.astype(np.int8), STATE_FLAGS),
             "friction_force": (("t", "contact"), self.friction_force),
             "event_time": ("event", self.event_time), "event_contact": ("event", self.event_contact),
             "event_state": ("event", self.event_state.astype(np.int8), STATE_FLAGS)},
            coords={"t": self.t, "dof": np.arange(n), "contact": np.arange(k), "event": np.arange(self.event_time.size)})
        return finish(ds, "system with frictional contacts: event-driven simulation", "system")


@dataclass(frozen=True)
class Segment:
    """A piece of the flow: the contact ``states``, its start ``z`` = (x, v, 1) at time ``t``, its
    ``duration``; ``rows`` the switching functions (of `Flow` of ``states``) that ended it and
    ``after`` the states from then on (``()`` and ``states`` for the last piece)."""

    states: tuple
    t: float
    z: np.ndarray
    duration: float
    rows: tuple
    after: tuple


def zero_slip(system: System, z: np.ndarray, stuck: list[int]) -> np.ndarray:
    """``z`` with the slip velocity of the ``stuck`` contacts exactly zero (the smallest change
    of the velocity in the metric of M)."""
    if not stuck:
        return z
    n = system.dofs
    W = system.directions[:, stuck]
    V = np.array([system.contacts[i].surface_speed for i in stuck])
    v = z[n:2 * n]
    MiW = system.inverse_mass @ W
    z = z.copy()
    z[n:2 * n] = v + MiW @ np.linalg.lstsq(W.T @ MiW, V - W.T @ v, rcond=None)[0]
    return z


def _frictionless(contact) -> bool:
    return contact.friction.static == 0.0 and float(contact.friction.kinetic(0.0)) == 0.0


def choose_states(system: System, z: np.ndarray, states: tuple, zero: set, released: dict, flows: dict,
                  piece: int = 0) -> tuple:
    """The contact states from ``z`` on: contacts not in ``zero`` keep ``states``; those in
    ``zero`` (at zero slip velocity) stick unless their sticking force exceeds ``f_s N``
    (released in the force's direction), ``released`` (contact -> sign) slip at once. ``flows``
    caches the flows of the force history's ``piece``."""
    if not isinstance(system, System):
        raise ParameterError("system", system, "a stickslip.system.System")
    st = list(states)
    for i in zero:  # a frictionless contact never sticks: its force is 0 whichever way it slips
        st[i] = released.get(i, 1 if _frictionless(system.contacts[i]) else 0)
    n = system.dofs
    rigid = [i for i, c in enumerate(system.contacts) if c.rigid]
    for _ in range(len(zero) + len(rigid) + 1):
        flow = Flow.cached(system, tuple(st), flows, piece)
        forces, normals = flow.force_rows @ z, flow.normal_rows @ z
        pulling = [i for i in rigid if st[i] != OPEN and normals[i] < -1e-12 * np.abs(normals).max()]
        if pulling:  # a closed rigid contact whose reaction would pull opens (the most pulling first)
            st[min(pulling, key=lambda i: normals[i])] = OPEN
            continue
        worst, over = None, 0.0
        for i in zero:
            if st[i] != 0:
                continue
            limit = max(0.0, system.contacts[i].friction.static * float(normals[i]))
            excess = abs(forces[i]) - limit
            if excess > 1e-12 * max(limit, abs(forces[i])) and excess > over:
                worst, over = i, excess
        if worst is None:
            break
        st[worst] = 1 if forces[worst] > 0 else -1
    moving = [i for i in zero if st[i] in (-1, 1)]  # (not those opened: no friction)
    if moving:  # released ones: do they slip the way they were released?
        flow = Flow.cached(system, tuple(st), flows, piece)
        a = flow.acceleration(z)
        terms = np.abs(flow.A[n:2 * n]) @ np.abs(z)  # the size of what the accelerations sum (their round-off)
    for i in moving:
        c = system.contacts[i]
        if _frictionless(c):
            continue  # no tangential force whichever way it slips, so no paradox
        rate = -c.direction @ a  # d v_r / dt
        size = np.abs(c.direction) @ terms + 1e-300
        if st[i] * rate < -1e-9 * size:
            raise NoSolutionError(f"no consistent contact state at contact {i}: released to slip with sign {st[i]}, "
                                  f"its slip velocity would change with sign {-st[i]} (a Painleve-like paradox "
                                  "of these directions and laws)")
    return tuple(st)


def land(system: System, flow: Flow, z: np.ndarray, states, landing, flows: dict, piece: int = 0) -> tuple:
    """``(states, z)`` after the rigid contacts ``landing`` touch their surfaces at ``z`` (``flow``
    the flow before): a plastic impact (`Flow.impact`) on every closed rigid contact with Coulomb's
    friction impulse: a landing one slips the way its slip velocity was, or sticks where that impulse
    would reverse the slip; a closed one slipping before goes on slipping unless its impulse would
    reverse it (it sticks); one stuck before (or landing stuck) whose tangential impulse would exceed
    f_s times its normal one slips (a landing one the other way, one stuck before the way its impulse
    pushes); a closed rigid contact whose impulse would pull opens instead (the most pulling first); a
    contact that stuck without a rigid normal and is moved by the impact slips."""
    st = list(states)
    vr0 = flow.slip_rows @ z
    first = {i: 1 if vr0[i] > 0 else -1 for i in landing}
    for i in landing:
        st[i] = first[i]
    before = {i: st[i] for i, c in enumerate(system.contacts) if c.rigid and st[i] != OPEN and i not in first}
    speed = max(1.0, *(abs(c.surface_speed) for c in system.contacts))
    for _ in range(3 * len(system.contacts) + 1):
        impact = Flow.cached(system, tuple(st), flows, piece)
        after, impulses = impact.impact(z)
        size = max((abs(v) for v in impulses.values()), default=0.0)
        pulling = {j: v for j, v in impulses.items() if v < -1e-12 * size}
        if pulling:
            st[min(pulling, key=pulling.get)] = OPEN
            continue
        # a stuck one whose friction impulse would exceed f_s times its normal one slips (Coulomb)
        tangential = impact.tangential_impulses
        size = max(size, *(abs(v) for v in tangential.values()), 1e-300)  # (round-off at contacts not involved)
        beyond = [i for i in impulses if st[i] == 0 and abs(tangential.get(i, 0.0)) >
                  system.contacts[i].friction.static * impulses[i] + 1e-12 * size]
        if beyond:
            for i in beyond:
                st[i] = -first[i] if i in first else (1 if tangential[i] > 0 else -1)
            continue
        vr = flow.slip_rows @ after
        reversed_ = [i for i in impulses if st[i] in (-1, 1) and st[i] == first.get(i, before.get(i))
                     and vr[i] * st[i] <= 1e-13 * speed and (i in first or vr0[i] * st[i] > 1e-13 * speed)]
        if not reversed_:
            break
        for i in reversed_:  # the friction impulse would reverse the slip: it sticks (if Coulomb allows)
            st[i] = 0
    vr = flow.slip_rows @ after  # (the last impact's: the loop may end without computing it)
    for i, c in enumerate(system.contacts):
        if st[i] == 0 and not c.rigid and abs(vr[i]) > 1e-13 * speed:
            st[i] = 1 if vr[i] > 0 else -1
    return st, after


def _sampled(flow: Flow, z: np.ndarray, times: np.ndarray, dt: float) -> np.ndarray:
    """The states at ``times`` (uniform, ``dt`` apart) of the flow from ``z``, one per row: the
    first by its matrix exponential, the others by powers of the step's, doubled (``log2`` of
    the count of matrix products, not one per sample)."""
    block = flow.propagate(z, times[0])[:, None]
    power = flow.propagate(np.eye(z.size), dt) if times.size > 1 else None
    while block.shape[1] < times.size:
        block = np.hstack([block, power @ block])
        power = power @ power
    return block[:, :times.size].T


def _given_states(states, vr, speed, unilateral, off) -> tuple:
    try:
        given = tuple(int(s) for s in states)
        ok = len(given) == len(vr) and all(s in (-1, 0, 1, OPEN) and float(s) == float(o)
                                           for s, o in zip(given, states))
    except (TypeError, ValueError):
        ok = False
    if not ok:
        raise ParameterError("states", states, f"{len(vr)} numbers, each 1 (slip), 0 (stick), -1 (reverse slip) "
                             "or 2 (open, for a unilateral contact)")
    for i, (s, v) in enumerate(zip(given, vr)):
        if s == OPEN and not unilateral[i]:
            raise ParameterError("states", list(states), f"2 (open) only for a unilateral contact (contact {i} has "
                                 "no normal direction)")
        if s == OPEN:
            continue
        if off[i]:
            raise ParameterError("states", list(states), f"2 (open) for contact {i}: the start is off its rigid "
                                 "surface (a gap n . x0 > 0)")
        if (s == 0 and abs(v) > 1e-9 * speed) or (s != 0 and s * v < -1e-9 * speed):
            raise ParameterError("states", list(states), f"states the start allows: contact {i} has slip velocity "
                                 f"{v:.6g}, so it cannot {'stick' if s == 0 else 'slip with sign ' + str(s)}")
    return given


def _check(system, x0, v0, t_end, samples, max_events, flows):
    affine_laws(system)
    n = system.dofs
    x0 = np.zeros(n) if x0 is None else np.asarray(Q["x0"].check_array(x0, "x0"), dtype=float).reshape(-1)
    v0 = np.zeros(n) if v0 is None else np.asarray(Q["v0"].check_array(v0, "v0"), dtype=float).reshape(-1)
    for name, arr in (("x0", x0), ("v0", v0)):
        if arr.shape != (n,):
            raise ParameterError(name, arr.tolist(), f"{n} numbers (one per degree of freedom)")
    t_end, samples = Q.check("t_end", t_end), Q.check("samples", samples)
    k = len(system.contacts)
    if samples * (2 * n + 2 * k) > MAX_NUMBERS:
        raise ParameterError("samples", samples, f"<= {MAX_NUMBERS // (2 * n + 2 * k)} for {n} degrees of freedom and "
                             f"{k} contacts (the samples hold at most {MAX_NUMBERS:.3g} numbers, 1 GB)",
                             also=("mass", "contacts"))
    longest, h = longest_run(system, flows)
    if t_end > longest:
        raise ParameterError("t_end", t_end, f"<= {longest:.6g} s ({MAX_STEPS:.0e} steps of the event "
                             f"search, {h:.3g} s each, set by the fastest time scale of the system)",
                             also=("mass", "stiffness", "damping") + (("harmonics",) if system.harmonics else ()))
    return x0, v0, t_end, samples, Q.check("max_events", max_events)


def affine_laws(system: System) -> None:
    """A `ParameterError` unless ``system`` is a `System` whose contacts' laws are affine in the slip
    speed (what the exact flows take)."""
    if not isinstance(system, System):
        raise ParameterError("system", system, "a stickslip.system.System")
    for i, c in enumerate(system.contacts):
        if getattr(c.friction, "affine", None) is None:
            raise ParameterError(f"contacts[{i}].friction", type(c.friction).__name__,
                                 "a law affine in the slip speed (Coulomb, linear weakening) for the exact flows; a "
                                 "system with other laws (Stribeck, a user's law, rate-and-state) moves by "
                                 "stickslip.system.rate_state_simulate (integrated between its switches)")
        if c.unilateral and c.friction.affine[1] != 0.0:
            raise ParameterError(f"contacts[{i}].friction", type(c.friction).__name__,
                                 "Coulomb on a unilateral contact for the exact flows (s N(x) mu(v) is not linear "
                                 "where mu depends on the slip speed); such a system moves by "
                                 "stickslip.system.rate_state_simulate (integrated between its switches)")


def longest_run(system: System, flows: dict | None = None) -> tuple[float, float]:
    """``(t, h)``: the longest run of ``system`` (`MAX_STEPS` steps of the event search, at most the
    largest end time) and the search's step ``h`` with every contact slipping (its fastest time scale)."""
    free = Flow.cached(system, tuple(1 for _ in system.contacts), {} if flows is None else flows)
    return (min(MAX_STEPS * free.h, Q["t_end"].range.hi) if np.isfinite(free.h) else Q["t_end"].range.hi), free.h


def simulate(system: System, x0=None, v0=None, t_end: float = 10.0, *, samples: int = 1001,
             max_events: int = 1_000_000, segments: bool = False, states=None, stop_at=None) -> SystemRun:
    """Simulate ``system`` from ``(x0, v0)`` (default rest at zero) to ``t_end``, with
    ``samples`` uniform samples; at most ``max_events`` contact events (else `NoSolutionError`).
    With ``segments`` the run keeps its pieces of flow (`Segment`: for `monodromy`). The
    contact ``states`` to start in (1 slip, 0 stick, -1 reverse slip; default: chosen from the
    start, as at an event) are for a start on a switching line, such as just after an event.
    ``stop_at = (contact, state)`` ends the run just after that contact first enters that state
    (its samples those before; a return map's run). A `ForceHistory` is followed piece by piece
    (the flows of one piece at a time are kept)."""
    flows: dict = {}
    x0, v0, t_end, samples, max_events = _check(system, x0, v0, t_end, samples, max_events, flows)
    if not isinstance(segments, (bool, np.bool_)):
        raise ParameterError("segments", segments, "True or False")
    if segments and system.history is not None:
        system.unforced("segments (a monodromy's pieces of flow)")
    if stop_at is not None and not (isinstance(stop_at, tuple) and len(stop_at) == 2 and all(
            isinstance(v, (int, np.integer)) and not isinstance(v, bool) for v in stop_at)
            and 0 <= stop_at[0] < len(system.contacts) and stop_at[1] in (-1, 0, 1, OPEN)):
        raise ParameterError("stop_at", stop_at, f"(contact, state): a contact from 0 to {len(system.contacts) - 1} "
                             "and a state -1, 0, 1 or 2")
    n, k = system.dofs, len(system.contacts)
    z = system.state(x0, v0)
    piece = 0 if system.history is None else system.history.piece_at(0.0)
    if piece:
        flows = {}
    end = np.inf if system.history is None else system.history.piece(piece)[2]
    vr = [c.slip_velocity(v0) for c in system.contacts]
    speed = max(1.0, *(abs(c.surface_speed) for c in system.contacts))
    opened = {i for i, c in enumerate(system.contacts) if c.unilateral and not c.rigid
              and c.normal_row(n, system.extra) @ z <= 0.0}
    far = set()
    for i, c in enumerate(system.contacts):
        if c.rigid:  # open with a gap n . x > 0; closed on the surface; never inside it
            gap, scale = float(c.normal_direction @ x0), float(np.abs(c.normal_direction).max() * np.abs(x0).max())
            if gap < -1e-12 * scale:
                raise ParameterError("x0", x0.tolist(), f"outside the rigid contact {i} (its gap n . x0 = {gap:.6g} "
                                     "< 0)")
            if gap > 1e-9 * scale:  # off its surface beyond round-off (a given state may not close it)
                far.add(i)
            if gap > 1e-12 * scale or (gap >= 0 and c.normal_direction @ v0 > 0):
                opened.add(i)
    arriving = [i for i, c in enumerate(system.contacts) if c.rigid and i not in opened
                and c.normal_direction @ v0 < 0]
    if arriving:  # on its surface and moving into it: a landing at t = 0 (a contact at zero slip: stuck)
        pre = [OPEN if i in opened or i in arriving else 0 if abs(vr[i]) <= 1e-14 * speed else (1 if vr[i] > 0 else -1)
               for i in range(k)]
        after, z = land(system, Flow.cached(system, tuple(pre), flows, piece), z, pre, arriving, flows, piece)
        v0 = z[n:2 * n]
        vr = [c.slip_velocity(v0) for c in system.contacts]
        opened = {i for i in range(k) if after[i] == OPEN}  # (not the sign of n . v: round-off after the impact)
    zero = {i for i in range(k) if abs(vr[i]) <= 1e-14 * speed} - opened
    if states is None:
        states = tuple(OPEN if i in opened else 0 if i in zero else (1 if vr[i] > 0 else -1) for i in range(k))
        states = choose_states(system, z, states, zero, {}, flows, piece)
    else:
        states = _given_states(states, vr, speed, [c.unilateral for c in system.contacts],
                               [i in far for i in range(k)])
        zero = {i for i in range(k) if states[i] == 0}
    z = zero_slip(system, z, [i for i in zero if states[i] == 0])
    ts = np.linspace(0.0, t_end, samples)
    out = np.empty((samples, 2 * n))
    st_out = np.empty((samples, k), dtype=np.int8)
    f_out = np.empty((samples, k))
    ev_t, ev_c, ev_s, pieces = [], [], [], []
    t, j, instant, released = 0.0, 0, 0, {}
    while True:
        flow = Flow.cached(system, states, flows, piece)
        stop = min(t_end, end)
        t_next, z_next, hit = flow.first_event(z, stop - t)
        t_next = t + t_next if t_next < stop - t else stop
        if segments:
            pieces.append(Segment(states, t, z, t_next - t, tuple(hit), states))
        j1 = j
        while j1 < samples and (ts[j1] < t_next or (not hit and ts[j1] <= t_next)):
            j1 += 1
        if j1 > j:
            zs = _sampled(flow, z, ts[j:j1] - t, ts[1] - ts[0])
            out[j:j1], st_out[j:j1], f_out[j:j1] = zs[:, :2 * n], states, zs @ flow.force_rows.T
            j = j1
        if not hit and t_next < t_end:  # the force history's next piece (the force is continuous there)
            t, z, flows = t_next, z_next, {}
            piece += 1
            end = system.history.piece(piece)[2]
            continue
        if not hit:
            break
        instant = instant + 1 if t_next == t else 0
        if instant > MAX_INSTANT_EVENTS or len(ev_t) >= max_events:
            why = (f"{MAX_INSTANT_EVENTS} contact events at t = {t:.17g} without time passing (chattering)"
                   if instant > MAX_INSTANT_EVENTS else f"more than max_events = {max_events} contact events")
            raise NoSolutionError(f"simulation stopped: {why}")
        t, z = t_next, z_next
        beyond = [int(flow.owners[r]) for r in hit if flow.kinds[r] == LAW_LIMIT]
        if beyond:
            i = beyond[0]
            raise NoSolutionError(f"simulation stopped at t = {t:.17g}: the slip speed of contact {i} reached the "
                                  f"limit of its friction law, |v_r| < {system.contacts[i].friction.max_speed:.6g} "
                                  "(beyond it the law gives no friction coefficient)")
        opening = {int(flow.owners[r]) for r in hit if flow.kinds[r] == OPENING}
        closing = {int(flow.owners[r]) for r in hit if flow.kinds[r] == CLOSING}
        hit = sorted({int(flow.owners[r]) for r in hit} - opening - closing)
        if not instant:  # a contact released stays released through further events at the same instant
            released = {}  # (else two groups at their limits together re-stick each other in turn)
        for i in hit:
            if states[i] == 0:  # its force reached f_s N: released in its direction
                released[i] = 1 if (flow.force_rows[i] @ z) > 0 else -1
        vr = flow.slip_rows @ z
        before = list(states)
        for i in opening:  # its normal force reached zero: no force from now on
            before[i] = OPEN
        for i in closing:  # touching again, with no normal force yet: slips the way the surface moves under it
            before[i] = 1 if vr[i] > 0 else -1
        landing = [i for i in closing if system.contacts[i].rigid]
        if landing:
            before, z = land(system, flow, z, before, landing, flows, piece)
            vr = flow.slip_rows @ z
        zero = set(hit) | {i for i in range(k) if before[i] == 0}
        zero |= {i for i in range(k) if abs(vr[i]) <= 1e-13 * speed and before[i] != OPEN}
        new = choose_states(system, z, tuple(before), zero, released, flows, piece)
        z = Flow.cached(system, new, flows, piece).stick(z)
        for i in range(k):
            if new[i] != states[i]:
                ev_t.append(t), ev_c.append(i), ev_s.append(new[i])
        if segments:
            pieces[-1] = dataclasses.replace(pieces[-1], after=new)
        if stop_at is not None and new[stop_at[0]] == stop_at[1] != states[stop_at[0]]:
            if segments:  # the piece after the event: its start is the state there
                pieces.append(Segment(new, t, z, 0.0, (), new))
            ts, out, st_out, f_out = ts[:j], out[:j], st_out[:j], f_out[:j]
            break
        states = new
    return SystemRun(ts, out[:, :n], out[:, n:], st_out, f_out, np.array(ev_t), np.array(ev_c, dtype=np.int64),
                     np.array(ev_s, dtype=np.int8), tuple(pieces))

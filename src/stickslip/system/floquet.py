"""Monodromy matrices with saltation matrices, limit cycles and their Floquet multipliers.

Along a run the derivative of the end state with respect to the start state is the product,
in order, of each piece's ``expm(tau A)`` (its (x, v) block) and, at each event, the saltation
matrix of the switching function ``h`` (gradient ``n``) that ended it,

    S = I + (f+ - f-) n^T / (n . f-),

with ``f-`` and ``f+`` the vector fields of the states before and after, at the event. Every
kind of switch — stick onset, stick release, slip reversal — is such a crossing; only the
fields and the function differ. At a stick onset ``S`` removes the velocity along the contact
(a multiplier 0 per contact that sticks); a cycle's other multipliers say its stability.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy
from scipy.linalg import expm

from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..quantities import SYSTEM as Q
from ..results import Result
from .flow import CLOSING, OPEN, STATE_FLAGS, Flow, shares_flows
from .model import System
from .simulate import SystemRun, land, simulate, zero_slip
from .. import validation as check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["monodromy", "saltation", "jump", "SystemCycle", "limit_cycle", "return_fixed_point", "orbit_scale",
           "without_own", "cycle_dataset", "period_events", "entries", "NEUTRAL", "inside"]

#: A multiplier within this of the unit circle is on it (round-off of a neutral direction: a contact
#: that sticks through the period, anywhere).
NEUTRAL = 1e-9


def inside(multipliers: np.ndarray) -> bool:
    """No multiplier outside the unit circle beyond `NEUTRAL`."""
    return bool(np.all(np.abs(multipliers) < 1.0 + NEUTRAL))


def saltation(f_minus: np.ndarray, f_plus: np.ndarray, normal: np.ndarray, rate: float | None = None) -> np.ndarray:
    """``I + (f+ - f-) n^T / (n . f-)``: the jump of the linearised flow at a transversal crossing.
    Where the switching function depends on time too (a forced system), ``rate`` is its whole
    rate of change before the crossing, ``n . f- + dh/dt``."""
    f_minus, f_plus = check.finite_array("f_minus", f_minus, 1), check.finite_array("f_plus", f_plus, 1)
    normal = check.finite_array("normal", normal, 1)
    if not f_minus.size == f_plus.size == normal.size:
        raise ParameterError("normal", normal.size, f"a vector of the size of f_minus and f_plus ({f_minus.size})")
    rate = float(normal @ f_minus) if rate is None else float(rate)
    if rate == 0.0:
        raise NoSolutionError("a grazing event (the switching function is tangent to the flow): the monodromy "
                              "is not defined there")
    return np.eye(f_minus.size) + np.outer(f_plus - f_minus, normal) / rate


def jump(system: System, segment, z: np.ndarray, flows: dict, skip: int | None = None,
         onto: np.ndarray | None = None) -> tuple:
    """``(S, f)``: the saltation matrix of the events that ended ``segment`` (at its end state
    ``z``) and the field ``f`` after them. Events at the same instant (of contacts a symmetry
    makes switch together) are taken one contact after another, each with its own switching
    function and the fields before and after its own switch; for contacts that do not touch
    each other's switching functions the order does not matter. A contact that changes state
    there without a switching function of its own reaching zero (released because another one
    stuck: the load moves to it) changes with the last crossing: the field after that crossing
    is the one of every new state. Without the contact ``skip`` (its own switch is the
    section's, projected by the caller). With ``onto`` (2n rows), ``S @ onto`` in place of ``S``: each
    crossing's saltation is the identity plus a rank-one term (an impact's reset the identity plus a
    few columns' term), applied as such (no product of 2n-square matrices)."""
    n = system.dofs
    flow = Flow.cached(system, segment.states, flows)
    crossed, seen = [], set()
    for r in segment.rows:
        owner = int(flow.owners[r])
        if owner != skip and owner not in seen:
            seen.add(owner)
            crossed.append((r, owner))
    final = tuple(s if i == skip else a for i, (a, s) in enumerate(zip(segment.after, segment.states)))
    steps = [(r, o) for r, o in crossed if segment.after[o] != segment.states[o] or _lands(system, flow, r, o)]
    if not steps and crossed and final != segment.states:
        steps = crossed[-1:]  # only consequential changes: they go with the last crossing
    states = list(segment.states)
    out = np.eye(2 * n) if onto is None else np.array(onto, dtype=float)
    f_minus = flow.A @ z  # the whole field: with harmonic forces the switching functions move in time too
    for k, (r, owner) in enumerate(steps):
        prior = list(states)  # with the changes of the steps before (contacts landed at the same instant)
        states[owner] = segment.after[owner]
        if k == len(steps) - 1:
            states = list(final)
        after = Flow.cached(system, tuple(states), flows)
        rate = flow.rows[r] @ f_minus
        if _lands(system, flow, r, owner):  # a plastic impact: z+ = R z- (R of the state it lands in, even
            landed, z = land(system, flow, z, prior, [owner], flows)  # if pulled off at once: `simulate`)
            reset = Flow.cached(system, tuple(landed), flows)
            f_plus = after.A @ z
            if rate == 0.0:
                raise NoSolutionError(f"contact {owner} touches its surface with no normal velocity (a grazing "
                                      "impact): the monodromy is not defined there")
            # (R + (f+ - R f-) h^T / rate) out, R the reset
            u, out = f_plus[:2 * n] - reset.project(f_minus[:2 * n]), reset.project(out)
        else:
            f_plus = after.A @ z
            if rate == 0.0:
                raise NoSolutionError("a grazing event (the switching function is tangent to the flow): the "
                                      "monodromy is not defined there")
            u = f_plus[:2 * n] - f_minus[:2 * n]  # (I + (f+ - f-) h^T / rate) out: `saltation`
        out += np.outer(u / rate, flow.rows[r][:2 * n] @ out)
        f_minus = f_plus
    return out, f_minus[:2 * n]


def _lands(system: System, flow: Flow, row: int, owner: int) -> bool:
    """Whether ``row`` of ``flow`` is a rigid contact touching its surface (an impact)."""
    return bool(flow.kinds[row] == CLOSING and system.contacts[owner].rigid)


def monodromy(system: System, run: SystemRun | tuple) -> np.ndarray:
    """``d(x, v)(t_end) / d(x, v)(0)`` of a run simulated with ``segments=True`` (or of a tuple
    of its segments: up to just after the last one's events)."""
    check.instance("system", system, System, "a stickslip.system.System")
    segments = run if isinstance(run, tuple) else run.segments
    if not segments:
        raise ParameterError("run", "a run without segments", "a run of simulate(..., segments=True)")
    n = system.dofs
    flows: dict = {}
    out = np.eye(2 * n)
    for seg in segments:
        flow = Flow.cached(system, seg.states, flows)
        step = expm(seg.duration * flow.A)
        out = step[:2 * n, :2 * n] @ out
        if seg.rows:
            out = jump(system, seg, step @ seg.z, flows, onto=out)[0]
    return out


def without_own(multipliers: np.ndarray) -> np.ndarray:
    """The multipliers but the flow's own (the one nearest 1), in their order."""
    try:
        multipliers = np.asarray(multipliers, dtype=complex)
    except (TypeError, ValueError):
        raise ParameterError("multipliers", multipliers, "a non-empty vector of (complex) numbers") from None
    if multipliers.ndim != 1 or multipliers.size == 0:
        raise ParameterError("multipliers", multipliers.tolist(), "a non-empty vector of (complex) numbers")
    return np.delete(multipliers, np.argmin(np.abs(multipliers - 1.0)))


def cycle_dataset(cycle, attrs: dict, title: str) -> xr.Dataset:
    """A cycle's multipliers, start and events as a dataset (`SystemCycle`, `RelativeCycle`),
    with ``attrs``; units and meanings from the declarations (`stickslip.cf.finish`)."""
    m = cycle.multipliers
    ds = xr.Dataset(
        {"multiplier_real": ("multiplier", m.real), "multiplier_imag": ("multiplier", m.imag),
         "x0": ("dof", cycle.x0), "v0": ("dof", cycle.v0),
         "event_time": ("event", cycle.event_time), "event_contact": ("event", cycle.event_contact),
         "event_state": ("event", cycle.event_state.astype(np.int8), STATE_FLAGS)},
        coords={"dof": np.arange(cycle.x0.size), "event": np.arange(cycle.event_time.size)},
        attrs={**attrs, "stable": int(cycle.stable), "section_contact": cycle.contact, "section_state": cycle.state})
    return finish(ds, title, "system")


def period_events(system: System, z: np.ndarray, states: tuple, period: float) -> tuple:
    """``(time, contact, state)`` of the events of one period from ``z`` (the section's own last)."""
    n = system.dofs
    run = simulate(system, z[:n], z[n:2 * n], period * (1 + 1e-9), samples=2, states=states)
    inside = run.event_time <= period * (1 + 1e-12)
    return run.event_time[inside], run.event_contact[inside], run.event_state[inside]


@dataclass(frozen=True, eq=False, repr=False)
class SystemCycle(Result):
    """A periodic orbit: its ``period``, the state ``x0``, ``v0`` just after the event that starts
    it (contact ``contact`` entering state ``state``; every contact's state then in ``states``,
    to start a `simulate` there), its ``multipliers`` (by decreasing size), and the events
    of one period (the last is the section's own, at ``period``)."""

    period: float
    x0: np.ndarray
    v0: np.ndarray
    contact: int
    state: int
    states: tuple
    multipliers: np.ndarray
    event_time: np.ndarray
    event_contact: np.ndarray
    event_state: np.ndarray
    MODEL = "system"

    @property
    def stable(self) -> bool:
        """No multiplier but the flow's own (the one nearest 1) outside the unit circle (`inside`)."""
        return inside(without_own(self.multipliers))

    def to_dict(self) -> dict:
        return {"period": self.period, "stable": self.stable, "multipliers_abs": np.abs(self.multipliers).tolist(),
                "events": int(self.event_time.size), "x0": self.x0.tolist(), "v0": self.v0.tolist()}

    def to_xarray(self) -> xr.Dataset:
        """Units and meanings from the declarations (`stickslip.cf.finish`)."""
        return cycle_dataset(self, {"period": self.period},
                             "system with frictional contacts: limit cycle and its Floquet multipliers")


def entries(run: SystemRun, signature) -> list[tuple]:
    """``(time, state just after, segment number, contact states after)`` of each event of ``run`` where a contact
    entered a state, as ``signature`` = (contact, state) says."""
    out = []
    for i, (seg, nxt) in enumerate(zip(run.segments, run.segments[1:])):
        if seg.rows and seg.after[signature[0]] == signature[1] != seg.states[signature[0]]:
            out.append((seg.t + seg.duration, nxt.z, i, nxt.states))
    return out


def _newton_step(system: System, segments: tuple, residual: np.ndarray, states: tuple, target: int,
                 back: np.ndarray) -> np.ndarray:
    """The change ``d`` of the start on the section that makes the return map's linearisation
    return to it: ``(P' - I) d = -r``, keeping every sticking contact's slip velocity zero (least
    squares). ``P' = B (I - f n^T / (n . f)) S Phi-`` is the derivative of the return map: the
    monodromy up to just before the return ``Phi-``, the saltation ``S`` of other contacts
    switching at that instant, the end moved along the flow ``f`` to the section ``n`` of the
    contact ``target`` (not ``Phi``, which is the derivative at a fixed time), and mapped back by
    the permutation ``B`` (the identity for a plain cycle)."""
    n = system.dofs
    end, flows = segments[-1], {}
    flow = Flow.cached(system, end.states, flows)
    before = monodromy(system, segments[:-1]) if len(segments) > 1 else np.eye(2 * n)
    phi = expm(end.duration * flow.A)
    ze = phi @ end.z
    phi, f_minus = jump(system, end, ze, flows, skip=target, onto=phi[:2 * n, :2 * n] @ before)
    row = next(r for r in end.rows if flow.owners[r] == target)
    normal = flow.rows[row][:2 * n]
    rate = float(normal @ f_minus)
    if rate == 0.0:
        raise NoSolutionError("a grazing return to the section: no Newton step")
    deriv = phi - np.outer(f_minus, normal @ phi) / rate
    if _lands(system, flow, row, target):  # the section is a landing: its reset
        landed, _ = land(system, flow, ze, list(end.states), [target], flows)
        deriv = Flow.cached(system, tuple(landed), flows).project(deriv)
    deriv = deriv[back]
    rows = [deriv - np.eye(2 * n), normal[back][None, :]]  # the section at the start: n . B^-1 z
    for i, st in enumerate(states):
        c = system.contacts[i]
        if st == 0:
            rows.append(np.concatenate([np.zeros(n), c.direction])[None, :])
        if c.rigid and st != OPEN:  # closed: on the surface, not moving off it
            rows += [np.concatenate([c.normal_direction, np.zeros(n)])[None, :],
                     np.concatenate([np.zeros(n), c.normal_direction])[None, :]]
    rhs = np.concatenate([-residual[:2 * n], np.zeros(sum(r.shape[0] for r in rows[1:]))])
    d = np.linalg.lstsq(np.vstack(rows), rhs, rcond=None)[0]
    return np.concatenate([d, [0.0]])


def orbit_scale(system: System, segments) -> np.ndarray:
    """What a return's residual in ``(x, v)`` is relative to: the largest displacement and the largest
    velocity at the starts of ``segments`` (a return's pieces: its events), each for its kind (1 where
    that is 0). A small orbit converges as well as a large one."""
    n = system.dofs
    Z = np.abs(np.array([s.z[:2 * n] for s in segments]))
    sx, sv = Z[:, :n].max(), Z[:, n:].max()
    return np.repeat([sx if sx > 0 else 1.0, sv if sv > 0 else 1.0], n)


def return_fixed_point(system: System, z: np.ndarray, states: tuple, signature: tuple, horizon: float, tol: float,
                       max_iter: int, symmetry: tuple | None = None, newton_after: int = 2) -> tuple:
    """The start ``z`` (``(x, v, 1)`` just after contact ``signature[0]`` entered the state
    ``signature[1]``, every contact's state ``states``) to which the return map comes back to
    ``tol`` of the orbit's size (`orbit_scale`): ``(time of the return, z, states, segments of the return)``.

    The return is the next such event of the same contact, or with ``symmetry`` =
    ``(target, back, contacts_back)`` of the contact ``target``, the state at it mapped back
    by the permutation ``back`` of ``(x, v)`` (``z[back]``) and the contacts' states by
    ``contacts_back``: a relative periodic orbit (a wave moving by one cell of a symmetric
    structure). The map is iterated, then (after ``newton_after`` iterations, once near and the
    contact states repeating) solved by Newton's method; where a Newton step leaves the
    neighbourhood it goes back to iterating."""
    n = system.dofs
    target, back, contacts_back = symmetry or (signature[0], np.arange(2 * n), np.arange(len(system.contacts)))
    newton, fixed = False, None
    z = zero_slip(system, z, [i for i, s in enumerate(states) if s == 0])  # a start from a neighbouring system
    for it in range(max_iter):
        try:
            one = simulate(system, z[:n], z[n:2 * n], horizon, samples=2, segments=True, states=states,
                           stop_at=(target, signature[1]))
            ret = [r for r in entries(one, (target, signature[1])) if r[0] > 0.0]
        except (ParameterError, NoSolutionError):
            if not newton:
                raise
            ret = []
        if not ret and newton and fixed is not None:  # the Newton step left the neighbourhood: iterate instead
            (z, states), newton = fixed, False
            continue
        if not ret:
            raise NoSolutionError(f"contact {target} did not enter state {signature[1]} within {horizon:g} s of "
                                  f"the start: no {'periodic orbit' if symmetry is None else 'travelling wave'} "
                                  f"through that event (tried {it + 1} returns)")
        period, z_next, last, next_states = ret[0]
        z_next = np.concatenate([z_next[:2 * n][back], [1.0]])
        next_states = tuple(next_states[i] for i in contacts_back)
        residual = z_next - z
        miss = float(np.abs(residual[:2 * n] / orbit_scale(system, one.segments[:last + 1])).max())
        if miss <= tol:
            return period, z, states, one.segments[:last + 1]
        fixed = (z_next, next_states)
        near = np.abs(residual).max() < 1e-2 * max(1.0, np.abs(z).max())  # Newton's start: as large orbits had it
        newton = it >= newton_after and next_states == states and (near or miss < 1e-2)
        if newton:
            z = z + _newton_step(system, one.segments[:last + 1], residual, states, target, back)
        else:
            z, states = z_next, next_states
    raise NoSolutionError(f"the return map did not come back to its start within tol = {tol:g} in {max_iter} "
                          f"iterations (the last return missed it by {miss:.3g} of the orbit's size)")


@shares_flows
def limit_cycle(system: System, x0=None, v0=None, *, transient: float = 100.0, tol: float = 1e-10,
                max_iter: int = 200) -> SystemCycle:
    """The periodic orbit the motion from ``(x0, v0)`` settles on after ``transient`` seconds.

    The last contact event of the transient (a contact entering a state) is the Poincare
    section; the return map to it is iterated, then (once near, the contact states repeating)
    solved by Newton's method with the monodromy as its derivative, until the state repeats to
    ``tol`` (relative); the multipliers are those of the monodromy over one period (with
    saltation matrices)."""
    if isinstance(system, System):
        system.unforced("a limit cycle")
    transient = Q.check("transient", transient)
    tol, max_iter = Q.check("tol", tol), Q.check("max_iter", max_iter)
    try:
        run = simulate(system, x0, v0, transient, samples=2, segments=True)
    except ParameterError as err:  # the run's bound on its length is the transient's
        if err.name != "t_end":
            raise
        raise ParameterError("transient", transient, err.allowed, also=err.also) from None
    if run.event_time.size < 2:
        raise NoSolutionError(f"no contact events within transient = {transient:g} s: no stick-slip cycle to follow")
    spacing = float(np.diff(run.event_time[-16:]).max())
    if transient - run.event_time[-1] > 10.0 * spacing:  # a cycle's events are never that far apart
        raise NoSolutionError(f"no contact event in the last {transient - run.event_time[-1]:.6g} s of the transient "
                              f"(the last at t = {run.event_time[-1]:.6g} s, {run.event_time.size} in all): the motion "
                              "settled (steady sliding, or rest) and no stick-slip cycle follows from this start")
    signature = (int(run.event_contact[-1]), int(run.event_state[-1]))
    crossings = entries(run, signature)
    n = system.dofs
    z, states = crossings[-1][1], crossings[-1][3]
    horizon = transient if len(crossings) < 2 else 4.0 * (crossings[-1][0] - crossings[-2][0])
    try:
        period, z, start, segments = return_fixed_point(system, z, states, signature, horizon, tol, max_iter)
    except NoSolutionError as err:
        raise NoSolutionError(f"{err}; the section was the transient's last such event (t = {crossings[-1][0]:.6g} s): "
                              "a longer transient lets the motion settle onto its cycle first") from None
    mult = np.linalg.eigvals(monodromy(system, segments))
    mult = mult[np.argsort(-np.abs(mult))]
    return SystemCycle(period, z[:n], z[n:2 * n], signature[0], signature[1], start, mult,
                       *period_events(system, z, start, period))

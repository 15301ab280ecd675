"""The periodic response of a system under a periodic force, and its Floquet multipliers.

With harmonic forces (`Harmonic`) whose frequencies are whole multiples of the lowest ``W``, the
force repeats every ``T = 2 pi / W`` and a steady motion repeats every ``p T`` (``p = 1``: the
response at the forcing period; ``p > 1``: a subharmonic). It is a fixed point of the
stroboscopic map ``P``: the state ``(x, v)`` at ``t = 0`` to the state at ``t = p T``, through
every contact event in between. `forced_response` iterates ``P`` from the end of a transient,
then solves ``P(y) = y`` by Newton's method with the monodromy (`monodromy`: saltation matrices
at the events, whose switching functions move with the force) as ``P'``, keeping the slip
velocity of contacts that stick at ``t = 0`` zero: the map and its multipliers are taken on
that stick (a change of such a contact's slip velocity is not a state the motion can be in; each
gives a multiplier 0). The section is a fixed time, so no multiplier is the flow's own: the
motion is stable when no multiplier lies outside the unit circle (beyond `NEUTRAL`). A contact
that sticks through the whole period may stick anywhere: its position is a multiplier 1, a
family of responses (``neutral``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg
import lazy_loader as lazy

from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..quantities import SYSTEM as Q
from ..results import Result
from .floquet import NEUTRAL, inside, monodromy
from .flow import STATE_FLAGS
from .model import System
from .simulate import SystemRun, affine_laws, longest_run, simulate

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["ForcedResponse", "forced_response", "stroboscopic_fixed_point", "forcing_period", "extent",
           "stick_basis", "stroboscopic_multipliers"]


def stick_basis(system: System, states: tuple) -> np.ndarray:
    """An orthonormal basis (columns) of the changes of ``(x, v)`` that keep the slip velocity of the
    contacts sticking in ``states`` zero (the identity when none sticks)."""
    n = system.dofs
    rows = [np.concatenate([np.zeros(n), system.contacts[i].direction]) for i, s in enumerate(states) if s == 0]
    return scipy.linalg.null_space(np.array(rows)) if rows else np.eye(2 * n)


def _on_stick(system: System, run: SystemRun, states: tuple) -> tuple:
    """``(Q, Q^T P' Q)``: the stick's basis at the start and the stroboscopic map's derivative on it
    (``P'`` maps onto the stick: the run ends in the states it started in)."""
    Q = stick_basis(system, states)
    return Q, Q.T @ monodromy(system, run) @ Q


def stroboscopic_multipliers(system: System, run: SystemRun, states: tuple) -> np.ndarray:
    """The multipliers of the run's stroboscopic map on the stick of ``states``, a 0 for each sticking
    contact's slip velocity, by decreasing size."""
    Q, R = _on_stick(system, run, states)
    mult = np.concatenate([np.linalg.eigvals(R), np.zeros(2 * system.dofs - Q.shape[1])])
    return mult[np.argsort(-np.abs(mult))]


def forcing_period(system: System) -> float:
    """The period ``T`` of the system's force (`System.forcing_period`); a `ParameterError` naming
    ``harmonics`` where the force is not periodic (``history`` with a `ForceHistory`)."""
    if not isinstance(system, System):
        raise ParameterError("system", system, "a stickslip.system.System")
    if system.history is not None:
        system.unforced("a periodic response")
    if not system.harmonics:
        raise ParameterError("harmonics", [], "at least one Harmonic (a periodic force); the cycle of a system "
                             "under a constant force is stickslip.system.limit_cycle's")
    period = system.forcing_period
    if period is None:
        raise ParameterError("harmonics", [h.frequency for h in system.harmonics],
                             "frequencies that are whole multiples of the lowest (a periodic force)")
    return period


@dataclass(frozen=True, eq=False, repr=False)
class ForcedResponse(Result):
    """A periodic response: its ``period`` ``p T`` (``periods`` = p forcing periods), the state
    ``x0``, ``v0`` at ``t = 0`` (phase zero of every harmonic force) and the contact ``states``
    then, the ``multipliers`` (by decreasing size), the smallest and largest displacement of each
    degree of freedom over a period (``x_min``, ``x_max``, from ``samples`` uniform samples and
    the events), and the events of one period."""

    period: float
    periods: int
    x0: np.ndarray
    v0: np.ndarray
    states: tuple
    multipliers: np.ndarray
    x_min: np.ndarray
    x_max: np.ndarray
    event_time: np.ndarray
    event_contact: np.ndarray
    event_state: np.ndarray
    MODEL = "system"

    @property
    def stable(self) -> bool:
        """No multiplier outside the unit circle (`inside`)."""
        return inside(self.multipliers)

    @property
    def neutral(self) -> bool:
        """A multiplier on the unit circle (within `NEUTRAL`): a family of responses (a contact stuck
        through the period, anywhere), or a bifurcation."""
        return bool(np.any(np.abs(np.abs(self.multipliers) - 1.0) < NEUTRAL))

    @property
    def amplitude(self) -> np.ndarray:
        """Half the peak-to-peak displacement of each degree of freedom."""
        return 0.5 * (self.x_max - self.x_min)

    def to_dict(self) -> dict:
        return {"period": self.period, "periods": self.periods, "stable": self.stable, "neutral": self.neutral,
                "multipliers_abs": np.abs(self.multipliers).tolist(), "amplitude": self.amplitude.tolist(),
                "events": int(self.event_time.size), "x0": self.x0.tolist(), "v0": self.v0.tolist()}

    def to_xarray(self) -> xr.Dataset:
        """Units and meanings from the declarations (`stickslip.cf.finish`)."""
        m = self.multipliers
        ds = xr.Dataset(
            {"multiplier_real": ("multiplier", m.real), "multiplier_imag": ("multiplier", m.imag),
             "x0": ("dof", self.x0), "v0": ("dof", self.v0), "x_min": ("dof", self.x_min),
             "x_max": ("dof", self.x_max),
             "event_time": ("event", self.event_time), "event_contact": ("event", self.event_contact),
             "event_state": ("event", self.event_state.astype(np.int8), STATE_FLAGS)},
            coords={"dof": np.arange(self.x0.size), "event": np.arange(self.event_time.size)},
            attrs={"period": self.period, "periods": self.periods, "stable": int(self.stable),
                   "neutral": int(self.neutral)})
        return finish(ds, "system with frictional contacts: periodic response to a periodic force", "system")


#: Samples of each run of the stroboscopic map, from which (with its events) each variable's size is taken.
SIZE_SAMPLES = 65


def _run(system: System, z: np.ndarray, states: tuple, horizon: float, samples: int = SIZE_SAMPLES) -> SystemRun:
    n = system.dofs
    return simulate(system, z[:n], z[n:2 * n], horizon, samples=samples, segments=True, states=states)


def _newton_step(system: System, run: SystemRun, residual: np.ndarray, states: tuple) -> np.ndarray:
    """``d`` on the stick of ``states`` with ``(P' - I) d = -r`` there, by least squares. Where it is
    singular (a multiplier within `NEUTRAL` of 1: a contact stuck through the period, anywhere), the
    step along that family of responses is the one that moves the sticking contacts least, as a slow
    change of the force leaves them (the shortest step moved them with the rest: along a branch the
    stuck block of examples/friction_damper drifted a third of the structure's change each step, and
    reached its stick limit early)."""
    Q, R = _on_stick(system, run, states)
    U, s, Vt = np.linalg.svd(R - np.eye(R.shape[0]))
    keep = s > NEUTRAL * max(1.0, s[0])
    d = Vt[keep].T @ ((U[:, keep].T @ (-Q.T @ residual)) / s[keep])
    family, n = Vt[~keep].T, system.dofs
    held = np.array([np.concatenate([c.direction, np.zeros(n)]) for c, st in zip(system.contacts, states)
                     if st == 0]).reshape(-1, 2 * n) @ Q  # each sticking contact's position along its direction
    if family.shape[1] and held.shape[0]:
        d = d - family @ np.linalg.lstsq(held @ family, held @ d, rcond=None)[0]
    return Q @ d


def _sizes(system: System, run: SystemRun) -> np.ndarray:
    """The size of each of ``(x, v)`` over ``run`` (its largest modulus at its samples and events), at
    least 1e-12 of the largest of its kind (displacements, velocities): what a residual is relative to."""
    n = system.dofs
    Z = np.vstack([np.array([s.z[:2 * n] for s in run.segments]), np.hstack([run.x, run.v])])
    size = np.abs(Z).max(axis=0)
    for part in (slice(0, n), slice(n, 2 * n)):
        size[part] = np.maximum(size[part], 1e-12 * size[part].max())
    return np.where(size > 0.0, size, 1.0)


def stroboscopic_fixed_point(system: System, y: np.ndarray, states: tuple, horizon: float, tol: float,
                             max_iter: int, newton_after: int = 2, near: float = 1e-2) -> tuple:
    """``(y, states, run)``: the state ``y = (x, v)`` at ``t = 0`` (contact states ``states``) that the
    motion over ``horizon`` (a whole number of forcing periods) brings back to itself within
    ``tol`` of each variable's size over the run (`_sizes`), and that run (with its segments).
    Iterated, then (once within ``near``, the contact states at the end repeating) by Newton's method;
    a Newton step that changes the contact states at the start or fails goes back to iterating."""
    newton, fixed, residual = False, None, np.full(1, np.inf)
    for it in range(max_iter):
        try:
            run = _run(system, y, states, horizon)
        except (ParameterError, NoSolutionError):
            if not newton or fixed is None:
                raise
            (y, states), newton = fixed, False
            continue
        y_end, end_states = np.concatenate([run.x[-1], run.v[-1]]), tuple(int(s) for s in run.states[-1])
        residual = y_end - y
        miss = float(np.abs(residual / _sizes(system, run)).max())
        if miss <= tol and end_states == states:
            return y, states, run
        fixed = (y_end, end_states)
        newton = it >= newton_after and end_states == states and miss < near
        if newton:
            y = y + _newton_step(system, run, residual, states)
        else:
            y, states = y_end, end_states
    raise NoSolutionError(f"the stroboscopic map over {horizon:.6g} s did not come back to its start within "
                          f"tol = {tol:g} in {max_iter} iterations (the last return missed it by "
                          f"{np.abs(residual).max():.3g}, absolute): no periodic response of this period near the motion "
                          "(try more periods, a longer transient, or another start)")


def forced_response(system: System, x0=None, v0=None, *, periods: int = 1, transient: float = 100.0,
                    tol: float = 1e-10, max_iter: int = 200, samples: int = 2001) -> ForcedResponse:
    """The periodic response of ``system`` under its periodic force that the motion from ``(x0,
    v0)`` settles on after a ``transient`` of at least that many seconds (a whole number of
    forcing periods), repeating every ``periods`` forcing periods (see the module). Its
    multipliers are those of the stroboscopic map over ``periods`` forcing periods; ``x_min``,
    ``x_max`` from ``samples`` uniform samples of that time and the states at its events."""
    T = forcing_period(system)
    affine_laws(system)
    periods = Q.check("periods", periods)
    longest = longest_run(system)[0]
    if periods * T > longest:
        low = min(h.frequency for h in system.harmonics)
        raise ParameterError("harmonics", [h.frequency for h in system.harmonics],
                             f"a lowest frequency of at least {low * periods * T / longest:.6g} rad/s: "
                             f"{periods} period(s) of the force, {periods * T:.6g} s, are longer than a run can be "
                             f"({longest:.6g} s, set by the system's fastest time scale)", also=("periods",))
    transient = Q.check("transient", transient)
    tol, max_iter, samples = Q.check("tol", tol), Q.check("max_iter", max_iter), Q.check("samples", samples)
    whole = max(1, int(np.ceil(transient / T)))
    try:
        first = simulate(system, x0, v0, whole * T, samples=2)
    except ParameterError as err:  # the run's bound on its length is the transient's
        if err.name != "t_end":
            raise
        raise ParameterError("transient", transient, err.allowed, also=err.also) from None
    y = np.concatenate([first.x[-1], first.v[-1]])
    states = tuple(int(s) for s in first.states[-1])
    y, states, run = stroboscopic_fixed_point(system, y, states, periods * T, tol, max_iter)
    mult = stroboscopic_multipliers(system, run, states)
    n = system.dofs
    x_min, x_max, sampled = extent(system, y, states, periods * T, samples)
    return ForcedResponse(periods * T, periods, y[:n], y[n:], states, mult, x_min, x_max,
                          sampled.event_time, sampled.event_contact, sampled.event_state)


def extent(system: System, y: np.ndarray, states: tuple, duration: float, samples: int) -> tuple:
    """``(x_min, x_max, run)``: the smallest and largest displacement of each degree of freedom over
    ``duration`` from ``y = (x, v)`` (contact states ``states``), from ``samples`` uniform samples and
    the state at every event; the run (its samples, events and segments)."""
    n = system.dofs
    run = simulate(system, y[:n], y[n:2 * n], duration, samples=samples, states=states, segments=True)
    x_all = np.vstack([run.x, np.array([s.z[:n] for s in run.segments])])
    return x_all.min(axis=0), x_all.max(axis=0), run

"""Systems whose contacts follow rate-and-state friction: their motion, steady sliding and its stability.

With a rate-and-state law at a contact (`stickslip.rsf.RateState`) its friction force is a
smooth function of the slip rate and of the contact's state variables, and it does not stick:

    M x'' + C x' + K x = f + sum_i w_i N_i sign(v_i) mu_i(|v_i|, psi_i),   v_i = V_i - w_i . x',
    psi_i' = g_i(|v_i|, psi_i)

(``psi = ln(V_0 theta / D_c)``, one or two per contact; ``g`` the law's evolution). The motion is
integrated by Radau IIA (scipy; the state variables make it stiff). The law as written,
``mu = f_0 + a ln(v / V_0) + b psi``, has no value at ``v = 0``: a run whose slip rate reaches zero
stops and says so; the regularised law (``asinh``) holds through ``v = 0`` in either direction.
The system's other contacts (any other law, a constant normal force) slip with ``s N mu(|v|)`` or
stick (`stickslip.system.rate_state_modes`: modes, switches located as events of the runs).

Steady sliding: the structure rests (``x' = 0``) with every contact slipping at ``v_i = V_i`` and
each rate-and-state contact's state steady, ``K x = f + sum_i w_i N_i sign(V_i) mu_ss,i(|V_i|)``; its
stability is that of the equations linearised there (complex steps), in ``(x, x', psi)``. For one
block on one contact the leading pair crosses the imaginary axis at the closed-form critical stiffness
``k_c = N (b - a) / D_c (1 + m V^2 / (N a D_c))`` (Ruina 1983, Rice & Ruina 1983).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import lazy_loader as lazy
from scipy.integrate import solve_ivp

from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..quantities import SYSTEM as Q
from ..results import Result
from ..rsf import RateState
from ..rsf.slider import MAX_CALLS, complex_jacobian
from .model import System
from .rate_state_modes import first_mode, mode_events, switch
from .flow import OPEN, STATE_FLAGS
from .simulate import MAX_INSTANT_EVENTS, MAX_NUMBERS
from .smoothkernel import Compiled, Failed, compiled_laws
from .steady import SteadySliding
from .. import validation as check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["RateStateRun", "RateStateSteady", "rate_state_simulate", "rate_state_steady", "is_rate_state", "integrated",
           "RateStateEquations", "start_state", "slowest_state_time"]

#: A slip rate taken for zero (m/s): the regularised law's friction is 0 to round-off there.
_TINY = 1e-300
#: The longest run, in the slowest time scale ``D_c / V`` of the contacts' states (refused up front,
#: not left to use up the evaluations: a cycle of stick-slip takes a few of them and hundreds of steps).
LONGEST = 1e4
#: How `rate_state_simulate` integrates between switches.
METHODS = ("auto", "compiled", "radau")


def _constant_normal(system: System, which: str) -> None:
    """A `ParameterError` naming the first contact with a normal direction (``which``: the system's kind)."""
    for i, c in enumerate(system.contacts):
        if c.unilateral or c.rigid:
            raise ParameterError(f"contacts[{i}].normal_direction", c.normal_direction.tolist(),
                                 f"left out: a system with {which} has a constant normal force at every contact "
                                 "(unilateral and rigid contacts are not in this version)")


def is_rate_state(system: System) -> bool:
    """True when a contact's law is rate-and-state (the system then moves by `rate_state_simulate`;
    its other contacts, which may stick, need a constant normal force: checked, an error if not)."""
    check.instance("system", system, System, "a stickslip.system.System")
    rsf = any(isinstance(c.friction, RateState) for c in system.contacts)
    if rsf:
        _constant_normal(system, "rate-and-state contacts")
    return rsf


def integrated(system: System) -> bool:
    """True when ``system`` moves by `rate_state_simulate` (integrated between its switches): a contact's
    law is rate-and-state, or not affine in the slip speed (Stribeck, a user's law: no exact flow), or
    a unilateral contact's law depends on the slip speed (its force ``s N(x) mu(v)`` is not linear).
    With rate-and-state contacts every contact needs a constant normal force, without them no contact
    may be rigid (checked, an error if not)."""
    check.instance("system", system, System, "a stickslip.system.System")
    if is_rate_state(system):
        return True
    smooth = any(getattr(c.friction, "affine", None) is None or (c.unilateral and c.friction.affine[1] != 0.0)
                 for c in system.contacts)
    if smooth:
        for i, c in enumerate(system.contacts):
            if c.rigid:
                raise ParameterError(f"contacts[{i}].rigid", True, "false in a system with a law that is not affine "
                                     "in the slip speed (rigid contacts are not in this version; a unilateral "
                                     "contact with a normal_stiffness is)")
    return smooth


def slowest_state_time(eq: "RateStateEquations") -> float:
    """The slowest time scale ``D_c / V`` of the rate-and-state contacts' states (s; inf without one)."""
    return max((float(law.dc_values.max()) / max(abs(V), law.v_ref) for law, V, r in zip(eq.laws, eq.V, eq.rsf)
                if r), default=math.inf)


def _laws(system) -> list:
    if not isinstance(system, System):
        raise ParameterError("system", system, "a stickslip.system.System")
    if not integrated(system):
        raise ParameterError("contacts", [type(c.friction).__name__ for c in system.contacts],
                             "a rate-and-state law (stickslip.rsf.RateState) or a law not affine in the slip speed "
                             "(Stribeck, a user's law) at one contact at least (affine laws only: "
                             "stickslip.system.simulate, exact)")
    return [c.friction for c in system.contacts]


class RateStateEquations:
    """The right-hand side in ``y = (x, x', psi of the first rate-and-state contact, of the next, ...)``.

    A contact with another law (``rsf[i]`` False) slips or sticks as ``mode[i]`` says (1 or -1: slipping
    that way, its force ``s N mu(v)``; 0: stuck, its force the one that keeps its slip rate at zero,
    `stick_forces`; `OPEN`: a unilateral contact off its surface, no force); `set_mode` sets it. A
    rate-and-state contact's entry of ``mode`` is not used. A unilateral contact's normal force is
    ``N(x) = N_0 - k_n n . x`` (`normal`), pushing the structure along ``n`` while closed (with
    ``normal_on_structure``)."""

    def __init__(self, system: System):
        self.system, self.laws = system, _laws(system)
        self.n = system.dofs
        self.rsf = [isinstance(law, RateState) for law in self.laws]
        self.offsets = np.cumsum([0] + [law.states if r else 0 for law, r in zip(self.laws, self.rsf)])
        self.size = 2 * self.n + int(self.offsets[-1])
        self.V = np.array([c.surface_speed for c in system.contacts])
        self.N = np.array([c.normal_force for c in system.contacts])
        self.Kn = system.normal_directions  # k_n n per contact (zero without a normal direction)
        self.push = system.normal_units * np.array([c.pushes for c in system.contacts], dtype=float)
        self.set_mode(tuple(1 if r or V >= 0 else -1 for r, V in zip(self.rsf, self.V)))

    def set_mode(self, mode) -> None:
        """The contacts' states: 1 or -1 slipping, 0 stuck (only a contact whose law is not rate-and-state).
        With stuck contacts (columns ``E`` of the directions) ``MiE = M^-1 E`` and ``gram_inv`` the
        pseudo-inverse of ``E^T M^-1 E``."""
        self.mode = tuple(int(m) for m in mode)
        self.stuck = [i for i, m in enumerate(self.mode) if m == 0 and not self.rsf[i]]
        if self.stuck:  # (a pseudo-inverse: stuck contacts along the same direction share its force, least norm)
            E = self.system.directions[:, self.stuck]
            self.MiE = self.system.inverse_mass @ E
            self.gram_inv = np.linalg.pinv(E.T @ self.MiE)

    def normal(self, y):
        """Each contact's normal force at ``y``: ``N_0 - k_n n . x`` (``N_0`` without a normal direction)."""
        return self.N - self.Kn.T @ y[:self.n]

    def _rest(self, t, y, forces):
        sysm, n = self.system, self.n
        rest = sysm.external_force(t) - sysm.stiffness @ y[:n] - sysm.damping @ y[n:2 * n] + sysm.directions @ forces
        closed = np.array(self.mode) != OPEN
        return rest + self.push[:, closed] @ self.normal(y)[closed]

    def stick_forces(self, t, y) -> np.ndarray:
        """The friction forces of the stuck contacts (in `stuck`'s order) that keep their slip rates at zero."""
        if not self.stuck:
            return np.zeros(0)
        rest = self.system.inverse_mass @ self._rest(t, y, self.forces(y)[1])
        return -self.gram_inv @ (self.system.directions[:, self.stuck].T @ rest)

    def psi(self, y, i):
        return y[2 * self.n + self.offsets[i]:2 * self.n + self.offsets[i + 1]]

    def forces(self, y):
        """``(slip rates, friction forces, d psi / dt)`` at ``y`` (complex ``y`` for complex steps)."""
        n, W = self.n, self.system.directions
        vr = self.V - W.T @ y[n:2 * n]
        forces = np.empty(len(self.laws), dtype=np.result_type(y, float))
        rates = np.empty(self.size - 2 * n, dtype=forces.dtype)
        normal = self.normal(y)
        for i, law in enumerate(self.laws):
            if not self.rsf[i]:  # slipping as its mode says (stuck: 0 here, see stick_forces; open: none)
                s = self.mode[i]
                if s == 0 or s == OPEN:
                    forces[i] = 0.0
                    continue
                v = vr[i].real if s * vr[i].real > 0 else s * _TINY  # just released: its side of zero
                mu = law.kinetic(v) + (1j * law.slope(v) * vr[i].imag if np.iscomplexobj(vr) else 0.0)
                forces[i] = s * normal[i] * mu
                continue
            s = 1.0 if vr[i].real >= 0 else -1.0
            if not law.regularized and vr[i].real <= 0.0:
                raise _Stopped(i)
            log_v = np.log(s * vr[i]) if abs(vr[i]) > _TINY else np.log(_TINY)  # (regularised: mu(0) = 0)
            psi = self.psi(y, i)
            mu, _, _ = law.friction(log_v, psi)
            forces[i] = s * self.N[i] * mu
            rates[self.offsets[i]:self.offsets[i + 1]] = law.state_rate(log_v, psi)
        return vr, forces, rates

    def sampled(self, Y: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(slip rates, friction forces)`` at each row of ``Y`` (states a run accepted in the current
        mode, at times ``t``: at once)."""
        n = self.n
        vr = self.V[None, :] - Y[:, n:2 * n] @ self.system.directions
        normal = self.N[None, :] - Y[:, :n] @ self.Kn
        forces = np.empty_like(vr)
        for i, law in enumerate(self.laws):
            if not self.rsf[i]:
                s = self.mode[i]
                if s == 0 or s == OPEN:  # (stuck: its force below, from the constraint)
                    forces[:, i] = 0.0
                    continue
                v = np.where(s * vr[:, i] > 0, vr[:, i], s * _TINY)
                forces[:, i] = s * normal[:, i] * np.asarray(law.kinetic(v), dtype=float)
                continue
            log_v = np.log(np.maximum(np.abs(vr[:, i]), _TINY))
            psi = Y[:, 2 * n + self.offsets[i]:2 * n + self.offsets[i + 1]].T
            mu = np.broadcast_to(law.friction(log_v, psi)[0], log_v.shape)
            forces[:, i] = np.where(vr[:, i] >= 0, 1.0, -1.0) * self.N[i] * mu
        if self.stuck:  # the stuck contacts' forces: linear in the rows, the force in time apart
            sysm = self.system
            if sysm.history is None:  # f + B (cos W t, sin W t, ...) at every sample at once
                E = np.array([f(h.frequency * t) for h in sysm.harmonics for f in (np.cos, np.sin)]).reshape(-1, t.size)
                F = sysm.force[None, :] + (sysm.forcing_matrix @ E).T
            else:
                F = np.array([sysm.external_force(float(ti)) for ti in t])
            closed = np.array(self.mode) != OPEN
            rest = (F - Y[:, :n] @ sysm.stiffness.T - Y[:, n:2 * n] @ sysm.damping.T + forces @ sysm.directions.T
                    + normal[:, closed] @ self.push[:, closed].T)
            lam = -self.gram_inv @ (sysm.directions[:, self.stuck].T @ sysm.inverse_mass @ rest.T)
            forces[:, self.stuck] = lam.T
        return vr, forces

    def jacobian(self, t, y):
        """``d y' / d y`` by complex steps (exact to round-off: the laws take complex arguments)."""
        return complex_jacobian(lambda z: self(t, z), y)

    def guarded(self, t, y):
        """``y'``, NaN at a state beyond zero slip rate of a law without regularisation (a trial state
        of an implicit step: the solver's Newton iteration fails there and the step shrinks)."""
        try:
            return self(t, y)
        except _Stopped:
            return np.full(y.size, np.nan)

    def guarded_jacobian(self, t, y):
        """`jacobian`, zero at a state beyond zero slip rate (see `guarded`)."""
        try:
            return self.jacobian(t, y)
        except _Stopped:
            return np.zeros((y.size, y.size))

    def __call__(self, t, y):
        sysm, n = self.system, self.n
        _, forces, rates = self.forces(y)
        a = sysm.inverse_mass @ self._rest(t, y, forces)
        if self.stuck:  # M a = rest + E lambda with E^T a = 0
            a = a - self.MiE @ (self.gram_inv @ (sysm.directions[:, self.stuck].T @ a))
        return np.concatenate([y[n:2 * n], a, rates])


class _Budget(Exception):
    """`MAX_CALLS` evaluations of the equations used up."""


class _Stopped(Exception):
    def __init__(self, contact: int):
        self.contact = contact


@dataclass(frozen=True, eq=False, repr=False)
class RateStateRun(Result):
    """A motion of a system with rate-and-state contacts: samples of the displacements ``x``, the
    velocities ``v``, each contact's ``slip_rate``, ``friction_force``, state variables ``psi``
    (``ln(V_0 theta / D_c)``; a second one NaN where a law has one, both NaN for a contact with
    another law) and ``states`` (1 slip, 0 stick, -1 reverse slip); the switches of the contacts
    that may stick (``event_time``, ``event_contact``, ``event_state``: the state after)."""

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    slip_rate: np.ndarray
    friction_force: np.ndarray
    psi: np.ndarray
    states: np.ndarray | None = None
    event_time: np.ndarray = field(default_factory=lambda: np.zeros(0))
    event_contact: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    event_state: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int8))
    MODEL = "system"

    def to_dict(self) -> dict:
        return {"t_end": float(self.t[-1]), "x_end": self.x[-1].tolist(), "v_end": self.v[-1].tolist(),
                "slip_rate_end": self.slip_rate[-1].tolist(), "slip_rate_max": self.slip_rate.max(axis=0).tolist(),
                "slip_rate_min": self.slip_rate.min(axis=0).tolist(), "events": int(self.event_time.size)}

    def to_xarray(self) -> xr.Dataset:
        """Units and meanings from the declarations (`stickslip.cf.finish`)."""
        n, k = self.x.shape[1], self.slip_rate.shape[1]
        ds = xr.Dataset(
            {"x": (("t", "dof"), self.x), "v": (("t", "dof"), self.v),
             "slip_rate": (("t", "contact"), self.slip_rate,
                           {"units": "m/s", "long_name": "slip velocity V - w . x' of the contact"}),
             "friction_force": (("t", "contact"), self.friction_force),
             "psi": (("t", "contact", "state_variable"), self.psi,
                     {"units": "1", "long_name": "state variable ln(V_0 theta / D_c) of the contact's law"})},
            coords={"t": self.t, "dof": np.arange(n), "contact": np.arange(k),
                    "state_variable": np.arange(self.psi.shape[2])})
        if self.states is not None:
            ds["contact_state"] = (("t", "contact"), self.states.astype(np.int8), STATE_FLAGS)
            ds["event_time"] = ("event", self.event_time)
            ds["event_contact"] = ("event", self.event_contact)
            ds["event_state"] = ("event", self.event_state.astype(np.int8), STATE_FLAGS)
        return finish(ds, "system with rate-and-state contacts: a motion", "system")


@dataclass(frozen=True, eq=False, repr=False)
class RateStateSteady(SteadySliding):
    """`SteadySliding` of a system with rate-and-state contacts: the resting position, the friction
    forces, the direct effect's damping ``C + sum_i N_i (d mu_i / d v) w_i w_i^T``, the eigenvalues
    of the equations linearised in ``(x, x', psi)`` and each rate-and-state contact's steady ``psi``."""

    psi: tuple = ()

    @property
    def marginal(self) -> bool:
        """The leading eigenvalue's real part is zero to round-off of that eigenvalue (``1e3 eps`` of its
        modulus): the direct effect's eigenvalues, ``-N a / (m V)``, dwarf the slow pair whose real part
        decides, so the largest modulus is no scale for it."""
        lead = self.eigenvalues[0] if self.eigenvalues.size else 0.0
        return bool(abs(lead.real) <= 1e3 * np.finfo(float).eps * abs(lead))

    def to_dict(self) -> dict:
        return {**super().to_dict(), "psi": [p.tolist() for p in self.psi]}


def _steady_state(eq: RateStateEquations) -> np.ndarray:
    sysm = eq.system
    if np.any(eq.V == 0.0):
        i = int(np.flatnonzero(eq.V == 0.0)[0])
        raise ParameterError(f"contacts[{i}].surface_speed", 0.0, "not 0 for steady sliding (a rate-and-state "
                             "contact at rest has no steady state: its state grows without end; another "
                             "contact at rest does not slide)")
    eq.set_mode(tuple(1 if V > 0 else -1 for V in eq.V))
    y = np.zeros(eq.size)
    for i, law in enumerate(eq.laws):
        if not eq.rsf[i]:
            if abs(eq.V[i]) >= law.max_speed:
                raise ParameterError(f"contacts[{i}].surface_speed", float(eq.V[i]),
                                     f"below the speed {law.max_speed:g} where its friction law ends")
            continue
        if eq.V[i] < 0 and not law.regularized:
            raise ParameterError(f"contacts[{i}].surface_speed", float(eq.V[i]), "> 0 for the law as written, which "
                                 "has no value at a backward slip (or the law regularized)")
        y[2 * eq.n + eq.offsets[i]:2 * eq.n + eq.offsets[i + 1]] = law.steady_psi(abs(eq.V[i]))
    _, forces, _ = eq.forces(y)  # at x = 0: N_0 at every contact
    forces = forces.real
    k_eff, load = sysm.stiffness.copy(), sysm.external_force(0.0) + sysm.directions @ forces + eq.push @ eq.N
    for i, c in enumerate(sysm.contacts):  # N(x) = N_0 - k_n n . x: its push and its friction s mu N(x)
        if c.unilateral:
            k_eff += np.outer(sysm.directions[:, i] * forces[i] / eq.N[i] + eq.push[:, i], eq.Kn[:, i])
    try:
        y[:eq.n] = np.linalg.solve(k_eff, load)
    except np.linalg.LinAlgError:
        raise ParameterError("stiffness", sysm.stiffness.tolist(), "an invertible matrix for steady sliding (the "
                             "structure held in place by its springs)") from None
    normal = eq.normal(y)
    for i, c in enumerate(sysm.contacts):
        if c.unilateral and not normal[i] > 0.0:
            raise NoSolutionError(f"contact {i} is open at the resting position (its normal force would be "
                                  f"{normal[i]:.6g} N): no steady sliding on it")
    return y


def rate_state_steady(system: System) -> RateStateSteady:
    """Steady sliding of ``system`` (a rate-and-state contact at least, every surface moving) and its
    linear stability."""
    eq = RateStateEquations(system)
    system.unforced("steady sliding")
    y = _steady_state(eq)
    jac = eq.jacobian(0.0, y)
    if not np.all(np.isfinite(jac)):
        raise NoSolutionError("the equations overflow about steady sliding (a slip rate, a or D_c too small "
                              "for the rest of the system)")
    eig = np.linalg.eigvals(jac)
    eig = eig[np.lexsort((-eig.imag, -eig.real))]
    vr, forces, _ = eq.forces(y)
    W, n = system.directions, eq.n
    normal = eq.normal(y)
    slopes = [normal[i] * (float(np.real(law.friction(np.log(abs(vr[i])), eq.psi(y, i))[1])) / abs(vr[i])
                           if eq.rsf[i] else float(law.slope(vr[i].real)) * np.sign(vr[i].real))
              for i, law in enumerate(eq.laws)]  # N d(s mu) / d v: (d mu / d ln v) / v for rate-and-state
    direct = system.damping + (W * np.array(slopes)) @ W.T
    return RateStateSteady(y[:n].copy(), forces.real.copy(), direct, eig,
                           tuple(eq.psi(y, i).copy() for i in range(len(eq.laws)) if eq.rsf[i]))


def _given_psi(psi0, eq: RateStateEquations) -> np.ndarray:
    """``psi0``: one entry per rate-and-state contact (in order), a number or a list of its law's state
    variables."""
    laws = [law for law, r in zip(eq.laws, eq.rsf) if r]
    want = f"{len(laws)} entries, one per rate-and-state contact: its state variable ln(V_0 theta / D_c) (a list " \
           "of two for a law with two), each finite"
    if not isinstance(psi0, (list, tuple, np.ndarray)):
        raise ParameterError("psi0", psi0, "a list of " + want)
    try:
        rows = [np.atleast_1d(np.asarray(p, dtype=float)) for p in psi0]
    except (TypeError, ValueError):
        raise ParameterError("psi0", psi0, want) from None
    if len(rows) != len(laws) or any(r.shape != (law.states,) for r, law in zip(rows, laws)):
        raise ParameterError("psi0", psi0, want)
    return np.concatenate([np.zeros(0)] + [np.asarray(Q["psi0"].check_array(r, "psi0"), dtype=float) for r in rows])


def start_state(eq: RateStateEquations, x0=None, v0=None, psi0=None) -> np.ndarray:
    """``y = (x, x', psi)`` at the start: ``x0`` (default: steady sliding's position under the force at
    ``t = 0``), ``v0`` (default:
    rest) and ``psi0`` (one list per contact; default: steady at the start's slip rates), checked."""
    system, n = eq.system, eq.n
    y = np.zeros(eq.size)
    if x0 is None:
        y[:n] = _steady_state(eq)[:n] if np.all(eq.V != 0.0) else 0.0
    if x0 is not None or v0 is not None:
        for name, value, at in (("x0", x0, slice(0, n)), ("v0", v0, slice(n, 2 * n))):
            if value is None:
                continue
            arr = np.asarray(Q[name].check_array(value, name), dtype=float).reshape(-1)
            if arr.shape != (n,):
                raise ParameterError(name, arr.tolist(), f"{n} numbers (one per degree of freedom)")
            y[at] = arr
    vr = eq.V - system.directions.T @ y[n:2 * n]
    for i, law in enumerate(eq.laws):
        if psi0 is None and eq.rsf[i]:
            if vr[i] == 0.0:
                raise ParameterError("psi0", None, f"given: contact {i} starts at zero slip rate, where no state "
                                     "is steady", also=("v0",))
            y[2 * n + eq.offsets[i]:2 * n + eq.offsets[i + 1]] = law.steady_psi(abs(vr[i]))
    if psi0 is not None:
        y[2 * n:] = _given_psi(psi0, eq)
    try:
        eq.forces(y)
    except _Stopped as stop:
        raise ParameterError("v0", y[n:2 * n].tolist(), f"a start at which contact {stop.contact} slips forward "
                             "(the law without regularisation has no value at zero or negative slip rate)") from None
    return y


def rate_state_simulate(system: System, x0=None, v0=None, t_end: float = 10.0, *, psi0=None, samples: int = 1001,
                        rtol: float = 1e-10, method: str = "auto") -> RateStateRun:
    """The motion of ``system`` (its rate-and-state contacts slipping; any other contact slipping or
    sticking, `stickslip.system.rate_state_modes`) from ``(x0, v0)`` (default: steady sliding's
    position, at rest) with the rate-and-state contacts' state variables ``psi0`` (one list per
    such contact; default: steady at the slip rate of the start), over ``t_end`` with ``samples``
    samples; Radau IIA at relative tolerance ``rtol`` between the switches, which are located to
    round-off of the dense output.

    ``method``: ``"radau"`` as above; ``"compiled"`` DOP853 compiled with the laws
    (`stickslip.system.smoothkernel`: a system without a rate-and-state contact or a force history,
    whose laws are affine, Stribeck's or a user's function numba compiles, at most four such
    functions); ``"auto"`` (the default) the compiled one where it applies, else Radau. A compiled run
    that stops (a law without a value, a step below round-off) is made again with Radau, which says why."""
    if not isinstance(method, str) or method not in METHODS:
        raise ParameterError("method", method, "one of " + ", ".join(METHODS))
    eq = RateStateEquations(system)
    laws = None if method == "radau" else compiled_laws(eq)
    if method == "compiled" and laws is None:
        raise ParameterError("method", method, "'auto' or 'radau' for this system (the compiled flows take no "
                             "rate-and-state contact, no force history, laws affine, Stribeck's or a user's function "
                             "numba compiles, at most four such functions)")
    flows = None if laws is None else Compiled(eq, laws)
    n, k = eq.n, len(eq.laws)
    t_end, samples, rtol = Q.check("t_end", t_end), Q.check("samples", samples), Q.check("rtol", rtol)
    scale = slowest_state_time(eq)  # (no rate-and-state contact: t_end's declared range bounds it)
    if t_end > LONGEST * scale:
        raise ParameterError("t_end", t_end, f"<= {LONGEST * scale:.6g} s ({LONGEST:.0e} times the slowest time "
                             f"D_c / V of the contacts' states, {scale:.3g} s; simulate in pieces from the last "
                             "state for more)", also=("contacts",))
    if samples * (2 * n + 3 * k + eq.size) > MAX_NUMBERS:
        raise ParameterError("samples", samples, f"<= {int(MAX_NUMBERS // (2 * n + 3 * k + eq.size))} for "
                             "this system (the samples hold at most 1.25e8 numbers, 1 GB)")
    y = start_state(eq, x0, v0, psi0)
    mode, y = first_mode(eq, y)
    times = np.linspace(0.0, t_end, samples)
    Y, slip, force = np.empty((samples, eq.size)), np.empty((samples, k)), np.empty((samples, k))
    states = np.empty((samples, k), dtype=np.int8)
    events = ([], [], [])
    last = [0.0, y, 0]  # the latest state the equations were evaluated at (where a failed run got to), calls

    def rhs(t, state):
        last[2] += 1
        if last[2] > MAX_CALLS:
            raise _Budget
        try:
            out = eq(t, state)
        except _Stopped:  # a trial state beyond zero slip rate: Radau's Newton iteration fails, the step shrinks
            return np.full(state.size, np.nan)
        last[:2] = t, state
        return out

    t, j, instant = 0.0, 0, 0
    while True:
        switches = mode_events(eq)
        try:
            if flows is not None:
                sol = flows.solve(t, t_end, y, times[j:], rtol, switches)
            else:
                sol = solve_ivp(rhs, (t, t_end), y, method="Radau", t_eval=times[j:], rtol=rtol,
                                jac=eq.guarded_jacobian, atol=rtol * np.maximum(1.0, np.abs(y)) * 1e-3,
                                events=switches or None)
        except Failed:  # Radau says why
            return rate_state_simulate(system, x0, v0, t_end, psi0=psi0, samples=samples, rtol=rtol, method="radau")
        except _Budget:
            raise NoSolutionError(f"more than {MAX_CALLS:.0e} evaluations of the equations by t = {last[0]:.6g} s "
                                  f"of t_end = {t_end:g} s: a shorter t_end, or a looser rtol") from None
        except ParameterError:  # a law's own (a user's function out of its range)
            raise
        except (ValueError, _Stopped):  # scipy refuses a step or a Jacobian that is not finite
            sol = None
        if sol is None or sol.status < 0 or not np.all(np.isfinite(sol.y)):
            _failed(eq, sol, last, t_end)
        m = len(sol.t)  # (a list, empty, where no sample falls between two switches)
        if m:
            Y[j:j + m] = sol.y.T
            slip[j:j + m], force[j:j + m] = eq.sampled(sol.y.T, sol.t)
            states[j:j + m] = np.where(eq.rsf, np.where(slip[j:j + m] >= 0, 1, -1), np.array(eq.mode))
            j += m
        if sol.status == 0:
            break
        hit = next(e for e, te in zip(switches, sol.t_events) if te.size)
        te, ye = float(sol.t_events[switches.index(hit)][0]), sol.y_events[switches.index(hit)][0]
        if hit.kind == "limit":
            raise NoSolutionError(f"simulation stopped at t = {te:.17g}: the slip speed of contact {hit.contact} "
                                  f"reached the limit of its friction law, |v_r| < "
                                  f"{eq.laws[hit.contact].max_speed:.6g} (beyond it the law gives no friction "
                                  "coefficient)")
        instant = instant + 1 if te <= t else 0
        if instant > MAX_INSTANT_EVENTS:
            raise NoSolutionError(f"simulation stopped: {MAX_INSTANT_EVENTS} contact events at t = {t:.17g} without "
                                  "time passing (chattering)")
        before = eq.mode
        mode, y = switch(eq, te, ye, hit)
        for i in range(k):
            if mode[i] != before[i]:
                events[0].append(te), events[1].append(i), events[2].append(mode[i])
        t = te
        if j == samples and t >= t_end:
            break
    if j != samples:
        _failed(eq, None, last, t_end)
    kmax = max((law.states for law, r in zip(eq.laws, eq.rsf) if r), default=0)
    psi = np.full((samples, k, kmax), np.nan)
    for i in range(k):
        psi[:, i, :eq.offsets[i + 1] - eq.offsets[i]] = Y[:, 2 * n + eq.offsets[i]:2 * n + eq.offsets[i + 1]]
    return RateStateRun(times, Y[:, :n].copy(), Y[:, n:2 * n].copy(), slip, force, psi, states,
                        np.array(events[0]), np.array(events[1], dtype=int), np.array(events[2], dtype=np.int8))


def _failed(eq: RateStateEquations, sol, last, t_end: float):
    """Raise what stopped a run: a contact's slip rate at zero under the law as written, or Radau."""
    n, system = eq.n, eq.system
    slow = [i for i, v in enumerate(eq.V - system.directions.T @ last[1][n:2 * n])
            if eq.rsf[i] and not eq.laws[i].regularized and v <= 1e-3 * abs(eq.V[i])]
    if slow:
        raise NoSolutionError(f"the slip rate of contact {slow[0]} fell to zero at t = {last[0]:.6g} s: the law "
                              "as written (mu = f0 + a ln(v / V0) + ...) has no value there; give it "
                              "regularized = true")
    why = "its numbers left the range of floats" if sol is None else sol.message
    raise NoSolutionError(f"the motion could not be integrated beyond t = {last[0]:.6g} s of t_end = {t_end:g} s "
                          f"(Radau: {why}); a regularised contact held near zero slip rate (a "
                          "stick, where the law's slope a exp(Psi/a)/(2 V0) makes the equations too stiff) "
                          "stops it too")

"""An elastic half-space sliding antiplane on a rigid body (the paper's model 3 out of its plane), or
its surface free under an applied traction, in time: the spectral boundary integral method.

The interface ``0 <= x < L`` is periodic, cut into ``N`` elements (``dx = L / N``); the surface's
displacement ``w`` along z is the slip on the rigid body. Its traction is the loading ``tau0(x, t)``
plus the half-space's response (`stickslip.sbim.kernels`), ``tau = tau0 + f - (mu / c) V``, with
``f`` the static and memory terms computed mode by mode by the FFT from the slips and the slip
rates before the step: the radiation damping ``-(mu / c) V`` is the only term in the current rate,
so each node's rate follows from its interface law alone (explicit; Geubelle and Rice, 1995).

**Laws** (`FreeSurface`, `Coulomb`, `SlipWeakening`): the shear strength of each node. A stuck node
holds while its driving stress ``g = tau0 + f`` stays within its static strength; a node that moves
slides at ``V = (c / mu) sign(g) (|g| - S)`` with its sliding strength ``S``, the kinetic one (Coulomb)
or the slip-weakened one, ``tau_s - (tau_s - tau_d) min(|slip| / D_c, 1)``, and sticks again
(``V = 0``, ``tau = g``) when ``|g| <= S``.

**Scheme.** The rate found at ``t_n`` is held over the step, ``w_{n+1} = w_n + dt V_n``, and the
memory integral takes each past step's slip at the step's end (`stickslip.sbim.kernels.
ragged_step_weights`): first order in ``dt`` (measured in the tests). ``dt = beta dx / c``; ``beta <=
2/pi`` (the update of the shortest mode's static stiffness, ``|k| c dt <= 2``), and a run is refused
if any mode of the scheme would grow by more than 1 % over its steps (`stickslip.sbim.stability`, the
roots of each mode's recurrence: with 16 periods of history the shortest modes grow from ``beta`` =
0.55). Each mode's history is kept for ``history_periods`` of its periods and truncated
beyond (the neglected part of its kernel, `stickslip.sbim.kernels.truncated_part`, is in the result).
Each mode keeps its own length of history (`stickslip.sbim.history`): about ``(eta N / beta) ln(N / 2)``
complex numbers, the cost of a step in complex products (1.3 million at ``N = 2^14``, ``eta = 4``,
``beta = 1/2``).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field, fields, is_dataclass
from typing import Callable

import numpy as np

from ..errors import NoSolutionError, ParameterError
from ..quantities.sbim import SBIM as Q
from ..results import Result
from .fields import PeriodicGrid, check_hooks, check_resumed, space_time
from .history import History
from .kernels import ragged_step_weights, truncated_part
from .ratestate import RateStateFriction, advance_state, slip_rates
from .scales import resolution_notes, weakening_lengths
from .stability import check_stable

log = logging.getLogger("stickslip.sbim")

__all__ = ["FreeSurface", "Coulomb", "SlipWeakening", "AntiplaneProblem", "AntiplaneRun", "run_antiplane",
           "mode_traction", "uniform_traction", "partial_antiplane", "RUN_FORMAT", "law_parameters"]

#: Largest history kept (modes x steps, complex numbers): 2 GB.
MAX_HISTORY = 1 << 27


@dataclass(frozen=True)
class FreeSurface:
    """No strength: the surface is free under the applied traction."""

    def initial(self, n: int) -> np.ndarray:
        return np.zeros(n)

    def strength(self, slip: np.ndarray, sliding: np.ndarray) -> np.ndarray:
        return np.zeros(slip.shape)


@dataclass(frozen=True)
class Coulomb:
    """Static and kinetic shear strengths [Pa] (friction coefficients times the normal stress)."""

    static_strength: float
    kinetic_strength: float

    def __post_init__(self):
        for name in ("static_strength", "kinetic_strength"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        if self.kinetic_strength > self.static_strength:
            raise ParameterError("kinetic_strength", self.kinetic_strength, f"at most static_strength = "
                                 f"{self.static_strength:g} Pa", also=("static_strength",))

    def strength(self, slip: np.ndarray, sliding: np.ndarray) -> np.ndarray:
        return np.where(sliding, self.kinetic_strength, self.static_strength)


@dataclass(frozen=True)
class SlipWeakening:
    """Linear slip-weakening: from ``static_strength`` to ``kinetic_strength`` [Pa] over
    ``weakening_slip`` [m] of slip (a stuck node keeps the strength its slip has reached)."""

    static_strength: float
    kinetic_strength: float
    weakening_slip: float

    def __post_init__(self):
        for name in ("static_strength", "kinetic_strength", "weakening_slip"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        if self.kinetic_strength > self.static_strength:
            raise ParameterError("kinetic_strength", self.kinetic_strength, f"at most static_strength = "
                                 f"{self.static_strength:g} Pa", also=("static_strength",))

    def strength(self, slip: np.ndarray, sliding: np.ndarray) -> np.ndarray:
        fall = np.minimum(np.abs(slip) / self.weakening_slip, 1.0)
        return self.static_strength - (self.static_strength - self.kinetic_strength) * fall


def law_parameters(law) -> dict:
    """The numbers ``law`` was built with, by their declared names (a law's own ``parameters()`` where it
    has one: rate-and-state's, a regularisation's with its law's), the run's record of its law."""
    own = getattr(law, "parameters", None)
    if callable(own):
        return own()
    return {f.name: getattr(law, f.name) for f in fields(law)} if is_dataclass(law) else {}


def uniform_traction(traction: float) -> Callable:
    """A loading ``tau0(x, t) = traction`` [Pa] applied at ``t = 0``."""
    value = Q.check("traction", traction)
    return lambda x, t: np.full(np.shape(x), value)


def mode_traction(traction: float, mode: int, length: float) -> Callable:
    """A loading ``tau0 = traction cos(2 pi mode x / length)`` [Pa] applied at ``t = 0``."""
    value, mode, length = Q.check("traction", traction), Q.check("mode", mode), Q.check("length", length)
    return lambda x, t: value * np.cos(2.0 * math.pi * mode * x / length)


@dataclass(frozen=True)
class AntiplaneProblem(PeriodicGrid):
    """A half-space (``shear_modulus`` [Pa], ``shear_wave_speed`` [m/s]) whose surface, periodic over
    ``length`` [m] in ``elements``, slides antiplane on a rigid body under the ``law`` and the loading
    ``traction`` (a function of ``x`` [m] and ``t`` [s] giving Pa); ``beta``, ``history_periods``: the
    scheme's (module docstring)."""

    shear_modulus: float
    shear_wave_speed: float
    length: float
    elements: int
    traction: Callable
    law: object = field(default_factory=FreeSurface)
    beta: float = 0.5
    history_periods: float = 4.0

    def __post_init__(self):
        for name in ("shear_modulus", "shear_wave_speed", "length", "elements", "history_periods"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        beta = self.beta
        if isinstance(beta, (int, float)) and not isinstance(beta, bool) and math.isfinite(beta) and beta > 0.6366:
            raise ParameterError("beta", beta, "at most the explicit scheme's stable limit 2/pi = 0.6366 (c_s dt / dx; "
                                 "above it the shortest mode's static stiffness makes the step unstable)")
        object.__setattr__(self, "beta", Q.check("beta", beta))
        if not callable(self.traction):
            raise ParameterError("traction", self.traction, "a function of (x [m], t [s]) giving the shear traction "
                                 "[Pa] (uniform_traction, mode_traction)")
        if not isinstance(self.law, (FreeSurface, Coulomb, SlipWeakening, RateStateFriction)):
            raise ParameterError("law", self.law, "FreeSurface(), Coulomb(...), SlipWeakening(...) or "
                                 "RateStateFriction(...)")


@dataclass(frozen=True, eq=False, repr=False)
class AntiplaneRun(Result):
    """Samples ``t`` [s] of the slip, slip rate and shear stress at each ``x`` [m] (``(samples, N)``), and
    at each sample, summed over the steps before it and the interface (per metre along z, J/m): the
    loading's work on the slip rates ``load_work``, the interface's ``dissipation`` (its traction's) and
    ``travel`` [m^2/m], the slip's path (`stickslip.sbim.energy.energy_book` keeps the books)."""

    problem: AntiplaneProblem
    t: np.ndarray
    slip: np.ndarray
    slip_rate: np.ndarray
    shear_stress: np.ndarray
    kernel_truncation: float
    load_work: np.ndarray | None = None
    dissipation: np.ndarray | None = None
    travel: np.ndarray | None = None

    def to_dict(self) -> dict:
        p = self.problem
        return {"shear_modulus": p.shear_modulus, "shear_wave_speed": p.shear_wave_speed, "length": p.length,
                "elements": p.elements, "beta": p.beta, "dt": p.dt, "history_periods": p.history_periods,
                "kernel_truncation": self.kernel_truncation, "samples": len(self.t), "law": type(p.law).__name__,
                **law_parameters(p.law)}

    def to_xarray(self):
        what = ("an elastic half-space's surface free under an antiplane traction" if isinstance(self.problem.law,
                FreeSurface) else "antiplane sliding of an elastic half-space on a rigid body")
        ds = space_time(self, ("slip", "slip_rate", "shear_stress"), f"{what} (spectral boundary integral method)")
        ds.attrs["law"] = type(self.problem.law).__name__
        return ds


def run_antiplane(problem: AntiplaneProblem, steps: int, every: int = 1, checkpoint=None,
                  progress=None) -> AntiplaneRun:
    """Run ``problem`` from rest for ``steps`` steps, storing every ``every``-th (and the last).

    ``checkpoint``: an object with ``resume() -> state or None``, ``due(step)`` and ``save(state)``
    (`stickslip.sbim.runfile.Checkpoint` with ``run_format=RUN_FORMAT`` keeps it in a netCDF file, `partial_antiplane` its samples): the run starts from the state it
    resumes and hands it the state whenever due and at the end; a resumed run is the uninterrupted one,
    to the last bit. ``progress(done, total)``: called every 64 steps."""
    if not isinstance(problem, AntiplaneProblem):
        raise ParameterError("problem", problem, "an AntiplaneProblem")
    steps, every = Q.check("steps", steps), Q.check("every", every)
    check_hooks(checkpoint, progress, run_format=(RUN_FORMAT, "stickslip.sbim.antiplane.RUN_FORMAT"))
    p = problem
    n, mu, c, dt = p.elements, p.shear_modulus, p.shear_wave_speed, p.dt
    k = p.wavenumbers
    omega = k * c
    count = np.zeros(k.size, dtype=np.int64)
    count[1:] = np.minimum(steps, np.ceil(p.history_periods * 2.0 * math.pi / (omega[1:] * dt))).astype(np.int64)
    if int(count.sum()) > MAX_HISTORY:
        raise ParameterError("steps", steps, f"a history of at most {MAX_HISTORY} numbers ({int(count.sum())} asked: "
                             "fewer history_periods, elements or steps)", also=("history_periods",))
    check_stable("antiplane", p.beta, n, p.history_periods, steps)
    state = checkpoint.resume() if checkpoint is not None else None  # another run's file: refused before any note
    if state is not None:
        check_resumed(state, steps, every, n, "slip")
    if isinstance(p.law, SlipWeakening):
        half, zone = weakening_lengths(p.shear_modulus, p.law.weakening_slip,
                                       p.law.static_strength - p.law.kinetic_strength)
        for note in resolution_notes(half, zone, p.dx, p.length, "mu"):
            log.warning("%s", note)
    history = History(ragged_step_weights(omega, dt, count), count, steps)
    x = p.x
    slip = np.zeros(n)
    sliding = np.zeros(n, bool)
    law = p.law
    rsf = isinstance(law, RateStateFriction)
    psi, log_v = (law.initial_psi(n), np.full(n, math.log(law.slip_rate))) if rsf else (np.zeros(0), np.zeros(0))
    out = {name: [] for name in SAMPLES}
    books = np.zeros(3)  # the loading's work, the interface's dissipation, the slip's path, over the steps so far
    start = 0
    if state is not None:
        start, slip, sliding = int(state["step"]), state["slip"].copy(), state["sliding"].astype(bool)
        psi, log_v, books = state["psi"].copy(), state["log_v"].copy(), state["books"].copy()
        history.buffer[:] = state["h"]
        out = {name: list(state["out_" + name]) for name in SAMPLES}
    for step in range(start, steps + 1):
        t = step * dt
        memory = history.memory(step)
        f = np.fft.irfft(mu * k * (memory - np.fft.rfft(slip)), n)
        try:
            load = np.broadcast_to(np.asarray(p.traction(x, t), dtype=float), x.shape)
        except (TypeError, ValueError) as err:
            raise ParameterError("traction", "a loading", f"a function of (x, t) giving the shear traction [Pa] at the "
                                 f"{n} nodes ({err})") from None
        drive = load + f
        if not np.all(np.isfinite(drive)):
            raise ParameterError("traction", "a loading", f"finite tractions (not finite at t = {t:g} s)")
        if rsf:  # every node slides: its rate balances the strength, drive - (mu / c) V = sigma mu(V, psi)
            try:
                log_v = slip_rates(law.law, law.normal_stress, mu / c, drive, psi, log_v)
            except NoSolutionError as err:
                raise NoSolutionError(f"at t = {t:.6g} s: {err}") from None
            rate = np.exp(log_v)
        else:
            held = np.abs(drive) <= law.strength(slip, sliding)  # a stuck node holds up to its static strength
            excess = np.abs(drive) - law.strength(slip, np.ones(n, bool))  # a moving one meets its sliding strength
            sliding = ~held & (excess > 0.0)
            rate = np.where(sliding, (c / mu) * np.sign(drive) * excess, 0.0)
        stress = drive - (mu / c) * rate
        if step % every == 0 or step == steps:
            for name, value in zip(SAMPLES, (t, slip.copy(), rate, stress, books.copy())):
                out[name].append(value)
        if step == steps:
            break
        books += dt * p.dx * np.array([load @ rate, stress @ rate, np.abs(rate).sum()])
        slip = slip + dt * rate
        if rsf:
            psi = advance_state(law.law, psi, log_v, dt)
        history.push(step, np.fft.rfft(rate))
        if progress is not None and step % 64 == 0:
            progress(step, steps)
        if checkpoint is not None and checkpoint.due(step + 1):
            checkpoint.save(_state(step + 1, slip, sliding, psi, log_v, books, history, out))
    if checkpoint is not None and start <= steps:
        checkpoint.save(_state(steps + 1, slip, sliding, psi, log_v, books, history, out))
    return partial_antiplane(p, _samples(out, n))


#: The samples a run keeps (and its checkpoint with them).
SAMPLES = ("t", "slip", "slip_rate", "shear_stress", "books")
#: The format of an antiplane run's file (`stickslip.sbim.runfile.Checkpoint`'s ``run_format``).
RUN_FORMAT = "stickslip-sbim-antiplane-1"


def _samples(out: dict, n: int) -> dict:
    """The samples kept so far (`SAMPLES`, each a list) as the arrays ``out_<name>`` of a state."""
    shapes = {"t": (-1,), "books": (-1, 3)}
    return {"out_" + name: np.array(v, dtype=float).reshape(shapes.get(name, (-1, n))) for name, v in out.items()}


def _state(step, slip, sliding, psi, log_v, books, history, out) -> dict:
    """A run's whole state before ``step`` (``steps + 1``: done), for its checkpoint (written at once: the
    history's buffer itself, not a copy)."""
    return {"step": np.int64(step), "slip": slip, "sliding": sliding.astype(np.int8), "psi": psi, "log_v": log_v,
            "books": books, "h": history.buffer, **_samples(out, slip.size)}


def partial_antiplane(problem: AntiplaneProblem, state: dict) -> AntiplaneRun:
    """The samples of a checkpoint's ``state`` as a run (`stickslip.sbim.runfile.Checkpoint`'s
    ``fields``: ``lambda state: partial_antiplane(problem, state).to_xarray()``)."""
    return AntiplaneRun(problem, state["out_t"], state["out_slip"], state["out_slip_rate"], state["out_shear_stress"],
                        truncated_part(problem.history_periods), *np.asarray(state["out_books"]).reshape(-1, 3).T)

"""An elastic half-space sliding in its plane on a rigid body (the paper's model 3), with unilateral
contact and friction, or its surface free under applied tractions, in time: the spectral boundary
integral method, modes I and II.

The interface ``0 <= x < L`` is periodic, cut into ``N`` elements; the half-space lies above it
(``y > 0``), the rigid body below, at rest. The surface's displacements are the slip ``U_x`` on the
rigid body and the opening ``U_y`` (``>= 0`` in contact problems). Its tractions are the loading
``(tau0, sigma0)(x, t)`` (the stresses with the surface held, negative ``sigma0`` compressive) plus the
half-space's response (`stickslip.sbim.inplane_kernels`)::

    sigma_xy = G_x - (mu / c_s) V_x,     sigma_yy = G_y - eta (mu / c_s) V_y,

``G`` the loading and the static, coupling and memory terms computed mode by mode by the FFT from the
displacements and the rates before the step (explicit, as `stickslip.sbim.antiplane`).

**Laws** (`stickslip.sbim.interface`): `FreeSurface` (both tractions vanish); unilateral contact
with the rigid body and `CoulombFriction` or `SlipWeakeningFriction`, their strength the coefficient
times the contact pressure, or the pressure relaxed over a slip (`PrakashClifton`); rate-and-state
friction (`stickslip.sbim.RateStateFriction`: every node slides, the contact held closed, its strength the
contact pressure times ``mu(V, psi)``, or the pressure Prakash and Clifton's regularisation relaxes, which
rate-and-state between two materials needs; a node that would open stops the run). Sliding at a
coefficient above 1 without that regularisation is ill-posed (`stickslip.sbim.flutter`): such a run
goes on, says so on the ``stickslip.sbim`` log and keeps the statement in its result
(``ill_posed``, the dataset's ``well_posedness``).

**Scheme.** First order (the rates held over a step, `stickslip.sbim.antiplane`); ``dt = beta dx /
c_s``. Each mode keeps ``history_periods`` of its shear
periods of rates, their weights faded over that window (`stickslip.sbim.inplane_kernels.hann_taper`:
a kernel cut short lets the free surface's Rayleigh mode grow); the largest part of a kernel's
integral left out by the cut is in the result. A run in which any mode of the scheme would grow by
more than 1 % over its steps is refused (`stickslip.sbim.stability`).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from ..errors import ParameterError
from ..quantities.sbim import SBIM as Q
from ..results import Result
from .antiplane import MAX_HISTORY, FreeSurface
from .fields import PeriodicGrid, check_hooks, check_resumed, space_time
from .flutter import FLUTTER_ONSET, bimaterial_ill_posedness, ill_posedness
from .initial import InitialState
from .ratestate import RateStateFriction, advance_state, contact_step
from .interface import (LAWS, CoulombFriction, PrakashClifton, SlipWeakeningFriction, interface_step, law_parameters,
                        relaxed_pressure, slip_weakening_lengths)
from .scales import resolution_notes
from .stability import check_stable
from .surface import MAX_POISSON, Solid, Surface, history_windows, interface_damping
from .inplane_kernels import inplane_truncation, wave_speed_ratio

#: Most dimensionless times in a run's kernel table (`stickslip.sbim.inplane_kernels.kernel_table`).
MAX_TABLE = 1 << 24
#: Most shear periods of history in-plane.
MAX_PERIODS = 64.0

log = logging.getLogger("stickslip.sbim")

__all__ = ["InplaneProblem", "InplaneRun", "run_inplane", "partial_run", "uniform_load", "mode_load", "patch_load",
           "RUN_FORMAT"]


#: The format of an in-plane run's file (`stickslip.sbim.runfile.Checkpoint`'s ``run_format``).
RUN_FORMAT = "stickslip-sbim-inplane-3"  # 2: the energy books in the state; 3: the lower surface's samples


def uniform_load(traction: float, normal_traction: float) -> Callable:
    """Shear ``traction`` and ``normal_traction`` [Pa] (negative: compression), uniform, from ``t = 0``."""
    tau, sigma = Q.check("traction", traction), Q.check("normal_traction", normal_traction)
    return lambda x, t: (np.full(np.shape(x), tau), np.full(np.shape(x), sigma))


def mode_load(traction: float, normal_traction: float, mode: int, length: float, load_speed: float = 0.0) -> Callable:
    """``(traction, normal_traction) cos(2 pi mode (x - load_speed t) / length)`` [Pa] from ``t = 0`` (a
    moving load with ``load_speed`` [m/s])."""
    tau, sigma = Q.check("traction", traction), Q.check("normal_traction", normal_traction)
    mode, length = Q.check("mode", mode), Q.check("length", length)
    speed = Q.check("load_speed", load_speed)

    def load(x, t):
        shape = np.cos(2.0 * math.pi * mode * (x - speed * t) / length)
        return tau * shape, sigma * shape

    return load


def patch_load(traction: float, normal_traction: float, patch_traction: float, patch_width: float,
               patch_centre: float, load_speed: float = 0.0) -> Callable:
    """Uniform shear ``traction`` and ``normal_traction`` [Pa], with ``patch_traction`` more shear on
    ``|x - patch_centre - load_speed t| < patch_width / 2`` [m] (periodic; ``load_speed`` [m/s]: the patch
    moving), from ``t = 0``."""
    tau, sigma = Q.check("traction", traction), Q.check("normal_traction", normal_traction)
    extra = Q.check("patch_traction", patch_traction)
    width, centre = Q.check("patch_width", patch_width), Q.check("patch_centre", patch_centre)
    speed = Q.check("load_speed", load_speed)

    def load(x, t):
        period = float(x[-1] + x[1] - x[0]) if np.size(x) > 1 else 1.0
        d = np.abs((x - centre - speed * t + period / 2) % period - period / 2)
        return np.where(d < width / 2, tau + extra, tau), np.full(np.shape(x), sigma)

    return load


@dataclass(frozen=True)
class InplaneProblem(PeriodicGrid):
    """A half-space (``shear_modulus`` [Pa], ``shear_wave_speed`` [m/s], ``poisson``) whose surface,
    periodic over ``length`` [m] in ``elements``, slides in its plane on a rigid body under the ``law``
    and the ``load`` (a function of ``x`` [m] and ``t`` [s] giving the shear and normal tractions [Pa]:
    `uniform_load`, `mode_load`); ``beta``, ``history_periods``: the scheme's (module docstring);
    ``initial``: the interface at ``t = 0`` and its past (`stickslip.sbim.initial.InitialState`; by
    default at rest, nothing moved before); ``lower``: the half-space below the interface
    (`stickslip.sbim.surface.Solid`; by default a rigid body). With two half-spaces the slip and opening
    are the upper surface's displacement less the lower's and ``dt = beta dx / c_s`` of the faster."""

    shear_modulus: float
    shear_wave_speed: float
    poisson: float
    length: float
    elements: int
    load: Callable
    law: object = field(default_factory=FreeSurface)
    beta: float = 0.3
    history_periods: float = 16.0
    initial: InitialState | None = None
    lower: Solid | None = None

    def __post_init__(self):
        for name in ("shear_modulus", "shear_wave_speed", "poisson", "length", "elements", "history_periods"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        beta = self.beta
        object.__setattr__(self, "beta", Q.check("beta", beta))
        if self.poisson > MAX_POISSON:
            raise ParameterError("poisson", self.poisson, f"at most {MAX_POISSON} in-plane (the kernels' quadrature "
                                 "grows with c_p / c_s)")
        if self.history_periods > MAX_PERIODS:
            raise ParameterError("history_periods", self.history_periods, f"at most {MAX_PERIODS:g} in-plane (the "
                                 "kernels' quadrature grows with the square of the history; their tails beyond are "
                                 "below 1e-4 of their start)")
        if not callable(self.load):
            raise ParameterError("load", self.load, "a function of (x [m], t [s]) giving the shear and normal "
                                 "tractions [Pa] (uniform_load, mode_load)")
        if not isinstance(self.law, LAWS + (RateStateFriction,)):
            raise ParameterError("law", self.law, "FreeSurface(), CoulombFriction(...), SlipWeakeningFriction(...), "
                                 "PrakashClifton(...) or RateStateFriction(...)")
        if self.rate_state is not None:
            self._check_rate_state()
        if self.lower is not None and not isinstance(self.lower, Solid):
            raise ParameterError("lower", self.lower, "None (a rigid body) or a Solid(shear_modulus, "
                                 "shear_wave_speed, poisson)")
        if self.initial is not None:
            if self.lower is not None:
                raise ParameterError("initial", "an InitialState", "None with a lower half-space (a state with a "
                                     "past is given for the upper surface on a rigid body)", also=("lower",))
            if not isinstance(self.initial, InitialState):
                raise ParameterError("initial", self.initial, "None (at rest) or an InitialState")
            if self.initial.slip.size != self.elements:
                raise ParameterError("initial", f"{self.initial.slip.size} nodes", f"one per element "
                                     f"({self.elements})", also=("elements",))
            if not isinstance(self.law, FreeSurface) and np.any(self.initial.opening < 0.0):
                raise ParameterError("opening", float(self.initial.opening.min()), ">= 0 on a rigid body (a gap, "
                                     "or closed)")

    @property
    def rate_state(self) -> RateStateFriction | None:
        """The run's rate-and-state friction (bare or regularised by `PrakashClifton`), or None."""
        law = self.law.friction if isinstance(self.law, PrakashClifton) else self.law
        return law if isinstance(law, RateStateFriction) else None

    def _check_rate_state(self):
        """Rate-and-state in-plane: from steady sliding, its ``normal_stress`` the load's at ``t = 0``; between
        two materials regularised (Prakash-Clifton)."""
        if self.initial is not None:
            raise ParameterError("law", "RateStateFriction(...)", "a law of a run from steady sliding (not from an "
                                 "initial state)", also=("initial",))
        if self.lower is not None and not isinstance(self.law, PrakashClifton):
            raise ParameterError("law", "RateStateFriction(...)", "PrakashClifton(RateStateFriction(...), "
                                 "relaxation_slip, relaxation_speed) between two materials (a strength following "
                                 "the pressure at once is ill-posed there: Rice, Lapusta and Ranjith 2001)",
                                 also=("lower",))
        pressure = -_loaded(self.load, self.x, 0.0)[1]
        if not np.allclose(pressure, self.rate_state.normal_stress, rtol=1e-9, atol=0.0):
            raise ParameterError("normal_stress", self.rate_state.normal_stress, f"the load's compression at t = 0 "
                                 f"({float(pressure.min()):.6g} to {float(pressure.max()):.6g} Pa, uniform): in-plane "
                                 "the strength follows the contact pressure", also=("load",))

    @property
    def eta(self) -> float:
        """``c_p / c_s``."""
        return wave_speed_ratio(self.poisson)

    @property
    def upper(self) -> Solid:
        """The half-space above the interface."""
        return Solid(self.shear_modulus, self.shear_wave_speed, self.poisson)

    @property
    def dt(self) -> float:
        fastest = max(self.shear_wave_speed, 0.0 if self.lower is None else self.lower.shear_wave_speed)
        return self.beta * self.dx / fastest


@dataclass(frozen=True, eq=False, repr=False)
class InplaneRun(Result):
    """Samples ``t`` [s] of the slip, opening, their rates and the tractions at each ``x`` (``(samples, N)``),
    and the books up to each (`BOOKS`, per metre along z; `stickslip.sbim.energy.energy_book`); between two
    materials the lower surface's displacement too (`LOWER`; None on a rigid body)."""

    problem: InplaneProblem
    t: np.ndarray
    slip: np.ndarray
    opening: np.ndarray
    slip_rate: np.ndarray
    opening_rate: np.ndarray
    shear_stress: np.ndarray
    normal_traction: np.ndarray
    kernel_truncation: float
    ill_posed: str = ""
    load_work: np.ndarray | None = None
    dissipation: np.ndarray | None = None
    friction_work: np.ndarray | None = None
    contact_work: np.ndarray | None = None
    lower_displacement_x: np.ndarray | None = None
    lower_displacement_y: np.ndarray | None = None

    FIELDS = ("slip", "opening", "slip_rate", "opening_rate", "shear_stress", "normal_traction")
    #: The books a run keeps at each sample [J/m] (`stickslip.sbim.energy.energy_book`): the loading's work on
    #: the slip and opening rates, the interface traction's, the friction's (the kinetic strength's on the slip
    #: rate; without a kinetic coefficient, rate-and-state or a free surface, the shear traction's) and the
    #: normal traction's on the opening rate (a gap closed within a step).
    BOOKS = ("load_work", "dissipation", "friction_work", "contact_work")
    #: The lower half-space's surface displacement at each sample (the upper's is it plus the slip and opening).
    LOWER = ("lower_displacement_x", "lower_displacement_y")

    def to_dict(self) -> dict:
        p = self.problem
        return {"shear_modulus": p.shear_modulus, "shear_wave_speed": p.shear_wave_speed, "poisson": p.poisson,
                "length": p.length, "elements": p.elements, "beta": p.beta, "dt": p.dt,
                "history_periods": p.history_periods, "kernel_truncation": self.kernel_truncation,
                "samples": len(self.t), "law": type(p.law).__name__, "well_posed": not self.ill_posed,
                "ill_posedness": self.ill_posed, **law_parameters(p.law),
                **({} if p.lower is None else {"lower_shear_modulus": p.lower.shear_modulus,
                                               "lower_shear_wave_speed": p.lower.shear_wave_speed,
                                               "lower_poisson": p.lower.poisson})}

    def to_xarray(self):
        on = "a rigid body" if self.problem.lower is None else "another elastic half-space"
        names = self.FIELDS + (() if self.lower_displacement_x is None else self.LOWER)
        ds = space_time(self, names, f"in-plane sliding of an elastic half-space on {on} (spectral boundary "
                        "integral method)")
        ds.attrs["well_posedness"] = self.ill_posed or "well posed"
        ds.attrs["law"] = type(self.problem.law).__name__
        return ds


def _loaded(load, x, t):
    """The shear and normal tractions of ``load`` at ``t``, each one per node, or refused."""
    try:
        tau0, sigma0 = load(x, t)
        tau0 = np.broadcast_to(np.asarray(tau0, dtype=float), x.shape)
        sigma0 = np.broadcast_to(np.asarray(sigma0, dtype=float), x.shape)
    except (TypeError, ValueError) as err:
        raise ParameterError("load", "a loading", f"a function of (x, t) giving two arrays, the shear and normal "
                             f"tractions [Pa] at the {x.size} nodes ({err})") from None
    return tau0, sigma0


def run_inplane(problem: InplaneProblem, steps: int, every: int = 1, checkpoint=None, progress=None) -> InplaneRun:
    """Run ``problem`` from rest (or its ``initial`` state) for ``steps`` steps, storing every ``every``-th
    (and the last).

    ``checkpoint``: an object with ``resume() -> state or None``, ``due(step) -> bool`` and
    ``save(state)`` (`stickslip.sbim.runfile.Checkpoint` keeps it in a file): the run starts from the
    state it resumes, and hands it the state (a dict of arrays) whenever it is due. A resumed run
    is the uninterrupted one, to the last bit. ``progress(done, total)``: called every 64 steps."""
    if not isinstance(problem, InplaneProblem):
        raise ParameterError("problem", problem, "an InplaneProblem")
    steps, every = Q.check("steps", steps), Q.check("every", every)
    check_hooks(checkpoint, progress, run_format=(RUN_FORMAT, "stickslip.sbim.runfile.RUN_FORMAT"))
    p = problem
    n, dt, k = p.elements, p.dt, p.wavenumbers
    solids = (p.upper,) if p.lower is None else (p.upper, p.lower)
    windows = [history_windows(solid, k, dt, p.history_periods) for solid in solids]
    for solid in solids:
        beta = solid.shear_wave_speed * dt / p.dx  # the user's beta for the faster solid
        asked = p.history_periods * n / beta  # about the kernel table's length
        if asked > MAX_TABLE:
            raise ParameterError("beta", p.beta, f"a kernel table of at most {MAX_TABLE} times (history_periods x "
                                 f"elements / beta = {asked:.3g}: a larger beta, fewer history_periods or elements)",
                                 also=("history_periods", "elements"))
    pre = 0 if p.initial is None else int(windows[0].max())  # steps of the past before t = 0
    kept = sum(int(np.minimum(steps + pre, w).sum()) for w in windows)
    if kept > MAX_HISTORY // 2:
        raise ParameterError("steps", steps, f"a history of at most {MAX_HISTORY // 2} numbers per component "
                             f"({kept} asked: fewer history_periods, elements or steps)", also=("history_periods",))
    for solid in solids:
        _stable(p, solid, steps)
    ill = _ill_posedness(p)
    if ill:
        log.warning("%s", ill)
    for note in _resolution(p):
        log.warning("%s", note)
    top = Surface(solids[0], 1, k, dt, p.history_periods, steps, pre)
    bottom = None if p.lower is None else Surface(p.lower, -1, k, dt, p.history_periods, steps, pre)
    rad = interface_damping(p.upper, p.lower)
    x = p.x
    Ux, Uy = np.zeros(n), np.zeros(n)  # the slip and the opening
    Lx, Ly = np.zeros(n), np.zeros(n)  # the lower surface's displacement (none on a rigid body)
    sliding = np.zeros(n, bool)
    pressure = None
    rate = p.rate_state
    rsf, regularised = rate is not None, isinstance(p.law, PrakashClifton)
    psi = rate.initial_psi(n) if rsf else np.zeros(0)
    log_v = np.full(n, math.log(rate.slip_rate)) if rsf else np.zeros(0)
    out = {name: [] for name in ("t",) + InplaneRun.FIELDS}
    books, out_books = np.zeros(4), []  # the loading's work, the interface's, the kinetic strength's, the normal's
    out_lower = []  # the lower surface's displacement at the samples (two materials)
    kinetic = _kinetic(p.law)
    start = 0
    state = checkpoint.resume() if checkpoint is not None else None
    if state is not None:
        check_resumed(state, steps, every, n, "Ux")
        start, Ux, Uy = int(state["step"]), state["Ux"].copy(), state["Uy"].copy()
        sliding = state["sliding"].astype(bool)
        pressure = state["pressure"].copy() if state["pressure"].size else None
        top.hx.buffer[:], top.hy.buffer[:] = state["hx"], state["hy"]
        if rsf:
            psi, log_v = state["psi"].copy(), state["log_v"].copy()
        if bottom is not None:
            Lx, Ly = state["Lx"].copy(), state["Ly"].copy()
            bottom.hx.buffer[:], bottom.hy.buffer[:] = state["lx"], state["ly"]
        out = {name: list(state["out_" + name]) for name in out}
        books, out_books = state["books"].copy(), list(state["out_books"])
        out_lower = list(state.get("out_lower", ()))
    elif p.initial is not None:
        Ux, Uy = p.initial.slip.copy(), p.initial.opening.copy()
        sliding = p.initial.fill(dt, pre, top.hx, top.hy)
    for step in range(start, steps + 1):
        t = step * dt
        h = step + pre  # the histories' step
        tau0, sigma0 = _loaded(p.load, x, t)
        fx, fy = top.tractions(h, Ux + Lx, Uy + Ly)
        Gx, Gy = tau0 + np.fft.irfft(fx, n), sigma0 + np.fft.irfft(fy, n)
        if bottom is not None:
            (zx, zy), (wx, wy) = top.impedance, bottom.impedance
            bx, by = bottom.tractions(h, Lx, Ly)
            Bx, By = tau0 + np.fft.irfft(bx, n), sigma0 + np.fft.irfft(by, n)
            Gx, Gy = (wx * Gx + zx * Bx) / (zx + wx), (wy * Gy + zy * By) / (zy + wy)
        if not (np.all(np.isfinite(Gx)) and np.all(np.isfinite(Gy))):
            raise ParameterError("load", "a loading", f"finite tractions (not finite at t = {t:g} s)")
        seen = pressure  # the pressure the strength sees this step (Prakash-Clifton's, before it relaxes)
        if rsf:
            if regularised and pressure is None:
                pressure = -Gy  # the interface pressed before the run
            Vx, Vy, sxy, syy, log_v = contact_step(rate, Gx, Gy, psi, log_v, rad[0], t, pressure)
            if regularised:
                pressure = relaxed_pressure(p.law, pressure, -Gy, Vx, dt)
        else:
            Vx, Vy, sxy, syy, sliding, pressure = interface_step(p.law, Gx, Gy, Ux, Uy, sliding, pressure, dt, rad)
        if step % every == 0 or step == steps:
            for name, value in zip(out, (t, Ux.copy(), Uy.copy(), Vx, Vy, sxy, syy)):
                out[name].append(value)
            out_books.append(books.copy())
            if bottom is not None:
                out_lower.append(np.stack([Lx, Ly]))
        if step == steps:
            break
        if seen is None or not isinstance(p.law, PrakashClifton):
            seen = np.maximum(-syy, 0.0)
        books += dt * p.dx * np.array([tau0 @ Vx + sigma0 @ Vy, sxy @ Vx + syy @ Vy,
                                       sxy @ Vx if kinetic is None else kinetic * (seen @ np.abs(Vx)), syy @ Vy])
        if bottom is not None:  # each side's rate from the traction the law set
            vx, vy = (sxy - Bx) / wx, (syy - By) / wy
            Lx, Ly = Lx + dt * vx, Ly + dt * vy
            bottom.push(h, vx, vy)
            top.push(h, vx + Vx, vy + Vy)
        else:
            top.push(h, Vx, Vy)
        Ux, Uy = Ux + dt * Vx, Uy + dt * Vy
        if rsf:
            psi = advance_state(rate.law, psi, log_v, dt)
        if not isinstance(p.law, FreeSurface):
            Uy = np.maximum(Uy, 0.0)  # closed to round-off
        if progress is not None and step % 64 == 0:
            progress(step, steps)
        if checkpoint is not None and checkpoint.due(step + 1):
            checkpoint.save(_state(step + 1, Ux, Uy, Lx, Ly, sliding, pressure, top, bottom, out, psi, log_v,
                                   books, out_books, out_lower))
    if checkpoint is not None and start <= steps:
        checkpoint.save(_state(steps + 1, Ux, Uy, Lx, Ly, sliding, pressure, top, bottom, out, psi, log_v, books,
                               out_books, out_lower))
    return InplaneRun(p, *(np.array(out[name]) for name in out), _truncation(p), ill,
                      *np.array(out_books).reshape(-1, 4).T, *_lower_samples(out_lower, bottom is not None, n))


def _kinetic(law) -> float | None:
    """The kinetic friction coefficient of a Coulomb or slip-weakening law (regularised or not), else None."""
    law = law.friction if isinstance(law, PrakashClifton) else law
    return law.kinetic_friction if isinstance(law, (CoulombFriction, SlipWeakeningFriction)) else None


def _truncation(p: InplaneProblem) -> float:
    """The largest part of a kernel's integral the history leaves out, of either solid."""
    return max(inplane_truncation(s.poisson, p.history_periods) for s in (p.upper, p.lower) if s is not None)


def _stable(p: InplaneProblem, solid: Solid, steps: int) -> None:
    """Refuse a run whose scheme would grow on ``solid``'s surface (`stickslip.sbim.stability`)."""
    beta = solid.shear_wave_speed * p.dt / p.dx
    try:
        check_stable("inplane", beta, p.elements, p.history_periods, steps, solid.poisson)
    except ParameterError as err:
        if beta == p.beta:
            raise
        why = err.allowed.removeprefix("a stable explicit scheme: ").replace("poisson", "lower poisson")
        raise ParameterError("beta", p.beta, f"a stable explicit scheme on the lower half-space too (its own "
                             f"c_s dt / dx = {beta:.3g}; {why})", also=("history_periods", "steps")) from None


def _ill_posedness(p: InplaneProblem) -> str:
    """Why the run's law is ill-posed on its pair of bodies, or ``""`` (rate-and-state on a rigid body: its
    Coulomb part, the steady friction at the start, below the flutter onset, its direct effect damping only;
    above it, said on the log as not assessed)."""
    if isinstance(p.law, RateStateFriction):
        f = float(p.law.law.steady_friction(p.law.slip_rate))
        if f > FLUTTER_ONSET:
            log.warning("well-posedness not assessed: rate-and-state sliding at a steady friction %.3g above %g",
                        f, FLUTTER_ONSET)
        return ""
    if isinstance(p.law, (FreeSurface, PrakashClifton)):
        return ""
    if p.lower is None:
        return ill_posedness(p.law, p.poisson)
    return bimaterial_ill_posedness(p.law, p.upper, p.lower)


def _resolution(p: InplaneProblem) -> list[str]:
    """What a slip-weakening run's grid and period cannot show (its pressure the load's at ``t = 0``)."""
    law = p.law.friction if isinstance(p.law, PrakashClifton) else p.law
    pressure = -float(np.mean(_loaded(p.load, p.x, 0.0)[1]))
    if not isinstance(law, SlipWeakeningFriction) or not 1e-3 <= pressure <= 1e10:
        return []
    half, zone = slip_weakening_lengths(law, p.shear_modulus, p.poisson, pressure)
    return resolution_notes(half, zone, p.dx, p.length, "mu / (1 - nu)")


def _lower_samples(out_lower, lower: bool, n: int) -> tuple:
    """The lower surface's displacement along x and y at the samples (``(None, None)`` on a rigid body)."""
    if not lower:
        return None, None
    both = np.asarray(out_lower, dtype=float).reshape(-1, 2, n)
    return both[:, 0], both[:, 1]


def _state(step, Ux, Uy, Lx, Ly, sliding, pressure, top, bottom, out, psi, log_v, books, out_books,
           out_lower) -> dict:
    """A run's whole state before ``step`` (``steps + 1``: done), for its checkpoint (a lower half-space's
    displacement and histories only with one)."""
    n = Ux.size
    samples = {"out_" + name: np.array(v, dtype=float).reshape((len(v),) if name == "t" else (len(v), n))
               for name, v in out.items()}
    lower = {} if bottom is None else {"Lx": Lx, "Ly": Ly, "lx": bottom.hx.buffer, "ly": bottom.hy.buffer,
                                       "out_lower": np.asarray(out_lower, dtype=float).reshape(-1, 2, n)}
    if psi.size:  # rate-and-state: each node's state and slip rate
        lower.update(psi=psi, log_v=log_v)
    return {"step": np.int64(step), "Ux": Ux, "Uy": Uy, "sliding": sliding.astype(np.int8),
            "pressure": np.zeros(0) if pressure is None else pressure, "hx": top.hx.buffer, "hy": top.hy.buffer,
            "books": books, "out_books": np.array(out_books, dtype=float).reshape(-1, 4), **lower, **samples}


def partial_run(problem: InplaneProblem, state: dict, ill_posed: str = "") -> InplaneRun:
    """The samples of a checkpoint's ``state`` as a run (`stickslip.sbim.runfile`)."""
    n = problem.elements
    return InplaneRun(problem, *(state["out_" + name] for name in ("t",) + InplaneRun.FIELDS),
                      _truncation(problem), ill_posed, *np.asarray(state["out_books"]).reshape(-1, 4).T,
                      *_lower_samples(state.get("out_lower", ()), problem.lower is not None, n))

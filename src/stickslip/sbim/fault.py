"""Earthquake cycles on a vertical strike-slip fault in a half-space, quasi-dynamic (a problem of the kind
of the SCEC SEAS benchmark BP1-QD): rate-and-state friction varying with depth down to ``depth``,
below it the fault creeping at the plate rate.

**Geometry.** Antiplane slip ``s(z, t)`` on the fault ``0 <= z`` (depth) between two identical
half-spaces, the ground surface ``z = 0`` free: the slip is even about it (its image), and the domain
is closed by a second mirror at ``z = H`` (``domain_depth``), so the fault is one of a periodic row of
period ``2 H`` and its modes are a cosine transform's, ``cos(k_m z)``, ``k_m = pi m / H``. A mode's
static stiffness is ``mu k_m / 2`` (each side moves ``s / 2``), the radiation damping ``mu / (2 c_s)``.

**Loading.** Below ``depth`` the fault slips at the plate rate ``V_p``: with the slip deficit ``phi = s
- V_p t`` (zero there), the stress on the fault is ``tau_0 - K[phi] - eta V`` (a uniform slip stresses
nothing), and each rate-and-state node's ``V`` balances its strength ``sigma mu(V, psi)`` (Newton on
``ln V``, `stickslip.sbim.ratestate.slip_rates`). ``tau_0`` holds steady sliding at ``initial_rate``
with ``a`` at its largest; each node's state is the one that slides it at ``initial_rate`` under
``tau_0`` (as BP1 sets it).

**Steps.** Scipy's RK45 one step at a time (its error control follows slow creep and fast slip
alike). The run keeps the largest slip rate at every step, the slip profile every
``interseismic_interval`` while the fault is locked and every ``coseismic_interval`` while it slips
faster than ``event_rate``, and each event's start, end and peak slip rate (`FaultRun`).
"""

from __future__ import annotations

import functools
import logging
import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..errors import NoSolutionError, ParameterError
from ..quantities import RSF
from ..quantities.sbim import SBIM as Q
from ..results import Result
from ..rsf import RateState
from .fields import check_hooks
from .ratestate import slip_rates

__all__ = ["StrikeSlipFault", "FaultRun", "run_fault", "partial_fault", "fault_fields", "YEAR", "RUN_FORMAT"]

log = logging.getLogger("stickslip.sbim")

#: One year [s] (365 days).
YEAR = 365.0 * 86400.0


@dataclass(frozen=True)
class _NodeLaw(RateState):
    """A regularised `RateState` whose ``a`` is one number per node (the fault's profile)."""

    def __post_init__(self):
        a = RSF["a"].check_array(self.a)  # every node's a in the law's declared range
        object.__setattr__(self, "a", float(a.flat[0]))  # the scalar checks, then the profile
        super().__post_init__()
        object.__setattr__(self, "a", a)


@dataclass(frozen=True)
class StrikeSlipFault:
    """A vertical strike-slip fault (module docstring): a half-space of ``shear_modulus`` [Pa] and
    ``shear_wave_speed`` [m/s]; the regularised rate-and-state ``law`` (one state variable; its ``a``
    replaced by ``a_profile(z)``, a function of depth [m]) under ``normal_stress`` [Pa] down to
    ``depth`` [m] in ``elements``, creeping at ``plate_rate`` [m/s] below, all sliding at
    ``initial_rate`` [m/s] at the start; the domain closed by a mirror at ``domain_depth`` [m]
    (default twice ``depth``)."""

    shear_modulus: float
    shear_wave_speed: float
    depth: float
    elements: int
    law: object
    a_profile: Callable
    normal_stress: float
    plate_rate: float
    initial_rate: float | None = None
    domain_depth: float | None = None

    def __post_init__(self):
        for name in ("shear_modulus", "shear_wave_speed", "elements", "normal_stress", "plate_rate"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        object.__setattr__(self, "depth", Q.check("depth", self.depth))
        if not isinstance(self.law, RateState) or self.law.states != 1 or self.law.evolution == "prz":
            raise ParameterError("law", self.law, "a stickslip.rsf.RateState with one state variable, the aging or "
                                 "the slip law")
        if self.law.b <= 0.0:
            raise ParameterError("b", self.law.b, "above 0 on a fault (its state must evolve: the initial state "
                                 "divides by b)")
        rate = self.plate_rate if self.initial_rate is None else self.initial_rate
        object.__setattr__(self, "initial_rate", Q.check("initial_rate", rate))
        deep = 2.0 * self.depth if self.domain_depth is None else self.domain_depth
        deep = Q.check("domain_depth", deep)
        least = self.depth * (1.0 + 1.0 / self.elements)
        if deep < least:
            raise ParameterError("domain_depth", deep, f"at least depth + a cell ({least:g} m): below the "
                                 "rate-and-state part the fault creeps", also=("depth",))
        object.__setattr__(self, "domain_depth", deep)
        if not callable(self.a_profile):
            raise ParameterError("a_profile", self.a_profile, "a function of depth [m] giving a at each depth")
        try:
            a = np.broadcast_to(np.asarray(self.a_profile(self.z), dtype=float), self.z.shape)
        except (TypeError, ValueError) as err:
            raise ParameterError("a_profile", self.a_profile, f"a function of depth [m] giving a ({err})") from None
        law = self.law
        node_law = _NodeLaw(a.copy(), law.b, law.dc, law.f0, law.v_ref, law.evolution, regularized=True)
        object.__setattr__(self, "_node_law", node_law)
        viscous = self.normal_stress * float(a.min()) / self.plate_rate
        if viscous < self.damping:
            least = self.damping * self.plate_rate / a.min()
            raise ParameterError("normal_stress", self.normal_stress, f"at least {least:.3g} Pa here: at the plate "
                                 f"rate the strength's rate dependence sigma a / V_p = {viscous:.3g} Pa s/m is below "
                                 f"the radiation damping mu / (2 c_s) = {self.damping:.3g}, where the quasi-dynamic "
                                 "equations are stiff (explicit steps of dz / c_s for ever)",
                                 also=("plate_rate", "a_profile"))

    def resolution(self) -> str:
        """What the cells cannot show: empty, or a sentence with the cohesive zone ``(9 pi / 32) mu D_c / (b
        sigma)`` (Day et al., 2005) when a cell is longer than half of it."""
        law = self.law
        if law.b <= 0.0:
            return ""
        zone = 9.0 * math.pi / 32.0 * self.shear_modulus * law.dc / (law.b * self.normal_stress)
        if self.dz <= zone / 2.0:
            return ""
        return (f"unresolved: a cell of {self.dz:.4g} m is longer than half the cohesive zone ({zone:.4g} m): the "
                "ruptures are not resolved (their peak slip rates and recurrence depend on the grid)")

    @property
    def dz(self) -> float:
        return self.depth / self.elements

    @property
    def z(self) -> np.ndarray:
        """The rate-and-state nodes' depths [m] (cell centres)."""
        return (np.arange(self.elements) + 0.5) * self.dz

    @property
    def a(self) -> np.ndarray:
        return self._node_law.a

    @property
    def cells(self) -> int:
        """Cells of the domain down to its mirror (creeping below ``depth``)."""
        return int(round(self.domain_depth / self.dz))

    @property
    def damping(self) -> float:
        return self.shear_modulus / (2.0 * self.shear_wave_speed)

    @functools.cached_property
    def stiffness(self) -> np.ndarray:
        """Each cosine mode's static stiffness ``mu k_m / 2`` [Pa/m] (``k_m = pi m / H``)."""
        return 0.5 * self.shear_modulus * math.pi * np.arange(self.cells) / (self.cells * self.dz)

    def stress(self, deficit: np.ndarray) -> np.ndarray:
        """``-K[phi]`` [Pa] at the rate-and-state nodes from their slip deficit (zero below)."""
        from scipy.fft import dct, idct

        full = np.zeros(self.cells)
        full[:self.elements] = deficit
        return idct(-self.stiffness * dct(full, type=2, norm="ortho"), type=2, norm="ortho")[:self.elements]

    def initial_traction(self) -> float:
        """``tau_0`` [Pa]: steady sliding at ``initial_rate`` with ``a`` at its largest."""
        law, v = self.law, self.initial_rate
        widest = RateState(float(np.max(self.a)), law.b, law.dc, law.f0, law.v_ref, law.evolution, regularized=True)
        return self.normal_stress * widest.steady_friction(v) + self.damping * v

    def initial_psi(self) -> np.ndarray:
        """Each node's ``psi = ln(V_0 theta / D_c)`` sliding at ``initial_rate`` under ``tau_0``."""
        law, v, a = self.law, self.initial_rate, self.a
        strength = (self.initial_traction() - self.damping * v) / (a * self.normal_stress)
        log_sinh = strength + np.log1p(-np.exp(-2.0 * strength)) - math.log(2.0)  # no overflow at large strength
        big_psi = a * (math.log(2 * law.v_ref / v) + log_sinh)
        return (big_psi - law.f0) / law.b


@dataclass(frozen=True, eq=False, repr=False)
class FaultRun(Result):
    """A fault's run: at every step ``t`` [s] its largest slip rate ``max_slip_rate`` [m/s]; the slip
    profiles ``slip`` [m] (``(profiles, elements)``) at ``profile_t`` [s]; each event's ``event_start``,
    ``event_end`` [s] (the largest slip rate above ``event_rate``) and ``event_peak`` [m/s]."""

    problem: StrikeSlipFault
    t: np.ndarray
    max_slip_rate: np.ndarray
    profile_t: np.ndarray
    slip: np.ndarray
    event_start: np.ndarray
    event_end: np.ndarray
    event_peak: np.ndarray
    event_rate: float

    @property
    def recurrence(self) -> np.ndarray:
        """The intervals [s] between successive events' starts."""
        return np.diff(self.event_start)

    def to_dict(self) -> dict:
        p = self.problem
        rec = self.recurrence
        return {"depth": p.depth, "elements": p.elements, "steps": int(self.t.size), "t_end": float(self.t[-1]),
                "events": int(self.event_start.size),
                "recurrence_mean": float(rec.mean()) if rec.size else float("nan"),
                "peak_slip_rate": float(self.event_peak.max() if self.event_peak.size else self.max_slip_rate.max())}

    def to_xarray(self):
        import xarray as xr

        from ..cf import finish

        ds = xr.Dataset({"max_slip_rate": ("step", self.max_slip_rate), "step_t": ("step", self.t),
                         "slip": (("profile_t", "z"), self.slip), "event_start": ("event", self.event_start),
                         "event_end": ("event", self.event_end), "event_peak": ("event", self.event_peak)},
                        coords={"profile_t": self.profile_t, "z": self.problem.z})
        return finish(ds, "earthquake cycles on a strike-slip fault (quasi-dynamic, rate-and-state)", "sbim",
                      params={k: v for k, v in self.to_dict().items() if math.isfinite(v)})


def run_fault(problem: StrikeSlipFault, t_end: float, interseismic_interval: float = 5 * YEAR,
              coseismic_interval: float = 1.0, event_rate: float = 1e-3, rtol: float = 1e-7,
              max_steps: int = 1_000_000, checkpoint=None, progress=None) -> FaultRun:
    """Run ``problem`` for ``t_end`` [s] (module docstring); ``rtol``: RK45's relative tolerance; at most
    ``max_steps`` steps (BP1 on 200-m cells takes about 20 a year, 4 ms each here).

    ``checkpoint``: an object with ``resume() -> state or None``, ``due(step)`` and ``save(state)``
    (`stickslip.sbim.runfile.Checkpoint` with ``run_format=RUN_FORMAT`` keeps it in a netCDF file,
    `fault_fields` its root group): the run starts from the state it resumes (the integrator's step
    and its last stage with it) and hands it the state whenever due and at the end. A resumed run is
    the uninterrupted one, to the last bit. ``progress(t, t_end)``: called every 100 steps."""
    from scipy.integrate import RK45

    if not isinstance(problem, StrikeSlipFault):
        raise ParameterError("problem", problem, "a StrikeSlipFault")
    t_end = Q.check("duration", t_end, "t_end")
    inter = Q.check("interseismic_interval", interseismic_interval)
    co = Q.check("coseismic_interval", coseismic_interval)
    event_rate = Q.check("event_rate", event_rate)
    rtol, max_steps = Q.check("rtol", rtol), Q.check("max_steps", max_steps)
    check_hooks(checkpoint, progress, "progress(t, t_end)", (RUN_FORMAT, "stickslip.sbim.fault.RUN_FORMAT"))
    state = checkpoint.resume() if checkpoint is not None else None  # another run's file: refused before any note
    p, n = problem, problem.elements
    note = p.resolution()
    if note:
        log.warning("%s", note)
    law, sigma, eta, vp = p._node_law, p.normal_stress, p.damping, p.plate_rate
    tau0 = p.initial_traction()
    last = [np.full(n, math.log(p.initial_rate))]

    def log_rates(y):
        return slip_rates(law, sigma, eta, tau0 + p.stress(y[:n]), y[n:], last[0])

    def rhs(t, y):
        try:
            log_v = log_rates(y)
        except NoSolutionError:  # a trial state no slip rate balances: RK45 shortens the step
            return np.full(y.size, np.nan)
        last[0] = log_v
        return np.concatenate([np.exp(log_v) - vp, law.state_rate(log_v, y[None, n:])[0]])

    if state is None:
        solver = RK45(rhs, 0.0, np.concatenate([np.zeros(n), p.initial_psi()]), t_end, rtol=rtol, atol=rtol * 1e-3)
        rec = {"ts": [0.0], "vmax": [p.initial_rate], "prof_t": [0.0], "prof": [np.zeros(n)], "starts": [],
               "ends": [], "peaks": []}
        next_profile, in_event = inter, False
    else:  # the integrator as it was after the state's last step
        solver = RK45(rhs, float(state["t"]), state["y"], t_end, rtol=rtol, atol=rtol * 1e-3)
        solver.f, solver.h_abs, last[0] = state["f"], float(state["h_abs"]), state["last"]
        rec = {name: list(state[name]) for name in RECORDS}
        next_profile, in_event = float(state["next_profile"]), bool(state["in_event"])
        if float(state["t"]) >= t_end:
            solver.status = "finished"
    while solver.status == "running":
        if len(rec["ts"]) > max_steps:
            raise NoSolutionError(f"the fault's run took more than {max_steps} steps by t = {solver.t:.6g} s "
                                  "(max_steps)")
        solver.step()
        if solver.status == "failed" or not np.all(np.isfinite(solver.y)):
            raise NoSolutionError(f"the fault's run stopped at t = {solver.t:.6g} s ({solver.status})")
        t, y = solver.t, solver.y
        v = float(np.exp(last[0].max()))  # RK45's last stage is at the step's end (first same as last)
        rec["ts"].append(t)
        rec["vmax"].append(v)
        fast = v > event_rate
        if fast and not in_event:
            rec["starts"].append(t)
            rec["peaks"].append(v)
        elif fast:
            rec["peaks"][-1] = max(rec["peaks"][-1], v)
        elif in_event:
            rec["ends"].append(t)
        in_event = fast
        if t >= next_profile or solver.status != "running":
            rec["prof_t"].append(t)
            rec["prof"].append(y[:n] + vp * t)
            next_profile = t + (co if fast else inter)
        elif fast and next_profile - t > co:
            next_profile = t + co
        if checkpoint is not None and (solver.status != "running" or checkpoint.due(len(rec["ts"]))):
            checkpoint.save(_state(solver, last[0], rec, next_profile, in_event))
        if progress is not None and len(rec["ts"]) % 100 == 0:
            progress(t, t_end)
    return partial_fault(p, _state(solver, last[0], rec, next_profile, in_event), event_rate)


#: The records a fault's run keeps (and its checkpoint with them).
RECORDS = ("ts", "vmax", "prof_t", "prof", "starts", "ends", "peaks")
#: The format of a fault's run file (`stickslip.sbim.runfile.Checkpoint`'s ``run_format``).
RUN_FORMAT = "stickslip-sbim-fault-1"


def _state(solver, last, rec, next_profile, in_event) -> dict:
    n = last.size
    out = {name: np.array(rec[name], dtype=float) for name in RECORDS}
    out["prof"] = out["prof"].reshape(-1, n)
    return {"step": np.int64(len(rec["ts"]) - 1), "t": np.float64(solver.t), "y": solver.y, "f": solver.f,
            "h_abs": np.float64(solver.h_abs), "last": last, "next_profile": np.float64(next_profile),
            "in_event": np.int8(in_event), **out}


def partial_fault(problem: StrikeSlipFault, state: dict, event_rate: float = 1e-3) -> FaultRun:
    """The records of a fault's run ``state`` (its checkpoint's) as a run; an event still going ends at
    the last step."""
    ends = list(state["ends"])
    if len(ends) < len(state["starts"]):
        ends.append(float(state["ts"][-1]))
    return FaultRun(problem, np.asarray(state["ts"]), np.asarray(state["vmax"]), np.asarray(state["prof_t"]),
                    np.asarray(state["prof"]).reshape(-1, problem.elements), np.asarray(state["starts"]),
                    np.array(ends, dtype=float), np.asarray(state["peaks"]), event_rate)


def fault_fields(problem: StrikeSlipFault, event_rate: float = 1e-3):
    """``fields(state)`` for a fault's `stickslip.sbim.runfile.Checkpoint`: the state's records as the
    run's CF dataset."""
    return lambda state: partial_fault(problem, state, event_rate).to_xarray()

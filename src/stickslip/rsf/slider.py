"""The spring-slider with rate-and-state friction, driven by a load-point velocity history.

A slider on a rate-and-state interface under normal stress ``sigma`` is pulled through a spring
of stiffness ``k`` (per unit area) by a load point moving at ``V_lp(t)``; the shear stress is the
spring's, ``tau' = k (V_lp - V)``, and

    quasi-static (m = 0):  tau = sigma mu(V, theta),
    with inertia:          m V' = tau - sigma mu(V, theta),

so that in the variables ``(ln V, psi, tau)``

    (ln V)' = (k (V_lp - V) / sigma - mu_Psi sum_i b_i psi_i') / mu_lnV     (quasi-static)
    (ln V)' = (tau - sigma mu) / (m V)                                      (inertia)

with ``psi_i'`` the law's evolution. A velocity history is piecewise constant (a velocity step,
slide-hold-slide with a hold at ``V_lp = 0``); each piece is solved by LSODA (scipy's ``odeint``,
switching between Adams and BDF as the equations stiffen) with the equations and their Jacobian
compiled (`stickslip.rsf.kernel`), restarted at every change of ``V_lp``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy

from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..quantities import RSF as Q
from ..results import Result
from .kernel import KERNELS, pack
from .pieces import MAX_CALLS, solve_piece
from .law import RateState

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["SpringSlider", "SliderRun", "slide", "load_history", "MAX_CALLS", "directional", "complex_jacobian"]

@dataclass(frozen=True)
class SpringSlider:
    """A slider of ``mass`` per unit area (0: quasi-static) under ``normal_stress``, pulled through a
    spring of ``stiffness`` per unit area, on an interface with the rate-and-state ``law``."""

    law: RateState
    normal_stress: float
    stiffness: float
    mass: float = 0.0

    def __post_init__(self):
        if not isinstance(self.law, RateState):
            raise ParameterError("law", self.law, "a stickslip.rsf.RateState")
        for name in ("normal_stress", "stiffness", "mass"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))

    def rhs(self, y, v_load: float):
        """``y' `` for ``y = (ln V, psi_1[, psi_2], tau, slip)``; complex ``y`` for complex steps."""
        law, n = self.law, self.law.states
        log_v, psi, tau = y[0], y[1:1 + n], y[1 + n]
        v = np.exp(log_v)
        dpsi = law.state_rate(log_v, psi)
        mu, mu_v, mu_psi = law.friction(log_v, psi)
        if self.mass == 0.0:
            dlog_v = (self.stiffness * (v_load - v) / self.normal_stress - mu_psi * (law.b_values @ dpsi)) / mu_v
        else:
            dlog_v = (tau - self.normal_stress * mu) / (self.mass * v)
        out = np.empty(len(y), dtype=np.result_type(y, float))
        out[0], out[1:1 + n], out[1 + n], out[2 + n] = dlog_v, dpsi, self.stiffness * (v_load - v), v
        return out

    def steady_state(self, v: float) -> np.ndarray:
        """``y`` of steady sliding at slip rate ``v`` (slip 0)."""
        psi = self.law.steady_psi(v)
        mu, _, _ = self.law.friction(math.log(v), psi)
        return np.concatenate([[math.log(v)], psi, [self.normal_stress * float(np.real(mu)), 0.0]])


@dataclass(frozen=True, eq=False, repr=False)
class SliderRun(Result):
    """A slider's history: samples at times ``t``."""

    t: np.ndarray
    slip_rate: np.ndarray
    #: The state variables theta_i (s), one column each.
    theta: np.ndarray
    friction: np.ndarray
    shear_stress: np.ndarray
    slip: np.ndarray
    load_point: np.ndarray
    steps: int
    #: ``(ln V, psi, tau, slip)`` at the end, where ``slide(..., start=run)`` goes on from.
    end_state: np.ndarray
    MODEL = "rsf"

    def to_dict(self) -> dict:
        return {"t_end": float(self.t[-1]), "slip_rate_end": float(self.slip_rate[-1]),
                "friction_end": float(self.friction[-1]), "slip_rate_max": float(self.slip_rate.max()),
                "friction_max": float(self.friction.max()), "friction_min": float(self.friction.min()),
                "slip_end": float(self.slip[-1]), "steps": self.steps}

    def to_xarray(self) -> xr.Dataset:
        """Units and meanings from the declarations (`stickslip.cf.finish`)."""
        data = {name: ("t", getattr(self, name)) for name in ("slip_rate", "friction", "shear_stress", "slip",
                                                              "load_point")}
        data["theta"] = ("t", self.theta[:, 0])
        if self.theta.shape[1] > 1:
            data["theta2"] = ("t", self.theta[:, 1])
        ds = xr.Dataset(data, coords={"t": self.t}, attrs={"steps": self.steps})
        return finish(ds, "spring-slider with rate-and-state friction", "rsf")


def load_history(load_velocity, times=None) -> tuple[np.ndarray, np.ndarray]:
    """``(times, velocities)`` of a load-point history: one velocity from time 0, or a velocity
    per time (the first time 0, strictly increasing), each held until the next."""
    if times is None:
        return np.zeros(1), np.array([Q.check("load_velocity", load_velocity)])
    times = Q["history_time"].check_array(times, "times")
    velocities = Q["load_velocity"].check_array(load_velocity, "load_velocity")
    if times.ndim != 1 or velocities.shape != times.shape or times.size == 0:
        raise ParameterError("times", times.tolist(), "one time per load velocity (as many as load_velocity)")
    if times[0] != 0.0 or np.any(np.diff(times) <= 0):
        raise ParameterError("times", times.tolist(), "increasing, starting at 0")
    return times, velocities


def slide(slider: SpringSlider, load_velocity, t_end: float, *, times=None, v_init: float | None = None,
          samples: int = 1001, rtol: float = 1e-10, start: SliderRun | None = None) -> SliderRun:
    """The slider's response to the load-point history (``load_velocity`` from ``times``) over
    ``t_end``, from steady sliding at ``v_init`` (default: the first load velocity), or from the end
    of the run ``start`` (its time, slip and load point carried on)."""
    if not isinstance(slider, SpringSlider):
        raise ParameterError("slider", slider, "a stickslip.rsf.SpringSlider")
    times, velocities = load_history(load_velocity, times)
    t_end = Q.check("t_end", t_end)
    samples, rtol = Q.check("samples", samples), Q.check("rtol", rtol)
    if start is not None:
        if not isinstance(start, SliderRun) or start.end_state.size != slider.law.states + 3:
            raise ParameterError("start", start, "a SliderRun of a slider with as many state variables")
        if v_init is not None:
            raise ParameterError("v_init", v_init, "left out with start (the run goes on from its end)")
        y, t_start, x_load = start.end_state, float(start.t[-1]), float(start.load_point[-1])
    else:
        if v_init is None:
            if velocities[0] == 0.0:
                raise ParameterError("v_init", None, "given when the history starts with a hold (load_velocity 0)")
            v_init = velocities[0]
        v_init = Q.check("v_init", v_init)
        y, t_start, x_load = slider.steady_state(v_init), 0.0, 0.0
    grid = np.linspace(0.0, t_end, samples)
    out = np.empty((samples, y.size))
    load = np.empty(samples)
    steps = 0
    out[0], load[0] = y, x_load
    edges = [t for t in times if t < t_end] + [t_end]
    for (t0, t1), v_lp in zip(zip(edges, edges[1:]), velocities):
        p = pack(slider, v_lp)
        if not np.all(np.isfinite(_jacobian(y, p))):
            raise NoSolutionError(f"the slider's equations overflow at t = {t0:.6g} s (a slip rate's response to "
                                  "stress beyond the range of the numbers: a mass, a or D_c too small for the rest)")
        inside = (grid > t0) & (grid <= t1)
        at = np.concatenate([[t0], grid[inside]])
        if at[-1] < t1:
            at = np.append(at, t1)
        ys, taken = solve_piece(p, y, at, rtol)
        steps += taken
        out[inside] = ys[1:1 + int(inside.sum())]
        load[inside] = x_load + v_lp * (grid[inside] - t0)
        x_load += v_lp * (t1 - t0)
        y = ys[-1]
    n = slider.law.states
    log_v, psi = out[:, 0], out[:, 1:1 + n]
    mu = np.real(slider.law.friction(log_v, psi.T)[0]) * np.ones_like(log_v)  # every sample at once
    tau = slider.normal_stress * mu if slider.mass == 0.0 else out[:, 1 + n]
    result = SliderRun(t_start + grid, np.exp(log_v), slider.law.theta(psi), mu, tau, out[:, 2 + n], load, steps, y)
    if not all(np.all(np.isfinite(a)) for a in (result.slip_rate, result.theta, result.shear_stress, result.slip)):
        raise NoSolutionError("the slider's history overflows: its slip rate or state left the range of the numbers")
    return result


def _jacobian(y: np.ndarray, p: np.ndarray) -> np.ndarray:
    out = np.empty((y.size, y.size))
    try:
        with np.errstate(all="ignore"):  # numpy's scalars give inf where Python's math raises
            KERNELS.interpreted.jacobian(y, p, out)
    except (ArithmeticError, ValueError):
        out[:] = np.inf
    return out


#: The complex step of `directional` and `complex_jacobian`.
COMPLEX_STEP = 1e-30


def directional(func, y: np.ndarray, u: np.ndarray) -> np.ndarray:
    """``J(y) u`` of a function that takes complex arguments, for a real ``u``, by one complex step
    (exact to round-off: no difference is taken)."""
    return np.imag(func(y + 1j * COMPLEX_STEP * u)) / COMPLEX_STEP


def complex_jacobian(func, y: np.ndarray) -> np.ndarray:
    """``d func / d y`` by complex steps, one column per entry of ``y``."""
    return np.stack([directional(func, y, e) for e in np.eye(y.size)], axis=1)


def jacobian(slider: SpringSlider, y: np.ndarray, v_load: float) -> np.ndarray:
    """``d y' / d y`` by complex steps (exact to round-off: no difference is taken)."""
    return complex_jacobian(lambda z: slider.rhs(z, v_load), y)

"""Steady sliding of the spring-slider: its linear stability, the critical stiffness and the
Hopf frequency, and the limit cycle beyond.

The eigenvalues are those of the slider's equations linearised (by complex steps) about steady
sliding at the load-point velocity, in ``(ln V, psi)`` (quasi-static) or ``(ln V, psi, tau)``
(with inertia); slip does not enter. The critical stiffness ``k_c`` is where the leading pair
crosses the imaginary axis (Brent's method in ``ln k``); for one state variable the closed form
(Ruina 1983, Rice & Ruina 1983) is ``k_c = sigma (b - a) / D_c (1 + m V^2 / (sigma a D_c))``,
with frequency ``omega_c = (V / D_c) sqrt((b - a) / a)`` with or without inertia.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from scipy.optimize import brentq

from ..errors import NoSolutionError, ParameterError
from ..quantities import COMMON, RSF as Q
from ..results import Result
from .slider import SpringSlider, jacobian, slide

__all__ = ["SliderStability", "linear_stability", "SliderCycle", "slider_cycle"]


@dataclass(frozen=True, eq=False, repr=False)
class SliderStability(Result):
    """Steady sliding at ``load_velocity``: its ``eigenvalues`` (by decreasing real part) at the
    slider's stiffness, the ``critical_stiffness`` (0 if steady sliding is stable at every stiffness)
    and the frequency of the oscillation born there."""

    load_velocity: float
    steady_friction: float
    eigenvalues: np.ndarray
    critical_stiffness: float
    hopf_frequency: float
    MODEL = "rsf"

    @property
    def stable(self) -> bool:
        return bool(np.all(self.eigenvalues.real < 0))

    def to_dict(self) -> dict:
        return {"stable": self.stable, "steady_friction": self.steady_friction,
                "critical_stiffness": self.critical_stiffness, "hopf_frequency": self.hopf_frequency,
                "hopf_period": 2 * math.pi / self.hopf_frequency if self.hopf_frequency > 0 else 0.0,
                "eigenvalue_real": self.eigenvalues.real.tolist(), "eigenvalue_imag": self.eigenvalues.imag.tolist()}


def _eigenvalues(slider: SpringSlider, v: float) -> np.ndarray:
    y = slider.steady_state(v)
    keep = slice(0, y.size - 1) if slider.mass > 0 else slice(0, y.size - 2)  # drop slip (and tau, determined)
    J = jacobian(slider, y, v)[keep, keep]
    if not np.all(np.isfinite(J)):
        raise NoSolutionError("the slider's equations overflow about steady sliding (a slip rate's response to "
                              "stress beyond the range of the numbers: a mass, a or D_c too small for the rest)")
    eig = np.linalg.eigvals(J)
    return eig[np.lexsort((-eig.imag, -eig.real))]


def linear_stability(slider: SpringSlider, load_velocity: float) -> SliderStability:
    """Linear stability of steady sliding at ``load_velocity`` and the critical stiffness."""
    if not isinstance(slider, SpringSlider):
        raise ParameterError("slider", slider, "a stickslip.rsf.SpringSlider")
    v = Q.check("load_velocity", load_velocity)
    if v == 0.0:
        raise ParameterError("load_velocity", v, "positive for steady sliding")
    eig = _eigenvalues(slider, v)
    scale = slider.normal_stress / min(slider.law.dc, slider.law.dc2 or math.inf)

    def growth(log_k: float) -> float:
        return float(_eigenvalues(replace(slider, stiffness=math.exp(log_k)), v).real.max())

    ks = np.log(scale) + np.log(10.0) * np.arange(-12, 13)
    ks = ks[(ks >= math.log(Q["stiffness"].range.lo)) & (ks <= math.log(Q["stiffness"].range.hi))]
    g = np.array([growth(k) for k in ks])
    k_c, omega = 0.0, 0.0
    unstable = np.nonzero(g > 0)[0]
    if unstable.size:
        last = unstable[-1]
        if last + 1 >= ks.size:
            raise NoSolutionError("steady sliding is unstable at every stiffness up to the declared maximum")
        log_k = brentq(growth, ks[last], ks[last + 1], xtol=1e-14, rtol=1e-14)
        k_c = math.exp(log_k)
        omega = float(np.abs(_eigenvalues(replace(slider, stiffness=k_c), v)[0].imag))
    return SliderStability(v, slider.law.steady_friction(v), eig, k_c, omega)


@dataclass(frozen=True, eq=False, repr=False)
class SliderCycle(Result):
    """A limit cycle of the slider at a constant load-point velocity: its period and extremes."""

    period: float
    friction_min: float
    friction_max: float
    slip_rate_min: float
    slip_rate_max: float
    MODEL = "rsf"

    def to_dict(self) -> dict:
        return {"period": self.period, "friction_min": self.friction_min, "friction_max": self.friction_max,
                "slip_rate_min": self.slip_rate_min, "slip_rate_max": self.slip_rate_max}


def slider_cycle(slider: SpringSlider, load_velocity: float, *, transient: float | None = None, cycles: int = 5,
                 rtol: float = 1e-10, tol: float = 1e-6) -> SliderCycle:
    """The cycle the slider settles on at ``load_velocity`` from a perturbed steady sliding (slip
    rate 1.2 times the load's): the period between upward crossings of ``V = V_lp``, once the last
    ``cycles`` periods agree to ``tol``, looked for up to ``transient`` (default: 1000 periods of
    the linear oscillation)."""
    cycles, rtol, tol = Q.check("cycles", cycles), Q.check("rtol", rtol), COMMON["tol"].check(tol, "tol")
    if tol < rtol:  # periods computed to rtol cannot be seen to agree closer: it would run its whole transient
        raise ParameterError("tol", tol, f"at least rtol = {rtol:g} (periods computed to rtol cannot be seen to "
                                         "agree more closely)", also=("rtol",))
    transient = None if transient is None else Q["t_end"].check(transient, "transient")
    stability = linear_stability(slider, load_velocity)
    if stability.stable:
        raise NoSolutionError(f"steady sliding at {load_velocity:g} m/s is stable at this stiffness (k_c = "
                              f"{stability.critical_stiffness:.6g} Pa/m): there is no cycle to settle on from near it")
    guess = 2 * math.pi / max(float(np.abs(stability.eigenvalues[0].imag)), 1e-300)
    transient = 1000 * guess if transient is None else transient
    if not 4 * (cycles + 2) * guess <= min(transient, Q["t_end"].range.hi):
        raise NoSolutionError(f"the oscillation's period (about {guess:.6g} s) is too long for {cycles} of them "
                              f"within {min(transient, Q['t_end'].range.hi):.6g} s")
    chunk = 4 * (cycles + 2) * guess
    run = slide(slider, load_velocity, chunk, v_init=1.2 * load_velocity, samples=20001, rtol=rtol)
    periods = np.array([])
    while True:
        r = np.log(run.slip_rate / load_velocity)
        up = np.nonzero((r[:-1] < 0) & (r[1:] >= 0))[0]
        crossings = run.t[up] - r[up] * (run.t[up + 1] - run.t[up]) / (r[up + 1] - r[up])
        if crossings.size >= cycles + 1:
            periods = np.diff(crossings[-(cycles + 1):])
            if np.ptp(periods) <= tol * periods.mean():
                break
        if run.t[-1] >= transient:
            said = (f"periods {periods.min():.6g} to {periods.max():.6g} s" if periods.size else
                    f"fewer than {cycles} oscillations in the last {chunk:.6g} s")
            raise NoSolutionError(f"the oscillation has not settled to {tol:g} after {run.t[-1]:.6g} s ({said}): "
                                  "a longer transient, or no cycle")
        if crossings.size >= 2:  # the chunk spans the last cycles, sampled finely enough to find them
            chunk = 1.5 * (cycles + 1) * float(np.diff(crossings).max())
        run = slide(slider, load_velocity, chunk, start=run, samples=20001, rtol=rtol)
    last = run.t >= crossings[-(cycles + 1)]
    return SliderCycle(float(periods.mean()), float(run.friction[last].min()), float(run.friction[last].max()),
                       float(run.slip_rate[last].min()), float(run.slip_rate[last].max()))

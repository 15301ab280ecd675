"""A rate-and-state interface in the quasi-dynamic approximation: the elastic half-space's static
response by the FFT and its radiation damping, no wave memory (Rice, 1993), for slow slip and long
earthquake cycles; antiplane, periodic along the interface.

Each node's shear traction ``tau0(x, t) + f - eta V`` equals its strength ``sigma mu(V, psi)`` (the
package's rate-and-state law, `stickslip.rsf.RateState`), with ``f_k = -K_k delta_k`` the static
stress of the slip's modes. Two geometries:

* ``"rigid"``: a half-space sliding on a rigid body (the paper's model 3), ``K_k = mu |k|``,
  ``eta = mu / c_s``;
* ``"fault"``: a fault between two identical half-spaces slipping ``delta`` (each side ``delta / 2``),
  ``K_k = mu |k| / 2``, ``eta = mu / (2 c_s)``.

The slip rate at each node is found from that equation by Newton's method on ``ln V`` (the left side
falls, the right rises with ``V``: one root), and the slips and states ``psi`` advance by scipy's
adaptive ``solve_ivp`` (RK45, its error control the step's: slow creep and fast slip alike). A
mode of wavenumber ``k`` is a spring-slider of stiffness ``K_k`` with the damping ``eta``: steady
sliding is unstable for modes longer than ``2 pi mu / (s K_c)`` (``K_c = sigma (b - a) / D_c``,
``s = 1`` rigid, 2 fault), as the tests check against that slider's linearisation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import NoSolutionError, ParameterError
from ..quantities.sbim import SBIM as Q
from ..results import Result
from .fields import space_time
from .ratestate import perturbed_psi, slip_rates

__all__ = ["QuasiDynamicProblem", "QuasiDynamicRun", "run_quasidynamic"]


@dataclass(frozen=True)
class QuasiDynamicProblem:
    """An interface of ``length`` [m] in ``elements``, of a half-space (``shear_modulus`` [Pa],
    ``shear_wave_speed`` [m/s]) on a rigid body or a fault (``geometry``), under ``normal_stress`` [Pa]
    with the rate-and-state ``law`` (one state variable), sliding steadily at ``slip_rate`` [m/s] at
    ``t = 0`` under the traction that holds it there, plus ``stressing_rate`` [Pa/s] from then on."""

    shear_modulus: float
    shear_wave_speed: float
    length: float
    elements: int
    law: object
    normal_stress: float
    slip_rate: float
    stressing_rate: float = 0.0
    geometry: str = "rigid"

    def __post_init__(self):
        from ..rsf import RateState

        for name in ("shear_modulus", "shear_wave_speed", "length", "elements"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        for name in ("normal_stress", "slip_rate", "stressing_rate"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))
        if not isinstance(self.law, RateState) or self.law.states != 1:
            raise ParameterError("law", self.law, "a stickslip.rsf.RateState with one state variable")
        if self.geometry not in ("rigid", "fault"):
            raise ParameterError("geometry", self.geometry, "'rigid' (a half-space on a rigid body) or 'fault' (two "
                                 "identical half-spaces)")

    @property
    def sides(self) -> int:
        return 1 if self.geometry == "rigid" else 2

    @property
    def damping(self) -> float:
        """``eta`` [Pa s/m]: the radiation damping."""
        return self.shear_modulus / (self.sides * self.shear_wave_speed)

    @property
    def x(self) -> np.ndarray:
        return np.arange(self.elements) * self.length / self.elements

    @property
    def stiffness(self) -> np.ndarray:
        """``K_k`` [Pa/m] of the real FFT's modes."""
        k = 2.0 * math.pi * np.arange(self.elements // 2 + 1) / self.length
        return self.shear_modulus * k / self.sides

    def steady_traction(self) -> float:
        """The traction [Pa] of steady sliding at ``slip_rate``."""
        return self.normal_stress * self.law.steady_friction(self.slip_rate) + self.damping * self.slip_rate


@dataclass(frozen=True, eq=False, repr=False)
class QuasiDynamicRun(Result):
    """Samples ``t`` [s] of the slip, slip rate and state at each ``x`` (``(samples, N)``)."""

    problem: QuasiDynamicProblem
    t: np.ndarray
    slip: np.ndarray
    slip_rate: np.ndarray
    psi: np.ndarray
    evaluations: int

    def to_dict(self) -> dict:
        p = self.problem
        return {"shear_modulus": p.shear_modulus, "length": p.length, "elements": p.elements,
                "normal_stress": p.normal_stress, "slip_rate_max": float(self.slip_rate.max()),
                "samples": len(self.t), "geometry": p.geometry}

    def to_xarray(self):
        return space_time(self, ("slip", "slip_rate"), f"quasi-dynamic rate-and-state interface "
                          f"({self.problem.geometry})")


def run_quasidynamic(problem: QuasiDynamicProblem, t_end: float, psi_perturbation=None, samples: int = 201,
                     rtol: float = 1e-8) -> QuasiDynamicRun:
    """Run ``problem`` from steady sliding (each node's ``psi`` plus ``psi_perturbation``, an array of
    ``elements`` numbers, or none) for ``t_end`` [s], ``samples`` uniform samples."""
    from scipy.integrate import solve_ivp

    if not isinstance(problem, QuasiDynamicProblem):
        raise ParameterError("problem", problem, "a QuasiDynamicProblem")
    t_end = Q.check("t_end", t_end)
    samples, rtol = Q.check("samples", samples), Q.check("rtol", rtol)
    n, p = problem.elements, problem
    psi0 = perturbed_psi(p.law, p.slip_rate, n, psi_perturbation)
    tau_i = p.steady_traction()
    K = p.stiffness
    last = [np.full(n, math.log(p.slip_rate))]
    calls = [0]

    def rates(t, y):
        slip, psi = y[:n], y[n:]
        drive = tau_i + p.stressing_rate * t + np.fft.irfft(-K * np.fft.rfft(slip), n)
        log_v = slip_rates(p.law, p.normal_stress, p.damping, drive, psi, last[0])
        last[0] = log_v
        return log_v

    def rhs(t, y):
        calls[0] += 1
        try:
            log_v = rates(t, y)
        except NoSolutionError:  # a trial state with no slip rate (a drive below the strength's least):
            return np.full(y.size, np.nan)  # RK45 refuses the step (its error is not below 1) and shortens it
        return np.concatenate([np.exp(log_v), p.law.state_rate(log_v, y[None, n:])[0]])

    grid = np.linspace(0.0, t_end, samples)
    sol = solve_ivp(rhs, (0.0, t_end), np.concatenate([np.zeros(n), psi0]), method="RK45", rtol=rtol,
                    atol=rtol * 1e-3, t_eval=grid)
    if sol.status != 0 or not np.all(np.isfinite(sol.y)):
        raise NoSolutionError(f"the quasi-dynamic run stopped at t = {sol.t[-1]:.6g} s ({sol.message})")
    y = sol.y.T
    log_v = np.array([rates(t, row) for t, row in zip(sol.t, y)])
    return QuasiDynamicRun(p, sol.t, y[:, :n], np.exp(log_v), y[:, n:], calls[0])

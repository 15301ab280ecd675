"""Rate-and-state friction at an interface's nodes: each node's slip rate from the stress that drives
it, and its state over a step; shared by the quasi-dynamic runs (`stickslip.sbim.run_quasidynamic`)
and the fully dynamic antiplane and in-plane ones (`RateStateFriction` in `stickslip.sbim.run_antiplane`
and `stickslip.sbim.run_inplane`; in-plane the strength is the contact pressure's, the contact held
closed: `contact_step`).

At a node driven by ``g`` (the load and the half-space's static and memory terms) with the radiation
damping ``eta``, the slip rate balances the strength, ``g - eta V = sigma mu(V, psi)``: the left side
falls and the right rises with ``V`` (one root), found by Newton's method on ``ln V``. A drive no
positive slip rate balances (at or below zero, or below the regularised strength's least) has no root:
`slip_rates` says so and the caller decides (the quasi-dynamic integrator shortens its step; a dynamic
run stops).

Over a step at a constant slip rate the aging and the slip laws' states have closed forms
(`advance_state`): ``theta`` relaxes to ``D_c / V`` as ``exp(-V dt / D_c)`` (aging), and
``ln(V theta / D_c)`` decays so (slip), whatever the step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import NoSolutionError, ParameterError
from ..quantities.sbim import SBIM as Q

__all__ = ["RateStateFriction", "slip_rates", "advance_state", "perturbed_psi", "contact_step", "NEWTON",
           "NEWTON_TOL"]

#: Newton iterations on ln V at most, and the tolerance on its step.
NEWTON, NEWTON_TOL = 60, 1e-12
#: ln V below which a slip rate is taken for zero (1e-300 m/s).
LOG_ZERO = math.log(1e-300)


def slip_rates(law, normal_stress: float, damping: float, drive: np.ndarray, psi: np.ndarray,
               guess: np.ndarray) -> np.ndarray:
    """``ln V`` at each node where ``drive - damping V = normal_stress mu(V, psi)`` (``law`` a
    `stickslip.rsf.RateState` with one state variable); Newton from ``guess``, each step at most 5
    (far from the root the slope misleads). Raises `NoSolutionError` if it does not converge."""
    if np.any(drive <= 0.0):
        raise NoSolutionError(f"a drive at or below zero at {int(np.sum(drive <= 0.0))} nodes (the strength would "
                              "have to push the slip on: the interface slides forwards only)")
    log_v = np.array(guess, dtype=float)
    for _ in range(NEWTON):
        mu, mu_v, _ = law.friction(log_v, psi[None, :])
        v = np.exp(log_v)
        g = normal_stress * np.real(mu) + damping * v - drive
        step = g / (normal_stress * np.real(mu_v) + damping * v)
        step = np.clip(step, -5.0, 5.0)
        log_v = log_v - step
        if np.max(np.abs(step)) < NEWTON_TOL:
            if np.min(log_v) < LOG_ZERO:
                raise NoSolutionError("a slip rate fell to zero (the drive below the strength at any positive rate; "
                                      "the plain law has no value at zero slip rate, the regularised one no root below it)")
            return log_v
    raise NoSolutionError("no slip rate balances the drive (Newton on ln V did not converge: the drive below the "
                          "strength at every slip rate the numbers hold)")


def advance_state(law, psi: np.ndarray, log_v: np.ndarray, dt: float) -> np.ndarray:
    """``psi`` after ``dt`` at the constant slip rates ``exp(log_v)`` (the aging or the slip law: exact)."""
    x = np.exp(log_v) * dt / law.dc
    steady = math.log(law.v_ref) - log_v  # psi of steady sliding at V
    if law.evolution == "aging":  # r = V theta / D_c relaxes to 1: r e^-x + (1 - e^-x), two terms >= 0
        return steady + np.log(np.exp(psi - steady - x) - np.expm1(-x))
    return steady + (psi - steady) * np.exp(-x)  # slip: ln(V theta / D_c) = psi - steady decays


@dataclass(frozen=True)
class RateStateFriction:
    """A rate-and-state interface for `stickslip.sbim.run_antiplane`: the ``law`` (a
    `stickslip.rsf.RateState`, one state variable, the aging or the slip law) under ``normal_stress``
    [Pa], every node sliding steadily at ``slip_rate`` [m/s] at ``t = 0`` (its state steady there)
    plus ``psi_perturbation`` (one number per element, or none)."""

    law: object
    normal_stress: float
    slip_rate: float
    psi_perturbation: object = None

    def __post_init__(self):
        from ..rsf import RateState

        if not isinstance(self.law, RateState) or self.law.states != 1 or self.law.evolution == "prz":
            raise ParameterError("law", self.law, "a stickslip.rsf.RateState with one state variable and the aging "
                                 "or the slip law (their states advance exactly over a step)")
        for name in ("normal_stress", "slip_rate"):
            object.__setattr__(self, name, Q.check(name, getattr(self, name)))

    def steady_drive(self, damping: float) -> float:
        """The uniform traction [Pa] that holds steady sliding at ``slip_rate``."""
        return self.normal_stress * self.law.steady_friction(self.slip_rate) + damping * self.slip_rate

    def initial_psi(self, n: int) -> np.ndarray:
        return perturbed_psi(self.law, self.slip_rate, n, self.psi_perturbation)

    def parameters(self) -> dict:
        """Its numbers by their declared names (``slip_law`` true for Ruina's slip law; the perturbation not)."""
        rs = self.law
        return {"a": rs.a, "b": rs.b, "dc": rs.dc, "f0": rs.f0, "v_ref": rs.v_ref, "slip_law": rs.evolution == "slip",
                "normal_stress": self.normal_stress, "slip_rate": self.slip_rate}


def perturbed_psi(law, slip_rate: float, n: int, perturbation) -> np.ndarray:
    """``psi`` of steady sliding at ``slip_rate`` at ``n`` nodes plus ``perturbation`` (``n`` finite
    numbers, or None)."""
    psi = np.full(n, float(law.steady_psi(slip_rate)[0]))
    if perturbation is None:
        return psi
    try:
        d = np.asarray(perturbation, dtype=float)
    except (TypeError, ValueError):
        d = np.zeros(0)
    if d.shape != (n,) or not np.all(np.isfinite(d)):
        raise ParameterError("psi_perturbation", f"<{type(perturbation).__name__} of shape {d.shape}>",
                             f"{n} finite numbers (one per element) or None")
    return psi + d


def contact_step(law: RateStateFriction, Gx: np.ndarray, Gy: np.ndarray, psi: np.ndarray, log_v: np.ndarray,
                 damping: float, t: float, pressure: np.ndarray | None = None):
    """One in-plane step of rate-and-state nodes in closed contact: ``(V_x, V_y, sigma_xy, sigma_yy, ln V)``
    from the drives ``Gx``, ``Gy`` (the opening rate zero, so ``sigma_yy = Gy``), the strength the contact
    pressure ``-Gy`` (or the ``pressure`` the strength sees, Prakash-Clifton's) times ``mu(V, psi)``,
    ``damping`` the shear radiation damping. A node that would open (``Gy >= 0``), or no slip rate balancing
    a drive, stops the run (`NoSolutionError`)."""
    if np.any(Gy >= 0.0):
        raise NoSolutionError(f"at t = {t:.6g} s a node would open (normal traction {float(Gy.max()):.3g} Pa): "
                              "rate-and-state friction in-plane holds the contact closed")
    try:
        log_v = slip_rates(law.law, -Gy if pressure is None else pressure, damping, Gx, psi, log_v)
    except NoSolutionError as err:
        raise NoSolutionError(f"at t = {t:.6g} s: {err}") from None
    V = np.exp(log_v)
    return V, np.zeros_like(V), Gx - damping * V, Gy, log_v

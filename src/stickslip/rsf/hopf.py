"""The Hopf bifurcation of the spring-slider's steady sliding: sub- or supercritical.

At the critical stiffness ``k_c`` a pair of eigenvalues ``+-i w`` crosses the imaginary axis. Its
first Lyapunov coefficient ``l1`` (Kuznetsov, *Elements of Applied Bifurcation Theory*, eq. 3.20)
decides what is born there: ``l1 < 0`` a stable cycle on the unstable side (supercritical),
``l1 > 0`` an unstable cycle on the stable side (subcritical: finite perturbations of steady
sliding above ``k_c`` grow), ``l1 = 0`` neither at this order. With ``A q = i w q``,
``A^T p = -i w p``, ``conj(p) . q = 1`` and ``B``, ``C`` the second and third derivatives of the
vector field,

    l1 = Re[ <p, C(q, q, q*)> - 2 <p, B(q, A^-1 B(q, q*))> + <p, B(q*, (2 i w - A)^-1 B(q, q))> ] / (2 w).

The derivatives: the Jacobian by complex steps (exact), then central differences of it for ``B``
and ``C``; ``l1`` is taken at two difference steps, and their difference is its error.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Callable

import numpy as np

from .. import validation as check
from ..errors import NoSolutionError, ParameterError
from ..quantities import RSF as Q
from ..results import Result
from .slider import SpringSlider, complex_jacobian, directional
from .stability import linear_stability

__all__ = ["first_lyapunov_coefficient", "HopfCriticality", "hopf_criticality"]

def _bilinear(form, x, y):
    """A real bilinear ``form`` extended to complex arguments."""
    xr, xi, yr, yi = x.real, x.imag, y.real, y.imag
    return form(xr, yr) - form(xi, yi) + 1j * (form(xr, yi) + form(xi, yr))


def _trilinear(form, x, y, z):
    out = 0.0
    for a, fa in ((x.real, 1.0), (x.imag, 1j)):
        for b, fb in ((y.real, 1.0), (y.imag, 1j)):
            for c, fc in ((z.real, 1.0), (z.imag, 1j)):
                out = out + fa * fb * fc * form(a, b, c)
    return out


def _coefficient(field, x0, h) -> tuple[float, float]:
    J = complex_jacobian(field, x0)
    eig, right = np.linalg.eig(J)
    pick = int(np.argmax(eig.imag))
    w = float(eig[pick].imag)
    if w <= 0 or abs(eig[pick].real) > 1e-6 * abs(eig[pick]):
        raise NoSolutionError(f"no pair of eigenvalues on the imaginary axis here (leading {eig[pick]:.6g})")
    q = right[:, pick]
    left_eig, left = np.linalg.eig(J.T)
    p = left[:, int(np.argmin(np.abs(left_eig + 1j * w)))]
    p = p / np.conj(np.conj(p) @ q)  # conj(p) . q = 1

    def B(u, v):  # d/de [J(x0 + e v) u], central
        return (directional(field, x0 + h * v, u) - directional(field, x0 - h * v, u)) / (2 * h)

    def C(u, v, s):  # d2/de dd [J(x0 + e v + d s) u], central
        return (directional(field, x0 + h * (v + s), u) - directional(field, x0 + h * (v - s), u)
                - directional(field, x0 - h * (v - s), u)
                + directional(field, x0 - h * (v + s), u)) / (4 * h * h)

    qc = np.conj(q)
    b_qqc = _bilinear(B, q, qc)
    b_qq = _bilinear(B, q, q)
    term = (_trilinear(C, q, q, qc) - 2 * _bilinear(B, q, np.linalg.solve(J, b_qqc))
            + _bilinear(B, qc, np.linalg.solve(2j * w * np.eye(x0.size) - J, b_qq)))
    return float((np.conj(p) @ term).real / (2 * w)), w


def first_lyapunov_coefficient(field: Callable, x0, step: float = 1e-4) -> tuple[float, float, float]:
    """``(l1, error, w)`` of the vector ``field`` (a function of a state that takes complex
    arguments) at its equilibrium ``x0``, where its Jacobian has eigenvalues ``+-i w``; ``step`` the
    difference step, in the units of the state (the error: ``l1`` at ``step`` against ``step / 2``)."""
    field = check.function("field", field)
    x0 = check.finite_array("x0", x0, ndim=1)
    if x0.size < 2:
        raise ParameterError("x0", x0.tolist(), "a state of at least 2 variables (a Hopf pair needs two)")
    step = Q.check("lyapunov_step", step, "step")
    try:
        value = np.asarray(field(x0.astype(complex)))
    except TypeError as err:
        raise ParameterError("field", getattr(field, "__name__", field), f"a function of one state vector "
                             f"({type(err).__name__}: {err})") from None
    if value.shape != x0.shape or value.dtype.kind not in "fc" or not np.isfinite(value).all():
        raise ParameterError("field", getattr(field, "__name__", field), f"a function returning {x0.size} finite "
                             f"numbers at x0 (it returned shape {value.shape}, {value.dtype})")
    coarse, w = _coefficient(field, x0, step)
    fine, _ = _coefficient(field, x0, step / 2)
    if not (math.isfinite(fine) and math.isfinite(coarse)):
        raise NoSolutionError(f"the first Lyapunov coefficient came out {fine} at step {step:g}: the field is not "
                              "smooth enough about x0 at that step")
    return fine, abs(fine - coarse), w


@dataclass(frozen=True, eq=False, repr=False)
class HopfCriticality(Result):
    """The Hopf point of steady sliding at ``load_velocity``: the ``critical_stiffness``, the
    ``frequency`` ``w`` and the first Lyapunov coefficient ``l1`` (in the slider's variables
    ``ln V``, ``psi``[, ``tau``/sigma], 1/s) with its numerical ``error``; `criticality` says what it means."""

    load_velocity: float
    critical_stiffness: float
    frequency: float
    l1: float
    error: float
    MODEL = "rsf"

    @property
    def criticality(self) -> str:
        """``subcritical`` (l1 > 0), ``supercritical`` (l1 < 0), or ``degenerate`` (zero within ten
        times its error: a higher order decides)."""
        if abs(self.l1) <= 10 * self.error:
            return "degenerate"
        return "subcritical" if self.l1 > 0 else "supercritical"

    def to_dict(self) -> dict:
        return {"load_velocity": self.load_velocity, "critical_stiffness": self.critical_stiffness,
                "hopf_frequency": self.frequency, "l1": self.l1, "l1_error": self.error,
                "criticality": self.criticality}


def hopf_criticality(slider: SpringSlider, load_velocity: float) -> HopfCriticality:
    """The Hopf point of the slider's steady sliding at ``load_velocity`` (its stiffness set to the
    critical one) and whether it is sub- or supercritical."""
    stability = linear_stability(slider, load_velocity)
    if stability.critical_stiffness == 0.0:
        raise NoSolutionError("steady sliding is stable at every stiffness (b <= a): no Hopf point")
    v = stability.load_velocity
    at = replace(slider, stiffness=stability.critical_stiffness)
    y = at.steady_state(v)
    keep = y.size - 1 if at.mass > 0 else y.size - 2  # (ln V, psi[, tau]): slip, and tau quasi-statically, do not enter
    scale = np.ones(keep)
    if at.mass > 0:
        scale[-1] = at.normal_stress  # tau in units of sigma: every variable of order one

    def field(u):
        full = y.astype(np.result_type(u, float))
        full[:keep] = u * scale
        return at.rhs(full, v)[:keep] / scale

    try:
        l1, error, w = first_lyapunov_coefficient(field, y[:keep] / scale)
    except NoSolutionError as err:
        raise NoSolutionError(f"the Hopf point at k_c = {stability.critical_stiffness:.6g}: {err}") from None
    if not (math.isfinite(l1) and math.isfinite(error)):
        raise ParameterError("slider", slider, "a slider whose equations stay finite about its Hopf point")
    return HopfCriticality(v, stability.critical_stiffness, w, l1, error)

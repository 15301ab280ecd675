"""The explicit scheme's stability, mode by mode: the roots of each mode's recurrence.

One mode of wavenumber ``k`` advances, with ``a = k c_s dt`` and the slips of the steps ``q_n = dt V_n``::

    q_n = a D^-1 [-S0 u_n + sum_{i < M} H_i q_{n-1-i}],    u_{n+1} = u_n + q_n,

``D`` the radiation damping per ``mu / c_s`` (1 antiplane; ``diag(1, c_p / c_s)`` in-plane), ``S0`` the
static stiffness per ``mu k``, ``H_i = H((i + 1) a)`` the scheme's memory weights
(`stickslip.sbim.kernels`, `stickslip.sbim.inplane_kernels`) and ``M`` the steps of history kept. Its
characteristic function, ``F(z) = det[(z - 1)(D - a H(z)) + a S0]`` with ``H(z) = sum_i H_i z^-(1+i)``,
is ``z^-dM`` times a polynomial of degree ``d (M + 1)`` (``d`` = 1 or 2 components): by the argument
principle the recurrence has ``d - wind(F)`` roots outside the unit circle, ``wind`` the winding number
of ``F`` along it (``H(z)`` there by one FFT). The scheme is stable when no mode has any.

In-plane, the free surface (both components moving, as on open nodes) is the stricter case, the
surface held normally (closed contact) the milder; the check asks both. Found with it: the first-order scheme
with in-plane kernels cut short is weakly unstable (the free surface's undamped Rayleigh mode grows
at about 1e-3 of its frequency at ``nu = 1/4`` with 4 or 8 periods kept); faded over the window
(`stickslip.sbim.inplane_kernels.hann_taper`) it is not, at ``nu <= 0.3`` and ``beta`` up to 0.38.
Above ``nu`` = 1/3 (where the instantaneous coupling ``2 - c_p / c_s`` changes sign) the free
surface's shortest modes grow in this first-order scheme at most ``beta``: such runs are refused.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from ..errors import ParameterError
from ..quantities.sbim import SBIM as Q
from .inplane_kernels import hann_taper, inplane_kernels, kernel_table, static_stiffness, wave_speed_ratio
from .kernels import antiplane_kernel

__all__ = ["growing_roots", "check_stable", "GROWTH"]

#: The largest spurious growth of any mode of the scheme over a run.
GROWTH = 0.01


def _system(kind: str, a: float, M: int, poisson: float | None, held: bool, window: int, table=None):
    T = a * np.arange(1, M + 1, dtype=float)
    if kind == "antiplane":
        return np.eye(1), np.eye(1), antiplane_kernel(T)[:, None, None]
    eta = wave_speed_ratio(poisson)
    s11, s22, s12 = static_stiffness(poisson)
    if table is None:
        h = inplane_kernels(T, poisson) if M else np.zeros((3, 0))
    else:  # h at T = j T1 (`kernel_table`), a = m T1
        h = table[1][:, table[0] * np.arange(1, M + 1)]
    h11, h22, h12 = h * hann_taper(np.arange(M), window)
    if held:
        return np.eye(1), np.array([[s11]]), h11[:, None, None]
    H = np.stack([np.stack([h11, -1j * h12], -1), np.stack([1j * h12, h22], -1)], -2)
    return np.diag([1.0, eta]), np.array([[s11, -1j * s12], [1j * s12, s22]]), H


def growing_roots(mode_step: float, history_steps: int, kind: str = "antiplane", poisson: float | None = None,
                  held: bool = False, radius: float = 1.0, window_steps: int | None = None, table=None) -> int:
    """Roots of modulus above ``radius`` of the recurrence of a mode with ``a = mode_step = k c_s dt``
    keeping ``history_steps`` steps (module docstring; on the circle ``|z| = r`` the same count holds),
    in-plane faded over ``window_steps`` (``history_steps`` if not given:
    `stickslip.sbim.inplane_kernels.hann_taper`); ``table``: `kernel_table`'s at ``T1`` with ``a = m T1``,
    as ``(m, table)``."""
    a, M = Q.check("mode_step", mode_step), Q.check("history_steps", history_steps)
    radius = Q.check("radius", radius)
    window = M if window_steps is None else Q.check("window_steps", window_steps)
    if kind not in ("antiplane", "inplane"):
        raise ParameterError("kind", kind, "'antiplane' or 'inplane'")
    if window < M:
        raise ParameterError("window_steps", window, f"at least history_steps = {M}", also=("history_steps",))
    if kind == "inplane":
        poisson = Q.check("poisson", poisson)
    D, S0, H = _system(kind, a, M, poisson, bool(held), window, table)
    d = D.shape[0]
    K = max(4096, 1 << int(math.ceil(math.log2(32 * (M + 1)))))
    theta = 2.0 * math.pi * np.arange(K) / K
    z = radius * np.exp(1j * theta)
    Hz = np.zeros((K, d, d), dtype=complex)
    if M:
        scale = radius ** -np.arange(1.0, M + 1.0)
        Hz = np.fft.fft(H * scale[:, None, None], n=K, axis=0) / np.exp(1j * theta)[:, None, None]
    Fm = (z - 1.0)[:, None, None] * (D[None] - a * Hz) + a * S0[None]
    F = np.linalg.det(Fm) if d > 1 else Fm[:, 0, 0]
    phase = np.angle(np.concatenate([F, F[:1]]))
    wind = int(round(np.sum(np.angle(np.exp(1j * np.diff(phase)))) / (2.0 * math.pi)))
    return d - wind


def check_stable(kind: str, beta: float, elements: int, history_periods: float, steps: int,
                 poisson: float | None = None) -> None:
    """Refuse a run in which a mode of the scheme (not of the physics) would grow by more than
    `GROWTH` over its ``steps``: the modes ``1, 2, 4, ...`` and the shortest (``a = pi beta``) are
    checked, free and (in-plane) held normally. A check passed is remembered for the process (the
    same scheme run again, under another law or load, is not checked twice)."""
    if kind not in ("antiplane", "inplane"):
        raise ParameterError("kind", kind, "'antiplane' or 'inplane'")
    beta, elements = Q.check("beta", beta), Q.check("elements", elements)
    history_periods, steps = Q.check("history_periods", history_periods), Q.check("steps", steps)
    if kind == "inplane":
        poisson = Q.check("poisson", poisson)
    _checked(kind, float(beta), int(elements), float(history_periods), int(steps),
             None if kind == "antiplane" else float(poisson))


@functools.lru_cache(maxsize=64)
def _checked(kind: str, beta: float, elements: int, history_periods: float, steps: int, poisson) -> None:
    half = elements // 2
    radius = (1.0 + GROWTH) ** (1.0 / steps)
    modes = sorted({1 << j for j in range(int(math.log2(max(half, 1))) + 1)} | {half})
    T1 = 2.0 * math.pi * beta / elements  # k_1 c_s dt, as the run's
    windows = {m: int(math.ceil(history_periods * 2.0 * math.pi / (m * T1))) for m in modes}
    modes = [m for m in modes if windows[m] <= 1 << 20]
    table = None
    if kind == "inplane" and modes:
        table = kernel_table(poisson, T1, max(m * (int(math.ceil(history_periods * 2.0 * math.pi / (m * T1))) + 1)
                                                for m in range(1, half + 1)))
    for m in reversed(modes):
        a, M = m * T1, windows[m]  # a shorter run is a prefix of this one
        for held in ((False, True) if kind == "inplane" else (False,)):
            if growing_roots(a, M, kind, poisson, held, radius, M, None if table is None else (m, table)):
                where = f", poisson = {poisson:g}" if kind == "inplane" else ""
                surface = " held normally" if held else (" free" if kind == "inplane" else "")
                raise ParameterError("beta", beta, f"a stable explicit scheme: with history_periods = "
                                     f"{history_periods:g}{where}, the scheme's mode {m} of {half}{surface} would "
                                     f"grow by more than {GROWTH:.0%} over the run's {steps} steps (try a smaller "
                                     "beta, a longer history_periods or fewer steps; stickslip.sbim.stability)",
                                     also=("history_periods", "steps"))

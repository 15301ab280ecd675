"""The elastodynamic convolution kernels of a half-space's surface, mode by mode.

**Antiplane (mode III).** A half-space ``y > 0`` of shear modulus ``mu`` and shear-wave speed ``c``
whose surface moves along z by ``w(x, t) = sum_k W_k(t) e^{i k x}`` (at rest before ``t = 0``) pulls on
it with the shear traction, mode by mode (Laplace transform of ``c^2 (w_xx + w_yy) = w_tt``: a mode
decays into the body as ``e^{-y sqrt(k^2 + s^2 / c^2)}``)::

    tau_k(s) = -(mu / c) sqrt(s^2 + omega^2) W_k(s),        omega = |k| c,

which in time is the radiation damping ``-(mu / c) dW/dt``, the static stiffness ``-mu |k| W`` and
the memory that undoes it at first (Geubelle and Rice, 1995)::

    tau_k(t) = -(mu / c) dW_k/dt - mu |k| W_k(t) + mu |k| int_0^t H(omega t') dW_k/dt(t - t') dt',

    H(T) = int_T^inf J1(u) / u du = 1 - int_0^T J0(u) du + J1(T),

``H(0) = 1`` (at first only the radiation damping acts), ``H(T) = O(T^-3/2)``. Its integral,
``A(T) = int_0^T H = T H(T) + 1 - J0(T)``, tends to 1: a velocity held over a step adds the exact
`step_weights` ``(A(omega t_{j+1}) - A(omega t_j)) / omega``; the scheme takes each step's slip at the
step's end instead, ``dt H(omega t_{j+1})`` (`ragged_step_weights`: stable, `stickslip.sbim.stability`).

**Truncation.** Each mode keeps its history for ``eta`` of its periods ``2 pi / omega`` (Lapusta et
al., 2000, keep a few): the part of the kernel's integral left out is ``1 - A(2 pi eta)``
(`truncated_part`: 0.042 at 1 period, 0.0049 at 4, 0.00057 at 16).
"""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError

__all__ = ["antiplane_kernel", "antiplane_kernel_integral", "step_weights", "ragged_step_weights", "truncated_part"]


def _times(name: str, value) -> np.ndarray:
    """``value`` as an array of finite numbers >= 0 (a dimensionless time ``omega t``), or refused."""
    try:
        T = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        T = np.asarray(np.nan)
    if isinstance(value, bool) or T.size == 0 or not np.all(np.isfinite(T)) or np.any(T < 0) or T.size > 1 << 27:
        shown = value if len(repr(value)) <= 60 else f"<{type(value).__name__}>"
        raise ParameterError(name, shown, "finite numbers >= 0 (at most 2^27 of them)")
    return T


def _j0_integral(T: np.ndarray) -> np.ndarray:
    from scipy.special import itj0y0

    return itj0y0(T)[0]


def antiplane_kernel(T) -> np.ndarray:
    """``H(T) = int_T^inf J1(u) / u du`` for ``T >= 0``."""
    from scipy.special import j1

    T = _times("T", T)
    return 1.0 - _j0_integral(T) + j1(T)


def antiplane_kernel_integral(T) -> np.ndarray:
    """``A(T) = int_0^T H(u) du = T H(T) + 1 - J0(T)``."""
    from scipy.special import j0

    T = _times("T", T)
    return T * antiplane_kernel(T) + 1.0 - j0(T)


def step_weights(omega: np.ndarray, dt: float, count: np.ndarray, length: int) -> np.ndarray:
    """``(modes, length)``: for each mode of angular frequency ``omega`` (``|k| c``; 0 for the uniform
    mode, whose memory is nil), ``int_{j dt}^{(j+1) dt} H(omega t') dt'`` for ``j < count`` (its kept
    history, in steps), 0 beyond."""
    omega = _times("omega", omega).ravel()
    if isinstance(dt, bool) or not isinstance(dt, (int, float, np.floating)) or not 0 < dt < 1e300:
        raise ParameterError("dt", dt, "a time step > 0 [s]")
    if isinstance(length, bool) or not isinstance(length, (int, np.integer)) or not 1 <= length <= (1 << 27) // max(
            omega.size, 1):
        raise ParameterError("length", length, f"a whole number of steps, 1 to {(1 << 27) // max(omega.size, 1)}")
    count = _times("count", count).ravel()
    if count.size != omega.size:
        raise ParameterError("count", f"{count.size} values", f"one per mode ({omega.size})")
    j = np.arange(length + 1, dtype=float)
    out = np.zeros((omega.size, length))
    moving = omega > 0
    A = antiplane_kernel_integral(omega[moving, None] * dt * j[None, :])
    out[moving] = np.diff(A, axis=1) / omega[moving, None]
    out[np.arange(length)[None, :] >= np.asarray(count)[:, None]] = 0.0
    return out


def ragged_step_weights(omega: np.ndarray, dt: float, count: np.ndarray) -> np.ndarray:
    """The scheme's weights ``dt H(omega (j + 1) dt)``, ``j < count``, of each mode, one mode after another
    (a flat array of ``sum(count)`` weights): each past step's slip taken at the step's end in the
    convolution (the displacement piecewise constant, as Geubelle and Rice). The exact weights of a rate
    held over the step, `step_weights`, make the shortest modes grow for ``beta`` above about 0.2
    (`stickslip.sbim.stability`); these are stable up to ``beta = 2/pi`` and first order alike."""
    omega = _times("omega", omega).ravel()
    if isinstance(dt, bool) or not isinstance(dt, (int, float, np.floating)) or not 0 < dt < 1e300:
        raise ParameterError("dt", dt, "a time step > 0 [s]")
    count = _times("count", count).ravel()
    if count.size != omega.size or np.any(count != np.round(count)) or count.sum() > (1 << 27):
        raise ParameterError("count", f"{count.size} values", f"a whole number of steps per mode ({omega.size}), "
                             "2^27 in all at most")
    count = count.astype(np.int64)
    parts = [np.zeros(n) if w == 0.0 else dt * antiplane_kernel(w * dt * np.arange(1, n + 1, dtype=float))
             for w, n in zip(omega, count) if n > 0]
    return np.concatenate(parts) if parts else np.zeros(0)


def truncated_part(history_periods: float) -> float:
    """``1 - A(2 pi eta)``: the part of a mode's kernel integral beyond ``eta = history_periods`` of its
    periods."""
    from ..quantities.sbim import SBIM

    eta = SBIM.check("history_periods", history_periods)
    return float(1.0 - antiplane_kernel_integral(2.0 * np.pi * eta))

"""The in-plane (modes I and II) convolution kernels of a half-space's surface, mode by mode.

A half-space ``y > 0`` (shear modulus ``mu``, wave speeds ``c_s`` and ``c_p = eta c_s``) whose surface
moves by ``U_x, U_y`` (one Fourier mode ``e^{i k x}``, ``k > 0``, Laplace variable ``s``) exerts on
what lies below it the tractions ``sigma_xy, sigma_yy`` at ``y = 0`` (Lamé potentials decaying as
``e^{-alpha y}``, ``e^{-beta y}``; ``p = s / (k c_s)``, ``a = alpha / k = sqrt(1 + p^2 / eta^2)``,
``b = beta / k = sqrt(1 + p^2)``, ``D = 1 + (1 + p^2) / eta^2``)::

    sigma_xy = -mu k S11(p) U_x + i mu k S12(p) U_y,
    sigma_yy = -mu k S22(p) U_y - i mu k S12(p) U_x,

    S11 = a (a b + 1) / D,   S22 = b (a b + 1) / D,   S12 = 2 - (a b + 1) / D.

At ``p -> infinity`` the surface only radiates, ``S11 ~ p``, ``S22 ~ eta p``, ``S12 -> 2 - eta``; at
``p = 0`` the static stiffnesses ``S11 = S22 = 2 / (1 + 1 / eta^2)``, ``S12 = 2 / (1 + eta^2)``.

**In time** (as `stickslip.sbim.kernels` for antiplane; Geubelle and Rice, 1995, write the same with
their own kernels), with ``omega = k c_s`` and each ``S(p) = S(0) + r p - p h(p)``, ``r`` = 1, ``eta``
and 0::

    sigma_xy = -(mu / c_s) V_x - mu k S11(0) U_x + mu k int_0^t h11(omega t') V_x(t - t') dt'
               + i mu k [S12(0) U_y - int_0^t h12(omega t') V_y(t - t') dt'],
    sigma_yy = -eta (mu / c_s) V_y - mu k S22(0) U_y + mu k int_0^t h22(omega t') V_y(t - t') dt'
               - i mu k [S12(0) U_x - int_0^t h12(omega t') V_x(t - t') dt'].

``h(p) = (S(0) + r p - S(p)) / p`` is analytic off the segment ``[-i eta, i eta]`` where ``a`` and ``b``
have their branch cuts; the Bromwich integral folded onto that segment gives, with ``J(y)`` the jump of
``h`` across it at ``p = i y`` and ``c = (S(0) - S_left(0)) / 2`` the half residue of its left side at
``p = 0`` (``S(0)`` for ``h11`` and ``h22``, 0 for ``h12``)::

    h(T) = c + (1 / pi) int_0^eta Re[J(y) e^{i y T}] dy,
    A(T) = int_0^T h = c T + (1 / pi) int_0^eta Re[J(y) (e^{i y T} - 1) / (i y)] dy,

finite integrals computed by Gauss-Legendre points on ``[0, 1]`` and ``[1, eta]`` with the square-root
ends mapped away. The same folding gives the antiplane kernel's closed form (a check in the tests).
``A(infinity) = r``: the memory undoes the radiation damping, leaving the static stiffness.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from ..errors import ParameterError
from ..quantities.sbim import SBIM

__all__ = ["wave_speed_ratio", "static_stiffness", "inplane_stiffness", "inplane_kernels",
           "inplane_kernel_integrals", "inplane_step_weights", "inplane_truncation", "hann_taper", "kernel_table",
           "KERNEL_NAMES"]

#: The three kernels' names, in the order `inplane_kernels` returns them.
KERNEL_NAMES = ("h11", "h22", "h12")

_CHUNK = 1 << 20  # points x times per block of the quadrature


def wave_speed_ratio(poisson: float) -> float:
    """``eta = c_p / c_s = sqrt(2 (1 - nu) / (1 - 2 nu))`` in plane strain."""
    nu = SBIM.check("poisson", poisson)
    return math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu))


def _ab(p: np.ndarray, eta: float) -> tuple[np.ndarray, np.ndarray]:
    """``a, b`` with ``Re > 0`` for ``Re p > 0`` (cuts on the imaginary segments ``|y| < eta``, ``< 1``)."""
    p = np.asarray(p, dtype=complex)
    return p * np.sqrt(1.0 / eta**2 + 1.0 / p**2), p * np.sqrt(1.0 + 1.0 / p**2)


def _stiffness(a, b, p, eta):
    ab1 = a * b + 1.0
    D = 1.0 + (1.0 + p * p) / eta**2
    return a * ab1 / D, b * ab1 / D, 2.0 - ab1 / D


def inplane_stiffness(p, poisson: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``S11, S22, S12`` at complex ``p`` with ``Re p > 0`` (module docstring)."""
    eta = wave_speed_ratio(poisson)
    p = np.asarray(p, dtype=complex)
    if p.size == 0 or not np.all(np.isfinite(p)) or np.any(p.real <= 0.0):
        raise ParameterError("p", "values" if p.size > 1 else p, "finite complex numbers with a positive real part")
    a, b = _ab(p, eta)
    return _stiffness(a, b, p, eta)


def static_stiffness(poisson: float) -> tuple[float, float, float]:
    """``S11(0), S22(0), S12(0)``."""
    return _static(wave_speed_ratio(poisson))


def _cut(eta: float, T_max: float):
    """Points ``y`` and weights on ``[0, eta]`` and the jumps ``J`` of the three kernels there."""
    panels = 1 + int(eta * T_max / 4.0)  # a phase of at most 4 (times pi/2) across a panel of 24 points
    g, w = np.polynomial.legendre.leggauss(24)
    u = ((np.arange(panels)[:, None] + (g[None, :] + 1.0) / 2.0) / panels).ravel()  # composite, on [0, 1]
    wu = np.tile(w / (2.0 * panels), panels)
    theta = u * math.pi / 2.0  # y = sin(theta) on [0, 1]
    y = [np.sin(theta)]
    wy = [wu * math.pi / 2.0 * np.cos(theta)]
    if eta > 1.0:
        phi = u * math.pi  # y = (1 + eta) / 2 - (eta - 1) / 2 cos(phi) on [1, eta]
        y.append((1.0 + eta) / 2.0 - (eta - 1.0) / 2.0 * np.cos(phi))
        wy.append(wu * math.pi * (eta - 1.0) / 2.0 * np.sin(phi))
    y, wy = np.concatenate(y), np.concatenate(wy)
    p = 1j * y
    a_r = np.sqrt(np.maximum(1.0 - (y / eta) ** 2, 0.0)).astype(complex)
    b_r = np.where(y < 1.0, np.sqrt(np.abs(1.0 - y * y)), 1j * np.sqrt(np.abs(y * y - 1.0)))
    b_l = np.where(y < 1.0, -b_r, b_r)
    right = _stiffness(a_r, b_r, p, eta)
    left = _stiffness(-a_r, b_l, p, eta)
    J = [(sl - sr) / p for sl, sr in zip(left, right)]
    return y, wy, J


def _fold(eta: float, T: np.ndarray, integral: bool) -> np.ndarray:
    s = _static(eta)
    c = np.array([s[0], s[1], 0.0])
    y, wy, J = _cut(eta, float(T.max()) if T.size else 0.0)
    out = np.empty((3, T.size))
    flat = T.ravel()
    block = max(1, _CHUNK // y.size)
    Jw = np.stack(J) * wy / math.pi  # (3, points)
    for lo in range(0, flat.size, block):
        t = flat[lo:lo + block, None]
        if integral:
            phase = (np.sin(y * t) + 2j * np.sin(y * t / 2.0) ** 2) / y  # (e^{iyT} - 1) / (i y)
        else:
            phase = np.exp(1j * y * t)
        out[:, lo:lo + block] = np.real(phase @ Jw.T).T + (c[:, None] * t[None, :, 0] if integral else c[:, None])
    return out.reshape((3,) + T.shape)


def _static(eta: float) -> tuple[float, float, float]:
    s = 2.0 / (1.0 + 1.0 / eta**2)
    return s, s, 2.0 / (1.0 + eta**2)


def _times(T) -> np.ndarray:
    try:
        T = np.asarray(T, dtype=float)
    except (TypeError, ValueError):
        T = np.asarray(np.nan)
    if T.size == 0 or not np.all(np.isfinite(T)) or np.any(T < 0) or np.any(T > 1e5) or T.size > 1 << 24:
        raise ParameterError("T", "values" if T.size > 1 else T, "finite dimensionless times 0 <= omega t <= 1e5 "
                             "(at most 2^24 of them)")
    return T


def inplane_kernels(T, poisson: float) -> np.ndarray:
    """``h11, h22, h12`` at the dimensionless times ``T = k c_s t`` (``(3,) + shape``)."""
    return _fold(wave_speed_ratio(poisson), _times(T), integral=False)


def inplane_kernel_integrals(T, poisson: float) -> np.ndarray:
    """``A = int_0^T h`` of ``h11, h22, h12`` (``(3,) + shape``)."""
    return _fold(wave_speed_ratio(poisson), _times(T), integral=True)


#: Spacing of the table's own points in ``T`` when the multiples asked are denser (a cubic spline between).
TABLE_SPACING = 0.02


@functools.lru_cache(maxsize=4)
def kernel_table(poisson: float, T1: float, reach: int) -> np.ndarray:
    """``h11, h22, h12`` at ``T = j T1``, ``j = 0 .. reach`` (``(3, reach + 1)``, read-only), shared by the
    run's weights and its stability check: computed at each multiple if they are few or sparse, else at
    points ``TABLE_SPACING`` apart and interpolated by a cubic spline (1e-7 of ``h(0)``: the tests)."""
    from scipy.interpolate import CubicSpline

    eta = wave_speed_ratio(poisson)
    T = T1 * np.arange(reach + 1, dtype=float)
    if reach <= 4096 or T1 >= TABLE_SPACING:
        out = _fold(eta, T, integral=False)
    else:
        knots = np.linspace(0.0, T[-1], int(math.ceil(T[-1] / TABLE_SPACING)) + 1)
        out = CubicSpline(knots, _fold(eta, knots, integral=False), axis=1)(T)
    out.setflags(write=False)
    return out


def hann_taper(j: np.ndarray, window: int) -> np.ndarray:
    """``(1 + cos(pi j / window)) / 2``: the in-plane memory's weights fade over the kept window instead
    of stopping at its end (a kernel cut short makes the free surface's Rayleigh mode grow slowly,
    `stickslip.sbim.stability`; faded, it does not at ``nu <= 0.3``)."""
    return 0.5 + 0.5 * np.cos(math.pi * np.asarray(j, dtype=float) / window)


def inplane_step_weights(poisson: float, T1: float, dt: float, counts: np.ndarray,
                         windows: np.ndarray) -> np.ndarray:
    """``(3, sum(counts))``: for mode ``m`` (``omega_m = m omega_1``, ``T1 = omega_1 dt``) and each of its
    ``counts[m]`` past steps ``j``, the scheme's weights ``dt h(T1 m (j + 1))`` of ``h11, h22, h12`` (each
    step's displacement taken at its end, as `stickslip.sbim.kernels.ragged_step_weights`) faded by
    `hann_taper` over the mode's ``windows[m]`` steps, one mode after another; the uniform mode keeps
    none. Every ``T`` is a multiple of ``T1``: ``h`` is computed once at each multiple needed."""
    counts = np.asarray(counts, dtype=np.int64)
    windows = np.asarray(windows, dtype=np.int64)
    m = np.arange(counts.size)
    reach = int((m * (windows + 1)).max()) if counts.size else 0  # as the stability check's table
    if (reach * T1 > 1e5 or counts.sum() > (1 << 27) or np.any(counts[:1] > 0) or np.any(counts < 0)
            or windows.shape != counts.shape or np.any(windows < counts)):
        raise ParameterError("counts", f"{counts.size} modes", "a history reaching at most omega t = 1e5, 2^27 numbers "
                             "in all, none for the uniform mode, within each mode's window")
    h = kernel_table(poisson, T1, reach)
    parts = [dt * h[:, mm * np.arange(1, n + 1)] * hann_taper(np.arange(n), w)
             for mm, n, w in zip(m, counts, windows) if n > 0]
    return np.concatenate(parts, axis=1) if parts else np.zeros((3, 0))


def inplane_truncation(poisson: float, history_periods: float) -> float:
    """The largest part of a kernel's integral left out beyond ``eta = history_periods`` shear periods,
    in units of the radiation damping ``mu / c_s`` (``|1 - A11|``, ``|c_p / c_s - A22| c_s / c_p``,
    ``|A12|``)."""
    eta = wave_speed_ratio(poisson)
    T = np.array([2.0 * math.pi * SBIM.check("history_periods", history_periods)])
    A = _fold(eta, T, integral=True)[:, 0]
    return float(max(abs(1.0 - A[0]), abs(eta - A[1]) / eta, abs(A[2])))

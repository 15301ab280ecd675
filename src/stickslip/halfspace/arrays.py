"""Validators for arrays of parameters (the scalar ones live in `stickslip.validation`)."""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError


def real_array(name: str, value) -> np.ndarray:
    """``value`` as a float array; every entry must be a finite real number."""
    try:
        arr = np.asarray(value)
    except Exception as exc:  # pragma: no cover - exotic inputs
        raise ParameterError(name, value, "a finite real number or array of them") from exc
    if arr.dtype == bool or not (np.issubdtype(arr.dtype, np.integer) or np.issubdtype(arr.dtype, np.floating)):
        raise ParameterError(name, value, "a finite real number or array of them")
    arr = arr.astype(float)
    bad = ~np.isfinite(arr)
    if bad.any():
        raise ParameterError(name, float(arr[bad].flat[0]), "a finite real number")
    return arr


def array_in(name: str, value, lo: float, hi: float, *, lo_open: bool, hi_open: bool, allowed: str) -> np.ndarray:
    """A float array whose every entry lies between ``lo`` and ``hi``."""
    arr = real_array(name, value)
    bad = (arr <= lo if lo_open else arr < lo) | (arr >= hi if hi_open else arr > hi)
    if bad.any():
        raise ParameterError(name, float(arr[bad].flat[0]), allowed)
    return arr


def cbar_array(value, name: str = "c") -> np.ndarray:
    """Scaled wave speed ``c/c2``: subsonic and travelling to the left, ``-1 < c < 0``."""
    return array_in(name, value, -1.0, 0.0, lo_open=True, hi_open=True,
                    allowed="in (-1, 0) (subsonic wave, c < 0 in the paper's convention)")


#: The largest period ``b`` (in stick lengths) of a wave's fields: the stick zone, ``1/b`` of
#: the period, must hold 10 of the at most 1e7 interface points a field evaluation takes.
MAX_B = 1e6
#: The largest period of the closed forms (the inverse and direct problems): ``D`` grows like
#: ``b^2`` and leaves double range near 1e154.
MAX_B_ALGEBRA = 1e100
#: The largest friction coefficient: measured ones stay below about 2; the closed forms are
#: checked up to 50.
MAX_MU = 100.0

#: Largest v* = V*/c2 accepted: by [26] v* = cbar nu (tau*_yy/G)/2, under a quarter of the remote
#: strain, which linear elasticity keeps far below 1 (1e308 overflowed the fields to NaN).
MAX_V_STAR = 1.0


def v_star_at_most(vs: float) -> float:
    """``vs`` if it is at most ``MAX_V_STAR``, else a `ParameterError` naming ``v_star``."""
    if vs > MAX_V_STAR:
        raise ParameterError("v_star", vs, f"at most {MAX_V_STAR:g} (v* = cbar nu (tau*_yy/G)/2 by [26]: under a "
                             "quarter of the remote strain, far below 1 in linear elasticity)")
    return vs


def b_array(value, name: str = "b", most: float = MAX_B_ALGEBRA) -> np.ndarray:
    """Period ``b`` in units of the stick length ``a = 1``: in ``(1, most]``."""
    why = "a shorter stick zone is not resolved" if most <= MAX_B else "D ~ b^2 leaves double range"
    return array_in(name, value, 1.0, most, lo_open=True, hi_open=False,
                    allowed=f"in (1, {most:g}] (period in units of the stick length a = 1; {why})")

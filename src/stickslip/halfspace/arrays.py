"""Checks of the half-space's parameters that are numbers or arrays (ranges declared in
`stickslip.quantities.HALFSPACE`)."""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError
from ..quantities import HALFSPACE as Q

#: The largest period ``b`` (in stick lengths) of a wave's fields: the stick zone, ``1/b`` of the
#: period, must hold 10 of the at most 1e7 interface points a field evaluation takes.
MAX_B = 1e6
#: The largest period of the closed forms (the inverse and direct problems), declared.
MAX_B_ALGEBRA = Q["b"].range.hi
#: The largest friction coefficient, declared.
MAX_MU = Q["mu"].range.hi
#: Largest v* = V*/c2, declared: by [26] v* = cbar nu (tau*_yy/G)/2, under a quarter of the remote
#: strain, which linear elasticity keeps far below 1 (1e308 overflowed the fields to NaN).
MAX_V_STAR = Q["v_star"].range.hi


def real_array(name: str, value) -> np.ndarray:
    """``value`` as a float array of the declared quantity ``name``."""
    return Q[name].check_array(value)


def cbar_array(value, name: str = "c") -> np.ndarray:
    """Scaled wave speed ``c/c2``: subsonic and travelling to the left, ``-1 < c < 0``."""
    return Q["cbar"].check_array(value, name)


def v_star_at_most(vs: float) -> float:
    """``vs`` checked as ``v_star``."""
    return Q.check("v_star", vs)


def b_array(value, name: str = "b", most: float = MAX_B_ALGEBRA) -> np.ndarray:
    """Period ``b`` in units of the stick length ``a = 1``, at most ``most`` (`MAX_B` for fields)."""
    arr = Q["b"].check_array(value, name)
    if most < MAX_B_ALGEBRA and (arr > most).any():
        raise ParameterError(name, float(arr[arr > most].flat[0]), f"in (1, {most:g}] for the fields (the stick "
                             f"zone, 1/b of the period, must hold 10 of the at most 1e7 interface points)")
    return arr

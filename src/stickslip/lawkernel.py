"""Friction laws compiled with numba, for the compiled flows of laws that are not affine.

A compiled law is two C callbacks of one signature, ``mu(v_r, a, b, c)`` and its derivative
``dmu/dv_r(v_r, a, b, c)``, of the signed slip velocity and three numbers of the law
(`compiled` gives ``(mu, slope, (a, b, c))`` for a `stickslip.friction` law; it lives here, not on
the laws, so that the friction module, whose code the FE campaigns' fingerprint covers, is
untouched by it). Being C callbacks of one type, every law
runs through the same compiled integrator, compiled once and cached on disk, where numba functions
passed as arguments would have it compiled again for each law in each process. A user's law, a
Python function ``mu(v_r)``, is compiled when numba can compile it for one float (numpy and math
functions, plain arithmetic); its slope is then a central difference, as `UserLaw.slope` takes it.
"""

from __future__ import annotations

import hashlib
import math
import weakref

import numpy as np
from numba import cfunc, njit, types
from numba.core.errors import NumbaError

from .friction import FrictionLaw, Stribeck, UserLaw

__all__ = ["LAW", "compiled", "stribeck_mu", "stribeck_slope", "user_law"]

#: The signature of a compiled law and of its slope: ``(v_r, a, b, c) -> float``.
LAW = types.float64(types.float64, types.float64, types.float64, types.float64)


@cfunc(LAW, cache=True)
def stribeck_mu(v_r, fs, fd, vs):
    """``mu = fd + (fs - fd) exp(-|v_r| / vs)``."""
    return fd + (fs - fd) * math.exp(-abs(v_r) / vs)


@cfunc(LAW, cache=True)
def stribeck_slope(v_r, fs, fd, vs):
    slope = -(fs - fd) / vs * math.exp(-abs(v_r) / vs)
    return slope if v_r > 0 else -slope


def user_law(mu):
    """``(mu, slope)`` callbacks for a user's function ``mu`` compiled by numba (``a`` of the three
    numbers is the relative step of the slope's central difference, taken on the side of
    ``v_r = 0`` the slip is on); None when numba cannot compile ``mu`` for one float (the flows
    then stay in Python). Where ``mu`` raises (a division by zero too) the callbacks give NaN:
    the compiled flows stop there as at a coefficient out of range."""
    try:
        fn = njit(types.float64(types.float64))(mu)
    except (NumbaError, TypeError, ValueError, NotImplementedError):
        return None

    @cfunc(LAW)
    def value(v_r, step, b, c):
        try:
            return fn(v_r)
        except Exception:  # noqa: BLE001 - whatever the user's function raises: no value (the run stops there)
            return math.nan

    @cfunc(LAW)
    def slope(v_r, step, b, c):
        h = step * max(1.0, abs(v_r))
        lo = max(v_r - h, 0.5 * v_r) if v_r > 0 else v_r - h
        hi = min(v_r + h, 0.5 * v_r) if v_r < 0 else v_r + h
        try:
            return (fn(hi) - fn(lo)) / (hi - lo)
        except Exception:  # noqa: BLE001
            return math.nan

    return value, slope


_USER: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()  # a user's function -> {its numbers: callbacks}


def _numbers(mu) -> tuple:
    """The numbers (and arrays) ``mu`` reads from its globals and closure: numba freezes them when it
    compiles ``mu``, so the callbacks are made again when one of them changes (a global set in a
    loop of runs), as the Python path would read it afresh."""
    found = []
    names = getattr(getattr(mu, "__code__", None), "co_names", ())
    scope = getattr(mu, "__globals__", {})
    cells = [c.cell_contents for c in (getattr(mu, "__closure__", None) or ()) if _readable(c)]
    for value in [scope.get(n) for n in names] + cells:
        if isinstance(value, (bool, int, float, complex, np.number)):
            found.append(value)
        elif isinstance(value, np.ndarray):
            found.append((value.shape, value.dtype.str, hashlib.sha256(value.tobytes()).hexdigest()))
    return tuple(found)


def _readable(cell) -> bool:
    try:
        cell.cell_contents
    except ValueError:  # an empty cell
        return False
    return True


def compiled(law: FrictionLaw):
    """``(mu, slope, (a, b, c))`` of ``law`` compiled, for the compiled flows of laws that are not
    affine; None if it has none (its flows run in Python): the Stribeck law, and a `UserLaw` whose
    function numba compiles (once per function)."""
    if isinstance(law, Stribeck):
        return stribeck_mu, stribeck_slope, (law.fs, law.fd, law.vs)
    if isinstance(law, UserLaw):
        key = _numbers(law.mu)
        try:
            made = _USER.setdefault(law.mu, {})
        except TypeError:  # not weakly referable: compiled every time
            made = {}
        if key not in made:
            made[key] = user_law(law.mu)
        pair = made[key]
        return None if pair is None else (*pair, (law.step, 0.0, 0.0))
    return None

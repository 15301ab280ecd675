"""Small validators: each checks one named value and raises `ParameterError`."""

from __future__ import annotations

import math
import os
import pathlib
import sys
from numbers import Real

from .errors import ParameterError


def subnormal(value: float) -> bool:
    """``value`` is a non-zero float below the smallest normal number (2.2e-308) in size."""
    return isinstance(value, float) and value != 0.0 and abs(value) < sys.float_info.min


def finite(name: str, value) -> float:
    """Return ``value`` as float; it must be a finite real number, zero or normal (a subnormal
    number, below 2.2e-308 in size, has lost digits: 1e-320 as a density or a mass made
    divisions by zero and infinite frequencies further on)."""
    if isinstance(value, bool) or not isinstance(value, Real):
        raise ParameterError(name, value, "a finite real number")
    value = float(value)
    if not math.isfinite(value):
        raise ParameterError(name, value, "a finite real number")
    if subnormal(value):
        raise ParameterError(name, value, f"a finite real number, zero or at least {sys.float_info.min:.3g} in size "
                             "(this one is subnormal)")
    return value


def positive(name: str, value) -> float:
    """A finite number > 0."""
    v = finite(name, value)
    if v <= 0.0:
        raise ParameterError(name, v, "> 0")
    return v


def nonnegative(name: str, value) -> float:
    """A finite number >= 0."""
    v = finite(name, value)
    if v < 0.0:
        raise ParameterError(name, v, ">= 0")
    return v


def in_range(name: str, value, lo: float, hi: float, *, lo_open=False, hi_open=False) -> float:
    """A finite number in the interval between ``lo`` and ``hi``."""
    v = finite(name, value)
    below = v <= lo if lo_open else v < lo
    above = v >= hi if hi_open else v > hi
    if below or above:
        left, right = ("(" if lo_open else "["), (")" if hi_open else "]")
        raise ParameterError(name, v, f"in {left}{lo:g}, {hi:g}{right}")
    return v


def greater_than(name: str, value, bound: float, meaning: str = "") -> float:
    """A finite number > ``bound`` (``meaning`` says what the parameter is, for the message)."""
    v = finite(name, value)
    if v <= bound:
        raise ParameterError(name, v, f"> {bound:g}" + (f" ({meaning})" if meaning else ""))
    return v


def poisson_ratio(name: str, value) -> float:
    """Poisson's ratio of an isotropic elastic solid in plane strain: in [0, 0.5)."""
    return in_range(name, value, 0.0, 0.5, hi_open=True)


#: The radius ratios ``R*/R`` the annulus models accept. Below ``1 + 1e-4`` the reduced
#: coefficients [13] lose ``eps / (xi - 1)^2`` of their digits to cancellation (1e-8 at the
#: bound, 3 % at ``1 + 1e-7``); beyond 1e3 the annulus is a hole in an unbounded plate, which
#: the models are not written or checked for.
RADIUS_RATIO = (1.0 + 1e-4, 1e3)


def radius_ratio(name: str, value) -> float:
    """Outer over inner radius of an annulus, in `RADIUS_RATIO`."""
    v = finite(name, value)
    lo, hi = RADIUS_RATIO
    if not lo <= v <= hi:
        raise ParameterError(name, v, f"in [{lo:.4f}, {hi:g}] (outer radius / inner radius: thinner walls lose "
                             "the coefficients' digits, thicker ones are a hole in a plate)")
    return v


def at_least(name: str, value, bound: float, bound_name: str) -> float:
    """A finite number >= another parameter's value (the message names both)."""
    v = finite(name, value)
    if v < bound:
        raise ParameterError(name, v, f">= {bound_name} = {bound:g}", also=(bound_name,))
    return v


def positive_int(name: str, value) -> int:
    """An integer >= 1 (an integral float such as ``3.0`` is accepted)."""
    if isinstance(value, bool) or not isinstance(value, Real) or not math.isfinite(value) \
            or int(value) != value or value < 1:
        raise ParameterError(name, value, "an integer >= 1")
    return int(value)


def count(name: str, value, most: int, what: str = "") -> int:
    """An integer from 1 to ``most`` (a size: samples, points, modes), refused up front when it
    would take more memory or time than any use needs."""
    try:
        v = positive_int(name, value)
    except ParameterError:
        v = most + 1
    if v > most:
        raise ParameterError(name, value, f"an integer from 1 to {most}" + (f" ({what})" if what else ""))
    return v


def _shown(value):
    """``value`` for a message: itself when short, else its type."""
    text = repr(value)
    return value if len(text) <= 60 else f"<{type(value).__name__}>"


def instance(name: str, value, kind, what: str):
    """``value`` if it is a ``kind`` (a class or a tuple of them), else a `ParameterError` saying
    ``what`` it must be (a model object passed where a number was meant, a number for a model)."""
    if not isinstance(value, kind):
        raise ParameterError(name, _shown(value), what)
    return value


def function(name: str, value):
    """``value`` if it can be called (a function of the user's), else a `ParameterError`."""
    if not callable(value):
        raise ParameterError(name, _shown(value), "a function (something callable)")
    return value


def _real(value):
    """``value`` as a float array; complex numbers refused (numpy would drop their imaginary parts with
    only a warning: a result computed from other numbers than those given)."""
    import numpy as np

    if np.iscomplexobj(value):
        raise TypeError("complex")
    return np.asarray(value, dtype=float)


def finite_array(name: str, value, ndim: int | None = None, empty: bool = False):
    """``value`` as a float array of finite numbers (of ``ndim`` dimensions, if given; non-empty
    unless ``empty``): text, None, complex numbers, nested lists of uneven length, NaN or infinities are
    refused."""
    import numpy as np

    try:
        array = _real(value)
    except (TypeError, ValueError, OverflowError):
        raise ParameterError(name, _shown(value), "an array of finite real numbers") from None
    if ndim is not None and array.ndim != ndim:
        raise ParameterError(name, _shown(value), f"an array of finite real numbers of {ndim} dimension"
                             f"{'s' if ndim != 1 else ''} (this one has {array.ndim})")
    if not empty and array.size == 0:
        raise ParameterError(name, _shown(value), "a non-empty array of finite real numbers")
    if not np.isfinite(array).all():
        raise ParameterError(name, _shown(value), "an array of finite real numbers (this one holds NaN or infinities)")
    return array


def real_array(name: str, value):
    """``value`` as a float array (any shape; NaN passes through, as numpy's functions take it): for
    the vectorised formulas, whose only bad input is one that is not real numbers at all (complex ones
    refused: numpy would drop their imaginary parts)."""
    try:
        return _real(value)
    except (TypeError, ValueError, OverflowError):
        raise ParameterError(name, _shown(value), "a real number or an array of them") from None


def special_kind(path) -> str | None:
    """What ``path`` is when it is neither a regular file nor absent: ``"a FIFO"``, ``"a device"``,
    ``"a socket"``, ``"a folder"``, ``"a dangling symbolic link (to TARGET)"``; None for a regular
    file (or a link to one) and for a name that does not exist. Reading a FIFO or a device such as
    /dev/zero waits or reads for ever, and writing over one replaces the device: both are refused
    before any work."""
    import stat

    if not isinstance(path, (str, os.PathLike)):
        raise ParameterError("path", path, "a path (str or os.PathLike)")
    path = pathlib.Path(path)
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        if os.path.islink(path):
            return f"a dangling symbolic link (to {os.readlink(path)}, which does not exist)"
        return None
    except OSError:  # a loop of links, a name too long, a part that is a file: the callers' own checks say it
        return None
    if stat.S_ISREG(mode):
        return None
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else "not a regular file"


def regular_input(name: str, path, what: str = "a readable file") -> pathlib.Path:
    """``path`` if it is an existing regular file (or a link to one), else a `ParameterError`
    naming ``name`` and saying what the path is (a FIFO, a device, a folder, a dangling link,
    nothing): checked before opening it, which for a FIFO or /dev/zero would never end."""
    if not isinstance(path, (str, os.PathLike)):
        raise ParameterError(name, path, f"{what} (a path)")
    kind = special_kind(path)
    if kind is not None:
        raise ParameterError(name, str(path), f"{what}, a regular file (this is {kind})")
    return pathlib.Path(path)

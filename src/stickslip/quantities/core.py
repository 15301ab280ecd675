"""`Quantity`: one declared quantity (name, symbol, units, range, meaning), and `Domain`, the
quantities of one model.

A quantity's range is written as an interval, ``"(0, 1e15]"``: a round bracket leaves its end
out, a square one takes it in, ``inf`` is no bound. ``Quantity.check`` refuses, with a
`ParameterError` naming the parameter as the user typed it, anything that is not a finite
number in the range: text, booleans, NaN, infinities, subnormal numbers (below 2.2e-308 in
size, they have lost digits), and for an integer quantity anything not integral.
"""

from __future__ import annotations

import math
import re
import sys
from dataclasses import dataclass
from numbers import Real
from typing import Iterable

from ..errors import ParameterError

__all__ = ["Range", "Quantity", "Domain", "number"]

_INTERVAL = re.compile(r"^\s*([\[(])\s*([^,]+?)\s*,\s*([^,]+?)\s*([\])])\s*$")


def number(value: float) -> str:
    """A bound or a value for people: ``1e15`` not ``1e+15``, ``0.5``, ``1.0001``, ``2097152``."""
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, int) or (isinstance(value, float) and value.is_integer() and abs(value) < 1e16):
        digits = str(int(value))
        mantissa = digits.rstrip("0")
        zeros = len(digits) - len(mantissa)
        return f"{mantissa}e{zeros}" if zeros >= 4 and len(mantissa.lstrip("-")) == 1 else digits
    text = f"{value:.6g}"
    mantissa, _, exponent = text.partition("e")
    return mantissa + (f"e{int(exponent)}" if exponent else "")


def _subnormal(value: float) -> bool:
    return isinstance(value, float) and value != 0.0 and abs(value) < sys.float_info.min


@dataclass(frozen=True)
class Range:
    """An interval ``lo .. hi``; ``lo_open``/``hi_open`` leave an end out."""

    lo: float = -math.inf
    hi: float = math.inf
    lo_open: bool = True
    hi_open: bool = True

    @classmethod
    def parse(cls, text: str) -> "Range":
        """``"(0, 1e15]"`` -> ``Range(0, 1e15, lo_open=True, hi_open=False)``."""
        m = _INTERVAL.match(text)
        if m is None:
            raise ValueError(f"not an interval: {text!r}")
        left, lo, hi, right = m.groups()
        lo, hi = float(lo), float(hi)
        if not lo <= hi:
            raise ValueError(f"empty interval: {text!r}")
        return cls(lo, hi, left == "(" or math.isinf(lo), right == ")" or math.isinf(hi))

    def __contains__(self, value: float) -> bool:
        above = value > self.lo if self.lo_open else value >= self.lo
        below = value < self.hi if self.hi_open else value <= self.hi
        return above and below

    def text(self) -> str:
        """``> 0``, ``>= 0``, ``< 1``, ``in [0, 0.5)``, or ``finite`` for the whole line."""
        lo, hi = math.isinf(self.lo), math.isinf(self.hi)
        if lo and hi:
            return "finite"
        if hi:
            return f"{'>' if self.lo_open else '>='} {number(self.lo)}"
        if lo:
            return f"{'<' if self.hi_open else '<='} {number(self.hi)}"
        return f"in {'(' if self.lo_open else '['}{number(self.lo)}, {number(self.hi)}{')' if self.hi_open else ']'}"

    @property
    def interval(self) -> str:
        """The range as written in a declaration, ``(0, 1e15]``."""
        return f"{'(' if self.lo_open else '['}{number(self.lo)}, {number(self.hi)}{')' if self.hi_open else ']'}"


@dataclass(frozen=True)
class Quantity:
    """One quantity stickslip takes or gives.

    ``units`` is a UDUNITS-2 string (``"1"`` for a pure number, ``""`` for a label or a flag,
    which has none); a quantity of a scaled model in units of a scale (``R``, ``E``) writes
    that scale in ``scale`` and ``"1"`` in ``units``. ``range`` is the interval of the values
    the models accept (None: a result, not an input); ``why`` says where the model stops
    making sense beyond it. ``integer`` quantities are counts; ``choices`` lists the values of
    a label. ``standard_name`` is the CF standard name, where one exists.
    """

    name: str
    units: str
    meaning: str
    symbol: str = ""
    range: Range | None = None
    why: str = ""
    integer: bool = False
    choices: tuple[str, ...] = ()
    standard_name: str = ""
    scale: str = ""

    # -- validation ---------------------------------------------------------------------
    @property
    def allowed(self) -> str:
        """What a value must be, for a message — ``in (0, 1e15] kg (why)``."""
        if self.choices:
            return "one of " + ", ".join(self.choices)
        kind = "an integer " if self.integer else ""
        rng = self.range.text() if self.range is not None else "finite"
        text = f"{kind}{rng}" if rng != "finite" else (kind.strip() or "a finite real number")
        unit = self.scale or (self.units if self.units not in ("1", "") else "")
        if unit and rng != "finite":
            text += f" {unit}"
        return text + (f" ({self.why})" if self.why else "")

    def check(self, value, name: str | None = None):
        """``value`` as float (int for an integer quantity, str for a label) if it is allowed;
        else a `ParameterError` naming ``name`` (default: the quantity's own name)."""
        name = self.name if name is None else name
        if self.choices:
            if not isinstance(value, str) or value not in self.choices:
                raise ParameterError(name, value, self.allowed)
            return value
        if isinstance(value, bool) or not isinstance(value, Real):
            raise ParameterError(name, value, self.allowed if self.range is not None else "a finite real number")
        try:
            v = float(value)
        except OverflowError:  # an int beyond the float range
            raise ParameterError(name, value, self.allowed) from None
        if not math.isfinite(v):
            raise ParameterError(name, v, f"a finite real number, {self.allowed}" if self.range else
                                 "a finite real number")
        if _subnormal(v):
            raise ParameterError(name, v, f"a finite real number, zero or at least {sys.float_info.min:.3g} in size "
                                 f"(this one is subnormal), {self.allowed}")
        if self.integer and not v.is_integer():
            raise ParameterError(name, value, self.allowed)
        if self.range is not None and v not in self.range:
            raise ParameterError(name, int(v) if self.integer and abs(v) < 1e16 else v, self.allowed)
        return int(v) if self.integer else v

    def check_array(self, value, name: str | None = None):
        """``value`` as a float array (a number or any array-like) whose every entry is allowed."""
        import numpy as np

        name = self.name if name is None else name
        try:
            arr = np.asarray(value)
        except Exception:  # ragged lists and other shapes numpy cannot hold
            raise ParameterError(name, value, f"a number or an array of numbers, {self.allowed}") from None
        if arr.dtype == bool or arr.dtype.kind not in "iuf":
            raise ParameterError(name, value, f"a number or an array of numbers, {self.allowed}")
        arr = arr.astype(float)
        with np.errstate(invalid="ignore"):
            bad = ~np.isfinite(arr) | ((arr != 0) & (np.abs(arr) < sys.float_info.min))
            if self.range is not None:
                r = self.range
                bad |= (arr <= r.lo if r.lo_open else arr < r.lo) | (arr >= r.hi if r.hi_open else arr > r.hi)
            if self.integer:
                bad |= arr != np.round(arr)
        if bad.any():
            self.check(float(arr[bad].flat[0]), name)  # raises, with the first bad entry
        return arr

    def check_pair(self, value, name: str | None = None) -> tuple[float, float]:
        """Two components ``(x, y)``, each allowed (a point, a vector, a pair of stiffnesses)."""
        name = self.name if name is None else name
        try:
            x, y = value
        except (TypeError, ValueError):
            raise ParameterError(name, value, f"two numbers [x, y], each {self.allowed}") from None
        try:
            return self.check(x, name), self.check(y, name)
        except ParameterError:
            raise ParameterError(name, list(value) if isinstance(value, tuple) else value,
                                 f"two numbers [x, y], each {self.allowed}") from None

    def check_vector(self, value, name: str | None = None, sizes=(2, 3)) -> tuple:
        """Two or three components (of a plane body, of a solid: ``sizes``), each allowed."""
        name = self.name if name is None else name
        words = " or ".join({2: "two numbers [x, y]", 3: "three numbers [x, y, z]"}[n] for n in sizes)
        try:
            parts = list(value)
        except TypeError:
            raise ParameterError(name, value, f"{words}, each {self.allowed}") from None
        if len(parts) not in sizes:
            raise ParameterError(name, parts, f"{words}, each {self.allowed}")
        try:
            return tuple(self.check(x, name) for x in parts)
        except ParameterError:
            raise ParameterError(name, parts, f"{words}, each {self.allowed}") from None

    # -- descriptions -------------------------------------------------------------------
    def help(self, note: str = "") -> str:
        """The help of a command-line option: ``Mass m [kg], in (0, 1e15].`` plus ``note``."""
        head = self.meaning[:1].upper() + self.meaning[1:]
        sym = f" {self.symbol}" if self.symbol and self.symbol not in self.meaning.split() else ""
        unit = self.scale or self.units
        unit = f" [{unit}]" if unit not in ("", "1") else ""
        if self.choices:
            rng = ": " + ", ".join(self.choices)
        elif self.range is not None:
            rng = (", an integer " if self.integer else ", ") + self.range.text()
        else:
            rng = ""
        return f"{head}{sym}{unit}{rng}." + (f" {note}" if note else "")

    @property
    def cf_attrs(self) -> dict:
        """``units``, ``long_name`` (and ``standard_name``) of a variable holding this quantity."""
        attrs = {"long_name": self.meaning}
        if self.units:
            attrs["units"] = self.units
        if self.scale:
            attrs["scale"] = self.scale
        if self.standard_name:
            attrs["standard_name"] = self.standard_name
        return attrs


class Domain:
    """The quantities of one model, by name (``domain["mass"]``)."""

    def __init__(self, name: str, quantities: Iterable[Quantity], *, units: str = ""):
        self.name = name
        self.units = units  # what the model's units are, in words (for the docs)
        self.fallback: Domain | None = None  # the shared declarations (COMMON), for the names not declared here
        self._q: dict[str, Quantity] = {}
        for q in quantities:
            if q.name in self._q:
                raise ValueError(f"{name}: {q.name} declared twice")
            self._q[q.name] = q

    def __getitem__(self, name: str) -> Quantity:
        found = self.get(name)
        if found is None:
            raise KeyError(f"{name} is not declared in {self.name}")
        return found

    def __contains__(self, name: str) -> bool:
        return self.get(name) is not None

    def __iter__(self):
        return iter(self._q.values())

    def __len__(self) -> int:
        return len(self._q)

    def get(self, name: str) -> Quantity | None:
        """The declaration of ``name`` here, else in the fallback, else None."""
        found = self._q.get(name)
        return found if found is not None or self.fallback is None else self.fallback.get(name)

    def check(self, name: str, value, typed: str | None = None):
        """``self[name].check(value, typed)``: the value of parameter ``name``, named ``typed``."""
        return self[name].check(value, typed)

    def inputs(self) -> list[Quantity]:
        """The quantities with a range: the parameters a user gives."""
        return [q for q in self._q.values() if q.range is not None or q.choices]


def declare(name: str, units: str, meaning: str, rng: str | None = None, **more) -> Quantity:
    """A `Quantity` with its range written as an interval: ``declare("mass", "kg", "mass", "(0, 1e15]")``."""
    return Quantity(name, units, meaning, range=None if rng is None else Range.parse(rng), **more)

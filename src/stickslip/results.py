"""What every result object of stickslip can do, in one mixin (`Result`).

A result states its numbers with ``to_dict()`` (JSON-ready). From it the mixin makes

* a short ``repr``: the class and its first scalars, 4 significant digits;
* ``_repr_html_``: a table of every scalar with its units and meaning (Jupyter);
* a default ``to_xarray()``: scalars and lists of numbers as variables, text as attributes,
  with CF-style metadata (`stickslip.cf.finish`). Results with fields (trajectories, runs,
  waves) override it with their own dataset.

``MODEL`` names the vocabulary of units (`stickslip.vocabulary`): ``oscillator`` (SI),
``brake`` (the paper's scaled units) or ``halfspace``.
"""

from __future__ import annotations

import html
from typing import ClassVar

import numpy as np
import lazy_loader as lazy

from .cf import finish
from .errors import ParameterError
from .quantities import lookup

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["Result", "scalars"]


def scalars(data: dict, prefix: str = "") -> list[tuple[str, object]]:
    """``(dotted key, value)`` of the numbers, booleans and short texts of a nested dict."""
    if not isinstance(data, dict):
        shown = data if len(repr(data)) <= 60 else f"<{type(data).__name__}>"
        raise ParameterError("data", shown, "a dict (a result's to_dict())")
    if not isinstance(prefix, str):
        raise ParameterError("prefix", prefix, "a text (str) put before every key")
    out = []
    for key, value in data.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out += scalars(value, f"{name}.")
        elif isinstance(value, (bool, int, float, str, np.integer, np.floating, np.bool_)) or value is None:
            out.append((name, value))
    return out


def _short(value) -> str:
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value))
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return f"{float(value):.4g}"
    if isinstance(value, str):
        return repr(value if len(value) <= 40 else value[:37] + "...")
    return repr(value)


class Result:
    """Mixin: ``repr``, ``_repr_html_`` and a default ``to_xarray`` from ``to_dict``."""

    MODEL: ClassVar[str] = "common"
    #: Scalars shown in the repr (the first ones of ``to_dict``).
    REPR_FIELDS: ClassVar[int] = 6

    def to_dict(self) -> dict:
        raise NotImplementedError

    def __repr__(self) -> str:
        try:
            items = scalars(self.to_dict())
        except Exception:  # noqa: BLE001 - a repr never raises (a half-made object in a debugger)
            return f"<{type(self).__name__}>"
        shown = ", ".join(f"{k}={_short(v)}" for k, v in items[: self.REPR_FIELDS])
        more = f", ... ({len(items) - self.REPR_FIELDS} more)" if len(items) > self.REPR_FIELDS else ""
        return f"{type(self).__name__}({shown}{more})"

    def _repr_html_(self) -> str:
        rows = []
        for key, value in scalars(self.to_dict()):
            units, meaning = lookup(key.split(".")[-1], self.MODEL) or ("", "")
            rows.append("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in (
                key, _short(value).strip("'"), units, meaning)) + "</tr>")
        head = "<tr><th>quantity</th><th>value</th><th>units</th><th>meaning</th></tr>"
        return f"<table><caption>{html.escape(type(self).__name__)}</caption>{head}{''.join(rows)}</table>"

    def to_xarray(self) -> xr.Dataset:
        """The numbers of ``to_dict`` as a dataset: scalars as 0-d variables, lists of numbers
        along ``<name>_index``, texts as attributes."""
        data, attrs = {}, {}
        for key, value in self.to_dict().items():
            name = str(key)
            arr = np.asarray(value) if isinstance(value, (list, tuple, np.ndarray)) else None
            if isinstance(value, (bool, np.bool_)):
                data[name] = ((), np.int8(value))
            elif isinstance(value, (int, float, np.integer, np.floating)):
                data[name] = ((), value)
            elif arr is not None and arr.ndim == 1 and arr.dtype.kind in "iufb":
                data[name] = ((f"{name}_index",), arr)
            elif isinstance(value, str):
                attrs[name] = value
        ds = xr.Dataset(data, attrs=attrs)
        for name in ds.data_vars:
            ds[name].attrs["long_name"] = (lookup(name, self.MODEL) or (None, name.replace("_", " ")))[1]
        for dim in list(ds.dims):
            ds.coords[dim] = (dim, np.arange(ds.sizes[dim]), {"units": "1", "long_name": f"index of {dim[:-6]}"})
        return finish(ds, (type(self).__doc__ or type(self).__name__).strip().splitlines()[0], self.MODEL)

"""CF-style metadata for every dataset stickslip returns or writes.

`finish(ds, title, domain)` is the last step of every ``to_xarray`` and of every file the
command line or the report writes. It

* fills ``units`` and ``long_name`` of the variables and coordinates that do not state them,
  from the declarations of the model (`stickslip.quantities`);
* turns a scaled unit (``R``, ``E/M``, ``1/Omega``: not a UDUNITS string) into ``units = "1"``
  with the scale in a ``scale`` attribute;
* makes a one-dimensional, strictly monotone coordinate the index of its dimension;
* writes the global attributes ``Conventions``, ``title``, ``source`` (the stickslip
  version), ``history`` and ``references``, and the run's parameters as numbers.

State and regime codes carry ``flag_values`` and ``flag_meanings`` (see
`stickslip.contact.states`).
"""

from __future__ import annotations

import datetime
import re
from typing import Mapping

import numpy as np
import lazy_loader as lazy

from . import __version__
from .quantities import declared

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["CONVENTIONS", "SOURCE", "REFERENCES", "finish", "for_file", "from_file", "load_result", "is_udunits", "flag_attrs", "plain_attrs",
           "stamp"]

CONVENTIONS = "CF-1.10"
SOURCE = f"stickslip {__version__}"
REFERENCES = ("Friction-induced vibration and stick-slip waves: short survey and new results "
              "(the paper stickslip reproduces)")

# the units stickslip writes, as UDUNITS-2 symbols (a product of powers, or one quotient)
_SYMBOLS = {"1", "m", "s", "kg", "N", "Pa", "J", "W", "rad", "Hz", "K", "degree", "percent"}
_FACTOR = re.compile(r"^([A-Za-z]+|1)(\^?-?\d+)?$")


def is_udunits(units: str) -> bool:
    """Whether ``units`` is a product (and at most one quotient) of the SI symbols stickslip
    writes, in UDUNITS-2 syntax: ``m``, ``m s-1``, ``m/s``, ``N s/m``, ``1``, ``rad/s``."""
    if not isinstance(units, str) or not units.strip():
        return False
    parts = [p.strip() for p in units.split("/")]
    if len(parts) > 2 or any(not p for p in parts):
        return False
    for part in parts:
        for factor in part.split():
            m = _FACTOR.match(factor)
            if m is None or m.group(1) not in _SYMBOLS:
                return False
    return True


def _flag_word(meaning) -> str:
    """A flag meaning as CF spells one: letters, digits and ``_ - . + @`` only, no blanks
    ("bistable: steady sliding or stick-slip" -> ``bistable_steady_sliding_or_stick_slip``)."""
    word = re.sub(r"[^A-Za-z0-9_.+@-]+", "_", str(meaning)).replace("-", "_")
    return re.sub(r"_+", "_", word).strip("_")


def flag_attrs(codes: Mapping[str, int]) -> dict:
    """``flag_values`` (integers) and ``flag_meanings`` of a code variable, from ``{name: code}``."""
    return {"flag_values": np.asarray(list(codes.values()), dtype=np.int8),
            "flag_meanings": " ".join(_flag_word(k) for k in codes)}


def plain_attrs(params: Mapping, prefix: str = "") -> dict:
    """Flat netCDF attributes from a nested mapping: numbers stay numbers, booleans become
    0/1, nested mappings get ``prefix_`` names, ``None`` is left out."""
    out = {}
    for key, value in params.items():
        name = f"{prefix}{key}"
        if value is None:
            continue
        if isinstance(value, Mapping):
            out.update(plain_attrs(value, f"{name}_"))
        elif isinstance(value, (bool, np.bool_)):
            out[name] = int(value)
        elif isinstance(value, (np.integer, np.floating)):
            out[name] = value.item()
        elif isinstance(value, (list, tuple, np.ndarray)):
            arr = np.asarray(value)
            out[name] = arr.astype(int) if arr.dtype == bool else (arr if arr.dtype.kind in "iuf" else
                                                                   ", ".join(map(str, arr.ravel().tolist())))
        else:
            out[name] = value
    return out


def stamp(ds: xr.Dataset, what: str) -> xr.Dataset:
    """Append a line ``<UTC time> <what>`` to the ``history`` attribute (in place; returns ``ds``)."""
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    old = ds.attrs.get("history", "")
    ds.attrs["history"] = f"{old}\n{now} {what}" if old else f"{now} {what}"
    return ds


def _describe(name: str, var: xr.Variable, domain: str) -> None:
    attrs = var.attrs
    if "flag_values" in attrs:
        attrs["flag_values"] = np.asarray(attrs["flag_values"], dtype=np.int8) if not isinstance(
            attrs["flag_values"], str) else np.asarray(attrs["flag_values"].split(), dtype=np.int8)
        attrs.pop("units", None)  # a flag variable has no units (CF 3.5)
        if "long_name" not in attrs:
            known = declared(name, domain)
            attrs["long_name"] = known.meaning if known else name.replace("_", " ")
        return
    known = declared(name, domain)
    if known is not None:
        attrs.setdefault("long_name", known.meaning)
        if var.dtype.kind in "iufcb" and known.units:
            attrs.setdefault("units", known.units)
        if known.standard_name and attrs.get("units") == known.units:
            attrs.setdefault("standard_name", known.standard_name)
    if var.dtype.kind in "US O":
        attrs.pop("units", None)  # labels are not measured
        return
    units = attrs.get("units")
    if isinstance(units, str) and not is_udunits(units):
        attrs["scale"] = units
        attrs["units"] = "1"
        if "long_name" in attrs and f"units of {units}" not in attrs["long_name"]:
            attrs["long_name"] = f"{attrs['long_name']} (in units of {units})"


def _integer_codes(ds: xr.Dataset) -> xr.Dataset:
    """Codes stored as floats (NaN: none) become ``int8``, NaN becoming a ``none`` code: -1,
    or one below the smallest code where -1 already means something (a contact mode's
    reverse slip)."""
    for name in list(ds.variables):
        var = ds[name]
        if "flag_values" not in var.attrs or var.dtype.kind != "f":
            continue
        attrs = dict(var.attrs)
        values = np.asarray(var.values)
        if np.isnan(values).any():
            flags = np.atleast_1d(np.asarray(attrs["flag_values"], dtype=np.int8))
            meanings = dict(zip(flags.tolist(), str(attrs["flag_meanings"]).split()))
            none = next((c for c, m in meanings.items() if m == "none"),
                        -1 if -1 not in meanings else int(flags.min()) - 1)
            values = np.where(np.isnan(values), none, values)
            if none not in meanings:
                attrs["flag_values"] = np.concatenate([[none], flags]).astype(np.int8)
                attrs["flag_meanings"] = "none " + str(attrs["flag_meanings"])
        ds[name] = (var.dims, values.astype(np.int8), attrs)
    return ds


def _index_dimensions(ds: xr.Dataset) -> xr.Dataset:
    for dim in list(ds.dims):
        if dim in ds.coords:
            continue
        for name, coord in ds.coords.items():
            if coord.dims != (dim,) or coord.dtype.kind not in "iuf" or coord.size < 2:
                continue
            step = np.diff(coord.values.astype(float))
            if np.all(np.isfinite(coord.values)) and (np.all(step > 0) or np.all(step < 0)):
                ds = ds.swap_dims({dim: name})
                break
    return ds


def for_file(ds: xr.Dataset) -> xr.Dataset:
    """``ds`` as it is written to a netCDF file (CF 1.10, as compliance-checker reads it): a
    coordinate variable gets no ``_FillValue`` (CF 2.5.1), and a dimension indexed by labels
    (``kind``: stick, slip, ...) is indexed by their numbers instead, the labels kept beside them
    as an auxiliary coordinate ``<dim>_name`` (a coordinate variable must be numeric and monotone).
    The arrays are shared, not copied."""
    ds = ds.copy()
    for dim in list(ds.dims):
        if dim in ds.coords and ds[dim].dtype.kind in "USO":
            labels = ds[dim]
            ds = ds.assign_coords({f"{dim}_name": (dim, labels.values.astype(str), {
                "long_name": labels.attrs.get("long_name", dim)})})
            ds = ds.drop_vars(dim).assign_coords({dim: (dim, np.arange(labels.size, dtype=np.int32), {
                "long_name": f"{labels.attrs.get('long_name', dim)} number (its name in {dim}_name)", "units": "1"})})
    for name in ds.coords:
        if ds[name].dims == (name,) or name.endswith("_name"):
            ds[name].encoding["_FillValue"] = None
    return ds


def from_file(ds: xr.Dataset) -> xr.Dataset:
    """The dataset `for_file` wrote, as it was: dimensions indexed by their labels again."""
    for name in [n for n in ds.coords if str(n).endswith("_name") and str(n)[:-5] in ds.dims]:
        dim = str(name)[:-5]
        labels = ds[name]
        ds = ds.drop_vars([name, dim]).assign_coords({dim: (dim, labels.values.astype(str),
                                                            {"long_name": labels.attrs.get("long_name", dim)})})
    return ds


def load_result(path, group: str | None = None) -> xr.Dataset:
    """A netCDF file stickslip wrote, loaded as its producer made it: ``kind`` and the other
    dimensions the file indexes by number are indexed by their labels again
    (``ds.fraction.sel(kind="stick")``). ``group="checkpoint"`` reads a run's state."""
    return from_file(xr.load_dataset(path, group=group))


def finish(ds: xr.Dataset, title: str, domain: str = "common", *, params: Mapping | None = None,
           history: str | None = None) -> xr.Dataset:
    """``ds`` with CF-style metadata (a new dataset; the arrays are shared, not copied).

    ``domain`` picks the declarations: ``oscillator`` (SI units), ``brake`` (the annulus,
    dimensionless: time ``Omega t``, lengths in ``R``), ``halfspace`` (scaled by ``G``, ``c2``
    and the stick length) or ``common``. ``params`` are stored as attributes (numbers);
    ``history`` is appended to the ``history`` attribute with the time.
    """
    ds = _integer_codes(ds.copy())
    for name, var in ds.variables.items():
        var.attrs = dict(var.attrs)
        _describe(name, var, domain)
    ds = _index_dimensions(ds)
    ds.attrs = {**plain_attrs(ds.attrs), **plain_attrs(params or {})}
    model = ds.attrs.get("source")
    if model is not None and model != SOURCE:  # a model's own note on how the data were made
        ds.attrs["comment"] = f"{ds.attrs['comment']}; {model}" if "comment" in ds.attrs else model
    ds.attrs.update({"Conventions": CONVENTIONS, "title": title, "source": SOURCE, "references": REFERENCES})
    if history is not None or "history" not in ds.attrs:
        stamp(ds, history or f"created by {SOURCE}")
    return ds

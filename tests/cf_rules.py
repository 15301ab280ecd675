"""The CF-style rules every dataset and file of stickslip must follow (issue 10), checked
independently of `stickslip.cf` (its own list of accepted unit strings, its own reading).

`problems(ds)` returns the broken rules of one dataset as sentences; `file_problems(path)`
opens a netCDF file or a Zarr store first (a store must be consolidated).
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import xarray as xr

import stickslip

#: Every unit string stickslip may write: UDUNITS-2 spellings of SI units, "1" for dimensionless.
UNITS = {"1", "m", "s", "kg", "N", "Pa", "J", "rad", "Hz", "m/s", "m s-1", "1/s", "s-1", "rad/s", "N/m",
         "N s/m", "J/kg", "m2", "Pa s", "kg/m3", "N s3/m3", "J/m", "Pa/m", "kg/m2"}
_CODE_NAMES = re.compile(r"(^|_)(state|regime)$")
_REPR = re.compile(r"^\s*[\[{(].*[:,].*[\]})]\s*$|^(True|False|None)$")


def problems(ds: xr.Dataset, where: str = "") -> list[str]:
    out = []
    at = f"{where}: " if where else ""
    a = ds.attrs
    if not str(a.get("Conventions", "")).startswith("CF-"):
        out.append(f"{at}no Conventions attribute")
    for key in ("title", "history"):
        if not str(a.get(key, "")).strip():
            out.append(f"{at}no {key} attribute")
    if f"stickslip {stickslip.__version__}" not in str(a.get("source", "")):
        out.append(f"{at}source does not name the stickslip version: {a.get('source')!r}")
    for key, value in a.items():
        if isinstance(value, str) and _REPR.match(value):
            out.append(f"{at}attribute {key} is a Python repr, not numbers: {value[:40]!r}")
        if isinstance(value, (bool, np.bool_)) or value is None:
            out.append(f"{at}attribute {key} is {value!r}")
    for name, var in ds.variables.items():
        va, kind = var.attrs, var.dtype.kind
        if not str(va.get("long_name", "")).strip():
            out.append(f"{at}{name} has no long_name")
        flag = "flag_values" in va
        if flag:
            values = np.atleast_1d(np.asarray(va["flag_values"]))
            if kind not in "iu" or values.dtype.kind not in "iu":
                out.append(f"{at}{name} holds codes but is {var.dtype}, flag_values {values.dtype}")
            if len(str(va.get("flag_meanings", "")).split()) != values.size:
                out.append(f"{at}{name}: flag_meanings do not match flag_values")
        elif kind in "iufcb":
            if _CODE_NAMES.search(str(name)):
                out.append(f"{at}{name} holds codes without flag_values/flag_meanings")
            if va.get("units") not in UNITS:
                out.append(f"{at}{name} has units {va.get('units')!r}, not a UDUNITS string")
    for dim in ds.dims:
        if dim in ds.indexes:
            values = ds.indexes[dim]
            if not values.is_unique:
                out.append(f"{at}coordinate {dim} repeats values")
            elif values.dtype.kind in "iuf" and not (values.is_monotonic_increasing or values.is_monotonic_decreasing):
                out.append(f"{at}coordinate {dim} is not monotone")
            continue
        for name, coord in ds.coords.items():
            if coord.dims == (dim,) and coord.dtype.kind in "iuf" and coord.size > 1:
                step = np.diff(np.asarray(coord.values, float))
                if np.all(step > 0) or np.all(step < 0):
                    out.append(f"{at}dimension {dim} has the monotone coordinate {name} but no index")
    return out


def file_problems(path) -> list[str]:
    path = Path(path)
    if path.suffix == ".zarr" or (path / "zarr.json").exists() or (path / ".zgroup").exists():
        out = []
        meta = path / "zarr.json"
        consolidated = (path / ".zmetadata").exists() or (
            meta.exists() and "consolidated_metadata" in json.loads(meta.read_text()) and
            json.loads(meta.read_text())["consolidated_metadata"] is not None)
        if not consolidated:
            out.append(f"{path.name}: Zarr store not consolidated")
        with xr.open_zarr(path, consolidated=consolidated or None) as ds:
            return out + problems(ds, path.name)
    with xr.open_dataset(path) as ds:
        return problems(ds, path.name)


def compliance_errors(path) -> list[str]:
    """What compliance-checker (the IOOS checker, CF 1.10; not ours) reports of a netCDF file at
    high and medium priority (errors and warnings; low-priority suggestions are left out), or
    its own crash on the file."""
    import subprocess
    import sys

    checker = Path(sys.executable).with_name("compliance-checker")
    done = subprocess.run([str(checker), "--test", "cf:1.10", "-f", "json_new", "-o", "-", str(path)],
                          capture_output=True, text=True, timeout=300)
    try:
        report = json.loads(done.stdout)
    except json.JSONDecodeError:
        return [f"compliance-checker failed on {path}: {done.stderr.strip()[-300:]}"]
    out = []
    for result in report.values():
        for checks in result.values():
            if checks.get("errors"):
                out += [f"checker error: {e}" for e in checks["errors"].values()]
            for level in ("high_priorities", "medium_priorities"):
                for item in checks.get(level, []):
                    out += [f"{item['name']}: {m}" for m in item.get("msgs", [])]
    return out

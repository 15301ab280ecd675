"""The Zarr store of a sweep: its layout, a checksum per point, and what a resume may trust.

A store holds every output on the grid, a ``done`` mask and a ``checksum`` per point: the
first 63 bits of the SHA-256 of the point's grid index and its outputs' stored bytes,
written with the outputs and before ``done``. A kill at any moment leaves points that are
done with their checksum, or not done. A done point whose values no longer match its
checksum (a flipped byte, a lost chunk, a value edited by hand) is found by `damaged`; a
resume computes it again and says so, a reader (`verify_store`) refuses the store.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Mapping, Sequence

import numpy as np
import lazy_loader as lazy
import zarr

from ..cf import SOURCE, finish, flag_attrs, plain_attrs
from ..errors import ParameterError
from ..files import content_digest
from ..quantities import lookup

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["SWEEP_FORMAT", "NOT_COMPUTED", "is_vector", "create", "open_group", "verify_store", "damaged",
           "forget", "matches", "write_points", "result", "failures", "tidy"]

#: The layout of a sweep store; a store with another layout is refused, not misread.
SWEEP_FORMAT = "stickslip-sweep-2"
#: The layout before per-point checksums (one checksum of the whole store): resumed after an upgrade.
_FORMAT_1 = "stickslip-sweep-1"
#: The code of a point not computed yet, in an output of codes.
NOT_COMPUTED = -1
_CHECKSUM = "checksum"


def is_vector(spec) -> bool:
    """An output of ``size`` numbers per point: ``(units, size)``."""
    return isinstance(spec, tuple) and len(spec) == 2 and isinstance(spec[0], str) and \
        isinstance(spec[1], (int, np.integer)) and not isinstance(spec[1], bool) and spec[1] >= 1


def _variable(dims: tuple, shape: tuple, spec, name: str = "") -> tuple:
    """An output's empty array: NaN floats with ``units``, integer codes (``{meaning: code}``), or
    ``(units, size)``: NaN floats along one more dimension ``<name>_index`` of ``size``."""
    if isinstance(spec, Mapping):
        codes = {"not_computed": NOT_COMPUTED, **spec}
        return dims, np.full(shape, NOT_COMPUTED, np.int8), {**flag_attrs(codes), "comment": (
            f"{NOT_COMPUTED} where the point is not computed yet (done is 0)")}
    note = "NaN where the point is not computed yet (done is 0) or the output does not apply to it"
    if is_vector(spec):
        return (*dims, f"{name}_index"), np.full((*shape, int(spec[1])), np.nan), {"units": spec[0], "comment": note}
    return dims, np.full(shape, np.nan), {"units": spec, "comment": note}


def create(store: Path, axes: dict, outputs: dict, attrs: dict, title: str, model: str) -> None:
    """A new store for the grid ``axes`` with every output not computed."""
    shape = tuple(len(v) for v in axes.values())
    data = {name: _variable(tuple(axes), shape, spec, name) for name, spec in outputs.items()}
    for name, (_, _, var_attrs) in data.items():  # named by the vocabulary of the model, else by the output's name
        var_attrs.setdefault("long_name", (lookup(name, model) or (None, name))[1])
    data["done"] = (tuple(axes), np.zeros(shape, np.int8), {"units": "1", "long_name": "point computed (1) or not (0)"})
    data[_CHECKSUM] = (tuple(axes), np.zeros(shape, np.int64), {
        "units": "1", "long_name": "checksum of the point's stored outputs",
        "comment": "first 63 bits of the SHA-256 of the grid index and the outputs' bytes; 0 where not done"})
    coords = {k: (k, np.asarray(v, float)) for k, v in axes.items()}
    params = plain_attrs(attrs)
    ds = finish(xr.Dataset(data, coords=coords), title, model, params={**params, "parameters": " ".join(params)})
    ds.to_zarr(store, mode="w", consolidated=False, zarr_format=2)  # v2: consolidated metadata is standard there
    group = open_group(store, "r+")
    group.attrs["sweep_format"] = SWEEP_FORMAT
    zarr.consolidate_metadata(str(store))


def open_group(store, mode: str):
    """The store's root group, read from its own metadata (never the consolidated copy, which
    is refreshed after each write and may lag behind a killed one)."""
    return zarr.open_group(str(store), mode=mode, use_consolidated=False)


def _outputs(group) -> list[str]:
    return [n for n in group.array_keys() if n not in ("done", _CHECKSUM) and "done" in group
            and group[n].shape[:group["done"].ndim] == group["done"].shape and n not in _coords(group)]


def _coords(group) -> set:
    return set(group["done"].attrs.get("_ARRAY_DIMENSIONS", [])) if "done" in group else set()


def _checksums(index: Sequence[tuple], columns: Mapping[str, np.ndarray]) -> np.ndarray:
    """The checksum of each point ``index[k]`` whose output ``name`` is ``columns[name][k]``
    (as stored: the bytes of its type in the store)."""
    out = np.empty(len(index), np.int64)
    ordered = [columns[name] for name in sorted(columns)]
    for k, idx in enumerate(index):
        h = hashlib.sha256(repr(tuple(int(i) for i in idx)).encode())
        for col in ordered:
            h.update(np.ascontiguousarray(col[k]).tobytes())
        out[k] = int.from_bytes(h.digest()[:8], "little") >> 1  # 63 bits: never the 0 of a point not done
    return out


def _read(store):
    """The group, its format, its outputs' names; a `ParameterError` if it cannot be read."""
    try:
        group = open_group(store, "r")
        found = group.attrs.get("sweep_format")
        names = _outputs(group) if found in (SWEEP_FORMAT, _FORMAT_1) else []
    except Exception as err:  # noqa: BLE001 - whatever a damaged store makes the decoder raise
        raise ParameterError("store", str(store), f"a readable sweep store ({type(err).__name__}: it is damaged; "
                             "overwrite it to start afresh)") from None
    if found not in (SWEEP_FORMAT, _FORMAT_1):
        raise ParameterError("store", str(store), f"a sweep store in the format {SWEEP_FORMAT} (this one: {found}, "
                             "written by another version or program; overwrite it to start afresh)")
    return group, found, names


def tidy(store) -> None:
    """Remove what a killed write leaves in the store (zarr's temporary ``*.partial`` files):
    readers would warn about them. For the store's one writer only."""
    for leftover in Path(store).rglob("*.partial"):
        leftover.unlink(missing_ok=True)


def damaged(store) -> list[tuple]:
    """The grid indices of the done points whose outputs do not match their checksum. A store
    in the earlier layout (one checksum of the whole store) is upgraded in place when it is
    intact, else refused: which of its points changed cannot be told."""
    group, found, names = _read(store)
    if found == _FORMAT_1:
        _upgrade(store, group, names)
        group = open_group(store, "r")
    try:
        done = np.asarray(group["done"][...], bool)
        index = list(zip(*np.nonzero(done)))
        stored = group[_CHECKSUM][...][done] if index else np.zeros(0, np.int64)
        sums = _checksums(index, {n: group[n][...][done] for n in names})
    except Exception as err:  # noqa: BLE001 - a lost metadata file, an undecodable chunk
        raise ParameterError("store", str(store), f"a readable sweep store ({type(err).__name__}: it is damaged; "
                             "overwrite it to start afresh)") from None
    return [tuple(int(i) for i in idx) for idx, a, b in zip(index, sums, stored) if a != b]


def _upgrade(store: Path, group, names: list) -> None:
    arrays = {name: group[name][...] for name in group.array_keys()}
    if content_digest(arrays) not in (group.attrs.get("content_sha256"), group.attrs.get("pending_sha256")):
        raise ParameterError("store", str(store), "an intact sweep store (its content does not match its checksum: "
                             "it was changed or damaged; overwrite it to start afresh)")
    group = open_group(store, "r+")
    done = np.asarray(arrays["done"], bool)
    sums = np.zeros(done.shape, np.int64)
    index = list(zip(*np.nonzero(done)))
    sums[done] = _checksums(index, {n: arrays[n][done] for n in names})
    dims = list(group["done"].attrs.get("_ARRAY_DIMENSIONS", []))
    array = group.create_array(_CHECKSUM, shape=done.shape, dtype=np.int64, fill_value=0, overwrite=True)
    array[...] = sums
    array.attrs.update({"_ARRAY_DIMENSIONS": dims, "units": "1", "long_name": "checksum of the point's stored outputs"})
    for key in ("content_sha256", "pending_sha256"):
        group.attrs.pop(key, None)
    group.attrs["sweep_format"] = SWEEP_FORMAT
    zarr.consolidate_metadata(str(store))


def verify_store(store) -> None:
    """Refuse (`ParameterError`) a store of another format, or with a done point whose outputs
    do not match its checksum (a reader cannot compute it again; a resume does)."""
    bad = damaged(store)
    if bad:
        raise ParameterError("store", str(store), f"an intact sweep store ({len(bad)} point(s), the first at grid "
                             f"index {bad[0]}, do not match their checksum: changed or damaged; resume the sweep to "
                             "compute them again, or overwrite it)")


def forget(store, index: list[tuple]) -> None:
    """Mark the points ``index`` not done (they are computed again)."""
    if index:
        group = open_group(store, "r+")
        where = tuple(np.array(c) for c in zip(*index))
        group["done"].vindex[where] = 0
        group[_CHECKSUM].vindex[where] = 0


def matches(store: Path, axes: dict, outputs: dict, attrs: dict) -> bool:
    """The store holds this sweep: the same axes, outputs and fixed parameters (``attrs``)."""
    try:
        ds = xr.open_zarr(store, consolidated=False)
    except Exception:  # noqa: BLE001 - not a readable store of this layout: not this sweep
        return False
    attrs = plain_attrs(attrs)
    if set(str(ds.attrs.get("parameters", "")).split()) != set(attrs):
        return False
    same_axes = "done" in ds and list(ds["done"].dims) == list(axes) and all(
        ds[k].size == len(v) and np.array_equal(ds[k].values, np.asarray(v, float)) for k, v in axes.items())
    same_attrs = all(k in ds.attrs and _same_value(ds.attrs[k], v) for k, v in attrs.items())
    same_source = ds.attrs.get("source") == SOURCE
    return same_axes and same_attrs and same_source and all(name in ds for name in outputs)


def _same_value(a, b) -> bool:
    try:
        return bool(np.array_equal(np.asarray(a, dtype=float), np.asarray(b, dtype=float)))
    except (TypeError, ValueError):
        return str(a) == str(b)


def write_points(group, store: Path, names: list, sizes: dict, chunk: list, values: list) -> None:
    """Store the ``values`` of the points ``chunk`` (grid indices): outputs, then their
    checksums, then ``done`` (a kill at any moment leaves each point done and intact, or not
    done)."""
    where = tuple(np.array(c) for c in zip(*chunk))
    columns = {name: np.asarray([v[j] for v in values]).astype(group[name].dtype) for j, name in enumerate(names)}
    for name, column in columns.items():
        if name in sizes:  # a row per point
            for idx, row in zip(chunk, column):
                group[name][idx] = row
        else:
            group[name].vindex[where] = column
    group[_CHECKSUM].vindex[where] = _checksums(chunk, columns)
    group["done"].vindex[where] = 1  # last: a point counts only once all its outputs are in
    if "failed" in group.attrs:  # a point computed now no longer counts as failed
        computed = set(map(tuple, chunk))
        group.attrs["failed"] = json.dumps({k: v for k, v in failures(group).items()
                                            if tuple(int(i) for i in k.split(",")) not in computed})
    zarr.consolidate_metadata(str(store))


def failures(group) -> dict:
    """``{"i,j": message}`` of the points that raised (`stickslip.sweep.run_sweep` on dask.distributed)."""
    return json.loads(group.attrs.get("failed", "{}"))


def result(store: Path) -> xr.Dataset:
    """The store's outputs and ``done`` mask (the checksums are the store's business)."""
    return xr.open_zarr(store, consolidated=False).load().drop_vars(_CHECKSUM, errors="ignore")

"""Points off a sweep's grid, kept in its store: the extra evaluations a search makes between
the grid's values (the bisections of a tracked CEA sweep), each keyed by its value.

`OffGrid(store, name)` holds the points in the store's group ``name``, one sub-group per point
(named by the bits of its value): its arrays, then its ``value`` and ``checksum`` (the first 63
bits of the SHA-256 of the value and the arrays' bytes) as attributes, written last. A kill at
any moment leaves a point complete with its checksum, or without one (not stored); a point whose
arrays no longer match its checksum is left out of `load` (computed again) and said so. The
store is the sweep's: `stickslip.sweep.run_sweep` has refused it first if it holds another
computation, and its lock (`stickslip.files.exclusive`) is the caller's to hold while writing.
"""

from __future__ import annotations

import hashlib
import logging
from pathlib import Path
from typing import Mapping

import numpy as np

from .store import open_group

__all__ = ["OffGrid"]

log = logging.getLogger("stickslip.sweep")


def _checksum(value: float, arrays: Mapping[str, np.ndarray]) -> int:
    h = hashlib.sha256(np.float64(value).tobytes())
    for name in sorted(arrays):
        h.update(name.encode())
        h.update(np.ascontiguousarray(arrays[name], dtype=np.float64).tobytes())
    return int.from_bytes(h.digest()[:8], "little") >> 1


class OffGrid:
    """The off-grid points of the sweep store ``store`` in its group ``name``."""

    def __init__(self, store, name: str):
        self.store, self.name = Path(store), name

    def load(self) -> dict[float, dict[str, np.ndarray]]:
        """``{value: {array name: float64 array}}`` of every complete, intact point."""
        root = open_group(self.store, "r")
        if self.name not in root:
            return {}
        out, bad = {}, 0
        for key, point in root[self.name].groups():
            attrs = point.attrs
            if "checksum" not in attrs:  # killed while written
                continue
            arrays = {n: np.asarray(a[...], np.float64) for n, a in point.arrays()}
            value = float(attrs["value"])
            if _checksum(value, arrays) != int(attrs["checksum"]):
                bad += 1
                continue
            out[value] = arrays
        if bad:
            log.warning("%d stored off-grid point(s) in %s/%s do not match their checksum: computed again", bad,
                        self.store, self.name)
        return out

    def add(self, value: float, arrays: Mapping[str, np.ndarray]) -> None:
        """Store the point ``value`` with its ``arrays`` (1-D, floats), replacing any point there."""
        value = float(value)
        root = open_group(self.store, "r+")
        group = root.require_group(self.name)
        key = f"v{np.float64(value).view(np.int64)}"
        point = group.create_group(key, overwrite=True)
        for n, a in arrays.items():
            a = np.asarray(a, np.float64).ravel()
            array = point.create_array(n, shape=a.shape, dtype=np.float64, chunks=(max(1, a.size),),
                                       fill_value=np.nan, overwrite=True)
            if a.size:
                array[...] = a
        point.attrs.update({"value": value})
        point.attrs["checksum"] = _checksum(value, {n: np.asarray(a, np.float64).ravel() for n, a in arrays.items()})

    def clear(self) -> None:
        """Remove every stored point."""
        root = open_group(self.store, "r+")
        if self.name in root:
            del root[self.name]

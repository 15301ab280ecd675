"""A long run kept in a netCDF file as it goes, and resumed from it (`run_inplane`'s and
`stickslip.sbim.fault.run_fault`'s ``checkpoint``).

The file's root group holds the fields sampled so far as a CF dataset (readable at any time, in
ParaView or xarray); its group ``checkpoint`` the run's whole state (displacements, which nodes
slide, the pressure the strength sees, each mode's history of rates, the samples). It is written
every `CHECKPOINT_SECONDS` of wall time, by a new file moved over the old one (a run killed while
writing keeps the previous state), and at the end. A resumed run is the uninterrupted one to the
last bit. The file names its run by a key (``run_key``: a digest of everything the run depends on,
given by the caller); a file of another run, or not a run's, is refused, naming ``checkpoint``.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np

from ..cf import for_file
from ..errors import ParameterError
from ..files import to_netcdf
from .inplane import RUN_FORMAT  # an in-plane run's, the default (public here too)

__all__ = ["Checkpoint", "RUN_FORMAT", "CHECKPOINT_SECONDS"]

#: Wall time between two writes of a run's file [s].
CHECKPOINT_SECONDS = 60.0


class Checkpoint:
    """The run file at ``path`` for the run named ``key``; ``seconds`` between writes (0: every step;
    default `CHECKPOINT_SECONDS`);
    ``fields(state)`` the CF dataset of the samples in a state (written to the root group);
    ``run_format`` the kind of run the file holds (an in-plane run's by default, `RUN_FORMAT`; a run refuses
    a checkpoint of another kind). A state's complex arrays are stored as their real and imaginary parts;
    ``complex_names``, which named them, is no longer needed (kept so that calls giving it still work)."""

    def __init__(self, path, key: str, fields, seconds: float | None = None, run_format: str = RUN_FORMAT,
                 complex_names: tuple = ()):
        self.path, self.key, self.fields = Path(path), str(key), fields
        self.seconds = float(CHECKPOINT_SECONDS if seconds is None else seconds)
        self.run_format, self.complex_names = str(run_format), tuple(complex_names)
        self.last = time.monotonic()
        self.writes = 0

    def _refused(self, why: str) -> ParameterError:
        return ParameterError("checkpoint", str(self.path), f"a checkpoint of this run, or a new file ({why}; "
                              "give --overwrite, or another path, to start afresh)")

    def resume(self) -> dict | None:
        """The state stored at ``path`` for this run, or None when there is no file."""
        if not self.path.exists():
            return None
        import xarray as xr

        try:
            with xr.open_dataset(self.path) as root:
                attrs = dict(root.attrs)
            with xr.open_dataset(self.path, group="checkpoint") as ds:
                state = {name: ds[name].values for name in ds.data_vars}
        except (OSError, ValueError, KeyError) as err:
            raise self._refused(f"this file is not a run's netCDF file: {type(err).__name__}") from None
        if attrs.get("run_format") != self.run_format:
            raise self._refused(f"its format is {attrs.get('run_format', 'none')!r}, not {self.run_format!r}")
        if attrs.get("run_key") != self.key:
            raise self._refused("it holds another run: other parameters, load, steps or sampling")
        for name in [k[:-3] for k in state if k.endswith("_re") and k[:-3] + "_im" in state]:
            state[name] = state.pop(name + "_re") + 1j * state.pop(name + "_im")
        return state

    def due(self, step: int) -> bool:
        return time.monotonic() - self.last >= self.seconds

    def save(self, state: dict) -> None:
        """Write ``state`` (a new file moved over the old one)."""
        import xarray as xr

        split = set(self.complex_names) | {k for k, v in state.items() if np.iscomplexobj(v)}
        flat = {k: v for k, v in state.items() if k not in split}
        for name in split & set(state):
            flat[name + "_re"], flat[name + "_im"] = state[name].real, state[name].imag
        group = xr.Dataset({k: (tuple(f"{k}_{i}" for i in range(np.ndim(v))), np.asarray(v))
                            for k, v in flat.items()})
        root = for_file(self.fields(state))
        root.attrs.update({"run_format": self.run_format, "run_key": self.key, "steps_done": int(state["step"])})
        partial = self.path.with_name(f".{self.path.name}.{os.getpid()}.partial")
        try:
            to_netcdf(root, partial)
            to_netcdf(group, partial, mode="a", group="checkpoint")
            os.replace(partial, self.path)
        finally:
            if partial.exists():
                partial.unlink()
        self.last = time.monotonic()
        self.writes += 1

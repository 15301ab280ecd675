"""Explicit contact runs around the ring: schedule, records, checkpoints (shared).

The reduced-model integrator (`ring`) and the finite elements (`fem`) advance different
schemes but keep the same books: a time series sampled ``samples_per_transit`` times per
wave transit, snapshots of the contact nodes every ``snapshot_every`` transits and at every
sample of the last ``tail`` transits, and a netCDF checkpoint written every ``every`` time
units, on any exception and at the end. A run resumed from its checkpoint is bitwise
identical to an uninterrupted one (float64 throughout, and the scheme state is stored).
This module holds those books; each model supplies a `RunFormat`, a step and a recorder.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, ClassVar

import numpy as np
import xarray as xr

from .. import validation as check
from ..errors import ParameterError
from .reduced.params import BrakeParams, PhysicalParams
from .ring.scheme import STATE_NAMES

__all__ = ["RunFormat", "RunRecord", "schedule", "prepare", "save", "resume", "loop", "run_to_dataset",
           "dataset_to_run", "settings_key"]

_KEYS = ("chunk", "samples_total", "snap_every", "tail_samples", "samples_per_transit", "modes", "contact",
         "initial", "initial_hash")


@dataclass(frozen=True)
class RunFormat:
    """How one model's run is stored: snapshot fields, scheme state, scheme constructor."""

    fields: dict            # snapshot field -> (units, long_name)
    kernel: tuple           # names of the scheme-state arrays stored for resuming
    kernel_dim: str         # their dimension name
    kernel_note: str
    energy_units: str
    energy_note: str
    node_label: str         # "node" or "contact node"
    source: str
    key_attrs: tuple        # scheme constructor arguments after params, stored in attrs
    scheme: Callable        # scheme(params, *key values)
    extra_attrs: Callable = staticmethod(lambda scheme: {})


@dataclass(frozen=True, eq=False)
class RunRecord:
    """A run's books. Subclasses set ``FORMAT``; series and snapshots read as attributes."""

    FORMAT: ClassVar[RunFormat]
    scheme: object
    settings: dict
    series: dict
    snapshots: dict
    kernel: dict
    samples_done: int

    @property
    def params(self) -> BrakeParams:
        return self.scheme.params

    @property
    def complete(self) -> bool:
        return self.samples_done >= self.settings["samples_total"]

    @property
    def t(self) -> np.ndarray:
        return self.series["t"]

    @property
    def t_end(self) -> float:
        return float(self.samples_done * self.settings["chunk"] * self.scheme.dt)

    def __getattr__(self, name):
        for store in ("series", "snapshots"):
            data = self.__dict__.get(store, {})
            if name in data:
                return data[name]
        raise AttributeError(name)

    def to_xarray(self) -> xr.Dataset:
        """Snapshots ``(snapshot, node)``, series ``(sample[, kind | mode])``, units in attrs."""
        return run_to_dataset(self)

    @classmethod
    def from_xarray(cls, ds: xr.Dataset):
        return dataset_to_run(cls, ds)


def _scheme_key(scheme, fmt: RunFormat) -> tuple:
    return tuple(getattr(scheme, k) for k in fmt.key_attrs)


def settings_key(run) -> tuple:
    """What must agree for a checkpoint to be resumed (``samples_total`` may grow)."""
    return _scheme_key(run.scheme, run.FORMAT) + tuple(run.settings[k] for k in _KEYS
                                                       if k not in ("samples_total", "tail_samples"))


def _params_attrs(params: BrakeParams) -> dict:
    out = {k: v for k, v in params.to_dict().items() if k != "physical"}
    if params.physical is not None:
        out.update({f"physical_{k}": v for k, v in params.to_dict()["physical"].items()})
    return out


def run_to_dataset(run) -> xr.Dataset:
    fmt, s, st = run.FORMAT, run.scheme, run.settings
    N, K = s.theta.size, st["modes"] + 1
    ser, snp = run.series, run.snapshots

    def col(store, key, shape, dtype=float):
        return np.asarray(store[key], dtype=dtype) if key in store else np.zeros(shape, dtype)

    data = {
        "energy": ("sample", col(ser, "energy", 0), {"units": fmt.energy_units, "long_name": fmt.energy_note}),
        "kinetic": ("sample", col(ser, "kinetic", 0), {"units": fmt.energy_units, "long_name": "kinetic energy"}),
        "fraction": (("sample", "kind"), col(ser, "fractions", (0, 4)),
                     {"units": "1", "long_name": f"fraction of {fmt.node_label}s in each state"}),
        "state": (("snapshot", "node"), col(snp, "state", (0, N), np.int8),
                  {"long_name": f"{fmt.node_label} state", "flag_values": [0, 1, 2, 3],
                   "flag_meanings": " ".join(STATE_NAMES)}),
    }
    for name in ("U", "V"):
        z = col(ser, f"modes_{name}", (0, K), complex)
        for part, arr in (("re", z.real), ("im", z.imag)):
            data[f"modes_{name}_{part}"] = (("sample", "mode"), arr, {"units": "R", "long_name": f"rfft({name})/N"})
    for name, (units, long) in fmt.fields.items():
        data[name] = (("snapshot", "node"), col(snp, name, (0, N)), {"units": units, "long_name": long})
    for name in fmt.kernel:
        data[f"kernel_{name}"] = (fmt.kernel_dim, run.kernel[name], {"long_name": fmt.kernel_note})
    coords = {"t": ("sample", col(ser, "t", 0), {"units": "1/Omega", "long_name": "time Omega t"}),
              "snap_t": ("snapshot", col(snp, "snap_t", 0), {"units": "1/Omega"}),
              "theta": ("node", s.theta, {"units": "rad"}), "kind": ("kind", list(STATE_NAMES)),
              "mode": ("mode", np.arange(K))}
    attrs = {**_params_attrs(s.params), **dict(zip(fmt.key_attrs, _scheme_key(s, fmt))), **fmt.extra_attrs(s),
             "dt": s.dt, "transit_time": s.transit_time, "samples_done": run.samples_done,
             "complete": int(run.complete), **{k: (int(v) if isinstance(v, bool) else v) for k, v in st.items()},
             "source": fmt.source}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def dataset_to_run(cls, ds: xr.Dataset):
    fmt, a = cls.FORMAT, ds.attrs
    physical = {k[len("physical_"):]: float(v) for k, v in a.items() if k.startswith("physical_")}
    params = BrakeParams(float(a["xi"]), float(a["nu"]), float(a["gamma"]), float(a["delta"]), float(a["friction"]),
                         physical=PhysicalParams(**physical) if physical else None)
    key = [a[k].item() if hasattr(a[k], "item") else a[k] for k in fmt.key_attrs]
    scheme = fmt.scheme(params, *key)
    settings = {k: (a[k].item() if hasattr(a[k], "item") else a[k]) for k in _KEYS}
    settings["contact"] = bool(settings["contact"])
    series = {"t": ds["t"].values, "energy": ds["energy"].values, "kinetic": ds["kinetic"].values,
              "fractions": ds["fraction"].values}
    for name in ("U", "V"):
        series[f"modes_{name}"] = ds[f"modes_{name}_re"].values + 1j * ds[f"modes_{name}_im"].values
    snapshots = {"snap_t": ds["snap_t"].values, "state": ds["state"].values.astype(np.int8)}
    snapshots.update({name: ds[name].values for name in fmt.fields})
    kernel = {name: ds[f"kernel_{name}"].values.copy() for name in fmt.kernel}
    return cls(scheme, settings, series, snapshots, kernel, int(a["samples_done"]))


def schedule(scheme, t_end, samples_per_transit, snapshot_every, tail) -> dict:
    """Steps per sample, number of samples, snapshot interval and tail length, in samples."""
    chunk = max(1, int(round(scheme.steps_per_transit / samples_per_transit)))
    total = int(np.ceil(t_end / (chunk * scheme.dt) - 1e-9))
    per_transit = scheme.steps_per_transit / chunk
    return {"chunk": chunk, "samples_total": max(total, 1),
            "snap_every": max(1, int(round(snapshot_every * per_transit))),
            "tail_samples": int(round(tail * per_transit))}


def prepare(scheme, *, t_end, transits, samples_per_transit, snapshot_every, tail, modes, contact, initial,
            progress) -> tuple[float, dict]:
    """Validate the common options of a run; return ``t_end`` and the settings."""
    if (t_end is None) == (transits is None):
        raise ParameterError("t_end", t_end, "given (> 0), or else transits, but not both")
    t_end = check.positive("t_end", t_end) if transits is None else \
        check.positive("transits", transits) * scheme.transit_time
    spt = check.positive_int("samples_per_transit", samples_per_transit)
    if spt < 4:
        raise ParameterError("samples_per_transit", spt, "an integer >= 4")
    if progress is not None and not callable(progress):
        raise ParameterError("progress", progress, "a callable progress(t, t_end) or None")
    modes = min(check.positive_int("modes", modes), scheme.theta.size // 2)
    settings = {**schedule(scheme, t_end, spt, check.positive("snapshot_every", snapshot_every),
                           check.nonnegative("tail", tail)),
                "samples_per_transit": spt, "modes": modes, "contact": bool(contact), "initial": initial.label,
                "initial_hash": initial.digest()}
    return t_end, settings


def save(run, path) -> None:
    """Write the run atomically (a kill during the write leaves the previous file)."""
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")
    run.to_xarray().to_netcdf(tmp)
    os.replace(tmp, path)


def resume(cls, path, scheme, settings):
    """The run stored at ``path`` if it is this run (else `ParameterError`), or None."""
    path = Path(path)
    if not path.exists():
        return None
    old = cls.from_xarray(xr.load_dataset(path))
    if old.params.to_dict() != scheme.params.to_dict() or \
            settings_key(old) != settings_key(cls(scheme, settings, {}, {}, {}, 0)):
        raise ParameterError("checkpoint", str(path), "a checkpoint of the same run (parameters, scheme, schedule "
                             "and initial condition must match; delete it to start afresh)")
    return cls(scheme, {**old.settings, "samples_total": settings["samples_total"],
                        "tail_samples": settings["tail_samples"]},
               old.series, old.snapshots, old.kernel, old.samples_done)


def loop(run, checkpoint, every, progress, t_end, step: Callable, record: Callable):
    """Advance ``run`` to its last sample: ``step(kernel)`` advances one sample's steps,
    ``record(done, kernel, series, snaps)`` books it."""
    cls, s, st, k = type(run), run.scheme, run.settings, run.kernel
    series = {key: list(v) for key, v in run.series.items()}
    snaps = {key: list(v) for key, v in run.snapshots.items()}
    done, total, chunk = run.samples_done, st["samples_total"], st["chunk"]
    every = t_end / 10.0 if every is None else check.positive("every", every)
    per_checkpoint = max(1, int(every / (chunk * s.dt)))

    def result():
        return cls(s, st, {key: np.asarray(v) for key, v in series.items()},
                   {key: np.asarray(v) for key, v in snaps.items()}, {key: v.copy() for key, v in k.items()}, done)

    try:
        while done < total:
            step(k)
            done += 1
            record(done, k, series, snaps)
            if progress is not None:
                progress(done * chunk * s.dt, t_end)
            if checkpoint is not None and done % per_checkpoint == 0 and done < total:
                save(result(), checkpoint)
    except BaseException:
        if checkpoint is not None and done > run.samples_done:
            save(result(), checkpoint)
        raise
    out = result()
    if checkpoint is not None:
        save(out, checkpoint)
    return out


def snapshot_due(done: int, st: dict) -> bool:
    """Snapshots every ``snap_every`` samples and at every sample of the tail."""
    return done % st["snap_every"] == 0 or done > st["samples_total"] - st["tail_samples"] or \
        done == st["samples_total"]

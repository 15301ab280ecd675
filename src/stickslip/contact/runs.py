"""Checkpointed run books of an explicit contact scheme: schedule, records, resume.

Every contact model (the ring of the reduced model, the FE annulus) advances its scheme
(`stickslip.contact.scheme.ExplicitScheme`) and keeps the same books:

* a time series sampled ``samples_per_transit`` times per P-wave transit: the energy of
  the deviation from steady sliding, the kinetic energy, the fraction of contact nodes in
  each state, Fourier modes of the normal and tangential displacements along the contact
  line;
* snapshots of the contact nodes (``U, V`` normal and tangential displacements, their
  step velocities ``Ud, Vd``, the reactions ``P, Q``, the ``gap`` at ``t_{m+1}`` and the
  ``state``) every ``snapshot_every`` transits and at every sample of the last ``tail``;
* a netCDF checkpoint written every ``every`` time units (by default every `CHECKPOINT_SECONDS`
  of wall time: a killed run loses at most that much work, and a short run writes its file
  once), on any exception and at the end.

A run resumed from its checkpoint is bitwise identical to an uninterrupted one (float64
throughout, and the scheme state is stored); a checkpoint of another run is refused.
A model supplies a `RunFormat` (units and names of its fields, its scheme and parameter
types) and a `RunRecord` subclass; `run_explicit` does the rest.
"""

from __future__ import annotations

import contextlib
import time
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, ClassVar

import numpy as np
import lazy_loader as lazy

from ..results import Result
from ..quantities import COMMON as Q
from ..cf import SOURCE, finish, for_file, from_file, plain_attrs
from ..errors import NoSolutionError, ParameterError
from ..files import content_digest, exclusive, to_netcdf
from .scheme import StepState
from .states import SEPARATION, SLIP_POS, STATE_ATTRS, STATE_NAMES, state_fractions

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["MAX_VOLUME", "MAX_WORK", "RunFormat", "RunRecord", "schedule", "prepare", "save", "resume", "loop",
           "run_explicit", "run_to_dataset", "results_view", "dataset_to_run", "settings_key", "snapshot_due",
           "window_snapshots", "volume_due", "volume_at_start", "held_transits"]

_KEYS = ("chunk", "samples_total", "snap_every", "tail_samples", "samples_per_transit", "modes", "contact",
         "initial", "initial_hash", "volume_every")
#: Volume snapshots (``prepare(volume_every=...)``, 0 = none): every free dof, and the reactions of the contact nodes.
_VOLUME = {"vol_u": ("dof", "length", "displacement u_m of every free dof (volume snapshot)"),
           "vol_v": ("dof", "velocity", "velocity v_m of the scheme at every free dof (volume snapshot)"),
           "vol_P": ("node", "traction", "normal reaction (contact pressure) at the volume snapshot"),
           "vol_Q": ("node", "traction", "tangential reaction (friction) at the volume snapshot")}
#: Snapshot fields: (kind of unit, long name); a model's `RunFormat` names the units and may refine the names.
_SNAPSHOT = {"U": ("length", "normal displacement of the contact node"),
             "V": ("length", "tangential displacement of the contact node"),
             "Ud": ("velocity", "normal step velocity (u_{m+1} - u_m)/dt"),
             "Vd": ("velocity", "tangential step velocity (u_{m+1} - u_m)/dt (surface speed = 1)"),
             "P": ("traction", "normal reaction (contact pressure)"),
             "Q": ("traction", "tangential reaction (friction), positive along the surface motion"),
             "gap": ("length", "gap u_n - gap0 at t_{m+1} (where the constraint of the step acts)")}
_KERNEL = ("u", "v", "a", "ref")


@dataclass(frozen=True)
class RunFormat:
    """How one model's run is stored.

    ``units`` gives the units of ``length``, ``velocity`` and ``traction`` for the snapshot
    fields (``U, V, Ud, Vd, P, Q, gap``, and the volume snapshots ``vol_*``), ``notes`` long names that
    replace the generic ones;
    ``traction_scale(scheme)`` turns reactions per unit mass into the stored ``P, Q``;
    ``params_type`` has ``to_attrs()`` and ``from_attrs(attrs)``; ``scheme(params, *key)``
    rebuilds the scheme from the ``key_attrs`` stored in attrs.
    """

    units: dict
    energy_units: str
    energy_note: str
    node_label: str         # "node" or "contact node"
    source: str
    key_attrs: tuple
    scheme: Callable
    params_type: type
    traction_scale: Callable = staticmethod(lambda scheme: 1.0)
    extra_attrs: Callable = staticmethod(lambda scheme: {})
    notes: dict = field(default_factory=dict)
    title: str = "run of an explicit contact scheme"
    time_units: str = "1/Omega"
    time_note: str = "time Omega t"
    model: str = "brake"
    position_note: str = ""  # what ``theta`` is, if not the angle of the node
    mode_note: str = "circumferential Fourier mode"
    extra_coords: Callable = staticmethod(lambda scheme: {})  # name -> (values, attrs) along the nodes
    #: Snapshot fields a model adds to the plane ones (name -> (kind of unit, long name)), taken from
    #: ``scheme.snapshot_fields(out, u)`` at each snapshot; with volume snapshots, ``vol_<name>`` of those of
    #: kind ``traction`` too (the solids' ``W`` and ``Q_cross``).
    extra_fields: Callable = staticmethod(lambda scheme: {})
    #: The SI values of the symbols of the model's scaled units (``R`` [m], ``Omega`` [rad/s],
    #: ``E`` [Pa], ``M`` [1]) when the run was set up in SI, else {}: the run's file then holds its
    #: results in SI (`results_view`).
    scales: Callable = staticmethod(lambda scheme: {})

    @property
    def fields(self) -> dict:
        """``name -> (units, long_name)`` of every snapshot field (of a plane model; `fields_of` a scheme's)."""
        return {k: (self.units[kind], self.notes.get(k, note)) for k, (kind, note) in _SNAPSHOT.items()}

    def fields_of(self, scheme) -> dict:
        """`fields` and the ``extra_fields`` of ``scheme``."""
        extra = {k: (self.units[kind], note) for k, (kind, note) in self.extra_fields(scheme).items()}
        return {**self.fields, **extra}

    def volume_extra(self, scheme) -> dict:
        """``vol_<name> -> (units, long_name)`` of the extra fields kept with volume snapshots."""
        return {f"vol_{k}": (self.units[kind], f"{note} at the volume snapshot")
                for k, (kind, note) in self.extra_fields(scheme).items() if kind == "traction"}


@dataclass(frozen=True, eq=False, repr=False)
class RunRecord(Result):
    """A run's books. Subclasses set ``FORMAT``; series and snapshots read as attributes.

    Series (one row per sample): ``t``, ``energy`` (of the deviation from steady sliding,
    `ExplicitScheme.energies`), ``kinetic``, ``fractions`` (columns `STATE_NAMES`),
    ``modes_U``, ``modes_V`` (``rfft / nodes`` of ``U``, ``V`` along the contact line).
    Snapshots: ``snap_t``, ``U``, ``V``, ``Ud``, ``Vd``, ``P``, ``Q``, ``gap``, ``state``.
    ``kernel``: the scheme state ``u, v, a`` and the reference ``ref`` (steady sliding).
    """

    MODEL: ClassVar[str] = "brake"

    FORMAT: ClassVar[RunFormat]
    scheme: object
    settings: dict
    series: dict
    snapshots: dict
    kernel: dict
    samples_done: int

    @property
    def params(self):
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

    @property
    def transits(self) -> float:
        return self.t_end / self.scheme.transit_time

    def __getattr__(self, name):
        for store in ("series", "snapshots"):
            data = self.__dict__.get(store, {})
            if name in data:
                return data[name]
        raise AttributeError(name)

    def to_dict(self) -> dict:
        """Parameters, scheme, schedule and progress (no arrays)."""
        s = self.scheme
        return {"params": self.params.to_dict(), **dict(zip(self.FORMAT.key_attrs, _scheme_key(s, self.FORMAT))),
                "dt": s.dt, "transit_time": s.transit_time, "transits": self.transits,
                "samples_done": self.samples_done, "complete": self.complete,
                **{k: v for k, v in self.settings.items() if k != "initial_hash"}}

    def to_xarray(self) -> xr.Dataset:
        """Snapshots over ``(snap_t, theta)``, series over ``t`` (and ``kind`` or ``mode``), with
        CF-style metadata; `from_xarray` reads it back."""
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


def run_to_dataset(run) -> xr.Dataset:
    fmt, s, st = run.FORMAT, run.scheme, run.settings
    N, K = s.theta.size, st["modes"] + 1
    ser, snp = run.series, run.snapshots

    def col(store, key, shape, dtype=float):  # none yet (or none since a resume): an empty column of its shape
        return np.asarray(store[key], dtype=dtype) if len(store.get(key, ())) else np.zeros(shape, dtype)

    T, S, X = "t", "snap_t", "theta"  # the series, snapshot and node dimensions, indexed by time and angle
    data = {
        "energy": (T, col(ser, "energy", 0), {"units": fmt.energy_units, "long_name": fmt.energy_note}),
        "kinetic": (T, col(ser, "kinetic", 0), {"units": fmt.energy_units, "long_name": "kinetic energy"}),
        "fraction": ((T, "kind"), col(ser, "fractions", (0, 4)),
                     {"units": "1", "long_name": f"fraction of {fmt.node_label}s in each state"}),
        "state": ((S, X), col(snp, "state", (0, N), np.int8), {"long_name": f"{fmt.node_label} state", **STATE_ATTRS}),
    }
    for name in ("U", "V"):
        z = col(ser, f"modes_{name}", (0, K), complex)
        for part, arr in (("re", z.real), ("im", z.imag)):
            data[f"modes_{name}_{part}"] = ((T, "mode"), arr, {"units": fmt.units["length"],
                                                               "long_name": f"{part} of rfft({name})/N"})
    for name, (units, long) in fmt.fields_of(s).items():
        data[name] = ((S, X), col(snp, name, (0, N)), {"units": units, "long_name": long})
    for name in _KERNEL:
        data[f"kernel_{name}"] = ("dof", run.kernel[name], {"units": fmt.units["length"],
                                                             "long_name": f"scheme state {name} for resuming"})
    coords = {T: (T, col(ser, "t", 0), {"units": fmt.time_units, "long_name": fmt.time_note}),
              S: (S, col(snp, "snap_t", 0), {"units": fmt.time_units, "long_name": f"{fmt.time_note} of the snapshot"}),
              X: (X, s.theta, {"units": "rad", "long_name": fmt.position_note or f"angle of the {fmt.node_label}"}),
              "kind": ("kind", list(STATE_NAMES), {"long_name": "contact state"}),
              "mode": ("mode", np.arange(K), {"units": "1", "long_name": fmt.mode_note}),
              **{name: (X, values, attrs) for name, (values, attrs) in fmt.extra_coords(s).items()}}
    attrs = {**s.params.to_attrs(), **dict(zip(fmt.key_attrs, _scheme_key(s, fmt))), **fmt.extra_attrs(s),
             "dt": s.dt, "transit_time": s.transit_time, "samples_done": run.samples_done,
             "complete": int(run.complete), **{k: (int(v) if isinstance(v, bool) else v) for k, v in st.items()},
             "source": fmt.source, "record": cls_name(run)}
    if st.get("volume_every"):
        W = "vol_t"  # the volume snapshots' dimension, indexed by time
        for name, (where, kind, long) in _VOLUME.items():
            dim, size = ("dof", run.kernel["u"].size) if where == "dof" else (X, N)
            data[name] = ((W, dim), col(snp, name, (0, size)), {"units": fmt.units[kind],
                                                                "long_name": fmt.notes.get(name, long)})
        for name, (units, long) in fmt.volume_extra(s).items():
            data[name] = ((W, X), col(snp, name, (0, N)), {"units": units, "long_name": long})
        data["vol_state"] = ((W, X), col(snp, "vol_state", (0, N), np.int8),
                             {"long_name": f"{fmt.node_label} state at the volume snapshot", **STATE_ATTRS})
        coords[W] = (W, col(snp, "vol_t", 0), {"units": fmt.time_units,
                                               "long_name": f"{fmt.time_note} of the volume snapshot"})
    return finish(xr.Dataset(data, coords=coords, attrs=attrs), fmt.title, fmt.model)


def cls_name(run) -> str:
    """The record type of a run (``FemRun``, ``RingRun``): a checkpoint of another model is refused."""
    return type(run).__name__


def _plain(value):
    return value.item() if hasattr(value, "item") else value


def _same(a, b) -> bool:
    """Two attribute values are the same (numbers exactly, arrays elementwise, text as text)."""
    try:
        return bool(np.array_equal(np.asarray(a), np.asarray(b)))
    except (TypeError, ValueError):
        return str(a) == str(b)


def dataset_to_run(cls, ds: xr.Dataset, scheme=None):
    """The run stored in ``ds``; its scheme rebuilt from the attributes, or ``scheme`` if given
    (a model whose parameters cannot be stored as attributes, a mesh say, passes its own)."""
    fmt, a = cls.FORMAT, ds.attrs
    if scheme is None:
        scheme = fmt.scheme(fmt.params_type.from_attrs(a), *[_plain(a[k]) for k in fmt.key_attrs])
    settings = {k: _plain(a[k]) if k in a or k != "volume_every" else 0 for k in _KEYS}  # 0: from before volumes
    settings["contact"] = bool(settings["contact"])
    series = {"t": ds["t"].values, "energy": ds["energy"].values, "kinetic": ds["kinetic"].values,
              "fractions": ds["fraction"].values}
    for name in ("U", "V"):
        series[f"modes_{name}"] = ds[f"modes_{name}_re"].values + 1j * ds[f"modes_{name}_im"].values
    snapshots = {"snap_t": ds["snap_t"].values, "state": ds["state"].values.astype(np.int8)}
    snapshots.update({name: ds[name].values for name in fmt.fields_of(scheme)})
    kernel = {name: ds[f"kernel_{name}"].values.copy() for name in _KERNEL}
    if "vol_t" in ds.variables and ds.sizes["vol_t"]:  # none yet: left out, the books start them
        snapshots.update({name: ds[name].values for name in ("vol_t", *_VOLUME, *fmt.volume_extra(scheme))})
        snapshots["vol_state"] = ds["vol_state"].values.astype(np.int8)
    return cls(scheme, settings, series, snapshots, kernel, int(a["samples_done"]))


def schedule(scheme, t_end, samples_per_transit, snapshot_every, tail) -> dict:
    """Steps per sample, number of samples, snapshot interval and tail length, in samples."""
    chunk = max(1, int(round(scheme.steps_per_transit / samples_per_transit)))
    total = int(np.ceil(t_end / (chunk * scheme.dt) - 1e-9))
    per_transit = scheme.steps_per_transit / chunk
    return {"chunk": chunk, "samples_total": max(total, 1),
            "snap_every": max(1, int(round(snapshot_every * per_transit))),
            "tail_samples": int(round(tail * per_transit))}


#: The largest run accepted, in dof-steps (degrees of freedom x time steps): about 4 hours of the
#: kernel at ~1.5 ns per dof-step. Larger requests are refused up front, not left to hang.
MAX_WORK = 1e13
#: The most numbers the volume snapshots of one run may hold (1.25e8 float64: 1 GB of memory).
MAX_VOLUME = 1.25e8


def prepare(scheme, *, t_end, transits, samples_per_transit, snapshot_every, tail, modes, contact, initial,
            progress, volume_every=None) -> tuple[float, dict]:
    """Validate the common options of a run; return ``t_end`` and the settings.

    ``volume_every`` (transits, optional) asks for volume snapshots (`volume_due`): every
    free dof's displacement and velocity, the contact nodes' reactions and states."""
    if (t_end is None) == (transits is None):
        raise ParameterError("t_end", t_end, "given (> 0), or else transits, but not both")
    t_end = Q.check("t_end", t_end) if transits is None else \
        Q.check("transits", transits) * scheme.transit_time
    dofs = scheme.sparse_operator.shape[0]
    length = ("t_end", t_end) if transits is None else ("transits", transits)
    if t_end / scheme.dt * dofs > MAX_WORK:
        limit = MAX_WORK / dofs * scheme.dt
        if getattr(scheme, "time_step", None):  # the user's step is what makes the run too long
            raise ParameterError("time_step", scheme.time_step, f">= {t_end * dofs / MAX_WORK:.4g} s for a run of "
                                 f"{t_end:.4g} s on this mesh ({dofs} dofs): at most {MAX_WORK:.0e} dof-steps per "
                                 "run (about 4 hours)", also=(length[0],))
        most = limit if transits is None else limit / scheme.transit_time
        raise ParameterError(*length, f"<= {most:.4g} on this mesh ({dofs} dofs, {scheme.dt:.3g} per step): "
                             f"at most {MAX_WORK:.0e} dof-steps per run (about 4 hours): a shorter run, or a "
                             "coarser mesh",
                             also=tuple(k for k in getattr(scheme, "MESH_KEYS", ("nodes", "n_theta", "n_r"))
                                        if hasattr(scheme, k)))
    spt = Q.check("samples_per_transit", samples_per_transit)
    if spt < 4:
        raise ParameterError("samples_per_transit", spt, "an integer >= 4")
    if progress is not None and not callable(progress):
        raise ParameterError("progress", progress, "a callable progress(t, t_end) or None")
    modes = min(Q.check("modes", modes), scheme.theta.size // 2)
    settings = {**schedule(scheme, t_end, spt, Q.check("snapshot_every", snapshot_every),
                           Q.check("tail", tail)),
                "samples_per_transit": spt, "modes": modes, "contact": bool(contact), "initial": initial.label,
                "initial_hash": initial.digest()}
    least = 3  # samples: with a tail of 3 samples or more, a run of 3 samples has 3 snapshots in it
    if 0 < tail and settings["chunk"] == 1 and settings["tail_samples"] < least:  # the step itself is too long
        step = scheme.dt / scheme.transit_time
        most = tail / least
        if getattr(scheme, "time_step", None):
            raise ParameterError("time_step", scheme.time_step, f"<= {most * scheme.transit_time:.4g} for the limit "
                                 f"regime's {least} snapshots in the last {tail:g} transits")
        raise ParameterError("mesh", f"a stable step of {step:.3g} transits", f"fine enough for a step of at most "
                             f"{most:.3g} transits (the limit regime is read from {least} snapshots in the last "
                             f"{tail:g}): refine it",
                             also=tuple(k for k in ("nodes", "n_theta", "n_r", "xi") if hasattr(scheme, k)
                                        or hasattr(getattr(scheme, "params", None), k)))
    if settings["tail_samples"] >= least and window_snapshots(settings) < 3:
        per = (t_end / length[1]) / (scheme.dt * settings["chunk"])  # samples per unit of the length typed
        raise ParameterError(*length, f"> {(least - 1) / per:.3g} here: the limit regime is read from at least 3 "
                             "snapshots at the end of the run",  # samples per transit: set by the mesh's step
                             also=("samples_per_transit",) + tuple(
                                 k for k in ("nodes", "n_theta", "n_r", "xi") if hasattr(scheme, k)
                                 or hasattr(getattr(scheme, "params", None), k)))
    settings["volume_every"] = 0 if volume_every is None else max(1, int(round(min(  # in samples
        Q.check("volume_every", volume_every) * scheme.steps_per_transit / settings["chunk"], 2.0**53))))
    if settings["volume_every"]:
        count = -(-settings["samples_total"] // settings["volume_every"]) + 1  # and one at t = 0
        size = dofs * 2 + scheme.theta.size * 3  # u and v of every free dof; P, Q and the state of the contact nodes
        if count * size > MAX_VOLUME:
            sample = settings["chunk"] * scheme.dt / scheme.transit_time  # in transits
            least = (settings["samples_total"] * size / max(MAX_VOLUME - 2 * size, size) + 1) * sample
            raise ParameterError("volume_every", volume_every, f">= {least:.3g} transits for this run ({count} volume "
                                 f"snapshots of {size} numbers; at most {MAX_VOLUME:.3g} numbers, 1 GB, in all)")
    return t_end, settings


#: The layout of a checkpoint; a file written with another layout is refused, not misread.
RUN_FORMAT = "stickslip-run-3"


def _digest(ds: xr.Dataset) -> str:
    return content_digest({name: ds[name].values for name in ds.variables})


#: The SI units of the symbols of the scaled models' units (the symbol ``M``, a modal mass, is a number).
_SI_SYMBOLS = {"R": {"m": 1}, "Omega": {"s": -1}, "E": {"Pa": 1}, "M": {}, "rad": {"rad": 1}}
_FACTOR = __import__("re").compile(r"^([A-Za-z]+)(?:\^(-?\d+))?$")


def _si(scale: str, values: dict):
    """``(factor, SI units)`` of a scaled unit (``"E R^2 / M"``, ``"R Omega"``, ``"1/Omega"``)
    given the symbols' SI ``values``, or None if a symbol is unknown."""
    factor, dims = 1.0, {}
    top, _, bottom = scale.partition("/")
    for sign, part in ((1, top), (-1, bottom)):
        for token in part.split():
            if token == "1":
                continue
            m = _FACTOR.match(token)
            if m is None or m.group(1) not in _SI_SYMBOLS or (m.group(1) not in values and m.group(1) != "rad"):
                return None
            power = sign * int(m.group(2) or 1)
            factor *= values.get(m.group(1), 1.0) ** power
            for unit, p in _SI_SYMBOLS[m.group(1)].items():
                dims[unit] = dims.get(unit, 0) + p * power
    dims = {u: p for u, p in dims.items() if p}
    if dims == {"Pa": 1, "m": 2}:  # an energy per unit thickness
        return factor, "J/m"
    up = " ".join(u + (str(p) if p != 1 else "") for u, p in dims.items() if p > 0) or "1"
    down = " ".join(u + (str(-p) if p != -1 else "") for u, p in dims.items() if p < 0)
    return factor, (f"{up}/{down}" if down else up)


def results_view(run) -> xr.Dataset:
    """The run as its file shows it: the series and snapshots (not the scheme's state, which the
    file keeps apart for resuming), in SI units when the run was set up in SI (the model's
    ``scales``): each scaled variable converted, its ``scale`` attribute replaced by SI units, the
    times in the model's scaled unit kept beside them as ``<time>_scaled``."""
    ds = run.to_xarray()
    ds = ds.drop_vars([f"kernel_{name}" for name in _KERNEL])
    values = run.FORMAT.scales(run.scheme)
    if not values:
        return ds
    for name in list(ds.variables):
        var = ds[name]
        scale = var.attrs.get("scale")
        found = None if scale is None else _si(str(scale), values)
        if found is None:
            continue
        factor, units = found
        attrs = {k: v for k, v in var.attrs.items() if k != "scale"}
        attrs.update(units=units, long_name=str(attrs.get("long_name", name)).replace(f" (in units of {scale})", ""))
        if name in ds.coords and var.dims == (name,):  # a time axis: its scaled values kept beside it
            ds = ds.assign_coords({f"{name}_scaled": (name, var.values, dict(var.attrs))})
            attrs["long_name"] = attrs["long_name"].replace("time Omega t", "time")
        ds[name] = (var.dims, var.values * factor, attrs)
    ds.attrs.update({f"si_{k}": v for k, v in values.items()})
    ds.attrs["units_note"] = ("SI units (converted from the model's scaled ones with si_R [m], si_Omega [rad/s], si_E "
                              "[Pa], si_M [1]; the times in the scaled unit are the *_scaled coordinates)")
    return ds


def save(run, path) -> None:
    """Write the run atomically (a kill during the write leaves the previous file): its results
    (`results_view`) at the root, and in the group ``checkpoint`` everything a resume needs,
    exactly, with a checksum of its content that `resume` verifies."""
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")
    state = run.to_xarray()
    digest = _digest(state)
    stamp = {"run_format": RUN_FORMAT, "content_sha256": digest}
    state.attrs.update(stamp)
    state = state.assign_coords(dof=("dof", np.arange(state.sizes.get("dof", 0), dtype=np.int64),
                                     {"units": "1", "long_name": "free degree of freedom number"}))
    results = results_view(run)
    results.attrs.update({**stamp, "results_sha256": _digest(results)})
    results.attrs["checkpoint"] = "the group checkpoint holds the scheme's state for resuming this run"
    to_netcdf(for_file(results), tmp, mode="w")
    to_netcdf(for_file(state), tmp, mode="a", group="checkpoint")
    os.replace(tmp, path)


#: How a difference in a key that is a digest is told (its value says nothing to a user).
_DIFFER = {"problem_sha256": "the problem (mesh, stiffness and springs, load, contact frames or clamped dofs)",
           "initial_hash": "the initial condition"}
#: How the schedule's internal keys are told.
_LABELS = {"chunk": "time steps per sample (set by the time step)", "snap_every": "samples between snapshots",
           "samples_per_transit": "samples per transit", "modes": "Fourier modes kept",
           "contact": "contact (1) or free (0)",
           "volume_every": "samples between volume snapshots (0: none; set by volume_every, on the command line by "
                           "--xdmf and --xdmf-every)",
           "initial": "initial condition", "step_given": "time step given [s] (0: none)"}
_AFRESH = "overwrite it to start afresh"


def held_transits(path) -> float | None:
    """Transits held by the checkpoint at ``path``, less one sample (None without a readable one).

    A run asked for ``T`` transits ends within one sample past ``T`` (`schedule`), so a held run
    of ``T`` gives a value below ``T``: a driver that lengthens a run in steps starts again at the
    first step not below it, where a run asked for less than it holds is refused (`resume`)."""
    try:
        with xr.open_dataset(path) as ds:
            a = ds.attrs
            sample = float(a["chunk"]) * float(a["dt"]) / float(a["transit_time"])
            held = (float(a["samples_done"]) - 1.0) * sample
    except (OSError, KeyError, ValueError, TypeError, ZeroDivisionError):
        return None
    return held if np.isfinite(held) else None


def resume(cls, path, scheme, settings):
    """The run stored at ``path`` if it is this run (else `ParameterError`), or None."""
    path = Path(path)
    if not path.exists():
        return None
    refused = ParameterError("checkpoint", str(path), "a checkpoint of the same run (parameters, scheme, schedule "
                             "and initial condition must match; " + _AFRESH + ")")
    try:
        root = from_file(xr.load_dataset(path))  # the results, whose attributes say what the file is
        attrs = dict(root.attrs)
    except (OSError, KeyError, ValueError, TypeError) as err:  # not netCDF, or damaged
        raise ParameterError("checkpoint", str(path), "a run's netCDF checkpoint (this file is not netCDF, or is "
                             f"damaged or empty; {_AFRESH})") from err
    if "run_format" not in attrs and str(attrs.get("source", "")).startswith("stickslip"):
        raise ParameterError("checkpoint", str(path), "a run's checkpoint (this file is another stickslip result: "
                             f"{attrs.get('title', 'not a run')}; give another path, or {_AFRESH})")
    if attrs.get("run_format") != RUN_FORMAT:
        raise ParameterError("checkpoint", str(path), f"a checkpoint in the run format {RUN_FORMAT} (this one: "
                             f"{attrs.get('run_format', 'none')}, written by another version or another program; "
                             + _AFRESH + ")")
    try:
        ds = from_file(xr.load_dataset(path, group="checkpoint")).drop_vars("dof", errors="ignore")
    except (OSError, KeyError, ValueError, TypeError) as err:  # no state to resume from, or a damaged one
        raise ParameterError("checkpoint", str(path), "a run's netCDF checkpoint with its group checkpoint (this "
                             f"file has none, or it is damaged; {_AFRESH})") from err
    if ds.attrs.get("run_format") != RUN_FORMAT:
        raise ParameterError("checkpoint", str(path), f"a checkpoint in the run format {RUN_FORMAT} (its state: "
                             f"{ds.attrs.get('run_format', 'none')}; " + _AFRESH + ")")
    if ds.attrs.get("source") != SOURCE or ds.attrs.get("record") != cls.__name__:
        raise ParameterError("checkpoint", str(path), f"a checkpoint of a {cls.__name__} written by {SOURCE} (this one: "
                             f"{ds.attrs.get('record', 'another record')} written by {ds.attrs.get('source', 'unknown')}; "
                             + _AFRESH + ")")
    if ds.attrs.get("content_sha256") != _digest(ds) or attrs.get("results_sha256") != _digest(root):
        raise ParameterError("checkpoint", str(path), "an intact checkpoint written by stickslip (its content does "
                             "not match its checksum: the file was changed or damaged; " + _AFRESH + ")")
    try:
        old = dataset_to_run(cls, ds, scheme)
        stored = {k: _plain(ds.attrs[k]) for k in (*plain_attrs(scheme.params.to_attrs()), *cls.FORMAT.key_attrs)}
    except (OSError, KeyError, ValueError, TypeError) as err:  # not a run of this model
        raise refused from err
    expected = {**plain_attrs(scheme.params.to_attrs()),
                **dict(zip(cls.FORMAT.key_attrs, _scheme_key(scheme, cls.FORMAT)))}
    differ = [(k, stored[k], v) for k, v in expected.items() if not _same(stored[k], v)]
    names = (*cls.FORMAT.key_attrs, *(k for k in _KEYS if k not in ("samples_total", "tail_samples")))
    differ += [(k, a, b) for k, a, b in zip(names, settings_key(old), settings_key(cls(scheme, settings, {}, {}, {}, 0)))
               if a != b and k not in dict((d[0], 0) for d in differ)]
    if any(k == "initial" for k, _, _ in differ):  # its label says it; the digest adds nothing
        differ = [d for d in differ if d[0] != "initial_hash"]
    if differ:
        raise ParameterError("checkpoint", str(path), "a checkpoint of the same run (it differs in " + "; ".join(
            _DIFFER.get(k, f"{_LABELS.get(k, k)}: stored {a!r}, now {b!r}") for k, a, b in differ) + "; " + _AFRESH
            + ")")
    if old.samples_done > settings["samples_total"]:
        end = settings["samples_total"] * settings["chunk"] * scheme.dt
        raise ParameterError("checkpoint", str(path), f"a checkpoint of a run no longer than the one asked for (it "
                             f"holds {old.t_end:.6g} {cls.FORMAT.time_units} ({old.transits:.4g} transits) where this "
                             f"run ends at {end:.6g} {cls.FORMAT.time_units} ({end / scheme.transit_time:.4g} "
                             f"transits): ask for at least as much to continue it, or {_AFRESH})")
    return cls(scheme, {**old.settings, "samples_total": settings["samples_total"],
                        "tail_samples": settings["tail_samples"]},
               old.series, old.snapshots, old.kernel, old.samples_done)


#: A displacement this many times the largest of the start and of steady sliding is a blown-up
#: run (no motion of an elastic body in contact grows by twelve orders of magnitude).
BLOW_UP = 1e12


#: Wall time [s] between two checkpoints of a run when no ``every`` is given: each one rewrites
#: the file, so a run checkpointed at fixed fractions of its length spent 1.7x its kernel on them.
CHECKPOINT_SECONDS = 60.0


def loop(run, checkpoint, every, progress, t_end, step: Callable, record: Callable):
    """Advance ``run`` to its last sample: ``step(kernel)`` advances one sample's steps,
    ``record(done, kernel, series, snaps)`` books it. A run that blows up (`BLOW_UP`) stops
    with a `NoSolutionError`; its checkpoint keeps the last good sample."""
    cls, s, st, k = type(run), run.scheme, run.settings, run.kernel
    series = {key: list(v) for key, v in run.series.items()}
    snaps = {key: list(v) for key, v in run.snapshots.items()}
    done, total, chunk = run.samples_done, st["samples_total"], st["chunk"]
    per_checkpoint = None if every is None else max(1, int(Q.check("every", every) / (chunk * s.dt)))
    saved = time.monotonic()

    def result():
        return cls(s, st, {key: np.asarray(v) for key, v in series.items()},
                   {key: np.asarray(v) for key, v in snaps.items()}, {key: v.copy() for key, v in k.items()}, done)

    scale = max(float(np.abs(k["u"]).max()), float(np.abs(k["ref"]).max())) or 1.0
    try:
        while done < total:
            good = {key: v.copy() for key, v in k.items()}
            try:
                step(k)
            except BaseException:  # a step that fails midway (a solver that stops) leaves no half-made state
                for key, value in good.items():
                    k[key][...] = value
                raise
            if not np.abs(k["u"]).max() < BLOW_UP * scale:  # blown up (or NaN): back to the last good state, kept
                for key, value in good.items():
                    k[key][...] = value
                t0 = done * chunk * s.dt
                raise NoSolutionError(
                    f"the run blew up between t = {t0:.6g} and {t0 + chunk * s.dt:.6g} (non-finite displacements; is "
                    f"the time step {s.dt:.3g} stable?)" + (f"; {checkpoint} keeps the last good state, at t = {t0:.6g}"
                                                           if checkpoint is not None else ""))
            done += 1
            record(done, k, series, snaps)
            if progress is not None:
                progress(done * chunk * s.dt, t_end)
            if checkpoint is not None and done < total and (
                    time.monotonic() - saved >= CHECKPOINT_SECONDS if per_checkpoint is None
                    else done % per_checkpoint == 0):
                save(result(), checkpoint)
                saved = time.monotonic()
    except BaseException:
        if checkpoint is not None and done > run.samples_done:
            save(result(), checkpoint)
        raise
    out = result()
    if checkpoint is not None:
        save(out, checkpoint)
    return out


def window_snapshots(st: dict) -> int:
    """The snapshots a run of settings ``st`` keeps in the window `stickslip.contact.classify`
    reads by default: its last ``tail_samples`` samples, every one of them a snapshot
    (`snapshot_due`; a snapshot's time is one step before its sample's end)."""
    return max(0, min(st["samples_total"], st["tail_samples"]))


def snapshot_due(done: int, st: dict) -> bool:
    """Snapshots every ``snap_every`` samples and at every sample of the tail."""
    return done % st["snap_every"] == 0 or done > st["samples_total"] - st["tail_samples"] or \
        done == st["samples_total"]


def volume_due(done: int, st: dict) -> bool:
    """Volume snapshots (if the run has them) every ``volume_every`` samples and at the last one (and
    one at ``t = 0``, `volume_at_start`)."""
    every = st.get("volume_every", 0)
    return bool(every) and (done % every == 0 or done == st["samples_total"])


def volume_at_start(scheme, u0, v0, st: dict, run_format) -> dict:
    """The volume snapshot at ``t = 0`` (if the run keeps volume snapshots): the start's
    displacement and velocity, and the reactions the scheme starts from (`ExplicitScheme.initial_state`:
    the steady ones at the contact nodes that touch, in forward slip; the others separated)."""
    if not st.get("volume_every"):
        return {}
    u0, v0 = np.asarray(u0, float), np.asarray(v0, float)
    touching = scheme.touching(u0) if st["contact"] else np.zeros(scheme.nodes, bool)
    _, r_n, r_t = scheme.steady_reference() if st["contact"] else (None, 0.0, 0.0)
    scale = run_format.traction_scale(scheme)
    return {"vol_t": [0.0], "vol_u": [u0.copy()], "vol_v": [v0.copy()], "vol_P": [scale * touching * r_n],
            "vol_Q": [scale * touching * r_t], "vol_state": [np.where(touching, SLIP_POS, SEPARATION).astype(np.int8)],
            **{name: [np.zeros(scheme.nodes)] for name in run_format.volume_extra(scheme)}}  # none across in steady sliding


def run_explicit(cls, scheme, u0, v0, settings: dict, t_end: float, *, checkpoint=None, every=None, progress=None,
                 overwrite: bool = False):
    """Run ``scheme`` from displacement ``u0`` and velocity ``v0`` with the books of ``cls``.

    ``settings`` come from `prepare`; with ``checkpoint`` the run resumes from the file if
    it holds this run (else `ParameterError`; ``overwrite=True`` starts afresh instead),
    and is written as it goes.
    """
    if not (isinstance(cls, type) and issubclass(cls, RunRecord)):
        raise ParameterError("cls", cls, "a RunRecord class (stickslip.contact.RunRecord or a subclass)")
    if not all(callable(getattr(scheme, name, None)) for name in ("initial_state", "steady_reference")):
        raise ParameterError("scheme", type(scheme).__name__, "an explicit scheme (stickslip.contact.ExplicitScheme)")
    if not isinstance(settings, dict) or "contact" not in settings:
        raise ParameterError("settings", settings, "the settings of stickslip.contact.prepare")
    with contextlib.ExitStack() as stack:
        if checkpoint is not None:  # one writer per checkpoint, for the whole run
            stack.enter_context(exclusive(checkpoint, "checkpoint"))
            if overwrite:
                Path(checkpoint).unlink(missing_ok=True)
        return _run_explicit(cls, scheme, u0, v0, settings, t_end, checkpoint, every, progress)


def _run_explicit(cls, scheme, u0, v0, settings, t_end, checkpoint, every, progress):
    run = resume(cls, checkpoint, scheme, settings) if checkpoint is not None else None
    if run is None:
        start = scheme.initial_state(u0, v0, settings["contact"])
        ref = scheme.steady_reference()[0] if settings["contact"] else np.zeros_like(start.u)
        run = cls(scheme, settings, {}, volume_at_start(scheme, u0, v0, settings, run_format=cls.FORMAT),
                  {"u": start.u, "v": start.v, "a": start.a, "ref": ref.copy()}, 0)
    out = scheme.new_output()
    normal, tangent = scheme.contact_dofs
    scale = run.FORMAT.traction_scale(scheme)
    st = run.settings
    extra = bool(run.FORMAT.extra_fields(scheme))

    def step(k):
        scheme.advance(StepState(k["u"], k["v"], k["a"]), st["chunk"], st["contact"], out)

    def record(done, k, series, snaps):
        m = done * st["chunk"] - 1  # index of the last step: fields at t_m
        u0_, u1 = out.u_prev, k["u"]
        kin, ela = scheme.energies(u0_, u1, k["ref"])
        U, V = u0_[normal], u0_[tangent]
        rec = {"t": m * scheme.dt, "kinetic": kin, "energy": kin + ela, "fractions": state_fractions(out.state),
               "modes_U": np.fft.rfft(U)[:st["modes"] + 1] / U.size, "modes_V": np.fft.rfft(V)[:st["modes"] + 1] / V.size}
        for key, v in rec.items():
            series.setdefault(key, []).append(v)
        if snapshot_due(done, st):
            fields = {"snap_t": m * scheme.dt, "U": U, "V": V, "Ud": (u1[normal] - U) / scheme.dt,
                      "Vd": (u1[tangent] - V) / scheme.dt, "P": scale * out.lam_n, "Q": scale * out.lam_t,
                      "gap": scheme.gaps(u1), "state": out.state.copy()}
            if extra:
                fields.update(scheme.snapshot_fields(out, u0_))
            for key, v in fields.items():
                snaps.setdefault(key, []).append(v)
        if volume_due(done, st):
            fields = {"vol_t": m * scheme.dt, "vol_u": u0_.copy(), "vol_v": k["v"].copy(), "vol_P": scale * out.lam_n,
                      "vol_Q": scale * out.lam_t, "vol_state": out.state.copy()}
            if extra:
                across = scheme.snapshot_fields(out, u0_)
                fields.update({name: across[name[4:]] for name in run.FORMAT.volume_extra(scheme)})
            for key, v in fields.items():
                snaps.setdefault(key, []).append(v)

    return loop(run, checkpoint, every, progress, t_end, step, record)

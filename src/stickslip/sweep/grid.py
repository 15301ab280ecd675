"""`run_sweep`: a function evaluated on every point of a grid, resumably."""

from __future__ import annotations

import functools
import itertools
import json
import logging
import math
import os
import shutil
from pathlib import Path
from typing import Callable, Mapping, Sequence

import dask
import numpy as np

from .. import validation as check
from ..cluster import check_scheduler, guarded, is_distributed, reachable
from ..errors import ParameterError
from ..files import exclusive
from ..quantities import COMMON as Q, MAX_POINTS
from ..cf import SOURCE
from .pool import worker_pool
from .store import create, damaged, failures, forget, is_vector, matches, open_group, result, tidy, write_points
from .stream import described, failure_error, stream

__all__ = ["run_sweep", "evaluate_point"]

log = logging.getLogger("stickslip.sweep")
#: dask's own names of its local schedulers, which `dask.compute` takes as well.
DASK_NAMES = ("sync", "single-threaded", "threading", "multiprocessing")


def evaluate_point(func, names: Sequence[str], sizes: Mapping[str, int], point: dict) -> list:
    """``func(**point)``'s outputs ``names`` in order (``sizes[name]`` numbers for a vector output)."""
    func = check.function("func", func)
    if isinstance(names, str) or not isinstance(names, Sequence) or not all(isinstance(n, str) for n in names):
        raise ParameterError("names", names, "a list of output names (text)")
    if not isinstance(sizes, Mapping) or not isinstance(point, Mapping):
        raise ParameterError("sizes" if not isinstance(sizes, Mapping) else "point",
                             sizes if not isinstance(sizes, Mapping) else point, "a mapping (dict)")
    result = func(**point)
    missing = [n for n in names if n not in result]
    if missing:
        raise ParameterError("func", getattr(func, "__name__", func), f"a function returning the outputs {missing}")
    out = []
    for n in names:
        if n not in sizes:
            out.append(float(result[n]))
            continue
        value = np.asarray(result[n], dtype=float).ravel()
        if value.size != sizes[n]:
            raise ParameterError("func", getattr(func, "__name__", func), f"a function returning {sizes[n]} numbers "
                                 f"for the output {n!r} (it returned {value.size})")
        out.append(value)
    return out


def run_sweep(func: Callable[..., Mapping[str, float]], axes: Mapping[str, Sequence[float]], store, *,
              outputs: Mapping[str, str], batch: int = 32, scheduler: str | Callable = "processes",
              progress: Callable[[int, int], None] | None = None, attrs: Mapping | None = None,
              workers: int | None = None, overwrite: bool = False, title: str = "parameter sweep",
              model: str = "common", keep_going: bool = False) -> "xarray.Dataset":  # noqa: F821
    """Evaluate ``func`` on a grid, resumably.

    Parameters
    ----------
    func : callable
        ``func(**point) -> {output: float}``; a top-level function for the process scheduler.
    axes : mapping
        Axis name -> values, e.g. ``{"belt_speed": [...], "damping": [...]}``.
    store : path
        Zarr directory. Created if absent (with its parents); if present with the same axes,
        outputs and ``attrs`` the sweep resumes, otherwise a `ParameterError` is raised: a store
        computed with other parameters or by another version is never reused. A stored point
        whose outputs no longer match its checksum (`stickslip.sweep.store`) is computed again,
        and a warning on the ``stickslip.sweep`` logger says so.
    outputs : mapping
        Output name -> units (floats, NaN until computed), or -> ``{meaning: code}`` for an
        output of integer codes (stored as ``int8`` with ``flag_values``/``flag_meanings``;
        `NOT_COMPUTED` until computed), or -> ``(units, size)`` for ``size`` floats per point
        (one more dimension, ``<name>_index``; the function returns an array).
    batch : int
        Points per write.
    scheduler : str, callable or distributed.Client
        ``"processes"`` (a local pool, in batches), ``"threads"``, ``"synchronous"`` or a callable
        as `dask.compute` takes them; or dask.distributed (`stickslip.cluster`): ``"distributed"``
        (a local cluster of ``workers`` processes), a running scheduler's address
        ``tcp://HOST:PORT``, or a `distributed.Client`. There every point is stored as it
        finishes (every ``batch`` points, and each within `FLUSH_SECONDS` of finishing), and a
        point that raises is left not done with its message in the store's ``failed`` attribute
        (JSON, keyed ``"i,j"`` by grid index) while the sweep goes on; at the end a
        `NoSolutionError` says how many failed (a later call computes them again). The
        dashboard's address and each failure are logged (``stickslip.sweep``).
    progress : callable, optional
        ``progress(done, total)`` after every write.
    workers : int, optional
        Processes for the ``"processes"`` scheduler (default: the CPU count); 1 runs the
        points in this process. Scripts that use more need the ``if __name__ ==
        "__main__":`` guard (spawned workers).
    overwrite : bool
        Start afresh, replacing the store, instead of resuming it.
    title, model : str
        The store's ``title`` attribute, and the vocabulary of its variables' units and
        long names (`stickslip.cf.finish`).
    keep_going : bool
        On the local schedulers too, a point that raises is stored with its message (as on
        dask.distributed) and the sweep goes on, instead of stopping it.

    Returns
    -------
    xarray.Dataset
        Every output on the grid, plus the ``done`` mask.
    """
    try:
        axes = {str(k): [check.finite(f"axes[{k!r}]", x) for x in v] for k, v in axes.items()}
    except (AttributeError, TypeError):
        raise ParameterError("axes", axes, "a mapping of names to lists of finite numbers") from None
    if not axes or any(len(v) == 0 for v in axes.values()):
        raise ParameterError("axes", axes, "a mapping of names to non-empty value lists")
    for name, values in axes.items():  # a value twice is a point computed twice on an axis that is no coordinate
        if len(set(values)) < len(values):
            raise ParameterError(f"axes[{name!r}]", values if len(values) <= 8 else f"{len(values)} values",
                                 "a list of distinct values (one repeats)")
    func = check.function("func", func)
    points = math.prod(len(v) for v in axes.values())
    if points > MAX_POINTS:
        raise ParameterError("axes", {k: len(v) for k, v in axes.items()}, f"a grid of at most {MAX_POINTS:.0e} points "
                             f"(this one has {points:.3g}: split the study, or run it on a cluster)")
    if not isinstance(outputs, Mapping) or not outputs or {"done", "checksum"} & set(outputs) or \
            not all(isinstance(k, str) and (isinstance(u, (str, Mapping)) or is_vector(u)) for k, u in outputs.items()):
        raise ParameterError("outputs", outputs, "a non-empty mapping of output names (not 'done' or 'checksum') to "
                             "units, to {meaning: code} or to (units, size)")
    outputs = dict(outputs)
    if not isinstance(store, (str, os.PathLike)):
        raise ParameterError("store", store, "a path (str or os.PathLike) of a Zarr directory")
    batch = Q.check("batch", batch)
    if not (isinstance(scheduler, str) and scheduler in DASK_NAMES) and (isinstance(scheduler, str) or not (callable(scheduler)
                                                                          or is_distributed(scheduler))):
        check_scheduler(scheduler)  # before the store is made
        if is_distributed(scheduler) and "://" in scheduler:
            reachable(scheduler)  # a server that is not a Dask scheduler is refused here, not mid-sweep
    if workers is not None:  # each worker process holds its own interpreter (about 200 MB)
        workers = Q.check("workers", workers)
    if scheduler == "processes" and workers == 1:
        scheduler = "synchronous"  # a pool of one only adds the start-up of a process
    store = Path(store)
    try:  # a store is created with its missing parents, like any output folder
        store.parent.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise ParameterError("store", str(store), f"a path whose parent folder can be made ({err.strerror})") from None
    with exclusive(store, "store"):  # one writer per store
        if overwrite and store.exists():
            shutil.rmtree(store)
        return _sweep(func, axes, store, outputs, batch, scheduler, workers, progress, attrs, title, model, keep_going)


def _producer(func) -> str:
    """``module.function`` of the point function (of a `functools.partial`, its function)."""
    while hasattr(func, "func"):
        func = func.func
    return f"{getattr(func, '__module__', '?')}.{getattr(func, '__qualname__', type(func).__name__)}"


def _sweep(func, axes, store, outputs, batch, scheduler, workers, progress, attrs, title, model, keep_going):
    attrs = {**dict(attrs or {}), "producer": _producer(func)}
    if store.exists():
        tidy(store)
        bad = damaged(store)  # first: a store that cannot be read is said to be damaged, whatever it holds
        if not matches(store, axes, outputs, attrs):
            raise ParameterError("store", str(store), "a new path, or a sweep store of the same computation (the same "
                                 f"producer, axes, outputs and fixed parameters, written by {SOURCE}; overwrite it "
                                 "to start afresh)")
        if bad:
            log.warning("%d stored point(s) of %s do not match their checksum (the first at grid index %s): "
                        "computed again", len(bad), store, bad[0])
            forget(store, bad)
    else:
        create(store, axes, outputs, attrs, title, model)
    group = open_group(store, "r+")
    names = list(outputs)
    sizes = {name: int(spec[1]) for name, spec in outputs.items() if is_vector(spec)}
    shape = tuple(len(v) for v in axes.values())
    todo = [idx for idx in itertools.product(*(range(n) for n in shape)) if not group["done"][idx]]
    total, finished = math.prod(shape), math.prod(shape) - len(todo)
    if progress:
        progress(finished, total)
    call = functools.partial(evaluate_point, func, names, sizes)
    if todo and is_distributed(scheduler):
        def tick(stored):
            nonlocal finished
            finished += stored
            if progress:
                progress(finished, total)

        stream(call, {idx: _point(axes, idx) for idx in todo}, store, group, names, sizes, batch, scheduler,
               workers, tick, total)
        return result(store)
    failed = failures(group)
    with worker_pool(scheduler if todo else "synchronous", workers) as evaluate:  # one pool for the whole sweep
        for start in range(0, len(todo), batch):
            chunk = todo[start:start + batch]
            if not keep_going:
                values = evaluate([dask.delayed(call)(_point(axes, idx)) for idx in chunk])
            else:  # each point's outcome: ("ok", values) or ("error", message)
                outcomes = evaluate([dask.delayed(guarded)(call, _point(axes, idx)) for idx in chunk])
                for idx, (status, value) in zip(chunk, outcomes):
                    key = ",".join(map(str, idx))
                    if status == "ok":
                        failed.pop(key, None)
                        continue
                    failed[key] = value
                    log.warning("point %s (%s) failed (%d so far): %s", idx, described(_point(axes, idx)),
                                len(failed), value)
                ok = [k for k, (status, _) in enumerate(outcomes) if status == "ok"]
                chunk, values = [chunk[k] for k in ok], [outcomes[k][1] for k in ok]
                group.attrs["failed"] = json.dumps(failed)
            if chunk:
                write_points(group, store, names, sizes, chunk, values)
            finished += len(chunk)
            if progress:
                progress(finished, total)
    if keep_going and failed:
        raise failure_error(failed, total, store)
    return result(store)


def _point(axes: dict, idx: tuple) -> dict:
    return {k: axes[k][i] for k, i in zip(axes, idx)}



"""Resumable parameter sweeps: a grid of independent runs, computed with Dask, stored in Zarr.

`run_sweep(func, axes, store, outputs=...)` evaluates ``func(**point)`` at every point of
the grid spanned by ``axes`` and writes each finished batch into a Zarr store together
with a ``done`` mask. If the run is killed, calling it again with the same store only
computes the points that are not done yet. The store records its format and a SHA-256 of
its content (`stickslip.files.content_digest`), so a store from another program or
version, or one damaged since (a flipped byte, a lost chunk), is refused, not resumed. The
batches go through ``dask.compute`` on local threads or processes; with
``scheduler="distributed"``, an address ``tcp://HOST:PORT`` or a `distributed.Client` the
points go to dask.distributed instead (`stickslip.cluster`): each is stored as it finishes,
and one that raises is stored with its message without stopping the sweep.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import multiprocessing
import os
import shutil
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import Callable, Mapping, Sequence

import dask
import numpy as np
import xarray as xr
import zarr

from . import validation as check
from .quantities import COMMON as Q, MAX_POINTS
from .cf import SOURCE, finish, flag_attrs, plain_attrs
from .errors import NoSolutionError, ParameterError
from .quantities import lookup
from .files import content_digest, die_with_parent, exclusive
from .cluster import client as dask_client, guarded, is_distributed

__all__ = ["worker_pool", "run_sweep", "verify_store", "SWEEP_FORMAT", "NOT_COMPUTED"]

#: The layout of a sweep store; a store with another layout is refused, not misread.
SWEEP_FORMAT = "stickslip-sweep-1"


#: The code of a point not computed yet, in an output of codes.
NOT_COMPUTED = -1


def _call(func, point: dict, names: Sequence[str], sizes: Mapping[str, int] | None = None) -> list:
    result = func(**point)
    missing = [n for n in names if n not in result]
    if missing:
        raise ParameterError("func", getattr(func, "__name__", func), f"a function returning the outputs {missing}")
    sizes = sizes or {}
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


def _vector(spec) -> bool:
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
    if _vector(spec):
        return (*dims, f"{name}_index"), np.full((*shape, int(spec[1])), np.nan), {"units": spec[0], "comment": note}
    return dims, np.full(shape, np.nan), {"units": spec, "comment": note}


def _create(store: Path, axes: dict, outputs: dict, attrs: dict, title: str, model: str) -> None:
    shape = tuple(len(v) for v in axes.values())
    data = {name: _variable(tuple(axes), shape, spec, name) for name, spec in outputs.items()}
    for name, (_, _, var_attrs) in data.items():  # named by the vocabulary of the model, else by the output's name
        var_attrs.setdefault("long_name", (lookup(name, model) or (None, name))[1])
    data["done"] = (tuple(axes), np.zeros(shape, np.int8), {"units": "1", "long_name": "point computed (1) or not (0)"})
    coords = {k: (k, np.asarray(v, float)) for k, v in axes.items()}
    params = plain_attrs(attrs)
    ds = finish(xr.Dataset(data, coords=coords), title, model, params={**params, "parameters": " ".join(params)})
    ds.to_zarr(store, mode="w", consolidated=False, zarr_format=2)  # v2: consolidated metadata is standard there
    group = _group(store, "r+")
    digest = _digest(group)
    group.attrs.update({"sweep_format": SWEEP_FORMAT, "content_sha256": digest, "pending_sha256": digest})
    zarr.consolidate_metadata(str(store))


def _group(store, mode: str):
    """The store's root group, read from its own metadata (never the consolidated copy, which
    is refreshed after each batch and may lag behind a killed write)."""
    return zarr.open_group(str(store), mode=mode, use_consolidated=False)


def _digest(group, replace: Mapping | None = None) -> str:
    """Checksum of every array of the store (``replace``: arrays about to be written instead)."""
    arrays = {name: group[name][...] for name in group.array_keys()}
    arrays.update(replace or {})
    return content_digest(arrays)


def verify_store(store) -> None:
    """Refuse (`ParameterError`) a store of another format, or whose content does not match its
    checksum. While a batch is written the store holds either its last or its next content
    (``pending_sha256``): a kill at any point leaves a store that verifies and resumes."""
    try:
        group = _group(store, "r")
        found = group.attrs.get("sweep_format")
        digest = _digest(group) if found == SWEEP_FORMAT else None
    except Exception as err:  # noqa: BLE001 - whatever a damaged store makes the decoder raise
        raise ParameterError("store", str(store), f"a readable sweep store ({type(err).__name__}: it is damaged; "
                             "overwrite it to start afresh)") from None
    if found != SWEEP_FORMAT:
        raise ParameterError("store", str(store), f"a sweep store in the format {SWEEP_FORMAT} (this one: {found}, "
                             "written by another version or program; overwrite it to start afresh)")
    if digest not in (group.attrs.get("content_sha256"), group.attrs.get("pending_sha256")):
        raise ParameterError("store", str(store), "an intact sweep store (its content does not match its checksum: "
                             "it was changed or damaged; overwrite it to start afresh)")


def _producer(func) -> str:
    """``module.function`` of the point function (of a `functools.partial`, its function)."""
    while hasattr(func, "func"):
        func = func.func
    return f"{getattr(func, '__module__', '?')}.{getattr(func, '__qualname__', type(func).__name__)}"


def _same_value(a, b) -> bool:
    try:
        return bool(np.array_equal(np.asarray(a, dtype=float), np.asarray(b, dtype=float)))
    except (TypeError, ValueError):
        return str(a) == str(b)


def _matches(store: Path, axes: dict, outputs: dict, attrs: dict) -> bool:
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


#: The environment variables that set a worker's BLAS and OpenMP threads (`worker_pool`).
BLAS_THREADS = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


@contextlib.contextmanager
def _environment(values: Mapping[str, str]):
    """Set the variables of ``values`` that the environment does not set, for the block."""
    added = [k for k in values if k not in os.environ]
    os.environ.update({k: values[k] for k in added})
    try:
        yield
    finally:
        for k in added:
            os.environ.pop(k, None)


@contextlib.contextmanager
def worker_pool(scheduler="processes", workers: int | None = None):
    """``evaluate(delayed_list) -> tuple``: `dask.compute` of Dask delayed calls on one pool for
    the whole block: spawned processes (``workers``, default the CPU count; they die with their
    parent) for the ``"processes"`` scheduler, else ``scheduler`` as `dask.compute` takes it
    (``"synchronous"``, ``"threads"``, ``client.get``). Each worker's BLAS and OpenMP get the
    CPUs over the workers (`BLAS_THREADS`, unless the caller's environment sets them): a CEA
    on 37k dofs took 15.9 s on one thread and 16.3 s on two, and two workers of two threads
    each on two cores made a sweep 1.6 times slower than the same CEAs one after another."""
    with contextlib.ExitStack() as stack:
        extra = {}
        if scheduler == "processes":
            share = str(max(1, (os.cpu_count() or 1) // (workers or os.cpu_count() or 1)))
            stack.enter_context(_environment({name: share for name in BLAS_THREADS}))
            context = multiprocessing.get_context("spawn")
            extra["pool"] = stack.enter_context(ProcessPoolExecutor(workers, mp_context=context,
                                                                    initializer=die_with_parent))
        yield lambda calls: dask.compute(*calls, scheduler=scheduler, **extra)


def run_sweep(func: Callable[..., Mapping[str, float]], axes: Mapping[str, Sequence[float]], store, *,
              outputs: Mapping[str, str], batch: int = 32, scheduler: str | Callable = "processes",
              progress: Callable[[int, int], None] | None = None, attrs: Mapping | None = None,
              workers: int | None = None, overwrite: bool = False, title: str = "parameter sweep",
              model: str = "common") -> xr.Dataset:
    """Evaluate ``func`` on a grid, resumably.

    Parameters
    ----------
    func : callable
        ``func(**point) -> {output: float}``; a top-level function for the process scheduler.
    axes : mapping
        Axis name -> values, e.g. ``{"belt_speed": [...], "damping": [...]}``.
    store : path
        Zarr directory. Created if absent (with its parents); if present with the same axes, outputs and
        ``attrs``, and intact, the sweep resumes, otherwise a `ParameterError` is raised: a
        store computed with other parameters, by another version or damaged is never reused.
    outputs : mapping
        Output name -> units (floats, NaN until computed), or -> ``{meaning: code}`` for an
        output of integer codes (stored as ``int8`` with ``flag_values``/``flag_meanings``;
        `NOT_COMPUTED` until computed), or -> ``(units, size)`` for ``size`` floats per point
        (one more dimension, ``<name>_index``; the function returns an array).
    batch : int
        Points per checkpoint.
    scheduler : str, callable or distributed.Client
        ``"processes"`` (a local pool, in batches), ``"threads"``, ``"synchronous"`` or a callable
        as `dask.compute` takes them; or dask.distributed (`stickslip.cluster`): ``"distributed"``
        (a local cluster of ``workers`` processes), a running scheduler's address
        ``tcp://HOST:PORT``, or a `distributed.Client`. There every point is stored as it
        finishes (every ``batch`` points, and each within `FLUSH_SECONDS` of finishing), and a point that raises is left not done with its message in the store's
        ``failed`` attribute (JSON, keyed ``"i,j"`` by grid index) while the sweep goes on;
        at the end a `NoSolutionError` says how many failed (a later call computes them again).
    progress : callable, optional
        ``progress(done, total)`` after every batch.
    workers : int, optional
        Processes for the ``"processes"`` scheduler (default: the CPU count); 1 runs the
        points in this process. Scripts that use more need the ``if __name__ ==
        "__main__":`` guard (spawned workers).

    overwrite : bool
        Start afresh, replacing the store, instead of resuming it.
    title, model : str
        The store's ``title`` attribute, and the vocabulary of its variables' units and
        long names (`stickslip.cf.finish`).

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
    points = math.prod(len(v) for v in axes.values())
    if points > MAX_POINTS:
        raise ParameterError("axes", {k: len(v) for k, v in axes.items()}, f"a grid of at most {MAX_POINTS:.0e} points "
                             f"(this one has {points:.3g}: split the study, or run it on a cluster)")
    if not isinstance(outputs, Mapping) or not outputs or "done" in outputs or \
            not all(isinstance(k, str) and (isinstance(u, (str, Mapping)) or _vector(u)) for k, u in outputs.items()):
        raise ParameterError("outputs", outputs, "a non-empty mapping of output names (not 'done') to units, "
                             "to {meaning: code} or to (units, size)")
    outputs = dict(outputs)
    if not isinstance(store, (str, os.PathLike)):
        raise ParameterError("store", store, "a path (str or os.PathLike) of a Zarr directory")
    batch = Q.check("batch", batch)
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
        return _sweep(func, axes, store, outputs, batch, scheduler, workers, progress, attrs, title, model)


def _sweep(func, axes, store, outputs, batch, scheduler, workers, progress, attrs, title, model):
    attrs = {**dict(attrs or {}), "producer": _producer(func)}
    if store.exists():
        verify_store(store)  # first: a damaged store is said to be damaged, whatever it holds
        if not _matches(store, axes, outputs, attrs):
            raise ParameterError("store", str(store), "a new path, or a sweep store of the same computation (the same "
                                 f"producer, axes, outputs and fixed parameters, written by {SOURCE}; overwrite it "
                                 "to start afresh)")
    else:
        _create(store, axes, outputs, attrs, title, model)
    group = _group(store, "r+")
    names = list(outputs)
    sizes = {name: int(spec[1]) for name, spec in outputs.items() if _vector(spec)}
    shape = tuple(len(v) for v in axes.values())
    todo = [idx for idx in itertools.product(*(range(n) for n in shape)) if not group["done"][idx]]
    total, finished = math.prod(shape), math.prod(shape) - len(todo)
    if progress:
        progress(finished, total)
    if todo and is_distributed(scheduler):
        _stream(func, axes, store, group, names, sizes, todo, batch, scheduler, workers, progress, finished, total)
        return _result(store)
    with worker_pool(scheduler if todo else "synchronous", workers) as evaluate:  # one pool for the whole sweep
        for start in range(0, len(todo), batch):
            chunk = todo[start:start + batch]
            points = [{k: axes[k][i] for k, i in zip(axes, idx)} for idx in chunk]
            values = evaluate([dask.delayed(_call)(func, p, names, sizes) for p in points])
            _write(group, store, names, sizes, chunk, values)
            finished += len(chunk)
            if progress:
                progress(finished, total)
    return _result(store)


#: A streaming sweep writes what has finished at least this often [s] (and every ``batch`` points).
FLUSH_SECONDS = 10.0


def _stream(func, axes, store, group, names, sizes, todo, batch, scheduler, workers, progress, finished, total):
    """The points ``todo`` on dask.distributed (`stickslip.cluster`), stored as they finish
    (every ``batch`` points, and each within `FLUSH_SECONDS` of finishing: no point waits for a
    slower one); a point that raises is left not done, its message in the store's
    ``failed`` attribute (JSON ``{"i,j": message}``), the sweep goes on, and at its end a
    `NoSolutionError` says how many failed."""
    import json
    import time

    from distributed import as_completed

    failed = json.loads(group.attrs.get("failed", "{}"))
    ready, values = [], []
    last = time.monotonic()

    def flush(tell=True):
        nonlocal finished, last
        if ready:
            _write(group, store, names, sizes, list(ready), list(values))
            finished += len(ready)
            ready.clear()
            values.clear()
        group.attrs["failed"] = json.dumps(failed)
        zarr.consolidate_metadata(str(store))
        last = time.monotonic()
        if progress and tell:
            progress(finished, total)

    share = str(max(1, (os.cpu_count() or 1) // (workers or os.cpu_count() or 1)))  # BLAS threads per local worker
    with _environment({name: share for name in BLAS_THREADS}), dask_client(scheduler, workers) as cl:
        futures = {}
        for idx in todo:
            point = {k: axes[k][i] for k, i in zip(axes, idx)}
            futures[cl.submit(guarded, _call, func, point, names, sizes, pure=False)] = idx
        # results fetched as they finish (a worker that dies later holds none of them), stored at
        # least every FLUSH_SECONDS while any has come in; SIGTERM (a batch system ending the job)
        # stops the sweep as Ctrl-C does, after storing what has finished
        completed = as_completed(list(futures), with_results=True, raise_errors=False)
        try:
            with _terminate_as_interrupt():
                while futures:
                    arrived = completed.next_batch(block=False)
                    if not arrived:
                        time.sleep(0.05)
                    for future, outcome in arrived:
                        _book(futures.pop(future), future, outcome, ready, values, failed)
                        future.release()
                    if len(ready) >= batch or (ready and time.monotonic() - last >= FLUSH_SECONDS):
                        flush()
        except BaseException:  # interrupted (Ctrl-C, SIGTERM, a progress callback raising): keep what finished
            flush(tell=False)
            raise
        flush()
    if failed:
        first = next(iter(failed.items()))
        raise NoSolutionError(f"{len(failed)} of {total} points failed (the first, at grid index ({first[0]}): "
                              f"{first[1]}); the others are stored in {store}, these are left not done with their "
                              "messages in its failed attribute, and a rerun computes them again")


def _book(idx, future, outcome, ready, values, failed) -> None:
    """One finished future: its values, or why it failed (the point raised; or the scheduler gave
    up on it, its workers dying, or cancelled it)."""
    key = ",".join(map(str, idx))
    if future.status == "finished" and isinstance(outcome, tuple) and len(outcome) == 2:
        status, value = outcome
        if status == "ok":
            ready.append(idx)
            values.append(value)
            failed.pop(key, None)
            return
        failed[key] = value
        return
    why = outcome[1] if isinstance(outcome, tuple) and len(outcome) == 3 else outcome  # (type, exception, tb)
    failed[key] = f"{future.status}: {type(why).__name__}: {why}"


@contextlib.contextmanager
def _terminate_as_interrupt():
    """SIGTERM raises KeyboardInterrupt in the block (main thread only; restored after)."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def interrupt(signum, frame):
        raise KeyboardInterrupt("SIGTERM")

    previous = signal.signal(signal.SIGTERM, interrupt)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _result(store: Path) -> xr.Dataset:
    return xr.open_zarr(store, consolidated=False).load()


def _write(group, store: Path, names: list, sizes: dict, chunk: list, values: list) -> None:
    """Store the ``values`` of the points ``chunk`` (grid indices) and mark them done, so that a
    kill at any moment leaves the store's last or next content (`verify_store`)."""
    where = tuple(np.array(c) for c in zip(*chunk))
    new = {name: group[name][...] for name in [*names, "done"]}
    for j, name in enumerate(names):
        new[name][where] = np.array([v[j] for v in values])
    new["done"][where] = True
    group.attrs["pending_sha256"] = _digest(group, new)
    for name in names:
        if name in sizes:  # a row per point
            for idx in chunk:
                group[name][idx] = new[name][idx]
        else:
            group[name].vindex[where] = new[name][where]
    group["done"].vindex[where] = True  # last: a batch counts only once all outputs are in
    group.attrs["content_sha256"] = group.attrs["pending_sha256"]
    if "failed" in group.attrs:  # a point computed now no longer counts as failed
        import json

        failed = json.loads(group.attrs["failed"])
        group.attrs["failed"] = json.dumps({k: v for k, v in failed.items()
                                            if tuple(int(i) for i in k.split(",")) not in set(map(tuple, chunk))})
    zarr.consolidate_metadata(str(store))

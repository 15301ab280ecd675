"""A sweep's points on dask.distributed, each stored as it finishes (no batch barrier)."""

from __future__ import annotations

import contextlib
import json
import logging
import time
from typing import Callable

from ..cluster import client as dask_client, guarded
from ..errors import NoSolutionError
from .pool import blas_share
from .store import failures, write_points

__all__ = ["FLUSH_SECONDS", "stream", "failure_error", "described"]

log = logging.getLogger("stickslip.sweep")

#: A streaming sweep writes what has finished at least this often [s] (and every ``batch`` points).
FLUSH_SECONDS = 10.0


def stream(call: Callable, points: dict, store, group, names, sizes, batch, scheduler, workers, tick,
           total: int) -> None:
    """Compute ``points`` (grid index -> keyword arguments of ``call``) on dask.distributed
    (`stickslip.cluster`), stored as they finish: every ``batch`` points, and each within
    `FLUSH_SECONDS` of finishing, so no point waits for a slower one. A point that raises is
    left not done, its message in the store's ``failed`` attribute (JSON ``{"i,j":
    message}``), the sweep goes on, and at its end a `NoSolutionError` says how many failed.
    ``tick(stored)`` after each write; the dashboard's address and each failure are logged
    (``stickslip.sweep``)."""
    from distributed import as_completed

    failed = failures(group)
    ready, values = [], []
    last = time.monotonic()

    def flush(tell=True):
        nonlocal last
        stored = len(ready)
        if ready:
            write_points(group, store, names, sizes, list(ready), list(values))
            ready.clear()
            values.clear()
        group.attrs["failed"] = json.dumps(failed)
        last = time.monotonic()
        if tell:
            tick(stored)

    with blas_share(workers), dask_client(scheduler, workers) as cl:
        if getattr(cl, "dashboard_link", None):
            log.info("Dask dashboard: %s", cl.dashboard_link)
        futures = {cl.submit(guarded, call, point, pure=False): idx for idx, point in points.items()}
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
                        idx = futures.pop(future)
                        if not _book(idx, future, outcome, ready, values, failed):
                            log.warning("point %s (%s) failed (%d so far): %s", idx, described(points[idx]),
                                        len(failed), failed[",".join(map(str, idx))])
                        future.release()
                    if len(ready) >= batch or (ready and time.monotonic() - last >= FLUSH_SECONDS):
                        flush()
        except BaseException:  # interrupted (Ctrl-C, SIGTERM, a progress callback raising): keep what finished
            flush(tell=False)
            raise
        flush()
    if failed:
        raise failure_error(failed, total, store)


def failure_error(failed: dict, total: int, store) -> NoSolutionError:
    """The error that ends a sweep in which the points ``failed`` (``{"i,j": message}``) failed."""
    first = next(iter(failed.items()))
    return NoSolutionError(f"{len(failed)} of {total} points failed (the first, at grid index ({first[0]}): "
                           f"{first[1]}); the others are stored in {store}, these are left not done with their "
                           "messages in its failed attribute, and a rerun computes them again")


def described(point: dict) -> str:
    """``name = value, ...`` of a point's parameters."""
    return ", ".join(f"{k} = {v:g}" if isinstance(v, float) else f"{k} = {v}" for k, v in point.items())


def _book(idx, future, outcome, ready, values, failed) -> bool:
    """One finished future: its values (True), or why it failed (False: the point raised; or
    the scheduler gave up on it, its workers dying, or cancelled it)."""
    key = ",".join(map(str, idx))
    if future.status == "finished" and isinstance(outcome, tuple) and len(outcome) == 2:
        status, value = outcome
        if status == "ok":
            ready.append(idx)
            values.append(value)
            failed.pop(key, None)
            return True
        failed[key] = value
        return False
    why = outcome[1] if isinstance(outcome, tuple) and len(outcome) == 3 else outcome  # (type, exception, tb)
    failed[key] = f"{future.status}: {type(why).__name__}: {why}"
    return False


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

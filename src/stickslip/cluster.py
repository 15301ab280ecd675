"""Dask.distributed for the sweeps: a local cluster of processes, or an existing scheduler.

`is_distributed(scheduler)` tells a distributed scheduler from the others `stickslip.sweep`
takes: ``"distributed"`` (a `distributed.LocalCluster` of ``workers`` processes, one thread
each, started for the sweep and closed after it), an address ``tcp://HOST:PORT`` (or ``tls://``,
``ucx://``, ``inproc://``) of a running scheduler (its workers started by hand, or by
``dask-jobqueue`` on a batch system), or a `distributed.Client`. `client(scheduler, workers)`
yields the `distributed.Client` and says where its dashboard is, when it has one.

The point function runs in the workers as `guarded` calls it: an exception becomes a record
``("error", message)`` instead of a failed task, so that one bad point is stored with its
message and the sweep goes on. A worker that dies (killed, out of memory) loses only its
running point: the scheduler gives it to another worker (up to ``distributed.scheduler.
allowed-failures`` times, then the point is recorded as failed with the scheduler's reason).
"""

from __future__ import annotations

import contextlib
import os

from .errors import ParameterError

__all__ = ["is_distributed", "check_scheduler", "client", "guarded", "reachable", "PROTOCOLS", "CONNECT_SECONDS"]

#: Address prefixes of a running scheduler.
PROTOCOLS = ("tcp://", "tls://", "ucx://", "inproc://")
#: How long to wait for a scheduler at an address before refusing it.
CONNECT_SECONDS = 10.0


def is_distributed(scheduler) -> bool:
    """``"distributed"``, a scheduler's address, or a `distributed.Client`."""
    if isinstance(scheduler, str):
        return scheduler == "distributed" or scheduler.startswith(PROTOCOLS)
    return type(scheduler).__name__ == "Client" and type(scheduler).__module__.startswith("distributed")


def check_scheduler(value, option: str = "scheduler"):
    """``value`` if it names a scheduler the sweeps take by name (``processes``, ``distributed``,
    ``threads``, ``synchronous``, or an address ``tcp://HOST:PORT``), else a `ParameterError`
    naming ``option``."""
    if value is None:
        return None
    if isinstance(value, str) and (value in ("processes", "distributed", "threads", "synchronous") or (
            value.startswith(PROTOCOLS) and len(value.split("://", 1)[1]) > 0)):
        return value
    raise ParameterError(option, value, "processes (a local pool of processes), distributed (a local Dask cluster), "
                         "the address tcp://HOST:PORT of a running Dask scheduler, or threads or synchronous")


@contextlib.contextmanager
def client(scheduler, workers: int | None = None, announce=None):
    """The `distributed.Client` of ``scheduler`` (see the module docstring) for the block;
    ``announce(text)``, if given, is told the scheduler's and the dashboard's addresses."""
    from distributed import Client, LocalCluster

    if not isinstance(scheduler, str):  # the caller's client: used, not closed
        yield scheduler
        return
    with contextlib.ExitStack() as stack:
        if scheduler == "distributed":
            cluster = stack.enter_context(LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                                       processes=True, host="127.0.0.1", dashboard_address=":0"))
            made = stack.enter_context(Client(cluster))
        else:
            try:
                made = stack.enter_context(Client(scheduler, timeout=CONNECT_SECONDS))
            except Exception as err:  # noqa: BLE001 - a server that is not Dask makes the protocol raise anything
                raise ParameterError("scheduler", scheduler, f"the address of a running Dask scheduler ({type(err).__name__}: "
                                     f"none answered as one within {CONNECT_SECONDS:g} s)") from None
        if announce is not None:
            link = getattr(made, "dashboard_link", None)
            announce(f"Dask scheduler {made.scheduler.address}" + (f", dashboard {link}" if link else ""))
        yield made


def reachable(address: str, option: str = "scheduler") -> None:
    """Refuse (`ParameterError` naming ``option``) an address ``tcp://HOST:PORT`` where nothing
    answers within `CONNECT_SECONDS` (checked before any work)."""
    import socket

    host, _, port = address.split("://", 1)[1].rpartition(":")
    try:
        with socket.create_connection((host.strip("[]"), int(port)), timeout=CONNECT_SECONDS):
            pass
    except (OSError, ValueError) as err:
        raise ParameterError(option, address, f"the address of a running Dask scheduler (tcp://HOST:PORT; "
                             f"{type(err).__name__}: none answered within {CONNECT_SECONDS:g} s)") from None
    identity = _identity(address)
    if not isinstance(identity, dict) or identity.get("type") != "Scheduler":
        why = identity if isinstance(identity, str) else f"it says it is {identity!r:.60}"
        raise ParameterError(option, address, "the address of a running Dask scheduler (a server answers there, "
                             f"but not as a Dask scheduler within {2 * CONNECT_SECONDS:g} s: {why})")


def _identity(address: str):
    """What the server at ``address`` says it is, asked in Dask's own protocol (its handshake, then
    the ``identity`` request every Dask server answers); a string saying why if it could not be
    asked: garbage, silence (at most 2 x `CONNECT_SECONDS`) or a closed connection."""
    import asyncio

    async def ask():
        from distributed.comm import connect

        comm = await connect(address, timeout=CONNECT_SECONDS)
        try:
            await comm.write({"op": "identity"})
            return await comm.read()
        finally:
            comm.abort()

    try:
        return asyncio.run(asyncio.wait_for(ask(), 2 * CONNECT_SECONDS))
    except Exception as err:  # noqa: BLE001 - whatever a server that is not Dask makes the protocol raise
        return f"{type(err).__name__}: {str(err)[:80] or 'no answer'}"


def guarded(func, *args):
    """``("ok", func(*args))``, or ``("error", message)`` if it raises (in the worker)."""
    try:
        return ("ok", func(*args))
    except Exception as err:  # noqa: BLE001 - any point may fail; it is stored, not raised
        return ("error", f"{type(err).__name__}: {err}")

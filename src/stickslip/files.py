"""Files that several processes could touch: one writer at a time, and workers that do not
outlive the process that started them.

`exclusive(path, option)` holds an advisory lock (``fcntl.flock``) on ``<path>.lock`` for
as long as a run writes ``path`` (a checkpoint, a sweep store). A second run on the same
file is refused at once with a `ParameterError` naming the option, instead of the two
overwriting each other. The lock dies with its process, so a killed run leaves no stale
lock. (On a system without ``fcntl`` the lock is a no-op.)

`die_with_parent` is a process-pool initializer: on Linux the worker asks the kernel to
kill it when its parent dies, so killing a sweep leaves no worker behind.

`content_digest(arrays)` is the SHA-256 of named arrays (name, shape, type and bytes):
checkpoints and sweep stores carry it, and a file whose content no longer matches it (a
flipped byte, a lost chunk, a value edited by hand) is refused instead of resumed.

`to_netcdf(ds, path, **options)` is `xarray.Dataset.to_netcdf` without the cost of asking
for a Dask cluster when there can be none: xarray asks Dask which scheduler is active, and
Dask imports `distributed` to look for a client (0.3-0.7 s on a process's first file). A
process that has not imported `distributed` has no client, so the question is skipped.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import signal
import sys
from pathlib import Path
from typing import Mapping

import numpy as np

from .errors import ParameterError

try:
    import fcntl
except ImportError:  # pragma: no cover - not POSIX
    fcntl = None

__all__ = ["exclusive", "die_with_parent", "content_digest", "to_netcdf", "write_xdmf_series"]


def to_netcdf(ds, path, **options) -> None:
    """``ds.to_netcdf(path, **options)``; when `distributed` was never imported in this process
    (so no Dask client exists), without importing it to look for one."""
    if not hasattr(ds, "to_netcdf") or not isinstance(path, (str, os.PathLike)):
        raise ParameterError("ds" if not hasattr(ds, "to_netcdf") else "path", ds if not hasattr(ds, "to_netcdf") else path,
                             "an xarray.Dataset" if not hasattr(ds, "to_netcdf") else "a path (str or os.PathLike)")
    names = ("distributed", "dask.distributed")
    if any(name in sys.modules for name in names):  # imported (a client may exist), or guarded
        ds.to_netcdf(path, **options)
        return
    for name in names:
        sys.modules[name] = None  # an import of it raises ImportError: "no cluster"
    try:
        ds.to_netcdf(path, **options)
    finally:
        for name in names:
            if sys.modules.get(name, 0) is None:
                del sys.modules[name]


def content_digest(arrays: Mapping[str, object]) -> str:
    """SHA-256 of every array's name, shape, type and values (a changed byte changes it)."""
    if not isinstance(arrays, Mapping):
        raise ParameterError("arrays", arrays, "a mapping of names to arrays")
    digest = hashlib.sha256()
    for name in sorted(map(str, arrays)):
        values = np.asarray(arrays[name])
        digest.update(f"{name}|{values.shape}|".encode())
        if values.dtype.kind in "biuf":
            digest.update(values.dtype.str.encode() + np.ascontiguousarray(values).tobytes())
        else:
            digest.update(repr(values.tolist()).encode())
    return digest.hexdigest()


@contextlib.contextmanager
def exclusive(path, option: str):
    """Hold the write lock of ``path`` (``<path>.lock`` beside it), or raise `ParameterError`."""
    path = Path(path)
    if fcntl is None:
        yield path
        return
    lock = path.with_name(path.name + ".lock")
    while True:
        try:
            fd = os.open(lock, os.O_RDWR | os.O_CREAT, 0o644)
        except (FileNotFoundError, NotADirectoryError, PermissionError) as err:
            raise ParameterError(option, str(path), f"a path in an existing, writable folder ({type(err).__name__} "
                                                   f"for {path.parent})") from None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise ParameterError(option, str(path), "a path no other run is writing (another stickslip process "
                                                   "holds it now; wait for it, or use another path)") from None
        try:  # the lock file may have been removed by its previous holder meanwhile: take the new one
            same = os.stat(lock).st_ino == os.fstat(fd).st_ino
        except FileNotFoundError:
            same = False
        if same:
            break
        os.close(fd)
    try:
        os.ftruncate(fd, 0)
        os.write(fd, str(os.getpid()).encode())
        yield path
    finally:
        with contextlib.suppress(OSError):
            os.unlink(lock)  # while still held: nobody can have locked this file in between
        os.close(fd)


def die_with_parent() -> None:
    """Ask the kernel to send SIGKILL to this process when its parent dies (Linux only)."""
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):  # pragma: no cover - not Linux
        pass


def write_xdmf_series(path, points: np.ndarray, cells: list, steps) -> Path:
    """Write a mesh and a time series of fields for ParaView: ``path`` (``.xdmf``) and its
    HDF5 data beside it (``path.with_suffix(".h5")``), with meshio's ``xdmf.TimeSeriesWriter``.

    ``points`` ``(n, 3)``, ``cells`` ``[(meshio cell type, connectivity)]``, ``steps`` an
    iterable of ``(time, point_data, cell_data)``. The files are written in a hidden folder
    beside ``path`` and moved into place, the ``.h5`` first: an interrupted write leaves no
    partial file under either name (a kill between the two moves would pair an older
    ``.xdmf`` with the new ``.h5``). meshio 5.3 would put the HDF5 file in the working folder
    (meshio issue 1442): the writer here puts it beside the XDMF file.
    """
    if not isinstance(path, (str, os.PathLike)):
        raise ParameterError("path", path, "a path (str or os.PathLike) ending in .xdmf")
    import shutil
    import tempfile

    import h5py
    from meshio.xdmf import TimeSeriesWriter

    class Writer(TimeSeriesWriter):
        def __enter__(self):
            self.h5_filename = str(self.filename.with_suffix(".h5"))
            self.h5_file = h5py.File(self.h5_filename, "w")
            return self

    path = Path(path)
    if path.suffix.lower() != ".xdmf" or not path.parent.is_dir():
        raise ParameterError("path", str(path), "a file name ending in .xdmf in an existing folder")
    tmp = Path(tempfile.mkdtemp(prefix=f".{path.stem}-", suffix=".tmp", dir=path.parent))
    try:
        with Writer(tmp / path.name) as writer:
            writer.write_points_cells(points, cells)
            for t, point_data, cell_data in steps:
                writer.write_data(float(t), point_data=point_data, cell_data=cell_data)
        os.replace(tmp / path.with_suffix(".h5").name, path.with_suffix(".h5"))
        os.replace(tmp / path.name, path)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return path

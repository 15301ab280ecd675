"""Run one command-line trial in a forked child with a time limit (issue 9's harness).

A trial that hangs inside compiled code (numba, LAPACK) cannot be interrupted by a signal
handler in the same process; a forked child can be killed. Forking after the package is
imported and its kernels compiled keeps a trial at a few milliseconds of overhead.
"""

from __future__ import annotations

import dataclasses
import json
import math
import os
import signal
import tempfile
import time

import numpy as np


@dataclasses.dataclass(frozen=True)
class Trial:
    args: tuple[str, ...]
    code: int | str  # an exit code, "hang" or "killed by signal N"
    out: str
    err: str
    seconds: float

    @property
    def hang(self) -> bool:
        return self.code == "hang"


def trial(args: list[str], timeout: float = 60.0) -> Trial:
    """Run ``stickslip ARGS`` in a forked child; kill it after ``timeout`` seconds."""
    from stickslip.cli import run

    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        start = time.perf_counter()
        pid = os.fork()
        if pid == 0:  # the child: never returns into pytest
            code = 3
            try:
                os.dup2(out.fileno(), 1)
                os.dup2(err.fileno(), 2)
                code = run(list(args))
            finally:
                import sys

                sys.stdout.flush()
                sys.stderr.flush()
                os._exit(code if isinstance(code, int) else 3)
        code: int | str = "hang"
        while time.perf_counter() - start < timeout:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                code = os.waitstatus_to_exitcode(status)
                if code < 0:
                    code = f"killed by signal {-code}"
                break
            time.sleep(0.002)
        else:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
        seconds = time.perf_counter() - start
        out.seek(0)
        err.seek(0)
        return Trial(tuple(args), code, out.read(), err.read(), seconds)


def json_finite(text: str) -> bool:
    """Every number in a JSON document is finite (``NaN``/``Infinity`` parse as floats)."""
    def walk(v):
        if isinstance(v, dict):
            return all(walk(x) for x in v.values())
        if isinstance(v, list):
            return all(walk(x) for x in v)
        return not isinstance(v, float) or math.isfinite(v)
    return walk(json.loads(text))


def files_finite(folder) -> list[str]:
    """Files under ``folder`` (netCDF, Zarr, CSV, JSON) holding a non-finite number that
    their metadata does not explain (a variable may hold NaN if its ``comment`` says where)."""
    import pathlib

    import xarray as xr

    bad = []
    for path in sorted(pathlib.Path(folder).rglob("*")):
        if path.suffix in (".nc", ".zarr") and (path.is_file() or (path / ".zattrs").exists()
                                                 or (path / "zarr.json").exists()):
            opened = xr.open_zarr(path, consolidated=False) if path.suffix == ".zarr" else xr.open_dataset(path)
            with opened as ds:
                for name, var in {**ds.data_vars, **ds.coords}.items():
                    values = np.asarray(var.values)
                    if values.dtype.kind == "f" and not np.isfinite(values).all():
                        if "NaN" not in var.attrs.get("comment", ""):
                            bad.append(f"{path.name}:{name}")
        elif path.suffix == ".json" and path.is_file():
            if not json_finite(path.read_text()):
                bad.append(path.name)
        elif path.suffix == ".csv" and path.is_file():
            text = path.read_text().lower()
            if "nan" in text or "inf" in text:
                bad.append(path.name)
    return bad

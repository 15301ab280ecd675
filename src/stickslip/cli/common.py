"""Output helpers shared by the subcommands."""

from __future__ import annotations

import contextlib
import json
import math
import os
import tempfile
from pathlib import Path
from typing import Annotated

import numpy as np
import typer
from rich.console import Console
from rich.table import Table

from ..errors import NoSolutionError, ParameterError

#: ``--overwrite``: start a store or checkpoint afresh instead of resuming it.
Overwrite = Annotated[bool, typer.Option("--overwrite", help="Start afresh, replacing the store or checkpoint, "
                                         "instead of resuming it (one from another run is refused without it).")]


def _clean(value):
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_clean(v) for v in value]
    if isinstance(value, (np.integer,)):
        return int(value)
    if isinstance(value, (np.floating, float)):
        return None if not math.isfinite(float(value)) else float(value)
    if isinstance(value, np.bool_):
        return bool(value)
    if isinstance(value, np.ndarray):
        return _clean(value.tolist())
    return value


def non_finite(value, prefix: str = "") -> list[str]:
    """Paths (``a.b[2]``) of the NaN and infinite numbers in a nested result."""
    if isinstance(value, dict):
        return [p for k, v in value.items() for p in non_finite(v, f"{prefix}.{k}" if prefix else str(k))]
    if isinstance(value, (list, tuple, np.ndarray)):
        return [p for i, v in enumerate(value) for p in non_finite(v, f"{prefix}[{i}]")]
    if isinstance(value, (float, np.floating)) and not math.isfinite(float(value)):
        return [prefix]
    return []


def emit(data: dict, as_json: bool, title: str) -> None:
    """Print ``data`` as one JSON object, or as a table for people. A result with a NaN or an
    infinity is not printed: it is a `NoSolutionError` naming the fields (exit code 1)."""
    bad = non_finite(data)
    if bad:
        raise NoSolutionError(f"no finite {title or 'result'}: {', '.join(bad[:5])}"
                              f"{f' and {len(bad) - 5} more' if len(bad) > 5 else ''} came out NaN or infinite "
                              "(the parameters are outside the range where the computation is meaningful)")
    data = _clean(data)
    if as_json:
        print(json.dumps(data))
        return
    table = Table(title=title, show_header=False)
    for key, value in data.items():
        if isinstance(value, list) and len(value) > 8:
            value = f"[{len(value)} items]"
        table.add_row(key, str(value))
    Console().print(table)


def _writable_folder(name: str, path: Path, folder: Path) -> None:
    """``folder`` exists, is a folder, and a file can be created in it (tried, then removed)."""
    if not folder.is_dir():
        raise ParameterError(name, str(path), f"a path in an existing folder ({folder} is not one)")
    try:
        with tempfile.NamedTemporaryFile(dir=folder, prefix=".stickslip-probe-"):
            pass
    except OSError as exc:
        raise ParameterError(name, str(path), f"a path in a folder you can write to (creating a file in {folder} "
                                               f"failed: {exc.strerror or type(exc).__name__})") from None


def output_path(name: str, path: Path | None, suffix: str) -> Path | None:
    """Check an output file before any work: its suffix, that it is not a folder, that its
    folder exists and can be written to, and that an existing file can be replaced."""
    if path is None:
        return None
    if path.suffix.lower() != suffix:
        raise ParameterError(name, str(path), f"a file name ending in {suffix}")
    if path.is_dir():
        raise ParameterError(name, str(path), "a file name, not a folder")
    _writable_folder(name, path, path.parent if str(path.parent) else Path("."))
    if path.exists() and not os.access(path, os.W_OK):
        raise ParameterError(name, str(path), "a file you can write to")
    return path


def output_folder(name: str, path: Path, suffix: str | None = None) -> Path:
    """Check an output folder (a store, a results folder) before any work: its suffix, that it is
    not a file, and that it or its nearest existing parent can be written to."""
    if suffix is not None and path.suffix.lower() != suffix:
        raise ParameterError(name, str(path), f"a folder name ending in {suffix}")
    if path.exists() and not path.is_dir():
        raise ParameterError(name, str(path), "a folder (created if absent), not a file")
    existing = path.resolve()
    while not existing.exists():
        existing = existing.parent
    if not existing.is_dir():
        raise ParameterError(name, str(path), f"a folder whose parents are folders ({existing} is a file)")
    _writable_folder(name, path, existing)
    return path


@contextlib.contextmanager
def progress_bar(label: str):
    """A transient rich progress bar on stderr; yields the library's ``progress(done, total)``
    callback. Without a terminal on stderr (a pipe, a log file, a batch job) nothing is drawn."""
    from rich.progress import Progress

    console = Console(stderr=True)
    if not console.is_terminal:
        yield lambda done, total: None
        return
    with Progress(console=console, transient=True) as bar:
        task = bar.add_task(label, total=None)
        yield lambda done, total: bar.update(task, completed=done, total=total)

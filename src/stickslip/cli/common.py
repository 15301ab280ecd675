"""Output helpers shared by the subcommands."""

from __future__ import annotations

import contextlib
import json
import math
from pathlib import Path

import numpy as np
from rich.console import Console
from rich.table import Table

from ..errors import ParameterError


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


def emit(data: dict, as_json: bool, title: str) -> None:
    """Print ``data`` as one JSON object, or as a table for people."""
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


def output_path(name: str, path: Path | None, suffix: str) -> Path | None:
    """Validate an output file name (its suffix and that its folder exists)."""
    if path is None:
        return None
    if path.suffix.lower() != suffix:
        raise ParameterError(name, str(path), f"a file name ending in {suffix}")
    if not path.parent.exists():
        raise ParameterError(name, str(path), "a path in an existing directory")
    return path


@contextlib.contextmanager
def progress_bar(label: str):
    """A transient rich progress bar; yields the library's ``progress(done, total)`` callback."""
    from rich.progress import Progress

    with Progress(transient=True) as bar:
        task = bar.add_task(label, total=None)
        yield lambda done, total: bar.update(task, completed=done, total=total)

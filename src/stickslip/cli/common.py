"""Output helpers shared by the subcommands."""

from __future__ import annotations

import contextlib
import json
import math
import os
import shlex
import sys
import tempfile
from pathlib import Path
from typing import Annotated, Optional

import numpy as np
import typer
from rich.console import Console
from rich.table import Table
from rich.text import Text

from ..errors import NoSolutionError, ParameterError
from ..validation import special_kind
from ..quantities import FEM, MAX_POINTS, Quantity, lookup
from . import status

def declared(quantity: Quantity, flag: str, note: str = "", **options):
    """A typer option that reads the declaration ``quantity``: its help is the declaration's
    (meaning, symbol, units, range) plus ``note``, and a value given is checked against the
    declared range while the command line is parsed, before any work, the error naming
    ``flag``. The declaration is kept on the option (``.quantity``) for the tests."""
    def check(value):
        return value if value is None else quantity.check(value, flag)

    info = typer.Option(flag, help=quantity.help(note), callback=check, **options)
    info.quantity = quantity
    return info


def _scheduler(value):
    from ..cluster import check_scheduler, reachable

    value = check_scheduler(value, "--scheduler")
    if value is not None and "://" in value:
        reachable(value, "--scheduler")  # before any work: no store is made for a scheduler that is not there
    return value


#: ``--scheduler``: where a sweep's points are computed (`stickslip.sweep.run_sweep`).
def scheduler_option(help_text: str):
    """A ``--scheduler`` option (checked by `stickslip.cluster.check_scheduler`) with its own help."""
    return typer.Option("--scheduler", callback=_scheduler, help=help_text)


Scheduler = Annotated[Optional[str], typer.Option(
    "--scheduler", callback=_scheduler,
    help="Where the points are computed: processes (a local pool, the default), distributed (a local Dask cluster "
         "of --workers processes, each point stored as it finishes, a failing point stored with its message) or "
         "the address tcp://HOST:PORT of a running Dask scheduler and its workers.")]

#: ``--overwrite``: start a store or checkpoint afresh instead of resuming it.
Overwrite = Annotated[bool, typer.Option("--overwrite", help="Start afresh, replacing the store or checkpoint, "
                                         "instead of resuming it (one from another run is refused without it), "
                                         "and replace the other outputs given if they exist.")]
#: ``--overwrite`` of a command that writes results: without it an existing file is refused.
Replace = Annotated[bool, typer.Option("--overwrite", help="Replace the output files given if they exist (without "
                                       "it, an existing file is refused, whatever wrote it).")]


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


def _number(value) -> str:
    """A number for people: 6 significant digits, integers as they are."""
    if isinstance(value, bool) or value is None:
        return str(value).lower() if isinstance(value, bool) else "-"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, list):
        return "[" + ", ".join(_number(v) for v in value) + "]" if len(value) <= 8 else f"[{len(value)} items]"
    return str(value)


def units_of(key: str, model: str) -> tuple[str, str]:
    """Units and meaning of a result's key ``a.b.c``: of its own name, else of the nearest part
    of its path that is declared (``counts.stick-slip``: a count; ``checks.pressure``: a check)."""
    for part in reversed(key.split(".")):
        found = lookup(part, model)
        if found is not None:
            return found
    return "", ""


def _rows(data: dict, prefix: str = ""):
    """``(key, value)`` rows of a nested result; lists of records are yielded whole."""
    for key, value in data.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            yield from _rows(value, f"{name}.")
        else:
            yield name, value


def emit(data: dict, as_json: bool, title: str, model: str = "common", meanings: dict | None = None) -> None:
    """Print ``data`` as one JSON object on stdout (with ``units``: the units and meaning of
    each key that has them), or as tables for people (value, units, meaning; 6 significant
    digits). A result with a NaN or an infinity is not printed: it is a `NoSolutionError`
    naming the fields (exit code 1). ``model`` picks the vocabulary of units
    (`stickslip.vocabulary`); ``meanings`` gives a key's own ``(units, meaning)`` where this
    result's quantity is not the vocabulary's (an equilibrium's ``stable`` is not a cycle's)."""
    bad = non_finite(data)
    if bad:
        raise NoSolutionError(f"no finite {title or 'result'}: {', '.join(bad[:5])}"
                              f"{f' and {len(bad) - 5} more' if len(bad) > 5 else ''} came out NaN or infinite "
                              "(the parameters are outside the range where the computation is meaningful)")
    data = _clean(data)
    meanings = meanings or {}

    def described(key: str) -> tuple[str, str]:
        return meanings.get(key) or units_of(key, model)

    rows = list(_rows(data))
    records = {k: v for k, v in rows if isinstance(v, list) and v and all(isinstance(x, dict) for x in v)}
    keys = {k for k, _ in rows} | {f"{k}.{c}" for k, v in records.items() for c in v[0]}
    units = {k: dict(zip(("units", "long_name"), described(k))) for k in sorted(keys) if any(described(k))}
    if as_json:
        print(json.dumps({**data, "units": units} if units and "units" not in data else data))
        return
    console = Console()
    plain = Text  # every cell is text as it is: "[re, im]" or "[rad]" are not markup
    table = Table(title=plain(title), show_header=True, header_style="bold")
    for column in ("quantity", "value", "units", "meaning"):  # a long word folds onto the next line, never cut
        table.add_column(plain(column), overflow="fold")
    for key, value in rows:
        if key not in records:
            table.add_row(*map(plain, (key, _number(value), *described(key))))
    console.print(table)
    for key, items in records.items():
        columns = list(items[0])
        notes = [f"{c}: {described(c)[1]}" for c in columns if described(c)[1]]
        sub = Table(title=plain(f"{title}: {key}"), header_style="bold", caption=plain("; ".join(notes)) if notes
                    else None)
        for c in columns:
            unit = described(c)[0]
            sub.add_column(plain(f"{c} [{unit}]" if unit and unit != "1" else c), overflow="fold")
        for item in items:
            sub.add_row(*(plain(_number(item.get(c))) for c in columns))
        console.print(sub)


#: The run file of a long computation, written as it goes and resumed (``brake integrate``, ``fem``).
RunOut = Annotated[Optional[Path], typer.Option("--out", help=(
    "The run (.nc): written as it goes and at the end; a killed run resumes from it (--overwrite starts afresh)."))]
#: The interval of a run's ParaView snapshots (with ``--xdmf``).
XdmfEvery = Annotated[Optional[float], declared(FEM["xdmf_every"], "--xdmf-every", (
    "Of the --xdmf snapshots (default 1), and the last one; kept on the run's samples, a whole number of time "
    "steps apart, so it may differ by a fraction of a sample."))]


def xdmf_path(path, overwrite: bool = False):
    """An ``--xdmf`` output path and its ``.h5`` companion, both checked before any work (or None);
    existing ones are replaced with ``--overwrite`` only."""
    path = output_path("--xdmf", path, ".xdmf", overwrite)
    if path is not None:
        output_path("--xdmf", path.with_suffix(".h5"), ".h5", overwrite)
    return path


def xdmf_snapshots(xdmf, every, overwrite: bool = False) -> tuple:
    """``(path, interval in transits)`` of a run's ``--xdmf``/``--xdmf-every``, checked before any
    work; ``(None, None)`` without ``--xdmf`` (and ``--xdmf-every`` alone is refused)."""
    xdmf = xdmf_path(xdmf, overwrite)
    if every is not None and xdmf is None:
        raise ParameterError("--xdmf-every", every, "given with --xdmf only (it sets the interval of the "
                             "snapshots --xdmf writes)")
    return xdmf, (None if xdmf is None else FEM.check("xdmf_every", 1.0 if every is None else every, "--xdmf-every"))


#: The help of a map axis option (``--x``, ``--y``), the same for every map.
AXIS_HELP = "name=lo:hi:n, n values from lo to hi (append :log for logarithmic spacing)"


def axis(option: str, text: str, increasing: bool = False) -> tuple[str, list[float]]:
    """A map axis ``name=lo:hi:n`` (linear) or ``name=lo:hi:n:log`` -> ``(name, values)``; with
    ``increasing``, ``lo < hi`` (a sweep whose tracking and critical values run upwards)."""
    example = "e.g. belt_speed=0.05:1.5:40 or mismatch=1e-7:1e-4:12:log"
    try:
        name, _, spec = text.partition("=")
        parts = spec.split(":")
        log = len(parts) == 4 and parts[3] == "log"
        if len(parts) != 3 and not log:
            raise ValueError
        lo, hi, n = float(parts[0]), float(parts[1]), int(parts[2])
    except ValueError:
        raise ParameterError(option, text, f"name=lo:hi:n or name=lo:hi:n:log, {example}") from None
    if n < 2 or not name.strip() or not (math.isfinite(lo) and math.isfinite(hi)) or n > 100_000:
        raise ParameterError(option, text, f"name=lo:hi:n with finite lo, hi and 2 <= n <= 100000, {example}")
    if log and min(lo, hi) <= 0:
        raise ParameterError(option, text, "lo, hi > 0 for a logarithmic axis (:log)")
    values = np.logspace(np.log10(lo), np.log10(hi), n) if log else np.linspace(lo, hi, n)
    if len(set(values.tolist())) < n:  # lo = hi, or closer than n doubles apart: a point computed twice
        raise ParameterError(option, text, f"name=lo:hi:n with {n} distinct values from lo to hi (lo != hi), {example}")
    if increasing and hi < lo:
        raise ParameterError(option, text, "LO < HI (the values increase)")
    return name.strip(), [float(v) for v in values]


def map_size(option: str, text: str, *sizes: int) -> None:
    """A map of at most `MAX_POINTS` points (the product of its axes' sizes), refused up front."""
    points = math.prod(sizes)
    if points > MAX_POINTS:
        raise ParameterError(option, text, f"an axis that keeps the map within {MAX_POINTS:.0e} points (this one makes "
                             f"{' x '.join(map(str, sizes))} = {points:.3g}: split the study, or run it on a cluster)",
                             also=("--x",))


def checked_axis(option: str, text: str, check) -> tuple[str, list[float]]:
    """`axis`, with ``check(name, value)`` run on every value: a value it refuses is named as the
    axis option and its text (``--x = 'friction=0:20:3'``), with the range of the parameter."""
    name, values = axis(option, text)
    try:
        for value in values:
            check(name, value)
    except ParameterError as exc:
        if exc.name == "parameter":  # not a parameter of the model at all
            raise ParameterError(option, text, exc.allowed) from None
        raise ParameterError(option, text, f"an axis of {name} with every value {exc.allowed}",
                             also=tuple(a for a in exc.also if a != option)) from None
    return name, values


def command_line() -> str:
    """The command this process runs, as typed (for a file's ``history``)."""
    return "stickslip " + " ".join(shlex.quote(a) for a in sys.argv[1:])


def write_netcdf(ds, out: Path) -> None:
    """Write a result dataset to ``out`` (through a temporary file, so a kill leaves no half
    file), with the command line in its ``history``."""
    from ..cf import for_file, stamp
    from ..files import to_netcdf

    ds = for_file(stamp(ds.copy(), command_line()))
    tmp = Path(out).with_name(Path(out).name + ".partial")
    try:
        to_netcdf(ds, tmp)
        os.replace(tmp, out)
    finally:
        tmp.unlink(missing_ok=True)


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


def _holds_a_run(path: Path) -> bool:
    """``path`` is a run's checkpoint (a netCDF file with the ``run_format`` attribute)."""
    try:
        import xarray as xr

        with xr.open_dataset(path) as ds:
            return "run_format" in ds.attrs
    except Exception:  # not netCDF: not a checkpoint
        return False


def _name_fits(name: str, path: Path) -> None:
    """Every part of ``path`` is a name the file system takes (255 bytes on most), and the whole
    path is not beyond its limit (4096 bytes): checked before any work, not when writing."""
    limit = os.pathconf("/", "PC_NAME_MAX") if hasattr(os, "pathconf") else 255
    longest = max((len(os.fsencode(part)) for part in path.parts), default=0)
    if longest > limit:
        raise ParameterError(name, str(path)[:60] + "...", f"a path whose every name is at most {limit} bytes long "
                             f"(one is {longest})")
    if len(os.fsencode(str(path.resolve()))) >= 4096:
        raise ParameterError(name, str(path)[:60] + "...", "a path shorter than 4096 bytes")


#: The formats of ``--plot``, by the file's suffix (matplotlib writes each).
FIGURE_SUFFIXES = (".png", ".svg", ".pdf")
FIGURE_HELP = "Write a figure to this file: PNG, SVG or PDF by its suffix."


def output_path(name: str, path: Path | None, suffix: str | tuple[str, ...],
                overwrite: bool | None = None) -> Path | None:
    """Check an output file before any work: its suffix (or one of them), that its name fits the file system, that
    it is not a folder, that its folder exists and can be written to, and that an existing file
    can be replaced. ``overwrite`` is the command's ``--overwrite``: an existing file (whatever
    wrote it) is replaced only if it is true. None is for a run's checkpoint, which the run
    itself resumes or refuses (`stickslip.contact.runs`)."""
    if path is None:
        return None
    suffixes = (suffix,) if isinstance(suffix, str) else tuple(suffix)
    if path.suffix.lower() not in suffixes:
        allowed = suffixes[0] if len(suffixes) == 1 else ", ".join(suffixes[:-1]) + " or " + suffixes[-1]
        raise ParameterError(name, str(path), f"a file name ending in {allowed}")
    _name_fits(name, path)
    kind = special_kind(path)
    if kind is not None and kind != "a folder":  # a FIFO blocks its reader, a device is replaced by the file
        raise ParameterError(name, str(path), f"a regular file or a new name (this is {kind})")
    try:
        if path.is_dir():
            raise ParameterError(name, str(path), "a file name, not a folder")
        _writable_folder(name, path, path.parent if str(path.parent) else Path("."))
        exists = path.exists()
    except OSError as exc:  # a path the system refuses to look at (a loop of links, a name too long)
        raise ParameterError(name, str(path), f"a path the file system can use ({exc.strerror})") from None
    if exists and not os.access(path, os.W_OK):
        raise ParameterError(name, str(path), "a file you can write to")
    if overwrite is False and exists:
        what = "holds a run's checkpoint" if _holds_a_run(path) else "exists"
        raise ParameterError(name, str(path), f"a new file (this one {what}, and this command would replace it: "
                             "give --overwrite to replace it)")
    return path


def overwrite_needs(overwrite: bool, name: str, *paths) -> None:
    """``--overwrite`` without any output it would replace is refused, not ignored."""
    if overwrite and all(p is None for p in paths):
        raise ParameterError("--overwrite", True, f"left out without {name} (there is no file to replace)")


def output_folder(name: str, path: Path, suffix: str | None = None) -> Path:
    """Check an output folder (a store, a results folder) before any work: its suffix, that it is
    not a file, and that it or its nearest existing parent can be written to."""
    if suffix is not None and path.suffix.lower() != suffix:
        raise ParameterError(name, str(path), f"a folder name ending in {suffix}")
    _name_fits(name, path)
    kind = special_kind(path)
    if kind is not None and kind != "a folder":
        raise ParameterError(name, str(path), f"a folder (created if absent), not {kind}")
    try:
        if path.exists() and not path.is_dir():
            raise ParameterError(name, str(path), "a folder (created if absent), not a file")
        existing = path.resolve()
        while not existing.exists():
            existing = existing.parent
    except OSError as exc:
        raise ParameterError(name, str(path), f"a path the file system can use ({exc.strerror})") from None
    if not existing.is_dir():
        raise ParameterError(name, str(path), f"a folder whose parents are folders ({existing} is a file)")
    _writable_folder(name, path, existing)
    return path


@contextlib.contextmanager
def progress_bar(label: str):
    """A transient rich progress bar on stderr (with the time left); yields the library's
    ``progress(done, total)`` callback. Without a terminal on stderr (a pipe, a log file, a
    batch job) the command's heartbeat (`stickslip.cli.status`) writes a line at most every
    `~stickslip.cli.status.STATUS_SECONDS` saying how far the loop is and the time left."""
    from rich.progress import Progress, TimeElapsedColumn

    console = Console(stderr=True)
    if not console.is_terminal:
        yield status.progress(label) or (lambda done, total: None)
        return
    with Progress(*Progress.get_default_columns(), TimeElapsedColumn(), console=console, transient=True) as bar:
        task = bar.add_task(label, total=None)
        yield lambda done, total: bar.update(task, completed=done, total=total)

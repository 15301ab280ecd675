"""`stickslip reproduce`: compute, plot and check every registered figure; write the report.

Each figure's dataset is checkpointed to ``<out>/data/<key>.nc`` (written atomically)
with a fingerprint of the package source and the ``quick`` flag; a rerun (for instance
after the run was killed) loads finished figures instead of recomputing them.

Each figure's outcome (its texts, checks, timings, mode and the code that made it) is kept
as a record, ``<out>/data/<key>.report.json``; the report is rendered from all the records
in ``<out>``, in the order of the registry. A run of some figures (``--only``) thus replaces
their sections and keeps the others; a section from a run of the other mode (quick or full)
or by other code says so. ``report.md`` links the figures' PNG files; ``report.html`` embeds
them (base64 ``data:`` URIs), so it can be copied alone.
"""

from __future__ import annotations

import base64
import contextlib
import datetime as _dt
import hashlib
import inspect
import json
import logging
import mimetypes
import os
import re
import shutil
import platform
import sys
import time
import uuid
from concurrent.futures import as_completed
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable, Sequence

import lazy_loader as lazy

from .cf import finish, for_file, from_file
from . import __version__, plotting
from .errata import ERRATA, anchor, to_markdown
from .errors import ParameterError
from .files import to_netcdf
from .figures import Check, FigureSpec, registry

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

log = logging.getLogger("stickslip.report")

#: A figure's record in the data folder: ``<key>`` + this.
RECORD_SUFFIX = ".report.json"
#: The version of the records' layout (a record of another layout is not read).
RECORD_FORMAT = 1


@dataclass
class FigureOutcome:
    spec: FigureSpec
    checks: list[Check]
    seconds: float
    cached: bool
    image: str
    method: str = ""  # what was computed, for the data used (default: the spec's method)
    data: str = ""  # where the data came from, when that can differ between runs (``ds.attrs["data_source"]``)
    quick: bool | None = None  # the mode of the run that made it (None: the summary's)
    finished: str = ""  # when it was made (UTC, ISO 8601)
    fingerprint: str = ""  # `source_fingerprint` of the code that made it ("": not known)
    version: str = ""  # stickslip's version, and Python's, that made it
    python: str = ""

    @property
    def passed(self) -> bool:
        """All verification checks pass (paper claims that are not reproduced do not count)."""
        return all(c.passed for c in self.checks if not c.claim)

    @property
    def not_reproduced(self) -> list[Check]:
        return [c for c in self.checks if c.claim and not c.passed]


def _verdict(check: Check) -> str:
    if check.claim:
        return "reproduced" if check.passed else "**not reproduced**"
    return "pass" if check.passed else "**FAIL**"


@dataclass
class Summary:
    out: Path
    quick: bool
    outcomes: list[FigureOutcome] = field(default_factory=list)
    fingerprint: str = ""  # `source_fingerprint` of this run's code ("": not known)
    reported: list[str] = field(default_factory=list)  # the figures in the report written last, this run's or not
    unreadable: list[str] = field(default_factory=list)  # records in ``out`` that could not be read

    @property
    def passed(self) -> bool:
        return all(o.passed for o in self.outcomes)

    def to_dict(self) -> dict:
        return {"out": str(self.out), "quick": self.quick, "passed": self.passed,
                "figures": [{"key": o.spec.key, "passed": o.passed, "checks": len(o.checks),
                             "failed": [c.name for c in o.checks if not c.passed and not c.claim],
                             "not_reproduced": [c.name for c in o.not_reproduced], "seconds": o.seconds,
                             "cached": o.cached} for o in self.outcomes],
                "report": str(self.out / "report.md"), "report_figures": self.reported}


def source_fingerprint() -> str:
    """SHA-256 of the package's Python sources: a checkpoint is reused only by the same code."""
    root = Path(__file__).parent
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*.py")):
        digest.update(str(path.relative_to(root)).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def select(only: str | None) -> list[FigureSpec]:
    specs = registry()
    if only is None:
        return list(specs.values())
    keys = [k.strip() for k in only.split(",") if k.strip()]
    if not keys:  # "" or ",": not "everything" (a 20-minute run the user did not ask for)
        raise ParameterError("--only", only, "comma-separated figure keys among " + ", ".join(specs))
    unknown = [k for k in keys if k not in specs]
    if unknown:
        raise ParameterError("--only", ",".join(unknown), "comma-separated figure keys among " + ", ".join(specs))
    return [specs[k] for k in keys]


def _checkpoint(spec: FigureSpec, data_dir: Path, quick: bool, fingerprint: str):
    """``(dataset or None, key)``: the figure's checkpoint if it was made by this code (``fingerprint``),
    from the same data outside the package (a campaign: part of the key) and in this mode."""
    path = data_dir / f"{spec.key}.nc"
    if spec.inputs is not None:  # data from outside the package (a campaign): part of the fingerprint
        fingerprint = f"{fingerprint}+{spec.inputs(data_dir)}"
    if path.exists():
        try:
            ds = from_file(xr.load_dataset(path))
            if ds.attrs.get("fingerprint") == fingerprint and bool(ds.attrs.get("quick")) == quick:
                return ds, fingerprint
        except (OSError, ValueError):
            pass  # unreadable checkpoint (killed mid-write by another tool): recompute
    return None, fingerprint


def _load_or_compute(spec: FigureSpec, data_dir: Path, quick: bool, fingerprint: str, force: bool):
    path = data_dir / f"{spec.key}.nc"
    ds, fingerprint = _checkpoint(spec, data_dir, quick, fingerprint)
    if ds is not None and not force:
        return ds, True
    # figures built on sweeps take a cache folder, so a killed sweep resumes point by point; the
    # folder is this code's and this mode's (a sweep left by other code or the other mode is
    # never resumed: it is removed)
    tag = hashlib.sha256(f"{fingerprint}|{int(quick)}".encode()).hexdigest()[:12]
    cache = data_dir / f"{spec.key}.{tag}.partial"
    for stale in data_dir.glob(f"{spec.key}.*.partial"):
        if stale != cache and stale.is_dir():
            shutil.rmtree(stale, ignore_errors=True)
    accepts = inspect.signature(spec.compute).parameters
    options = {"data_dir": data_dir} if "data_dir" in accepts else {}
    if "cache" in accepts:
        cache.mkdir(exist_ok=True)
        options["cache"] = cache
    ds = spec.compute(quick, **options)
    domain = ("oscillator" if spec.model.startswith("1-DOF") else "halfspace" if "half-space" in spec.model else
              "rsf" if "rate-and-state" in spec.model else "system" if "frictional contact" in spec.model else "brake")
    ds.attrs.update({"fingerprint": fingerprint, "quick": int(quick), "figure": spec.key})
    ds = finish(ds, spec.title, domain, history=f"stickslip reproduce{' --quick' if quick else ''} (figure {spec.key})")
    tmp = path.with_suffix(".nc.partial")
    to_netcdf(for_file(ds), tmp)
    os.replace(tmp, path)
    shutil.rmtree(cache, ignore_errors=True)
    return ds, False


def _started(key: str, number: int, total: int, begun: float, title: str) -> None:
    log.info("%s: started (figure %d of %d, %s elapsed): %s", key, number, total,
             _elapsed(time.time() - begun), title)


def _compute_apart(key: str, data_dir: Path, quick: bool, fingerprint: str, force: bool, number: int, total: int,
                   begun: float) -> float:
    """In a worker process: compute figure ``key``'s dataset into its checkpoint; its seconds."""
    spec = registry()[key]
    _started(key, number, total, begun, spec.title)
    start = time.perf_counter()
    _load_or_compute(spec, data_dir, quick, fingerprint, force)
    return time.perf_counter() - start


def _worker_logs(level: int) -> None:
    """A worker's log records on its stderr, as the parent's command line shows them (one line each)."""
    if level <= logging.INFO:
        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(logging.Formatter("%(message)s"))
        logging.getLogger("stickslip").addHandler(handler)
        logging.getLogger("stickslip").setLevel(level)


def start_order(specs: list[FigureSpec], data_dir: Path) -> list[FigureSpec]:
    """The figures in the order to start them: the longest first, by their last record (by their
    declared `FigureSpec.cost` where none is kept), so that two workers finish together."""
    def seconds(spec):
        try:
            return float(json.loads(record_path(data_dir, spec.key).read_text())["seconds"])
        except (OSError, ValueError, KeyError, TypeError):
            return spec.cost
    return sorted(specs, key=lambda s: -seconds(s))


def reproduce(out: Path, *, quick: bool = False, only: str | None = None, force: bool = False,
              progress=None, workers: int = 1, waiting=None) -> Summary:
    """Compute, plot and check the selected figures, record each, then write ``report.md`` and
    ``report.html`` from every figure recorded in ``out`` (this run's and earlier runs').
    ``progress(spec)`` is called as each figure is taken up here.

    With ``workers > 1`` the figures to compute (those without a checkpoint of this code and
    mode) are computed in that many worker processes (`stickslip.sweep.process_pool`), the
    longest first, while this process plots, checks and records each as its data arrive; each
    time it goes back to waiting for them, ``waiting(keys, done, total)`` is called with the keys
    of the figures still computing and the numbers of figures recorded and selected."""
    specs = select(only)
    out = Path(out)
    data_dir = out / "data"
    data_dir.mkdir(parents=True, exist_ok=True)
    fingerprint = source_fingerprint()
    summary = Summary(out, quick, fingerprint=fingerprint)
    begun = time.time()
    registered = registry()
    sources = {spec.key: registered[spec.data_from] if spec.data_from else spec for spec in specs}
    forced = {key: force and sources[key] is spec for key, spec in zip(sources, specs)}
    number = {spec.key: k for k, spec in enumerate(specs, 1)}
    with contextlib.ExitStack() as stack:
        apart: dict = {}  # source key -> the future of its computation in a worker
        if workers > 1:
            todo = {s.key: s for s in sources.values()
                    if forced.get(s.key) or _checkpoint(s, data_dir, quick, fingerprint)[0] is None}
            if len(todo) > 1:
                from .sweep import process_pool

                pool = stack.enter_context(process_pool(min(workers, len(todo)), _worker_logs,
                                                        (logging.getLogger("stickslip").getEffectiveLevel(),)))
                for s in start_order(list(todo.values()), data_dir):
                    apart[s.key] = pool.submit(_compute_apart, s.key, data_dir, quick, fingerprint,
                                               bool(forced.get(s.key)), number.get(s.key, 0), len(specs), begun)
        # the figures computed in workers are plotted, checked and logged as each arrives (in the
        # order they finish: a short one queued last no longer holds back those done before it)
        pending = {future: key for key, future in apart.items()}
        computing = set(pending.values())
        if waiting and computing:
            waiting(sorted(computing), len(summary.outcomes), len(specs))
        for future in as_completed(pending):
            computed = future.result()  # the seconds of its computation (the wait for it is not its time)
            computing.discard(pending[future])
            for spec in (s for s in specs if sources[s.key].key == pending[future]):
                if progress:
                    progress(spec)
                ds, _ = _load_or_compute(sources[spec.key], data_dir, quick, fingerprint, False)
                _record(summary, spec, ds, False, time.perf_counter() - computed, out, quick, fingerprint)
            if waiting and computing:
                waiting(sorted(computing), len(summary.outcomes), len(specs))
        for spec in (s for s in specs if sources[s.key].key not in apart):
            if progress:
                progress(spec)
            start = time.perf_counter()
            _started(spec.key, number[spec.key], len(specs), begun, spec.title)
            ds, cached = _load_or_compute(sources[spec.key], data_dir, quick, fingerprint, forced[spec.key])
            _record(summary, spec, ds, cached, start, out, quick, fingerprint)
    summary.outcomes.sort(key=lambda o: number[o.spec.key])  # the report's order
    return summary


def _record(summary: Summary, spec: FigureSpec, ds, cached: bool, start: float, out: Path, quick: bool,
            fingerprint: str) -> None:
    """Plot and check figure ``spec`` from ``ds``, keep its outcome and rewrite the report."""
    image = f"{spec.key}.png"
    problems = plotting.save(spec.plot(ds), out / image)  # the figure's legibility problems
    checks = spec.check(ds) + [Check(
        "the figure is legible at 100 % (stickslip.plotting.legibility_problems)", not problems,
        f"{len(problems)} problem(s)", "none: text >= 7 pt, units on axes, no overlaps, nothing on the data, "
        "every colour code explained", "; ".join(problems[:8]))]
    method = spec.describe(ds) if spec.describe else spec.method
    data = str(ds.attrs.get("data_source", ""))  # a campaign figure's data (CF's "source": the producer)
    summary.outcomes.append(FigureOutcome(
        spec, checks, time.perf_counter() - start, cached, image, method, data, quick=quick,
        finished=_dt.datetime.now(_dt.timezone.utc).isoformat(timespec="microseconds"),
        fingerprint=fingerprint, version=__version__, python=platform.python_version()))
    report = write_report(summary)  # keep the report current while the run proceeds
    summary.reported, summary.unreadable = [o.spec.key for o in report.outcomes], report.unreadable
    done = summary.outcomes[-1]
    failed = [c for c in done.checks if not c.passed and not c.claim]
    log.info("%s: %s in %.1f s%s: %d of %d checks pass%s", spec.key, "FAILED" if failed else "done", done.seconds,
             " (from its checkpoint)" if cached else "", sum(c.passed for c in done.checks), len(done.checks),
             f", {len(done.not_reproduced)} paper claim(s) not reproduced" if done.not_reproduced else "")


def _elapsed(seconds: float) -> str:
    minutes, seconds = divmod(int(round(seconds)), 60)
    return f"{minutes} min {seconds:02d} s" if minutes else f"{seconds} s"


# --- records: one per figure, the report is rendered from all of them -------------------------------
def record_path(data_dir: Path, key: str) -> Path:
    """Where the record of figure ``key`` is kept."""
    return Path(data_dir) / f"{key}{RECORD_SUFFIX}"


def to_record(outcome: FigureOutcome) -> dict:
    """``outcome`` as a JSON-able record: everything its section of the report shows."""
    s = outcome.spec
    return {"format": RECORD_FORMAT, "key": s.key, "title": s.title, "model": s.model, "claim": s.claim,
            "errata": list(s.errata), "method": outcome.method or s.method, "data": outcome.data,
            "image": outcome.image, "seconds": float(outcome.seconds), "cached": bool(outcome.cached),
            "quick": None if outcome.quick is None else bool(outcome.quick), "finished": outcome.finished,
            "fingerprint": outcome.fingerprint, "version": outcome.version, "python": outcome.python,
            "checks": [{"name": str(c.name), "passed": bool(c.passed), "measured": str(c.measured),
                        "expected": str(c.expected), "detail": str(c.detail), "claim": bool(c.claim)}
                       for c in outcome.checks]}


def from_record(record: dict) -> FigureOutcome:
    """The `FigureOutcome` of a record made by `to_record` (KeyError, TypeError or ValueError if it is not one)."""
    if record["format"] != RECORD_FORMAT:
        raise ValueError(f"record format {record['format']!r}, not {RECORD_FORMAT}")
    spec = FigureSpec(record["key"], record["title"], record["model"], record["claim"], record["method"],
                      tuple(record["errata"]))
    checks = [Check(**c) for c in record["checks"]]
    return FigureOutcome(spec, checks, float(record["seconds"]), bool(record["cached"]), record["image"],
                         record["method"], record["data"], record["quick"], record["finished"],
                         record["fingerprint"], record["version"], record["python"])


def _write_atomic(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file beside it: a reader sees the old or the new text."""
    tmp = path.with_name(f"{path.name}.{os.getpid()}.{uuid.uuid4().hex[:8]}.partial")  # unique: runs may overlap
    try:
        with open(tmp, "x", encoding="utf-8") as f:  # the umask's permissions, as for any file of the run
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def save_record(data_dir: Path, outcome: FigureOutcome) -> Path:
    """Keep ``outcome`` as its figure's record in ``data_dir`` (replacing an earlier one)."""
    path = record_path(data_dir, outcome.spec.key)
    _write_atomic(path, json.dumps(to_record(outcome), indent=1, ensure_ascii=False) + "\n")
    return path


def recorded(out: Path, quick: bool, fingerprint: str = "") -> Summary:
    """The `Summary` of every figure recorded in ``out/data``, in the order of the registry (a
    figure it no longer has comes last); ``quick`` and ``fingerprint`` are the latest run's, which
    the sections of other runs are compared with. Records that cannot be read are listed in
    ``unreadable``."""
    out = Path(out)
    order = {key: i for i, key in enumerate(registry())}
    outcomes, unreadable = [], []
    for path in sorted((out / "data").glob(f"*{RECORD_SUFFIX}")):
        try:
            outcomes.append(from_record(json.loads(path.read_text(encoding="utf-8"))))
        except (OSError, ValueError, KeyError, TypeError):
            unreadable.append(path.name)
    outcomes.sort(key=lambda o: (order.get(o.spec.key, len(order)), o.spec.key))
    return Summary(out, quick, outcomes, fingerprint, unreadable=unreadable)


# --- Markdown --------------------------------------------------------------------------------------
def cell(text: object) -> str:
    """``text`` as the content of one cell of a Markdown table, whatever it holds: line breaks
    become spaces, and ``\\``, ``|`` and ``` ` ``` are escaped (a code span could hide the pipes
    between cells), as is ``<`` where it could open an HTML tag. Other Markdown (emphasis, links)
    is kept."""
    text = " ".join(line.strip() for line in str(text).splitlines())
    text = re.sub(r"([\\`|])", r"\\\1", text)
    return re.sub(r"<(?=[A-Za-z/!?])", "&lt;", text)


def markdown_table(header: Sequence[str], rows: Iterable[Sequence[object]]) -> list[str]:
    """The lines of a Markdown table of ``rows`` under ``header``, each cell escaped by `cell`."""
    lines = ["| " + " | ".join(cell(h) for h in header) + " |", "|" + "---|" * len(header)]
    for row in rows:
        if len(row) != len(header):
            raise ValueError(f"a row of {len(row)} cells in a table of {len(header)} columns: {row!r}")
        lines.append("| " + " | ".join(cell(c) for c in row) + " |")
    return lines


def _when(iso: str) -> str:
    """An ISO 8601 UTC time as ``2026-11-26 22:00:03 UTC`` ("time unknown" when empty or unreadable)."""
    try:
        return _dt.datetime.fromisoformat(iso).astimezone(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC")
    except (TypeError, ValueError):
        return "time unknown"


def _mode(quick: bool) -> str:
    return "quick" if quick else "full"


def _other_run(o: FigureOutcome, summary: Summary) -> list[str]:
    """How the run that made ``o`` differs from the latest run (``summary``'s): mode, code."""
    notes = []
    if o.quick is not None and bool(o.quick) != summary.quick:
        notes.append("other mode")
    if o.fingerprint and summary.fingerprint and o.fingerprint != summary.fingerprint:
        notes.append("other code")
    return notes


def _errata_links(ids: Sequence[str]) -> str:
    known = {e.id for e in ERRATA}
    return ", ".join(f"[{e}](#{anchor(e)})" if e in known else f"{e} (not in the errata)" for e in ids)


def markdown_report(summary: Summary) -> str:
    """The report of ``summary`` in Markdown (``summary.quick`` and ``fingerprint`` are the latest
    run's: a figure from a run of the other mode, or by other code, is marked as such)."""
    now = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    checks = [c for o in summary.outcomes for c in o.checks]
    n_checks = sum(not c.claim for c in checks)
    n_pass = sum(c.passed for c in checks if not c.claim)
    n_claims = sum(c.claim for c in checks)
    n_reproduced = sum(c.passed for c in checks if c.claim)
    other_mode = sum("other mode" in _other_run(o, summary) for o in summary.outcomes)
    other_code = sum("other code" in _other_run(o, summary) for o in summary.outcomes)
    lines = ["# stickslip — reproduction report", "",
             f"Paper: *Friction-induced vibration and stick-slip waves: short survey and new results*. "
             f"stickslip {__version__}, Python {platform.python_version()}, {now}, latest run in "
             f"{_mode(summary.quick)} mode.", "",
             f"**{n_pass} of {n_checks} checks passed** over {len(summary.outcomes)} figures"
             + (f"; **{n_reproduced} of {n_claims} marked claims of the paper reproduced** (a claim that is not "
                "reproduced is a finding, stated with its numbers, not a failure of the run)." if n_claims else ".")]
    if other_mode or other_code:
        lines += ["", "Each figure's section comes from the latest run of that figure; marked in the table and in "
                  "their sections: " + ", ".join(
                      ([f"{other_mode} from a run in {_mode(not summary.quick)} mode"] if other_mode else [])
                      + ([f"{other_code} computed by other code"] if other_code else [])) + "."]
    if summary.unreadable:
        lines += ["", "Records that could not be read (rerun these figures with `--only`): "
                  + ", ".join(f"`{name}`" for name in summary.unreadable) + "."]
    rows = []
    for o in summary.outcomes:
        verdict = ("pass" if o.passed else "**FAIL**") + (f", {len(o.not_reproduced)} claim(s) not reproduced"
                                                          if o.not_reproduced else "")
        quick = summary.quick if o.quick is None else bool(o.quick)
        run = ", ".join([_mode(quick)] + ([_when(o.finished)] if o.finished else [])
                        + [f"**{note}**" for note in _other_run(o, summary)])
        rows.append([f"[{o.spec.title}](#{o.spec.key})", o.spec.model,
                     f"{sum(c.passed for c in o.checks)}/{len(o.checks)}", verdict,
                     f"{o.seconds:.1f}{' (cached)' if o.cached else ''}", run])
    lines += ["", *markdown_table(["Figure", "Model", "Checks", "Verdict", "Time [s]", "Run"], rows)]
    for o in summary.outcomes:
        s = o.spec
        quick = summary.quick if o.quick is None else bool(o.quick)
        notes = _other_run(o, summary)
        rerun = f"`stickslip reproduce{' --quick' if summary.quick else ''} --only {s.key}`"
        marks = ([f"**From a run in {_mode(quick)} mode**, not in the {_mode(summary.quick)} mode of the latest run."]
                 if "other mode" in notes else []) + (
            [f"**Computed by other code** (source fingerprint {o.fingerprint}; the latest run's is "
             f"{summary.fingerprint})."] if "other code" in notes else [])
        run = (f"*Run:* {_mode(quick)} mode" + (f", finished {_when(o.finished)}" if o.finished else "")
               + f", {o.seconds:.1f} s{' (from the checkpoint)' if o.cached else ''}"
               + (f", stickslip {o.version}" if o.version else "") + (f", Python {o.python}" if o.python else "")
               + ".")
        lines += ["", f'<a id="{s.key}"></a>', "", f"## {s.title}", "", f"*Model:* {s.model}", "", run, "",
                  *([" ".join(marks) + f" {rerun} replaces this section.", ""] if marks else []),
                  f"**The paper's claim.** {s.claim}", "", f"**What was computed.** {o.method or s.method}", "",
                  *([f"**Data used.** {o.data[:1].upper() + o.data[1:]}.", ""] if o.data else []),
                  f"![{s.title}]({o.image})", "",
                  *markdown_table(["Check", "Measured", "Expected", "Verdict", "Detail"],
                                  [[c.name, c.measured, c.expected, _verdict(c), c.detail] for c in o.checks])]
        if s.errata:
            lines += ["", "Errata involved: " + _errata_links(s.errata) + "."]
    lines += ["", '<a id="errata"></a>', ""]
    lines += ["#" + line if line.startswith("#") else line for line in to_markdown(anchors=True).splitlines()]
    return "\n".join(lines) + "\n"


# --- HTML ------------------------------------------------------------------------------------------
_HTML = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>stickslip reproduction report</title>
<style>body{{font-family:sans-serif;max-width:70em;margin:2em auto;line-height:1.4}}
table{{border-collapse:collapse;margin:1em 0}}td,th{{border:1px solid #ccc;padding:.3em .6em;font-size:90%}}
img{{max-width:100%}}code{{background:#f4f4f4}}</style></head><body>
{body}
</body></html>
"""


def _embedded(src: str, folder: Path) -> str | None:
    """The image file ``src`` (relative to ``folder``) as a ``data:`` URI; None if it is not a file there."""
    path = (folder / src).resolve()
    if not path.is_relative_to(folder.resolve()) or not path.is_file():
        return None
    mime = mimetypes.guess_type(path.name)[0] or "application/octet-stream"
    return f"data:{mime};base64,{base64.b64encode(path.read_bytes()).decode('ascii')}"


def html_report(md: str, folder: Path) -> str:
    """The HTML page of the Markdown report ``md``, its images (paths relative to ``folder``)
    embedded as ``data:`` URIs: the page shows its figures wherever it is copied. An image that
    is not found is replaced by a line saying so."""
    import markdown
    from markdown.extensions import Extension
    from markdown.treeprocessors import Treeprocessor

    class EmbedImages(Treeprocessor):
        def run(self, root):
            for img in root.iter("img"):
                src = img.get("src", "")
                if re.match(r"[A-Za-z][A-Za-z0-9+.-]*:", src):  # data:, http: ...: not a file of the report
                    continue
                uri = _embedded(src, Path(folder))
                if uri is not None:
                    img.set("src", uri)
                else:
                    img.tag, img.text = "em", f"(the image {src} was not found beside the report)"
                    img.attrib.clear()

    class Embed(Extension):
        def extendMarkdown(self, md):
            md.treeprocessors.register(EmbedImages(md), "embed_images", -1)  # after unescaping

    return _HTML.format(body=markdown.markdown(md, extensions=["tables", Embed()]))


def write_report(summary: Summary) -> Summary:
    """Record the figures of ``summary`` in ``summary.out/data``, then write ``report.md`` and
    ``report.html`` there from every figure recorded (`recorded`); returns what was reported."""
    data_dir = Path(summary.out) / "data"
    data_dir.mkdir(parents=True, exist_ok=True)
    for outcome in summary.outcomes:
        save_record(data_dir, outcome)
    report = recorded(summary.out, summary.quick, summary.fingerprint)
    md = markdown_report(report)
    _write_atomic(Path(summary.out) / "report.md", md)
    _write_atomic(Path(summary.out) / "report.html", html_report(md, Path(summary.out)))
    return report


__all__ = ["reproduce", "start_order", "Summary", "FigureOutcome", "markdown_report", "write_report", "html_report", "recorded",
           "save_record", "to_record", "from_record", "record_path", "cell", "markdown_table", "ERRATA"]

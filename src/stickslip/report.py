"""`stickslip reproduce`: compute, plot and check every registered figure; write the report.

Each figure's dataset is checkpointed to ``<out>/data/<key>.nc`` (written atomically)
with a fingerprint of the package source and the ``quick`` flag; a rerun (for instance
after the run was killed) loads finished figures instead of recomputing them.
"""

from __future__ import annotations

import datetime as _dt
import hashlib
import inspect
import os
import shutil
import platform
import time
from dataclasses import dataclass, field
from pathlib import Path

import xarray as xr

from .cf import finish, for_file, from_file
from . import __version__, plotting
from .errata import ERRATA, to_markdown
from .errors import ParameterError
from .files import to_netcdf
from .figures import Check, FigureSpec, registry


@dataclass
class FigureOutcome:
    spec: FigureSpec
    checks: list[Check]
    seconds: float
    cached: bool
    image: str
    method: str = ""  # what was computed, for the data used (default: the spec's method)
    data: str = ""  # where the data came from, when that can differ between runs (``ds.attrs["data_source"]``)

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

    @property
    def passed(self) -> bool:
        return all(o.passed for o in self.outcomes)

    def to_dict(self) -> dict:
        return {"out": str(self.out), "quick": self.quick, "passed": self.passed,
                "figures": [{"key": o.spec.key, "passed": o.passed, "checks": len(o.checks),
                             "failed": [c.name for c in o.checks if not c.passed and not c.claim],
                             "not_reproduced": [c.name for c in o.not_reproduced], "seconds": o.seconds,
                             "cached": o.cached} for o in self.outcomes],
                "report": str(self.out / "report.md")}


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


def _load_or_compute(spec: FigureSpec, data_dir: Path, quick: bool, fingerprint: str, force: bool):
    path = data_dir / f"{spec.key}.nc"
    if spec.inputs is not None:  # data from outside the package (a campaign): part of the fingerprint
        fingerprint = f"{fingerprint}+{spec.inputs(data_dir)}"
    if path.exists() and not force:
        try:
            ds = from_file(xr.load_dataset(path))
            if ds.attrs.get("fingerprint") == fingerprint and bool(ds.attrs.get("quick")) == quick:
                return ds, True
        except (OSError, ValueError):
            pass  # unreadable checkpoint (killed mid-write by another tool): recompute
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


def reproduce(out: Path, *, quick: bool = False, only: str | None = None, force: bool = False,
              progress=None) -> Summary:
    """Compute, plot and check the selected figures, then write ``report.md`` and ``report.html``."""
    specs = select(only)
    out = Path(out)
    data_dir = out / "data"
    data_dir.mkdir(parents=True, exist_ok=True)
    fingerprint = source_fingerprint()
    summary = Summary(out, quick)
    for spec in specs:
        if progress:
            progress(spec)
        start = time.perf_counter()
        source = registry()[spec.data_from] if spec.data_from else spec
        ds, cached = _load_or_compute(source, data_dir, quick, fingerprint, force and source is spec)
        image = f"{spec.key}.png"
        problems = plotting.save(spec.plot(ds), out / image)  # the figure's legibility problems
        checks = spec.check(ds) + [Check(
            "the figure is legible at 100 % (stickslip.plotting.legibility_problems)", not problems,
            f"{len(problems)} problem(s)", "none: text >= 7 pt, units on axes, no overlaps, nothing on the data, "
            "every colour code explained", "; ".join(problems[:8]).replace("|", "/"))]
        method = spec.describe(ds) if spec.describe else spec.method
        data = str(ds.attrs.get("data_source", ""))  # a campaign figure's data (CF's "source": the producer)
        summary.outcomes.append(FigureOutcome(spec, checks, time.perf_counter() - start, cached, image, method, data))
        write_report(summary)  # keep the report current while the run proceeds
    return summary


def markdown_report(summary: Summary) -> str:
    """The report of ``summary`` in Markdown."""
    now = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    checks = [c for o in summary.outcomes for c in o.checks]
    n_checks = sum(not c.claim for c in checks)
    n_pass = sum(c.passed for c in checks if not c.claim)
    n_claims = sum(c.claim for c in checks)
    n_reproduced = sum(c.passed for c in checks if c.claim)
    lines = ["# stickslip — reproduction report", "",
             f"Paper: *Friction-induced vibration and stick-slip waves: short survey and new results*. "
             f"stickslip {__version__}, Python {platform.python_version()}, {now}, "
             f"{'quick' if summary.quick else 'full'} mode.", "",
             f"**{n_pass} of {n_checks} checks passed** over {len(summary.outcomes)} figures"
             + (f"; **{n_reproduced} of {n_claims} marked claims of the paper reproduced** (a claim that is not "
                "reproduced is a finding, stated with its numbers, not a failure of the run)." if n_claims else "."),
             "", "| Figure | Model | Checks | Verdict | Time [s] |", "|---|---|---|---|---|"]
    for o in summary.outcomes:
        verdict = ("pass" if o.passed else "**FAIL**") + (f", {len(o.not_reproduced)} claim(s) not reproduced"
                                                          if o.not_reproduced else "")
        lines.append(f"| [{o.spec.title}](#{o.spec.key}) | {o.spec.model} | "
                     f"{sum(c.passed for c in o.checks)}/{len(o.checks)} | {verdict} | "
                     f"{o.seconds:.1f}{' (cached)' if o.cached else ''} |")
    for o in summary.outcomes:
        s = o.spec
        lines += ["", f'<a id="{s.key}"></a>', "", f"## {s.title}", "", f"*Model:* {s.model}", "",
                  f"**The paper's claim.** {s.claim}", "", f"**What was computed.** {o.method or s.method}", "",
                  *([f"**Data used.** {o.data[:1].upper() + o.data[1:]}.", ""] if o.data else []),
                  f"![{s.title}]({o.image})", "", "| Check | Measured | Expected | Verdict | Detail |",
                  "|---|---|---|---|---|"]
        for c in o.checks:
            lines.append(f"| {c.name} | {c.measured} | {c.expected} | {_verdict(c)} | {c.detail} |")
        if s.errata:
            lines += ["", "Errata involved: " + ", ".join(f"[{e}](#errata)" for e in s.errata) + "."]
    lines += ["", '<a id="errata"></a>', ""]
    lines += ["#" + line if line.startswith("#") else line for line in to_markdown().splitlines()]
    return "\n".join(lines) + "\n"


_HTML = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>stickslip reproduction report</title>
<style>body{{font-family:sans-serif;max-width:70em;margin:2em auto;line-height:1.4}}
table{{border-collapse:collapse;margin:1em 0}}td,th{{border:1px solid #ccc;padding:.3em .6em;font-size:90%}}
img{{max-width:100%}}code{{background:#f4f4f4}}</style></head><body>
{body}
</body></html>
"""


def write_report(summary: Summary) -> None:
    import markdown

    md = markdown_report(summary)
    (summary.out / "report.md").write_text(md)
    body = markdown.markdown(md, extensions=["tables"])
    (summary.out / "report.html").write_text(_HTML.format(body=body))


__all__ = ["reproduce", "Summary", "FigureOutcome", "markdown_report", "write_report", "ERRATA"]

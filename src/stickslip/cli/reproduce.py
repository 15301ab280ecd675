"""`stickslip reproduce`: all paper figures and the reproduction report."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Annotated, Optional

import typer
from rich.console import Console

from ..quantities import COMMON
from .common import declared, emit, output_folder
from .status import phase


def reproduce(out: Annotated[Path, typer.Option(help="Output directory.")] = Path("results"),
              quick: Annotated[bool, typer.Option("--quick", help="Coarser, faster runs (same checks).")] = False,
              only: Annotated[Optional[str], typer.Option(
                  help="Comma-separated figure keys, e.g. fig2,fig3; the report keeps the other figures' sections "
                       "from earlier runs in --out.")] = None,
              force: Annotated[bool, typer.Option("--force", help="Recompute even if a checkpoint exists.")] = False,
              workers: Annotated[Optional[int], declared(COMMON["workers"], "--workers",
                                                         "Figures computed at once, each in its own process. "
                                                         "Default: all cores.")] = None,
              json: Annotated[bool, typer.Option("--json", help="Print one JSON summary on stdout.")] = False,
              list_: Annotated[bool, typer.Option("--list", help="List the figure keys and titles, and exit.")] = False
              ) -> int:
    """Compute, plot and check every figure of the paper; write report.md and report.html.

    The report holds every figure run in --out: a run with --only replaces those figures'
    sections and keeps the others (a section from a run of the other mode, or by other code,
    is marked). report.html embeds its images: it can be copied alone.
    """
    if list_:
        from ..figures import registry

        figures = {key: spec.title for key, spec in registry().items()}
        if json:
            emit({"figures": figures}, True, "")
        else:
            for key, title in figures.items():
                print(f"{key:>24}  {title}")
        return 0
    from ..report import reproduce as run

    out = output_folder("--out", out)
    console = Console(stderr=True)
    status = console.status("starting")
    status.start()
    try:
        summary = run(out, quick=quick, only=only, force=force, workers=workers or os.cpu_count() or 1,
                      progress=lambda spec: (status.update(f"{spec.key}: {spec.title}"), phase(f"figure {spec.key}")),
                      waiting=lambda keys, done, total: (status.update(f"computing {', '.join(keys)}"),
                                                         phase(f"{done} of {total} figures done, computing "
                                                               f"{', '.join(keys)}")))
    finally:
        status.stop()
    if json:
        emit(summary.to_dict(), True, "")
    else:
        for o in summary.outcomes:
            mark = "[green]pass[/green]" if o.passed else "[red]FAIL[/red]"
            note = f"  ({len(o.not_reproduced)} paper claim(s) not reproduced)" if o.not_reproduced else ""
            console.print(f"{o.spec.key:>24}  {mark}  {sum(c.passed for c in o.checks)}/{len(o.checks)} checks"
                          f"  {o.seconds:6.1f} s{' (cached)' if o.cached else ''}{note}")
        earlier = len(set(summary.reported) - {o.spec.key for o in summary.outcomes})
        console.print(f"report: {out / 'report.md'} and {out / 'report.html'}"
                      + (f" (with {earlier} figure(s) from earlier runs)" if earlier else ""))
        if summary.unreadable:
            console.print(f"[red]unreadable records left out of the report:[/red] {', '.join(summary.unreadable)}")
    return 0 if summary.passed else 1

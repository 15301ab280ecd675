"""The documentation's parameter tables, written from the declarations
(``python -m stickslip.quantities > docs/parameters.md``; `make docs` does it)."""

from __future__ import annotations

from .core import Domain, Quantity

_TITLES = {"oscillator": "The 1-DOF friction oscillator (`stickslip oscillator`, `stickslip.oscillator`)",
           "brake": "The annulus on a turning shaft (`stickslip brake`, `stickslip.brake`)",
           "halfspace": "The sliding half-space (`stickslip halfspace`, `stickslip.halfspace`)",
           "fem": "Any 2-D body (`stickslip fem`, `stickslip.fem`)",
           "system": "Linear structures with several frictional contacts (`stickslip.system`)",
           "rsf": "Rate-and-state friction and the spring-slider (`stickslip.rsf`)",
           "sbim": "Interfaces in time by the spectral boundary integral method (`stickslip.sbim`)",
           "common": "Shared by every model"}


def _cell(text: str) -> str:
    """Text for a Markdown table cell: a ``|`` would end the cell, so it is escaped."""
    return text.replace("|", "\\|").replace("\n", " ")


def _range(q: Quantity) -> str:
    if q.choices:
        return ", ".join(f"`{c}`" for c in q.choices)
    text = ("integer " if q.integer else "") + q.range.interval
    return _cell(text)


def _units(q: Quantity) -> str:
    return q.scale or ("—" if q.units in ("", "1") else q.units)


def table(domain: Domain, inputs: bool) -> str:
    """A Markdown table of the parameters (``inputs``) or the results of ``domain``."""
    rows = [q for q in domain if (q.range is not None or bool(q.choices)) == inputs]
    if not rows:
        return ""
    if inputs:
        head = "| name | symbol | units | range | meaning | why the range ends there |\n|---|---|---|---|---|---|\n"
        body = "".join(f"| `{q.name}` | {_cell(q.symbol)} | {_units(q)} | {_range(q)} | {_cell(q.meaning)} | "
                       f"{_cell(q.why)} |\n" for q in sorted(rows, key=lambda q: q.name.lower()))
    else:
        head = "| name | units | meaning |\n|---|---|---|\n"
        body = "".join(f"| `{q.name}` | {_units(q)} | {_cell(q.meaning)} |\n"
                       for q in sorted(rows, key=lambda q: q.name.lower()))
    return head + body


def markdown(domains: dict[str, Domain]) -> str:
    """The whole page: for each model, its parameters (with ranges) and the results it writes."""
    out = ["# Parameters and results\n",
           "Every quantity stickslip takes or gives is declared once, in `stickslip.quantities`: its name, symbol, "
           "units, the range of values the models accept (a round bracket leaves the end out, a square one takes it "
           "in) and its meaning. The command line's help and errors, the units of `--json` results, the attributes "
           "of the files written and these tables are all read from there. This page is generated "
           "(`python -m stickslip.quantities`); a name missing from a model's table is looked up under "
           "*Shared by every model*.\n"]
    for name in ("oscillator", "brake", "halfspace", "fem", "system", "rsf", "sbim", "common"):
        domain = domains[name]
        out.append(f"## {_TITLES[name]}\n")
        if domain.units:
            out.append(f"Units: {domain.units}.\n")
        for inputs, title in ((True, "Parameters"), (False, "Results")):
            text = table(domain, inputs)
            if text:
                out.append(f"### {title}\n\n{text}")
    return "\n".join(out)

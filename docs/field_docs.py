"""Every dataclass of the API reference gets a table of its fields: type, units, accepted
range and meaning, read from the quantities' declarations (`stickslip.quantities`) where the
field's name is declared in its model's domain. Connected to autodoc in ``conf.py``."""

from __future__ import annotations

import dataclasses
import re
import typing

#: The package's sub-packages whose quantities live in a domain of their own.
_DOMAINS = ("oscillator", "brake", "halfspace", "fem", "system", "rsf")


def _domain(module: str) -> str:
    parts = module.split(".")
    return next((p for p in parts[1:2] if p in _DOMAINS), "common")


def _type(field, hints) -> str:
    hint = hints.get(field.name, field.type)
    text = hint if isinstance(hint, str) else getattr(hint, "__name__", None) or str(hint)
    return text.replace("typing.", "").replace("numpy.", "np.")


def field_rows(cls) -> list[tuple[str, str, str, str, str]]:
    """``(name, type, units, range, meaning)`` of each public field of the dataclass ``cls``."""
    from stickslip.quantities import declared

    try:
        hints = typing.get_type_hints(cls)
    except Exception:  # a hint that does not resolve: the text as written
        hints = {}
    domain = _domain(cls.__module__)
    rows = []
    for field in dataclasses.fields(cls):
        if field.name.startswith("_"):
            continue
        q = declared(field.name, domain)
        if q is None:
            rows.append((field.name, _type(field, hints), "", "", ""))
            continue
        units = q.scale or q.units
        span = ", ".join(q.choices) if q.choices else (q.range.text() if q.range is not None else "")
        symbol = f" ({q.symbol})" if q.symbol and q.symbol not in q.meaning.split() else ""
        meaning = q.meaning[:1].upper() + q.meaning[1:] + symbol
        rows.append((field.name, _type(field, hints), units, span, meaning))
    return rows


def _prose(text: str) -> str:
    """Text set as reST prose: ``|x|`` is not a substitution, ``*`` not emphasis, ``x_`` not a link."""
    text = re.sub(r"([\\|*`])", r"\\\1", text)
    return re.sub(r"_(?=\W|$)", r"\\_", text)


def _literal(text: str) -> str:
    return f"``{text}``" if text else ""


def add_field_table(app, what, name, obj, options, lines) -> None:
    """autodoc-process-docstring: a dataclass's docstring ends with its fields' table."""
    if what != "class" or not dataclasses.is_dataclass(obj) or not name.startswith("stickslip."):
        return
    rows = field_rows(obj)
    if not rows:
        return
    lines += ["", ".. rubric:: Fields", "",
              ".. list-table::", "   :header-rows: 1", "   :widths: 18 22 12 20 28", "",
              "   * - field", "     - type", "     - units", "     - accepted", "     - meaning"]
    for field, kind, units, span, meaning in rows:
        lines += [f"   * - {_literal(field)}", f"     - {_literal(kind)}", f"     - {_literal(units)}",
                  f"     - {_literal(span)}", f"     - {_prose(meaning)}"]
    lines.append("")

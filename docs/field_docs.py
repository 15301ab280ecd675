"""Every dataclass of the API reference gets a table of its fields: type, units, accepted
range and meaning, read from the quantities' declarations (`stickslip.quantities`) where the
field's name is declared in its model's domain. Connected to autodoc in ``conf.py`` (`connect`).

The table is a dataclass's only list of its fields. Without the handlers below autodoc lists them
up to three more times: as the constructor's parameters with their types (``autodoc_typehints =
"description"``: every field is a parameter of the generated ``__init__``), as the docstring's
numpy "Parameters"/"Attributes" sections (napoleon's ``:param:``/``:ivar:`` lines), and as
attributes where a field has a ``#:`` comment. The descriptions of the last two go into the
table's meaning column instead."""

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


def _meaning(declared: str, described: str) -> str:
    """The declared meaning (as prose), then the docstring's description (reST as written)."""
    text = _prose(declared)
    return f"{text}. {described}" if text and described else text or described


def _literal(text: str) -> str:
    return f"``{text}``" if text else ""


#: A field line napoleon writes (``:param x:``, ``:type x:``, ``:ivar x:``, ``:vartype x:``).
_FIELD_LINE = re.compile(r"^:(param|type|ivar|vartype)\s+(?:[^:]*\s)?(\w+):\s*(.*)$")


def _is_documented_dataclass(what, name, obj) -> bool:
    return what == "class" and dataclasses.is_dataclass(obj) and isinstance(obj, type) and name.startswith("stickslip.")


def take_field_lines(lines: list[str], fields: set[str]) -> dict[str, str]:
    """Remove from ``lines`` the napoleon field lines (and their indented continuations) of ``fields``;
    return the descriptions of those fields (``:param:`` and ``:ivar:``)."""
    kept, described, i = [], {}, 0
    while i < len(lines):
        m = _FIELD_LINE.match(lines[i])
        if m is None or m.group(2) not in fields:
            kept.append(lines[i])
            i += 1
            continue
        text = [m.group(3).strip()]
        i += 1
        while i < len(lines) and lines[i][:1] in (" ", "\t") and lines[i].strip():
            text.append(lines[i].strip())
            i += 1
        if m.group(1) in ("param", "ivar") and " ".join(text).strip():
            described[m.group(2)] = " ".join(text).strip()
    lines[:] = kept
    return described


def _attribute_docs(cls) -> dict[str, str]:
    """The ``#:`` comments (or strings after) of the fields of ``cls``, as autodoc reads them."""
    from sphinx.pycode import ModuleAnalyzer

    try:
        docs = ModuleAnalyzer.for_module(cls.__module__).find_attr_docs()
    except Exception:  # no source: nothing to add
        return {}
    return {attr: " ".join(line.strip() for line in text if line.strip())
            for (owner, attr), text in docs.items() if owner == cls.__qualname__}


def add_field_table(app, what, name, obj, options, lines) -> None:
    """autodoc-process-docstring: a dataclass's docstring ends with its fields' table, its fields'
    ``:param:``/``:ivar:`` lines folded into the table."""
    if not _is_documented_dataclass(what, name, obj):
        return
    fields = {f.name for f in dataclasses.fields(obj)}
    described = _attribute_docs(obj) if app is not None else {}
    described = {k: v for k, v in described.items() if k in fields}
    described.update(take_field_lines(lines, fields))
    rows = field_rows(obj)
    if not rows:
        return
    lines += ["", ".. rubric:: Fields", "",
              ".. list-table::", "   :header-rows: 1", "   :widths: 18 22 12 20 28", "",
              "   * - field", "     - type", "     - units", "     - accepted", "     - meaning"]
    for field, kind, units, span, meaning in rows:
        lines += [f"   * - {_literal(field)}", f"     - {_literal(kind)}", f"     - {_literal(units)}",
                  f"     - {_literal(span)}", f"     - {_meaning(meaning, described.get(field, ''))}"]
    lines.append("")


def drop_constructor_types(app, what, name, obj, options, signature, return_annotation):
    """autodoc-process-signature: a dataclass's constructor parameters are its fields, in the table:
    autodoc's list of them with their types (``autodoc_typehints = "description"``) is not added."""
    if _is_documented_dataclass(what, name, obj):
        app.env.current_document.autodoc_annotations.pop(name, None)


def owner_field(module: str, fullname: str) -> bool:
    """Whether ``module.fullname`` (``stickslip.rsf``, ``SliderRun.theta``) is a field of a dataclass."""
    import importlib

    owner, _, attr = fullname.rpartition(".")
    try:
        obj = importlib.import_module(module)
        for part in owner.split("."):
            obj = getattr(obj, part)
    except (ImportError, AttributeError, ValueError):
        return False
    return dataclasses.is_dataclass(obj) and attr in {f.name for f in dataclasses.fields(obj)}


def drop_field_attributes(app, doctree) -> None:
    """doctree-read: a dataclass field autodoc listed as an attribute or a method (it has a ``#:``
    comment) is removed, with its index entry: its comment is in the fields' table."""
    from sphinx import addnodes

    for desc in list(doctree.findall(addnodes.desc)):
        # a field with a ``#:`` comment is an attribute, or a method when its default is a staticmethod
        if desc.get("domain") != "py" or desc.get("objtype") not in ("attribute", "method") or not desc.children:
            continue
        sig = desc.children[0]
        if sig.get("module", "").startswith("stickslip") and owner_field(sig["module"], sig.get("fullname", "")):
            parent = desc.parent
            at = parent.index(desc)
            if at > 0 and isinstance(parent[at - 1], addnodes.index):
                parent.remove(parent[at - 1])
            parent.remove(desc)


def connect(app) -> None:
    """The handlers, connected after autodoc's and napoleon's own."""
    app.connect("autodoc-process-docstring", add_field_table)  # after napoleon: the fields' table
    app.connect("autodoc-process-signature", drop_constructor_types, priority=600)
    app.connect("doctree-read", drop_field_attributes)

"""The API reference reads well (issue 27): every public dataclass gets a table of its fields
with units and ranges from the declarations, valid reST whatever the declarations' text holds;
no property's summary line is split by napoleon into a bogus type."""

import dataclasses
import importlib
import io
import inspect
import pkgutil
import re
import sys
from pathlib import Path

import docutils.core

import stickslip

DOCS = Path(__file__).resolve().parents[1] / "docs"


def _public_classes():
    for info in pkgutil.walk_packages(stickslip.__path__, "stickslip."):
        if info.name.endswith("__main__") or ".cli" in info.name or info.name.endswith("vocabulary"):
            continue
        module = importlib.import_module(info.name)
        for name, obj in vars(module).items():
            if inspect.isclass(obj) and obj.__module__ == module.__name__ and not name.startswith("_"):
                yield f"{module.__name__}.{name}", obj


CLASSES = sorted(dict(_public_classes()).items())


def _field_docs():
    sys.path.insert(0, str(DOCS))
    try:
        import field_docs
    finally:
        sys.path.remove(str(DOCS))
    return field_docs


def test_every_dataclass_field_table_is_valid_rest_with_the_declared_units():
    field_docs = _field_docs()
    tables = 0
    for name, cls in CLASSES:
        if not dataclasses.is_dataclass(cls):
            continue
        lines: list[str] = []
        field_docs.add_field_table(None, "class", name, cls, {}, lines)
        if not lines:
            continue
        tables += 1
        messages = io.StringIO()  # docutils' warnings and errors (an undefined |substitution|, a bad table)
        docutils.core.publish_doctree("\n".join(lines), settings_overrides={
            "report_level": 2, "halt_level": 5, "warning_stream": messages})
        assert not messages.getvalue(), (name, messages.getvalue()[:300])
        # the table has a row per public field, and the declared units where the field is declared
        rows = {r[0]: r for r in field_docs.field_rows(cls)}
        assert set(rows) == {f.name for f in dataclasses.fields(cls) if not f.name.startswith("_")}
    assert tables >= 40


def test_the_oscillator_fields_carry_their_si_units():
    field_docs = _field_docs()
    from stickslip.oscillator import Oscillator

    units = {name: unit for name, _, unit, _, _ in field_docs.field_rows(Oscillator)}
    assert units == {"mass": "kg", "stiffness": "N/m", "normal_force": "N", "belt_speed": "m/s", "friction": "",
                     "damping": "N s/m"}


def test_no_property_summary_reads_as_a_type_for_napoleon():
    """napoleon reads a property's first line ``a: b`` as type ``a``, description ``b`` (Body.areas was
    shown as a type 'Signed area of every cell (positive')."""
    bad = []
    for name, cls in CLASSES:
        for attr, value in vars(cls).items():
            if isinstance(value, property) and value.__doc__:
                first = value.__doc__.strip().splitlines()[0]
                if re.match(r"^[^:`]{1,60}: ", first):
                    bad.append(f"{name}.{attr}: {first[:60]}")
    assert not bad, bad

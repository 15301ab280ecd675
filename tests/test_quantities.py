"""Every parameter and result declared once (issue 23): the declarations are well formed, every
numeric option of the command line and every numeric parameter of the public functions reads
one, the command line refuses a value just beyond each declared end (and says the range), the
docs' tables are the declarations', and no module checks a range of its own."""

from __future__ import annotations

import importlib
import inspect
import math
import numbers
import re
import typing
from pathlib import Path

import pytest

from stickslip.cf import is_udunits
from stickslip.cli import run
from stickslip.errors import ParameterError
from stickslip.quantities import DOMAINS, Quantity, Range, declared
from stickslip.quantities.tables import markdown

from .fuzz_harness import BASE, args_for, base_type, cli_params

ROOT = Path(__file__).resolve().parents[1]
ALL = [(d, q) for d, domain in DOMAINS.items() for q in domain._q.values()]


@pytest.mark.parametrize("domain, q", ALL, ids=[f"{d}.{q.name}" for d, q in ALL])
def test_every_declaration_is_well_formed(domain, q):
    assert q.meaning and q.meaning == q.meaning.strip()
    assert q.units == "" or is_udunits(q.units), q.units
    if q.range is not None:
        assert q.range.lo < q.range.hi or (q.range.lo == q.range.hi and not (q.range.lo_open or q.range.hi_open))
        assert math.isfinite(q.range.lo) or q.range.lo_open
        assert q.units != "" or q.integer, "a measured parameter has units ('1' for a pure number)"
    if q.choices:
        assert q.units == "" and q.range is None


def test_ranges_read_as_written_and_check_both_ends():
    r = Range.parse("(0, 1e15]")
    assert (0.0 in r, 1e15 in r, 1e-300 in r, 1.0000001e15 in r) == (False, True, True, False)
    assert Range.parse("[0, 0.5)").text() == "in [0, 0.5)" and Range.parse("(0, inf)").text() == "> 0"
    q = Quantity("mass", "kg", "mass", range=Range.parse("[1e-15, 1e15]"))
    for bad in (1e-16, 2e15, float("nan"), float("inf"), 1e-320, "1", True, None, [1.0]):
        with pytest.raises(ParameterError) as err:
            q.check(bad, "--mass")
        assert err.value.name == "--mass"
    assert q.check(1e15) == 1e15 and q.check(1e-15) == 1e-15
    n = Quantity("samples", "1", "samples", range=Range.parse("[10, 1e7]"), integer=True)
    assert n.check(10.0) == 10 and isinstance(n.check(10.0), int)
    for bad in (9, 10.5, 10**400, 1e7 + 1):
        with pytest.raises(ParameterError):
            n.check(bad)


def _numeric_options():
    """``(command, option, declaration or None, param)`` of every int/float option of the command line."""
    return [(command, param.opts[0], getattr(hint.__metadata__[0], "quantity", None), param)
            for command, param, hint in cli_params()
            if getattr(param, "param_type_name", "") == "option" and typing.get_origin(hint) is typing.Annotated
            and base_type(hint) in (int, float)]


NUMERIC = _numeric_options()


def test_every_numeric_option_reads_a_declaration_and_says_its_range():
    assert len(NUMERIC) > 100
    undeclared = [f"{c} {o}" for c, o, q, _ in NUMERIC if q is None]
    assert not undeclared, undeclared
    for command, option, q, param in NUMERIC:
        assert q.help() in param.help, (command, option)  # the declaration's words, range included


def _edges(q: Quantity):
    """Values just beyond each finite end of a range (the end itself where it is left out)."""
    r, out = q.range, []
    for end, open_, outward in ((r.lo, r.lo_open, -math.inf), (r.hi, r.hi_open, math.inf)):
        if math.isfinite(end):
            out.append(end if open_ else (math.nextafter(end, outward) if not q.integer else end + math.copysign(1, outward)))
    return out


EDGES = [(c, o, v) for c, o, q, _ in NUMERIC if c in BASE for v in _edges(q)]


@pytest.mark.parametrize("command, option, value", EDGES, ids=[f"{c} {o} {v!r}" for c, o, v in EDGES])
def test_a_value_just_beyond_a_declared_end_is_refused_naming_the_option_and_the_range(command, option, value,
                                                                                     tmp_path, capsys):
    q = next(q for c, o, q, _ in NUMERIC if (c, o) == (command, option))
    text = repr(int(value)) if q.integer else repr(value)
    assert run(args_for(command, option, text, tmp_path)) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and f"{option} = " in err and q.range.text() in err, err


#: Public callables whose numeric parameters are results, not inputs (records of a computation).
RESULTS = {"Radok"}
MODULES = {"stickslip.oscillator": "oscillator", "stickslip.friction": "oscillator", "stickslip.brake": "brake",
           "stickslip.brake.fem": "brake", "stickslip.brake.ring": "brake", "stickslip.brake.waves": "brake",
           "stickslip.halfspace": "halfspace", "stickslip.fem": "fem", "stickslip.contact": "common",
           "stickslip.sweep": "common", "stickslip.sbim": "sbim"}


def _api_parameters():
    from stickslip.contact import RunRecord
    from stickslip.results import Result

    for module, domain in MODULES.items():
        m = importlib.import_module(module)
        for name in m.__all__:
            obj = getattr(m, name)
            if not callable(obj) or name in RESULTS or (inspect.isclass(obj) and issubclass(obj, (Result, RunRecord))):
                continue
            try:
                signature = inspect.signature(obj)
                hints = typing.get_type_hints(obj.__init__ if inspect.isclass(obj) else obj)
            except (TypeError, ValueError, NameError):
                continue
            for p in signature.parameters.values():
                numeric = isinstance(p.default, numbers.Real) and not isinstance(p.default, bool)
                if numeric or hints.get(p.name) in (float, int, float | None, int | None):
                    yield module, domain, name, p.name


def test_every_numeric_parameter_of_the_public_functions_is_declared():
    params = list(_api_parameters())
    assert len(params) > 100
    missing = [f"{m}.{f}({p})" for m, d, f, p in params if declared(p, d) is None]
    assert not missing, missing


def test_the_docs_tables_are_the_declarations():
    assert (ROOT / "docs" / "parameters.md").read_text() == markdown(DOMAINS), \
        "docs/parameters.md is stale: python -m stickslip.quantities > docs/parameters.md"
    text = markdown(DOMAINS)
    assert "| `mass` | m | kg | [1e-15, 1e15] |" in text


#: The low-level range checks a model must not call: its ranges are declared.
_OWN_RANGES = re.compile(r"\bcheck\.(finite|positive|nonnegative|in_range|greater_than|poisson_ratio|radius_ratio|"
                         r"positive_int|count)\(")


def test_no_module_checks_a_range_of_its_own():
    found = [f"{p.relative_to(ROOT)}:{i}" for p in (ROOT / "src" / "stickslip").rglob("*.py")
             for i, line in enumerate(p.read_text().splitlines(), 1)
             if _OWN_RANGES.search(line) and "validation.py" not in p.name
             and p.relative_to(ROOT).as_posix() != "src/stickslip/sweep/grid.py"]
    assert not found, found


def test_the_old_vocabulary_still_answers_with_one_line_on_stderr():
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-c", "from stickslip.vocabulary import lookup, VOCABULARY; "
                           "print(lookup('mass', 'oscillator'), VOCABULARY['oscillator']['mass'])"],
                          capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "('kg', 'mass') ('kg', 'mass')"
    assert done.stderr.count("\n") == 1 and "deprecated" in done.stderr and "stickslip.quantities" in done.stderr

"""Fuzzing from the declarations (issue 23): the values a quantity's declared range makes special
(each end, just beyond it, just inside an open one, zero, +-1, +-1e300, 1e-300, a subnormal, a
huge count) on every declared option of every command, values Hypothesis draws inside and
around each range, every public function's parameters with the same values, and files that
are corrupt or of another kind wherever a command reads one.

Every trial runs in a forked child with a time limit (`fuzz_harness.trial`, `api_call`). The
contract (`fuzz_harness.problems`): exit 0 with finite numbers only and nothing on stderr, or
exit 1/2 with one line (naming the option as typed for 2); never exit 3, a signal, a traceback
or a hang; a function raises only `ParameterError` or `NoSolutionError`. `make test` runs a
fixed twenty-fourth of the declared values (without the large valid sizes, runs of minutes); the slow
set (CI) a quarter of the others and the generated ones.
``python -m tests.fuzz_harness`` prints the counts of the whole battery.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .budget import examples
from .fuzz_harness import (BASE, DRAWN_LEFT_OUT, EXTREMES, LONG_BY_DESIGN, OPTIONS, args_for, declared_cases,
                           declared_options, problems, trial, typed)
from .test_fuzz_api import CALLS

CASES = declared_cases()
RANGES = {(c, o): q.range for c, o, q in declared_options()}


#: Options of a run's length in time: a long one is legal and runs until its budget of work says no.
DURATIONS = {"--t-end", "--transits", "--transient"}


def _large_and_valid(case) -> bool:
    """A size over a thousand the declarations allow (a legal run of minutes: a continuation
    of 100000 points takes three), or a duration over 1e4 (rsf slide --t-end 1e300 runs 25 s
    before its budget of evaluations stops it), tried in the slow set only."""
    command, option, value = case
    try:
        duration = option in DURATIONS and 1e4 < float(value) and float(value) in RANGES[command, option]
    except ValueError:
        duration = False
    return (value.isdigit() and 1000 < int(value) < 10**8) or duration


FAST = [c for c in CASES[::48] if not _large_and_valid(c)]
#: The other half of every 24th value, and a quarter of the rest (every fourth), leaving out the
#: values test_fuzz_cli tries on every option already (0, -1, +-1e300, ...) and the large valid
#: sizes (legal runs of minutes): all of them would add an hour to CI; the whole battery is
#: ``python -m tests.fuzz_harness``.
SLOW = [c for c in CASES[24::48] if not _large_and_valid(c)] + \
    [c for c in CASES if c not in CASES[::24] and not _large_and_valid(c)
     and not (c[2] in EXTREMES and c[:2] in OPTIONS)][::4]


def _check(command, option, value, folder):
    t = trial(args_for(command, option, value, folder), timeout=300)
    found = problems(t, option, folder)
    assert not found, (t.args, t.code, found, t.err[-400:], t.out[:200])


def test_every_declared_option_has_its_special_values():
    assert len(CASES) > 1500 and {c for c, _, _ in CASES} == set(BASE) - {"fem steady", "system stability"}


@pytest.mark.parametrize("command, option, value", FAST, ids=[f"{c} {o} {v}" for c, o, v in FAST])
def test_a_forty_eighth_of_the_declared_values(command, option, value, tmp_path):
    _check(command, option, value, tmp_path)


@pytest.mark.slow
@pytest.mark.parametrize("command, option, value", SLOW, ids=[f"{c} {o} {v}" for c, o, v in SLOW])
def test_a_quarter_of_the_other_declared_values(command, option, value, tmp_path):
    _check(command, option, value, tmp_path)


#: The options of the generated battery: every declared one but the sizes of a run or a map,
#: whose large valid values are legal computations of minutes or hours (their ends are tried
#: above, where the work budgets refuse what exceeds them).
GENERATED = [(c, o, q) for c, o, q in declared_options() if c in BASE and not q.integer
             and c not in LONG_BY_DESIGN and o not in DRAWN_LEFT_OUT]


def _inside_and_around(q):
    r = q.range
    lo = r.lo if math.isfinite(r.lo) else -1e300
    hi = r.hi if math.isfinite(r.hi) else 1e300
    span = st.floats(lo, hi, allow_nan=False)
    if lo > 0 and hi / lo > 1e3:  # a range of many decades: drawn uniformly in the logarithm too
        span = st.one_of(span, st.floats(math.log10(lo), math.log10(hi)).map(lambda e: 10.0 ** e))
    return st.one_of(span, st.floats(lo - abs(lo) - 1, hi + abs(hi) + 1, allow_nan=False), st.floats())


@pytest.mark.slow
@settings(max_examples=examples(100),  # the bounded profile: the same examples in every CI run
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(data=st.data())
def test_values_drawn_from_each_declared_range(data, tmp_path_factory):
    command, option, q = data.draw(st.sampled_from(GENERATED))
    value = data.draw(_inside_and_around(q))
    _check(command, option, typed(value, False), tmp_path_factory.mktemp("drawn"))


API = [(name, param) for name, (_, params) in CALLS.items() for param in params]
_SERVER = []


def _api_server():
    """This test process's `fuzz_harness.api_serve` (started on first use, ended with the process)."""
    import subprocess
    import sys
    from pathlib import Path

    if not _SERVER or _SERVER[0].poll() is not None:
        _SERVER[:] = [subprocess.Popen([sys.executable, "-m", "tests.fuzz_harness", "--api-serve"],
                                       cwd=Path(__file__).resolve().parents[1], stdin=subprocess.PIPE,
                                       stdout=subprocess.PIPE, text=True)]
    return _SERVER[0]


@pytest.mark.slow
@pytest.mark.parametrize("name, param", API, ids=[f"{n} {p}" for n, p in API])
def test_every_public_parameter_with_its_declared_and_bad_values(name, param):
    """Each call forked with a time limit from a clean interpreter (`fuzz_harness.api_serve`;
    a fork of this test process, which may hold threads of Dask or Zarr, can deadlock)."""
    import json

    server = _api_server()
    server.stdin.write(f"{name}\t{param}\n")
    server.stdin.flush()
    answer = server.stdout.readline()
    assert answer, f"the API fuzz server ended (exit {server.wait()})"
    assert json.loads(answer) == []

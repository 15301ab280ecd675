"""Fuzzing the command line (issue 9): every numeric option of every command, one bad or
extreme value at a time, on an otherwise valid and cheap invocation (`fuzz_harness.BASE`).

* Values that are never a number (NaN, infinities, text, empty): exit 2 and one line on
  stderr naming the option as typed (``--t-end``, not ``t_end``). In-process, all options.
* Extreme but finite values (0, -1, +-1e300, 1e-300, the subnormal 1e-320): a finite result (stdout and every
  file written) with nothing on stderr, or exit 1/2 with one line, the option named for
  exit 2; never exit 3, a traceback or a hang. Each trial runs in a forked child with a
  time limit (`fuzz_harness.trial`). `make test` runs two of the six values per option
  (the pair rotates over the options, so each value meets a third of them); the slow
  set (CI) runs the other four on every option, and a Hypothesis-generated battery of
  values on options.
"""

from __future__ import annotations


import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from stickslip.cli import run

from .budget import examples
from .fuzz_harness import time_limit
from .fuzz_harness import (BASE, EXTREMES, NEVER_NUMBERS, OPTIONS, PATH_OPTIONS, args_for, bad_places,
                           path_args, problems, trial)


def test_every_command_has_a_base_invocation():
    assert {c for c, _ in OPTIONS} <= set(BASE) and len(OPTIONS) > 60




@pytest.mark.parametrize("command, option", OPTIONS, ids=[f"{c} {o}" for c, o in OPTIONS])
def test_a_value_that_is_no_number_is_refused_in_one_line_naming_the_option(command, option, tmp_path, capsys):
    for value in NEVER_NUMBERS:
        with time_limit(120):  # a hang guard, not a timing check: each trial is refused in milliseconds
            code = run(args_for(command, option, value, tmp_path))
        out, err = capsys.readouterr()
        assert code == 2 and out == "", (value, code, out, err)
        assert err.count("\n") == 1 and option in err and "Traceback" not in err, (value, err)


def _fast_values(index: int) -> list[str]:
    """The one value `make test` tries on option ``index`` (rotating through `EXTREMES`, so that
    every value meets some options); the slow set tries the others."""
    return [EXTREMES[(index // 4) % len(EXTREMES)]]


#: The options `make test` tries an extreme value on: every fourth one (the slow set tries every
#: value on every option).
FAST_OPTIONS = range(0, len(OPTIONS), 4)


@pytest.mark.parametrize("index", FAST_OPTIONS, ids=[" ".join(OPTIONS[i]) for i in FAST_OPTIONS])
def test_extreme_values_give_a_finite_result_or_one_clear_line(index, tmp_path):
    command, option = OPTIONS[index]
    for value in _fast_values(index):
        folder = tmp_path / value
        folder.mkdir()
        t = trial(args_for(command, option, value, folder), timeout=300)
        assert not problems(t, option, folder), (t.args, t.code, t.err[-400:], t.out[:300])


@pytest.mark.slow
@pytest.mark.parametrize("index", range(len(OPTIONS)), ids=[f"{c} {o}" for c, o in OPTIONS])
def test_every_extreme_value_on_every_option(index, tmp_path):
    command, option = OPTIONS[index]
    for value in EXTREMES:
        if index in FAST_OPTIONS and value in _fast_values(index):
            continue
        folder = tmp_path / value
        folder.mkdir()
        t = trial(args_for(command, option, value, folder), timeout=300)
        assert not problems(t, option, folder), (t.args, t.code, t.err[-400:], t.out[:300])


NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.integers(-10**15, 10**15).map(str),
    st.floats(-1e6, 1e6).map(lambda x: f"{x:.3g}"),
    st.sampled_from(["1e308", "-0", "0.0", "1e-320", "4.9e-324", "1_000", "0x10", " 1", "1e", "--", "nan0"]),
)


#: Sizes and durations: a large valid value is a legal run of minutes or hours (10^7 samples,
#: a 65536-node mesh, 10^6 transits, a campaign of 1000 seeds), not a hang. Their bounds are
#: tried by the extreme values above; the generated battery leaves them out.
SIZES = {"--samples", "--points", "--nodes", "--n-theta", "--n-r", "--wave-number", "--wave-numbers", "--seeds", "--geometry-seeds",
         "--workers", "--transits", "--t-end"}
GENERATED = [i for i, (_, option) in enumerate(OPTIONS) if option not in SIZES]


@pytest.mark.slow
@settings(max_examples=examples(60),  # the bounded profile: the same examples in every CI run
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(index=st.sampled_from(GENERATED), value=NUMBERS)
def test_generated_values_on_generated_options(index, value, tmp_path_factory):
    command, option = OPTIONS[index]
    folder = tmp_path_factory.mktemp("fuzz")
    t = trial(args_for(command, option, value, folder), timeout=300)
    assert not problems(t, option, folder), (t.args, t.code, t.err[-400:], t.out[:300])


def _path_trial(index, kind, tmp_path):
    command, option = PATH_OPTIONS[index]
    folder = tmp_path / kind.replace(" ", "-")
    folder.mkdir()
    t = trial(path_args(command, option, kind, folder), timeout=300)
    found = problems(t, option, folder)
    if t.code == 0 and kind != "another suffix":
        found.append("wrote to a bad place")
    assert not found, (t.args, t.code, t.err[-400:], found)
    if t.code != 0:  # refused before any work: no store, checkpoint or partial file left behind
        assert sorted(p.name for p in folder.iterdir()) == ["file"], list(folder.iterdir())


@pytest.mark.parametrize("index", range(len(PATH_OPTIONS)), ids=[f"{c} {o}" for c, o in PATH_OPTIONS])
def test_a_bad_place_to_write_is_refused_before_any_work(index, tmp_path):
    """A folder, a missing folder, an unwritable place, a path under a file or another suffix
    for every output, checkpoint and store option: one line naming the option, exit 2, and
    nothing written. `make test` tries one place per option (rotating), the slow set all."""
    places = bad_places(*PATH_OPTIONS[index])
    _path_trial(index, places[index % len(places)], tmp_path)


@pytest.mark.slow
@pytest.mark.parametrize("index", range(len(PATH_OPTIONS)), ids=[f"{c} {o}" for c, o in PATH_OPTIONS])
def test_every_bad_place_to_write_is_refused_before_any_work(index, tmp_path):
    places = bad_places(*PATH_OPTIONS[index])
    for kind in places:
        if kind != places[index % len(places)]:
            _path_trial(index, kind, tmp_path)

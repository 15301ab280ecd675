"""The validators refuse every bad value with a `ParameterError` naming it, and never let
another exception (TypeError, OverflowError, ValueError from a conversion) escape."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from stickslip import validation as check
from stickslip.errors import ParameterError

from .budget import examples

ANYTHING = st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=True, allow_infinity=True),
                     st.text(max_size=5), st.lists(st.integers(), max_size=2), st.complex_numbers())


def _outcome(func, *args):
    try:
        return func(*args)
    except ParameterError as err:
        assert err.name == "x" and err.allowed
        return err


@settings(max_examples=examples(100))  # no deadline: the profiles set none (a loaded CI machine must not fail them)
@given(ANYTHING)
def test_positive_int_accepts_only_integers_from_one(value):
    out = _outcome(check.positive_int, "x", value)
    ok = (not isinstance(value, bool) and isinstance(value, (int, float)) and math.isfinite(value)
          and int(value) == value and value >= 1)
    assert (out == int(value)) if ok else isinstance(out, ParameterError)


@settings(max_examples=examples(100))  # no deadline: the profiles set none (a loaded CI machine must not fail them)
@given(ANYTHING)
def test_count_is_bounded(value):
    out = _outcome(check.count, "x", value, 1000)
    ok = (not isinstance(value, bool) and isinstance(value, (int, float)) and math.isfinite(value)
          and int(value) == value and 1 <= value <= 1000)
    assert (out == int(value)) if ok else (isinstance(out, ParameterError) and "from 1 to 1000" in out.allowed)


@settings(max_examples=examples(100))  # no deadline: the profiles set none (a loaded CI machine must not fail them)
@given(ANYTHING)
def test_positive_and_finite_refuse_what_is_not_a_finite_real(value):
    for func in (check.finite, check.positive, check.nonnegative):
        out = _outcome(func, "x", value)
        if not isinstance(out, ParameterError):
            assert isinstance(out, float) and math.isfinite(out)
            assert out == 0.0 or abs(out) >= 2.2250738585072014e-308  # zero or normal, never subnormal


def test_numpy_integers_are_integers():
    assert check.positive_int("x", np.int64(3)) == 3 and check.count("x", np.float64(4.0), 5) == 4


@pytest.mark.parametrize("value", [1e-320, -4.9e-324, 2.2e-308])
def test_subnormal_numbers_are_refused_and_naming_the_option(value):
    """1e-320 as a density or a mass reached divisions by zero and infinite frequencies (found
    by the CLI fuzz test); zero and the smallest normal number pass."""
    for func in (check.finite, check.nonnegative if value > 0 else check.finite):
        with pytest.raises(ParameterError, match="subnormal") as err:
            func("density", value)
        assert err.value.name == "density"
    assert check.finite("x", 0.0) == 0.0 and check.positive("x", 2.2250738585072014e-308) > 0

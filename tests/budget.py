"""What a test may spend: the examples of a property test under the Hypothesis profile of the
session (`tests/conftest.py`: ``bounded`` for ``make test`` and CI, ``deep`` for ``make test-deep``)."""

from __future__ import annotations

from hypothesis import settings

#: Hypothesis's own default number of examples, the ``bounded`` profile's.
BOUNDED = 100


def examples(n: int) -> int:
    """``n`` examples under the bounded profile, ten times as many under the deep one."""
    return max(1, round(n * settings.default.max_examples / BOUNDED))

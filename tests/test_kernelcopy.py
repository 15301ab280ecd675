"""The compiled kernels' copies between arrays against numpy's slice assignment."""

import numpy as np
import pytest

from stickslip.kernelcopy import copy, copy_rows


def test_copy_into_a_vector_and_a_row_writes_what_numpy_writes():
    rng = np.random.default_rng(1)
    src, dst = rng.standard_normal(5), rng.standard_normal(7)
    expected = dst.copy()
    expected[:5] = src
    copy(dst, src)
    assert np.array_equal(dst, expected)
    matrix = rng.standard_normal((3, 5))
    expected = matrix.copy()
    expected[1] = src
    copy(matrix[1], src)
    assert np.array_equal(matrix, expected)


@pytest.mark.parametrize("at, count", [(0, 4), (2, 3), (6, 0), (5, 1)])
def test_copy_rows_writes_what_numpy_writes_and_no_more(at, count):
    rng = np.random.default_rng(at + 10 * count)
    src, dst = rng.standard_normal((4, 3)), rng.standard_normal((6, 3))
    expected = dst.copy()
    expected[at:at + count] = src[:count]
    copy_rows(dst, at, src, count)
    assert np.array_equal(dst, expected)

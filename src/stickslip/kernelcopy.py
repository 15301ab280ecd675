"""Copies between arrays inside the compiled kernels (numba), written as loops.

numba compiles each assignment of an array into a slice (``a[:] = b``, ``a[i] = row``,
``a[i:j] = b[:n]``) with its own shape-mismatch error path, formatted message included: about
half a second of compilation each, and 27 of them were 7 of the 20 s in which a first process
compiled the oscillator's event loop (benchmarks/compiled_first_call.py). A call of `copy` or
`copy_rows` compiles once per pair of array types and copies the same bits.
"""

from __future__ import annotations

from numba import njit

__all__ = ["copy", "copy_rows"]


@njit(cache=True)
def copy(dst, src):
    """``dst[:src.size] = src`` for one-dimensional ``dst`` and ``src`` (a row of a matrix is one)."""
    for i in range(src.size):
        dst[i] = src[i]


@njit(cache=True)
def copy_rows(dst, at, src, count):
    """``dst[at:at + count] = src[:count]`` for matrices with the same number of columns."""
    for r in range(count):
        for j in range(src.shape[1]):
            dst[at + r, j] = src[r, j]

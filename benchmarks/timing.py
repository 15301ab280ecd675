"""Timing helper shared by the benchmark scripts (not a benchmark itself)."""

import time


def best_of(fn, repeat: int = 3):
    """``(seconds, result)``: the shortest wall time of ``repeat`` calls of ``fn`` and its last result."""
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out

"""Each mode's history of slip rates, as long as that mode keeps it, and the convolution with its
kernel's step weights: compiled by numba for long runs, interpreted for short ones (`stickslip.jit`).

Mode ``m`` keeps ``n_m`` steps (``eta`` of its periods, `stickslip.sbim.kernels`), so the modes' buffers
are ragged: all are stored one after the other in a flat array (``offsets``), each a ring whose slot
of step ``s`` is ``s mod n_m``. A step costs ``sum_m n_m`` complex products: about
``(eta N / beta) ln(N / 2)``, not the ``N / 2`` times the longest of a rectangular history.
"""

from __future__ import annotations

import numpy as np

from ..jit import KernelSet

__all__ = ["History", "KERNELS", "STEP_COST"]

#: Interpreted cost of one complex product of the convolution [estimated microseconds].
STEP_COST = 0.5


def convolve(weights, buffer, offsets, counts, step, out):
    """``out[m] = sum_j weights[o_m + j] buffer[o_m + (step - 1 - j) mod n_m]``, the memory of each mode
    at ``step`` from the rates of the steps before it (``j = 0`` the last)."""
    for m in range(counts.size):
        n = counts[m]
        o = offsets[m]
        acc = 0j
        reach = min(n, step)
        if reach > 0:
            p = (step - 1) % n  # the last step's slot; the ring read backwards from it, then from its end
            first = min(p + 1, reach)
            for j in range(first):
                acc += weights[o + j] * buffer[o + p - j]
            for j in range(first, reach):
                acc += weights[o + j] * buffer[o + n + p - j]
        out[m] = acc


def push(buffer, offsets, counts, step, rates):
    """Store the rates of ``step`` (one per mode) in each mode's ring."""
    for m in range(counts.size):
        n = counts[m]
        if n > 0:
            buffer[offsets[m] + step % n] = rates[m]


KERNELS = KernelSet(globals(), ("convolve", "push"))


class History:
    """The ragged history of ``counts[m]`` steps per mode with their step ``weights`` (flat, one mode
    after another: `stickslip.sbim.kernels.ragged_step_weights`)."""

    def __init__(self, weights: np.ndarray, counts: np.ndarray, steps: int):
        self.counts = np.asarray(counts, dtype=np.int64)
        self.offsets = np.concatenate([[0], np.cumsum(self.counts)[:-1]]).astype(np.int64)
        self.size = int(self.counts.sum())
        self.weights = np.asarray(weights, dtype=complex)
        self.buffer = np.zeros(self.size, dtype=complex)
        self.kernels = KERNELS.choose(STEP_COST * self.size * steps)

    def memory(self, step: int, weights: np.ndarray | None = None) -> np.ndarray:
        """Each mode's convolution at ``step`` (a new array), with this history's weights or others of the
        same layout (another kernel over the same rates)."""
        out = np.zeros(self.counts.size, dtype=complex)
        w = self.weights if weights is None else weights
        self.kernels.convolve(w, self.buffer, self.offsets, self.counts, step, out)
        KERNELS.charge(self.kernels, STEP_COST * self.size)
        return out

    def push(self, step: int, rates: np.ndarray) -> None:
        self.kernels.push(self.buffer, self.offsets, self.counts, step, np.ascontiguousarray(rates, dtype=complex))

"""An in-plane run's interface at ``t = 0`` with a past (`InitialState`): the slip and the opening of each
node and the rates before, which fill each mode's history as if the interface had moved so (a wave
travelling for ever, `stickslip.sbim.waves`). A run without one starts from rest: nothing moved before.

The history holds each mode's own window of past steps (`stickslip.sbim.inplane`): the past is asked
at ``t = -j dt`` for ``j`` from that longest window down to 1, and its last rates (``t = -dt``) say which
nodes were sliding.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..errors import ParameterError

__all__ = ["InitialState"]


def _nodes(name: str, value, size: int | None = None) -> np.ndarray:
    try:
        a = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(name, value, "an array of finite numbers, one per node [m]") from None
    if a.ndim != 1 or a.size == 0 or not np.all(np.isfinite(a)):
        raise ParameterError(name, f"an array of shape {a.shape}", "a 1-D array of finite numbers, one per node")
    if size is not None and a.size != size:
        raise ParameterError(name, f"{a.size} values", f"one per node ({size})")
    return a


@dataclass(frozen=True, eq=False)
class InitialState:
    """The ``slip`` and ``opening`` [m] of each node at ``t = 0`` and ``rates(t)``, the slip and opening
    rates [m/s] of each node at a past time ``t < 0`` [s] (a function giving two arrays)."""

    slip: np.ndarray
    opening: np.ndarray
    rates: Callable

    def __post_init__(self):
        object.__setattr__(self, "slip", _nodes("slip", self.slip))
        object.__setattr__(self, "opening", _nodes("opening", self.opening, self.slip.size))
        if not callable(self.rates):
            raise ParameterError("rates", self.rates, "a function of t [s] < 0 giving the slip and opening rates "
                                 "[m/s] at the nodes (two arrays)")

    def past(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """The slip and opening rates at ``t < 0``, checked."""
        try:
            vx, vy = self.rates(t)
        except Exception as err:  # a user's function: whatever it raises is said in one line
            raise ParameterError("rates", "a past", f"a function of t giving two arrays of rates "
                                 f"({type(err).__name__}: {err})") from None
        n = self.slip.size
        return _nodes("rates", vx, n), _nodes("rates", vy, n)

    def fill(self, dt: float, pre: int, hx, hy) -> np.ndarray:
        """Push the rates of the ``pre`` steps before ``t = 0`` into the histories ``hx``, ``hy`` (their
        steps ``0 .. pre - 1``); the nodes sliding at the last of them."""
        vx = np.zeros(self.slip.size)
        for j in range(pre):
            vx, vy = self.past((j - pre) * dt)
            hx.push(j, np.fft.rfft(vx))
            hy.push(j, np.fft.rfft(vy))
        return vx != 0.0

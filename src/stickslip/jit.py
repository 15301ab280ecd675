"""Kernels written once, run compiled by numba or interpreted by Python.

numba compiles a kernel once and keeps it on disk (``cache=True``), but a process still pays
numba's own start-up before its first compiled call: importing numba and readying its
numpy support (which imports scipy.linalg for BLAS) took 0.6 s on the 2-core machine, six
times a short job such as the README's first command (a limit cycle of the oscillator in a
millisecond of work). A `KernelSet` holds a module's kernels as plain functions and gives
them two ways:

* `KernelSet.interpreted`: the functions as written, calling one another, run by Python;
* `KernelSet.compiled`: the same source compiled by ``numba.njit(cache=True)`` (imported on
  first use), the kernels calling their compiled twins;

and `KernelSet.choose` picks one for a piece of work: the interpreted kernels while the
interpreted work of the process, with the piece's estimate, stays within `KernelSet.budget`
(in estimated microseconds of interpreted time: the caller knows its kernels' cost per
segment, step or sample, and charges what it ran with `KernelSet.charge`), the compiled ones
for a large piece or once they are loaded. The two run the same IEEE operations in the same
order (no fast-math), so they give the same numbers (tests/test_jit.py checks them bit for
bit).

A module of kernels defines them without decorators and ends with
``KERNELS = KernelSet(globals(), ("name", ...))``.
"""

from __future__ import annotations

import functools
import threading
import types

__all__ = ["KernelSet", "BUDGET"]

#: Interpreted work a process does before it loads the compiled kernels [estimated microseconds]:
#: half of numba's start-up.
BUDGET = 300_000


class KernelSet:
    """The kernels ``names`` of a module whose globals are ``namespace``."""

    def __init__(self, namespace: dict, names, budget: int = BUDGET):
        self._namespace, self.names, self.budget = namespace, tuple(names), int(budget)
        self._spent = 0
        self._lock = threading.Lock()

    @functools.cached_property
    def interpreted(self) -> types.SimpleNamespace:
        """The kernels run by Python."""
        return self._twins(lambda f: f)

    @functools.cached_property
    def compiled(self) -> types.SimpleNamespace:
        """The kernels compiled by numba (and cached on disk)."""
        from numba import njit

        return self._twins(njit(cache=True))

    @property
    def loaded(self) -> bool:
        """The compiled kernels are loaded in this process."""
        return "compiled" in self.__dict__

    def choose(self, estimate: float) -> types.SimpleNamespace:
        """The kernels for a piece of work of at most ``estimate`` units: compiled if they are
        loaded or if the estimate, with the work charged before, exceeds `budget`; interpreted
        otherwise (then `charge` what ran)."""
        with self._lock:
            if not self.loaded and self._spent + estimate <= self.budget:
                return self.interpreted
        return self.compiled

    @property
    def left(self) -> float:
        """The interpreted work the process may still do before it loads the compiled kernels."""
        with self._lock:
            return 0.0 if self.loaded else max(self.budget - self._spent, 0.0)

    def charge(self, kernels, work: float) -> None:
        """Count ``work`` units done by ``kernels`` (nothing for the compiled ones)."""
        if kernels is not self.__dict__.get("compiled"):
            with self._lock:
                self._spent += work

    def _twins(self, make) -> types.SimpleNamespace:
        """Each kernel rebuilt over a copy of the module's globals in which every kernel name is
        its twin, then passed through ``make``; numba resolves a callee at compilation from its
        caller's globals, Python at each call: both find the twin."""
        scope = dict(self._namespace)
        for name in self.names:
            f = self._namespace[name]
            twin = types.FunctionType(f.__code__, scope, f.__name__, f.__defaults__, f.__closure__)
            twin.__doc__, twin.__qualname__ = f.__doc__, f.__qualname__
            scope[name] = make(twin)
        return types.SimpleNamespace(**{name: scope[name] for name in self.names})

"""Settings of a test session.

* **BLAS threads per worker.** With ``-n N`` (pytest-xdist) each of the N workers gets the CPUs
  over N for its BLAS and OpenMP threads (as `stickslip.sweep.pool.blas_share` gives a sweep's
  workers), unless the environment sets them: two workers of two OpenBLAS threads each on two
  cores spin against each other (the FE campaign's canary took 44 s that way, 8 s on one thread
  each, with another job on the cores).
* **Hypothesis profiles.** ``bounded`` (the default: ``make test`` and CI) runs each property
  test's stated number of examples, derandomized, so that every run tries the same inputs;
  ``deep`` (``make test-deep``, before an issue is resolved) ten times as many, drawn afresh
  each run (``--hypothesis-profile deep``). A test states its examples with
  `tests.budget.examples`, which scales them by the profile.
"""

from __future__ import annotations

import os

from hypothesis import settings

#: The environment variables that set a process's BLAS and OpenMP threads.
BLAS_THREADS = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")

settings.register_profile("bounded", deadline=None, derandomize=True, print_blob=True)
settings.register_profile("deep", deadline=None, max_examples=1000, print_blob=True)
settings.load_profile("bounded")  # --hypothesis-profile deep replaces it


def pytest_configure(config):
    workers = getattr(config.option, "numprocesses", None)
    if isinstance(workers, int) and workers > 1 and not hasattr(config, "workerinput"):
        share = str(max(1, (os.cpu_count() or 1) // workers))
        for name in BLAS_THREADS:  # inherited by the workers, which start after this hook
            os.environ.setdefault(name, share)

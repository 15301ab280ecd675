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
* **Slow by measured time.** The tests listed in ``tests/slow_by_time.txt`` (each 2 s or more in an
  idle fast run on the 2-core machine) are marked slow: ``make test`` stays under 4 minutes, CI runs
  them with the slow set (`tests.slow_by_time` adds to the list from a run's junit file).
"""

from __future__ import annotations

import os

import pytest
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


def pytest_collection_modifyitems(config, items):
    from tests.slow_by_time import listed

    slow = listed()
    if not any("::" in str(arg) for arg in config.args):  # whole files collected: every listed id of them is there
        files = {item.nodeid.split("::")[0] for item in items}
        stale = sorted(node for node in slow if node.split("::")[0] in files) if files else []
        stale = [node for node in stale if node not in {item.nodeid for item in items}]
        if stale:
            raise pytest.UsageError(f"tests/slow_by_time.txt lists tests not collected (renamed, or a parameter "
                                    f"changed): {stale[:5]}; correct the list")
    for item in items:
        if item.nodeid in slow:
            item.add_marker(pytest.mark.slow)
            item.add_marker(pytest.mark.slow_by_time)  # the plants' runner still takes them


@pytest.fixture(scope="session")
def quick_report(tmp_path_factory):
    """The whole quick report (`stickslip.report.reproduce` with ``quick=True``, several minutes),
    made once per test run for every slow test that reads it: ``(folder, summary)``.

    The folder is shared by the xdist workers (their common base folder): the first worker to
    ask computes the figures in two processes, holding a lock; another that asks meanwhile
    waits, then reads the same checkpoints (plotting and checking them again, not computing)."""
    import fcntl

    from stickslip.report import reproduce

    base = tmp_path_factory.getbasetemp()
    root = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base
    folder = root / "quick-report"
    with open(root / "quick-report.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        summary = reproduce(folder, quick=True, workers=2)
    return folder, summary

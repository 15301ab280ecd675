"""`python -m stickslip.precompile` fills numba's cache with every compiled path's kernels."""

import os
import subprocess
import sys

import pytest

#: The entry points of the compiled paths (module stem, function) whose index files numba writes.
ENTRIES = [("slipkernel", "run"), ("slipkernel", "evaluate"), ("smoothkernel", "segment"), ("search", "search"),
           ("kernel", "advance"), ("kernel", "run_affine"), ("kernel", "state"),
           ("history", "convolve"), ("history", "push"), ("kernel", "rhs"), ("kernel", "jacobian")]


@pytest.mark.slow
def test_precompile_leaves_each_compiled_path_in_the_cache(tmp_path):
    cache = tmp_path / "numba"
    done = subprocess.run([sys.executable, "-m", "stickslip.precompile"], env={**os.environ, "NUMBA_CACHE_DIR": str(cache)},
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0 and done.stdout == "", done.stderr[-800:]
    assert done.stderr.count("compiled in") == 7 and "numba's cache ready in" in done.stderr
    names = {p.name for p in cache.rglob("*.nbi")}
    missing = [f"{m}.{f}" for m, f in ENTRIES if not any(n.startswith(f"{m}.{f}-") for n in names)]
    assert not missing, (missing, sorted(names))

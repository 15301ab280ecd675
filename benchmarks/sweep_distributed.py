"""Sweeps on dask.distributed (issue 25): points per second on 1 and 2 local workers, and the
scheduler's cost per point against a plain loop.

The point is CPU work of about ``--seconds`` (a loop of small numpy products, one thread), the
same at every point. Measured in one run:

* a plain Python loop over the points (no store, no scheduler);
* `run_sweep(..., scheduler="distributed", workers=1)` and ``workers=2``: the whole call, the
  local cluster's start and the Zarr store included, and the same with the cluster's start
  left out (an existing scheduler by its address).

Target (issue 25): 2 workers >= 1.7 x one on a 2-core machine for points of about 1 s.

Usage: ``python benchmarks/sweep_distributed.py [--points 16] [--seconds 1.0]``
"""

from __future__ import annotations

import argparse
import functools
import os
import tempfile
import time
from pathlib import Path

os.environ.setdefault("OMP_NUM_THREADS", "1")  # one core per point, as the sweep gives each local worker
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from stickslip.sweep import run_sweep  # noqa: E402


def work(x: float, reps: int) -> dict:
    """About ``reps`` 100 x 100 products: the point's CPU time."""
    a = np.full((100, 100), 1e-3 * (1.0 + x))
    b = a.copy()
    for _ in range(reps):
        b = a @ b
        b /= np.abs(b).max()
    return {"y": float(b[0, 0])}


def _calibrate(seconds: float) -> int:
    t0 = time.perf_counter()
    work(0.0, 200)
    per = (time.perf_counter() - t0) / 200
    return max(1, int(seconds / per))


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=16)
    ap.add_argument("--seconds", type=float, default=1.0, help="CPU time of one point")
    args = ap.parse_args(argv)
    reps = _calibrate(args.seconds)
    func = functools.partial(work, reps=reps)
    xs = list(np.linspace(0.0, 1.0, args.points))
    t0 = time.perf_counter()
    for x in xs:
        func(x)
    loop = time.perf_counter() - t0
    print(f"{args.points} points of {loop / args.points:.3f} s: plain loop {loop:.2f} s "
          f"({args.points / loop:.2f} points/s)")
    rates = {}
    with tempfile.TemporaryDirectory() as tmp:
        for workers in (1, 2):
            t0 = time.perf_counter()
            run_sweep(func, {"x": xs}, Path(tmp) / f"w{workers}.zarr", outputs={"y": "1"}, scheduler="distributed",
                      workers=workers)
            whole = time.perf_counter() - t0
            from distributed import LocalCluster

            with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                              dashboard_address=":0") as cluster:
                t0 = time.perf_counter()
                run_sweep(func, {"x": xs}, Path(tmp) / f"a{workers}.zarr", outputs={"y": "1"},
                          scheduler=cluster.scheduler_address)
                running = time.perf_counter() - t0
            rates[workers] = args.points / running
            print(f"  {workers} worker(s): {whole:.2f} s with the cluster's start, {running:.2f} s on a running "
                  f"cluster ({rates[workers]:.2f} points/s); overhead per point against the loop "
                  f"{(running * workers - loop) / args.points * 1e3:.0f} ms of worker time")
    print(f"RATIO points per second, 2 workers / 1 worker = {rates[2] / rates[1]:.2f} (target >= 1.7)")


if __name__ == "__main__":
    main()

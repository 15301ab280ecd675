"""The 3-D brake of examples/brake3d at the sizes engineers mesh (issue 45): wall time and peak memory
of its steps, and the target's ratios.

Targets (issue 45): at >= 200,000 dofs, a full CEA of 30 modes near a shift and a 41-point reduced
friction sweep each within 10 minutes on the 2-core machine, peak memory <= 8 GB. Printed: each
step's seconds and the peak resident memory (``ru_maxrss``) after it (where the peak is reached), and the ratios time / 600 s and memory /
8 GB measured in this one run (below 1: within the target).

The full CEA is one shift-invert Arnoldi about ``i 2 pi shift`` (`stickslip.fem.cea.eigenvalues_near`,
the step `complex_eigenvalues` repeats along a band: one sparse LU of ``K + sigma C + sigma^2 M``
by SuperLU and ARPACK's iterations); the reduced sweep is `stickslip.fem.reduced.modal_basis`
(the real modes, shift-invert Lanczos, and the contact's static vectors) then `reduced_sweep`.

Usage: ``python benchmarks/brake3d_size.py [--pad 4] [--disc 7] [--order 2] [--modes 60] [--shift 5000]``
(cell sizes in mm).
"""

from __future__ import annotations

import argparse
import resource
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples" / "brake3d"))
import brake  # noqa: E402  (the example)

from stickslip.fem.cea import eigenvalues_near  # noqa: E402
from stickslip.fem.reduced import modal_basis, reduced_sweep  # noqa: E402


def peak_gb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024**2


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pad", type=float, default=4.0, help="the pad's cell size [mm]")
    parser.add_argument("--disc", type=float, default=7.0, help="the disc's cell size [mm]")
    parser.add_argument("--order", type=int, default=2)
    parser.add_argument("--modes", type=int, default=60, help="real modes of the reduction basis")
    parser.add_argument("--shift", type=float, default=5000.0, help="the full CEA's shift [Hz]")
    args = parser.parse_args()
    seconds, peaks = {}, {}

    class Stamped(dict):  # each step's peak memory so far, kept as its time is
        def __setitem__(self, key, value):
            super().__setitem__(key, value)
            peaks[key] = peak_gb()

    seconds = Stamped()
    with tempfile.TemporaryDirectory() as folder:
        t = time.perf_counter()
        problem = brake.build(brake.write_step(Path(folder) / "brake.step"), folder, args.pad, args.disc, args.order)
        dofs = problem.slave.n_dofs + problem.master.n_dofs
        _ = problem.coupling
        seconds["mesh, assembly, mortar"] = time.perf_counter() - t
        t = time.perf_counter()
        steady = problem.steady
        seconds["steady sliding"] = time.perf_counter() - t
        print(f"{dofs} dofs ({len(problem.slave.body.points)} pad nodes, {len(problem.master.body.points)} disc "
              f"nodes, order {args.order}); {int(steady.active.sum())} of {len(steady.active)} contact nodes active",
              flush=True)
        t = time.perf_counter()
        K, C, mass, _ = problem.linearised("lumped", "penalty")
        s, _, trusted, _, _ = eigenvalues_near(K.tocsc(), C, mass, args.shift, 30, True)
        seconds["full CEA, 30 modes near the shift"] = time.perf_counter() - t
        print(f"full CEA: {int(trusted.sum())} trusted of 30 near {args.shift:g} Hz, {time.perf_counter() - t:.1f} s, "
              f"peak {peak_gb():.2f} GB so far", flush=True)
        t = time.perf_counter()
        basis = modal_basis(problem, args.modes)
        seconds[f"reduction basis ({args.modes} modes + {basis.augmented} static vectors)"] = time.perf_counter() - t
        t = time.perf_counter()
        tracked = reduced_sweep(basis, np.linspace(0.0, 0.8, 41), band=(1e3, 0.5 * basis.top))
        seconds["41-point reduced friction sweep"] = time.perf_counter() - t
        found = ~np.isnan(tracked.critical)
        print(f"reduced sweep: {int(found.sum())} critical frictions, lowest "
              f"{np.nanmin(tracked.critical) if found.any() else float('nan'):.4f}")
    for step, sec in seconds.items():
        print(f"{step:60s} {sec:8.1f} s, peak after it {peaks[step]:6.2f} GB")
    reduced = sum(v for k, v in seconds.items() if "reduc" in k)
    print(f"full CEA time / 600 s: {seconds['full CEA, 30 modes near the shift'] / 600:.3f}")
    print(f"reduced sweep (basis and sweep) time / 600 s: {reduced / 600:.3f}")
    print(f"peak memory / 8 GB: {peak_gb() / 8:.3f} ({peak_gb():.2f} GB)")


if __name__ == "__main__":
    main()

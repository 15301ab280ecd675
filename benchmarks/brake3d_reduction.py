"""The reduced CEA's error against the full CEA as its basis grows, on the 3-D brake of
examples/brake3d (issue 45): the critical frictions of the modes that squeal first.

The full CEA's critical friction of each mode (penalty contact, as the reduction's) is bisected to
1/4096 of its bracket; the reduced sweep (41 frictions from 0 to 0.8, tracked, critical values by
multisection) is run with 30, 60, 120 and 240 real modes, with the modes' static vectors (the
default) and without (the modes alone: the reduction commercial tools use). Printed: each critical
friction's relative error and the sweep's seconds, measured in this one run.

Usage: ``python benchmarks/brake3d_reduction.py [--pad 8] [--disc 15]`` (cell sizes in mm, linear).
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples" / "brake3d"))
import brake  # noqa: E402

from stickslip.fem import complex_eigenvalues, modal_basis, reduced_sweep  # noqa: E402

#: The modes followed (Hz, near which the full CEA looks) and brackets of their critical frictions.
MODES = ((6373.7, 0.2, 0.35), (11110.0, 0.25, 0.4))


def full_critical(problem, near: float, lo: float, hi: float) -> float:
    def grows(mu):
        modes = complex_eigenvalues(dataclasses.replace(problem, friction=mu), (near - 300, near + 300), count=20,
                                    contact_model="penalty")
        return bool(modes.unstable.any())

    assert not grows(lo) and grows(hi)
    for _ in range(12):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if grows(mid) else (mid, hi)
    return 0.5 * (lo + hi)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pad", type=float, default=8.0)
    parser.add_argument("--disc", type=float, default=15.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        problem = brake.build(brake.write_step(Path(folder) / "brake.step"), folder, args.pad, args.disc)
    exact = {near: full_critical(problem, near, lo, hi) for near, lo, hi in MODES}
    print(f"{problem.slave.n_dofs + problem.master.n_dofs} dofs; full CEA's critical frictions: "
          + ", ".join(f"{v:.5f} at {k:g} Hz" for k, v in exact.items()))
    print("| modes | static vectors | " + " | ".join(f"error at {k:g} Hz" for k in exact) + " | seconds |")
    print("| ---: | --- | " + " | ".join("---:" for _ in exact) + " | ---: |")
    for count in (30, 60, 120, 240):
        for augment in ("modes", "none"):
            t = time.perf_counter()
            tracked = reduced_sweep(modal_basis(problem, count, augment=augment), np.linspace(0.0, 0.8, 41),
                                    band=(1e3, 12e3))
            seconds = time.perf_counter() - t
            errors = []
            for near, value in exact.items():
                found = ~np.isnan(tracked.critical) & (np.abs(tracked.critical_frequency - near) < 0.01 * near)
                errors.append(f"{np.min(np.abs(tracked.critical[found] / value - 1)):.1e}" if found.any() else "none")
            print(f"| {count} | {augment} | " + " | ".join(errors) + f" | {seconds:.1f} |", flush=True)


if __name__ == "__main__":
    main()

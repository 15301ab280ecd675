"""Linearising steady sliding for the CEA (`stickslip.fem.cea.linearised`) against assembling
the same body (`stickslip.fem.assemble`), in one run, at about 10k and 37k dofs.

Issue 24 measured the old linearisation, which edited the tangential rows of a LIL matrix in a
Python loop, at 2.0 s for 10k dofs and 27.7 s for 37k (about n^2). Target: linearising costs no
more than assembling (ratio <= 1). Both are timed best of three, the steady state (solved once,
cached) left out of both; the old loop is timed beside them on the same matrix, for the record.

Usage: ``python benchmarks/fem_linearise.py [--sizes 0.003 0.0015]`` (gmsh mesh sizes in m of
the annulus example, R = 0.1 m).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples" / "annulus"))
import mesh as annulus_mesh  # noqa: E402  (the example's gmsh script)
from timing import best_of  # noqa: E402

from stickslip.fem import (BodyScheme, ContactProblem, Material, RigidCylinder, assemble,  # noqa: E402
                           contact_frames, read_body)
from stickslip.fem.cea import linearised  # noqa: E402


def old_loop(problem: ContactProblem) -> float:
    """The tangential rows edited one by one in a LIL matrix (the code before issue 24), timed."""
    scheme = BodyScheme(problem)
    K = scheme.stiffness
    normal, tangent = scheme.contact_dofs
    touching = problem.steady.active[scheme.contact_nodes]
    normal, tangent = normal[touching], tangent[touching]
    keep = np.setdiff1d(np.arange(scheme.free.size), normal)

    def edit():
        A = K.tolil(copy=True)
        for n, t in zip(normal, tangent):
            A[t] = A[t] - problem.friction * A[n]
        return A.tocsr()[keep][:, keep]

    seconds, _ = best_of(edit, repeat=1)
    return seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=float, nargs="+", default=[0.003, 0.0015])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        for size in args.sizes:
            path = Path(tmp) / f"annulus-{size:g}.msh"
            annulus_mesh.make(path, size)
            body = read_body(path)
            material = Material(2.1e11, 0.3, 7850.0, alpha=10.0, beta=1e-7)
            t_assemble, system = best_of(lambda: assemble(body, material))
            problem = ContactProblem(system, contact_frames(body, "bore", RigidCylinder(0.1 + 1e-4, 50.0)), 0.7,
                                     ("rim",))
            problem.steady  # solved once, cached: not part of either timing
            t_linearise, (K, C, _, _) = best_of(lambda: linearised(problem))
            t_old = old_loop(problem)
            print(f"{system.n_dofs} dofs ({K.shape[0]} kept): assemble {t_assemble:.3f} s, linearise "
                  f"{t_linearise:.3f} s, ratio {t_linearise / t_assemble:.2f} (target <= 1); the old LIL loop "
                  f"{t_old:.2f} s ({t_old / t_linearise:.0f} x the new)")


if __name__ == "__main__":
    main()
